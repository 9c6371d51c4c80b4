//! Spectra, contributions, the initial-condition map and sweeps, each against an independent
//! computation.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use std::f64::consts::PI;
use wingbeat::analysis::contribution::contributions;
use wingbeat::analysis::ic_map::{ic_map, IcAttribution, IcMapOptions};
use wingbeat::analysis::psd::{band_power, welch, Detrend, WelchOptions};
use wingbeat::analysis::sweep::{apply, sweep, SweepOptions, SweepParam};
use wingbeat::config::SimConfig;
use wingbeat::simulate::{force_series, simulate};

#[test]
fn welch_of_a_sinusoid_plus_mean_has_the_right_peak_and_power() {
    let fs = 1000.0;
    let (a, f0, dc) = (2.0, 125.0, 0.5); // f0 on a bin for 1024-sample segments? 125 = 128 bins × 0.977 — not exact
    let x: Vec<f64> = (0..20_000)
        .map(|i| dc + a * (2.0 * PI * f0 * i as f64 / fs).sin())
        .collect();
    let opts = WelchOptions {
        segment_len: 1000,
        overlap: 0.5,
        detrend: Detrend::None,
        max_peaks: 4,
    };
    let s = welch(&x, fs, &opts, Some(25.0)).unwrap();
    assert_eq!(s.freq_hz.len(), 501);
    assert!((s.freq_hz[1] - 1.0).abs() < 1e-12);
    // Strongest peak at f0, labelled as 5 × 25 Hz; the DC peak is listed too.
    assert!((s.peaks[0].freq_hz - f0).abs() < 1e-9);
    assert!((s.peaks[0].flap_multiple.unwrap() - 5.0).abs() < 1e-12);
    assert!(s.peaks.iter().any(|p| p.freq_hz == 0.0));
    // Integrated density = mean square: a²/2 in the tone's band, dc² near zero frequency.
    let tone = band_power(&s, f0 - 3.0, f0 + 3.0);
    assert!(
        (tone - a * a / 2.0).abs() < 1e-3 * a * a / 2.0,
        "tone power {tone}"
    );
    let d = band_power(&s, 0.0, 2.0);
    assert!((d - dc * dc).abs() < 1e-3, "DC power {d}");
    // Detrending by the mean removes the DC part and keeps the tone.
    let sm = welch(
        &x,
        fs,
        &WelchOptions {
            detrend: Detrend::Mean,
            ..opts
        },
        None,
    )
    .unwrap();
    assert!(band_power(&sm, 0.0, 2.0) < 1e-12);
    assert!((band_power(&sm, f0 - 3.0, f0 + 3.0) - tone).abs() < 1e-9);
    // Linear detrending removes a ramp entirely.
    let ramp: Vec<f64> = (0..4096).map(|i| 3.0 + 0.01 * i as f64).collect();
    let sr = welch(
        &ramp,
        fs,
        &WelchOptions {
            segment_len: 512,
            detrend: Detrend::Linear,
            ..opts
        },
        None,
    )
    .unwrap();
    assert!(sr.psd.iter().all(|p| *p < 1e-20));
}

#[test]
fn welch_rejects_bad_options_by_name() {
    let x = vec![0.0; 100];
    let e = welch(
        &x,
        100.0,
        &WelchOptions {
            overlap: 0.99,
            ..Default::default()
        },
        None,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("psd.overlap"), "{e}");
    let e = welch(
        &x,
        100.0,
        &WelchOptions {
            segment_len: 2,
            ..Default::default()
        },
        None,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("psd.segment_len"), "{e}");
    let mut y = vec![0.0; 100];
    y[7] = f64::NAN;
    assert!(welch(&y, 100.0, &WelchOptions::default(), None)
        .unwrap_err()
        .to_string()
        .contains("psd.series[7]"));
}

#[test]
fn coriolis_spectrum_vanishes_without_yaw_and_peaks_at_twice_the_flap_frequency_with_it() {
    let cfg = SimConfig::paper();
    let f = force_series(&cfg).unwrap();
    let s = welch(
        &f[0].coriolis,
        cfg.sample_rate_hz,
        &WelchOptions::default(),
        Some(25.0),
    )
    .unwrap();
    // Largest oscillating peak at 2 f_d; the DC part (a large mean) is visible.
    let ac = s.peaks.iter().find(|p| p.freq_hz > 1.0).unwrap();
    assert!((ac.freq_hz - 50.0).abs() < 1.3, "{:?}", s.peaks);
    assert!(s.peaks.iter().any(|p| p.freq_hz == 0.0));
    let no_yaw = apply(&cfg, SweepParam::Gamma0, 0.0).unwrap();
    let f0 = force_series(&no_yaw).unwrap();
    assert!(f0[0].coriolis.iter().all(|v| *v == 0.0));
    let s0 = welch(
        &f0[0].coriolis,
        cfg.sample_rate_hz,
        &WelchOptions::default(),
        None,
    )
    .unwrap();
    assert!(s0.psd.iter().all(|p| *p == 0.0));
    // The stiffness coefficient is the same for every mode and oscillates at 2 f_d.
    assert_eq!(f[0].stiffness_coefficient, f[1].stiffness_coefficient);
}

#[test]
fn contributions_follow_the_paper_definition() {
    let c = contributions(&[1.0, 0.0], &[0.0, 2.0], &[1.0, 1.0], &[2.0, 2.0]);
    assert!(
        (c.euler - 12.5).abs() < 1e-12
            && (c.centrifugal - 50.0).abs() < 1e-12
            && (c.coriolis - 25.0).abs() < 1e-12
    );
    assert_eq!(contributions(&[1.0], &[1.0], &[1.0], &[0.0]).euler, 0.0);
}

