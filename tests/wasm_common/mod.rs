//! Checks shared by the wasm-bindgen-test suites: `wasm_api.rs` runs them in node,
//! `wasm_browser.rs` in headless Chromium. Each check calls the wasm API (`wingbeat::wasm`)
//! and the core directly — the core is compiled into the same wasm module — and compares.
#![allow(dead_code)]

use js_sys::{Float64Array, Reflect};
use std::cell::RefCell;
use std::rc::Rc;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use wingbeat::analysis::beat::envelope;
use wingbeat::analysis::ic_map::{ic_map, IcMapOptions};
use wingbeat::analysis::psd::{welch, WelchOptions};
use wingbeat::analysis::sweep::{sweep, SweepOptions, SweepParam};
use wingbeat::config::SimConfig;
use wingbeat::simulate::{force_series, simulate};
use wingbeat::wasm;

#[path = "../ts_common/mod.rs"]
mod ts_common;

/// Native reference numbers of the paper case (provenance: tests/lab_constants.rs, which
/// asserts the same values natively on x86_64 and prints them).
pub const PAPER_REFERENCE: [(&str, f64); 8] = [
    ("mode1.effective_freq_hz", 6.030639396854428e1),
    ("mode2.effective_freq_hz", 8.534646215176787e1),
    ("mode1.beat_period_vs_2fd_s", 9.70271467452204e-2),
    ("mode1.contribution.euler", 1.7770071621035974e1),
    ("mode1.contribution.centrifugal", 3.1608272606377934e0),
    ("mode1.contribution.coriolis", 5.379178730437413e1),
    ("mode2.contribution.coriolis", 2.463981694964878e1),
    ("mode1.q_total[12345]", -6.941943076968708e-7),
];

pub const TOL: f64 = 1e-12;

pub fn get(o: &JsValue, path: &str) -> JsValue {
    let mut v = o.clone();
    for key in path.split('.') {
        v = match key.parse::<u32>() {
            Ok(i) => Reflect::get_u32(&v, i),
            Err(_) => Reflect::get(&v, &JsValue::from_str(key)),
        }
        .unwrap_or_else(|_| panic!("no `{key}` in `{path}`"));
    }
    v
}

pub fn num(o: &JsValue, path: &str) -> f64 {
    get(o, path)
        .as_f64()
        .unwrap_or_else(|| panic!("`{path}` is not a number"))
}

/// A Float64Array field as a Vec (panics if the field is not a Float64Array).
pub fn f64s(o: &JsValue, path: &str) -> Vec<f64> {
    get(o, path)
        .dyn_into::<Float64Array>()
        .unwrap_or_else(|_| panic!("`{path}` is not a Float64Array"))
        .to_vec()
}

pub fn close(name: &str, got: f64, want: f64, tol: f64) {
    let scale = got.abs().max(want.abs()).max(1e-300);
    assert!(
        (got - want).abs() <= tol * scale || (got.is_nan() && want.is_nan()),
        "{name}: wasm API {got:e} vs {want:e}"
    );
}

pub fn close_all(name: &str, got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len(), "{name}: length");
    let scale = want.iter().fold(0.0f64, |m, v| m.max(v.abs())).max(1e-300);
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(
            (g - w).abs() <= tol * scale,
            "{name}[{i}]: wasm API {g:e} vs core {w:e}"
        );
    }
}

/// A series as the JS side passes it (a `Float64Array`).
pub fn fa(x: &[f64]) -> JsValue {
    Float64Array::from(x).into()
}

pub fn to_js<T: serde::Serialize>(v: &T) -> JsValue {
    v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .unwrap()
}

/// The error message of a failed wasm API call.
pub fn message<T: std::fmt::Debug>(r: Result<T, JsError>) -> String {
    let e = r.expect_err("expected an error");
    let v: JsValue = e.into();
    v.dyn_into::<js_sys::Error>()
        .map(|e| String::from(e.message()))
        .unwrap_or_default()
}

fn short_paper() -> SimConfig {
    SimConfig {
        duration_s: 0.4,
        ..SimConfig::paper()
    }
}

