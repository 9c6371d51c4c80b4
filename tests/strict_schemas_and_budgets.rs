//! Bounded and strict inputs: regression tests for the reproductions the core and the CLI
//! now refuse or answer (strict schemas at every level, paths in CLI type errors, compact
//! numbers, a work budget checked before the work, finite analyses).

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use serde_json::Value;
use std::time::{Duration, Instant};
use wingbeat::analysis::beat::{checked_envelope, envelope};
use wingbeat::analysis::contribution::contributions;
use wingbeat::analysis::psd::{welch, WelchOptions};
use wingbeat::analysis::sweep::{sweep, SweepOptions, SweepParam};
use wingbeat::config::SimConfig;
use wingbeat::kinematics::{Angle, DEFAULT_SAMPLED_MAX_HARMONIC};
use wingbeat::modes_doc::{modes_from_json, read_modes_document};
use wingbeat::simulate::{run_cost, simulate, MAX_RUN_WORK};
use wingbeat::WingbeatError;

mod common_cli;
use common_cli::run_timed as run;

fn parse_err(json: &str) -> String {
    SimConfig::from_json(json).expect_err("refused").to_string()
}

#[test]
fn unknown_keys_are_refused_at_every_level() {
    // The issue's case: `damping` instead of `zeta` used to run undamped with exit 0.
    let e = parse_err(r#"{"modes":[{"freq_hz":62.5,"a":[7.5e-6,9.3e-7],"damping":0.05}]}"#);
    assert!(e.contains("modes[0].damping") && e.contains("zeta"), "{e}");
    let e = parse_err(
        r#"{"kinematics":{"flap_freq_hz":25,"flap_hz":30,
        "alpha":{"kind":"fourier"},"beta":{"kind":"fourier"},"gamma":{"kind":"fourier"}}}"#,
    );
    assert!(e.contains("kinematics.flap_hz"), "{e}");
    let e = parse_err(
        r#"{"kinematics":{"flap_freq_hz":25,"alpha":{"kind":"sampled",
        "values":[0,1,0],"times":[0,0.01,0.02]},"beta":{"kind":"fourier"},"gamma":{"kind":"fourier"}}}"#,
    );
    assert!(e.contains("kinematics.alpha") && e.contains("times"), "{e}");
    let e = parse_err(
        r#"{"kinematics":{"flap_freq_hz":25,"alpha":{"kind":"fourier",
        "harmonics":[{"n":1,"amplitude":0.8,"freq":3}]},"beta":{"kind":"fourier"},"gamma":{"kind":"fourier"}}}"#,
    );
    assert!(e.contains("kinematics.alpha") && e.contains("freq"), "{e}");
    let e = parse_err(
        r#"{"modes":[{"freq_hz":62.5,"a":[1,0],"strains":[{"point":"P",
        "eps_x":1,"eps_y":0,"gamma_xy":0,"eps_z":3}]}]}"#,
    );
    assert!(e.contains("modes[0].strains[0].eps_z"), "{e}");
}

