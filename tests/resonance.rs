//! The resonance map (src/analysis/resonance.rs) against: the simulation's own Floquet summary,
//! Mathieu theory for the first parametric-instability tongue, a monodromy matrix integrated here
//! with classical RK4 (no code shared with the crate's solver), and the no-rotation limit.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use std::f64::consts::PI;
use std::time::Instant;
use wingbeat::analysis::resonance::{
    resonance_map, ResonanceOptions, MAX_ALPHA0_VALUES, MAX_POINTS,
};
use wingbeat::analysis::sweep::{apply, SweepParam};
use wingbeat::config::SimConfig;
use wingbeat::error::WingbeatError;
use wingbeat::kinematics::Kinematics;
use wingbeat::model::Mode;
use wingbeat::simulate::simulate;

fn opts(from_hz: f64, to_hz: f64, points: usize, alpha0: Option<Vec<f64>>) -> ResonanceOptions {
    ResonanceOptions {
        from_hz,
        to_hz,
        points,
        alpha0_values: alpha0,
    }
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}

/// One mode with no a_k (no forcing: only the homogeneous equation matters here).
fn bare_mode(freq_hz: f64, zeta: f64) -> Mode {
    Mode {
        name: "bare".into(),
        freq_hz,
        a: [0.0, 0.0],
        zeta,
        strains: vec![],
    }
}

#[test]
fn every_point_equals_the_simulations_floquet_summary() {
    let mut cfg = SimConfig::paper();
    cfg.duration_s = 0.1; // only the Floquet summary is compared
    let alpha0 = vec![0.4, 0.8];
    let o = opts(5.0, 60.0, 12, Some(alpha0.clone()));
    let mut calls = Vec::new();
    let map = resonance_map(&cfg, &o, |i, n| calls.push((i, n))).unwrap();
    assert_eq!(calls.len(), 24);
    assert_eq!(calls.last(), Some(&(24, 24)));
    assert!(calls.windows(2).all(|w| w[1].0 == w[0].0 + 1));
    assert_eq!(map.flap_hz.len(), 12);
    assert_eq!(map.flap_hz[0], 5.0);
    assert_eq!(map.flap_hz[11], 60.0);
    assert_eq!(map.alpha0.as_deref(), Some(&alpha0[..]));
    let mut unstable = 0;
    for (r, &a) in alpha0.iter().enumerate() {
        for (j, &f) in map.flap_hz.iter().enumerate() {
            let c = apply(
                &apply(&cfg, SweepParam::Alpha0, a).unwrap(),
                SweepParam::FlapHz,
                f,
            )
            .unwrap();
            let sim = simulate(&c).unwrap();
            let idx = r * map.flap_hz.len() + j; // row-major [alpha0][flap_hz]
            for (k, m) in map.modes.iter().enumerate() {
                let fl = &sim.modes[k].floquet;
                assert_eq!(m.freq_hz, cfg.modes[k].freq_hz);
                assert!(
                    rel(m.effective_freq_hz[idx], fl.effective_freq_hz) <= 1e-12,
                    "f_eff α0={a} f={f} k={k}"
                );
                assert!(
                    rel(m.max_modulus[idx], fl.max_modulus) <= 1e-12,
                    "|λ| α0={a} f={f} k={k}: {} vs {}",
                    m.max_modulus[idx],
                    fl.max_modulus
                );
                match (m.beat_period_s[idx], fl.beat_period_s) {
                    (Some(x), Some(y)) => assert!(rel(x, y) <= 1e-12, "beat α0={a} f={f} k={k}"),
                    (x, y) => assert_eq!(x, y),
                }
                assert_eq!(m.beat_harmonic[idx], fl.beat_harmonic);
                assert_eq!(m.stable[idx], fl.stable);
                unstable += usize::from(!m.stable[idx]);
            }
        }
    }
    // The paper's wing at 60 Hz with α0 = 0.8 softens past zero stiffness: the grid does include
    // unstable points, so both branches of the comparison ran.
    assert!(unstable > 0);
}

