//! The wasm API against the core, in node (wasm-bindgen-test-runner). Run:
//! `CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER=wasm-bindgen-test-runner cargo test --release
//!  --target wasm32-unknown-unknown --no-default-features --features web,render --test wasm_api`
//! (`npm run test:wasm` does this and the Chromium suite).
#![cfg(target_arch = "wasm32")]

mod wasm_common;
use wasm_bindgen_test::wasm_bindgen_test;

#[wasm_bindgen_test]
fn simulate_matches_core() {
    wasm_common::simulate_matches_core();
}

#[wasm_bindgen_test]
fn paper_reference_numbers() {
    wasm_common::paper_reference_numbers();
}

#[wasm_bindgen_test]
fn analyze_matches_core() {
    wasm_common::analyze_matches_core();
}

#[wasm_bindgen_test]
fn coriolis_force_peaks_at_twice_the_flap_frequency() {
    wasm_common::coriolis_force_peaks_at_twice_the_flap_frequency();
}

#[wasm_bindgen_test]
fn psd_matches_core() {
    wasm_common::psd_matches_core();
}

#[wasm_bindgen_test]
fn sweep_matches_core_and_reports_progress() {
    wasm_common::sweep_matches_core_and_reports_progress();
}

#[wasm_bindgen_test]
fn ic_map_matches_core() {
    wasm_common::ic_map_matches_core();
}

#[wasm_bindgen_test]
fn defaults_limits_reproduce() {
    wasm_common::defaults_limits_reproduce();
}

#[wasm_bindgen_test]
fn reproduce_matches_core() {
    wasm_common::reproduce_matches_core();
}

#[wasm_bindgen_test]
fn bad_input_names_the_field() {
    wasm_common::bad_input_names_the_field();
}

#[wasm_bindgen_test]
fn fe_modes_match_core() {
    wasm_common::fe_modes_match_core();
}

#[wasm_bindgen_test]
fn angles_match_core() {
    wasm_common::angles_match_core();
}

#[wasm_bindgen_test]
fn stiffness_spectra_match_reference() {
    wasm_common::stiffness_spectra_match_reference();
}

#[wasm_bindgen_test]
fn ts_declarations_match_results() {
    wasm_common::ts_declarations_match_results();
}

// ---- The lab-facing additions: parameters, applyOverrides, resonanceMap, analyze's angles ----

use std::cell::RefCell;
use std::rc::Rc;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use wasm_common::{f64s, get, message, num, to_js};
use wingbeat::analysis::angles::angle_series;
use wingbeat::analysis::resonance::{resonance_map as core_resonance_map, ResonanceOptions};
use wingbeat::config::SimConfig;
use wingbeat::params::{apply_overrides as core_apply_overrides, PARAMS, PHASE_LIMIT};
use wingbeat::wasm;

fn json(text: &str) -> JsValue {
    js_sys::JSON::parse(text).unwrap()
}

#[wasm_bindgen_test]
fn parameters_are_the_core_table() {
    let js = wasm::parameters().unwrap();
    let arr: js_sys::Array = js.clone().into();
    assert_eq!(arr.length() as usize, PARAMS.len());
    for (i, p) in PARAMS.iter().enumerate() {
        let at = |k: &str| get(&js, &format!("{i}.{k}"));
        assert_eq!(at("key").as_string().as_deref(), Some(p.key));
        assert_eq!(at("symbol").as_string().as_deref(), Some(p.symbol));
        assert_eq!(at("label").as_string().as_deref(), Some(p.label));
        assert_eq!(at("unit").as_string().as_deref(), Some(p.unit));
        for (k, v) in [
            ("min", p.min),
            ("max", p.max),
            ("step", p.step),
            ("default", p.default),
        ] {
            assert_eq!(num(&js, &format!("{i}.{k}")), v, "{}.{k}", p.key);
        }
    }
    assert_eq!(num(&js, "8.max"), 10.0); // duration: the 10 s damping experiment
}

