//! Property tests over every reader of outside input — the config JSON,
//! the modes document, the kinematics CSV, the planform readers, the FE input and the wasm
//! entry points' Rust-side checks (`wasm::helpers`, compiled natively with `--features web`).
//! For any input: no panic, and either `Ok` with finite outputs or `Err` with a message that
//! names a field (or, for text that is not JSON at all, says where parsing stopped).
//! Case counts are small so the whole file takes a few seconds in a debug build; the long
//! runs are the `cargo fuzz` targets in fuzz/ (docs/fuzzing.md).
// proptest is a native-only dev-dependency.
#![cfg(not(target_arch = "wasm32"))]

use proptest::prelude::*;
use wingbeat::config::SimConfig;
use wingbeat::error::parse_json;
use wingbeat::fem::{self, geometry, FemInput};
use wingbeat::kinematics_table::{kinematics_from_csv, AngleUnits, CsvKinematicsOptions};
use wingbeat::WingbeatError;

/// An error must say what it is about: a field for a value or a cap, the document and a
/// position or path for a parse error, and never be empty.
fn assert_clear(e: &WingbeatError) {
    let text = e.to_string();
    assert!(!text.trim().is_empty());
    assert!(text.len() < 2000, "message too long: {} chars", text.len());
    match e {
        WingbeatError::InvalidInput { field, allowed, .. } => {
            assert!(!field.is_empty() && !allowed.is_empty(), "{text}");
        }
        WingbeatError::ResourceCap { field, cap, .. } => {
            assert!(!field.is_empty() && !cap.is_empty(), "{text}");
        }
        WingbeatError::Parse { what, message } => {
            assert!(!what.is_empty() && !message.is_empty(), "{text}");
        }
        _ => {}
    }
}

/// JSON values built from a small vocabulary of the config's own keys plus strangers, so that
/// the cases reach the nested structs (not just "expected value at line 1").
fn json_value() -> impl Strategy<Value = serde_json::Value> {
    use serde_json::{json, Value};
    let key = prop_oneof![
        Just("kinematics"),
        Just("modes"),
        Just("duration_s"),
        Just("sample_rate_hz"),
        Just("initial_conditions"),
        Just("flap_freq_hz"),
        Just("alpha"),
        Just("beta"),
        Just("gamma"),
        Just("kind"),
        Just("harmonics"),
        Just("values"),
        Just("max_harmonic"),
        Just("n"),
        Just("amplitude"),
        Just("phase"),
        Just("name"),
        Just("freq_hz"),
        Just("a"),
        Just("zeta"),
        Just("strains"),
        Just("point"),
        Just("eps_x"),
        Just("damping"),
        Just("x"),
    ];
    let num = prop_oneof![
        Just(0.0),
        Just(-1.0),
        Just(1e308),
        Just(-1e308),
        Just(5e-324),
        Just(62.5),
        Just(25.0),
        Just(1e5),
        -1e3f64..1e3,
    ];
    let leaf = prop_oneof![
        Just(Value::Null),
        any::<bool>().prop_map(Value::Bool),
        num.prop_map(|v| json!(v)),
        (0u64..70).prop_map(|v| json!(v)),
        prop_oneof![
            Just("fourier"),
            Just("sampled"),
            Just("P"),
            Just(""),
            Just("fast")
        ]
        .prop_map(|s| json!(s)),
    ];
    leaf.prop_recursive(4, 48, 6, move |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..5).prop_map(Value::Array),
            prop::collection::vec((key.clone(), inner), 0..6).prop_map(|kv| {
                Value::Object(kv.into_iter().map(|(k, v)| (k.to_string(), v)).collect())
            }),
        ]
    })
}