/// Monodromy over one flap period of q̈ + 2ζω q̇ + [ω² − (α̇² cos²β + β̇²)] q = 0 with
/// α = α0 sin ω_d t, β = β0 sin ω_d t, integrated with classical RK4 from (1, 0) and (0, 1).
fn rk4_monodromy(f_k: f64, zeta: f64, f_d: f64, alpha0: f64, beta0: f64, steps: usize) -> [f64; 4] {
    let w = 2.0 * PI * f_k;
    let wd = 2.0 * PI * f_d;
    let stiff = |t: f64| {
        let (s, c) = (wd * t).sin_cos();
        let ad = alpha0 * wd * c;
        let bd = beta0 * wd * c;
        let b = beta0 * s;
        w * w - (ad * ad * b.cos() * b.cos() + bd * bd)
    };
    let rhs = |t: f64, x: [f64; 2]| [x[1], -2.0 * zeta * w * x[1] - stiff(t) * x[0]];
    let period = 1.0 / f_d;
    let h = period / steps as f64;
    let mut cols = [[1.0, 0.0], [0.0, 1.0]];
    for x in &mut cols {
        for i in 0..steps {
            let t = i as f64 * h;
            let k1 = rhs(t, *x);
            let k2 = rhs(
                t + h / 2.0,
                [x[0] + h / 2.0 * k1[0], x[1] + h / 2.0 * k1[1]],
            );
            let k3 = rhs(
                t + h / 2.0,
                [x[0] + h / 2.0 * k2[0], x[1] + h / 2.0 * k2[1]],
            );
            let k4 = rhs(t + h, [x[0] + h * k3[0], x[1] + h * k3[1]]);
            for d in 0..2 {
                x[d] += h / 6.0 * (k1[d] + 2.0 * k2[d] + 2.0 * k3[d] + k4[d]);
            }
        }
    }
    [cols[0][0], cols[1][0], cols[0][1], cols[1][1]]
}

fn max_modulus(m: [f64; 4]) -> f64 {
    let tr = m[0] + m[3];
    let det = m[0] * m[3] - m[1] * m[2];
    let disc = tr * tr - 4.0 * det;
    if disc >= 0.0 {
        ((tr.abs() + disc.sqrt()) / 2.0).abs()
    } else {
        det.sqrt()
    }
}

#[test]
fn multipliers_and_effective_frequency_match_an_independent_rk4_monodromy() {
    // The paper's wing, its kinematics (β enters the stiffness through cos²β and β̇²), with
    // damping on mode 2, over stable and unstable flap frequencies.
    let mut cfg = SimConfig::paper();
    cfg.modes[1].zeta = 0.02;
    let map = resonance_map(&cfg, &opts(10.0, 60.0, 11, None), |_, _| {}).unwrap();
    let mut checked_trace = 0;
    for (j, &f) in map.flap_hz.iter().enumerate() {
        for (k, mode) in cfg.modes.iter().enumerate() {
            let m = rk4_monodromy(mode.freq_hz, mode.zeta, f, 0.8, 0.5, 20_000);
            let got = map.modes[k].max_modulus[j];
            assert!(
                rel(got, max_modulus(m)) < 1e-9,
                "f={f} k={k}: {got} vs RK4 {}",
                max_modulus(m)
            );
            // Undamped and stable: the multipliers are e^(±2πi f_eff / f_d), so the trace of
            // the monodromy is 2 cos(2π f_eff / f_d) whatever branch f_eff was taken on.
            if mode.zeta == 0.0 && map.modes[k].stable[j] {
                let f_eff = map.modes[k].effective_freq_hz[j];
                let half_trace = 0.5 * (m[0] + m[3]);
                assert!(
                    (half_trace - (2.0 * PI * f_eff / f).cos()).abs() < 1e-8,
                    "f={f} k={k}: tr/2 {half_trace} vs cos {}",
                    (2.0 * PI * f_eff / f).cos()
                );
                checked_trace += 1;
            }
        }
    }
    assert!(checked_trace >= 5);
}

