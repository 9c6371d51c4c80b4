//! Sensing body rotation through wing strain for the lab: `senseRotation` and
//! `bodyRateRanges`. The analysis is the core's ([`crate::analysis::sensing`]); this file only
//! reads `feModes`' flat arrays, checks every input and cap before any work, and writes the
//! long results as typed arrays.

use super::helpers::{check_strain_nodes, mesh_from_flat};
use super::marshal::{
    config_from, err, f64_array_arg, f64a, from_js, function_arg, progress_fn, set, spectrum_js,
    to_js,
};
use crate::analysis::psd::{welch, WelchOptions};
use crate::analysis::sensing::{
    body_rate_vector, check_sensing_cost, delta_strain_series, detectability_map,
    modal_rotation_signal, place_sensors, DetectabilityMap, ModalSignal, Placement, SensingOptions,
    Sensor, DEFAULT_NOISE, DEFAULT_RHO, DEFAULT_SAMPLES_PER_SENSOR, MAX_K,
};
use crate::analysis::strain::{modal_strains_at, StrainSeries};
use crate::error::WingbeatError;
use js_sys::{Object, Uint8Array};
use serde::{Deserialize, Serialize};
use wasm_bindgen::prelude::*;

/// The options of `senseRotation` (declared as `SenseOptions`); missing = the core's defaults.
#[derive(Debug, Default, Deserialize)]
#[serde(default, deny_unknown_fields)]
struct SenseOptions {
    /// Sensors in the performance curve, 1 ..= 30.
    k_max: Option<usize>,
    /// Relative stroke variability ρ, [0, 1].
    rho: Option<f64>,
    /// Sensor noise σ, rms strain, (0, 1].
    noise: Option<f64>,
    /// Samples per sensor in the detection vector, 8 ..= 4096.
    samples_per_sensor: Option<usize>,
    /// Where the Δε series and spectrum are taken, [x, y] mm; default the best sensor.
    point_mm: Option<[f64; 2]>,
}

/// The sensing options from `SenseOptions`, validated with names `opts.*`.
fn sensing_options(o: &SenseOptions) -> Result<SensingOptions, JsError> {
    let s = SensingOptions {
        k_max: o.k_max.unwrap_or(MAX_K),
        rho: o.rho.unwrap_or(DEFAULT_RHO),
        noise: o.noise.unwrap_or(DEFAULT_NOISE),
        samples_per_sensor: o.samples_per_sensor.unwrap_or(DEFAULT_SAMPLES_PER_SENSOR),
    };
    s.validate_named([
        "opts.k_max",
        "opts.rho",
        "opts.noise",
        "opts.samples_per_sensor",
    ])
    .map_err(err)?;
    Ok(s)
}

/// The accepted ranges of the body angular velocity (core `params::BODY_RATE_RANGES`): one
/// entry per quantity (`mean`, `amplitude`, `phase`, `value`, `peak`) with `min`, `max`, `unit`.
#[wasm_bindgen(js_name = bodyRateRanges, unchecked_return_type = "BodyRateRange[]")]
pub fn body_rate_ranges() -> Result<JsValue, JsError> {
    to_js(&crate::params::BODY_RATE_RANGES[..])
}