/// A config that parsed and validated is run only when it is cheap, so a case stays short.
fn run_if_cheap(cfg: &SimConfig) {
    let (cost, _) = wingbeat::simulate::run_cost(cfg);
    assert!(!cost.is_nan());
    if cost > 3e3 || cfg.n_samples() > 2000 {
        return;
    }
    match wingbeat::simulate::simulate(cfg) {
        Err(e) => assert_clear(&e),
        Ok(r) => {
            for m in &r.modes {
                assert!(m.qdot_total.iter().all(|v| v.is_finite()));
                assert!(m.q.total.iter().all(|v| v.is_finite()));
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, .. ProptestConfig::default() })]

    /// Arbitrary text never panics the config, modes-document or FE-input readers.
    #[test]
    fn config_readers_take_any_text(text in "\\PC{0,200}") {
        if let Err(e) = SimConfig::from_json(&text) { assert_clear(&e); }
        if let Err(e) = wingbeat::modes_doc::read_modes_document(&text, "m.json") { assert_clear(&e); }
        if let Err(e) = parse_json::<FemInput>(&text, "fe.json") { assert_clear(&e); }
    }

    /// Structured JSON over the config's own keys: parsed, validated, cheap ones run; every
    /// refusal names what it refuses.
    #[test]
    fn config_json_is_ok_and_finite_or_refused_by_name(v in json_value()) {
        let text = v.to_string();
        match SimConfig::from_json(&text) {
            Err(e) => assert_clear(&e),
            Ok(cfg) => match cfg.validate() {
                Err(e) => assert_clear(&e),
                Ok(()) => run_if_cheap(&cfg),
            },
        }
        // the same value as the `modes` of a config and as a modes document
        let wrapped = serde_json::json!({ "modes": v }).to_string();
        match SimConfig::from_json(&wrapped) {
            Err(e) => assert_clear(&e),
            Ok(cfg) => if let Err(e) = cfg.validate() { assert_clear(&e) },
        }
        if let Err(e) = wingbeat::modes_doc::modes_from_json(&wrapped, "m.json") { assert_clear(&e); }
    }
}

