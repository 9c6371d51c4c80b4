//! Inputs that used to be read silently in a way the user did not mean are refused, naming the
//! path: JSON arrays where objects are meant (serde's derived structs read an array by
//! position) at every level of a config, an FE input and a modes document; two strain points
//! with one name in a mode (the second was dropped); keys of a modes document that would be
//! ignored; and a type error inside an angle names the field, not only the angle.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use serde_json::json;
use wingbeat::config::SimConfig;
use wingbeat::error::parse_json;
use wingbeat::fem::FemInput;
use wingbeat::modes_doc::{modes_from_json, read_modes_document};

/// A config whose `kinematics` (when given) is the paper's with the given keys replaced
/// (`Kinematics` has no defaults, so a partial one fails for another reason).
fn full(mut v: serde_json::Value) -> serde_json::Value {
    if let Some(k) = v.get("kinematics").and_then(|k| k.as_object()).cloned() {
        let mut base = serde_json::to_value(SimConfig::paper()).unwrap()["kinematics"].clone();
        for (key, val) in k {
            base[key] = val;
        }
        v["kinematics"] = base;
    }
    v
}

fn cfg_err(v: serde_json::Value) -> String {
    let v = full(v);
    SimConfig::from_json(&v.to_string())
        .expect_err(&format!("should be refused: {v}"))
        .to_string()
}

fn assert_array_refused(msg: &str, path: &str) {
    assert!(
        msg.contains("found an array") && msg.contains("not read by position"),
        "{msg}"
    );
    if !path.is_empty() {
        assert!(
            msg.contains(&format!("at `{path}`")),
            "expected path {path}: {msg}"
        );
    }
}

/// One mode and one strain, as objects and as the same fields in order.
fn mode_obj() -> serde_json::Value {
    json!({"name": "m", "freq_hz": 62.5, "a": [7.5e-6, 9.3e-7], "zeta": 0.0, "strains": [
        {"point": "P", "eps_x": 1.0, "eps_y": 0.0, "gamma_xy": 0.0}]})
}

#[test]
fn arrays_where_config_objects_belong_are_refused_at_every_level() {
    let paper = serde_json::to_value(SimConfig::paper()).unwrap();
    // the whole config, by position (kinematics, modes, duration, rate, ic)
    let whole = json!([paper["kinematics"], paper["modes"], 0.1, 1000.0, []]);
    assert_array_refused(&cfg_err(whole), "");
    let kin = &paper["kinematics"];
    let cases = vec![
        (
            json!({"kinematics": [25.0, kin["alpha"], kin["beta"], kin["gamma"]]}),
            "kinematics",
        ),
        (
            json!({"kinematics": {"alpha": [0.0, []]}}),
            "kinematics.alpha",
        ),
        (
            json!({"kinematics": {"alpha": {"kind": "fourier", "harmonics": [[1, 0.5, 0.0]]}}}),
            "kinematics.alpha.harmonics[0]",
        ),
        (
            json!({"kinematics": {"body_rate": [{"kind": "fourier"}, {"kind": "fourier"}, {"kind": "fourier"}]}}),
            "kinematics.body_rate",
        ),
        (
            json!({"kinematics": {"body_rate": {"z": {"kind": "fourier", "mean": 1.0, "harmonics": [[1, 0.5, 0.0]]}}}}),
            "kinematics.body_rate.z.harmonics[0]",
        ),
        (
            json!({"kinematics": {"body_rate": {"z": {"kind": "fourier", "harmonics": [[1, 0.0, 0.0]]}}}}),
            "kinematics.body_rate.z.harmonics[0]",
        ),
        (
            json!({"modes": [["m", 62.5, [7.5e-6, 9.3e-7], 0.0, []]]}),
            "modes[0]",
        ),
        (
            json!({"modes": [mode_obj(), {"freq_hz": 86.9, "a": [1e-6, 1e-6], "strains": [["P", 1.0, 0.0, 0.0]]}]}),
            "modes[1].strains[0]",
        ),
    ];
    for (v, path) in cases {
        assert_array_refused(&cfg_err(v), path);
    }
    // the same documents with objects are accepted
    let ok = json!({"modes": [mode_obj()], "kinematics": {"alpha": {"kind": "fourier",
        "harmonics": [{"n": 1, "amplitude": 0.5}]}}});
    SimConfig::from_json(&full(ok).to_string()).expect("objects are read");
    // a short array is refused as an array too, not as "invalid length"
    let m = cfg_err(json!({"modes": [["m", 62.5]]}));
    assert!(m.contains("modes[0]") && m.contains("array"), "{m}");
}

#[test]
fn arrays_where_fe_input_objects_belong_are_refused() {
    let def = serde_json::to_value(FemInput::default()).unwrap();
    let fe_err = |v: serde_json::Value| {
        parse_json::<FemInput>(&v.to_string(), "FE input")
            .expect_err(&format!("should be refused: {v}"))
            .to_string()
    };
    // the material by position (thickness, E, rho, nu in its own order)
    let mat: Vec<serde_json::Value> = def["material"]
        .as_object()
        .unwrap()
        .values()
        .cloned()
        .collect();
    assert_array_refused(&fe_err(json!({"material": mat})), "material");
    assert_array_refused(&fe_err(json!([def["planform_mm"]])), "");
    let clamp = json!({"clamp": {"strip": [2.0]}});
    assert!(
        parse_json::<FemInput>(&clamp.to_string(), "FE input").is_err(),
        "a strip clamp as an array was read: {clamp}"
    );
}

