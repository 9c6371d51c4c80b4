//! `wingbeat sense` end to end: the promised fields, CSV tables, and named errors.
#![cfg(not(target_arch = "wasm32"))]

use serde_json::Value;

mod common_cli;
use common_cli::run;

const FE: [&str; 8] = [
    "sense",
    "--preset",
    "fe-wing",
    "--mesh-size-mm",
    "2",
    "--duration",
    "0.3",
    "--sample-rate=5000",
];

fn fe_args<'a>(extra: &[&'a str]) -> Vec<&'a str> {
    let mut v: Vec<&str> = FE.to_vec();
    v.extend_from_slice(extra);
    v
}

#[test]
fn fe_wing_json_has_map_sensors_curve_and_series() {
    let (code, out, err) = run(&fe_args(&["--body-rate", "1,0,1", "--k-max", "10"]));
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("sense: two runs"), "progress on stderr: {err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    let n = v["n_nodes"].as_u64().unwrap() as usize;
    assert_eq!(v["map"]["d"].as_array().unwrap().len(), n);
    assert_eq!(v["nodes_mm"].as_array().unwrap().len(), n);
    let p = &v["placement"];
    assert_eq!(p["sensors"].as_array().unwrap().len(), 10);
    let d: Vec<f64> = p["d_prime"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert_eq!(d.len(), 10);
    assert!(d.windows(2).all(|w| w[1] >= w[0]), "{d:?}");
    assert!(d[0] > 0.0);
    assert!(p["k_for_90_percent"].as_u64().unwrap() >= 1);
    let pts = v["points"].as_array().unwrap();
    assert_eq!(pts.len(), 3);
    let t = v["t"].as_array().unwrap().len();
    assert_eq!(t, 1501);
    assert_eq!(pts[0]["delta_strain"]["eps_x"].as_array().unwrap().len(), t);
    assert!(!pts[0]["spectrum"]["eps_x"]["psd"]
        .as_array()
        .unwrap()
        .is_empty());
}

#[test]
fn zero_rate_gives_zero_signal_and_map() {
    let (code, out, err) = run(&fe_args(&[
        "--body-rate",
        "0,0,0",
        "--k-max",
        "2",
        "--points",
        "10,-5;20,-10",
    ]));
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    for d in v["map"]["d"].as_array().unwrap() {
        for c in d.as_array().unwrap() {
            assert_eq!(c.as_f64().unwrap(), 0.0);
        }
    }
    for p in v["points"].as_array().unwrap() {
        for c in ["eps_x", "eps_y", "gamma_xy"] {
            assert!(p["delta_strain"][c]
                .as_array()
                .unwrap()
                .iter()
                .all(|x| x.as_f64().unwrap() == 0.0));
        }
    }
}

#[test]
fn csv_tables() {
    let (code, out, err) = run(&fe_args(&[
        "--k-max", "5", "--format", "csv", "--table", "curve",
    ]));
    assert_eq!(code, 0, "{err}");
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines[0], "k,d_prime,pd,d_prime_ranked");
    assert_eq!(lines.len(), 6);
    let (code, out, err) = run(&fe_args(&[
        "--k-max", "4", "--format", "csv", "--table", "sensors",
    ]));
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("rank,node,component,x_mm,y_mm,d\n"));
    assert_eq!(out.lines().count(), 5);
    let (code, out, err) = run(&fe_args(&[
        "--k-max", "1", "--format", "csv", "--table", "series",
    ]));
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("t_s,d_eps_x_"));
    assert_eq!(out.lines().count(), 1502);
}

#[test]
fn paper_modes_give_the_modal_signal_only() {
    let (code, out, err) = run(&["sense", "--duration", "0.2", "--body-rate", "0,0,2"]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["delta_q"].as_array().unwrap().len(), 2);
    assert!(v["note"].as_str().unwrap().contains("no detectability map"));
    assert_eq!(v["points"][0]["point"], "P");
    assert!(v["delta_q"][0]
        .as_array()
        .unwrap()
        .iter()
        .any(|x| x.as_f64().unwrap() != 0.0));
}

#[test]
fn bad_flags_are_named() {
    for (args, name) in [
        (vec!["--body-rate", "1,2"], "--body-rate"),
        (vec!["--body-rate", "0,0,1000"], "--body-rate[2]"),
        (vec!["--body-rate", "0,nan,1"], "--body-rate"),
        (vec!["--k-max", "0"], "--k-max"),
        (vec!["--k-max", "31"], "--k-max"),
        (vec!["--rho", "2"], "--rho"),
        (vec!["--noise", "0"], "--noise"),
        (vec!["--samples-per-sensor", "4"], "--samples-per-sensor"),
        (vec!["--points", "1e6,0"], "point"),
        (vec!["--points", "a,b"], "--points"),
    ] {
        let mut a = vec!["sense", "--duration", "0.1"];
        a.extend(args.iter());
        let (code, _out, err) = run(&a);
        assert_ne!(code, 0, "{args:?} accepted");
        assert!(err.contains(name), "{args:?}: {err}");
    }
    let (code, _, err) = run(&["sense", "--mesh-size-mm", "2"]);
    assert_ne!(code, 0);
    assert!(err.contains("--mesh-size-mm"), "{err}");
    let (code, _, err) = run(&["sense", "--preset", "fe-wing", "--fe-modes", "0"]);
    assert_ne!(code, 0);
    assert!(err.contains("--fe-modes"), "{err}");
}

#[test]
fn a_modes_document_is_an_fe_wing_and_points_are_checked_first() {
    let (dir, f) = common_cli::modes_document("sense");
    let f = f.as_str();
    let (code, out, err) = run(&["sense", "--modes", f, "--duration", "0.2", "--k-max", "2"]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["placement"]["sensors"].as_array().unwrap().len(), 2);
    let (code, _, err) = run(&["sense", "--modes", f, "--points", "100,0"]);
    assert_ne!(code, 0);
    assert!(err.contains("--points"), "{err}");
    assert!(
        !err.contains("sense: two runs"),
        "refused before the runs: {err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