fn csv_field() -> impl Strategy<Value = String> {
    prop_oneof![
        (-1e3f64..1e3).prop_map(|v| format!("{v}")),
        Just("1e308".to_string()),
        Just("NaN".to_string()),
        Just("inf".to_string()),
        Just("".to_string()),
        Just("\"0.5\"".to_string()),
        Just("x".to_string()),
        (0u32..100).prop_map(|v| format!("{}", f64::from(v) * 0.001)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, .. ProptestConfig::default() })]

    /// Kinematics tables: arbitrary headers, rows and options.
    #[test]
    fn kinematics_csv_is_ok_and_finite_or_refused_by_name(
        header in prop_oneof![
            Just("t,alpha,beta,gamma"), Just("t_s,alpha_deg"), Just("time,alpha,alpha"),
            Just("t,delta"), Just("alpha,beta"), Just(""), Just("t,alpha_rad,beta_deg"),
        ],
        rows in prop::collection::vec(prop::collection::vec(csv_field(), 0..5), 0..40),
        regular in any::<bool>(),
        flap_hz in prop_oneof![Just(25.0), Just(1e-320), Just(1e9), Just(f64::NAN), 0.5f64..100.0],
        deg in any::<bool>(),
        max_harmonic in prop::option::of(0u32..300),
    ) {
        let mut text = format!("{header}\n");
        for (i, r) in rows.iter().enumerate() {
            if regular {
                // a well-formed row on a 1 ms grid, with the random fields as angles
                let a: Vec<String> = r.iter().take(3).cloned().collect();
                text.push_str(&format!("{},{}\n", f64::from(i as u32) * 1e-3, a.join(",")));
            } else {
                text.push_str(&r.join(","));
                text.push('\n');
            }
        }
        let opts = CsvKinematicsOptions {
            units: if deg { AngleUnits::Deg } else { AngleUnits::Rad },
            flap_hz,
            max_harmonic,
        };
        match kinematics_from_csv(&text, &opts) {
            Err(e) => assert_clear(&e),
            Ok(t) => {
                let cfg = SimConfig { kinematics: t.kinematics, ..SimConfig::paper() };
                if let Err(e) = cfg.validate() { assert_clear(&e); }
                let (cost, _) = wingbeat::simulate::run_cost(&cfg);
                prop_assert!(!cost.is_nan());
            }
        }
    }

    /// Planform readers (CSV and JSON) and the outline checks: an accepted outline has a
    /// finite positive area and an automatic mesh size; a refusal names the outline.
    #[test]
    fn planform_readers_are_ok_and_finite_or_refused_by_name(
        pts in prop::collection::vec(
            (prop_oneof![-60.0f64..60.0, Just(0.0), Just(1e-9), Just(1e300), Just(f64::NAN)],
             prop_oneof![-30.0f64..30.0, Just(0.0), Just(-1e-9)]),
            0..24),
        header in any::<bool>(),
        junk in prop::option::of("\\PC{0,12}"),
    ) {
        let mut csv = if header { "x_mm,y_mm\n".to_string() } else { String::new() };
        for (x, y) in &pts {
            csv.push_str(&format!("{x},{y}\n"));
        }
        if let Some(j) = &junk { csv.push_str(j); }
        let json = serde_json::to_string(&pts.iter().map(|&(x, y)| [x, y]).collect::<Vec<_>>())
            .unwrap_or_default();
        for parsed in [geometry::parse_planform_csv(&csv), geometry::parse_planform_json(&json)] {
            match parsed {
                Err(e) => assert_clear(&e),
                Ok(p) => match geometry::outline_summary(&p) {
                    Err(e) => assert_clear(&e),
                    Ok(s) => {
                        prop_assert!(s.area_mm2.is_finite() && s.area_mm2 > 0.0);
                        prop_assert!(s.span_mm >= geometry::MIN_EXTENT_MM);
                        prop_assert!(s.chord_mm >= geometry::MIN_EXTENT_MM);
                        let h = fem::default_mesh_size_mm(&geometry::validate_outline(&p).unwrap());
                        prop_assert!(h.is_finite() && h > 0.0);
                    }
                },
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, .. ProptestConfig::default() })]

    /// FE inputs: material, camber, clamp, mesh size and node cap from anywhere in and around
    /// their ranges, on small outlines; meshed (node cap 400) and, when it validates, solved
    /// for two modes. Either finite modes or a refusal naming the field.
    #[test]
    fn fe_inputs_are_ok_and_finite_or_refused_by_name(
        span in prop_oneof![1 => Just(1e-9), 1 => Just(0.005), 8 => 1.0f64..60.0, 1 => Just(1e6)],
        chord in prop_oneof![1 => Just(1e-9), 9 => 0.5f64..20.0],
        e_pa in prop_oneof![1 => Just(1e-300), 1 => Just(0.0), 1 => Just(1e3), 12 => 1e5f64..1e12,
            1 => Just(1e13), 1 => Just(1e20)],
        rho in prop_oneof![1 => Just(-1.0), 1 => Just(1.0), 12 => 10.0f64..2e4, 1 => Just(1e6)],
        nu in prop_oneof![1 => Just(-1.0), 1 => Just(0.5), 12 => -0.9f64..0.49],
        thickness_m in prop_oneof![1 => Just(1e-12), 1 => Just(1e-7), 12 => 1e-6f64..1e-3, 1 => Just(2.0)],
        camber in prop_oneof![1 => Just(-0.1), 12 => 0.0f64..0.5, 1 => Just(0.6)],
        clamp in prop_oneof![Just(fem::Clamp::Root), Just(fem::Clamp::Free),
            (-1.0f64..80.0).prop_map(|x_mm| fem::Clamp::Strip { x_mm })],
        mesh in prop::option::of(prop_oneof![1 => Just(0.0), 1 => Just(-1.0), 12 => 0.5f64..20.0, 1 => Just(1e9)]),
        max_nodes in prop::option::of(prop_oneof![1 => Just(0usize), 8 => 50usize..400, 1 => Just(1_000_000)]),
    ) {
        let input = FemInput {
            planform_mm: geometry::rectangle_planform(span, chord),
            planform_note: "prop".into(),
            camber,
            clamp,
            material: fem::ShellMaterial { thickness_m, e_pa, rho_kg_m3: rho, nu },
            n_modes: 2,
            mesh_size_mm: mesh,
            max_nodes: max_nodes.map(|n| n.min(400)).or(Some(400)),
        };
        // the JSON form reads back the same input (or is refused by name)
        match parse_json::<FemInput>(&serde_json::to_string(&input).unwrap(), "fe.json") {
            Err(e) => assert_clear(&e),
            Ok(back) => prop_assert_eq!(&back, &input),
        }
        match fem::compute_modes(&input) {
            Err(e) => assert_clear(&e),
            Ok(fe) => {
                prop_assert!(fe.freq_hz.iter().all(|f| f.is_finite() && *f >= 0.0), "{:?}", fe.freq_hz);
                prop_assert!(fe.shapes.iter().flatten().all(|v| v.is_finite()));
                prop_assert!(fe.a.iter().flatten().all(|v| v.is_finite()));
                prop_assert!(fe.strain_nodes.iter().flatten().flatten().all(|v| v.is_finite()));
            }
        }
    }
}

