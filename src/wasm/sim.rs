//! The simulation side of the wasm API: configs (defaults, validation, limits, the lab's
//! parameter table and named overrides), the simulation itself, the force terms, the kinematic angles and the paper-claims report.

use super::helpers;
use super::marshal::series_from_js;
use super::marshal::{config_from, err, from_js, obj_with, sim_js, to_js};
use crate::config::SimConfig;
use crate::params::apply_overrides as core_apply_overrides;
use crate::simulate::{force_series as core_force_series, simulate as core_simulate, ForceSeries};
use js_sys::{Array, Float64Array};
use serde::Serialize;
use std::collections::BTreeMap;
use wasm_bindgen::prelude::*;

/// The paper's forward-flight case (Tables 3–6), the default of every field.
#[wasm_bindgen(js_name = defaultConfig, unchecked_return_type = "SimConfig")]
pub fn default_config() -> Result<JsValue, JsError> {
    to_js(&SimConfig::default())
}

/// Validates a config (the core's checks plus the web caps); throws with the field's name.
#[wasm_bindgen(js_name = validateConfig)]
pub fn validate_config(
    #[wasm_bindgen(unchecked_param_type = "SimConfig")] cfg: JsValue,
) -> Result<(), JsError> {
    config_from(cfg).map(|_| ())
}

/// The resource caps in force (core and web).
#[wasm_bindgen(unchecked_return_type = "Limits")]
pub fn limits() -> Result<JsValue, JsError> {
    #[derive(Serialize)]
    struct Limits {
        max_duration_s: f64,
        max_sample_rate_hz: f64,
        max_samples: usize,
        web_max_sample_values: usize,
        max_sweep_points: usize,
        max_ic_cells: usize,
        max_modes: usize,
        max_resonance_points: usize,
        max_resonance_alpha0_values: usize,
        max_resonance_work: f64,
        max_strain_field_work: f64,
        max_outline_points: usize,
        web_max_run_work: f64,
        max_sweep_work: f64,
        min_flap_hz: f64,
        max_flap_hz: f64,
        max_strain_points: usize,
        default_sampled_max_harmonic: u32,
    }
    to_js(&Limits {
        max_duration_s: crate::config::MAX_DURATION_S,
        max_sample_rate_hz: crate::config::MAX_SAMPLE_RATE_HZ,
        max_samples: crate::config::MAX_SAMPLES,
        web_max_sample_values: helpers::WEB_MAX_SAMPLE_VALUES,
        max_sweep_points: crate::analysis::sweep::MAX_POINTS,
        max_ic_cells: crate::analysis::ic_map::MAX_CELLS,
        max_modes: crate::model::MAX_MODES,
        max_resonance_points: crate::analysis::resonance::MAX_POINTS,
        max_resonance_alpha0_values: crate::analysis::resonance::MAX_ALPHA0_VALUES,
        max_resonance_work: crate::analysis::resonance::MAX_WORK,
        max_strain_field_work: crate::analysis::strain::MAX_STRAIN_FIELD_WORK,
        max_outline_points: crate::fem::geometry::MAX_OUTLINE_POINTS,
        web_max_run_work: helpers::WEB_MAX_RUN_WORK,
        max_sweep_work: crate::analysis::sweep::MAX_SWEEP_WORK,
        min_flap_hz: crate::kinematics::MIN_FLAP_HZ,
        max_flap_hz: crate::kinematics::MAX_FLAP_HZ,
        max_strain_points: crate::model::MAX_STRAIN_POINTS,
        default_sampled_max_harmonic: crate::kinematics::DEFAULT_SAMPLED_MAX_HARMONIC,
    })
}

/// Runs a simulation: partial and total responses per mode, contributions, Floquet summary,
/// strains (see `SimResult`).
#[wasm_bindgen(unchecked_return_type = "SimResult")]
pub fn simulate(
    #[wasm_bindgen(unchecked_param_type = "SimConfig")] cfg: JsValue,
) -> Result<JsValue, JsError> {
    let cfg = config_from(cfg)?;
    let r = core_simulate(&cfg).map_err(err)?;
    sim_js(&r, cfg.sample_rate_hz)
}

