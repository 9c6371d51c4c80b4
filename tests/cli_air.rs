//! `wingbeat simulate --air-density`: the wing in air from the command line, its refusals,
//! `sense` in air and the air claims of `wingbeat reproduce` (`psd` and `sweep` in air:
//! tests/cli_psd_sweep_air.rs).

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

mod common_cli;
use common_cli::run;
use serde_json::Value;

#[test]
fn simulate_in_air_reports_the_air_block_per_mode() {
    let (code, out, err) = run(&[
        "simulate",
        "--preset",
        "fe-wing",
        "--air-density",
        "1.2",
        "--duration",
        "0.2",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["air"]["aero"]["air_density_kg_m3"], 1.2);
    assert_eq!(v["air"]["multipliers"].as_array().unwrap().len(), 8);
    for m in v["modes"].as_array().unwrap() {
        let air = &m["air"];
        let f = m["freq_hz"].as_f64().unwrap();
        let still = air["still_air_freq_hz"].as_f64().unwrap();
        assert!(still < f && still > 0.8 * f, "{still} vs {f}");
        assert!(air["decay_rate_per_s"].as_f64().unwrap() > 0.0);
        assert!(m["contribution_percent"]["aerodynamic"].as_f64().unwrap() > 0.0);
        assert_eq!(
            m["q"]["aerodynamic"].as_array().unwrap().len(),
            m["q"]["total"].as_array().unwrap().len()
        );
    }
    // CSV gains the aerodynamic partial response column per mode.
    let (code, out, _) = run(&[
        "simulate",
        "--preset",
        "fe-wing",
        "--air-density",
        "0.18",
        "--duration",
        "0.01",
        "--format",
        "csv",
    ]);
    assert_eq!(code, 0);
    assert!(out.lines().next().unwrap().contains("q1_aerodynamic"));
}

#[test]
fn vacuum_output_has_no_air_fields() {
    let (code, out, _) = run(&["simulate", "--preset", "fe-wing", "--duration", "0.05"]);
    assert_eq!(code, 0);
    assert!(!out.contains("aerodynamic") && !out.contains("\"air\""));
    let (code, zero, _) = run(&[
        "simulate",
        "--preset",
        "fe-wing",
        "--duration",
        "0.05",
        "--air-density",
        "0",
    ]);
    assert_eq!(code, 0);
    assert_eq!(out, zero, "density 0 is the vacuum path, byte for byte");
}

#[test]
fn air_refusals_name_the_field_and_range() {
    let (code, _, err) = run(&["simulate", "--air-density", "1.2"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("--air-density") && err.contains("mode shapes"),
        "{err}"
    );
    for bad in ["-1", "1e4", "nan"] {
        let (code, _, err) = run(&["simulate", "--preset", "fe-wing", "--air-density", bad]);
        assert_eq!(code, 2, "{bad}");
        assert!(
            err.contains("--air-density") && err.contains("1000"),
            "{bad}: {err}"
        );
    }
}

#[test]
fn reproduce_carries_the_computed_air_claims() {
    let (code, out, _) = run(&["reproduce", "--format", "json"]);
    assert_eq!(code, 0);
    let v: Value = serde_json::from_str(&out).unwrap();
    let claims = v["claims"].as_array().unwrap();
    for id in ["air-erases-beat", "air-3wd", "helium-vs-air"] {
        let c = claims
            .iter()
            .find(|c| c["id"] == id)
            .unwrap_or_else(|| panic!("{id}"));
        assert!(c["computed"].as_str().unwrap().contains("FE wing"), "{id}");
    }
    let beat = claims
        .iter()
        .find(|c| c["id"] == "air-erases-beat")
        .unwrap();
    assert_eq!(beat["verdict"], "holds");
}

#[test]
fn sense_runs_both_runs_in_the_medium_and_its_map_differs_from_vacuum() {
    let args = |rho: &'static str| {
        vec![
            "sense",
            "--preset",
            "fe-wing",
            "--fe-modes",
            "2",
            "--duration",
            "0.2",
            "--k-max",
            "2",
            "--body-rate",
            "0,0,2",
            "--air-density",
            rho,
        ]
    };
    let (code, air, err) = run(&args("1.2"));
    assert_eq!(code, 0, "{err}");
    let (code, vac, err) = run(&args("0"));
    assert_eq!(code, 0, "{err}");
    let (a, v): (Value, Value) = (
        serde_json::from_str(&air).unwrap(),
        serde_json::from_str(&vac).unwrap(),
    );
    // Both runs are in the medium, and the rotation-induced strain map differs in air.
    assert_eq!(a["air_density_kg_m3"], 1.2);
    assert_eq!(v["air_density_kg_m3"], 0.0);
    assert_ne!(a["map"], v["map"]);
}
