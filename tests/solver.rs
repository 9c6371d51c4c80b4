//! The solvers against closed forms, against each other, and at their theoretical orders.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use nalgebra::Vector2;
use std::f64::consts::PI;
use wingbeat::config::SimConfig;
use wingbeat::simulate::simulate;
use wingbeat::solve::{gauss, propagator::propagate, rk4, ModalOde};

#[test]
fn undamped_forced_oscillator_beats_exactly_as_the_closed_form() {
    // q̈ + ω² q = F cos Ω t from rest: q = F/(ω² − Ω²) (cos Ω t − cos ω t) — a beat.
    let (w, wf, f) = (2.0 * PI * 60.3, 2.0 * PI * 50.0, 0.7);
    let ode = ConstOsc {
        w,
        c: 0.0,
        f,
        g: 0.0,
        wf,
    };
    let dt = 1e-4;
    let n = 30_001; // 3 s, many beat periods
    let p = propagate(&ode, dt, n).unwrap();
    let amp = f / (w * w - wf * wf);
    let mut worst = 0.0_f64;
    for i in 0..n {
        let t = i as f64 * dt;
        let exact = amp * ((wf * t).cos() - (w * t).cos());
        let exact_v = amp * (-wf * (wf * t).sin() + w * (w * t).sin());
        worst = worst.max((p.q[0][i] - exact).abs() / amp.abs());
        worst = worst.max((p.qdot[0][i] - exact_v).abs() / (amp.abs() * w));
    }
    assert!(worst < 1e-10, "max relative error {worst:e}");
    assert!(p.period_error < 1e-9);
}

#[test]
fn damped_free_vibration_matches_closed_form() {
    let (w, z) = (2.0 * PI * 62.5, 0.01);
    let ode = ConstOsc {
        w,
        c: 2.0 * z * w,
        f: 0.0,
        g: 0.0,
        wf: 2.0 * PI * 25.0,
    };
    let p = propagate(&ode, 1e-4, 20_001).unwrap();
    let wd = w * (1.0 - z * z).sqrt();
    for i in (0..20_001).step_by(37) {
        let t = i as f64 * 1e-4;
        let e = (-z * w * t).exp();
        let h1 = e * ((wd * t).cos() + z * w / wd * (wd * t).sin());
        let h2 = e * (wd * t).sin() / wd;
        assert!((p.h_q[0][i] - h1).abs() < 1e-11, "h1 at {t}");
        assert!((p.h_q[1][i] - h2).abs() < 1e-11 / w, "h2 at {t}");
    }
}

#[test]
fn incommensurate_output_grid_is_handled_exactly() {
    // 7777 Hz output does not divide the 25 Hz period: every sample gets its own phase.
    let (w, wf, g) = (2.0 * PI * 41.0, 2.0 * PI * 25.0, 1.3);
    let ode = ConstOsc {
        w,
        c: 0.0,
        f: 0.0,
        g,
        wf,
    };
    let dt = 1.0 / 7777.0;
    let p = propagate(&ode, dt, 7000).unwrap();
    let amp = g / (w * w - wf * wf);
    for i in (0..7000).step_by(13) {
        let t = i as f64 * dt;
        let exact = amp * ((wf * t).sin() - wf / w * (w * t).sin());
        assert!((p.q[1][i] - exact).abs() < 1e-10 * amp.abs(), "sample {i}");
    }
}

fn observed_order(errors: &[f64]) -> Vec<f64> {
    errors.windows(2).map(|e| (e[0] / e[1]).log2()).collect()
}

#[test]
fn gauss_legendre_converges_at_order_eight() {
    let ode = Mathieu {
        a: 2.3,
        q: 0.4,
        c: 0.05,
    };
    let t_end = 2.0 * PI;
    let x0 = Vector2::new(1.0, -0.5);
    let reference = gauss::integrate(&ode, 0.0, t_end / 1024.0, 1024, x0)[0];
    let errs: Vec<f64> = [8usize, 16, 32]
        .iter()
        .map(|&n| (gauss::integrate(&ode, 0.0, t_end / n as f64, n, x0)[0] - reference).norm())
        .collect();
    let orders = observed_order(&errs);
    for o in &orders {
        assert!(
            (*o - 8.0).abs() < 0.6,
            "observed orders {orders:?}, errors {errs:?}"
        );
    }
}

#[test]
fn rk4_converges_at_order_four() {
    let ode = Mathieu {
        a: 2.3,
        q: 0.4,
        c: 0.05,
    };
    let t_end = 2.0 * PI;
    let reference = gauss::integrate(&ode, 0.0, t_end / 1024.0, 1024, Vector2::new(1.0, -0.5))[0];
    let errs: Vec<f64> = [40usize, 80, 160]
        .iter()
        .map(|&m| {
            let out = rk4::solve(&ode, 1.0, -0.5, t_end, 2, m);
            ((out[0].0[1] - reference[0]).powi(2) + (out[0].1[1] - reference[1]).powi(2)).sqrt()
        })
        .collect();
    for o in observed_order(&errs) {
        assert!((o - 4.0).abs() < 0.3, "observed order {o}, errors {errs:?}");
    }
}

#[test]
fn propagator_agrees_with_rk4_on_the_paper_case() {
    let cfg = SimConfig::paper();
    let kin = cfg.kinematics.compile();
    for mode in &cfg.modes {
        let ode = ModalOde::new(&kin, mode);
        let p = propagate(&ode, 1e-4, 20_001).unwrap();
        let r = rk4::solve(&ode, 0.0, 0.0, 1e-4, 20_001, 8);
        for (col, (rq, _)) in r.iter().enumerate() {
            let scale = max_abs(&p.q[col]);
            let d = max_diff(&p.q[col], rq);
            assert!(
                d < 1e-8 * scale,
                "mode {} column {col}: max diff {d:e} vs scale {scale:e}",
                mode.name
            );
        }
    }
}