pub fn simulate_matches_core() {
    let cfg = SimConfig::paper();
    let js = wasm::simulate(to_js(&cfg)).unwrap();
    let core = simulate(&cfg).unwrap();
    close_all("t", &f64s(&js, "t"), &core.t, TOL);
    assert_eq!(num(&js, "n") as usize, core.t.len());
    for (k, m) in core.modes.iter().enumerate() {
        let p = |s: &str| format!("modes.{k}.{s}");
        for (name, want) in [
            ("q.euler", &m.q.euler),
            ("q.centrifugal", &m.q.centrifugal),
            ("q.coriolis", &m.q.coriolis),
            ("q.free", &m.q.free),
            ("q.total", &m.q.total),
            ("qdot_total", &m.qdot_total),
        ] {
            close_all(&p(name), &f64s(&js, &p(name)), want, TOL);
        }
        let c = &m.contribution_percent;
        close(
            "euler",
            num(&js, &p("contribution_percent.euler")),
            c.euler,
            TOL,
        );
        close(
            "coriolis",
            num(&js, &p("contribution_percent.coriolis")),
            c.coriolis,
            TOL,
        );
        let f = &m.floquet;
        close(
            "f_eff",
            num(&js, &p("floquet.effective_freq_hz")),
            f.effective_freq_hz,
            TOL,
        );
        close(
            "max_modulus",
            num(&js, &p("floquet.max_modulus")),
            f.max_modulus,
            TOL,
        );
        close(
            "multiplier im",
            num(&js, &p("floquet.multipliers.0.1")),
            f.multipliers[0][1],
            TOL,
        );
        assert_eq!(
            get(&js, &p("floquet.stable")).as_bool(),
            Some(f.stable),
            "stable"
        );
        assert_eq!(
            get(&js, &p("name")).as_string().as_deref(),
            Some(m.name.as_str())
        );
    }
    let s = core.strain.as_ref().unwrap();
    close_all("strain.eps_y", &f64s(&js, "strain.eps_y"), &s.eps_y, TOL);
    close_all(
        "strain.gamma_xy",
        &f64s(&js, "strain.gamma_xy"),
        &s.gamma_xy,
        TOL,
    );
}

pub fn paper_reference_numbers() {
    let js = wasm::simulate(to_js(&SimConfig::paper())).unwrap();
    for (name, want) in PAPER_REFERENCE {
        let got = match name {
            "mode1.effective_freq_hz" => num(&js, "modes.0.floquet.effective_freq_hz"),
            "mode2.effective_freq_hz" => num(&js, "modes.1.floquet.effective_freq_hz"),
            "mode1.beat_period_vs_2fd_s" => num(&js, "modes.0.floquet.beat_period_vs_2fd_s"),
            "mode1.contribution.euler" => num(&js, "modes.0.contribution_percent.euler"),
            "mode1.contribution.centrifugal" => {
                num(&js, "modes.0.contribution_percent.centrifugal")
            }
            "mode1.contribution.coriolis" => num(&js, "modes.0.contribution_percent.coriolis"),
            "mode2.contribution.coriolis" => num(&js, "modes.1.contribution_percent.coriolis"),
            "mode1.q_total[12345]" => f64s(&js, "modes.0.q.total")[12345],
            other => panic!("unknown reference {other}"),
        };
        close(name, got, want, TOL);
    }
    // The headline number, to the digits quoted in docs/lab.md.
    let f = num(&js, "modes.0.floquet.effective_freq_hz");
    assert!((f - 60.3064).abs() < 5e-5, "{f}");
}

pub fn analyze_matches_core() {
    let cfg = short_paper();
    let opts = WelchOptions {
        segment_len: 1024,
        ..WelchOptions::default()
    };
    let js = wasm::analyze(to_js(&cfg), to_js(&opts), JsValue::from(1.0)).unwrap();
    assert!(get(&js, "spectra.0").is_null(), "mode 1 not asked for");
    assert!(get(&js, "forces.0").is_null());
    assert!(get(&js, "envelope.0").is_null());
    let sim = simulate(&cfg).unwrap();
    let fs = force_series(&cfg).unwrap();
    let k = 1;
    let f = &fs[k];
    let q = &sim.modes[k].q.total;
    let stiff: Vec<f64> = f
        .stiffness_coefficient
        .iter()
        .zip(q)
        .map(|(s, q)| s * q)
        .collect();
    let fsr = cfg.sample_rate_hz;
    for (name, x) in [
        ("euler", &f.euler),
        ("centrifugal", &f.centrifugal),
        ("coriolis", &f.coriolis),
        ("stiffness_force", &stiff),
        ("total", q),
    ] {
        let want = welch(x, fsr, &opts, Some(cfg.kinematics.flap_freq_hz)).unwrap();
        let p = format!("spectra.1.{name}");
        close_all(
            &format!("{p}.freq_hz"),
            &f64s(&js, &format!("{p}.freq_hz")),
            &want.freq_hz,
            TOL,
        );
        close_all(
            &format!("{p}.psd"),
            &f64s(&js, &format!("{p}.psd")),
            &want.psd,
            TOL,
        );
        close(
            "first peak",
            num(&js, &format!("{p}.peaks.0.freq_hz")),
            want.peaks[0].freq_hz,
            TOL,
        );
        if name != "stiffness_force" && name != "total" {
            close_all(
                &format!("forces.1.{name}"),
                &f64s(&js, &format!("forces.1.{name}")),
                x,
                TOL,
            );
        }
    }
    close_all(
        "forces.1.stiffness_force",
        &f64s(&js, "forces.1.stiffness_force"),
        &stiff,
        TOL,
    );
    // Envelope over the 5-smooth prefix (4000 of 4001 samples), last value held.
    let cor = &sim.modes[k].q.coriolis;
    let mut env = envelope(&cor[..4000]);
    env.push(env[3999]);
    close_all("envelope.1", &f64s(&js, "envelope.1"), &env, TOL);
    // The separate entry points agree too.
    let js_f = wasm::force_series(to_js(&cfg)).unwrap();
    close_all(
        "forceSeries.0.stiffness_coefficient",
        &f64s(&js_f, "0.stiffness_coefficient"),
        &fs[0].stiffness_coefficient,
        TOL,
    );
    let js_s = wasm::spectra(to_js(&cfg), to_js(&opts), JsValue::UNDEFINED).unwrap();
    let want = welch(&fs[0].coriolis, fsr, &opts, Some(25.0)).unwrap();
    close_all(
        "spectra.0.coriolis",
        &f64s(&js_s, "0.coriolis.psd"),
        &want.psd,
        TOL,
    );
    let full = wasm::envelope(fa(cor)).unwrap().to_vec();
    close_all("envelope()", &full, &envelope(cor), TOL);
}