/// Where rotation shows up in the strain of an FE wing (docs/sensing.md): two runs
/// of `config` (whose modes must be the FE wing's, in `feModes`' order), one under the constant
/// body rate `body_rate` = [x, y, z] rad/s (body axes) and one without; from their difference
/// Δq and the nodal modal strains (`nodes`, `triangles`, `strain_nodes` as `feModes` returns
/// them) the detectability D = E_Δ / (ρ² E_F + σ²) of every node and component, the greedy
/// choice of `opts.k_max` sensors with d′ and the detection probability P_d (1 % false alarms)
/// for K = 1 … k_max, and Δε(t) (three components), the flapping strain and the Welch spectra
/// of Δε at `opts.point_mm` (default: the best sensor). The modal series `dq` and `q_flap` come
/// back too, so a caller can form Δε at any other point (Σ_k ε_k Δq_k). Every input is checked
/// (errors name the field and its range), then the runs' work, the map's work and the series'
/// work against the core's caps, before any work. `progress(done, total)` is called after each
/// of the three stages. A zero body rate gives Δq and Δε exactly 0.
#[wasm_bindgen(js_name = senseRotation, unchecked_return_type = "SensingResult")]
pub fn sense_rotation(
    #[wasm_bindgen(unchecked_param_type = "SimConfig")] config: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] nodes: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Uint32Array | number[]")] triangles: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] strain_nodes: JsValue,
    #[wasm_bindgen(unchecked_param_type = "[number, number, number] | Float64Array")]
    body_rate: JsValue,
    #[wasm_bindgen(unchecked_param_type = "SenseOptions | undefined")] opts: JsValue,
    #[wasm_bindgen(
        unchecked_param_type = "((done: number, total: number) => void) | null | undefined"
    )]
    progress: JsValue,
) -> Result<JsValue, JsError> {
    let progress = function_arg(progress, "progress")?;
    let cfg = config_from(config)?;
    let o: SenseOptions = from_js(opts, "opts")?;
    let sopts = sensing_options(&o)?;
    let body_rate = f64_array_arg(&body_rate, "body_rate", 0, 3)?;
    let w = body_rate_vector("body_rate", &body_rate).map_err(err)?;
    let n_modes = cfg.modes.len();
    let (nodes, triangles, strain_nodes) =
        super::wing::flat_mesh_args(&nodes, &triangles, &strain_nodes, n_modes)?;
    let strain_nodes = &strain_nodes[..];
    let nn = check_strain_nodes(strain_nodes, n_modes).map_err(err)?;
    let (mesh_nodes, tris) = mesh_from_flat(&nodes, &triangles, nn).map_err(err)?;
    let strain = |k: usize, i: usize| {
        let j = (k * nn + i) * 3;
        [strain_nodes[j], strain_nodes[j + 1], strain_nodes[j + 2]]
    };
    // a point outside the wing is refused before any run
    let user_point = match o.point_mm {
        Some([x, y]) => {
            let e = modal_strains_at(&mesh_nodes, &tris, n_modes, strain, x, y).map_err(|e| {
                err(WingbeatError::invalid(
                    "opts.point_mm",
                    format!("[{x}, {y}] mm"),
                    e.to_string(),
                ))
            })?;
            Some(([x, y], e))
        }
        None => None,
    };
    check_sensing_cost(&cfg, w, nn, 1, "senseRotation").map_err(err)?;
    let mut progress = progress_fn(progress);
    progress(0, 3);
    let sig = modal_rotation_signal(&cfg, w).map_err(err)?;
    progress(1, 3);
    let map = detectability_map(nn, strain, &sig, &sopts).map_err(err)?;
    progress(2, 3);
    let placement = place_sensors(&mesh_nodes, strain, &sig, &sopts).map_err(err)?;
    progress(3, 3);
    let (point, source, modal) = match user_point {
        Some((p, e)) => (p, "opts", e),
        None => {
            let s = placement.sensors.first().ok_or_else(|| {
                err(WingbeatError::invalid(
                    "nodes",
                    "no sensor chosen",
                    "a mesh with at least one node",
                ))
            })?;
            let e = (0..n_modes).map(|k| strain(k, s.node)).collect();
            ([s.x_mm, s.y_mm], "best_sensor", e)
        }
    };
    let series = delta_strain_series(&["P".to_string()], &[modal], &sig).map_err(err)?;
    result_js(&Outcome {
        body_rate: w,
        options: sopts,
        n_nodes: nn,
        n_modes,
        sig: &sig,
        map: &map,
        placement: &placement,
        point,
        point_source: source,
        series: &series[0],
    })
}

