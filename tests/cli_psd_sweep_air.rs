//! `wingbeat psd` and `wingbeat sweep` with `--air-density`: what air adds to their output,
//! that every number is the library's air run, that a vacuum's output keeps its shape, and the
//! work caps that price the air run before anything runs.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

mod common_cli;
use common_cli::{run, run_timed};
use serde_json::Value;
use std::sync::OnceLock;
use std::time::Duration;
use wingbeat::aero::simulate::air_run_cost;
use wingbeat::aero::AeroWing;
use wingbeat::analysis::psd::{welch, Detrend, WelchOptions};
use wingbeat::analysis::sweep::MAX_SWEEP_WORK;
use wingbeat::config::SimConfig;
use wingbeat::run::MAX_RUN_WORK;
use wingbeat::simulate::{run_cost, simulate};

/// The CLI's `--preset fe-wing`, in a vacuum.
fn fe_wing() -> &'static SimConfig {
    static C: OnceLock<SimConfig> = OnceLock::new();
    C.get_or_init(|| SimConfig::fe_wing().expect("the FE wing preset solves"))
}

/// [`fe_wing`] over `duration` s in a medium of density `rho`.
fn fe_wing_in(rho: f64, duration: f64) -> SimConfig {
    let mut c = fe_wing().clone();
    c.duration_s = duration;
    c.aero.air_density_kg_m3 = rho;
    c
}

fn json(out: &str) -> Value {
    serde_json::from_str(out).expect("JSON output")
}

fn floats(v: &Value) -> Vec<f64> {
    v.as_array()
        .expect("an array")
        .iter()
        .map(|x| x.as_f64().expect("a number"))
        .collect()
}

const PSD_DURATION: &str = "0.2";
const PSD_SEGMENT: usize = 1024;

fn psd(rho: &str) -> Value {
    let seg = PSD_SEGMENT.to_string();
    let (code, out, err) = run(&[
        "psd",
        "--preset",
        "fe-wing",
        "--duration",
        PSD_DURATION,
        "--segment-len",
        &seg,
        "--air-density",
        rho,
    ]);
    assert_eq!(code, 0, "{err}");
    json(&out)
}

/// The spectrum the CLI writes for `x` (its default Welch options).
fn library_psd(x: &[f64], cfg: &SimConfig) -> Vec<f64> {
    let opts = WelchOptions {
        segment_len: PSD_SEGMENT,
        overlap: 0.5,
        detrend: Detrend::None,
        max_peaks: 8,
    };
    welch(
        x,
        cfg.sample_rate_hz,
        &opts,
        Some(cfg.kinematics.flap_freq_hz),
    )
    .unwrap()
    .psd
}

const VACUUM_MODE_KEYS: [&str; 9] = [
    "centrifugal",
    "coriolis",
    "effective_freq_hz",
    "euler",
    "freq_hz_natural",
    "name",
    "response_total",
    "stiffness_coefficient",
    "stiffness_force",
];

