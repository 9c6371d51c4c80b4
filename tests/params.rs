//! The lab's parameter table (src/params.rs): its slider ranges against the core's validation,
//! its overrides against the config the lab used to build by hand, and against the sweep.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::analysis::sweep::{self, SweepParam};
use wingbeat::config::{SimConfig, MAX_DURATION_S};
use wingbeat::error::WingbeatError;
use wingbeat::kinematics::{Angle, Harmonic, Kinematics, MAX_FLAP_HZ};
use wingbeat::params::{apply_overrides, defaults, find, parameters, PARAMS, PHASE_LIMIT};

/// What www/state.js `toConfig` built before the core owned the parameters: every angle one
/// sine with zero mean, every mode's ζ replaced, 10 kHz, no initial conditions.
fn lab_config(v: &[(&str, f64)], base: &SimConfig) -> SimConfig {
    let get = |k: &str| v.iter().find(|(key, _)| *key == k).unwrap().1;
    let angle = |amp: f64, phase: f64| Angle::Fourier {
        mean: 0.0,
        harmonics: vec![Harmonic {
            n: 1,
            amplitude: amp,
            phase,
        }],
    };
    SimConfig {
        kinematics: Kinematics {
            flap_freq_hz: get("flap_hz"),
            alpha: angle(get("alpha0"), get("alpha_phase")),
            beta: angle(get("beta0"), get("beta_phase")),
            gamma: angle(get("gamma0"), get("gamma_phase")),
            body_rate: Default::default(),
        },
        modes: base
            .modes
            .iter()
            .map(|m| {
                let mut m = m.clone();
                m.zeta = get("zeta");
                m
            })
            .collect(),
        duration_s: get("duration"),
        sample_rate_hz: 10_000.0,
        initial_conditions: vec![],
        aero: wingbeat::aero::AeroConfig::with_density(
            v.iter()
                .find(|(key, _)| *key == "air_density")
                .map_or(0.0, |kv| kv.1),
        ),
        ..SimConfig::paper()
    }
}

#[test]
fn table_has_the_contract_keys_in_order() {
    let keys: Vec<&str> = parameters().iter().map(|p| p.key).collect();
    assert_eq!(
        keys,
        [
            "alpha0",
            "beta0",
            "gamma0",
            "flap_hz",
            "zeta",
            "alpha_phase",
            "beta_phase",
            "gamma_phase",
            "duration",
            "air_density"
        ]
    );
    for p in &PARAMS {
        assert!(p.min < p.max && p.step > 0.0, "{}", p.key);
        assert!(p.default >= p.min && p.default <= p.max, "{}", p.key);
        let steps = (p.max - p.min) / p.step;
        assert!(
            (steps - steps.round()).abs() < 1e-9,
            "{}: range not on the step grid",
            p.key
        );
        assert!(!p.label.is_empty() && !p.symbol.is_empty());
    }
    assert_eq!(find("duration").unwrap().max, 10.0);
}

#[test]
fn every_slider_end_is_accepted_by_validate() {
    let base = SimConfig::paper();
    for p in &PARAMS {
        for v in [p.min, p.max] {
            let c = apply_overrides(&base, [(p.key, v)])
                .unwrap_or_else(|e| panic!("{} = {v}: {e}", p.key));
            c.validate().unwrap();
        }
    }
    // All ends together (the largest run the sliders can ask for, and the smallest).
    for end in [0, 1] {
        let all: Vec<(&str, f64)> = PARAMS
            .iter()
            .map(|p| (p.key, if end == 0 { p.min } else { p.max }))
            .collect();
        let c = apply_overrides(&base, all.iter().copied()).unwrap();
        c.validate().unwrap();
        // The longest run stays inside the browser's cap on sample values (wasm helpers).
        assert!(c.n_samples() * c.modes.len() <= 2_000_000, "web sample cap");
    }
    // The ranges are also inside the documented limits themselves.
    assert!(find("duration").unwrap().max <= MAX_DURATION_S);
    assert!(find("flap_hz").unwrap().max <= MAX_FLAP_HZ);
    for k in ["alpha0", "beta0", "gamma0"] {
        assert!(find(k).unwrap().max <= 2.0 * std::f64::consts::PI);
    }
}

#[test]
fn just_outside_each_range_is_an_error_naming_the_field_and_range() {
    let base = SimConfig::paper();
    for p in &PARAMS {
        for v in [p.min - p.step, p.max + p.step, f64::NAN, f64::INFINITY] {
            let e = apply_overrides(&base, [(p.key, v)]).unwrap_err();
            match &e {
                WingbeatError::InvalidInput { field, allowed, .. } => {
                    assert_eq!(field, &format!("overrides.{}", p.key));
                    assert!(
                        allowed.contains(&format!("[{}, {}]", p.min, p.max)),
                        "{allowed}"
                    );
                    assert!(allowed.contains(p.unit), "{allowed}");
                }
                other => panic!("{other:?}"),
            }
        }
    }
}

#[test]
fn defaults_are_the_paper_case() {
    let paper = SimConfig::paper();
    assert_eq!(apply_overrides(&paper, defaults()).unwrap(), paper);
    assert_eq!(lab_config(&defaults(), &paper), paper);
}

