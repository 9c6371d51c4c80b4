//! `wingbeat modes` on an outline that is not the default one (docs/fem.md, "Worked example"):
//! the automatic mesh size is printed and stored, the strain point lies inside the wing, the
//! strip clamp's edge is a node row, and `simulate --modes` reads the document back.
#![cfg(feature = "cli")]
// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

mod common_cli;
use common_cli::run;

#[test]
fn modes_on_a_slender_outline_with_the_automatic_size() {
    let dir = std::env::temp_dir().join(format!("wingbeat-fem-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("slender.csv");
    std::fs::write(
        &csv,
        "# synthetic slender wing (not a specimen), mm\nx_mm,y_mm\n0,0\n0,-8\n40,-6\n42,-2\n40,0\n",
    )
    .unwrap();
    let csv_s = csv.to_str().unwrap();
    let (code, out, err) = run(&[
        "modes",
        "--planform",
        csv_s,
        "--camber",
        "0.05",
        "--clamp",
        "strip:2",
        "--n-modes",
        "2",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("mesh size 0.57 mm (automatic)"), "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["mesh_size_mm"], 0.57);
    // P: one eighth of the free span (2 … 42 mm) out from the strip's edge, at mid-chord
    let s = &v["modes"][0]["strains"][0];
    assert_eq!(s["point"], "P");
    assert!(s["eps_x"].as_f64().unwrap().abs() > 1.0, "{s}");
    let f1 = v["freq_hz"][0].as_f64().unwrap();
    assert!((f1 - 178.4).abs() < 0.1, "f1 = {f1}");
    let on_line = v["clamped_nodes"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|i| {
            let x = v["nodes"][i.as_u64().unwrap() as usize][0]
                .as_f64()
                .unwrap();
            (x * 1e3 - 2.0).abs() < 1e-9
        })
        .count();
    assert!(on_line >= 8, "{on_line} clamped nodes on x = 2 mm");
    let json = dir.join("slender.json");
    std::fs::write(&json, &out).unwrap();
    let (code, sim, err) = run(&[
        "simulate",
        "--modes",
        json.to_str().unwrap(),
        "--duration",
        "0.1",
    ]);
    assert_eq!(code, 0, "{err}");
    let r: serde_json::Value = serde_json::from_str(&sim).unwrap();
    assert_eq!(r["modes"].as_array().unwrap().len(), 2);
    assert_eq!(r["modes"][0]["freq_hz"].as_f64().unwrap(), f1);
    let _ = std::fs::remove_dir_all(&dir);
}

/// `wingbeat modes --preset mohren2018`: the published sensing plate's modes, the same as the
/// library's preset, damped at ζ_k = 63/(2ω_k); its material flags still override, the
/// outline flags conflict, and an unknown preset is refused by name.
#[test]
fn modes_preset_mohren2018_gives_the_published_plate_with_its_damping() {
    let (code, out, err) = run(&["modes", "--preset", "mohren2018", "--n-modes", "3"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let lib = wingbeat::fem::compute_modes(&wingbeat::presets::mohren2018_plate_input(None, 3))
        .expect("plate solves");
    assert_eq!(v["mesh_size_mm"].as_f64().unwrap(), lib.mesh_size_mm);
    for k in 0..3 {
        let f = v["freq_hz"][k].as_f64().unwrap();
        assert!((f - lib.freq_hz[k]).abs() < 1e-9 * f, "mode {k}: {f}");
        let zeta = v["modes"][k]["zeta"].as_f64().unwrap();
        let want = wingbeat::presets::MOHREN2018_DAMPING_PER_S / (4.0 * std::f64::consts::PI * f);
        assert!((zeta - want).abs() < 1e-12, "mode {k}: ζ = {zeta}");
    }
    // the first bending mode of a 50 mm acrylic cantilever lies near 13.5 Hz, below the
    // Euler–Bernoulli beam's 14.0 Hz (tests/fem_published_plate.rs has the bounds)
    let f1 = lib.freq_hz[0];
    assert!(f1 > 13.0 && f1 < 14.0, "f1 = {f1}");
    // a softer material (Weber et al. sweep E) scales every frequency by √(E'/E)
    let (code, out, err) = run(&[
        "modes",
        "--preset",
        "mohren2018",
        "--n-modes",
        "1",
        "--e-pa",
        "1.5e9",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let soft = v["freq_hz"][0].as_f64().unwrap();
    assert!((soft / f1 - 0.5f64.sqrt()).abs() < 1e-6, "{soft} vs {f1}");
    let (code, _, err) = run(&["modes", "--preset", "mohren2018", "--camber", "0.1"]);
    assert_ne!(code, 0);
    assert!(err.contains("--camber"), "{err}");
    let (code, _, err) = run(&["modes", "--preset", "mohren", "--n-modes", "1"]);
    assert_ne!(code, 0);
    assert!(
        err.contains("--preset") && err.contains("mohren2018"),
        "{err}"
    );
}
