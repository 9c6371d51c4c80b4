//! The step size is chosen so that one period's integration errs by at most
//! 1e-11 (relative) for stiff modes and rich kinematics, and the dense output used on
//! incommensurate sample grids is as exact as the per-sample checkpoints. References are
//! independent integrations with four times as many Gauss–Legendre steps (error 4⁸ ≈ 6.5e4
//! times smaller), so a sign or factor error anywhere shows up many orders above the bounds.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use nalgebra::{Matrix2, Vector2};
use wingbeat::config::SimConfig;
use wingbeat::kinematics::{Angle, Compiled, Harmonic, Kinematics};
use wingbeat::model::Mode;
use wingbeat::simulate::{commensurate_sample_rate, simulate};
use wingbeat::solve::propagator::{max_step, period_map, propagate};
use wingbeat::solve::{gauss, LinearOde, ModalOde};

/// Modes of an FE-like set reaching 1.2 kHz (the 650–1200 Hz case), a-vectors of the
/// paper's size with varied directions.
fn stiff_modes() -> Vec<Mode> {
    [62.5, 86.9, 240.0, 410.0, 650.0, 820.0, 1000.0, 1200.0]
        .iter()
        .enumerate()
        .map(|(k, &f)| Mode {
            name: format!("{f} Hz"),
            freq_hz: f,
            a: [
                0.75e-5 * (0.7 * k as f64).cos(),
                0.3e-5 * (1.3 * k as f64).sin(),
            ],
            zeta: if k % 2 == 0 { 0.0 } else { 0.01 },
            strains: vec![],
        })
        .collect()
}

/// A 20-harmonic kinematics: every angle a mean-free Fourier series to n = 20 with amplitudes
/// decaying like 1/n², phases spread.
fn twenty_harmonics() -> Kinematics {
    let series = |amp: f64, ph: f64| Angle::Fourier {
        mean: 0.0,
        harmonics: (1..=20)
            .map(|n| Harmonic {
                n,
                amplitude: amp / (n * n) as f64,
                phase: ph * n as f64,
            })
            .collect(),
    };
    Kinematics {
        flap_freq_hz: 25.0,
        alpha: series(0.8, 0.3),
        beta: series(0.4, 1.1),
        gamma: series(0.15, 2.0),
        body_rate: Default::default(),
    }
}

/// Relative one-period errors of `period_map` against a 4× finer integration: monodromy in the
/// scaled norm (q, q̇/ω) and each particular solution; and the map's own estimate.
fn one_period_errors(kin: &Compiled, mode: &Mode) -> (f64, f64) {
    let ode = ModalOde::new(kin, mode);
    let t = ode.period();
    // 64 checkpoints give each particular solution's size over the period (its end value
    // alone can be tiny by cancellation, so the relative error refers to the size).
    let phases: Vec<f64> = (0..64).map(|j| j as f64 * t / 64.0).collect();
    let map = period_map(&ode, t, &phases);
    let steps = (t / max_step(&ode, t)).round() as usize * 4;
    let h = t / steps as f64;
    let e1 = gauss::integrate(&ode, 0.0, h, steps, Vector2::new(1.0, 0.0));
    let e2 = gauss::integrate(&ode, 0.0, h, steps, Vector2::new(0.0, 1.0));
    let zero = gauss::integrate(&ode, 0.0, h, steps, Vector2::zeros());
    // Columns of Φ(T): the forced parts are the same in e1, e2 (zero for the homogeneous
    // columns only when subtracting the particular solution).
    let col = |x: Vector2<f64>, p: Vector2<f64>| x - p;
    let j = ModalOde::TOTAL;
    let m_ref = Matrix2::from_columns(&[col(e1[j], zero[j]), col(e2[j], zero[j])]);
    let w = ode.freq_scale();
    let s = Matrix2::new(1.0, 0.0, 0.0, 1.0 / w);
    let u = Matrix2::new(1.0, 0.0, 0.0, w);
    let mut err = (s * (map.monodromy - m_ref) * u).norm() / (s * m_ref * u).norm();
    for (jj, z) in zero.iter().enumerate() {
        let size = map
            .part
            .iter()
            .map(|p| (s * p[jj]).norm())
            .fold((s * z).norm(), f64::max);
        let d = (s * (map.part_end[jj] - z)).norm() / size;
        err = err.max(d);
    }
    (err, map.error_estimate)
}

#[test]
fn one_period_error_is_below_1e_11_for_modes_to_1200_hz() {
    let kin = Kinematics::paper_forward_flight().compile();
    for m in &stiff_modes() {
        let (err, est) = one_period_errors(&kin, m);
        println!("{:>8} Hz: error {err:.2e}, estimate {est:.2e}", m.freq_hz);
        assert!(err <= 1e-11, "{} Hz: one-period error {err:e}", m.freq_hz);
        assert!(est <= 1e-11, "{} Hz: estimate {est:e}", m.freq_hz);
    }
}

#[test]
fn one_period_error_is_below_1e_11_under_20_harmonic_kinematics() {
    let k = twenty_harmonics();
    k.validate().unwrap();
    let kin = k.compile();
    for m in stiff_modes().iter().step_by(3) {
        let (err, est) = one_period_errors(&kin, m);
        println!(
            "{:>8} Hz, 20 harmonics: error {err:.2e}, estimate {est:.2e}",
            m.freq_hz
        );
        assert!(err <= 1e-11, "{} Hz: one-period error {err:e}", m.freq_hz);
        assert!(est <= 1e-11, "{} Hz: estimate {est:e}", m.freq_hz);
    }
}