#[test]
fn overrides_equal_the_config_the_lab_built_by_hand() {
    let base = SimConfig::paper();
    // The medium: only the density changes (the wing that air needs is attached by the caller).
    let air = apply_overrides(&base, [("air_density", 1.2)]).unwrap();
    assert_eq!(air.aero, wingbeat::aero::AeroConfig::with_density(1.2));
    assert_eq!(
        SimConfig {
            aero: Default::default(),
            ..air
        },
        base
    );
    let sets: [[(&str, f64); 9]; 3] = [
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
        [
            ("alpha0", 0.0),
            ("beta0", 1.0),
            ("gamma0", 0.5),
            ("flap_hz", 5.0),
            ("zeta", 0.1),
            ("alpha_phase", -PHASE_LIMIT),
            ("beta_phase", 0.0),
            ("gamma_phase", 0.0),
            ("duration", 0.2),
        ],
        [
            ("duration", 4.0),
            ("gamma_phase", 1.0),
            ("beta_phase", 2.0),
            ("alpha_phase", 3.0),
            ("zeta", 0.0),
            ("flap_hz", 60.0),
            ("gamma0", 0.25),
            ("beta0", 0.5),
            ("alpha0", 0.8),
        ],
    ];
    for set in &sets {
        let got = apply_overrides(&base, set.iter().copied()).unwrap();
        assert_eq!(got, lab_config(set, &base), "{set:?}");
    }
    // A subset leaves the other fields of the base alone.
    let got = apply_overrides(&base, [("gamma0", 0.1)]).unwrap();
    let mut want = base;
    want.kinematics.gamma = Angle::sine(0.1);
    assert_eq!(got, want);
}

#[test]
fn the_sweep_and_the_overrides_mean_the_same_thing() {
    let base = SimConfig::paper();
    for (key, param, v) in [
        ("gamma0", SweepParam::Gamma0, 0.35),
        ("alpha0", SweepParam::Alpha0, 1.1),
        ("beta0", SweepParam::Beta0, 0.2),
        ("flap_hz", SweepParam::FlapHz, 40.0),
        ("zeta", SweepParam::Zeta, 0.02),
    ] {
        let by_sweep = sweep::apply(&base, param, v).unwrap();
        let by_override = apply_overrides(&base, [(key, v)]).unwrap();
        assert_eq!(by_sweep, by_override, "{key}");
    }
    // γ0 on a base with a phase and a second harmonic: only the first amplitude changes.
    let mut b2 = base;
    b2.kinematics.gamma = Angle::Fourier {
        mean: 0.01,
        harmonics: vec![
            Harmonic {
                n: 2,
                amplitude: 0.03,
                phase: 0.4,
            },
            Harmonic {
                n: 1,
                amplitude: 0.2,
                phase: 0.7,
            },
        ],
    };
    let s = sweep::apply(&b2, SweepParam::Gamma0, 0.3).unwrap();
    let o = apply_overrides(&b2, [("gamma0", 0.3)]).unwrap();
    assert_eq!(s, o);
    // The sweep itself at that value gives what a simulation of the override gives.
    let sw = sweep::sweep(
        &b2,
        &sweep::SweepOptions {
            param: SweepParam::Gamma0,
            from: 0.1,
            to: 0.3,
            points: 2,
        },
        |_, _| {},
    )
    .unwrap();
    let r = wingbeat::simulate::simulate(&o).unwrap();
    let last = &sw.points[1];
    assert_eq!(last.value, 0.3);
    for (k, m) in last.modes.iter().enumerate() {
        assert_eq!(m.contribution_percent, r.modes[k].contribution_percent);
        assert_eq!(m.effective_freq_hz, r.modes[k].floquet.effective_freq_hz);
    }
}

#[test]
fn phases_set_the_first_harmonic_and_add_one_when_missing() {
    let mut base = SimConfig::paper();
    base.kinematics.beta = Angle::constant(0.1);
    let c = apply_overrides(&base, [("beta_phase", 0.5)]).unwrap();
    assert_eq!(
        c.kinematics.beta,
        Angle::Fourier {
            mean: 0.1,
            harmonics: vec![Harmonic {
                n: 1,
                amplitude: 0.0,
                phase: 0.5
            }]
        }
    );
    // Order does not matter: amplitude then phase equals phase then amplitude.
    let a = apply_overrides(&base, [("beta0", 0.4), ("beta_phase", 0.5)]).unwrap();
    let b = apply_overrides(&base, [("beta_phase", 0.5), ("beta0", 0.4)]).unwrap();
    assert_eq!(a, b);
}

#[test]
fn bad_keys_are_named() {
    let base = SimConfig::paper();
    let e = apply_overrides(&base, [("gamma_0", 0.1)]).unwrap_err();
    let msg = e.to_string();
    assert!(msg.contains("overrides.gamma_0"), "{msg}");
    assert!(msg.contains("gamma0") && msg.contains("duration"), "{msg}");
    let long = "x".repeat(500);
    let msg = apply_overrides(&base, [(long.as_str(), 0.1)])
        .unwrap_err()
        .to_string();
    assert!(msg.len() < 300, "{msg}");
    let msg = apply_overrides(&base, [("zeta", 0.01), ("zeta", 0.02)])
        .unwrap_err()
        .to_string();
    assert!(msg.contains("overrides.zeta"), "{msg}");
    // A sampled angle has no first harmonic to set.
    let mut s = base.clone();
    s.kinematics.alpha = Angle::Sampled {
        values: vec![0.0, 0.5, 0.0, -0.5],
        max_harmonic: None,
    };
    let msg = apply_overrides(&s, [("alpha_phase", 0.1)])
        .unwrap_err()
        .to_string();
    assert!(msg.contains("kinematics.alpha"), "{msg}");
    // An invalid base is still reported by validate.
    let mut bad = base;
    bad.sample_rate_hz = -1.0;
    let msg = apply_overrides(&bad, [("zeta", 0.01)])
        .unwrap_err()
        .to_string();
    assert!(msg.contains("sample_rate_hz"), "{msg}");
}
