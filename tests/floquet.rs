//! Floquet analysis against closed forms (constant coefficients), Mathieu's stability chart,
//! Liouville's formula, and the beat measured in simulated responses.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use std::f64::consts::PI;
use wingbeat::config::SimConfig;
use wingbeat::floquet::analyse;
use wingbeat::simulate::simulate;

#[test]
fn constant_coefficients_give_the_natural_frequency_on_every_branch() {
    // Including the paper's tie: 62.5 Hz = 2.5 × 25 Hz, where e^{iωT} = −1 on the full period.
    for (f, z) in [
        (62.5, 0.0),
        (60.3, 0.0),
        (10.0, 0.0),
        (137.2, 0.0),
        (62.5, 0.02),
        (300.0, 0.05),
    ] {
        let w = 2.0 * PI * f;
        let ode = ConstOsc {
            w,
            c: 2.0 * z * w,
            f: 1.0,
            g: 0.0,
            wf: 2.0 * PI * 25.0,
        };
        let r = analyse(&ode, 25.0, f64::NAN);
        let expect = f * (1.0 - z * z).sqrt();
        assert!(
            (r.effective_freq_hz - expect).abs() < 1e-9 * f,
            "f = {f}, ζ = {z}: got {}",
            r.effective_freq_hz
        );
        // Liouville: det M = exp(−c T).
        let m = r.monodromy;
        let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        assert!((det - (-2.0 * z * w * 0.04).exp()).abs() < 1e-10);
        assert!(r.stable, "f = {f}: {r:?}");
    }
}

/// Characteristic values of Mathieu's equation (standard form), q = 0.1, from the series
/// a1 = 1 + q − q²/8 − q³/64 − q⁴/1536, b1 = 1 − q − q²/8 + q³/64 − q⁴/1536,
/// a2 = 4 + 5q²/12 − 763q⁴/13824, b2 = 4 − q²/12 + 5q⁴/13824.
#[test]
fn mathieu_stability_boundaries() {
    let q: f64 = 0.1;
    let a1 = 1.0 + q - q * q / 8.0 - q.powi(3) / 64.0 - q.powi(4) / 1536.0;
    let b1 = 1.0 - q - q * q / 8.0 + q.powi(3) / 64.0 - q.powi(4) / 1536.0;
    let a2 = 4.0 + 5.0 * q * q / 12.0 - 763.0 * q.powi(4) / 13824.0;
    let b2 = 4.0 - q * q / 12.0 + 5.0 * q.powi(4) / 13824.0;
    let stable = |a: f64| analyse(&Mathieu { a, q, c: 0.0 }, 1.0 / PI, f64::NAN).stable;
    let d = 2e-4;
    assert!(
        stable(b1 - d) && !stable(b1 + d),
        "first tongue lower edge near {b1}"
    );
    assert!(
        !stable(a1 - d) && stable(a1 + d),
        "first tongue upper edge near {a1}"
    );
    assert!(
        stable(b2 - d) && !stable(b2 + d),
        "second tongue lower edge near {b2}"
    );
    assert!(
        !stable(a2 - d) && stable(a2 + d),
        "second tongue upper edge near {a2}"
    );
    // Inside the first tongue the growth rate is positive and grows toward its centre.
    let g = |a: f64| analyse(&Mathieu { a, q, c: 0.0 }, 1.0 / PI, f64::NAN).growth_rate_per_s;
    assert!(g(1.0) > g(1.08) && g(1.08) > 0.0);
    // Undamped and stable: |λ| = 1.
    let r = analyse(&Mathieu { a: 2.3, q, c: 0.0 }, 1.0 / PI, f64::NAN);
    assert!((r.max_modulus - 1.0).abs() < 1e-10);
}

#[test]
fn paper_mode1_effective_frequency_matches_the_simulated_beat() {
    let cfg = SimConfig {
        duration_s: 10.0,
        ..SimConfig::paper()
    };
    let r = simulate(&cfg).unwrap();
    let m = &r.modes[0];
    let f_eff = m.floquet.effective_freq_hz;
    // Centrifugal softening lowers 62.5 Hz to about 60.3 Hz; the naive averaged-stiffness
    // estimate is close but not exact.
    assert!((f_eff - 60.3064).abs() < 1e-3, "{f_eff}");
    assert!((m.floquet.averaged_freq_hz - f_eff).abs() < 0.1);
    assert_eq!(m.floquet.beat_harmonic, 2);
    let beat = wingbeat::analysis::beat::measure(&m.q.coriolis, cfg.sample_rate_hz, 25.0, 0.0, 1.0);
    let measured = beat.beat_freq_hz.unwrap();
    let predicted = 1.0 / m.floquet.beat_period_s.unwrap();
    assert!(
        (measured - predicted).abs() < 2e-3 * predicted,
        "measured {measured} Hz, predicted {predicted} Hz"
    );
    assert!(beat.modulation_index > 0.3);
    // The free-vibration peak of the response spectrum sits at f_eff too.
    let spec = wingbeat::analysis::psd::welch(
        &m.q.coriolis,
        cfg.sample_rate_hz,
        &wingbeat::analysis::psd::WelchOptions {
            segment_len: 100_000,
            overlap: 0.0,
            ..Default::default()
        },
        Some(25.0),
    )
    .unwrap();
    let near: Vec<_> = spec
        .peaks
        .iter()
        .filter(|p| (p.freq_hz - f_eff).abs() < 0.5)
        .collect();
    assert!(
        !near.is_empty(),
        "no spectral peak near {f_eff}: {:?}",
        spec.peaks
    );
}