#[test]
fn config_type_errors_name_the_field_path() {
    let e = parse_err(r#"{"modes":[{"freq_hz":"fast","a":[1,0]}]}"#);
    assert!(e.contains("`modes[0].freq_hz`"), "{e}");
    let e = parse_err(r#"{"duration_s":"x"}"#);
    assert!(e.contains("`duration_s`"), "{e}");
}

#[test]
fn modes_files_are_strict_but_keep_the_modes_document_keys() {
    let e = modes_from_json(
        r#"{"modes":[{"freq_hz":62.5,"a":[7.5e-6,9.3e-7],"damping":0.05}]}"#,
        "m.json",
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("damping") && e.contains("[0]"), "{e}");
    let e = modes_from_json(
        r#"{"modes":[{"freq_hz":62.5,"a":[1,0]}],"mode":[]}"#,
        "m.json",
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("unknown top-level key `mode`"), "{e}");
    // A document's known keys (units, planform_note, mesh_size_mm, …) are accepted.
    let ok = r#"{"modes":[{"freq_hz":62.5,"a":[1,0]}],"units":{"freq_hz":"Hz"},
        "planform_note":"x","mesh_size_mm":1.0,"kinds":["bending"],"freq_hz":[62.5],"a":[[1,0]]}"#;
    assert_eq!(modes_from_json(ok, "m.json").unwrap().len(), 1);
    assert_eq!(read_modes_document(ok, "m.json").unwrap().modes.len(), 1);
}

#[test]
fn numbers_in_messages_are_compact() {
    let invalid = |json: &str| {
        SimConfig::from_json(json)
            .unwrap()
            .validate()
            .unwrap_err()
            .to_string()
    };
    let e = invalid(r#"{"duration_s":1e308}"#);
    assert!(e.contains("1e308") && e.len() < 200, "{e}");
    let e = invalid(r#"{"sample_rate_hz":5e-324}"#);
    assert!(e.len() < 200 && !e.contains("00000000"), "{e}");
    assert_eq!(wingbeat::error::num(1e308), "1e308");
    assert_eq!(wingbeat::error::num(62.5), "62.5");
}

#[test]
fn cli_negative_values_reach_the_range_check() {
    let (code, _, err, _) = run(&["modes", "--camber", "-0.1"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("`camber`") && err.contains("[0, 0.5]"),
        "{err}"
    );
}

#[test]
fn cli_config_from_a_device_is_capped() {
    if !std::path::Path::new("/dev/zero").exists() {
        return;
    }
    let (code, _, err, dt) = run(&["simulate", "--config", "/dev/zero"]);
    assert_eq!(code, 2);
    assert!(err.contains("64 MiB"), "{err}");
    assert!(dt < Duration::from_secs(10), "{dt:?}");
}

#[test]
fn slow_flap_is_refused_quickly() {
    for args in [
        &["simulate", "--flap-hz", "1e-320"][..],
        &["simulate", "--flap-hz", "1e-3", "--duration", "0.1"][..],
        &[
            "sweep", "flap_hz", "--from", "1e-6", "--to", "1e-6", "--points", "2",
        ][..],
    ] {
        let (code, _, err, dt) = run(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains("flap"), "{args:?}: {err}");
        assert!(dt < Duration::from_secs(10), "{args:?}: {dt:?}");
    }
}

#[test]
fn stiff_modes_are_refused_before_the_work() {
    let stiff = |zeta: f64, flap: f64| {
        let mut c = SimConfig::from_json(&format!(
            r#"{{"modes":[{{"freq_hz":1e5,"a":[1e-6,0],"zeta":{zeta}}}],"duration_s":0.01}}"#
        ))
        .unwrap();
        c.kinematics.flap_freq_hz = flap;
        c
    };
    for (c, field) in [
        (stiff(0.0, 1.0), "modes[0].freq_hz"),
        (stiff(10.0, 25.0), "modes[0].zeta"),
    ] {
        let t0 = Instant::now();
        let e = simulate(&c).unwrap_err();
        assert!(t0.elapsed() < Duration::from_secs(5));
        assert!(matches!(e, WingbeatError::ResourceCap { .. }), "{e}");
        assert!(e.to_string().contains(field), "{e}");
    }
    // The paper case is far inside the budget.
    assert!(run_cost(&SimConfig::paper()).0 < MAX_RUN_WORK / 10.0);
}

fn table(n: usize) -> String {
    let v: Vec<String> = (0..n)
        .map(|j| {
            format!(
                "{:.6}",
                0.8 * (2.0 * std::f64::consts::PI * j as f64 / n as f64).sin()
            )
        })
        .collect();
    format!(
        r#"{{"kinematics":{{"flap_freq_hz":25,"alpha":{{"kind":"sampled","values":[{}]}},
        "beta":{{"kind":"fourier","harmonics":[{{"n":1,"amplitude":0.5}}]}},"gamma":{{"kind":"fourier"}}}},
        "duration_s":0.01}}"#,
        v.join(",")
    )
}

#[test]
fn long_sampled_tables_get_a_default_harmonic_cap() {
    let cfg = SimConfig::from_json(&table(10_000)).unwrap();
    let s = cfg.kinematics.alpha.series();
    assert_eq!(s.terms.len(), DEFAULT_SAMPLED_MAX_HARMONIC as usize);
    let t0 = Instant::now();
    let r = simulate(&cfg).expect("a 10 000-sample table runs");
    assert!(t0.elapsed() < Duration::from_secs(30), "{:?}", t0.elapsed());
    assert!(r.modes[0].q.total.iter().all(|v| v.is_finite()));
    // A short table keeps every harmonic it resolves (the interpolant through the samples).
    let short = Angle::Sampled {
        values: vec![0.0, 1.0, 0.0, -1.0],
        max_harmonic: None,
    };
    assert_eq!(short.series().terms.len(), 2);
}

