//! Property tests: identities that must hold for any admissible input.
// proptest is a native-only dev-dependency.
#![cfg(not(target_arch = "wasm32"))]

use proptest::prelude::*;
use wingbeat::config::SimConfig;
use wingbeat::kinematics::Kinematics;
use wingbeat::model::Mode;
use wingbeat::simulate::simulate;

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, .. ProptestConfig::default() })]

    /// Superposition, Liouville's formula and finiteness for random modes and kinematics.
    #[test]
    fn superposition_and_liouville_hold(
        f in 20.0f64..200.0, ax in -1e-4f64..1e-4, ay in -1e-4f64..1e-4, zeta in 0.0f64..0.1,
        a0 in 0.0f64..1.0, b0 in 0.0f64..0.6, g0 in 0.0f64..0.3, fd in 10.0f64..40.0,
        q0 in -1e-4f64..1e-4, v0 in -0.1f64..0.1,
    ) {
        let cfg = SimConfig {
            kinematics: Kinematics::sinusoidal(fd, a0, b0, g0),
            modes: vec![Mode { name: "p".into(), freq_hz: f, a: [ax, ay], zeta, strains: vec![] }],
            duration_s: 0.2,
            sample_rate_hz: 5000.0,
            initial_conditions: vec![[q0, v0]],
            ..SimConfig::paper()
        };
        match simulate(&cfg) {
            Ok(r) => {
                let m = &r.modes[0];
                let scale = m.q.total.iter().fold(1e-300f64, |s, v| s.max(v.abs()));
                for i in 0..r.t.len() {
                    let s = m.q.euler[i] + m.q.centrifugal[i] + m.q.coriolis[i] + m.q.free[i];
                    prop_assert!((s - m.q.total[i]).abs() <= 1e-11 * scale);
                }
                let mm = m.floquet.monodromy;
                let det = mm[0][0] * mm[1][1] - mm[0][1] * mm[1][0];
                let expect = (-2.0 * zeta * 2.0 * std::f64::consts::PI * f / fd).exp();
                prop_assert!((det - expect).abs() < 1e-8 * expect.max(1e-3), "det {} vs {}", det, expect);
                prop_assert!(m.floquet.effective_freq_hz.is_finite());
            }
            // Parametric resonance that overflows is allowed, but only as a clear error.
            Err(e) => prop_assert!(e.to_string().contains("parametrically unstable"), "{}", e),
        }
    }
}