#[test]
fn partial_responses_add_up_to_the_total() {
    let mut cfg = SimConfig::paper();
    cfg.initial_conditions = vec![[3e-4, -0.05], [1e-4, 0.02]];
    let r = simulate(&cfg).unwrap();
    for m in &r.modes {
        let scale = max_abs(&m.q.total);
        for i in 0..r.t.len() {
            let s = m.q.euler[i] + m.q.centrifugal[i] + m.q.coriolis[i] + m.q.free[i];
            assert!((s - m.q.total[i]).abs() < 1e-12 * scale, "sample {i}");
        }
    }
}

#[test]
fn no_rotation_no_response() {
    let mut cfg = SimConfig::paper();
    cfg.kinematics = wingbeat::kinematics::Kinematics::sinusoidal(25.0, 0.0, 0.0, 0.0);
    let r = simulate(&cfg).unwrap();
    for m in &r.modes {
        assert!(m.q.total.iter().all(|v| *v == 0.0));
        assert!((m.floquet.effective_freq_hz - m.freq_hz).abs() < 1e-9 * m.freq_hz);
    }
}

#[test]
fn responses_are_affine_in_yaw_amplitude_and_odd_in_a() {
    use wingbeat::analysis::sweep::{apply, SweepParam};
    let base = SimConfig {
        duration_s: 0.5,
        ..SimConfig::paper()
    };
    let r: Vec<_> = [0.0, 0.1, 0.2]
        .iter()
        .map(|&g| simulate(&apply(&base, SweepParam::Gamma0, g).unwrap()).unwrap())
        .collect();
    for k in 0..2 {
        let scale = max_abs(&r[2].modes[k].q.total);
        for i in 0..r[0].t.len() {
            // Second difference of an affine function vanishes.
            let d2 = r[2].modes[k].q.total[i] - 2.0 * r[1].modes[k].q.total[i]
                + r[0].modes[k].q.total[i];
            assert!(d2.abs() < 1e-12 * scale);
            // Coriolis is linear (through zero) in γ0.
            assert!(
                (r[2].modes[k].q.coriolis[i] - 2.0 * r[1].modes[k].q.coriolis[i]).abs()
                    < 1e-12 * scale
            );
        }
        assert!(r[0].modes[k].q.coriolis.iter().all(|v| *v == 0.0));
    }
    // Flipping a (and so b) flips every response.
    let mut neg = base.clone();
    neg.modes.iter_mut().for_each(|m| m.a = [-m.a[0], -m.a[1]]);
    let (p, n) = (simulate(&base).unwrap(), simulate(&neg).unwrap());
    for k in 0..2 {
        assert!(p.modes[k]
            .q
            .total
            .iter()
            .zip(&n.modes[k].q.total)
            .all(|(a, b)| (a + b).abs() <= 1e-15 * a.abs().max(1e-300)));
    }
}

#[test]
fn cosine_phases_differ_from_sines_and_period_map_error_is_small() {
    // Phases are honoured: α with a 90° phase changes the response.
    let base = SimConfig {
        duration_s: 0.2,
        ..SimConfig::paper()
    };
    let mut shifted = base.clone();
    shifted.kinematics.alpha = wingbeat::kinematics::Angle::Fourier {
        mean: 0.0,
        harmonics: vec![wingbeat::kinematics::Harmonic {
            n: 1,
            amplitude: 0.8,
            phase: PI / 2.0,
        }],
    };
    let (a, b) = (simulate(&base).unwrap(), simulate(&shifted).unwrap());
    assert!(
        max_diff(&a.modes[0].q.total, &b.modes[0].q.total) > 0.1 * max_abs(&a.modes[0].q.total)
    );
    for m in &a.modes {
        assert!(
            m.accuracy.period_error_estimate < 1e-8,
            "{}",
            m.accuracy.period_error_estimate
        );
    }
}

/// A run writing into series handed back by other runs (longer, shorter, with and without an
/// initial state, with strains) gives exactly the numbers of a fresh run, and takes its memory
/// from the pool instead of allocating.
#[test]
fn a_run_into_recycled_series_equals_a_fresh_run() {
    use wingbeat::pool::SeriesPool;
    use wingbeat::simulate::simulate_reusing;
    let mut long = SimConfig::paper();
    long.duration_s = 3.0;
    long.initial_conditions = vec![[1e-6, 0.0], [0.0, 2e-4]];
    let mut short = SimConfig::paper();
    short.duration_s = 0.3;
    short.kinematics.flap_freq_hz = 25.5;
    let paper = SimConfig::paper();
    let mut pool = SeriesPool::new();
    // The longest run first: every later run finds room in its series and hands the same
    // number back (t, 6 per mode — the aerodynamic one is empty in a vacuum — and 3 strains).
    let held = 1 + 6 * 2 + 3;
    for cfg in [&long, &short, &paper, &long, &paper] {
        let r = simulate_reusing(cfg, &mut pool).unwrap();
        assert!(pool.is_empty(), "the run took every spare series");
        let fresh = simulate(cfg).unwrap();
        assert_eq!(r, fresh);
        r.recycle(&mut pool);
        assert_eq!(pool.len(), held);
    }
}