fn forces_js(f: &ForceSeries) -> Result<JsValue, JsError> {
    let o = obj_with(&[
        ("euler", &f.euler),
        ("centrifugal", &f.centrifugal),
        ("coriolis", &f.coriolis),
        ("stiffness_coefficient", &f.stiffness_coefficient),
    ])?;
    if !f.aerodynamic.is_empty() {
        super::marshal::set(&o, "aerodynamic", &super::marshal::f64a(&f.aerodynamic))?;
    }
    Ok(o.into())
}

/// The Eq. 13 force terms of every mode and the stiffness coefficient S(t) = α̇²cos²β + β̇²
/// (1/s², key `stiffness_coefficient`) on the output time grid (paper Fig. 4).
#[wasm_bindgen(js_name = forceSeries, unchecked_return_type = "ForceSeries[]")]
pub fn force_series(
    #[wasm_bindgen(unchecked_param_type = "SimConfig")] cfg: JsValue,
) -> Result<JsValue, JsError> {
    let cfg = config_from(cfg)?;
    let fs = core_force_series(&cfg).map_err(err)?;
    let out = Array::new();
    for f in &fs {
        out.push(&forces_js(f)?);
    }
    Ok(out.into())
}

/// Roll, pitch and yaw (rad) of the config's kinematics at each time in `times` (s),
/// interleaved `[α(t0), β(t0), γ(t0), α(t1), …]` (paper §2.1). The 3-D view uses it to pose
/// the wing at the same instants as the simulated responses.
#[wasm_bindgen(js_name = anglesAt)]
pub fn angles_at(
    #[wasm_bindgen(unchecked_param_type = "SimConfig")] cfg: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] times: JsValue,
) -> Result<Float64Array, JsError> {
    let cfg = config_from(cfg)?;
    let times = series_from_js(&times, "anglesAt.times", crate::config::MAX_SAMPLES)?;
    let kin = cfg.kinematics.compile();
    let mut out = Vec::with_capacity(3 * times.len());
    for &t in &times {
        let s = kin.state(t);
        out.extend_from_slice(&[s.alpha, s.beta, s.gamma]);
    }
    Ok(Float64Array::from(&out[..]))
}

/// The paper's claims next to what wingbeat computes, each with a verdict (a JS object). Full
/// module only (it solves the shell FE modes).
#[cfg(feature = "web")]
#[wasm_bindgen]
pub fn reproduce() -> Result<JsValue, JsError> {
    to_js(&crate::reproduce::reproduce().map_err(err)?)
}

/// The same report as plain text.
#[cfg(feature = "web")]
#[wasm_bindgen(js_name = reproduceText)]
pub fn reproduce_text() -> Result<String, JsError> {
    Ok(crate::reproduce::reproduce().map_err(err)?.to_text())
}

/// The named media (`vacuum`, `helium`, `air`) and their densities, kg/m³: the lab's medium
/// control offers these (any other density is a custom medium).
#[wasm_bindgen(unchecked_return_type = "Medium[]")]
pub fn media() -> Result<JsValue, JsError> {
    #[derive(serde::Serialize)]
    struct Medium {
        name: &'static str,
        density_kg_m3: f64,
    }
    let list: Vec<Medium> = crate::aero::MEDIA
        .iter()
        .map(|&(name, density_kg_m3)| Medium {
            name,
            density_kg_m3,
        })
        .collect();
    to_js(&list)
}

/// The lab's numeric parameters, in slider order, from the core's table (`params::PARAMS`):
/// `{ key, symbol, label, unit, min, max, step, default }` each, defaults = the paper case.
/// The lab builds its sliders and URL checks from this, so the ranges have one owner.
#[wasm_bindgen(unchecked_return_type = "Param[]")]
pub fn parameters() -> Result<JsValue, JsError> {
    to_js(crate::params::parameters())
}