#[test]
fn the_first_mathieu_tongue_is_where_theory_puts_it() {
    // β = γ = 0, α = α0 sin ω_d t: the stiffness is ω² − α0² ω_d² cos² ω_d t, i.e. with
    // τ = ω_d t the Mathieu equation q'' + (a − 2 q_m cos 2τ) q = 0 with
    // a = (ω/ω_d)² − α0²/2 and q_m = α0²/4. Its first instability tongue is
    // 1 − q_m < a < 1 + q_m to first order in q_m (the next terms are −q_m²/8 on both edges),
    // where the free response grows by e^(2π μ) per flap with μ ≈ ½ √(q_m² − (a − 1)²).
    let f_k = 50.0;
    let alpha0: f64 = 0.2;
    let qm = alpha0 * alpha0 / 4.0;
    let cfg = SimConfig {
        kinematics: Kinematics::sinusoidal(25.0, alpha0, 0.0, 0.0),
        modes: vec![bare_mode(f_k, 0.0)],
        ..SimConfig::paper()
    };
    let map = resonance_map(&cfg, &opts(48.5, 50.5, 401, None), |_, _| {}).unwrap();
    let m = &map.modes[0];
    let margin = 2e-4; // ≫ q_m²/8 = 1.25e-5, ≪ the tongue width 2 q_m = 0.02
    let (mut inside, mut outside) = (0, 0);
    let mut centre = (f64::INFINITY, 0.0, 0.0);
    for (j, &f) in map.flap_hz.iter().enumerate() {
        let a = (f_k / f).powi(2) - alpha0 * alpha0 / 2.0;
        let d = a - 1.0;
        if d.abs() < qm - margin {
            assert!(!m.stable[j], "f_d = {f}: a = {a} is inside the tongue");
            assert!(m.max_modulus[j] > 1.0 + 1e-6);
            inside += 1;
            if d.abs() < centre.0 {
                centre = (d.abs(), m.max_modulus[j], f);
            }
        } else if d.abs() > qm + margin {
            assert!(m.stable[j], "f_d = {f}: a = {a} is outside the tongue");
            assert!((m.max_modulus[j] - 1.0).abs() < 1e-9);
            outside += 1;
        }
    }
    assert!(inside > 50 && outside > 100, "{inside} {outside}");
    // Growth at the tongue's centre: ln|λ| / 2π ≈ q_m / 2 (first order; relative error O(q_m)).
    let mu = centre.1.ln() / (2.0 * PI);
    assert!(
        rel(mu, qm / 2.0) < 0.05,
        "μ = {mu} vs {} at {} Hz",
        qm / 2.0,
        centre.2
    );
    // Inside the tongue the free response locks to half the parametric frequency: f_eff = f_d.
    for (j, &f) in map.flap_hz.iter().enumerate() {
        if !m.stable[j] {
            assert!(rel(m.effective_freq_hz[j], f) < 1e-9, "f_d = {f}");
        }
    }
}

#[test]
fn without_rotation_the_effective_frequency_is_the_natural_one() {
    // β = γ = 0 and α0 → 0: the softening α̇² vanishes and f_eff → f_k; for small α0 it follows
    // the averaged stiffness, f_eff² ≈ f_k² − α0² f_d² / 2, to second order in α0.
    let mut cfg = SimConfig::paper();
    cfg.kinematics = Kinematics::sinusoidal(25.0, 0.8, 0.0, 0.0);
    let alpha0 = vec![0.0, 0.01, 0.02, 0.05, 0.1];
    let map = resonance_map(&cfg, &opts(10.0, 40.0, 7, Some(alpha0.clone())), |_, _| {}).unwrap();
    let n = map.flap_hz.len();
    for (k, m) in map.modes.iter().enumerate() {
        let f_k = cfg.modes[k].freq_hz;
        for (j, &f) in map.flap_hz.iter().enumerate() {
            assert!(rel(m.effective_freq_hz[j], f_k) < 1e-10, "α0 = 0, f = {f}");
            assert!((m.max_modulus[j] - 1.0).abs() < 1e-10);
            let mut last = 0.0;
            for (r, &a) in alpha0.iter().enumerate().skip(1) {
                let fe = m.effective_freq_hz[r * n + j];
                let gap = f_k - fe;
                assert!(
                    gap > last,
                    "the softening grows with α0 (α0 = {a}, f = {f})"
                );
                last = gap;
                let averaged = (f_k * f_k - a * a * f * f / 2.0).sqrt();
                assert!(
                    (fe - averaged).abs() < 10.0 * a.powi(4) * f,
                    "α0 = {a}, f = {f}: {fe} vs {averaged}"
                );
            }
        }
    }
    // Zero yaw and roll, but any flap frequency: still f_k (the forcing does not matter).
    cfg.kinematics = Kinematics::sinusoidal(25.0, 0.0, 0.0, 0.0);
    let map = resonance_map(&cfg, &opts(5.0, 60.0, 5, None), |_, _| {}).unwrap();
    for (k, m) in map.modes.iter().enumerate() {
        for &fe in &m.effective_freq_hz {
            assert!(rel(fe, cfg.modes[k].freq_hz) < 1e-10);
        }
    }
}

