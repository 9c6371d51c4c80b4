//! A sampled kinematics table without `max_harmonic` keeps at most
//! `kinematics::DEFAULT_SAMPLED_MAX_HARMONIC` (24) harmonics, for cost. A table the cap
//! low-passes no longer passes through its samples: then the run's output says so (JSON
//! `warnings`, stderr), naming the angle and the deviation; otherwise the interpolant passes
//! through every sample. The cap used to be silent while `--help` said "passes through every
//! sample".
#![cfg(not(target_arch = "wasm32"))]

use std::f64::consts::PI;
use wingbeat::config::SimConfig;
use wingbeat::kinematics::{Angle, DEFAULT_SAMPLED_MAX_HARMONIC};
use wingbeat::simulate::simulate;

mod common_cli;

/// A measured-looking stroke: a sine plus a deterministic ripple with content up to N/2.
fn table(n: usize) -> Vec<f64> {
    (0..n)
        .map(|j| {
            let p = 2.0 * PI * j as f64 / n as f64;
            0.8 * p.sin() + 0.01 * ((37.0 * j as f64 * 1.618).sin())
        })
        .collect()
}

/// Largest |interpolant − sample| at the sample times.
fn deviation(a: &Angle, values: &[f64]) -> f64 {
    let s = a.series();
    let n = values.len();
    values
        .iter()
        .enumerate()
        .map(|(j, v)| {
            let th = 2.0 * PI * j as f64 / n as f64;
            let y = s.mean
                + s.terms
                    .iter()
                    .map(|t| t.s * (t.n * th).sin() + t.c * (t.n * th).cos())
                    .sum::<f64>();
            (y - v).abs()
        })
        .fold(0.0, f64::max)
}

fn cfg_with(alpha: Angle) -> SimConfig {
    let mut cfg = SimConfig::paper();
    cfg.kinematics.alpha = alpha;
    cfg.duration_s = 0.02;
    cfg
}

#[test]
fn a_table_either_passes_through_every_sample_or_the_run_warns() {
    for n in [8, 48, 49, 50, 64, 200] {
        let values = table(n);
        for max_harmonic in [None, Some((n / 2) as u32), Some(3)] {
            let a = Angle::Sampled {
                values: values.clone(),
                max_harmonic,
            };
            let dev = deviation(&a, &values);
            let r = simulate(&cfg_with(a)).expect("runs");
            let warned = r.warnings.iter().any(|w| w.contains("kinematics.alpha"));
            match max_harmonic {
                // asked for: no warning, whatever it does
                Some(_) => assert!(!warned, "n = {n}, {max_harmonic:?}: {:?}", r.warnings),
                None if n / 2 > DEFAULT_SAMPLED_MAX_HARMONIC as usize => {
                    assert!(
                        dev > 1e-6,
                        "n = {n}: the cap should change the table ({dev})"
                    );
                    let w = r
                        .warnings
                        .iter()
                        .find(|w| w.contains("kinematics.alpha"))
                        .unwrap_or_else(|| {
                            panic!("n = {n}: deviation {dev} but no warning: {:?}", r.warnings)
                        });
                    assert!(
                        w.contains(&format!("{n}-sample")) && w.contains("max_harmonic"),
                        "{w}"
                    );
                }
                None => {
                    assert!(dev < 1e-12, "n = {n}: {dev}");
                    assert!(!warned, "n = {n}: {:?}", r.warnings);
                }
            }
            if max_harmonic == Some((n / 2) as u32) {
                assert!(
                    dev < 1e-12,
                    "all harmonics pass through every sample: n = {n}, {dev}"
                );
            }
        }
    }
}

#[test]
fn the_cli_writes_the_warning_to_json_and_stderr() {
    let values = table(64);
    let mut kin = serde_json::to_value(SimConfig::paper()).unwrap()["kinematics"].clone();
    kin["alpha"] = serde_json::json!({"kind": "sampled", "values": values});
    let cfg = serde_json::json!({"kinematics": kin, "duration_s": 0.02});
    let dir = std::env::temp_dir().join(format!("wingbeat-cap-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("cfg.json");
    std::fs::write(&path, cfg.to_string()).unwrap();
    let p = path.to_str().unwrap();
    for cmd in [
        &["simulate", "--config", p][..],
        &["psd", "--config", p, "--segment-len", "64"][..],
    ] {
        let (code, out, err) = common_cli::run(cmd);
        assert_eq!(code, 0, "{cmd:?}: {err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        let w = v["warnings"].as_array().expect("warnings in the JSON");
        assert!(
            w.iter().any(|w| w
                .as_str()
                .unwrap()
                .contains("64-sample table resolves 32 harmonics")),
            "{cmd:?}: {w:?}"
        );
        assert!(err.contains("64-sample table"), "{cmd:?}: {err}");
    }
    // with max_harmonic = 32 the same table runs without the warning
    kin["alpha"]["max_harmonic"] = serde_json::json!(32);
    let cfg = serde_json::json!({"kinematics": kin, "duration_s": 0.02});
    std::fs::write(&path, cfg.to_string()).unwrap();
    let (code, out, err) = common_cli::run(&["simulate", "--config", p]);
    assert_eq!(code, 0, "{err}");
    assert!(!out.contains("sample table resolves") && !err.contains("sample table resolves"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_measured_csv_on_the_grid_warns_too() {
    use wingbeat::kinematics_table::{kinematics_from_csv, AngleUnits, CsvKinematicsOptions};
    let n = 64;
    let mut csv = String::from("t,alpha\n");
    for (j, v) in table(n).iter().enumerate() {
        csv.push_str(&format!("{},{v}\n", j as f64 / (n as f64 * 25.0)));
    }
    let opts = CsvKinematicsOptions {
        units: AngleUnits::Rad,
        flap_hz: 25.0,
        max_harmonic: None,
    };
    let t = kinematics_from_csv(&csv, &opts).unwrap();
    assert!(
        t.warnings.iter().any(|w| w.contains("64-sample")),
        "{:?}",
        t.warnings
    );
    let mut cfg = SimConfig::paper();
    cfg.kinematics = t.kinematics;
    cfg.duration_s = 0.02;
    let r = simulate(&cfg).unwrap();
    assert!(
        r.warnings.iter().any(|w| w.contains("kinematics.alpha")),
        "{:?}",
        r.warnings
    );
}
