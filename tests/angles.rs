//! The angle series on the simulation grid (src/analysis/angles.rs) against a point-by-point
//! evaluation of the compiled kinematics (what the wasm `anglesAt` does) and the closed form.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use std::f64::consts::PI;
use wingbeat::analysis::angles::{angle_series, angles_on};
use wingbeat::config::SimConfig;
use wingbeat::kinematics::{Angle, Harmonic};
use wingbeat::params::apply_overrides;
use wingbeat::simulate::simulate;

#[test]
fn angles_lie_on_the_simulation_grid_and_equal_point_evaluation() {
    let cfg = apply_overrides(
        &SimConfig::paper(),
        [
            ("alpha_phase", 0.3),
            ("gamma_phase", -1.0),
            ("flap_hz", 31.5),
            ("duration", 0.5),
        ],
    )
    .unwrap();
    let a = angle_series(&cfg).unwrap();
    let sim = simulate(&cfg).unwrap();
    assert_eq!(a.alpha.len(), sim.t.len());
    assert_eq!(a.beta.len(), sim.t.len());
    assert_eq!(a.gamma.len(), sim.t.len());
    // anglesAt-equivalent: the compiled kinematics evaluated at each of the simulation's times.
    let kin = cfg.kinematics.compile();
    for (i, &t) in sim.t.iter().enumerate() {
        let s = kin.state(t);
        assert_eq!(
            (a.alpha[i], a.beta[i], a.gamma[i]),
            (s.alpha, s.beta, s.gamma)
        );
    }
    assert_eq!(angles_on(&kin, &sim.t), a);
    // The closed form A sin(2π f t + φ).
    let wd = 2.0 * PI * 31.5;
    for (i, &t) in sim.t.iter().enumerate().step_by(97) {
        assert!((a.alpha[i] - 0.8 * (wd * t + 0.3).sin()).abs() < 1e-12);
        assert!((a.beta[i] - 0.5 * (wd * t).sin()).abs() < 1e-12);
        assert!((a.gamma[i] - 0.2 * (wd * t - 1.0).sin()).abs() < 1e-12);
    }
}

#[test]
fn means_and_higher_harmonics_and_sampled_tables_come_through() {
    let mut cfg = SimConfig::paper();
    cfg.duration_s = 0.08;
    cfg.kinematics.beta = Angle::Fourier {
        mean: 0.1,
        harmonics: vec![Harmonic {
            n: 3,
            amplitude: 0.05,
            phase: 0.2,
        }],
    };
    cfg.kinematics.gamma = Angle::Sampled {
        values: vec![0.0, 0.1, 0.0, -0.1],
        max_harmonic: None,
    };
    let a = angle_series(&cfg).unwrap();
    let wd = 2.0 * PI * 25.0;
    let dt = 1.0 / cfg.sample_rate_hz;
    for i in 0..a.beta.len() {
        let t = i as f64 * dt;
        assert!((a.beta[i] - (0.1 + 0.05 * (3.0 * wd * t + 0.2).sin())).abs() < 1e-12);
        // Four samples of a sine over one period interpolate to that sine.
        assert!((a.gamma[i] - 0.1 * (wd * t).sin()).abs() < 1e-12);
    }
    // Invalid configs are the config's error.
    cfg.sample_rate_hz = 0.0;
    assert!(angle_series(&cfg)
        .unwrap_err()
        .to_string()
        .contains("sample_rate_hz"));
}