pub fn coriolis_force_peaks_at_twice_the_flap_frequency() {
    let cfg = short_paper();
    let opts = WelchOptions {
        segment_len: 4000,
        ..WelchOptions::default()
    };
    let js = wasm::spectra(to_js(&cfg), to_js(&opts), JsValue::from(0.0)).unwrap();
    let f = f64s(&js, "0.coriolis.freq_hz");
    let p = f64s(&js, "0.coriolis.psd");
    // Largest non-DC bin (the Coriolis force also has a large mean: bin 0).
    let i = (2..p.len()).max_by(|&a, &b| p[a].total_cmp(&p[b])).unwrap();
    assert!((f[i] - 50.0).abs() < 2.6, "Coriolis peak at {} Hz", f[i]);
    assert!(p[0] > 0.1 * p[i], "DC part visible with detrend none");
    // γ0 = 0: no Coriolis force at all.
    let c0 = wingbeat::analysis::sweep::apply(&cfg, SweepParam::Gamma0, 0.0).unwrap();
    let js0 = wasm::spectra(to_js(&c0), to_js(&opts), JsValue::from(0.0)).unwrap();
    assert!(f64s(&js0, "0.coriolis.psd").iter().all(|v| *v == 0.0));
}

pub fn psd_matches_core() {
    let x: Vec<f64> = (0..3000).map(|i| (i as f64 * 0.05).sin() + 0.3).collect();
    let opts = WelchOptions {
        segment_len: 512,
        ..WelchOptions::default()
    };
    let js = wasm::psd(
        fa(&x),
        JsValue::from(1000.0),
        to_js(&opts),
        JsValue::from(8.0),
    )
    .unwrap();
    let want = welch(&x, 1000.0, &opts, Some(8.0)).unwrap();
    close_all("psd", &f64s(&js, "psd"), &want.psd, TOL);
    close(
        "peak multiple",
        num(&js, "peaks.0.flap_multiple"),
        want.peaks[0].flap_multiple.unwrap(),
        TOL,
    );
}

pub fn sweep_matches_core_and_reports_progress() {
    let cfg = short_paper();
    let opts = SweepOptions {
        param: SweepParam::Gamma0,
        from: 0.0,
        to: 0.3,
        points: 4,
    };
    let calls = Rc::new(RefCell::new(Vec::new()));
    let c2 = calls.clone();
    let cb =
        Closure::wrap(Box::new(move |i: f64, n: f64| c2.borrow_mut().push((i, n)))
            as Box<dyn FnMut(f64, f64)>);
    let f: js_sys::Function = cb.as_ref().clone().unchecked_into();
    let js = wasm::sweep(to_js(&cfg), to_js(&opts), f.into()).unwrap();
    assert_eq!(
        *calls.borrow(),
        vec![(1.0, 4.0), (2.0, 4.0), (3.0, 4.0), (4.0, 4.0)]
    );
    let core = sweep(&cfg, &opts, |_, _| {}).unwrap();
    let vals: Vec<f64> = core.points.iter().map(|p| p.value).collect();
    close_all("values", &f64s(&js, "values"), &vals, TOL);
    for k in 0..2 {
        let cor: Vec<f64> = core
            .points
            .iter()
            .map(|p| p.modes[k].contribution_percent.coriolis)
            .collect();
        close_all(
            "coriolis",
            &f64s(&js, &format!("modes.{k}.coriolis")),
            &cor,
            TOL,
        );
        let fe: Vec<f64> = core
            .points
            .iter()
            .map(|p| p.modes[k].effective_freq_hz)
            .collect();
        close_all(
            "effective_freq_hz",
            &f64s(&js, &format!("modes.{k}.effective_freq_hz")),
            &fe,
            TOL,
        );
    }
    assert_eq!(get(&js, "param").as_string().as_deref(), Some("gamma0"));
    // γ0 = 0: no Coriolis share.
    assert_eq!(f64s(&js, "modes.0.coriolis")[0], 0.0);
    // A throwing progress callback is ignored.
    let thrower = js_sys::Function::new_with_args("i, n", "throw new Error('boom')");
    assert!(wasm::sweep(to_js(&cfg), to_js(&opts), thrower.into()).is_ok());
}

