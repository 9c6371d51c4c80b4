//! The TypeScript declarations of the wasm API (`TS_TYPES` in src/wasm/types.rs) against the
//! serde types they describe: a sample of each type is serialised to JSON and its keys must
//! be exactly the interface's (optional keys may be absent). The objects the wasm API builds
//! by hand (`Analysis`, `SweepResult`, ...) are checked in the wasm suites
//! (tests/wasm_common, `ts_declarations_match_results`).
#![cfg(not(target_arch = "wasm32"))]

mod ts_common;

use serde::Serialize;
use serde_json::Value;
use wingbeat::analysis::ic_map::IcMapOptions;
use wingbeat::analysis::psd::WelchOptions;
use wingbeat::analysis::spectra::mode_spectra;
use wingbeat::analysis::sweep::{SweepOptions, SweepParam};
use wingbeat::config::SimConfig;
use wingbeat::fem::FemInput;
use wingbeat::kinematics::Harmonic;
use wingbeat::simulate::{force_series, simulate};

fn keys<T: Serialize>(v: &T) -> Vec<String> {
    match serde_json::to_value(v).unwrap() {
        Value::Object(m) => m.keys().cloned().collect(),
        other => panic!("not an object: {other}"),
    }
}

#[test]
fn declarations_parse() {
    let ifaces = ts_common::interfaces(ts_common::declarations());
    assert!(ifaces.len() >= 25, "{:?}", ifaces.keys());
    let fe = &ifaces["FemInput"];
    // Nested object types do not leak their keys.
    assert!(fe.iter().any(|k| k.name == "clamp" && k.optional));
    assert!(!fe.iter().any(|k| k.name == "strip" || k.name == "x_mm"));
}

#[test]
fn input_types_match_serde() {
    let i = ts_common::interfaces(ts_common::declarations());
    let cfg = SimConfig::paper();
    ts_common::check(&i, "SimConfig", &keys(&cfg));
    ts_common::check(&i, "Kinematics", &keys(&cfg.kinematics));
    // with a body rate the optional `body_rate` key appears, and its x, y, z
    let turning = cfg.kinematics.clone().with_body_rate([1.0, 2.0, 3.0]);
    ts_common::check(&i, "Kinematics", &keys(&turning));
    ts_common::check(&i, "BodyRate", &keys(&turning.body_rate));
    ts_common::check(&i, "Mode", &keys(&cfg.modes[0]));
    ts_common::check(&i, "ModalStrain", &keys(&cfg.modes[0].strains[0]));
    let h = Harmonic {
        n: 1,
        amplitude: 0.8,
        phase: 0.0,
    };
    ts_common::check(&i, "Harmonic", &keys(&h));
    ts_common::check(&i, "WelchOptions", &keys(&WelchOptions::default()));
    let sweep = SweepOptions {
        param: SweepParam::Gamma0,
        from: 0.0,
        to: 0.3,
        points: 3,
    };
    ts_common::check(&i, "SweepOptions", &keys(&sweep));
    ts_common::check(&i, "IcMapOptions", &keys(&IcMapOptions::default()));
    ts_common::check(&i, "FemInput", &keys(&FemInput::default()));
    let res = wingbeat::analysis::resonance::ResonanceOptions {
        from_hz: 10.0,
        to_hz: 40.0,
        points: 4,
        alpha0_values: Some(vec![0.5, 0.8]),
    };
    ts_common::check(&i, "ResonanceOptions", &keys(&res));
    ts_common::check(&i, "Param", &keys(&wingbeat::params::PARAMS[0]));
}

#[test]
fn result_types_match_serde() {
    let i = ts_common::interfaces(ts_common::declarations());
    let cfg = SimConfig {
        duration_s: 0.2,
        ..SimConfig::paper()
    };
    let r = simulate(&cfg).unwrap();
    let m = &r.modes[0];
    ts_common::check(&i, "ModeResult", &keys(m));
    ts_common::check(&i, "Responses", &keys(&m.q));
    ts_common::check(&i, "Contributions", &keys(&m.contribution_percent));
    ts_common::check(&i, "FloquetResult", &keys(&m.floquet));
    ts_common::check(&i, "Accuracy", &keys(&m.accuracy));
    ts_common::check(&i, "StrainSeries", &keys(r.strain.as_ref().unwrap()));
    // The wasm `simulate` adds the sample count and rate, and always sets `strain_points`.
    let mut sim = keys(&r);
    sim.extend(["n", "sample_rate_hz", "strain_points"].map(String::from));
    sim.sort();
    sim.dedup();
    ts_common::check(&i, "SimResult", &sim);
    let f = force_series(&cfg).unwrap();
    ts_common::check(&i, "ForceSeries", &keys(&f[0]));
    let opts = WelchOptions {
        segment_len: 256,
        ..WelchOptions::default()
    };
    let s = mode_spectra(&f[0], &m.q.total, cfg.sample_rate_hz, &opts, Some(25.0)).unwrap();
    ts_common::check(&i, "ModeSpectra", &keys(&s));
    ts_common::check(&i, "Spectrum", &keys(&s.coriolis));
    ts_common::check(&i, "Peak", &keys(&s.coriolis.peaks[0]));
}