#[test]
fn parametric_resonance_is_reported_not_hidden() {
    // A 33 Hz mode under 25 Hz flapping with large roll: softening lowers it to about 25 Hz = f_p/2
    // (f_p = 50 Hz, the softening's frequency) and pumps it: the first tongue.
    let mut cfg = SimConfig {
        duration_s: 0.5,
        ..SimConfig::paper()
    };
    cfg.modes.truncate(1);
    cfg.modes[0].freq_hz = 33.0;
    cfg.kinematics = wingbeat::kinematics::Kinematics::sinusoidal(25.0, 1.2, 0.0, 0.1);
    let r = simulate(&cfg).unwrap();
    let fl = &r.modes[0].floquet;
    assert!(!fl.stable && fl.growth_rate_per_s > 1.0, "{fl:?}");
    // A long run overflows: a clear error, not NaN output.
    cfg.duration_s = 3000.0;
    cfg.sample_rate_hz = 100.0;
    let e = simulate(&cfg).unwrap_err().to_string();
    assert!(e.contains("parametrically unstable"), "{e}");
    // ... naming the mode and the inputs that drive it.
    assert!(
        e.contains("modes[0]") && e.contains("duration_s") && e.contains("kinematics.flap_freq_hz"),
        "{e}"
    );
}

/// A simulation reads Φ over the homogeneous period off its own output grid
/// (`floquet::analyse_sampled`) instead of integrating that span again: on grids that hold it
/// and grids that do not, its summary equals the separately integrated analysis
/// (`simulate::floquet_for`) to 1e-12 (seen: 4e-16 in f_eff, 3e-15 in |λ|), with the same
/// dominant harmonic.
#[test]
fn the_simulations_floquet_summary_equals_a_separate_integration() {
    use wingbeat::simulate::floquet_for;
    let mut cases: Vec<(&str, SimConfig)> = Vec::new();
    cases.push(("paper", SimConfig::paper()));
    let mut c = SimConfig::paper();
    c.modes = wingbeat::presets::fe_wing_modes().unwrap();
    c.duration_s = 0.5;
    cases.push(("FE wing, 6 modes", c));
    for (f, rate, d) in [
        (20.0, 10_000.0, 0.5),
        (7.0, 7_000.0, 1.0),
        (60.0, 6_000.0, 0.2),
        (25.0, 10_000.0, 0.03), // shorter than a period: the span is integrated
        (25.5, 10_000.0, 0.5),  // incommensurate: the span is integrated
        (25.0, 2_525.0, 0.5),   // 101 samples a period: odd, no Φ(T/2) on the grid
    ] {
        let mut c = SimConfig::paper();
        c.kinematics.flap_freq_hz = f;
        c.sample_rate_hz = rate;
        c.duration_s = d;
        cases.push(("varied", c));
    }
    let mut c = SimConfig::paper();
    // A mean pitch: β no longer odd about its mean, so S(t) has period T, not T/2.
    if let wingbeat::kinematics::Angle::Fourier { mean, .. } = &mut c.kinematics.beta {
        *mean = 0.1;
    }
    cases.push(("T_p = T", c));
    for (name, cfg) in &cases {
        let sim = simulate(cfg).unwrap();
        let kin = cfg.kinematics.compile();
        for (k, m) in cfg.modes.iter().enumerate() {
            let a = &sim.modes[k].floquet;
            let b = floquet_for(&kin, m);
            let at = format!("{name}, f_d = {} Hz, mode {k}", cfg.kinematics.flap_freq_hz);
            assert_eq!(a.dominant_harmonic, b.dominant_harmonic, "{at}");
            assert_eq!(a.beat_harmonic, b.beat_harmonic, "{at}");
            assert_eq!(a.stable, b.stable, "{at}");
            assert_eq!(a.homogeneous_period_s, b.homogeneous_period_s, "{at}");
            let close = |x: f64, y: f64, what: &str| {
                assert!(
                    (x - y).abs() <= 1e-12 * y.abs().max(1.0),
                    "{at}: {what} {x} vs {y}"
                );
            };
            close(a.effective_freq_hz, b.effective_freq_hz, "f_eff");
            close(a.characteristic_freq_hz, b.characteristic_freq_hz, "f_char");
            close(a.max_modulus, b.max_modulus, "|λ|max");
            match (a.beat_period_s, b.beat_period_s) {
                (Some(x), Some(y)) => close(x, y, "T_beat"),
                (x, y) => assert_eq!(x, y, "{at}"),
            }
        }
    }
}