#[test]
fn psd_in_air_adds_the_aerodynamic_response_spectrum_of_the_library_air_run() {
    let (air, vac) = (psd("1.2"), psd("0"));
    let d: f64 = PSD_DURATION.parse().unwrap();
    let (cfg_air, cfg_vac) = (fe_wing_in(1.2, d), fe_wing_in(0.0, d));
    let (run_air, run_vac) = (simulate(&cfg_air).unwrap(), simulate(&cfg_vac).unwrap());
    assert_eq!(air["air_density_kg_m3"], 1.2);
    assert!(air["units"]["response_aerodynamic"].is_string());
    let (ma, mv) = (
        air["modes"].as_array().unwrap(),
        vac["modes"].as_array().unwrap(),
    );
    assert_eq!(ma.len(), 4);
    for k in 0..ma.len() {
        // In air: the aerodynamic response's spectrum, nonzero, on the total's bins, and
        // exactly the Welch PSD of the library's air run.
        let aero = &ma[k]["response_aerodynamic"];
        let p = floats(&aero["psd"]);
        assert!(p.iter().any(|&x| x > 0.0), "mode {k}: all zero");
        assert_eq!(aero["freq_hz"], ma[k]["response_total"]["freq_hz"]);
        assert_eq!(p, library_psd(&run_air.modes[k].q.aerodynamic, &cfg_air));
        let total_air = floats(&ma[k]["response_total"]["psd"]);
        assert_eq!(total_air, library_psd(&run_air.modes[k].q.total, &cfg_air));
        // In a vacuum: the keys of before, no aerodynamic spectrum, the library's total.
        let keys: Vec<&str> = mv[k]
            .as_object()
            .unwrap()
            .keys()
            .map(String::as_str)
            .collect();
        assert_eq!(keys, VACUUM_MODE_KEYS, "mode {k}");
        let total_vac = floats(&mv[k]["response_total"]["psd"]);
        assert_eq!(total_vac, library_psd(&run_vac.modes[k].q.total, &cfg_vac));
        // Air changes the response's spectrum.
        let diff = total_air
            .iter()
            .zip(&total_vac)
            .map(|(a, v)| (a - v).abs())
            .fold(0.0, f64::max);
        let top = total_vac.iter().cloned().fold(0.0, f64::max);
        assert!(diff > 1e-3 * top, "mode {k}: air and vacuum agree");
    }
    let top: Vec<&str> = vac
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    assert_eq!(
        top,
        [
            "flap_freq_hz",
            "modes",
            "options",
            "sample_rate_hz",
            "units",
            "warnings"
        ]
    );
    assert_eq!(vac["units"].as_object().unwrap().len(), 2);
    // No density flag is the same vacuum, byte for byte.
    let seg = PSD_SEGMENT.to_string();
    let args = [
        "psd",
        "--preset",
        "fe-wing",
        "--duration",
        PSD_DURATION,
        "--segment-len",
        &seg,
    ];
    let (code, plain, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    let mut zero = args.to_vec();
    zero.extend(["--air-density", "0"]);
    assert_eq!(run(&zero).1, plain);
}

#[test]
fn psd_in_air_refuses_the_paper_table_modes_by_name() {
    let (code, out, err) = run(&["psd", "--air-density", "1.2", "--duration", "0.1"]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert!(
        err.contains("--air-density") && err.contains("mode shapes"),
        "{err}"
    );
}

#[test]
fn psd_in_air_counts_its_seventh_spectrum_against_the_bin_cap() {
    // 4 modes: six spectra of a 480 000-sample segment fit the 6.1e6-bin cap
    // (5 760 024 bins), seven do not (6 720 028): refused before the 48 s run.
    let (code, _, err, took) = run_timed(&[
        "psd",
        "--preset",
        "fe-wing",
        "--air-density",
        "1.2",
        "--duration",
        "48",
        "--segment-len",
        "480000",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("--segment-len") && err.contains("4 modes × 7 spectra"),
        "{err}"
    );
    assert!(took < Duration::from_secs(60), "{took:?}");
}

fn sweep_json(rho: &str, extra: &[&str]) -> Value {
    let mut args = vec![
        "sweep",
        "gamma0",
        "--preset",
        "fe-wing",
        "--from",
        "0",
        "--to",
        "0.25",
        "--points",
        "2",
        "--duration",
        "0.1",
        "--air-density",
        rho,
    ];
    args.extend(extra);
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    json(&out)
}

#[test]
fn sweep_in_air_points_are_single_air_runs_and_differ_from_vacuum() {
    let air = sweep_json("1.2", &[]);
    let vac = sweep_json("0", &[]);
    assert_eq!(air["air_density_kg_m3"], 1.2);
    assert!(vac.get("air_density_kg_m3").is_none());
    let points = air["points"].as_array().unwrap();
    assert_eq!(points.len(), 2);
    for (p, pv) in points.iter().zip(vac["points"].as_array().unwrap()) {
        let value = p["value"].as_f64().unwrap();
        // The same point as one `simulate` in air, every number equal.
        let v = value.to_string();
        let (code, out, err) = run(&[
            "simulate",
            "--preset",
            "fe-wing",
            "--gamma0",
            &v,
            "--duration",
            "0.1",
            "--air-density",
            "1.2",
        ]);
        assert_eq!(code, 0, "{err}");
        let sim = json(&out);
        let modes = p["modes"].as_array().unwrap();
        for (k, m) in modes.iter().enumerate() {
            let s = &sim["modes"][k];
            assert_eq!(m["contribution_percent"], s["contribution_percent"], "{v}");
            assert_eq!(
                m["effective_freq_hz"], s["floquet"]["effective_freq_hz"],
                "{v}"
            );
            assert_eq!(m["beat_period_s"], s["floquet"]["beat_period_s"], "{v}");
            assert_eq!(m["stable"], s["floquet"]["stable"], "{v}");
            let peak = floats(&s["q"]["total"])
                .iter()
                .fold(0.0f64, |a, x| a.max(x.abs()));
            assert_eq!(m["peak_abs_q"].as_f64().unwrap(), peak, "{v}");
            // Air: an aerodynamic share, a different response than in a vacuum.
            assert!(m["contribution_percent"]["aerodynamic"].as_f64().unwrap() > 0.0);
            let mv = &pv["modes"][k];
            assert!(mv["contribution_percent"].get("aerodynamic").is_none());
            assert_ne!(m["peak_abs_q"], mv["peak_abs_q"], "{v}, mode {k}");
            assert_ne!(m["effective_freq_hz"], mv["effective_freq_hz"]);
        }
    }
    // CSV: the aerodynamic share gets its column in air only.
    let (code, csv, err) = run(&[
        "sweep",
        "gamma0",
        "--preset",
        "fe-wing",
        "--points",
        "2",
        "--duration",
        "0.05",
        "--air-density",
        "0.18",
        "--format",
        "csv",
    ]);
    assert_eq!(code, 0, "{err}");
    let header = csv.lines().next().unwrap();
    assert!(
        header.contains("coriolis_percent,aerodynamic_percent,effective_freq_hz"),
        "{header}"
    );
    assert_eq!(csv.lines().count(), 1 + 2 * 4);
    for line in csv.lines().skip(1) {
        assert_eq!(line.split(',').count(), header.split(',').count(), "{line}");
    }
}

#[test]
fn sweep_in_air_is_priced_by_the_air_run_before_it_starts() {
    // The default FE wing over 2 s: just enough points that their air runs exceed the
    // sweep's budget at the last point; priced as vacuum runs the sweep would be refused at
    // another point or not at all.
    let cfg = fe_wing_in(1.2, 2.0);
    let points = AeroWing::build(cfg.wing.as_deref().unwrap(), &cfg.aero)
        .unwrap()
        .points
        .len();
    let air = air_run_cost(&cfg, points);
    let vacuum = run_cost(&fe_wing_in(0.0, 2.0)).0;
    let n = (MAX_SWEEP_WORK / air).floor() as usize + 1;
    let n_vacuum = (MAX_SWEEP_WORK / vacuum).floor() as usize + 1;
    assert!(
        (2..=2001).contains(&n) && n_vacuum != n,
        "air {air}, vacuum {vacuum}, n {n}"
    );
    let n = n.to_string();
    let (code, out, err, took) = run_timed(&[
        "sweep",
        "gamma0",
        "--preset",
        "fe-wing",
        "--points",
        &n,
        "--air-density",
        "1.2",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(out.is_empty());
    assert!(
        err.contains("sweep in air") && err.contains(&format!("by point {n} of {n}")),
        "{err}"
    );
    assert!(err.contains("20000000 step equivalents"), "{err}");
    // Refused before the first point (no run starts).
    assert!(!err.contains("sweep: "), "{err}");
    assert!(took < Duration::from_secs(30), "{took:?}");
}

#[test]
fn sweep_in_air_refuses_a_point_over_the_run_cap_before_the_first_runs() {
    // A slow enough flap needs more Gauss steps per period than one air run may take; the
    // first such power-of-two frequency f is the sweep's second point (25 + (f − 25) = f
    // exactly), refused before the first point runs.
    let cost_at = |f: f64| {
        let mut c = fe_wing_in(1.2, 2.0);
        wingbeat::params::set_param(&mut c, "flap_hz", f).unwrap();
        let points = AeroWing::build(c.wing.as_deref().unwrap(), &c.aero)
            .unwrap()
            .points
            .len();
        air_run_cost(&c, points)
    };
    assert!(cost_at(25.0) <= MAX_RUN_WORK);
    let f = (1..=10)
        .map(|i| 0.5f64.powi(i))
        .find(|&f| cost_at(f) > MAX_RUN_WORK)
        .expect("a frequency above 1 mHz over the run cap");
    let to = f.to_string();
    let (code, _, err, took) = run_timed(&[
        "sweep",
        "flap_hz",
        "--preset",
        "fe-wing",
        "--from",
        "25",
        "--to",
        &to,
        "--points",
        "2",
        "--air-density",
        "1.2",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("one run")
            && err.contains(&format!("sweep value {to}"))
            && err.contains("5000000"),
        "{err}"
    );
    assert!(took < Duration::from_secs(30), "{took:?}");
}

#[test]
fn sweep_ic_refuses_air_by_name() {
    let (code, _, err) = run(&[
        "sweep",
        "ic",
        "--preset",
        "fe-wing",
        "--air-density",
        "1.2",
        "--n",
        "3",
    ]);
    assert_eq!(code, 2);
    assert!(
        err.contains("--air-density") && err.contains("sweep ic"),
        "{err}"
    );
}