/// The air's declarations against an air run of the FE wing: the medium's config, the per-mode
/// `air` block, the run's `air` summary, and the aerodynamic keys of the responses, shares,
/// forces and spectra (present in air, absent in a vacuum: the keys are optional).
#[test]
fn air_types_match_serde() {
    let i = ts_common::interfaces(ts_common::declarations());
    let base = SimConfig::fe_wing().unwrap();
    let cfg = SimConfig {
        duration_s: 0.1,
        sample_rate_hz: 2000.0,
        aero: wingbeat::aero::AeroConfig::with_density(1.2),
        ..base
    };
    let mut cfg_keys = keys(&cfg);
    assert!(cfg_keys.contains(&"aero".to_string()));
    cfg_keys.sort();
    ts_common::check(&i, "SimConfig", &cfg_keys);
    ts_common::check(&i, "AeroConfig", &keys(&cfg.aero));
    let r = simulate(&cfg).unwrap();
    let m = &r.modes[0];
    ts_common::check(&i, "ModeResult", &keys(m));
    ts_common::check(&i, "ModeAir", &keys(m.air.as_ref().unwrap()));
    ts_common::check(&i, "AirSummary", &keys(r.air.as_ref().unwrap()));
    let q = keys(&m.q);
    assert!(q.contains(&"aerodynamic".to_string()), "{q:?}");
    ts_common::check(&i, "Responses", &q);
    let c = keys(&m.contribution_percent);
    assert!(c.contains(&"aerodynamic".to_string()), "{c:?}");
    ts_common::check(&i, "Contributions", &c);
    let f = force_series(&cfg).unwrap();
    assert!(!f[0].aerodynamic.is_empty());
    ts_common::check(&i, "ForceSeries", &keys(&f[0]));
    let opts = WelchOptions {
        segment_len: 64,
        ..WelchOptions::default()
    };
    let s = mode_spectra(&f[0], &m.q.total, cfg.sample_rate_hz, &opts, Some(25.0)).unwrap();
    assert!(s.aerodynamic.is_some());
    ts_common::check(&i, "ModeSpectra", &keys(&s));
}

/// The own-wing and own-kinematics declarations against the core's serde types.
#[test]
fn lab_wing_types_match_serde() {
    use wingbeat::analysis::strain::{StrainComponent, StrainFieldOptions, StrainStat};
    use wingbeat::kinematics_table::{kinematics_from_csv, AngleUnits, CsvKinematicsOptions};
    let i = ts_common::interfaces(ts_common::declarations());
    let b = &wingbeat::fem::geometry::builtin_planforms()[0];
    ts_common::check(&i, "BuiltinPlanform", &keys(b));
    ts_common::check(&i, "WingParam", &keys(&wingbeat::params::WING_PARAMS[0]));
    ts_common::check(
        &i,
        "MaterialPreset",
        &keys(&wingbeat::params::material_presets()[0]),
    );
    let s = StrainFieldOptions {
        component: StrainComponent::EpsX,
        stat: StrainStat::Peak,
    };
    ts_common::check(&i, "StrainFieldOptions", &keys(&s));
    let opts = CsvKinematicsOptions {
        units: AngleUnits::Deg,
        flap_hz: 25.0,
        max_harmonic: Some(3),
    };
    ts_common::check(&i, "CsvKinematicsOptions", &keys(&opts));
    let t = kinematics_from_csv("t,alpha\n0,0\n0.01,10\n0.02,0\n0.03,-10\n", &opts).unwrap();
    ts_common::check(&i, "KinematicsTable", &keys(&t));
    ts_common::check(&i, "FoldedSamples", &keys(&t.samples));
    let sum = wingbeat::fem::geometry::outline_summary(&b.points_mm).unwrap();
    let mut ok = keys(&sum);
    ok.extend(["ok", "default_mesh_size_mm", "default_strain_point_mm"].map(String::from));
    ts_common::check(&i, "PlanformOk", &ok);
}

#[test]
fn classify_types_match_serde() {
    use wingbeat::analysis::rotation_classify::{
        ClassifyOptions, ClassifyReport, Curves, GreedyPoint, RandomPoint, SparsePoint,
    };
    let i = ts_common::interfaces(ts_common::declarations());
    let opts = ClassifyOptions {
        s0: Some(1e-4),
        ..ClassifyOptions::default()
    };
    ts_common::check(&i, "ClassifyOptions", &keys(&opts));
    let sparse = SparsePoint {
        kept_modes: 3,
        sensors: vec![1, 2],
        accuracy: 0.8,
    };
    let random = RandomPoint {
        sensors: 2,
        mean: 0.6,
        sd: 0.1,
        failed_fits: 0,
    };
    ts_common::check(&i, "SparsePoint", &keys(&sparse));
    ts_common::check(&i, "RandomPoint", &keys(&random));
    let greedy = GreedyPoint {
        sensors: vec![4, 1],
        d_prime: 1.5,
        accuracy: 0.7,
    };
    ts_common::check(&i, "GreedyPoint", &keys(&greedy));
    let curves = Curves {
        all_sensors: 0.9,
        sparse: vec![sparse],
        random: vec![random],
        greedy: vec![greedy],
        s0: 1e-4,
    };
    ts_common::check(&i, "ClassifyCurves", &keys(&curves));
    let report = ClassifyReport {
        options: opts,
        train_samples: 2700,
        test_samples: 300,
        encoded: curves.clone(),
        raw: curves,
        sensors: vec![[0.0, 0.0]],
        steps_per_sample: 45,
    };
    ts_common::check(&i, "ClassifyReport", &keys(&report));
}