#[wasm_bindgen_test]
fn apply_overrides_matches_core_and_names_bad_keys() {
    let base = SimConfig::paper();
    let o = json(
        r#"{"alpha0": 1.2, "beta0": 0.3, "gamma0": 0, "flap_hz": 31.5, "zeta": 0.01,
            "alpha_phase": 0.5, "beta_phase": -1.57, "gamma_phase": 3.14, "duration": 10}"#,
    );
    let got = wasm::apply_overrides(to_js(&base), o).unwrap();
    let got: SimConfig = serde_wasm_bindgen::from_value(got).unwrap();
    let want = core_apply_overrides(
        &base,
        [
            ("alpha0", 1.2),
            ("beta0", 0.3),
            ("gamma0", 0.0),
            ("flap_hz", 31.5),
            ("zeta", 0.01),
            ("alpha_phase", 0.5),
            ("beta_phase", -1.57),
            ("gamma_phase", PHASE_LIMIT),
            ("duration", 10.0),
        ],
    )
    .unwrap();
    assert_eq!(got, want);
    // An undefined base is the paper case; empty overrides change nothing.
    let got = wasm::apply_overrides(JsValue::UNDEFINED, json("{}")).unwrap();
    let got: SimConfig = serde_wasm_bindgen::from_value(got).unwrap();
    assert_eq!(got, base);
    // Named errors, never a trap.
    for (bad, field) in [
        (r#"{"gamma_0": 0.1}"#, "overrides.gamma_0"),
        (r#"{"gamma0": 0.9}"#, "overrides.gamma0"),
        (r#"{"gamma0": 0.9}"#, "[0, 0.5]"),
        (r#"{"duration": 11}"#, "overrides.duration"),
        (r#"{"zeta": "0.1"}"#, "overrides.zeta"),
        (r#"{"zeta": null}"#, "overrides.zeta"),
        (r#"[1, 2]"#, "overrides"),
    ] {
        let m = message(wasm::apply_overrides(to_js(&base), json(bad)));
        assert!(m.contains(field), "{bad}: `{m}` lacks {field}");
    }
    let m = message(wasm::apply_overrides(
        to_js(&base),
        JsValue::from_f64(f64::NAN),
    ));
    assert!(m.contains("overrides"), "{m}");
    let m = message(wasm::apply_overrides(
        json(r#"{"duration_s": -1}"#),
        json("{}"),
    ));
    assert!(m.contains("duration_s"), "{m}");
}

#[wasm_bindgen_test]
fn resonance_map_matches_core_and_reports_progress() {
    let cfg = SimConfig::paper();
    let opts = ResonanceOptions {
        from_hz: 5.0,
        to_hz: 60.0,
        points: 12,
        alpha0_values: Some(vec![0.4, 0.8, 1.2]),
    };
    let calls = Rc::new(RefCell::new(Vec::new()));
    let c2 = calls.clone();
    let cb =
        Closure::wrap(Box::new(move |i: f64, n: f64| c2.borrow_mut().push((i, n)))
            as Box<dyn FnMut(f64, f64)>);
    let f: js_sys::Function = cb.as_ref().clone().unchecked_into();
    let js = wasm::resonance_map(to_js(&cfg), to_js(&opts), f.into()).unwrap();
    assert_eq!(calls.borrow().len(), 36);
    assert_eq!(calls.borrow().last(), Some(&(36.0, 36.0)));
    let core = core_resonance_map(&cfg, &opts, |_, _| {}).unwrap();
    assert_eq!(f64s(&js, "flap_hz"), core.flap_hz);
    assert_eq!(f64s(&js, "alpha0"), vec![0.4, 0.8, 1.2]);
    let mut unstable = 0;
    for (k, m) in core.modes.iter().enumerate() {
        assert_eq!(num(&js, &format!("modes.{k}.freq_hz")), m.freq_hz);
        assert_eq!(
            f64s(&js, &format!("modes.{k}.effective_freq_hz")),
            m.effective_freq_hz
        );
        assert_eq!(f64s(&js, &format!("modes.{k}.max_modulus")), m.max_modulus);
        let beat = f64s(&js, &format!("modes.{k}.beat_period_s"));
        for (g, w) in beat.iter().zip(&m.beat_period_s) {
            match w {
                Some(w) => assert_eq!(g, w),
                None => assert!(g.is_nan()),
            }
        }
        let stable = get(&js, &format!("modes.{k}.stable"))
            .dyn_into::<js_sys::Uint8Array>()
            .unwrap()
            .to_vec();
        let want: Vec<u8> = m.stable.iter().map(|&s| u8::from(s)).collect();
        assert_eq!(stable, want);
        unstable += want.iter().filter(|&&s| s == 0).count();
        let nb = get(&js, &format!("modes.{k}.beat_harmonic"))
            .dyn_into::<js_sys::Uint32Array>()
            .unwrap()
            .to_vec();
        assert_eq!(nb, m.beat_harmonic);
    }
    assert!(unstable > 0);
    // Without alpha0_values: one row, no `alpha0` key.
    let one = ResonanceOptions {
        alpha0_values: None,
        ..opts
    };
    let js = wasm::resonance_map(to_js(&cfg), to_js(&one), JsValue::UNDEFINED).unwrap();
    assert!(get(&js, "alpha0").is_undefined());
    assert_eq!(f64s(&js, "modes.0.effective_freq_hz").len(), 12);
    // A throwing progress callback is ignored.
    let thrower = js_sys::Function::new_with_args("i, n", "throw new Error('boom')");
    assert!(wasm::resonance_map(to_js(&cfg), to_js(&one), thrower.into()).is_ok());
}

#[wasm_bindgen_test]
fn resonance_map_names_bad_options() {
    let cfg = to_js(&SimConfig::paper());
    for (bad, field) in [
        (
            r#"{"from_hz": 5, "to_hz": 60, "points": 1}"#,
            "resonance.points",
        ),
        (
            r#"{"from_hz": 5, "to_hz": 60, "points": 99999}"#,
            "resonance.points",
        ),
        (
            r#"{"from_hz": -5, "to_hz": 60, "points": 10}"#,
            "resonance.from_hz",
        ),
        (
            r#"{"from_hz": 5, "to_hz": null, "points": 10}"#,
            "resonance.to_hz",
        ),
        (
            r#"{"from_hz": 5, "to_hz": 60, "points": 10, "bogus": 1}"#,
            "bogus",
        ),
        (
            r#"{"from_hz": 5, "to_hz": 60, "points": 10, "alpha0_values": [0.1, 9]}"#,
            "resonance.alpha0_values[1]",
        ),
        (
            r#"{"from_hz": 0.5, "to_hz": 60, "points": 2001, "alpha0_values": [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.7, 1.8, 1.9, 2.0, 2.1, 2.2, 2.3, 2.4, 2.5, 2.6, 2.7, 2.8, 2.9, 3.0, 3.1, 3.2, 3.3, 3.4, 3.5, 3.6, 3.7, 3.8, 3.9, 4.0, 4.1, 4.2, 4.3, 4.4, 4.5, 4.6, 4.7, 4.8, 4.9, 5.0, 5.1, 5.2, 5.3, 5.4, 5.5, 5.6, 5.7, 5.8, 5.9, 6.0]}"#,
            "over the cap",
        ),
    ] {
        let m = message(wasm::resonance_map(
            cfg.clone(),
            json(bad),
            JsValue::UNDEFINED,
        ));
        assert!(m.contains(field), "{bad}: `{m}` lacks {field}");
    }
    let m = message(wasm::resonance_map(
        cfg,
        JsValue::UNDEFINED,
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("resonance"), "{m}");
}

#[wasm_bindgen_test]
fn analyze_returns_the_angles_on_the_simulation_grid() {
    let cfg = core_apply_overrides(
        &SimConfig::paper(),
        [("duration", 0.4), ("alpha_phase", 0.3)],
    )
    .unwrap();
    let js = wasm::analyze(to_js(&cfg), JsValue::UNDEFINED, JsValue::from(0.0)).unwrap();
    let t = f64s(&js, "sim.t");
    let core = angle_series(&cfg).unwrap();
    let kin = cfg.kinematics.compile();
    for (name, got, want) in [
        ("alpha", f64s(&js, "angles.alpha"), &core.alpha),
        ("beta", f64s(&js, "angles.beta"), &core.beta),
        ("gamma", f64s(&js, "angles.gamma"), &core.gamma),
    ] {
        assert_eq!(got.len(), t.len(), "{name}");
        assert_eq!(&got, want, "{name}");
    }
    // The same numbers `anglesAt` gives for the same times.
    let at = wasm::angles_at(to_js(&cfg), wasm_common::fa(&t))
        .unwrap()
        .to_vec();
    let alpha = f64s(&js, "angles.alpha");
    for (i, &ti) in t.iter().enumerate().step_by(101) {
        assert_eq!(at[3 * i], alpha[i]);
        assert_eq!(kin.state(ti).alpha, alpha[i]);
    }
}

#[wasm_bindgen_test]
fn resonance_map_of_200_points_is_fast() {
    let cfg = to_js(&SimConfig::paper());
    let opts = json(r#"{"from_hz": 5, "to_hz": 60, "points": 200}"#);
    let t0 = js_sys::Date::now();
    let js = wasm::resonance_map(cfg, opts, JsValue::UNDEFINED).unwrap();
    let ms = js_sys::Date::now() - t0;
    wasm_bindgen_test::console_log!("resonanceMap, 200 points x 2 modes (paper wing): {ms} ms");
    assert_eq!(f64s(&js, "modes.1.max_modulus").len(), 200);
    assert!(ms < 30_000.0);
}

// ---- The lab's own wing and own kinematics (src/wasm/wing.rs, kinematicsFromCsv) ----

// The same reader wasm_common includes privately.
#[allow(clippy::duplicate_mod)]
#[path = "ts_common/mod.rs"]
mod ts_common;

use wingbeat::analysis::strain::{strain_field as core_strain_field, StrainFieldOptions};
use wingbeat::fem::{compute_modes, geometry, strain_point_for};
use wingbeat::params::{material_presets, wing_input as core_wing_input, WING_PARAMS};

fn js_keys(o: &JsValue) -> Vec<String> {
    js_sys::Object::keys(o.unchecked_ref::<js_sys::Object>())
        .iter()
        .map(|k| k.as_string().unwrap())
        .collect()
}

fn close(name: &str, got: f64, want: f64) {
    let scale = got.abs().max(want.abs()).max(1e-300);
    assert!(
        (got - want).abs() <= 1e-12 * scale,
        "{name}: wasm {got:e} vs core {want:e}"
    );
}

#[wasm_bindgen_test]
fn wing_tables_are_the_core_tables() {
    let js = wasm::wing_parameters().unwrap();
    for (i, p) in WING_PARAMS.iter().enumerate() {
        assert_eq!(
            get(&js, &format!("{i}.key")).as_string().as_deref(),
            Some(p.key)
        );
        for (k, v) in [
            ("min", p.min),
            ("max", p.max),
            ("step", p.step),
            ("default", p.default),
        ] {
            assert_eq!(num(&js, &format!("{i}.{k}")), v, "{}.{k}", p.key);
        }
    }
    let js = wasm::material_presets().unwrap();
    for (i, m) in material_presets().iter().enumerate() {
        assert_eq!(
            get(&js, &format!("{i}.id")).as_string().as_deref(),
            Some(m.id)
        );
        assert_eq!(num(&js, &format!("{i}.e_pa")), m.e_pa);
        assert_eq!(num(&js, &format!("{i}.thickness_um")), m.thickness_um);
    }
    let js = wasm::planforms().unwrap();
    for (i, b) in geometry::builtin_planforms().iter().enumerate() {
        assert_eq!(
            get(&js, &format!("{i}.id")).as_string().as_deref(),
            Some(b.id)
        );
        let n = js_sys::Array::from(&get(&js, &format!("{i}.points_mm"))).length() as usize;
        assert_eq!(n, b.points_mm.len());
        assert_eq!(num(&js, &format!("{i}.points_mm.1.1")), b.points_mm[1][1]);
    }
}

/// The lab's wing input path (wingInput → feModes) gives the same frequencies, a_k and strains
/// as `compute_modes` on the core's input, to 1e-12; modalStrainAt gives feModes' strains at
/// its strain point; strainField matches the core.
#[wasm_bindgen_test]
fn wing_input_path_matches_compute_modes() {
    let pts = geometry::builtin_planforms()[1].points_mm.clone(); // slender
    let input = wasm::wing_input(
        json(r#"{"n_modes": 3, "mesh_mm": 3, "camber": 0.05, "clamp_mm": 1.5}"#),
        to_js(&pts),
    )
    .unwrap();
    let core_in = core_wing_input(
        [
            ("n_modes", 3.0),
            ("mesh_mm", 3.0),
            ("camber", 0.05),
            ("clamp_mm", 1.5),
        ],
        Some(pts),
    )
    .unwrap();
    let back: wingbeat::fem::FemInput = serde_wasm_bindgen::from_value(input.clone()).unwrap();
    assert_eq!(back, core_in);
    let js = wasm::fe_modes(input, JsValue::from(0.0), JsValue::UNDEFINED).unwrap();
    let core = compute_modes(&core_in).unwrap();
    let (px, py) = strain_point_for(&core_in);
    let modes = core
        .model_modes(0.0, &[("P".to_string(), px, py)], "P")
        .unwrap();
    let freq = f64s(&js, "freq_hz");
    assert_eq!(freq.len(), 3);
    for k in 0..3 {
        close(&format!("freq_hz[{k}]"), freq[k], core.freq_hz[k]);
        close(
            &format!("a[{k}].x"),
            num(&js, &format!("a.{k}.0")),
            core.a[k][0],
        );
        close(
            &format!("a[{k}].y"),
            num(&js, &format!("a.{k}.1")),
            core.a[k][1],
        );
        for (c, want) in [
            ("eps_x", modes[k].strains[0].eps_x),
            ("eps_y", modes[k].strains[0].eps_y),
            ("gamma_xy", modes[k].strains[0].gamma_xy),
        ] {
            close(c, num(&js, &format!("modes.{k}.strains.0.{c}")), want);
        }
    }
    // modalStrainAt at feModes' own strain point equals the strains feModes reports there.
    let nodes = f64s(&js, "nodes");
    let tris = get(&js, "triangles")
        .dyn_into::<js_sys::Uint32Array>()
        .unwrap()
        .to_vec();
    let sn = f64s(&js, "strain_nodes");
    let p = [num(&js, "strain_point_mm.0"), num(&js, "strain_point_mm.1")];
    let at = wasm::modal_strain_at(
        wasm_common::fa(&nodes),
        js_sys::Uint32Array::from(&(&tris)[..]).into(),
        wasm_common::fa(&sn),
        JsValue::from(3.0),
        wasm_common::fa(&p),
    )
    .unwrap();
    for k in 0..3 {
        for c in ["eps_x", "eps_y", "gamma_xy"] {
            close(
                &format!("modalStrainAt {k} {c}"),
                num(&at, &format!("{k}.{c}")),
                num(&js, &format!("modes.{k}.strains.0.{c}")),
            );
        }
    }
    let i = ts_common::interfaces(ts_common::declarations());
    ts_common::check(&i, "ModalStrainValues", &js_keys(&get(&at, "0")));
    // Outside the wing and inconsistent arrays: named errors.
    let m = message(wasm::modal_strain_at(
        wasm_common::fa(&nodes),
        js_sys::Uint32Array::from(&(&tris)[..]).into(),
        wasm_common::fa(&sn),
        JsValue::from(3.0),
        wasm_common::fa(&[200.0, 0.0]),
    ));
    assert!(
        m.contains("point") && m.contains("inside the meshed planform"),
        "{m}"
    );
    let m = message(wasm::modal_strain_at(
        wasm_common::fa(&nodes),
        js_sys::Uint32Array::from(&(&tris)[..]).into(),
        wasm_common::fa(&sn),
        JsValue::from(4.0),
        wasm_common::fa(&p),
    ));
    assert!(m.contains("strain_nodes"), "{m}");
    let m = message(wasm::modal_strain_at(
        wasm_common::fa(&nodes),
        js_sys::Uint32Array::from(&(&tris)[..]).into(),
        wasm_common::fa(&sn),
        JsValue::from(2.5),
        wasm_common::fa(&p),
    ));
    assert!(m.contains("n_modes"), "{m}");
    let mut bad = tris.clone();
    bad[4] = 1_000_000;
    let m = message(wasm::modal_strain_at(
        wasm_common::fa(&nodes),
        js_sys::Uint32Array::from(&(&bad)[..]).into(),
        wasm_common::fa(&sn),
        JsValue::from(3.0),
        wasm_common::fa(&p),
    ));
    assert!(m.contains("triangles[4]"), "{m}");
    let m = message(wasm::modal_strain_at(
        wasm_common::fa(&nodes),
        js_sys::Uint32Array::from(&(&tris)[..]).into(),
        wasm_common::fa(&sn),
        JsValue::from(3.0),
        wasm_common::fa(&[1.0]),
    ));
    assert!(m.contains("point"), "{m}");
    // strainField against the core, both statistics.
    let qs: Vec<Vec<f64>> = (0..3)
        .map(|k| {
            (0..500)
                .map(|t| ((t * (k + 2)) as f64 * 0.01).sin())
                .collect()
        })
        .collect();
    let arr = js_sys::Array::new();
    for q in &qs {
        arr.push(&js_sys::Float64Array::from(&q[..]));
    }
    let refs: Vec<&[f64]> = qs.iter().map(Vec::as_slice).collect();
    let nn = core.nodes.len();
    for opts in [
        r#"{"stat": "rms"}"#,
        r#"{"component": "eps_y", "stat": "peak"}"#,
        r#"{"component": "gamma_xy", "stat": "rms"}"#,
    ] {
        let got = wasm::strain_field(
            wasm_common::fa(&sn),
            JsValue::from(3.0),
            arr.clone().into(),
            json(opts),
        )
        .unwrap()
        .to_vec();
        let o: StrainFieldOptions = serde_json::from_str(opts).unwrap();
        let want = core_strain_field(nn, 3, |k, i| core.strain_nodes[k][i], &refs, &o).unwrap();
        assert_eq!(got.len(), nn);
        let scale = want.iter().fold(0.0f64, |m, v| m.max(*v));
        for (g, w) in got.iter().zip(&want) {
            assert!((g - w).abs() <= 1e-12 * scale, "{opts}: {g} vs {w}");
        }
    }
    for (qs, opts, want) in [
        (
            json("[[1, 2]]"),
            r#"{"stat": "rms"}"#,
            "one series per mode (3)",
        ),
        (arr.clone().into(), r#"{"stat": "max"}"#, "strainField.stat"),
        (arr.clone().into(), r#"{"stat": "rms", "x": 1}"#, "x"),
        (JsValue::from_f64(1.0), r#"{"stat": "rms"}"#, "qs"),
        (json("[[1, 2], [1], [1, 2]]"), r#"{"stat": "rms"}"#, "qs[1]"),
        (
            json(r#"[[1, 2], [1, "a"], [1, 2]]"#),
            r#"{"stat": "rms"}"#,
            "qs[1][1]",
        ),
    ] {
        let m = message(wasm::strain_field(
            wasm_common::fa(&sn),
            JsValue::from(3.0),
            qs,
            json(opts),
        ));
        assert!(m.contains(want), "{opts}: `{m}` lacks {want}");
    }
    let m = message(wasm::strain_field(
        wasm_common::fa(&sn),
        JsValue::from(3.0),
        arr.into(),
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("strainField"), "{m}");
}

#[wasm_bindgen_test]
fn outline_functions_check_without_throwing() {
    let csv = "x_mm,y_mm\n0,-10\n40,-10\n40,0\n0,0\n";
    let pts = wasm::parse_planform(JsValue::from(csv), JsValue::from("csv")).unwrap();
    let same = wasm::parse_planform(
        JsValue::from("[[0,-10],[40,-10],[40,0],[0,0]]"),
        JsValue::from("json"),
    )
    .unwrap();
    assert_eq!(
        js_sys::JSON::stringify(&pts).unwrap(),
        js_sys::JSON::stringify(&same).unwrap()
    );
    let c = wasm::check_planform(pts).unwrap();
    assert_eq!(get(&c, "ok").as_bool(), Some(true));
    assert_eq!(num(&c, "area_mm2"), 400.0);
    assert_eq!(num(&c, "span_mm"), 40.0);
    assert_eq!(num(&c, "chord_mm"), 10.0);
    assert_eq!(get(&c, "root_edge").as_bool(), Some(true));
    let rect = geometry::rectangle_planform(40.0, 10.0);
    assert_eq!(
        num(&c, "default_mesh_size_mm"),
        wingbeat::fem::default_mesh_size_mm(&rect)
    );
    let (sx, sy) = wingbeat::fem::default_strain_point_mm(&rect);
    assert_eq!(num(&c, "default_strain_point_mm.0"), sx);
    assert_eq!(num(&c, "default_strain_point_mm.1"), sy);
    let i = ts_common::interfaces(ts_common::declarations());
    ts_common::check(&i, "PlanformOk", &js_keys(&c));
    // Bad outlines answer { ok: false, error } and never throw.
    for (bad, want) in [
        ("[[0,0],[1,1],[0,1],[1,0]]", "self-intersecting"),
        ("[[0,0],[1,1]]", "planform"),
        ("[[0,0],[1,1],[2, null]]", "points"),
        ("[1, 2, 3]", "points"),
        ("[]", "planform"),
    ] {
        let c = wasm::check_planform(json(bad)).unwrap();
        assert_eq!(get(&c, "ok").as_bool(), Some(false), "{bad}");
        let e = get(&c, "error").as_string().unwrap();
        assert!(e.contains(want), "{bad}: `{e}` lacks {want}");
        ts_common::check(&i, "PlanformError", &js_keys(&c));
    }
    let big = js_sys::Array::new();
    for _ in 0..5001 {
        big.push(&json("[0, 0]"));
    }
    let c = wasm::check_planform(big.into()).unwrap();
    assert!(get(&c, "error").as_string().unwrap().contains("5000"));
    // Only a non-array throws.
    assert!(message(wasm::check_planform(JsValue::from_f64(3.0))).contains("points"));
    assert!(message(wasm::check_planform(json(r#"{"a": 1}"#))).contains("points"));
    // Parse errors and wingInput errors name the line, format or key.
    assert!(message(wasm::parse_planform(
        JsValue::from("x_mm,y_mm\n1,2\n3,a\n"),
        JsValue::from("csv")
    ))
    .contains("line 3"));
    assert!(message(wasm::parse_planform(
        JsValue::from("[]"),
        JsValue::from("xml")
    ))
    .contains("parsePlanform.format"));
    let m = message(wasm::wing_input(
        json(r#"{"camber": 0.9}"#),
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("wing.camber") && m.contains("[0, 0.5]"), "{m}");
    let m = message(wasm::wing_input(
        json(r#"{"n_mode": 3}"#),
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("wing.n_mode"), "{m}");
    let m = message(wasm::wing_input(
        json(r#"{"nu": null}"#),
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("wing.nu"), "{m}");
    let m = message(wasm::wing_input(JsValue::UNDEFINED, JsValue::from_f64(1.0)));
    assert!(m.contains("points"), "{m}");
    let m = message(wasm::wing_input(JsValue::UNDEFINED, json("[[0,0],[1,1]]")));
    assert!(m.contains("planform"), "{m}");
    // The default: the table defaults on the default outline.
    let d = wasm::wing_input(JsValue::UNDEFINED, JsValue::UNDEFINED).unwrap();
    let d: wingbeat::fem::FemInput = serde_wasm_bindgen::from_value(d).unwrap();
    assert_eq!(d, wingbeat::params::default_wing().unwrap());
}

#[wasm_bindgen_test]
fn kinematics_from_csv_matches_core() {
    use wingbeat::kinematics_table::{kinematics_from_csv, AngleUnits, CsvKinematicsOptions};
    let mut text = String::from("t,alpha,gamma\n");
    for i in 0..80 {
        let t = i as f64 * 0.04 / 40.0;
        let th = 2.0 * std::f64::consts::PI * 25.0 * t;
        text.push_str(&format!(
            "{t},{},{}\n",
            45.0 * th.sin(),
            10.0 * (2.0 * th).cos()
        ));
    }
    let js = wasm::kinematics_from_csv(
        JsValue::from(&text),
        json(r#"{"units": "deg", "flap_hz": 25}"#),
    )
    .unwrap();
    let core = kinematics_from_csv(
        &text,
        &CsvKinematicsOptions {
            units: AngleUnits::Deg,
            flap_hz: 25.0,
            max_harmonic: None,
        },
    )
    .unwrap();
    let k: wingbeat::kinematics::Kinematics =
        serde_wasm_bindgen::from_value(get(&js, "kinematics")).unwrap();
    assert_eq!(k, core.kinematics);
    assert_eq!(f64s(&js, "samples.t"), core.samples.t);
    assert_eq!(f64s(&js, "samples.alpha"), core.samples.alpha);
    assert_eq!(f64s(&js, "samples.beta"), vec![0.0; 80]);
    assert_eq!(num(&js, "n_periods"), 2.0);
    assert_eq!(get(&js, "method").as_string().as_deref(), Some("grid"));
    let i = ts_common::interfaces(ts_common::declarations());
    ts_common::check(&i, "KinematicsTable", &js_keys(&js));
    ts_common::check(&i, "FoldedSamples", &js_keys(&get(&js, "samples")));
    // The kinematics drop into a config: anglesAt previews the interpolant through the samples.
    let cfg = SimConfig {
        kinematics: k,
        ..SimConfig::paper()
    };
    let at = wasm::angles_at(to_js(&cfg), wasm_common::fa(&[0.01]))
        .unwrap()
        .to_vec();
    close("alpha(T/4)", at[0], 45f64.to_radians());
    for (opts, want) in [
        (
            r#"{"units": "grad", "flap_hz": 25}"#,
            "kinematicsFromCsv.units",
        ),
        (r#"{"units": "deg", "flap_hz": -1}"#, "flap_hz"),
        (r#"{"units": "deg"}"#, "flap_hz"),
        (
            r#"{"units": "deg", "flap_hz": 25, "max_harmonic": 999}"#,
            "max_harmonic",
        ),
    ] {
        let m = message(wasm::kinematics_from_csv(JsValue::from(&text), json(opts)));
        assert!(m.contains(want), "{opts}: `{m}` lacks {want}");
    }
    let m = message(wasm::kinematics_from_csv(
        JsValue::from("t,alpha\n0,1\n"),
        json(r#"{"units": "deg", "flap_hz": 25}"#),
    ));
    assert!(m.contains("rows"), "{m}");
    let m = message(wasm::kinematics_from_csv(
        JsValue::from(&text),
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("kinematicsFromCsv"), "{m}");
    let l = wasm::limits().unwrap();
    assert_eq!(num(&l, "max_strain_field_work"), 5e8);
    ts_common::check(&i, "Limits", &js_keys(&l));
}

/// feModes' exported document (`modes_json`) read back by modesFromJson: the same modes and
/// mesh arrays (to the last place: the JSON text round trip), in feModes' layout.
#[wasm_bindgen_test]
fn modes_from_json_reads_the_exported_document() {
    let js = wasm::fe_modes(
        json(r#"{"n_modes": 2, "mesh_size_mm": 3}"#),
        JsValue::from(0.01),
        json(r#"{"json": true}"#),
    )
    .unwrap();
    let text = get(&js, "modes_json").as_string().unwrap();
    let doc = wasm::modes_from_json(JsValue::from(&text)).unwrap();
    let i = ts_common::interfaces(ts_common::declarations());
    ts_common::check(&i, "ModesDocument", &js_keys(&doc));
    ts_common::check(&i, "ImportedFe", &js_keys(&get(&doc, "fe")));
    let near = |name: &str, a: f64, b: f64| {
        assert!(
            (a - b).abs() <= 4.5e-16 * a.abs().max(b.abs()),
            "{name}: {a:e} vs {b:e}"
        );
    };
    for k in 0..2 {
        for p in [
            "freq_hz",
            "a.0",
            "a.1",
            "zeta",
            "strains.0.eps_x",
            "strains.0.gamma_xy",
        ] {
            let path = format!("modes.{k}.{p}");
            near(&path, num(&doc, &path), num(&js, &path));
        }
    }
    for key in ["freq_hz", "nodes", "shapes", "strain_nodes"] {
        let (a, b) = (f64s(&doc, &format!("fe.{key}")), f64s(&js, key));
        assert_eq!(a.len(), b.len(), "{key}");
        for (x, y) in a.iter().zip(&b) {
            near(key, *x, *y);
        }
    }
    assert_eq!(num(&doc, "fe.n_nodes"), num(&js, "n_nodes"));
    assert_eq!(num(&doc, "fe.mesh_size_mm"), num(&js, "mesh_size_mm"));
    let t = |o: &JsValue, p: &str| {
        get(o, p)
            .dyn_into::<js_sys::Uint32Array>()
            .unwrap()
            .to_vec()
    };
    assert_eq!(t(&doc, "fe.triangles"), t(&js, "triangles"));
    // A plain modes list has no `fe`; damaged documents name the part.
    let plain = wasm::modes_from_json(JsValue::from(
        r#"{"modes": [{"freq_hz": 60, "a": [1e-4, 0]}]}"#,
    ))
    .unwrap();
    assert!(get(&plain, "fe").is_undefined());
    assert_eq!(num(&plain, "modes.0.freq_hz"), 60.0);
    let m = message(wasm::modes_from_json(JsValue::from("{")));
    assert!(m.contains("modes JSON"), "{m}");
    let m = message(wasm::modes_from_json(JsValue::from(
        r#"{"modes": [{"freq_hz": -1, "a": [0, 0]}]}"#,
    )));
    assert!(m.contains("modes[0].freq_hz"), "{m}");
    let broken = text.replacen("\"triangles\":[[", "\"triangles\":[[9999999,", 1);
    let m = message(wasm::modes_from_json(JsValue::from(&broken)));
    assert!(m.contains("modes JSON: fe"), "{m}");
}

// ---- Issue 13: no coercion, no trap, no non-finite result, no key ignored ----

#[wasm_bindgen_test]
fn integer_arguments_are_never_coerced() {
    let cfg = to_js(&SimConfig {
        duration_s: 0.2,
        ..SimConfig::paper()
    });
    for k in [1.5, -1.0, f64::NAN, 4294967296.0, f64::INFINITY] {
        let m = message(wasm::analyze(
            cfg.clone(),
            JsValue::UNDEFINED,
            JsValue::from(k),
        ));
        assert!(m.contains("`mode`") && m.contains("integer"), "{k}: {m}");
        assert!(!m.contains("4294967295"), "{m}");
        let m = message(wasm::spectra(
            cfg.clone(),
            JsValue::UNDEFINED,
            JsValue::from(k),
        ));
        assert!(m.contains("`mode`"), "{k}: {m}");
    }
}

#[wasm_bindgen_test]
fn functions_and_fake_arrays_are_refused_by_name() {
    let f: JsValue = js_sys::Function::new_no_args("return 1").into();
    let m = message(wasm::analyze(
        f.clone(),
        JsValue::UNDEFINED,
        JsValue::UNDEFINED,
    ));
    assert!(
        m.contains("a function") && !m.contains("unwrap_throw"),
        "{m}"
    );
    let m = message(wasm::simulate(f.clone()));
    assert!(m.contains("a function"), "{m}");
    // `{ length: 2e9 }` is not allocated: refused by name.
    let fake = json(r#"{"length": 2000000000}"#);
    let m = message(wasm::psd(
        fake.clone(),
        JsValue::from(100.0),
        JsValue::UNDEFINED,
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("psd.series"), "{m}");
    let m = message(wasm::envelope(fake));
    assert!(m.contains("envelope.series"), "{m}");
    let m = message(wasm::psd(
        f,
        JsValue::from(100.0),
        JsValue::UNDEFINED,
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("psd.series"), "{m}");
}

#[wasm_bindgen_test]
fn psd_envelope_and_ic_map_are_finite_or_refused() {
    let x: Vec<f64> = (0..256).map(|i| (i as f64 * 0.3).sin()).collect();
    let m = message(wasm::psd(
        wasm_common::fa(&x),
        JsValue::from(5e-324),
        JsValue::UNDEFINED,
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("psd.sample_rate_hz"), "{m}");
    let big: Vec<f64> = x.iter().map(|v| v * 1e308).collect();
    match wasm::psd(
        wasm_common::fa(&big),
        JsValue::from(100.0),
        JsValue::UNDEFINED,
        JsValue::UNDEFINED,
    ) {
        Ok(s) => assert!(f64s(&s, "psd").iter().all(|p| p.is_finite())),
        Err(e) => {
            let m = message::<()>(Err(e));
            assert!(m.contains("psd.series"), "{m}");
        }
    }
    match wasm::envelope(wasm_common::fa(&big)) {
        Ok(e) => assert!(e.to_vec().iter().all(|v| v.is_finite())),
        Err(e) => {
            let m = message::<()>(Err(e));
            assert!(m.contains("envelope.series"), "{m}");
        }
    }
    let cfg = to_js(&SimConfig {
        duration_s: 0.2,
        ..SimConfig::paper()
    });
    let m = message(wasm::ic_map(
        cfg,
        json(r#"{"n_q": 3, "n_qdot": 3, "q_range": [-1e308, 1e308]}"#),
    ));
    assert!(m.contains("ic_map.q_range") && m.contains("1e308"), "{m}");
}

#[wasm_bindgen_test]
fn unknown_nested_keys_are_refused() {
    let m = message(wasm::simulate(json(
        r#"{"modes":[{"freq_hz":62.5,"a":[7.5e-6,9.3e-7],"damping":0.05}]}"#,
    )));
    assert!(m.contains("modes[0].damping"), "{m}");
    let m = message(wasm::modes_from_json(JsValue::from(
        r#"{"modes":[{"freq_hz":60,"a":[1e-4,0],"damping":0.05}]}"#,
    )));
    assert!(m.contains("damping"), "{m}");
}

#[wasm_bindgen_test]
fn air_run_matches_core() {
    wasm_common::air_run_matches_core();
}

#[wasm_bindgen_test]
fn classify_rotation_matches_core() {
    wasm_common::classify_rotation_matches_core();
}