#[cfg(feature = "web")]
mod wasm_side {
    //! The wasm entry points' checks that run before any work (`wasm::helpers`): integer
    //! arguments, series, flat mesh arrays, nodal strains and the web caps.
    use super::assert_clear;
    use proptest::prelude::*;
    use wingbeat::wasm::helpers;

    proptest! {
        #![proptest_config(ProptestConfig { cases: 256, .. ProptestConfig::default() })]

        /// Integer arguments: Ok only for an integer in range, returned unchanged.
        #[test]
        fn integers_are_never_coerced(
            v in prop_oneof![any::<f64>(), -3.0f64..10.0, Just(-1.0), Just(1.5),
                Just(4294967296.0), Just(f64::INFINITY), Just(f64::NAN)],
            hi in 0usize..100,
        ) {
            match helpers::check_int("mode", v, 0, hi) {
                Ok(i) => prop_assert!(v.fract() == 0.0 && v >= 0.0 && i as f64 == v && i <= hi),
                Err(e) => { assert_clear(&e); prop_assert!(e.to_string().contains("`mode`")); }
            }
            match helpers::check_mode_count("n_modes", v) {
                Ok(n) => prop_assert!(n >= 1 && n as f64 == v),
                Err(e) => assert_clear(&e),
            }
        }

        /// Series: finite ones pass; one non-finite value is refused naming its index.
        #[test]
        fn series_checks(
            x in prop::collection::vec(prop_oneof![-1e300f64..1e300, Just(f64::NAN), Just(f64::INFINITY)], 0..200),
        ) {
            match helpers::check_series("series", &x) {
                Ok(()) => prop_assert!(x.iter().all(|v| v.is_finite())),
                Err(e) => assert_clear(&e),
            }
        }

        /// Flat mesh arrays and nodal strains as JS hands them over: any lengths, any values,
        /// any indices.
        #[test]
        fn flat_mesh_and_strains(
            nodes in prop::collection::vec(prop_oneof![-1.0f64..1.0, Just(f64::NAN), Just(1e10)], 0..40),
            tris in prop::collection::vec(0u32..20, 0..30),
            strains in prop::collection::vec(prop_oneof![-1.0f64..1.0, Just(f64::INFINITY)], 0..60),
            n_modes in 1usize..4,
        ) {
            match helpers::check_strain_nodes(&strains, n_modes) {
                Err(e) => assert_clear(&e),
                Ok(n_nodes) => match helpers::mesh_from_flat(&nodes, &tris, n_nodes) {
                    Err(e) => assert_clear(&e),
                    Ok((ns, ts)) => {
                        prop_assert_eq!(ns.len(), n_nodes);
                        prop_assert!(ts.iter().flatten().all(|&i| i < n_nodes));
                    }
                },
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 64, .. ProptestConfig::default() })]

        /// The web caps on any config the JSON reader accepts.
        #[test]
        fn web_caps(v in super::json_value()) {
            if let Ok(cfg) = wingbeat::config::SimConfig::from_json(&v.to_string()) {
                if let Err(e) = helpers::check_web_caps(&cfg) { assert_clear(&e); }
            }
        }
    }
}