#[test]
fn sweeps_check_their_total_work_first() {
    let mut cfg = SimConfig::paper();
    cfg.duration_s = 99.0;
    let t0 = Instant::now();
    let e = sweep(
        &cfg,
        &SweepOptions {
            param: SweepParam::Gamma0,
            from: 0.0,
            to: 0.3,
            points: 2001,
        },
        |_, _| {},
    )
    .unwrap_err();
    assert!(t0.elapsed() < Duration::from_secs(5));
    assert!(matches!(e, WingbeatError::ResourceCap { .. }), "{e}");
}

#[test]
fn psd_and_envelope_are_finite_or_refused() {
    let x: Vec<f64> = (0..256).map(|i| (i as f64 * 0.3).sin()).collect();
    let o = WelchOptions::default();
    let e = welch(&x, 5e-324, &o, None).unwrap_err().to_string();
    assert!(e.contains("psd.sample_rate_hz"), "{e}");
    // ±1e308: refused by name (the density itself exceeds f64), never Infinity.
    let big: Vec<f64> = x.iter().map(|v| v * 1e308).collect();
    match welch(&big, 100.0, &o, None) {
        Ok(s) => assert!(s.psd.iter().all(|p| p.is_finite())),
        Err(e) => assert!(e.to_string().contains("psd.series"), "{e}"),
    }
    // 1e150: the squares would overflow unscaled; scaled, the density is finite and exact.
    let mid: Vec<f64> = x.iter().map(|v| v * 1e150).collect();
    let s = welch(&mid, 100.0, &o, None).unwrap();
    let r = welch(&x, 100.0, &o, None).unwrap();
    for (a, b) in s.psd.iter().zip(&r.psd) {
        assert!(a.is_finite());
        assert!((a / 1e300 - b).abs() <= 1e-9 * r.psd.iter().cloned().fold(0.0, f64::max));
    }
    match checked_envelope(&big, "envelope.series") {
        Ok(e) => assert!(e.iter().all(|v| v.is_finite())),
        Err(e) => assert!(e.to_string().contains("envelope.series"), "{e}"),
    }
    let near: Vec<f64> = x.iter().map(|v| v * 1e306).collect();
    let e = checked_envelope(&near, "envelope.series").expect("scaled envelope");
    let e0 = envelope(&x);
    for (a, b) in e.iter().zip(&e0) {
        assert!(a.is_finite() && (a / 1e306 - b).abs() < 1e-9, "{a} {b}");
    }
}

#[test]
fn contribution_shares_survive_a_growing_response() {
    let n = 1000;
    let e: Vec<f64> = (0..n).map(|i| (i as f64 * 0.1).sin()).collect();
    let c: Vec<f64> = (0..n).map(|i| 0.2 * (i as f64 * 0.2).cos()).collect();
    let k: Vec<f64> = (0..n).map(|i| 0.03 * (i as f64 * 0.05).sin()).collect();
    let t: Vec<f64> = (0..n).map(|i| e[i] + c[i] + k[i]).collect();
    let base = contributions(&e, &c, &k, &t);
    let s = |x: &[f64]| x.iter().map(|v| v * 1e209).collect::<Vec<f64>>();
    let big = contributions(&s(&e), &s(&c), &s(&k), &s(&t));
    for (a, b) in [
        (base.euler, big.euler),
        (base.centrifugal, big.centrifugal),
        (base.coriolis, big.coriolis),
    ] {
        assert!(a > 0.0 && (a - b).abs() <= 1e-9 * a, "{a} vs {b}");
    }
}

