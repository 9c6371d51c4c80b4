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
    let js = wasm::resonance_map(to_js(&cfg), to_js(&opts), Some(f)).unwrap();
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
    let js = wasm::resonance_map(to_js(&cfg), to_js(&one), None).unwrap();
    assert!(get(&js, "alpha0").is_undefined());
    assert_eq!(f64s(&js, "modes.0.effective_freq_hz").len(), 12);
    // A throwing progress callback is ignored.
    let thrower = js_sys::Function::new_with_args("i, n", "throw new Error('boom')");
    assert!(wasm::resonance_map(to_js(&cfg), to_js(&one), Some(thrower)).is_ok());
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
        let m = message(wasm::resonance_map(cfg.clone(), json(bad), None));
        assert!(m.contains(field), "{bad}: `{m}` lacks {field}");
    }
    let m = message(wasm::resonance_map(cfg, JsValue::UNDEFINED, None));
    assert!(m.contains("resonance"), "{m}");
}

#[wasm_bindgen_test]
fn analyze_returns_the_angles_on_the_simulation_grid() {
    let cfg = core_apply_overrides(
        &SimConfig::paper(),
        [("duration", 0.4), ("alpha_phase", 0.3)],
    )
    .unwrap();
    let js = wasm::analyze(to_js(&cfg), JsValue::UNDEFINED, Some(0)).unwrap();
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
    let at = wasm::angles_at(to_js(&cfg), &t).unwrap().to_vec();
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
    let js = wasm::resonance_map(cfg, opts, None).unwrap();
    let ms = js_sys::Date::now() - t0;
    wasm_bindgen_test::console_log!("resonanceMap, 200 points x 2 modes (paper wing): {ms} ms");
    assert_eq!(f64s(&js, "modes.1.max_modulus").len(), 200);
    assert!(ms < 30_000.0);
}