#[test]
fn simulate_reports_the_error_estimate_and_matches_a_finer_run() {
    // The whole run on the stiff set, 0.2 s at 20 kHz: every mode's estimate is in the output,
    // and the samples agree with a direct fine integration (4× the steps, per sample interval).
    let cfg = SimConfig {
        modes: stiff_modes(),
        duration_s: 0.2,
        sample_rate_hz: 20_000.0,
        ..SimConfig::paper()
    };
    let r = simulate(&cfg).unwrap();
    let kin = cfg.kinematics.compile();
    for (m, res) in cfg.modes.iter().zip(&r.modes) {
        let est = res.accuracy.period_error_estimate;
        assert!(est > 0.0 && est <= 1e-11, "{}: estimate {est:e}", m.name);
        assert_eq!(res.accuracy.periods, 6); // samples 0..=4000 reach t = 0.2 s = 5 T
        let ode = ModalOde::new(&kin, m);
        let dt = 1.0 / cfg.sample_rate_hz;
        let sub = ((dt / max_step(&ode, ode.period())).ceil() as usize).max(1) * 4;
        let mut x: Vector2<f64> = Vector2::zeros();
        let mut worst = 0.0_f64;
        let peak = max_abs(&res.q.total);
        for i in 0..r.t.len() {
            worst = worst.max((x[0] - res.q.total[i]).abs() / peak);
            x = gauss::integrate(&ode, i as f64 * dt, dt / sub as f64, sub, x)[ModalOde::TOTAL];
            // integrate starts every column from x; the total column is the one wanted.
        }
        println!(
            "{}: max |Δq| / peak = {worst:.2e} (estimate {est:.1e})",
            m.name
        );
        assert!(worst <= 1e-12, "{}: {worst:e}", m.name);
    }
}

#[test]
fn dense_output_on_an_incommensurate_grid_matches_per_sample_checkpoints() {
    // 25.5 Hz flap at 10 kHz: the grid does not divide the period, simulate takes the dense
    // path; propagate() integrates to every sample phase. Both must agree to 1e-12 of the peak.
    let mut cfg = SimConfig {
        duration_s: 0.5,
        ..SimConfig::paper()
    };
    cfg.kinematics.flap_freq_hz = 25.5;
    cfg.modes.push(stiff_modes()[7].clone());
    cfg.initial_conditions = vec![[1e-6, -2e-3], [0.0, 0.0], [2e-7, 0.0]];
    let r = simulate(&cfg).unwrap();
    assert!(r.modes[0].accuracy.method.contains("dense"));
    let kin = cfg.kinematics.compile();
    let dt = 1.0 / cfg.sample_rate_hz;
    for (k, (m, res)) in cfg.modes.iter().zip(&r.modes).enumerate() {
        let p = propagate(&ModalOde::new(&kin, m), dt, r.t.len()).unwrap();
        let [q0, v0] = cfg.ic(k);
        for (col, got) in [
            (ModalOde::EULER, &res.q.euler),
            (ModalOde::CENTRIFUGAL, &res.q.centrifugal),
            (ModalOde::CORIOLIS, &res.q.coriolis),
        ] {
            let d = max_diff(&p.q[col], got) / max_abs(&p.q[col]);
            assert!(d < 1e-12, "{} column {col}: {d:e}", m.name);
        }
        let total: Vec<f64> = (0..r.t.len())
            .map(|i| p.q[ModalOde::TOTAL][i] + q0 * p.h_q[0][i] + v0 * p.h_q[1][i])
            .collect();
        let qdot: Vec<f64> = (0..r.t.len())
            .map(|i| p.qdot[ModalOde::TOTAL][i] + q0 * p.h_qdot[0][i] + v0 * p.h_qdot[1][i])
            .collect();
        let dq = max_diff(&total, &res.q.total) / max_abs(&total);
        let dv = max_diff(&qdot, &res.qdot_total) / max_abs(&qdot);
        println!("{}: dense vs checkpoints: q {dq:.1e}, q̇ {dv:.1e}", m.name);
        assert!(dq < 1e-12 && dv < 1e-12, "{}: {dq:e} {dv:e}", m.name);
    }
}

#[test]
fn commensurate_sample_rate_snaps_to_whole_samples_per_period() {
    assert_eq!(commensurate_sample_rate(25.5, 10_000.0), 9996.0);
    assert_eq!(commensurate_sample_rate(25.0, 10_000.0), 10_000.0);
    assert_eq!(commensurate_sample_rate(7000.0, 1000.0), 7000.0);
    assert!(commensurate_sample_rate(f64::NAN, 10.0) == 10.0);
    // The snapped grid takes the checkpoint path and agrees with the unsnapped physics.
    let mut cfg = SimConfig {
        duration_s: 0.3,
        ..SimConfig::paper()
    };
    cfg.kinematics.flap_freq_hz = 25.5;
    cfg.sample_rate_hz = commensurate_sample_rate(25.5, 10_000.0);
    let r = simulate(&cfg).unwrap();
    assert!(!r.modes[0].accuracy.method.contains("dense"));
}
