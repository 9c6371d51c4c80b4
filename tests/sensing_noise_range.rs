//! Every sensor noise σ the range allows gives a finite sensing result, at both ends of the
//! range; a smaller one is refused naming `--noise` and the range. σ = 1e-300 used to pass the
//! check (any σ > 0) and then fail as "too large to combine in f64" (σ² is 0 in f64).
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::analysis::sensing::{SensingOptions, MIN_NOISE};

mod common_cli;
use common_cli::run;

#[test]
fn the_noise_range_ends_both_run_and_outside_is_refused_by_name() {
    let (dir, f) = common_cli::modes_document("noise");
    let f = f.as_str();
    let lo = format!("{MIN_NOISE:e}");
    for noise in [lo.as_str(), "1"] {
        let (code, out, err) = run(&[
            "sense",
            "--modes",
            f,
            "--duration",
            "0.1",
            "--noise",
            noise,
            "--k-max",
            "3",
        ]);
        assert_eq!(code, 0, "--noise {noise}: {err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        let d = v["placement"]["d_prime_all"].as_f64().unwrap_or_else(|| {
            panic!(
                "--noise {noise}: no finite d'_all in {}",
                &out[..300.min(out.len())]
            )
        });
        assert!(d.is_finite() && d >= 0.0, "--noise {noise}: {d}");
    }
    // just below the floor, and the value that used to fail late
    let below = format!("{:e}", MIN_NOISE * (1.0 - 1e-15));
    for noise in [below.as_str(), "1e-300", "0", "-1e-3", "1.0000001"] {
        let (code, _, err) = run(&["sense", "--modes", f, "--duration", "0.1", "--noise", noise]);
        assert_eq!(code, 2, "--noise {noise} accepted");
        assert!(
            err.contains("--noise") && err.contains("[1e-12, 1]"),
            "{noise}: {err}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_options_accept_exactly_the_documented_range() {
    let ok = |noise: f64| {
        SensingOptions {
            noise,
            ..SensingOptions::default()
        }
        .validate()
        .is_ok()
    };
    assert!(ok(MIN_NOISE) && ok(1.0));
    assert!(!ok(MIN_NOISE * (1.0 - 1e-15)) && !ok(1.0 + 1e-15) && !ok(f64::NAN));
    // σ² at the floor is a normal f64, so 1/σ² is finite
    assert!((MIN_NOISE * MIN_NOISE).is_normal());
}