/// `base` (a `SimConfig`; `undefined` = the paper case) with named parameters set by the core
/// (`params::apply_overrides`): `alpha0`, `beta0`, `gamma0` (first-harmonic amplitudes, rad),
/// `flap_hz` (Hz), `zeta` (every mode), `alpha_phase`, `beta_phase`, `gamma_phase` (first-harmonic
/// phases, rad), `duration` (s) — the same meaning as `sweep`'s parameters. Throws, naming the
/// key, for an unknown key, a value that is not a number or lies outside its slider range, and
/// whatever `validateConfig` would reject in the result.
#[wasm_bindgen(js_name = applyOverrides, unchecked_return_type = "SimConfig")]
pub fn apply_overrides(
    #[wasm_bindgen(unchecked_param_type = "SimConfig | undefined")] base: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Overrides")] overrides: JsValue,
) -> Result<JsValue, JsError> {
    let base = config_from(base)?;
    let o: BTreeMap<String, f64> = from_js(overrides, "overrides")?;
    let c = core_apply_overrides(&base, o.iter().map(|(k, v)| (k.as_str(), *v))).map_err(err)?;
    helpers::check_web_caps(&c).map_err(err)?;
    to_js(&c)
}

/// Measured kinematics from a CSV table (core `kinematics_table::kinematics_from_csv`, the
/// same function as `wingbeat simulate --kinematics-csv`): a header naming `t` (s) and any of
/// `alpha`, `beta`, `gamma` (missing = 0; optional `_deg`/`_rad` suffix matching `units`),
/// strictly increasing t over one or more whole flap periods. `opts`: `{ units: "deg" |
/// "rad", flap_hz, max_harmonic? }`. Returns `{ kinematics, samples: { t, alpha, beta, gamma }
/// (the file's samples folded onto one period, s and rad, file order), n_periods, method
/// ("grid" | "least_squares"), grid_points, max_harmonic, warnings }`; `kinematics` goes into
/// a `SimConfig` as it is, and `anglesAt` previews its periodic interpolant. Throws naming the
/// column, line or option.
#[wasm_bindgen(js_name = kinematicsFromCsv, unchecked_return_type = "KinematicsTable")]
pub fn kinematics_from_csv(
    #[wasm_bindgen(unchecked_param_type = "string")] text: JsValue,
    #[wasm_bindgen(unchecked_param_type = "CsvKinematicsOptions")] opts: JsValue,
) -> Result<JsValue, JsError> {
    use crate::kinematics_table::{kinematics_from_csv as core_from_csv, CsvKinematicsOptions};
    let opts: CsvKinematicsOptions = super::marshal::required_js(
        opts,
        "kinematicsFromCsv",
        "{ units: \"deg\" | \"rad\", flap_hz, max_harmonic? }",
    )?;
    let text = super::marshal::text_arg(
        &text,
        "kinematicsFromCsv.text",
        super::marshal::MAX_TEXT_CHARS,
        "a string: the CSV file's text",
    )?;
    let r = core_from_csv(&text, &opts).map_err(err)?;
    #[derive(Serialize)]
    struct Meta<'a> {
        kinematics: &'a crate::kinematics::Kinematics,
        n_periods: f64,
        method: crate::kinematics_table::TableMethod,
        grid_points: usize,
        max_harmonic: u32,
        warnings: &'a [String],
    }
    let o: js_sys::Object = to_js(&Meta {
        kinematics: &r.kinematics,
        n_periods: r.n_periods,
        method: r.method,
        grid_points: r.grid_points,
        max_harmonic: r.max_harmonic,
        warnings: &r.warnings,
    })?
    .unchecked_into();
    let s = &r.samples;
    let samples = obj_with(&[
        ("t", &s.t),
        ("alpha", &s.alpha),
        ("beta", &s.beta),
        ("gamma", &s.gamma),
    ])?;
    super::marshal::set(&o, "samples", &samples)?;
    Ok(o.into())
}
