//! The aerodynamic force sampled on the output grid (`simulate::sample_forces` in a fluid, what
//! the lab's spectrum panel and the wasm `analyze` show) against the quadrature sum evaluated
//! directly at each sample (`AeroWing::loads_nonlinear` at zero elastic velocity, the same
//! |v|v load and added-mass reaction): the sampled force comes from the air run's one-period
//! load table and must agree to 1e-12 of its largest value. In a vacuum there is no
//! aerodynamic series and the JSON has no such key.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::aero::{AeroConfig, AeroWing, FrameState};
use wingbeat::config::SimConfig;
use wingbeat::simulate::{force_series, sample_forces, ModeSelection};

#[test]
fn sampled_aerodynamic_force_equals_the_quadrature_sum_at_every_sample() {
    let base = SimConfig::fe_wing().unwrap();
    let cfg = SimConfig {
        duration_s: 0.1,
        sample_rate_hz: 5000.0,
        aero: AeroConfig::with_density(1.2),
        ..base.clone()
    };
    let f = sample_forces(&cfg, ModeSelection::All).unwrap();
    let geom = cfg.wing.as_deref().unwrap();
    let wing = AeroWing::build(geom, &cfg.aero).unwrap();
    let kin = cfg.kinematics.compile();
    let n = cfg.modes.len();
    let k = 0.5 * cfg.aero.air_density_kg_m3 * cfg.aero.normal_force_coefficient;
    let zero = vec![0.0; n];
    let peak: Vec<f64> = (0..n)
        .map(|m| {
            f[m].as_ref()
                .unwrap()
                .aerodynamic
                .iter()
                .fold(0.0f64, |a, v| a.max(v.abs()))
        })
        .collect();
    assert!(peak.iter().all(|p| *p > 0.0), "{peak:?}");
    let samples = cfg.n_samples();
    for i in 0..samples {
        let t = i as f64 / cfg.sample_rate_hz;
        let fs = FrameState::of(&kin.state(t));
        let mut want = vec![0.0; n];
        wing.loads_nonlinear(&fs, k, cfg.aero.air_density_kg_m3, &zero, &mut want);
        for m in 0..n {
            let got = f[m].as_ref().unwrap().aerodynamic[i];
            assert!(
                (got - want[m]).abs() <= 1e-12 * peak[m],
                "mode {m}, t = {t}: {got:e} vs {:e}",
                want[m]
            );
        }
    }
    // A vacuum: no aerodynamic series, and none in the JSON.
    let vac = force_series(&SimConfig {
        duration_s: 0.1,
        ..base
    })
    .unwrap();
    assert!(vac[0].aerodynamic.is_empty());
    let json = serde_json::to_string(&vac[0]).unwrap();
    assert!(!json.contains("aerodynamic"));
}
