//! The browser lab's WebAssembly API (feature `web`), built with wasm-bindgen.
//!
//! It exposes the same inputs as the CLI — [`SimConfig`], [`WelchOptions`], [`SweepOptions`],
//! [`IcMapOptions`] — as plain JS objects (serde-wasm-bindgen), and returns JS objects whose
//! small metadata comes through serde and whose long series are `Float64Array`s (copied once
//! out of wasm memory, never JSON).
//!
//! Every entry point returns `Result<_, JsError>`; the error message is the core's
//! [`WingbeatError`] text, which names the field and the allowed range. Inputs are deserialised
//! with their path tracked (a type error says where), validated by the core, then checked
//! against the web caps in [`helpers`], so nothing reaches code that could panic.
//! `console_error_panic_hook` is installed anyway, so a bug would at least say where it was.

pub mod helpers;

use crate::analysis::beat;
use crate::analysis::ic_map::{ic_map as core_ic_map, IcMapOptions};
use crate::analysis::psd::{welch, Spectrum, WelchOptions};
use crate::analysis::sweep::{sweep as core_sweep, SweepOptions};
use crate::config::SimConfig;
use crate::error::WingbeatError;
use crate::simulate::{force_series as core_force_series, simulate as core_simulate, SimResult};
use crate::simulate::{ForceSeries, StrainSeries};
use helpers::{check_series, check_web_caps, opt_or_nan, stiffness_term};
use js_sys::{Array, Float64Array, Function, Object, Reflect, Uint32Array};
use serde::de::DeserializeOwned;
use serde::Serialize;
use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &'static str = r#"
/** One harmonic `amplitude · sin(n ω_d t + phase)`; rad. */
export interface Harmonic { n: number; amplitude: number; phase?: number }
/** How one angle is given: mean + harmonics, or samples over one period (rad). */
export type Angle =
  | { kind: "fourier"; mean?: number; harmonics?: Harmonic[] }
  | { kind: "sampled"; values: number[]; max_harmonic?: number | null };