#[test]
fn caps_and_bad_options_are_named_before_any_work() {
    let cfg = SimConfig::paper();
    let field = |e: WingbeatError| match e {
        WingbeatError::InvalidInput { field, .. } | WingbeatError::ResourceCap { field, .. } => {
            field
        }
        other => panic!("{other:?}"),
    };
    let never = |_: usize, _: usize| panic!("no work before the checks");
    for (o, want) in [
        (opts(5.0, 60.0, 1, None), "resonance.points"),
        (opts(5.0, 60.0, MAX_POINTS + 1, None), "resonance.points"),
        (opts(0.0, 60.0, 10, None), "resonance.from_hz"),
        (opts(5.0, f64::NAN, 10, None), "resonance.to_hz"),
        (opts(5.0, 60.0, 10, Some(vec![])), "resonance.alpha0_values"),
        (
            opts(5.0, 60.0, 10, Some(vec![0.1; MAX_ALPHA0_VALUES + 1])),
            "resonance.alpha0_values",
        ),
        (
            opts(5.0, 60.0, 10, Some(vec![0.1, 7.0])),
            "resonance.alpha0_values[1]",
        ),
    ] {
        assert_eq!(field(resonance_map(&cfg, &o, never).unwrap_err()), want);
    }
    // The work cap: a 20 kHz mode against flap frequencies down to 0.5 Hz.
    let mut stiff = cfg.clone();
    stiff.modes[1].freq_hz = 2.0e4;
    let t0 = Instant::now();
    let e = resonance_map(&stiff, &opts(0.5, 60.0, MAX_POINTS, None), never).unwrap_err();
    assert!(matches!(e, WingbeatError::ResourceCap { .. }), "{e}");
    assert!(e.to_string().contains("resonance"), "{e}");
    assert!(t0.elapsed().as_secs_f64() < 2.0);
    // A bad base config is the config's error.
    let mut bad = cfg;
    bad.modes[0].zeta = -1.0;
    assert_eq!(
        field(resonance_map(&bad, &opts(5.0, 60.0, 10, None), never).unwrap_err()),
        "modes[0].zeta"
    );
    // Unknown option fields are rejected when parsed.
    let e = serde_json::from_str::<ResonanceOptions>(
        r#"{"from_hz": 5, "to_hz": 60, "points": 10, "alpha_values": [0.1]}"#,
    )
    .unwrap_err();
    assert!(e.to_string().contains("alpha_values"), "{e}");
}

#[test]
fn two_hundred_points_are_fast() {
    let cfg = SimConfig::paper();
    let t0 = Instant::now();
    let map = resonance_map(&cfg, &opts(5.0, 60.0, 200, None), |_, _| {}).unwrap();
    let dt = t0.elapsed().as_secs_f64();
    println!("resonance map, 200 points x 2 modes (paper wing, 5-60 Hz): {dt:.3} s");
    assert_eq!(map.modes[0].effective_freq_hz.len(), 200);
    assert!(dt < 30.0);
    // At the paper's 25 Hz: mode 1 at 60.31 Hz beats against 2 f_d every 0.0970 s
    // (tests/lab_constants.rs).
    let map = resonance_map(&cfg, &opts(25.0, 30.0, 2, None), |_, _| {}).unwrap();
    let m1 = &map.modes[0];
    assert!(rel(m1.effective_freq_hz[0], 6.030639396854428e1) < 1e-9);
    assert_eq!(m1.beat_harmonic[0], 2);
    assert!(rel(m1.beat_period_s[0].unwrap(), 9.70271467452204e-2) < 1e-9);
}