pub fn ic_map_matches_core() {
    let cfg = SimConfig::paper();
    let opts = IcMapOptions::default();
    let js = wasm::ic_map(to_js(&cfg), to_js(&opts)).unwrap();
    let core = ic_map(&cfg, &opts).unwrap();
    assert_eq!(num(&js, "n_q"), 101.0);
    assert_eq!(num(&js, "n_qdot"), 101.0);
    close_all(
        "coriolis_percent",
        &f64s(&js, "coriolis_percent"),
        &core.coriolis_percent,
        TOL,
    );
    close_all("q0", &f64s(&js, "q0"), &core.q0, TOL);
    close(
        "fraction_above_60",
        num(&js, "fraction_above_60"),
        core.fraction_above_60,
        TOL,
    );
}

pub fn defaults_limits_reproduce() {
    let js = wasm::default_config().unwrap();
    let back: SimConfig = serde_wasm_bindgen::from_value(js).unwrap();
    assert_eq!(back, SimConfig::default());
    let l = wasm::limits().unwrap();
    assert_eq!(num(&l, "web_max_sample_values"), 2_000_000.0);
    assert!(wasm::validate_config(JsValue::UNDEFINED).is_ok());
}

pub fn reproduce_matches_core() {
    let js = wasm::reproduce().unwrap();
    let core = wingbeat::reproduce::reproduce().unwrap();
    assert_eq!(num(&js, "summary.holds") as usize, core.summary.holds);
    assert_eq!(num(&js, "summary.fails") as usize, core.summary.fails);
    assert_eq!(wasm::reproduce_text().unwrap(), core.to_text());
}