/** Rotation kinematics (paper §2.1, Eq. 1). */
export interface Kinematics { flap_freq_hz: number; alpha: Angle; beta: Angle; gamma: Angle }
/** Modal strain at a named point, per unit q (Eqs. 16–18). */
export interface ModalStrain { point: string; eps_x: number; eps_y: number; gamma_xy: number }
/** One vibration mode: ω_k/2π in Hz, a_k in kg^½·m, damping ratio ζ. */
export interface Mode { name?: string; freq_hz: number; a: [number, number]; zeta?: number; strains?: ModalStrain[] }
/** A simulation request; every field is optional (missing = the paper's forward-flight case). */
export interface SimConfig {
  kinematics?: Kinematics;
  modes?: Mode[];
  duration_s?: number;
  sample_rate_hz?: number;
  initial_conditions?: [number, number][];
}
/** Welch PSD options (Hann window). detrend "none" keeps the DC part visible. */
export interface WelchOptions { segment_len?: number; overlap?: number; detrend?: "none" | "mean" | "linear"; max_peaks?: number }
export type SweepParam = "gamma0" | "alpha0" | "beta0" | "flap_hz" | "zeta";
export interface SweepOptions { param: SweepParam; from: number; to: number; points: number }
export interface IcMapOptions {
  mode?: number; n_q?: number; n_qdot?: number;
  q_range?: [number, number] | null; qdot_range?: [number, number] | null;
  attribution?: "forced" | "carried";
}
export interface Contributions { euler: number; centrifugal: number; coriolis: number }
export interface FloquetResult {
  multipliers: [number, number][]; monodromy: [[number, number], [number, number]];
  stable: boolean; max_modulus: number; growth_rate_per_s: number; homogeneous_period_s: number;
  characteristic_freq_hz: number; dominant_harmonic: number; effective_freq_hz: number;
  averaged_freq_hz: number; beat_harmonic: number; beat_period_s: number | null;
  beat_period_vs_2fd_s: number | null;
}
export interface Accuracy { method: string; period_error_estimate: number; periods: number; run_error_bound: number }
export interface Responses { euler: Float64Array; centrifugal: Float64Array; coriolis: Float64Array; free: Float64Array; total: Float64Array }
export interface ModeResult {
  name: string; freq_hz: number; zeta: number; q: Responses; qdot_total: Float64Array;
  contribution_percent: Contributions; floquet: FloquetResult; accuracy: Accuracy;
}
export interface StrainSeries { point: string; eps_x: Float64Array; eps_y: Float64Array; gamma_xy: Float64Array }
export interface SimResult {
  n: number; sample_rate_hz: number; flap_freq_hz: number; t: Float64Array; modes: ModeResult[];
  strain: StrainSeries | null; strain_points: StrainSeries[]; warnings: string[];
}
export interface ForceSeries { euler: Float64Array; centrifugal: Float64Array; coriolis: Float64Array; softening: Float64Array }
export interface Peak { freq_hz: number; psd: number; flap_multiple: number | null }
export interface Spectrum { freq_hz: Float64Array; psd: Float64Array; peaks: Peak[] }
/** Spectra of one mode: force terms, the stiffness term (α̇²cos²β+β̇²)·q_k, and the total response. */
export interface ModeSpectra { euler: Spectrum; centrifugal: Spectrum; coriolis: Spectrum; stiffness: Spectrum; total: Spectrum }
export interface Analysis {
  sim: SimResult;
  /** Per mode; null for modes not asked for. */
  forces: ({ euler: Float64Array; centrifugal: Float64Array; coriolis: Float64Array; stiffness: Float64Array } | null)[];
  spectra: (ModeSpectra | null)[];
  /** Envelope |analytic signal| of each asked-for mode's Coriolis response (see analyze()). */
  envelope: (Float64Array | null)[];
}
export interface SweepModeColumns {
  euler: Float64Array; centrifugal: Float64Array; coriolis: Float64Array;
  effective_freq_hz: Float64Array; beat_period_s: Float64Array; peak_abs_q: Float64Array; stable: boolean[];
}
export interface SweepResult { param: SweepParam; values: Float64Array; modes: SweepModeColumns[] }
export interface IcMapResult {
  mode: number; n_q: number; n_qdot: number; q0: Float64Array; qdot0: Float64Array;
  /** Row-major: row j = qdot0[j], column i = q0[i]. */
  coriolis_percent: Float64Array; min_percent: number; max_percent: number;
  fraction_above_60: number; attribution: "forced" | "carried";
}
/** Shell FE input (paper §3.1); every field optional (missing = the default synthetic wing). */
export interface FemInput {
  planform_mm?: [number, number][]; planform_note?: string; camber?: number;
  clamp?: "root" | "free" | { strip: { x_mm: number } };
  material?: { thickness_m: number; e_pa: number; rho_kg_m3: number; nu: number };
  n_modes?: number; mesh_size_mm?: number;
}
/** Shell FE modes: SI summary, Eq. 13 inputs (`modes`, strain at P) and the mesh as flat typed arrays. */
export interface FeModesResult {
  planform_note: string; freq_hz: Float64Array; a: [number, number][]; b: [number, number][];
  mass_kg: number; centre_of_mass_m: [number, number, number]; kinds: string[];
  residuals: Float64Array; mass_orthonormality_error: number; n_dofs: number;
  n_nodes: number; n_triangles: number; n_modes: number; mesh_size_mm: number;
  strain_point_mm: [number, number]; modes: Mode[];
  /** x, y, z per node, m. */ nodes: Float64Array;
  /** Three node indices per triangle. */ triangles: Uint32Array;
  /** Mode-major: shapes[k·n_nodes + i], kg^-½. */ shapes: Float64Array;
  /** strain_nodes[(k·n_nodes + i)·3 + c], c = ε_x, ε_y, γ_xy per unit q. */ strain_nodes: Float64Array;
}
export interface Limits {
  max_duration_s: number; max_sample_rate_hz: number; max_samples: number;
  web_max_sample_values: number; max_sweep_points: number; max_ic_cells: number; max_modes: number;
}
"#;