#[test]
fn arrays_and_duplicate_names_in_modes_documents_are_refused() {
    let text = json!({"modes": [["m", 62.5, [7.5e-6, 9.3e-7], 0.0, []]]}).to_string();
    assert_array_refused(
        &modes_from_json(&text, "m.json").unwrap_err().to_string(),
        "modes[0]",
    );
    assert_array_refused(
        &read_modes_document(&text, "m.json")
            .unwrap_err()
            .to_string(),
        "modes[0]",
    );
    let mut m = mode_obj();
    m["strains"] = json!([
        {"point": "P", "eps_x": 1.0, "eps_y": 0.0, "gamma_xy": 0.0},
        {"point": "Q", "eps_x": 1.0, "eps_y": 0.0, "gamma_xy": 0.0},
        {"point": "P", "eps_x": 2.0, "eps_y": 0.0, "gamma_xy": 0.0}
    ]);
    let doc = json!({"modes": [mode_obj(), m]});
    for e in [
        modes_from_json(&doc.to_string(), "m.json").unwrap_err(),
        read_modes_document(&doc.to_string(), "m.json").unwrap_err(),
        SimConfig::from_json(&doc.to_string())
            .and_then(|c| c.validate())
            .unwrap_err(),
    ] {
        let e = e.to_string();
        assert!(
            e.contains("modes[1].strains[2]")
                && e.contains("modes[1].strains[0]")
                && e.contains("\"P\""),
            "names both: {e}"
        );
    }
}

#[test]
fn unknown_or_malformed_companions_in_a_modes_document_are_refused() {
    let modes = json!([mode_obj()]);
    let mut material =
        serde_json::to_value(wingbeat::fem::ShellMaterial::paper_frequencies()).unwrap();
    material["damping"] = json!(0.1);
    for (doc, path) in [
        // a unit the document does not have, or not a unit string
        (
            json!({"modes": modes, "units": {"freq_hz": "Hz", "speed": "m/s"}}),
            "units.speed",
        ),
        (
            json!({"modes": modes, "units": {"freq_hz": 1}}),
            "units.freq_hz",
        ),
        (json!({"modes": modes, "units": ["Hz"]}), "units"),
        // an unknown key inside a known one (was dropped with the key)
        (
            json!({"modes": modes, "material": material}),
            "material.damping",
        ),
        // known keys of the wrong form (were never read)
        (json!({"modes": modes, "shapes": "flat"}), "shapes"),
        (
            json!({"modes": modes, "mesh_size_mm": [1.0]}),
            "mesh_size_mm",
        ),
        (
            json!({"freq_hz": [100.0], "a": [[1e-6, 1e-6]], "b": [[0.0, "x"]]}),
            "b[0][1]",
        ),
    ] {
        let e = modes_from_json(&doc.to_string(), "m.json")
            .unwrap_err()
            .to_string();
        assert!(e.contains(&format!("at `{path}`")), "{doc}: {e}");
        let e = read_modes_document(&doc.to_string(), "m.json")
            .unwrap_err()
            .to_string();
        assert!(e.contains(&format!("at `{path}`")), "{doc}: {e}");
    }
    // well-formed companions are still accepted (a `wingbeat modes` document without its mesh)
    for doc in [
        json!({"modes": modes, "units": {"freq_hz": "Hz"}, "planform_note": "x", "mesh_size_mm": 1.0}),
        json!({"freq_hz": [100.0], "a": [[1e-6, 1e-6]], "kinds": ["bending"]}),
    ] {
        modes_from_json(&doc.to_string(), "m.json").expect("accepted");
    }
}

#[test]
fn type_errors_inside_an_angle_name_the_field() {
    for (v, path) in [
        (
            json!({"kinematics": {"alpha": {"kind": "sampled", "values": [0.0, 0.1, 0.2], "max_harmonic": "x"}}}),
            "kinematics.alpha.max_harmonic",
        ),
        (
            json!({"kinematics": {"alpha": {"kind": "sampled", "values": [0.0, "a", 0.2]}}}),
            "kinematics.alpha.values[1]",
        ),
        (
            json!({"kinematics": {"beta": {"kind": "fourier", "harmonics": [{"n": 1.5, "amplitude": 0.1}]}}}),
            "kinematics.beta.harmonics[0].n",
        ),
        (
            json!({"kinematics": {"gamma": {"kind": "fourier", "mean": "zero"}}}),
            "kinematics.gamma.mean",
        ),
        (
            json!({"kinematics": {"gamma": {"kind": "fourier", "meen": 0.0}}}),
            "kinematics.gamma.meen",
        ),
        (
            json!({"kinematics": {"body_rate": {"y": {"kind": "fourier", "mean": [1]}}}}),
            "kinematics.body_rate.y.mean",
        ),
        (
            json!({"kinematics": {"alpha": {"kind": "spline"}}}),
            "kinematics.alpha.kind",
        ),
        (
            json!({"kinematics": {"alpha": {"mean": 0.0}}}),
            "kinematics.alpha",
        ),
    ] {
        let m = cfg_err(v.clone());
        assert!(m.contains(&format!("at `{path}`")), "{v}: {m}");
    }
    // unknown keys inside an angle are still named with the allowed ones
    let m = cfg_err(json!({"kinematics": {"gamma": {"kind": "fourier", "meen": 0.0}}}));
    assert!(m.contains("meen") && m.contains("mean"), "{m}");
}
