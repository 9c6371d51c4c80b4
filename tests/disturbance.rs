//! The seeded disturbance (wingbeat::disturbance): normalised exactly on its grid, frequencies
//! and phases where they were drawn, reproducible from its seed, and its derivative and
//! integral consistent with the rate (finite differences and quadrature, independent of the
//! closed forms under test).

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::disturbance::{Disturbance, DisturbanceSpec};

#[test]
fn the_rate_has_zero_mean_and_the_asked_for_spread_on_its_grid() {
    for (amp, seed) in [(0.312, 1), (0.1, 2), (3.0, 99)] {
        let d = Disturbance::new(&DisturbanceSpec::published(amp, seed)).unwrap();
        let xs: Vec<f64> = (0..4000).map(|i| d.rate(i as f64 * 1e-3)).collect();
        let mean = xs.iter().sum::<f64>() / 4000.0;
        let sd = (xs.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / 3999.0).sqrt();
        assert!(mean.abs() < 1e-13 * amp.max(1.0), "mean {mean}");
        assert!((sd / amp - 1.0).abs() < 1e-12, "sd {sd} vs {amp}");
        assert_eq!(d.freqs_hz.len(), 15);
        assert!(d.freqs_hz.iter().all(|f| (1.0..=10.0).contains(f)));
        assert!(d
            .phases_rad
            .iter()
            .all(|p| (0.0..std::f64::consts::TAU).contains(p)));
    }
}

#[test]
fn a_seed_gives_one_disturbance_and_another_seed_another() {
    let a = Disturbance::new(&DisturbanceSpec::published(0.312, 7)).unwrap();
    let b = Disturbance::new(&DisturbanceSpec::published(0.312, 7)).unwrap();
    let c = Disturbance::new(&DisturbanceSpec::published(0.312, 8)).unwrap();
    assert_eq!(a, b);
    assert_ne!(a.freqs_hz, c.freqs_hz);
    // The draw's frequencies spread over the band (not all alike): a check on the generator.
    let (lo, hi) = a
        .freqs_hz
        .iter()
        .fold((f64::MAX, f64::MIN), |(l, h), &f| (l.min(f), h.max(f)));
    assert!(hi - lo > 3.0, "{lo} … {hi}");
}

#[test]
fn derivative_and_angle_agree_with_the_rate() {
    let d = Disturbance::new(&DisturbanceSpec::published(0.312, 3)).unwrap();
    assert_eq!(d.angle(0.0), 0.0);
    let h = 1e-5;
    for &t in &[0.0, 0.123, 1.5, 3.999, 7.25] {
        let fd = (d.rate(t + h) - d.rate(t - h)) / (2.0 * h);
        assert!(
            (fd - d.rate_dot(t)).abs() < 1e-6 * d.rate_dot(t).abs().max(1.0),
            "rate_dot at {t}"
        );
        let da = (d.angle(t + h) - d.angle(t - h)) / (2.0 * h);
        // Central differences err by about h² · rate''' / 6 (≈ 1e-8 here).
        assert!(
            (da - d.rate(t)).abs() < 1e-6,
            "angle' at {t}: {da} vs {}",
            d.rate(t)
        );
    }
    // The angle at 2 s against Simpson's rule on the rate (2000 intervals).
    let n = 2000;
    let step = 2.0 / n as f64;
    let simpson: f64 = (0..=n)
        .map(|i| {
            let w = if i == 0 || i == n {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            w * d.rate(i as f64 * step)
        })
        .sum::<f64>()
        * step
        / 3.0;
    assert!(
        (simpson - d.angle(2.0)).abs() < 1e-9,
        "{simpson} vs {}",
        d.angle(2.0)
    );
    // The published indefinite integral: a constant away.
    let off = d.angle_offset();
    let indefinite = |t: f64| d.angle(t) + off;
    assert!(((indefinite(1.0) - indefinite(0.5)) - (d.angle(1.0) - d.angle(0.5))).abs() < 1e-15);
}

#[test]
fn bad_specs_are_named() {
    let base = DisturbanceSpec::published(0.1, 1);
    for (spec, field) in [
        (DisturbanceSpec { sines: 0, ..base }, "disturbance.sines"),
        (
            DisturbanceSpec {
                f_min_hz: f64::NAN,
                ..base
            },
            "disturbance.f_min_hz",
        ),
        (
            DisturbanceSpec {
                f_max_hz: 0.5,
                ..base
            },
            "disturbance.f_max_hz",
        ),
        (
            DisturbanceSpec {
                amplitude_rad_per_s: -1.0,
                ..base
            },
            "disturbance.amplitude_rad_per_s",
        ),
        (
            DisturbanceSpec {
                normalise_step_s: 0.0,
                ..base
            },
            "disturbance.normalise_step_s",
        ),
        (
            DisturbanceSpec {
                normalise_over_s: 1e6,
                normalise_step_s: 1e-6,
                ..base
            },
            "disturbance.normalise_over_s",
        ),
    ] {
        let e = Disturbance::new(&spec).unwrap_err().to_string();
        assert!(e.contains(field), "{field}: {e}");
    }
}

#[test]
fn eval_is_angle_rate_and_derivative_together() {
    let d = Disturbance::new(&DisturbanceSpec::published(0.312, 11)).unwrap();
    for i in 0..400 {
        let t = i as f64 * 0.0123;
        let (a, r, rd) = d.eval(t);
        let scale = 0.312 * 15.0 * std::f64::consts::TAU * 10.0;
        assert!((a - d.angle(t)).abs() <= 1e-13 * scale, "angle at {t}");
        assert!((r - d.rate(t)).abs() <= 1e-13 * scale, "rate at {t}");
        assert!(
            (rd - d.rate_dot(t)).abs() <= 1e-13 * scale,
            "rate_dot at {t}"
        );
    }
}