/// Installs the panic hook (runs when the module is instantiated). Designed never to fire.
#[wasm_bindgen(start)]
pub fn start() {
    console_error_panic_hook::set_once();
}

fn err(e: WingbeatError) -> JsError {
    JsError::new(&e.to_string())
}

/// Deserialises a JS value, naming the path of the first bad field in the error.
///
/// The value goes through `JSON.stringify` and serde_json — the same parser as the CLI's config
/// files — rather than straight through serde-wasm-bindgen, whose struct deserialiser skips
/// unknown keys and so would defeat `deny_unknown_fields`. NaN and ±Infinity become `null`
/// there and are reported as such.
fn from_js<T: DeserializeOwned + Default>(v: JsValue, what: &str) -> Result<T, JsError> {
    if v.is_undefined() || v.is_null() {
        return Ok(T::default());
    }
    parse_js(v, what)
}

fn parse_js<T: DeserializeOwned>(v: JsValue, what: &str) -> Result<T, JsError> {
    let text: String = js_sys::JSON::stringify(&v)
        .map_err(|_| {
            JsError::new(&format!(
                "invalid value for `{what}`: not JSON-serialisable (cyclic, BigInt or a throwing getter)"
            ))
        })?
        .into();
    let mut de = serde_json::Deserializer::from_str(&text);
    serde_path_to_error::deserialize(&mut de).map_err(|e| {
        let path = e.path().to_string();
        let place = if path == "." || path.is_empty() {
            what.to_string()
        } else {
            format!("{what}.{path}")
        };
        let inner = e.inner().to_string();
        let hint = if inner.contains("null") {
            " (NaN, ±Infinity and null are not numbers here)"
        } else {
            ""
        };
        JsError::new(&format!("invalid value for `{place}`: {inner}{hint}"))
    })
}

fn config_from(v: JsValue) -> Result<SimConfig, JsError> {
    let cfg: SimConfig = from_js(v, "config")?;
    cfg.validate().map_err(err)?;
    check_web_caps(&cfg).map_err(err)?;
    Ok(cfg)
}

fn to_js<T: Serialize + ?Sized>(v: &T) -> Result<JsValue, JsError> {
    v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| JsError::new(&format!("could not build the JS result: {e}")))
}

fn set(o: &Object, key: &str, v: &JsValue) -> Result<(), JsError> {
    Reflect::set(o, &JsValue::from_str(key), v)
        .map(|_| ())
        .map_err(|_| JsError::new(&format!("could not set `{key}` on the JS result")))
}

fn f64a(v: &[f64]) -> JsValue {
    Float64Array::from(v).into()
}

fn obj_with(pairs: &[(&str, &[f64])]) -> Result<Object, JsError> {
    let o = Object::new();
    for (k, v) in pairs {
        set(&o, k, &f64a(v))?;
    }
    Ok(o)
}

fn strain_js(s: &StrainSeries) -> Result<JsValue, JsError> {
    let o = obj_with(&[
        ("eps_x", &s.eps_x),
        ("eps_y", &s.eps_y),
        ("gamma_xy", &s.gamma_xy),
    ])?;
    set(&o, "point", &JsValue::from_str(&s.point))?;
    Ok(o.into())
}

#[derive(Serialize)]
struct ModeMeta<'a> {
    name: &'a str,
    freq_hz: f64,
    zeta: f64,
    contribution_percent: &'a crate::analysis::contribution::Contributions,
    floquet: &'a crate::floquet::FloquetResult,
    accuracy: &'a crate::simulate::Accuracy,
}