#[test]
fn ic_map_cells_equal_direct_simulations() {
    let cfg = SimConfig {
        duration_s: 1.0,
        ..SimConfig::paper()
    };
    let opts = IcMapOptions {
        n_q: 5,
        n_qdot: 4,
        ..Default::default()
    };
    let m = ic_map(&cfg, &opts).unwrap();
    let carried = ic_map(
        &cfg,
        &IcMapOptions {
            attribution: IcAttribution::Carried,
            ..opts
        },
    )
    .unwrap();
    for (r, &v0) in m.qdot0.iter().enumerate() {
        for (c, &q0) in m.q0.iter().enumerate() {
            let run = simulate(&SimConfig {
                initial_conditions: vec![[q0, v0]],
                ..cfg.clone()
            })
            .unwrap();
            let mr = &run.modes[0];
            let direct =
                contributions(&mr.q.euler, &mr.q.centrifugal, &mr.q.coriolis, &mr.q.total).coriolis;
            let got = m.coriolis_percent[r * m.q0.len() + c];
            assert!(
                (got - direct).abs() < 1e-9 * direct.max(1.0),
                "forced at ({q0}, {v0}): {got} vs {direct}"
            );
            let carried_direct: Vec<f64> =
                mr.q.coriolis
                    .iter()
                    .zip(&mr.q.free)
                    .map(|(a, b)| a + b)
                    .collect();
            let cd = contributions(
                &carried_direct,
                &mr.q.centrifugal,
                &mr.q.centrifugal,
                &mr.q.total,
            )
            .euler;
            let gc = carried.coriolis_percent[r * m.q0.len() + c];
            assert!(
                (gc - cd).abs() < 1e-9 * cd.max(1.0),
                "carried at ({q0}, {v0}): {gc} vs {cd}"
            );
        }
    }
    // At zero initial conditions the map equals the plain contribution.
    let plain = simulate(&cfg).unwrap().modes[0]
        .contribution_percent
        .coriolis;
    let centre = ic_map(
        &cfg,
        &IcMapOptions {
            n_q: 1,
            n_qdot: 1,
            q_range: Some([0.0, 0.0]),
            qdot_range: Some([0.0, 0.0]),
            ..Default::default()
        },
    )
    .unwrap();
    assert!((centre.coriolis_percent[0] - plain).abs() < 1e-9);
}

#[test]
fn ic_map_validates_its_options() {
    let cfg = SimConfig::paper();
    let e = ic_map(
        &cfg,
        &IcMapOptions {
            mode: 5,
            ..Default::default()
        },
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("ic_map.mode"), "{e}");
    let e = ic_map(
        &cfg,
        &IcMapOptions {
            n_q: 10_000,
            n_qdot: 10_000,
            ..Default::default()
        },
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("ic_map.n_q"), "{e}");
}

#[test]
fn gamma0_sweep_matches_single_runs_and_starts_at_zero_coriolis() {
    let cfg = SimConfig {
        duration_s: 0.6,
        ..SimConfig::paper()
    };
    let mut calls = 0;
    let s = sweep(
        &cfg,
        &SweepOptions {
            param: SweepParam::Gamma0,
            from: 0.0,
            to: 0.3,
            points: 4,
        },
        |d, t| {
            calls += 1;
            assert!(d <= t);
        },
    )
    .unwrap();
    assert_eq!(calls, 4);
    assert_eq!(s.points[0].modes[0].contribution_percent.coriolis, 0.0);
    let single = simulate(&apply(&cfg, SweepParam::Gamma0, 0.2).unwrap()).unwrap();
    let p = &s.points[2];
    assert!((p.value - 0.2).abs() < 1e-15);
    // (0.3 · 2/3 is 0.2 only to rounding, so compare to rounding.)
    let (a, b) = (
        p.modes[0].contribution_percent,
        single.modes[0].contribution_percent,
    );
    for (x, y) in [
        (a.euler, b.euler),
        (a.centrifugal, b.centrifugal),
        (a.coriolis, b.coriolis),
    ] {
        assert!((x - y).abs() < 1e-12 * y, "{a:?} vs {b:?}");
    }
    // Coriolis share grows with γ0 over this range.
    let cor: Vec<f64> = s
        .points
        .iter()
        .map(|p| p.modes[0].contribution_percent.coriolis)
        .collect();
    assert!(cor.windows(2).all(|w| w[1] > w[0]), "{cor:?}");
    let e = sweep(
        &cfg,
        &SweepOptions {
            param: SweepParam::Gamma0,
            from: 0.0,
            to: 0.3,
            points: 1,
        },
        |_, _| {},
    )
    .unwrap_err();
    assert!(e.to_string().contains("sweep.points"));
}

#[test]
fn strain_is_the_modal_sum() {
    let r = simulate(&SimConfig {
        duration_s: 0.3,
        ..SimConfig::paper()
    })
    .unwrap();
    let s = r.strain.as_ref().unwrap();
    assert_eq!(s.point, "P");
    for i in (0..r.t.len()).step_by(97) {
        let (q1, q2) = (r.modes[0].q.total[i], r.modes[1].q.total[i]);
        assert!(
            (s.gamma_xy[i] - (691.0 * q1 + 1710.0 * q2)).abs()
                < 1e-12 * s.gamma_xy[i].abs().max(1e-9)
        );
        assert!(
            (s.eps_y[i] - (-1577.0 * q1 + 96.7 * q2)).abs() < 1e-12 * s.eps_y[i].abs().max(1e-9)
        );
    }
    assert!(max_abs(&s.eps_x) > 0.0);
}