/// What [`sense_rotation`] found, for [`result_js`].
struct Outcome<'a> {
    body_rate: [f64; 3],
    options: SensingOptions,
    n_nodes: usize,
    n_modes: usize,
    sig: &'a ModalSignal,
    map: &'a DetectabilityMap,
    placement: &'a Placement,
    point: [f64; 2],
    point_source: &'a str,
    /// Δε and the flapping strain at the point.
    series: &'a (StrainSeries, StrainSeries),
}

/// The `SensingResult` object: the scalars through serde, the long series as typed arrays,
/// and the Welch spectra of Δε at the point.
fn result_js(r: &Outcome<'_>) -> Result<JsValue, JsError> {
    let (sig, map, placement) = (r.sig, r.map, r.placement);
    let (d, f) = r.series;
    let fd = sig.flap_freq_hz;
    let wopts = WelchOptions {
        segment_len: sig.t.len().clamp(8, 8192),
        ..Default::default()
    };
    let spec = |x: &[f64]| -> Result<JsValue, JsError> {
        spectrum_js(&welch(x, sig.sample_rate_hz, &wopts, Some(fd)).map_err(err)?)
    };

    #[derive(Serialize)]
    struct Meta<'a> {
        body_rate: [f64; 3],
        options: SensingOptions,
        flap_freq_hz: f64,
        sample_rate_hz: f64,
        n_nodes: usize,
        n_modes: usize,
        warnings: &'a [String],
        sensors: &'a [Sensor],
        d_prime_all: f64,
        pd_all: f64,
        k_for_90_percent: Option<usize>,
        method: &'a str,
        point_mm: [f64; 2],
        point_source: &'a str,
    }
    let o: Object = to_js(&Meta {
        body_rate: r.body_rate,
        options: r.options,
        flap_freq_hz: fd,
        sample_rate_hz: sig.sample_rate_hz,
        n_nodes: r.n_nodes,
        n_modes: r.n_modes,
        warnings: &sig.warnings,
        sensors: &placement.sensors,
        d_prime_all: placement.d_prime_all,
        pd_all: placement.pd_all,
        k_for_90_percent: placement.k_for_90_percent,
        method: &placement.method,
        point_mm: r.point,
        point_source: r.point_source,
    })?
    .unchecked_into();
    let flat3 = |v: &[[f64; 3]]| -> Vec<f64> { v.iter().flatten().copied().collect() };
    set(&o, "d_best", &f64a(&map.d_best))?;
    let best: Vec<u8> = map.best_component.iter().map(|&c| c as u8).collect();
    set(&o, "best_component", &Uint8Array::from(&best[..]).into())?;
    set(&o, "d", &f64a(&flat3(&map.d)))?;
    set(&o, "e_delta", &f64a(&flat3(&map.e_delta)))?;
    set(&o, "e_flap", &f64a(&flat3(&map.e_flap)))?;
    set(&o, "d_prime", &f64a(&placement.d_prime))?;
    set(&o, "pd", &f64a(&placement.pd))?;
    set(&o, "d_prime_ranked", &f64a(&placement.d_prime_ranked))?;
    set(&o, "t", &f64a(&sig.t))?;
    let comps = |s: &StrainSeries| -> Result<JsValue, JsError> {
        let c = Object::new();
        set(&c, "eps_x", &f64a(&s.eps_x))?;
        set(&c, "eps_y", &f64a(&s.eps_y))?;
        set(&c, "gamma_xy", &f64a(&s.gamma_xy))?;
        Ok(c.into())
    };
    set(&o, "delta", &comps(d)?)?;
    set(&o, "flap", &comps(f)?)?;
    let sp = Object::new();
    set(&sp, "eps_x", &spec(&d.eps_x)?)?;
    set(&sp, "eps_y", &spec(&d.eps_y)?)?;
    set(&sp, "gamma_xy", &spec(&d.gamma_xy)?)?;
    set(&o, "spectrum", &sp.into())?;
    let modal_list = |qs: &[Vec<f64>]| -> js_sys::Array { qs.iter().map(|q| f64a(q)).collect() };
    set(&o, "dq", &modal_list(&sig.delta))?;
    set(&o, "q_flap", &modal_list(&sig.flap))?;
    Ok(o.into())
}