#[test]
fn unstable_modes_have_no_beat_period() {
    // The lab's instability experiment: α0 0.87 rad at 29.5 Hz.
    let mut cfg = SimConfig::paper();
    cfg = wingbeat::analysis::sweep::apply(&cfg, SweepParam::Alpha0, 0.87).unwrap();
    cfg = wingbeat::analysis::sweep::apply(&cfg, SweepParam::FlapHz, 29.5).unwrap();
    cfg.duration_s = 1.0;
    let r = simulate(&cfg).unwrap();
    let unstable: Vec<_> = r.modes.iter().filter(|m| !m.floquet.stable).collect();
    assert!(!unstable.is_empty(), "the experiment's mode is unstable");
    for m in unstable {
        assert!(m.floquet.max_modulus > 1.0);
        assert_eq!(m.floquet.beat_period_s, None);
        assert_eq!(m.floquet.beat_period_vs_2fd_s, None);
    }
    // Stable modes keep theirs (the paper case).
    let p = simulate(&SimConfig::paper()).unwrap();
    assert!(p.modes[0].floquet.beat_period_s.is_some());
    let v: Value = serde_json::to_value(&r.modes[0].floquet).unwrap();
    assert!(v.get("beat_period_s").is_some());
}

#[test]
fn ic_map_ranges_are_bounded() {
    use wingbeat::analysis::ic_map::{ic_map, IcMapOptions};
    let mut cfg = SimConfig::paper();
    cfg.duration_s = 0.2;
    for r in [[-1e308, 1e308], [0.0, 1e7]] {
        let e = ic_map(
            &cfg,
            &IcMapOptions {
                n_q: 5,
                n_qdot: 5,
                q_range: Some(r),
                ..IcMapOptions::default()
            },
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("ic_map.q_range") && e.len() < 300, "{e}");
    }
    let m = ic_map(
        &cfg,
        &IcMapOptions {
            n_q: 5,
            n_qdot: 5,
            q_range: Some([-1e6, 1e6]),
            qdot_range: Some([-1e9, 1e9]),
            ..IcMapOptions::default()
        },
    )
    .unwrap();
    assert!(m.coriolis_percent.iter().all(|v| v.is_finite()));
}

#[test]
fn strain_points_are_capped_and_linear() {
    use wingbeat::model::{ModalStrain, MAX_STRAIN_POINTS};
    let point = |j: usize| ModalStrain {
        point: format!("S{j}"),
        eps_x: j as f64,
        eps_y: 1.0,
        gamma_xy: -(j as f64),
    };
    let mut cfg = SimConfig::paper();
    cfg.duration_s = 0.05;
    cfg.modes[0].strains = (0..100_000).map(point).collect();
    let t0 = Instant::now();
    let e = simulate(&cfg).unwrap_err().to_string();
    assert!(t0.elapsed() < Duration::from_secs(5));
    assert!(e.contains("modes[0].strains") && e.contains("256"), "{e}");
    // At the cap: every point's series is Σ_k ε_k q_k, in the order first named.
    cfg.modes[0].strains = (0..MAX_STRAIN_POINTS).map(point).collect();
    cfg.modes[1].strains = (0..MAX_STRAIN_POINTS).rev().map(point).collect();
    let r = simulate(&cfg).unwrap();
    assert_eq!(r.strain_points.len(), MAX_STRAIN_POINTS);
    for (j, s) in r.strain_points.iter().enumerate() {
        assert_eq!(s.point, format!("S{j}"));
        let i = 100;
        let want = j as f64 * (r.modes[0].q.total[i] + r.modes[1].q.total[i]);
        assert!((s.eps_x[i] - want).abs() <= 1e-12 * want.abs().max(1e-30));
    }
}

#[test]
fn shares_of_a_response_grown_past_1e200() {
    // The instability experiment run long: q_total of mode 1 reaches about 4e212.
    let base = wingbeat::analysis::sweep::apply(&SimConfig::paper(), SweepParam::Alpha0, 0.87)
        .and_then(|c| wingbeat::analysis::sweep::apply(&c, SweepParam::FlapHz, 29.5))
        .unwrap();
    let run = |d: f64| {
        let mut c = base.clone();
        c.duration_s = d;
        c.sample_rate_hz = 500.0;
        simulate(&c).unwrap()
    };
    let (short, long) = (run(100.0), run(400.0));
    let peak = long.modes[0]
        .q
        .total
        .iter()
        .fold(0.0_f64, |m, v| m.max(v.abs()));
    assert!(peak > 1e200 && peak.is_finite(), "{peak}");
    let (a, b) = (
        short.modes[0].contribution_percent,
        long.modes[0].contribution_percent,
    );
    for (x, y) in [
        (a.euler, b.euler),
        (a.centrifugal, b.centrifugal),
        (a.coriolis, b.coriolis),
    ] {
        assert!(y > 0.0 && (x - y).abs() <= 1e-6 * x, "{x} vs {y}");
    }
}