fn sim_js(r: &SimResult, sample_rate_hz: f64) -> Result<JsValue, JsError> {
    let o = Object::new();
    set(&o, "n", &JsValue::from_f64(r.t.len() as f64))?;
    set(&o, "sample_rate_hz", &JsValue::from_f64(sample_rate_hz))?;
    set(&o, "flap_freq_hz", &JsValue::from_f64(r.flap_freq_hz))?;
    set(&o, "t", &f64a(&r.t))?;
    let modes = Array::new();
    for m in &r.modes {
        let meta = to_js(&ModeMeta {
            name: &m.name,
            freq_hz: m.freq_hz,
            zeta: m.zeta,
            contribution_percent: &m.contribution_percent,
            floquet: &m.floquet,
            accuracy: &m.accuracy,
        })?;
        let mo: Object = meta.unchecked_into();
        let q = obj_with(&[
            ("euler", &m.q.euler),
            ("centrifugal", &m.q.centrifugal),
            ("coriolis", &m.q.coriolis),
            ("free", &m.q.free),
            ("total", &m.q.total),
        ])?;
        set(&mo, "q", &q)?;
        set(&mo, "qdot_total", &f64a(&m.qdot_total))?;
        modes.push(&mo);
    }
    set(&o, "modes", &modes)?;
    let strain = match &r.strain {
        Some(s) => strain_js(s)?,
        None => JsValue::NULL,
    };
    set(&o, "strain", &strain)?;
    let points = Array::new();
    for s in &r.strain_points {
        points.push(&strain_js(s)?);
    }
    set(&o, "strain_points", &points)?;
    set(&o, "warnings", &to_js(&r.warnings)?)?;
    Ok(o.into())
}

fn spectrum_js(s: &Spectrum) -> Result<JsValue, JsError> {
    let o = Object::new();
    set(&o, "freq_hz", &f64a(&s.freq_hz))?;
    set(&o, "psd", &f64a(&s.psd))?;
    set(&o, "peaks", &to_js(&s.peaks)?)?;
    Ok(o.into())
}