pub fn bad_input_names_the_field() {
    let bad = |json: &str| -> JsValue { js_sys::JSON::parse(json).unwrap() };
    let cases: [(&str, &str); 9] = [
        (r#"{"duration_s": -1}"#, "`duration_s`"),
        (r#"{"duration_s": 1000}"#, "duration_s × sample_rate_hz"),
        (r#"{"bogus": 1}"#, "bogus"),
        (
            r#"{"kinematics": {"flap_freq_hz": "x"}}"#,
            "config.kinematics",
        ),
        (
            r#"{"modes": [{"freq_hz": -5, "a": [1, 0]}]}"#,
            "`modes[0].freq_hz`",
        ),
        (
            r#"{"modes": [{"freq_hz": 5, "a": [1, 0, 3]}]}"#,
            "config.modes[0].a",
        ),
        (
            r#"{"kinematics": {"flap_freq_hz": 25, "alpha": {"kind": "fourier", "harmonics": [{"n": 1, "amplitude": 99}]}, "beta": {"kind": "fourier"}, "gamma": {"kind": "fourier"}}}"#,
            "kinematics.alpha.harmonics[0].amplitude",
        ),
        (
            r#"{"initial_conditions": [[0, 0], [0, 0], [0, 0]]}"#,
            "initial_conditions",
        ),
        (r#"{"sample_rate_hz": null}"#, "sample_rate_hz"),
    ];
    for (json, field) in cases {
        let m = message(wasm::simulate(bad(json)));
        assert!(m.contains(field), "{json}: message `{m}` lacks {field}");
    }
    // NaN and Infinity from JS (JSON cannot carry them).
    let o = js_sys::Object::new();
    Reflect::set(&o, &"duration_s".into(), &JsValue::from_f64(f64::NAN)).unwrap();
    let m = message(wasm::simulate(o.into()));
    assert!(m.contains("duration_s"), "{m}");
    let o = js_sys::Object::new();
    Reflect::set(
        &o,
        &"sample_rate_hz".into(),
        &JsValue::from_f64(f64::INFINITY),
    )
    .unwrap();
    let m = message(wasm::simulate(o.into()));
    assert!(m.contains("sample_rate_hz"), "{m}");
    // A cyclic object cannot be serialised: an error, not a panic.
    let o = js_sys::Object::new();
    Reflect::set(&o, &"me".into(), &o).unwrap();
    assert!(message(wasm::simulate(o.into())).contains("config"));
    // Options of the other entry points.
    let cfg = to_js(&short_paper());
    let m = message(wasm::sweep(
        cfg.clone(),
        bad(r#"{"param": "gamma1", "from": 0, "to": 1, "points": 3}"#),
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("sweep.param"), "{m}");
    let m = message(wasm::sweep(
        cfg.clone(),
        bad(r#"{"param": "gamma0", "from": 0, "to": 1, "points": 1}"#),
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("sweep.points"), "{m}");
    let m = message(wasm::sweep(
        cfg.clone(),
        JsValue::UNDEFINED,
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("sweep"), "{m}");
    let m = message(wasm::ic_map(cfg.clone(), bad(r#"{"mode": 7}"#)));
    assert!(m.contains("ic_map.mode"), "{m}");
    let m = message(wasm::ic_map(cfg.clone(), bad(r#"{"n_q": 1.5}"#)));
    assert!(m.contains("ic_map.n_q"), "{m}");
    let m = message(wasm::analyze(
        cfg.clone(),
        JsValue::UNDEFINED,
        JsValue::from(9.0),
    ));
    assert!(m.contains("mode"), "{m}");
    let m = message(wasm::analyze(
        cfg.clone(),
        bad(r#"{"segment_len": 3}"#),
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("psd.segment_len"), "{m}");
    let m = message(wasm::analyze(
        cfg,
        bad(r#"{"detrend": "cubic"}"#),
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("psd.detrend"), "{m}");
    let m = message(wasm::psd(
        fa(&[1.0, 2.0, f64::NAN, 3.0]),
        JsValue::from(100.0),
        JsValue::UNDEFINED,
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("psd.series[2]"), "{m}");
    let m = message(wasm::psd(
        fa(&[1.0; 64]),
        JsValue::from(f64::NAN),
        JsValue::UNDEFINED,
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("psd.sample_rate_hz"), "{m}");
    let m = message(wasm::envelope(fa(&[])));
    assert!(m.contains("envelope.series"), "{m}");
}

/// `feModes` against the core's `compute_modes` on a coarse mesh: frequencies, a_k, mass,
/// the flat mesh arrays and the Eq. 13 modes with strain at P, all to 1e-12.
pub fn fe_modes_match_core() {
    use wingbeat::fem::{compute_modes, FemInput, STRAIN_POINT_P_MM};
    let input = FemInput {
        n_modes: 3,
        mesh_size_mm: Some(2.5),
        ..Default::default()
    };
    let core = compute_modes(&input).unwrap();
    let js = wasm::fe_modes(
        js_sys::JSON::parse(r#"{"n_modes": 3, "mesh_size_mm": 2.5}"#).unwrap(),
        JsValue::from(0.01),
        JsValue::UNDEFINED,
    )
    .unwrap();
    close_all("freq_hz", &f64s(&js, "freq_hz"), &core.freq_hz, TOL);
    close_all("residuals", &f64s(&js, "residuals"), &core.residuals, TOL);
    for k in 0..3 {
        close(
            &format!("a[{k}].x"),
            num(&js, &format!("a.{k}.0")),
            core.a[k][0],
            TOL,
        );
        close(
            &format!("a[{k}].y"),
            num(&js, &format!("a.{k}.1")),
            core.a[k][1],
            TOL,
        );
        close(
            &format!("modes[{k}].a.x"),
            num(&js, &format!("modes.{k}.a.0")),
            core.a[k][0],
            TOL,
        );
        close(
            &format!("modes[{k}].zeta"),
            num(&js, &format!("modes.{k}.zeta")),
            0.01,
            TOL,
        );
    }
    close("mass_kg", num(&js, "mass_kg"), core.mass_kg, TOL);
    assert_eq!(num(&js, "n_nodes") as usize, core.nodes.len());
    assert_eq!(num(&js, "n_triangles") as usize, core.triangles.len());
    let nodes: Vec<f64> = core.nodes.iter().flatten().copied().collect();
    close_all("nodes", &f64s(&js, "nodes"), &nodes, TOL);
    let tris = get(&js, "triangles")
        .dyn_into::<js_sys::Uint32Array>()
        .expect("triangles is a Uint32Array")
        .to_vec();
    let want: Vec<u32> = core.triangles.iter().flatten().map(|&i| i as u32).collect();
    assert_eq!(tris, want);
    let shapes: Vec<f64> = core.shapes.iter().flatten().copied().collect();
    close_all("shapes", &f64s(&js, "shapes"), &shapes, TOL);
    let strains: Vec<f64> = core
        .strain_nodes
        .iter()
        .flatten()
        .flatten()
        .copied()
        .collect();
    close_all("strain_nodes", &f64s(&js, "strain_nodes"), &strains, TOL);
    // The modal strain at P equals the core's interpolation there.
    let (px, py) = STRAIN_POINT_P_MM;
    let e = core.strain_at(0, px, py).unwrap();
    close(
        "modes[0].strains[0].gamma_xy",
        num(&js, "modes.0.strains.0.gamma_xy"),
        e[2],
        TOL,
    );
    assert_eq!(
        get(&js, "modes.0.strains.0.point").as_string().unwrap(),
        "P"
    );
    // Bad input names the field.
    let bad = |json: &str| js_sys::JSON::parse(json).unwrap();
    for (json, field) in [
        (r#"{"camber": 2}"#, "camber"),
        (r#"{"mesh_size_mm": 0.01}"#, "node"),
        (r#"{"n_modes": 0}"#, "n_modes"),
        (r#"{"planform_mm": [[0, 0], [1, 1]]}"#, "planform"),
        (
            r#"{"material": {"thickness_m": 8e-5, "e_pa": -1, "rho_kg_m3": 860, "nu": 0.3}}"#,
            "e_pa",
        ),
        (r#"{"bogus": 1}"#, "bogus"),
    ] {
        let m = message(wasm::fe_modes(
            bad(json),
            JsValue::UNDEFINED,
            JsValue::UNDEFINED,
        ));
        assert!(m.contains(field), "{json}: message `{m}` lacks {field}");
    }
    let m = message(wasm::fe_modes(
        JsValue::UNDEFINED,
        JsValue::from(f64::NAN),
        JsValue::UNDEFINED,
    ));
    assert!(m.contains("zeta"), "{m}");
}

/// `anglesAt` against the core's compiled kinematics (paper §2.1), and its input checks.
pub fn angles_match_core() {
    let cfg = short_paper();
    let kin = cfg.kinematics.compile();
    let times = [0.0, 0.0013, 0.01, 0.037, 0.4];
    let got = wasm::angles_at(to_js(&cfg), fa(&times)).unwrap().to_vec();
    assert_eq!(got.len(), 15);
    for (i, &t) in times.iter().enumerate() {
        let s = kin.state(t);
        close(&format!("alpha({t})"), got[3 * i], s.alpha, TOL);
        close(&format!("beta({t})"), got[3 * i + 1], s.beta, TOL);
        close(&format!("gamma({t})"), got[3 * i + 2], s.gamma, TOL);
    }
    // A quarter period (0.01 s at 25 Hz) puts every sinusoid at its amplitude.
    close("alpha(T/4)", got[6], 0.8, 1e-12);
    close("gamma(T/4)", got[8], 0.2, 1e-12);
    let m = message(wasm::angles_at(to_js(&cfg), fa(&[0.0, f64::NAN])));
    assert!(m.contains("anglesAt.times[1]"), "{m}");
}

/// The stiffness-force spectra of the paper case (0.4 s, 1024-sample segments), natively
/// computed and hard-coded in tests/stiffness_spectra.rs, where the CLI's `psd` is checked
/// against the same numbers: one quantity in both front ends.
pub const STIFFNESS_FORCE_REFERENCE: [(usize, usize, f64); 6] = [
    (0, 0, 4.408644852178396e-6),
    (0, 5, 6.626491355668749e-6),
    (0, 10, 1.1366600536284352e-6),
    (1, 0, 1.2682627419937116e-8),
    (1, 5, 1.63832584735356e-8),
    (1, 10, 5.1592553304086635e-9),
];

pub fn stiffness_spectra_match_reference() {
    let cfg = short_paper();
    let opts = WelchOptions {
        segment_len: 1024,
        ..WelchOptions::default()
    };
    let js = wasm::spectra(to_js(&cfg), to_js(&opts), JsValue::UNDEFINED).unwrap();
    for (mode, bin, want) in STIFFNESS_FORCE_REFERENCE {
        let got = f64s(&js, &format!("{mode}.stiffness_force.psd"))[bin];
        close(
            &format!("spectra.{mode}.stiffness_force.psd[{bin}]"),
            got,
            want,
            TOL,
        );
    }
    assert!(
        get(&js, "0.stiffness").is_undefined(),
        "the old key is gone"
    );
}

fn js_keys(o: &JsValue) -> Vec<String> {
    js_sys::Object::keys(o.unchecked_ref::<js_sys::Object>())
        .iter()
        .map(|k| k.as_string().unwrap())
        .collect()
}

/// The TypeScript declarations (src/wasm/types.rs) against the objects the API really
/// returns: every key present is declared, every required key is present.
pub fn ts_declarations_match_results() {
    let i = ts_common::interfaces(ts_common::declarations());
    let cfg = short_paper();
    let check = |name: &str, o: &JsValue| ts_common::check(&i, name, &js_keys(o));
    let sim = wasm::simulate(to_js(&cfg)).unwrap();
    check("SimResult", &sim);
    check("ModeResult", &get(&sim, "modes.0"));
    check("Responses", &get(&sim, "modes.0.q"));
    check("StrainSeries", &get(&sim, "strain"));
    let opts = WelchOptions {
        segment_len: 512,
        ..WelchOptions::default()
    };
    let a = wasm::analyze(to_js(&cfg), to_js(&opts), JsValue::UNDEFINED).unwrap();
    check("Analysis", &a);
    check("AngleSeries", &get(&a, "angles"));
    check("ModeForces", &get(&a, "forces.0"));
    check("ModeSpectra", &get(&a, "spectra.0"));
    check("Spectrum", &get(&a, "spectra.0.coriolis"));
    check("Peak", &get(&a, "spectra.0.coriolis.peaks.0"));
    let f = wasm::force_series(to_js(&cfg)).unwrap();
    check("ForceSeries", &get(&f, "0"));
    let sweep = wasm::sweep(
        to_js(&cfg),
        to_js(&SweepOptions {
            param: SweepParam::Gamma0,
            from: 0.0,
            to: 0.3,
            points: 2,
        }),
        JsValue::UNDEFINED,
    )
    .unwrap();
    check("SweepResult", &sweep);
    check("SweepModeColumns", &get(&sweep, "modes.0"));
    let ic = wasm::ic_map(
        to_js(&cfg),
        to_js(&IcMapOptions {
            n_q: 3,
            n_qdot: 3,
            ..IcMapOptions::default()
        }),
    )
    .unwrap();
    check("IcMapResult", &ic);
    check("Limits", &wasm::limits().unwrap());
    let fe = wasm::fe_modes(
        js_sys::JSON::parse(r#"{"n_modes": 2, "mesh_size_mm": 3}"#).unwrap(),
        JsValue::UNDEFINED,
        JsValue::UNDEFINED,
    )
    .unwrap();
    check("FeModesResult", &fe);
    check("Mode", &get(&fe, "modes.0"));
    check("Param", &get(&wasm::parameters().unwrap(), "0"));
    let rm = wasm::resonance_map(
        to_js(&cfg),
        js_sys::JSON::parse(
            r#"{"from_hz": 20, "to_hz": 30, "points": 3, "alpha0_values": [0.5, 0.8]}"#,
        )
        .unwrap(),
        JsValue::UNDEFINED,
    )
    .unwrap();
    check("ResonanceMapResult", &rm);
    check("ResonanceModeColumns", &get(&rm, "modes.0"));
}

/// The FE wing in air through the wasm API: `cfg.wing` (typed arrays in `feModes`' layout)
/// carries the mesh and shapes, and `simulate` and `analyze` return what the core computes
/// for the same config and wing — the aerodynamic response, share, force and spectrum, and the
/// `air` blocks. Air without a wing, and a malformed wing, are refused by name; a wing given
/// in a vacuum changes nothing.
pub fn air_run_matches_core() {
    let base = SimConfig::fe_wing().unwrap();
    let cfg = SimConfig {
        duration_s: 0.12,
        sample_rate_hz: 4000.0,
        aero: wingbeat::aero::AeroConfig::with_density(1.2),
        ..base
    };
    let geom = cfg.wing.clone().unwrap();
    let n = geom.nodes.len();
    let nodes: Vec<f64> = geom.nodes.iter().flat_map(|p| [p[0], p[1], 0.0]).collect();
    let tris: Vec<u32> = geom.triangles.iter().flatten().map(|&i| i as u32).collect();
    let shapes: Vec<f64> = geom.shapes.iter().flatten().copied().collect();
    let put = |o: &js_sys::Object, k: &str, v: &JsValue| {
        Reflect::set(o, &JsValue::from_str(k), v).unwrap();
    };
    let wing_of = |nodes: &[f64], tris: &[u32], shapes: &[f64]| -> JsValue {
        let o = js_sys::Object::new();
        put(&o, "nodes", &fa(nodes));
        put(&o, "triangles", &js_sys::Uint32Array::from(tris).into());
        put(&o, "shapes", &fa(shapes));
        o.into()
    };
    let wing = wing_of(&nodes, &tris, &shapes);
    let with_wing = |c: &SimConfig, w: &JsValue| {
        let o = to_js(c);
        Reflect::set(&o, &JsValue::from_str("wing"), w).unwrap();
        o
    };
    let js = wasm::simulate(with_wing(&cfg, &wing)).unwrap();
    let core = simulate(&cfg).unwrap();
    for (k, m) in core.modes.iter().enumerate() {
        let p = |s: &str| format!("modes.{k}.{s}");
        close_all(&p("q.total"), &f64s(&js, &p("q.total")), &m.q.total, TOL);
        close_all(
            &p("q.aerodynamic"),
            &f64s(&js, &p("q.aerodynamic")),
            &m.q.aerodynamic,
            TOL,
        );
        let air = m.air.as_ref().unwrap();
        close(
            &p("air.decay_rate_per_s"),
            num(&js, &p("air.decay_rate_per_s")),
            air.decay_rate_per_s,
            TOL,
        );
        close(
            &p("air.still_air_freq_hz"),
            num(&js, &p("air.still_air_freq_hz")),
            air.still_air_freq_hz,
            TOL,
        );
        close(
            &p("contribution_percent.aerodynamic"),
            num(&js, &p("contribution_percent.aerodynamic")),
            m.contribution_percent.aerodynamic.unwrap(),
            TOL,
        );
    }
    assert_eq!(
        num(&js, "air.points") as usize,
        core.air.as_ref().unwrap().points
    );
    // The live analysis: the aerodynamic force and its spectrum of the selected mode.
    let opts = WelchOptions {
        segment_len: 256,
        ..WelchOptions::default()
    };
    let a = wasm::analyze(with_wing(&cfg, &wing), to_js(&opts), JsValue::from(0.0)).unwrap();
    let f = force_series(&cfg).unwrap();
    assert!(f[0].aerodynamic.iter().any(|v| *v != 0.0));
    close_all(
        "forces.0.aerodynamic",
        &f64s(&a, "forces.0.aerodynamic"),
        &f[0].aerodynamic,
        TOL,
    );
    let want = welch(&f[0].aerodynamic, cfg.sample_rate_hz, &opts, Some(25.0)).unwrap();
    close_all(
        "spectra.0.aerodynamic.psd",
        &f64s(&a, "spectra.0.aerodynamic.psd"),
        &want.psd,
        TOL,
    );
    // A vacuum ignores the wing: the same numbers as without it, no aerodynamic keys.
    let vac = SimConfig {
        aero: Default::default(),
        ..cfg.clone()
    };
    let v1 = wasm::simulate(with_wing(&vac, &wing)).unwrap();
    let v0 = wasm::simulate(to_js(&vac)).unwrap();
    assert_eq!(f64s(&v1, "modes.0.q.total"), f64s(&v0, "modes.0.q.total"));
    assert!(get(&v1, "modes.0.q.aerodynamic").is_undefined());
    assert!(get(&v1, "air").is_undefined());
    // Refusals, by name.
    let m = message(wasm::simulate(to_js(&cfg)));
    assert!(m.contains("aero.air_density_kg_m3"), "{m}");
    let m = message(wasm::simulate(with_wing(&cfg, &JsValue::from(5.0))));
    assert!(m.contains("config.wing"), "{m}");
    let refused = |w: JsValue| message(wasm::simulate(with_wing(&cfg, &w)));
    let m = refused(wing_of(&nodes, &tris, &shapes[..shapes.len() - n]));
    assert!(m.contains("config.wing.shapes"), "{m}");
    let m = refused(wing_of(&nodes[..nodes.len() - 1], &tris, &shapes));
    assert!(m.contains("config.wing.nodes"), "{m}");
    let mut t2 = tris.clone();
    t2[0] = n as u32 + 7;
    let m = refused(wing_of(&nodes, &t2, &shapes));
    assert!(m.contains("wing.triangles[0]"), "{m}");
    let mut nan_nodes = nodes;
    nan_nodes[4] = f64::NAN;
    let m = refused(wing_of(&nan_nodes, &tris, &shapes));
    assert!(m.contains("wing.nodes[1]"), "{m}");
}

/// `classifyRotation` on a thin, short case against the core's pipeline for the same request:
/// the same accuracies and normalisation, progress to 6 of 6; bad requests named.
pub fn classify_rotation_matches_core() {
    use wingbeat::analysis::rotation_classify::{
        classify, fe_case, mohren2018_classes, mohren2018_grid_every, ClassifyOptions,
    };
    let request = r#"{"n_modes": 3, "mesh_size_mm": 2.5, "grid_step_mm": 5, "seed": 3,
        "options": {"duration_s": 1.6, "discard_s": 0.5, "kept_modes": [2], "random_counts": [2],
        "random_draws": 3}}"#;
    let calls = Rc::new(RefCell::new(Vec::<(f64, f64)>::new()));
    let sink = calls.clone();
    let progress = Closure::<dyn FnMut(f64, f64)>::new(move |d, t| sink.borrow_mut().push((d, t)));
    let js = wasm::classify_rotation(
        js_sys::JSON::parse(request).unwrap(),
        progress.as_ref().clone(),
    )
    .unwrap();
    assert_eq!(calls.borrow().last(), Some(&(6.0, 6.0)));
    let fe = wingbeat::fem::compute_modes(&wingbeat::presets::mohren2018_plate_input(Some(2.5), 3))
        .unwrap();
    let case = fe_case(
        &fe,
        mohren2018_classes(10.0, 0.312, 0.1, 3),
        &mohren2018_grid_every(5),
    )
    .unwrap();
    let opts = ClassifyOptions {
        duration_s: 1.6,
        discard_s: 0.5,
        kept_modes: vec![2],
        random_counts: vec![2],
        random_draws: 3,
        ..ClassifyOptions::default()
    };
    let core = classify(&case, &opts).unwrap();
    assert_eq!(num(&js, "report.test_samples") as usize, core.test_samples);
    assert_eq!(
        get(&js, "report.sensors")
            .dyn_into::<js_sys::Array>()
            .unwrap()
            .length() as usize,
        11 * 6
    );
    let one = 1.0 / (2 * core.test_samples) as f64;
    for (name, c) in [("encoded", &core.encoded), ("raw", &core.raw)] {
        let got = num(&js, &format!("report.{name}.all_sensors"));
        assert!(
            (got - c.all_sensors).abs() <= one + 1e-12,
            "{name}: {got} vs {}",
            c.all_sensors
        );
        close(
            &format!("{name}.s0"),
            num(&js, &format!("report.{name}.s0")),
            c.s0,
            1e-9,
        );
    }
    close(
        "modes.0.freq_hz",
        num(&js, "modes.0.freq_hz"),
        fe.freq_hz[0],
        1e-9,
    );
    for (req, field) in [
        (r#"{"grid_step_mm": 0}"#, "request.grid_step_mm"),
        (r#"{"grid_step_mm": 1}"#, "request.grid_step_mm"),
        (r#"{"rotation_rad_s": 1e9}"#, "request.rotation_rad_s"),
        (
            r#"{"options": {"train_fraction": 2}}"#,
            "options.train_fraction",
        ),
        (r#"{"colour": 1}"#, "colour"),
    ] {
        let m = message(wasm::classify_rotation(
            js_sys::JSON::parse(req).unwrap(),
            JsValue::UNDEFINED,
        ));
        assert!(m.contains(field), "{req}: {m}");
    }
}
