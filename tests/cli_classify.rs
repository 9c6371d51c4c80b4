//! `wingbeat classify` (docs/sensing.md, "Classifying rotation"): a short run of the published
//! setup end to end through the binary, its CSV table and JSON units, the same through a
//! `wingbeat modes` file, and bad flags named.
#![cfg(feature = "cli")]
// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

mod common_cli;
use common_cli::run;

const SHORT: [&str; 16] = [
    "--n-modes",
    "3",
    "--mesh-size-mm",
    "2.5",
    "--duration",
    "1.6",
    "--discard",
    "0.5",
    "--kept-modes",
    "2,4",
    "--counts",
    "1,3",
    "--draws",
    "3",
    "--seed",
    "2",
];

#[test]
fn a_short_published_run_through_the_binary() {
    let mut args = vec!["classify", "--format", "csv"];
    args.extend(SHORT);
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines[0], "strain,placement,kept_modes,sensors,accuracy,sd");
    // Per strain: all sensors, 2 SSPOC rows, 2 random rows, 2 greedy d′ rows.
    assert_eq!(lines.len(), 1 + 2 * 7, "{out}");
    assert!(lines[1].starts_with("encoded,all,,1326,"), "{}", lines[1]);
    for l in &lines[1..] {
        let acc: f64 = l.split(',').nth(4).unwrap().parse().unwrap();
        assert!((0.0..=1.0).contains(&acc), "{l}");
    }

    let mut args = vec!["classify"];
    args.extend(SHORT);
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["report"]["sensors"].as_array().unwrap().len(), 1326);
    assert_eq!(v["modes"].as_array().unwrap().len(), 3);
    assert!(v["units"]["positions"].as_str().unwrap().contains("mm"));
    let zeta = v["modes"][0]["zeta"].as_f64().unwrap();
    let f = v["modes"][0]["freq_hz"].as_f64().unwrap();
    assert!((zeta - 63.0 / (4.0 * std::f64::consts::PI * f)).abs() < 1e-12);
    let pos = &v["encoded_sparse_positions"][0]["positions_mm"];
    assert!(!pos.as_array().unwrap().is_empty());
}

#[test]
fn any_fe_wing_from_a_modes_file() {
    let dir = std::env::temp_dir().join(format!("wingbeat-classify-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (code, out, err) = run(&[
        "modes",
        "--preset",
        "mohren2018",
        "--n-modes",
        "3",
        "--mesh-size-mm",
        "2.5",
    ]);
    assert_eq!(code, 0, "{err}");
    let file = dir.join("plate.json");
    std::fs::write(&file, out).unwrap();
    let mut args = vec![
        "classify",
        "--modes",
        file.to_str().unwrap(),
        "--format",
        "csv",
    ];
    args.extend(&SHORT[4..]);
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    assert!(out
        .lines()
        .nth(1)
        .unwrap()
        .starts_with("encoded,all,,1326,"));
}

#[test]
fn in_air_the_runs_carry_the_air_and_the_json_says_so() {
    // A short run of the plate in air against the same in a vacuum: the JSON names the density,
    // and the raw strain's all-sensor accuracy moves (the air's force depends on the rotation).
    let json = |rho: &str| {
        let mut args = vec!["classify", "--air-density", rho];
        args.extend(&SHORT[..8]);
        args.extend(["--kept-modes", "2", "--counts", "1", "--draws", "2"]);
        let (code, out, err) = run(&args);
        assert_eq!(code, 0, "{err}");
        serde_json::from_str::<serde_json::Value>(&out).unwrap()
    };
    let (air, vac) = (json("1.2"), json("0"));
    assert_eq!(air["air_density_kg_m3"], 1.2);
    assert_eq!(vac["air_density_kg_m3"], 0.0);
    let raw = |v: &serde_json::Value| v["report"]["raw"]["all_sensors"].as_f64().unwrap();
    let enc = |v: &serde_json::Value| v["report"]["encoded"]["all_sensors"].as_f64().unwrap();
    for v in [&air, &vac] {
        assert!((0.0..=1.0).contains(&raw(v)) && (0.0..=1.0).contains(&enc(v)));
    }
    assert!(
        raw(&air) != raw(&vac) || enc(&air) != enc(&vac),
        "air changed nothing: raw {} / {}, encoded {} / {}",
        raw(&air),
        raw(&vac),
        enc(&air),
        enc(&vac)
    );
}

#[test]
fn bad_flags_are_named() {
    for (flag, value, named) in [
        ("--kept-modes", "0", "--kept-modes"),
        ("--kept-modes", "5-2", "--kept-modes"),
        ("--counts", "x", "--counts"),
        ("--preset", "moth", "--preset"),
        ("--orientation", "sideways", "--orientation"),
        ("--split", "median", "--split"),
        ("--rotation", "NaN", "--rotation"),
        ("--flap-disturbance", "-1", "--flap-disturbance"),
        ("--draws", "0", "options.random_draws"),
        ("--discard", "9", "options.discard_s"),
        ("--gain", "0", "options.nonlinearity.gain"),
        ("--air-density", "-1", "--air-density"),
        ("--air-density", "2000", "--air-density"),
    ] {
        let (code, _, err) = run(&["classify", flag, value]);
        assert_ne!(code, 0, "{flag} {value}");
        assert!(err.contains(named), "{flag} {value}: {err}");
    }
}
