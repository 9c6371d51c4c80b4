//! The CLI's parameter flags go through the same interpretation as the lab's overrides
//! (`params::apply_values` / `params::set_param`): `--alpha-phase`, `--beta-phase` and
//! `--gamma-phase` give exactly the run that the library gives for the same `*_phase` override,
//! and bad values are refused by name with the allowed range.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use serde_json::Value;
use wingbeat::config::SimConfig;
use wingbeat::params::apply_overrides;
use wingbeat::simulate::simulate;

mod common_cli;
use common_cli::run;

/// The CLI's `simulate` JSON for `args` (0.2 s of the paper case plus `args`).
fn cli_run(args: &[&str]) -> Value {
    let mut all = vec!["simulate", "--duration", "0.2"];
    all.extend_from_slice(args);
    let (code, out, err) = run(&all);
    assert_eq!(code, 0, "{all:?}: {err}");
    serde_json::from_str(&out).expect("JSON output")
}

/// The library's run of the paper case with the lab's overrides, as the CLI prints it.
fn library_run(overrides: &[(&str, f64)]) -> Value {
    let mut o = overrides.to_vec();
    o.push(("duration", 0.2));
    let cfg = apply_overrides(&SimConfig::paper(), o).expect("valid overrides");
    serde_json::to_value(simulate(&cfg).expect("run")).expect("serialisable")
}

#[test]
fn phase_flags_give_the_run_of_the_same_override() {
    let plain = cli_run(&[]);
    for (flag, key, v) in [
        ("--alpha-phase", "alpha_phase", 0.7),
        ("--beta-phase", "beta_phase", -1.2),
        ("--gamma-phase", "gamma_phase", 2.5),
    ] {
        let text = v.to_string();
        let cli = cli_run(&[flag, &text]);
        assert_ne!(
            cli["modes"][0]["q"]["total"], plain["modes"][0]["q"]["total"],
            "{flag} changes the response"
        );
        // Every number of the output equal, bit for bit (serde_json prints round-trip floats).
        assert_eq!(
            cli,
            library_run(&[(key, v)]),
            "{flag} {v} = override {key} = {v}"
        );
    }
}

#[test]
fn phase_and_amplitude_flags_combine_as_overrides_do() {
    let cli = cli_run(&["--gamma0", "0.1", "--gamma-phase", "0.4", "--zeta", "0.01"]);
    let lib = library_run(&[("gamma0", 0.1), ("gamma_phase", 0.4), ("zeta", 0.01)]);
    assert_eq!(cli, lib);
}

#[test]
fn bad_phase_values_are_refused_by_name_with_the_range() {
    // Not a number: named by the flag.
    let (code, _, err) = run(&["simulate", "--duration", "0.2", "--alpha-phase", "nan"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("--alpha-phase") && err.contains("a finite number"),
        "{err}"
    );
    // Outside the core's phase range: named by the config field it sets, with the range.
    let (code, _, err) = run(&["simulate", "--duration", "0.2", "--beta-phase", "2000"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("kinematics.beta.harmonics[0].phase"), "{err}");
    assert!(
        err.contains("[-1000, 1000]") && err.contains("rad"),
        "{err}"
    );
    // A sampled angle has no first-harmonic phase to set, as for the lab's override.
    let dir = std::env::temp_dir().join(format!("wingbeat_phase_flags_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("sampled.json");
    std::fs::write(
        &file,
        concat!(
            r#"{"kinematics": {"flap_freq_hz": 25,"#,
            r#" "alpha": {"kind": "fourier", "mean": 0, "harmonics": [{"n": 1, "amplitude": 0.8, "phase": 0}]},"#,
            r#" "beta": {"kind": "fourier", "mean": 0, "harmonics": []},"#,
            r#" "gamma": {"kind": "sampled", "values": [0, 0.1, 0, -0.1]}}}"#
        ),
    )
    .unwrap();
    let (code, _, err) = run(&[
        "simulate",
        "--duration",
        "0.2",
        "--config",
        file.to_str().unwrap(),
        "--gamma-phase",
        "0.3",
    ]);
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("kinematics.gamma") && err.contains("sampled kinematics"),
        "{err}"
    );
    assert!(err.contains("Fourier kinematics"), "{err}");
}

#[test]
fn help_lists_the_phase_flags() {
    for sub in ["simulate", "psd", "sweep", "sense"] {
        let (code, out, err) = run(&[sub, "--help"]);
        assert_eq!(code, 0, "{err}");
        for flag in ["--alpha-phase", "--beta-phase", "--gamma-phase"] {
            assert!(out.contains(flag), "`{sub} --help` lists {flag}");
        }
    }
    let (_, out, _) = run(&["simulate", "--help"]);
    assert!(
        out.contains("alpha_phase"),
        "the help names the lab's slider"
    );
}