/// The crate version.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

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
    }
    to_js(&Limits {
        max_duration_s: crate::config::MAX_DURATION_S,
        max_sample_rate_hz: crate::config::MAX_SAMPLE_RATE_HZ,
        max_samples: crate::config::MAX_SAMPLES,
        web_max_sample_values: helpers::WEB_MAX_SAMPLE_VALUES,
        max_sweep_points: crate::analysis::sweep::MAX_POINTS,
        max_ic_cells: crate::analysis::ic_map::MAX_CELLS,
        max_modes: crate::model::MAX_MODES,
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
    Ok(obj_with(&[
        ("euler", &f.euler),
        ("centrifugal", &f.centrifugal),
        ("coriolis", &f.coriolis),
        ("softening", &f.softening),
    ])?
    .into())
}

/// The Eq. 13 force terms of every mode and the softening α̇²cos²β + β̇² (rad²/s²) on the
/// output time grid (paper Fig. 4).
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

/// Welch PSD of any series (one-sided, Hann window), with peaks labelled in multiples of
/// `flap_hz` when given.
#[wasm_bindgen(unchecked_return_type = "Spectrum")]
pub fn psd(
    series: &[f64],
    sample_rate_hz: f64,
    #[wasm_bindgen(unchecked_param_type = "WelchOptions | undefined")] opts: JsValue,
    flap_hz: Option<f64>,
) -> Result<JsValue, JsError> {
    let opts: WelchOptions = from_js(opts, "psd")?;
    check_series("psd.series", series).map_err(err)?;
    if let Some(f) = flap_hz {
        crate::error::check_positive("psd.flap_hz", f, 1e9, "Hz").map_err(err)?;
    }
    spectrum_js(&welch(series, sample_rate_hz, &opts, flap_hz).map_err(err)?)
}

/// Envelope |analytic signal| of a series (FFT Hilbert transform), used for the beat.
#[wasm_bindgen]
pub fn envelope(series: &[f64]) -> Result<Float64Array, JsError> {
    check_series("envelope.series", series).map_err(err)?;
    Ok(Float64Array::from(&beat::envelope(series)[..]))
}

/// Min/max decimation for plotting: returns `{ index: Float64Array, value: Float64Array }`.
#[wasm_bindgen(js_name = decimateMinMax)]
pub fn decimate_min_max(series: &[f64], buckets: usize) -> Result<JsValue, JsError> {
    check_series("decimate.series", series).map_err(err)?;
    let (idx, v) = helpers::decimate_minmax(series, buckets.min(1 << 20));
    let idx: Vec<f64> = idx.into_iter().map(|i| i as f64).collect();
    Ok(obj_with(&[("index", &idx), ("value", &v)])?.into())
}

struct Computed {
    sim: SimResult,
    /// Force terms of the modes asked for (None for the others).
    forces: Vec<Option<ForceSeries>>,
    /// The stiffness term (α̇²cos²β + β̇²)·q_k of the same modes.
    stiffness: Vec<Option<Vec<f64>>>,
}

/// Force terms of the modes in `which` (all when None), on the output grid. Same arithmetic as
/// the core's `force_series` (kinematic state once per sample, `model::coefficients` per mode),
/// restricted to the modes asked for so that the live view pays for one mode only.
fn forces_for(cfg: &SimConfig, which: Option<usize>) -> Vec<Option<ForceSeries>> {
    let kin = cfg.kinematics.compile();
    let n = cfg.n_samples();
    let dt = 1.0 / cfg.sample_rate_hz;
    let states: Vec<_> = (0..n).map(|i| kin.state(i as f64 * dt)).collect();
    cfg.modes
        .iter()
        .enumerate()
        .map(|(k, m)| {
            if which.is_some_and(|w| w != k) {
                return None;
            }
            let mut fs = ForceSeries {
                euler: Vec::with_capacity(n),
                centrifugal: Vec::with_capacity(n),
                coriolis: Vec::with_capacity(n),
                softening: Vec::with_capacity(n),
            };
            for s in &states {
                let c = crate::model::coefficients(m, s);
                fs.euler.push(c.euler);
                fs.centrifugal.push(c.centrifugal);
                fs.coriolis.push(c.coriolis);
                fs.softening.push(crate::model::softening(s));
            }
            Some(fs)
        })
        .collect()
}

fn compute(cfg: &SimConfig, which: Option<usize>) -> Result<Computed, JsError> {
    let sim = core_simulate(cfg).map_err(err)?;
    let forces = forces_for(cfg, which);
    let stiffness = forces
        .iter()
        .zip(&sim.modes)
        .map(|(f, m)| f.as_ref().map(|f| stiffness_term(&f.softening, &m.q.total)))
        .collect();
    Ok(Computed {
        sim,
        forces,
        stiffness,
    })
}

fn check_mode(cfg: &SimConfig, mode: Option<usize>) -> Result<(), JsError> {
    match mode {
        Some(k) if k >= cfg.modes.len() => Err(err(WingbeatError::invalid(
            "mode",
            k,
            format!("a mode index in [0, {}]", cfg.modes.len().saturating_sub(1)),
        ))),
        _ => Ok(()),
    }
}

fn spectra_js(c: &Computed, fs: f64, opts: &WelchOptions) -> Result<Array, JsError> {
    let flap = Some(c.sim.flap_freq_hz);
    let out = Array::new();
    for ((f, s), m) in c.forces.iter().zip(&c.stiffness).zip(&c.sim.modes) {
        let (Some(f), Some(s)) = (f, s) else {
            out.push(&JsValue::NULL);
            continue;
        };
        let o = Object::new();
        for (k, x) in [
            ("euler", &f.euler),
            ("centrifugal", &f.centrifugal),
            ("coriolis", &f.coriolis),
            ("stiffness", s),
            ("total", &m.q.total),
        ] {
            set(
                &o,
                k,
                &spectrum_js(&welch(x, fs, opts, flap).map_err(err)?)?,
            )?;
        }
        out.push(&o);
    }
    Ok(out)
}

/// PSDs, per mode, of the Euler, centrifugal and Coriolis forces, of the stiffness term
/// (α̇²cos²β + β̇²)·q_k and of the total response (see `ModeSpectra`). With `mode` given, only
/// that mode's entry is computed (the others are `null`).
#[wasm_bindgen(unchecked_return_type = "(ModeSpectra | null)[]")]
pub fn spectra(
    #[wasm_bindgen(unchecked_param_type = "SimConfig")] cfg: JsValue,
    #[wasm_bindgen(unchecked_param_type = "WelchOptions | undefined")] opts: JsValue,
    mode: Option<usize>,
) -> Result<JsValue, JsError> {
    let cfg = config_from(cfg)?;
    let opts: WelchOptions = from_js(opts, "psd")?;
    opts.validate().map_err(err)?;
    check_mode(&cfg, mode)?;
    Ok(spectra_js(&compute(&cfg, mode)?, cfg.sample_rate_hz, &opts)?.into())
}

/// Everything the lab's live panels need from one config, in one call: the simulation (all
/// modes), and for the modes asked for (`mode`, or all when omitted) the force terms, their
/// spectra and the envelope of the Coriolis response (`null` entries for the other modes).
///
/// The envelope is taken over the first `helpers::smooth_len(n)` samples (the largest
/// 2^a·3^b·5^c ≤ n: FFT lengths with large prime factors are several times slower) and the
/// remaining samples (under 10 % for n ≥ 100; one for the paper case's 20001) repeat its last
/// value; `envelope()` gives the whole-series one.
#[wasm_bindgen(unchecked_return_type = "Analysis")]
pub fn analyze(
    #[wasm_bindgen(unchecked_param_type = "SimConfig")] cfg: JsValue,
    #[wasm_bindgen(unchecked_param_type = "WelchOptions | undefined")] opts: JsValue,
    mode: Option<usize>,
) -> Result<JsValue, JsError> {
    let cfg = config_from(cfg)?;
    let opts: WelchOptions = from_js(opts, "psd")?;
    opts.validate().map_err(err)?;
    check_mode(&cfg, mode)?;
    let c = compute(&cfg, mode)?;
    let o = Object::new();
    set(&o, "sim", &sim_js(&c.sim, cfg.sample_rate_hz)?)?;
    let forces = Array::new();
    for (f, s) in c.forces.iter().zip(&c.stiffness) {
        match (f, s) {
            (Some(f), Some(s)) => forces.push(
                &obj_with(&[
                    ("euler", &f.euler),
                    ("centrifugal", &f.centrifugal),
                    ("coriolis", &f.coriolis),
                    ("stiffness", s),
                ])?
                .into(),
            ),
            _ => forces.push(&JsValue::NULL),
        };
    }
    set(&o, "forces", &forces)?;
    set(
        &o,
        "spectra",
        &spectra_js(&c, cfg.sample_rate_hz, &opts)?.into(),
    )?;
    let env = Array::new();
    for (k, m) in c.sim.modes.iter().enumerate() {
        if mode.is_some_and(|w| w != k) {
            env.push(&JsValue::NULL);
        } else {
            env.push(&f64a(&helpers::fast_envelope(&m.q.coriolis)));
        }
    }
    set(&o, "envelope", &env)?;
    Ok(o.into())
}

/// A parameter sweep (paper Fig. 6 for `gamma0`). `progress(done, total)` is called after each
/// point when given; an exception it throws is ignored.
#[wasm_bindgen(unchecked_return_type = "SweepResult")]
pub fn sweep(
    #[wasm_bindgen(unchecked_param_type = "SimConfig")] cfg: JsValue,
    #[wasm_bindgen(unchecked_param_type = "SweepOptions")] opts: JsValue,
    progress: Option<Function>,
) -> Result<JsValue, JsError> {
    let cfg = config_from(cfg)?;
    if opts.is_undefined() || opts.is_null() {
        return Err(JsError::new(
            "invalid value for `sweep`: missing (allowed: { param, from, to, points })",
        ));
    }
    let opts: SweepOptions = parse_js(opts, "sweep")?;
    let s = core_sweep(&cfg, &opts, |i, n| {
        if let Some(f) = &progress {
            let _ = f.call2(
                &JsValue::NULL,
                &JsValue::from_f64(i as f64),
                &JsValue::from_f64(n as f64),
            );
        }
    })
    .map_err(err)?;
    let o = Object::new();
    set(&o, "param", &to_js(&s.param)?)?;
    let values: Vec<f64> = s.points.iter().map(|p| p.value).collect();
    set(&o, "values", &f64a(&values))?;
    let modes = Array::new();
    let n_modes = s.points.first().map_or(0, |p| p.modes.len());
    for k in 0..n_modes {
        let col = |f: &dyn Fn(&crate::analysis::sweep::SweepModePoint) -> f64| -> Vec<f64> {
            s.points.iter().map(|p| f(&p.modes[k])).collect()
        };
        let mo = obj_with(&[
            ("euler", &col(&|m| m.contribution_percent.euler)),
            ("centrifugal", &col(&|m| m.contribution_percent.centrifugal)),
            ("coriolis", &col(&|m| m.contribution_percent.coriolis)),
            ("effective_freq_hz", &col(&|m| m.effective_freq_hz)),
            ("beat_period_s", &col(&|m| opt_or_nan(m.beat_period_s))),
            ("peak_abs_q", &col(&|m| m.peak_abs_q)),
        ])?;
        let stable: Vec<bool> = s.points.iter().map(|p| p.modes[k].stable).collect();
        set(&mo, "stable", &to_js(&stable)?)?;
        modes.push(&mo);
    }
    set(&o, "modes", &modes)?;
    Ok(o.into())
}

/// The initial-condition map (paper Fig. 7): Coriolis share over a grid of (q0, q̇0).
#[wasm_bindgen(js_name = icMap, unchecked_return_type = "IcMapResult")]
pub fn ic_map(
    #[wasm_bindgen(unchecked_param_type = "SimConfig")] cfg: JsValue,
    #[wasm_bindgen(unchecked_param_type = "IcMapOptions | undefined")] opts: JsValue,
) -> Result<JsValue, JsError> {
    let cfg = config_from(cfg)?;
    let opts: IcMapOptions = from_js(opts, "ic_map")?;
    let m = core_ic_map(&cfg, &opts).map_err(err)?;
    let o = obj_with(&[
        ("q0", &m.q0),
        ("qdot0", &m.qdot0),
        ("coriolis_percent", &m.coriolis_percent),
    ])?;
    for (k, v) in [
        ("mode", m.mode as f64),
        ("n_q", m.q0.len() as f64),
        ("n_qdot", m.qdot0.len() as f64),
        ("min_percent", m.min_percent),
        ("max_percent", m.max_percent),
        ("fraction_above_60", m.fraction_above_60),
    ] {
        set(&o, k, &JsValue::from_f64(v))?;
    }
    set(&o, "attribution", &to_js(&m.attribution)?)?;
    Ok(o.into())
}

/// Roll, pitch and yaw (rad) of the config's kinematics at each time in `times` (s),
/// interleaved `[α(t0), β(t0), γ(t0), α(t1), …]` (paper §2.1). The 3-D view uses it to pose
/// the wing at the same instants as the simulated responses.
#[wasm_bindgen(js_name = anglesAt)]
pub fn angles_at(
    #[wasm_bindgen(unchecked_param_type = "SimConfig")] cfg: JsValue,
    times: &[f64],
) -> Result<Float64Array, JsError> {
    let cfg = config_from(cfg)?;
    check_series("anglesAt.times", times).map_err(err)?;
    let kin = cfg.kinematics.compile();
    let mut out = Vec::with_capacity(3 * times.len());
    for &t in times {
        let s = kin.state(t);
        out.extend_from_slice(&[s.alpha, s.beta, s.gamma]);
    }
    Ok(Float64Array::from(&out[..]))
}

/// Shell FE modes of a wing (paper §3.1): mesh, assemble, solve `K φ = ω² M φ`, then the
/// modal model's inputs — frequencies, SI a_k and b_k, and `modes` ready for a `SimConfig`
/// (damping ratio `zeta`, modal strains at P = `strain_point_mm`). The mesh, shapes and nodal
/// strains come back as flat typed arrays (see `FeModesResult`). Errors name the field
/// (outline, material, camber, mesh size and its node cap). Seconds of work at fine meshes:
/// call it from a Web Worker.
#[wasm_bindgen(js_name = feModes, unchecked_return_type = "FeModesResult")]
pub fn fe_modes(
    #[wasm_bindgen(unchecked_param_type = "FemInput | undefined")] input: JsValue,
    zeta: Option<f64>,
) -> Result<JsValue, JsError> {
    let input: crate::fem::FemInput = from_js(input, "fem")?;
    let zeta = zeta.unwrap_or(0.0);
    crate::error::check_range("zeta", zeta, 0.0, 10.0, "").map_err(err)?;
    let fe = crate::fem::compute_modes(&input).map_err(err)?;
    let (px, py) = crate::fem::STRAIN_POINT_P_MM;
    let modes = fe
        .model_modes(zeta, &[("P".to_string(), px, py)], "strain point")
        .map_err(err)?;
    #[derive(Serialize)]
    struct Meta<'a> {
        planform_note: &'a str,
        a: &'a [[f64; 2]],
        b: &'a [[f64; 2]],
        mass_kg: f64,
        centre_of_mass_m: [f64; 3],
        kinds: &'a [String],
        mass_orthonormality_error: f64,
        n_dofs: usize,
        n_nodes: usize,
        n_triangles: usize,
        n_modes: usize,
        mesh_size_mm: f64,
        strain_point_mm: [f64; 2],
        modes: &'a [crate::model::Mode],
    }
    let o: Object = to_js(&Meta {
        planform_note: &fe.planform_note,
        a: &fe.a,
        b: &fe.b,
        mass_kg: fe.mass_kg,
        centre_of_mass_m: fe.centre_of_mass_m,
        kinds: &fe.kinds,
        mass_orthonormality_error: fe.mass_orthonormality_error,
        n_dofs: fe.n_dofs,
        n_nodes: fe.nodes.len(),
        n_triangles: fe.triangles.len(),
        n_modes: fe.freq_hz.len(),
        mesh_size_mm: input.mesh_size_mm,
        strain_point_mm: [px, py],
        modes: &modes,
    })?
    .unchecked_into();
    set(&o, "freq_hz", &f64a(&fe.freq_hz))?;
    set(&o, "residuals", &f64a(&fe.residuals))?;
    let nodes: Vec<f64> = fe.nodes.iter().flatten().copied().collect();
    set(&o, "nodes", &f64a(&nodes))?;
    let tris: Vec<u32> = fe
        .triangles
        .iter()
        .flatten()
        .map(|&i| u32::try_from(i).unwrap_or(u32::MAX))
        .collect();
    set(&o, "triangles", &Uint32Array::from(&tris[..]).into())?;
    let shapes: Vec<f64> = fe.shapes.iter().flatten().copied().collect();
    set(&o, "shapes", &f64a(&shapes))?;
    let strains: Vec<f64> = fe
        .strain_nodes
        .iter()
        .flatten()
        .flatten()
        .copied()
        .collect();
    set(&o, "strain_nodes", &f64a(&strains))?;
    Ok(o.into())
}

/// The paper's claims next to what wingbeat computes, each with a verdict (a JS object).
#[wasm_bindgen]
pub fn reproduce() -> Result<JsValue, JsError> {
    to_js(&crate::reproduce::reproduce().map_err(err)?)
}

/// The same report as plain text.
#[wasm_bindgen(js_name = reproduceText)]
pub fn reproduce_text() -> Result<String, JsError> {
    Ok(crate::reproduce::reproduce().map_err(err)?.to_text())
}
