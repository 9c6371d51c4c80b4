//! The analyses of the wasm API: spectra (per series, per mode, and everything the live
//! panels need in one `analyze` call), envelopes, sweeps, the
//! initial-condition map and the resonance map.

use super::helpers::{self, opt_or_nan};
use super::marshal::{
    config_from, err, f64a, from_js, function_arg, number_arg, obj_with, opt_number_arg,
    progress_fn, required_js, series_from_js, set, sim_js, spectrum_js, to_js,
};
use crate::analysis::angles::angles_on;
use crate::analysis::beat;
use crate::analysis::ic_map::{ic_map as core_ic_map, IcMapOptions};
use crate::analysis::psd::{welch, WelchOptions};
use crate::analysis::resonance::{resonance_map as core_resonance_map, ResonanceOptions};
use crate::analysis::spectra::mode_spectra;
use crate::analysis::strain::peak_abs;
use crate::analysis::sweep::{sweep as core_sweep, SweepOptions};
use crate::config::SimConfig;
use crate::error::WingbeatError;
use crate::model::stiffness_force;
use crate::simulate::SimResult;
use crate::simulate::{sample_forces, simulate as core_simulate, ForceSeries, ModeSelection};
use js_sys::{Array, Float64Array, Function, Object, Uint32Array, Uint8Array};
use wasm_bindgen::prelude::*;

/// Welch PSD of any series (one-sided, Hann window), with peaks labelled in multiples of
/// `flap_hz` when given.
#[wasm_bindgen(unchecked_return_type = "Spectrum")]
pub fn psd(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] series: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] sample_rate_hz: JsValue,
    #[wasm_bindgen(unchecked_param_type = "WelchOptions | undefined")] opts: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number | null | undefined")] flap_hz: JsValue,
) -> Result<JsValue, JsError> {
    let sample_rate_hz = number_arg(
        &sample_rate_hz,
        "psd.sample_rate_hz",
        "a positive number, Hz",
    )?;
    let flap_hz = opt_number_arg(
        &flap_hz,
        "psd.flap_hz",
        "a positive number, Hz, or undefined",
    )?;
    let opts: WelchOptions = from_js(opts, "psd")?;
    let series = series_from_js(&series, "psd.series", crate::config::MAX_SAMPLES)?;
    if let Some(f) = flap_hz {
        crate::error::check_positive("psd.flap_hz", f, 1e9, "Hz").map_err(err)?;
    }
    spectrum_js(&welch(&series, sample_rate_hz, &opts, flap_hz).map_err(err)?)
}

/// Envelope |analytic signal| of a series (FFT Hilbert transform), used for the beat.
#[wasm_bindgen]
pub fn envelope(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] series: JsValue,
) -> Result<Float64Array, JsError> {
    let series = series_from_js(&series, "envelope.series", crate::config::MAX_SAMPLES)?;
    let e = beat::checked_envelope(&series, "envelope.series").map_err(err)?;
    Ok(Float64Array::from(&e[..]))
}

/// What `spectra` and `analyze` compute from one config.
struct Computed {
    sim: SimResult,
    /// Force terms and the stiffness coefficient of the modes asked for (None for the others).
    forces: Vec<Option<ForceSeries>>,
}

fn compute(cfg: &SimConfig, which: Option<usize>) -> Result<Computed, JsError> {
    let sim = core_simulate(cfg).map_err(err)?;
    let forces = sample_forces(cfg, ModeSelection::from_option(which)).map_err(err)?;
    Ok(Computed { sim, forces })
}

/// The optional mode index a caller passed (a JS number): an integer in [0, modes − 1], never
/// coerced.
fn check_mode(cfg: &SimConfig, mode: &JsValue) -> Result<Option<usize>, JsError> {
    let hi = cfg.modes.len().saturating_sub(1);
    let mode = opt_number_arg(
        mode,
        "mode",
        &format!("an integer mode index in [0, {hi}], or undefined"),
    )?;
    mode.map(|k| {
        helpers::check_int("mode", k, 0, cfg.modes.len().saturating_sub(1)).map_err(|_| {
            err(WingbeatError::invalid(
                "mode",
                k,
                format!(
                    "an integer mode index in [0, {}]",
                    cfg.modes.len().saturating_sub(1)
                ),
            ))
        })
    })
    .transpose()
}

fn spectra_js(c: &Computed, fs: f64, opts: &WelchOptions) -> Result<Array, JsError> {
    let flap = Some(c.sim.flap_freq_hz);
    let out = Array::new();
    for (f, m) in c.forces.iter().zip(&c.sim.modes) {
        let Some(f) = f else {
            out.push(&JsValue::NULL);
            continue;
        };
        let s = mode_spectra(f, &m.q.total, fs, opts, flap).map_err(err)?;
        let o = Object::new();
        for (k, x) in [
            ("euler", &s.euler),
            ("centrifugal", &s.centrifugal),
            ("coriolis", &s.coriolis),
            ("stiffness_force", &s.stiffness_force),
            ("total", &s.total),
        ] {
            set(&o, k, &spectrum_js(x)?)?;
        }
        if let Some(a) = &s.aerodynamic {
            set(&o, "aerodynamic", &spectrum_js(a)?)?;
        }
        out.push(&o);
    }
    Ok(out)
}

/// The validated inputs of `spectra` and `analyze`: the config, the Welch options (`psd`) and
/// the optional mode index (in range).
fn live_inputs(
    cfg: JsValue,
    opts: JsValue,
    mode: JsValue,
) -> Result<(SimConfig, WelchOptions, Option<usize>), JsError> {
    let cfg = config_from(cfg)?;
    let opts: WelchOptions = from_js(opts, "psd")?;
    opts.validate().map_err(err)?;
    let mode = check_mode(&cfg, &mode)?;
    Ok((cfg, opts, mode))
}

/// PSDs, per mode, of the Euler, centrifugal and Coriolis forces, of the stiffness force
/// S(t)·q_k (S = α̇²cos²β + β̇², the stiffness coefficient) and of the total response (see
/// `ModeSpectra`; the core's `analysis::spectra::mode_spectra`, as the CLI's `psd`). With `mode`
/// given, only that mode's entry is computed (the others are `null`).
#[wasm_bindgen(unchecked_return_type = "(ModeSpectra | null)[]")]
pub fn spectra(
    #[wasm_bindgen(unchecked_param_type = "SimConfig")] cfg: JsValue,
    #[wasm_bindgen(unchecked_param_type = "WelchOptions | undefined")] opts: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number | null | undefined")] mode: JsValue,
) -> Result<JsValue, JsError> {
    let (cfg, opts, mode) = live_inputs(cfg, opts, mode)?;
    Ok(spectra_js(&compute(&cfg, mode)?, cfg.sample_rate_hz, &opts)?.into())
}

/// Everything the lab's live panels need from one config, in one call: the simulation (all
/// modes), and for the modes asked for (`mode`, or all when omitted) the force terms and the
/// stiffness force S(t)·q_k (`forces`), their spectra and the envelope of the Coriolis
/// response (`null` entries for the other modes), and the angles α, β, γ (rad) at `sim.t`
/// (`angles`), so a view can pose the wing at every sample without calling `anglesAt`.
///
/// The envelope is taken over the first `helpers::smooth_len(n)` samples (the largest
/// 2^a·3^b·5^c ≤ n: FFT lengths with large prime factors are several times slower) and the
/// remaining samples (under 10 % for n ≥ 100; one for the paper case's 20001) repeat its last
/// value; `envelope()` gives the whole-series one.
#[wasm_bindgen(unchecked_return_type = "Analysis")]
pub fn analyze(
    #[wasm_bindgen(unchecked_param_type = "SimConfig")] cfg: JsValue,
    #[wasm_bindgen(unchecked_param_type = "WelchOptions | undefined")] opts: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number | null | undefined")] mode: JsValue,
) -> Result<JsValue, JsError> {
    let (cfg, opts, mode) = live_inputs(cfg, opts, mode)?;
    let c = compute(&cfg, mode)?;
    let o = Object::new();
    set(&o, "sim", &sim_js(&c.sim, cfg.sample_rate_hz)?)?;
    let forces = Array::new();
    for (f, m) in c.forces.iter().zip(&c.sim.modes) {
        match f {
            Some(f) => {
                let fo = obj_with(&[
                    ("euler", &f.euler),
                    ("centrifugal", &f.centrifugal),
                    ("coriolis", &f.coriolis),
                    (
                        "stiffness_force",
                        &stiffness_force(&f.stiffness_coefficient, &m.q.total),
                    ),
                ])?;
                if !f.aerodynamic.is_empty() {
                    set(&fo, "aerodynamic", &f64a(&f.aerodynamic))?;
                }
                forces.push(&fo.into())
            }
            None => forces.push(&JsValue::NULL),
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
    let a = angles_on(&cfg.kinematics.compile(), &c.sim.t);
    let angles = obj_with(&[("alpha", &a.alpha), ("beta", &a.beta), ("gamma", &a.gamma)])?;
    set(&o, "angles", &angles)?;
    set(&o, "peaks", &peaks_js(&c.sim)?)?;
    let idx = extreme_samples(
        &c.sim
            .modes
            .iter()
            .map(|m| &m.q.total[..])
            .collect::<Vec<_>>(),
    );
    set(&o, "extreme_samples", &Uint32Array::from(&idx[..]).into())?;
    Ok(o.into())
}

/// `Analysis.peaks`: the run's largest |q| per mode and response, and the largest |strain| per
/// component at the strain point (`null` without strains), so the panels need not scan every
/// sample on the page's thread.
fn peaks_js(sim: &SimResult) -> Result<JsValue, JsError> {
    let q = Array::new();
    for m in &sim.modes {
        let o = Object::new();
        for (k, y) in [
            ("euler", &m.q.euler),
            ("centrifugal", &m.q.centrifugal),
            ("coriolis", &m.q.coriolis),
            ("total", &m.q.total),
        ] {
            set(&o, k, &JsValue::from_f64(peak_abs(y)))?;
        }
        q.push(&o);
    }
    let o = Object::new();
    set(&o, "q", &q)?;
    let strain = match &sim.strain {
        Some(s) => {
            let so = Object::new();
            for (k, y) in [
                ("eps_x", &s.eps_x),
                ("eps_y", &s.eps_y),
                ("gamma_xy", &s.gamma_xy),
            ] {
                set(&so, k, &JsValue::from_f64(peak_abs(y)))?;
            }
            so.into()
        }
        None => JsValue::NULL,
    };
    set(&o, "strain", &strain)?;
    Ok(o.into())
}

/// Evenly spaced samples taken (besides each mode's extremes) with three or more modes.
pub(crate) const EXTREME_STRIDE_SAMPLES: usize = 1000;

/// Sample indices (increasing, distinct) of the modal trajectory q(t) = (q_1, …, q_m)(t) at
/// which a linear function of q — or a norm of one — reaches its run-wide maximum: for one
/// mode q's minimum and maximum, for two the vertices of the trajectory's convex hull (exact
/// for every such function), for three or more at most `EXTREME_STRIDE_SAMPLES` evenly spaced
/// samples plus each mode's minimum and maximum (a display bound that the run may exceed).
/// NaN samples are skipped.
pub(crate) fn extreme_samples(qs: &[&[f64]]) -> Vec<u32> {
    let n = qs.iter().map(|q| q.len()).min().unwrap_or(0);
    if n == 0 {
        return Vec::new();
    }
    let mut out: Vec<usize> = Vec::new();
    let min_max = |q: &[f64], out: &mut Vec<usize>| {
        let (mut lo, mut hi) = (None::<usize>, None::<usize>);
        for (i, &v) in q[..n].iter().enumerate() {
            if v.is_nan() {
                continue;
            }
            if lo.is_none_or(|j| v < q[j]) {
                lo = Some(i);
            }
            if hi.is_none_or(|j| v > q[j]) {
                hi = Some(i);
            }
        }
        out.extend(lo);
        out.extend(hi);
    };
    match qs.len() {
        1 => min_max(qs[0], &mut out),
        2 => out = hull2(&qs[0][..n], &qs[1][..n]),
        _ => {
            let stride = n.div_ceil(EXTREME_STRIDE_SAMPLES).max(1);
            out.extend((0..n).step_by(stride));
            for q in qs {
                min_max(q, &mut out);
            }
        }
    }
    out.sort_unstable();
    out.dedup();
    out.into_iter().map(|i| i as u32).collect()
}

/// Vertex indices of the convex hull of the points (xs[i], ys[i]) (monotone chain; NaN points
/// skipped). Points strictly inside the octagon of the 8 directional extremes are dropped first
/// (Akl–Toussaint), so a long trajectory sorts only its outer points.
fn hull2(xs: &[f64], ys: &[f64]) -> Vec<usize> {
    let ok: Vec<usize> = (0..xs.len())
        .filter(|&i| xs[i].is_finite() && ys[i].is_finite())
        .collect();
    let cross = |o: usize, a: usize, b: usize| {
        (xs[a] - xs[o]) * (ys[b] - ys[o]) - (ys[a] - ys[o]) * (xs[b] - xs[o])
    };
    let mut cand = ok;
    if cand.len() > 64 {
        let mut ext: Vec<usize> = Vec::with_capacity(8);
        for d in 0..8 {
            let ang = std::f64::consts::PI * d as f64 / 4.0;
            let (c, s) = (ang.cos(), ang.sin());
            let mut best = cand[0];
            let mut bv = f64::NEG_INFINITY;
            for &i in &cand {
                let v = c * xs[i] + s * ys[i];
                if v > bv {
                    bv = v;
                    best = i;
                }
            }
            if ext.last() != Some(&best) && ext.first() != Some(&best) {
                ext.push(best);
            }
        }
        if ext.len() >= 3 {
            let m = ext.len();
            cand.retain(|&i| {
                (0..m).any(|j| {
                    let (a, b) = (ext[j], ext[(j + 1) % m]);
                    cross(a, b, i) <= 0.0
                })
            });
        }
    }
    cand.sort_by(|&a, &b| xs[a].total_cmp(&xs[b]).then(ys[a].total_cmp(&ys[b])));
    if cand.len() < 3 {
        return cand;
    }
    let mut lower: Vec<usize> = Vec::new();
    for &i in &cand {
        while lower.len() >= 2 && cross(lower[lower.len() - 2], lower[lower.len() - 1], i) <= 0.0 {
            lower.pop();
        }
        lower.push(i);
    }
    let mut upper: Vec<usize> = Vec::new();
    for &i in cand.iter().rev() {
        while upper.len() >= 2 && cross(upper[upper.len() - 2], upper[upper.len() - 1], i) <= 0.0 {
            upper.pop();
        }
        upper.push(i);
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    if lower.is_empty() {
        lower.push(cand[0]);
    }
    lower
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extreme_samples_hold_the_extremes_of_linear_functions() {
        let n = 5000;
        let q1: Vec<f64> = (0..n)
            .map(|i| (i as f64 * 0.013).sin() * (1.0 + (i as f64 * 0.0007).cos()))
            .collect();
        let q2: Vec<f64> = (0..n)
            .map(|i| (i as f64 * 0.029).cos() * 0.7 + (i as f64 * 0.0031).sin())
            .collect();
        let idx = extreme_samples(&[&q1, &q2]);
        assert!(idx.len() < n / 10, "{}", idx.len());
        for d in 0..64 {
            let (c, s) = ((d as f64 * 0.1).cos(), (d as f64 * 0.1).sin());
            let f = |i: usize| c * q1[i] + s * q2[i];
            let all = (0..n).map(f).fold(f64::NEG_INFINITY, f64::max);
            let sub = idx
                .iter()
                .map(|&i| f(i as usize))
                .fold(f64::NEG_INFINITY, f64::max);
            assert_eq!(all, sub, "direction {d}");
        }
        let one = extreme_samples(&[&q1]);
        assert_eq!(one.len(), 2);
        let q3: Vec<f64> = q1.iter().zip(&q2).map(|(a, b)| a - b).collect();
        let three = extreme_samples(&[&q1, &q2, &q3]);
        assert!(three.len() <= EXTREME_STRIDE_SAMPLES + 6);
        for q in [&q1, &q2, &q3] {
            let mx = q.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
            assert!(three.iter().any(|&i| q[i as usize] == mx));
        }
        assert!(extreme_samples(&[]).is_empty());
    }
}

/// A parameter sweep (paper Fig. 6 for `gamma0`). `progress(done, total)` is called after each
/// point when given; an exception it throws is ignored.
#[wasm_bindgen(unchecked_return_type = "SweepResult")]
pub fn sweep(
    #[wasm_bindgen(unchecked_param_type = "SimConfig")] cfg: JsValue,
    #[wasm_bindgen(unchecked_param_type = "SweepOptions")] opts: JsValue,
    #[wasm_bindgen(
        unchecked_param_type = "((done: number, total: number) => void) | null | undefined"
    )]
    progress: JsValue,
) -> Result<JsValue, JsError> {
    let progress: Option<Function> = function_arg(progress, "progress")?;
    let cfg = config_from(cfg)?;
    let opts: SweepOptions = required_js(opts, "sweep", "{ param, from, to, points }")?;
    let s = core_sweep(&cfg, &opts, progress_fn(progress)).map_err(err)?;
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

/// The resonance map: Floquet analysis of every mode over `opts.points` flap frequencies from
/// `from_hz` to `to_hz` (and, with `alpha0_values`, each roll amplitude; arrays are then
/// row-major `[alpha0][flap_hz]`). Per mode: effective frequency, largest |multiplier|, beat
/// period against the nearest n·f_d (NaN where none) and that n, stability (1/0) — the numbers
/// `simulate` reports in `floquet`, without any time series. `progress(done, total)` is called
/// after each point when given (an exception it throws is ignored). The caps (points, α0 values,
/// total work) are checked before any work.
#[wasm_bindgen(js_name = resonanceMap, unchecked_return_type = "ResonanceMapResult")]
pub fn resonance_map(
    #[wasm_bindgen(unchecked_param_type = "SimConfig")] cfg: JsValue,
    #[wasm_bindgen(unchecked_param_type = "ResonanceOptions")] opts: JsValue,
    #[wasm_bindgen(
        unchecked_param_type = "((done: number, total: number) => void) | null | undefined"
    )]
    progress: JsValue,
) -> Result<JsValue, JsError> {
    let progress: Option<Function> = function_arg(progress, "progress")?;
    let cfg = config_from(cfg)?;
    let opts: ResonanceOptions = required_js(
        opts,
        "resonance",
        "{ from_hz, to_hz, points, alpha0_values? }",
    )?;
    let m = core_resonance_map(&cfg, &opts, progress_fn(progress)).map_err(err)?;
    let o = Object::new();
    set(&o, "flap_hz", &f64a(&m.flap_hz))?;
    if let Some(a) = &m.alpha0 {
        set(&o, "alpha0", &f64a(a))?;
    }
    let modes = Array::new();
    for r in &m.modes {
        let beat: Vec<f64> = r.beat_period_s.iter().map(|&b| opt_or_nan(b)).collect();
        let mo = obj_with(&[
            ("effective_freq_hz", &r.effective_freq_hz),
            ("max_modulus", &r.max_modulus),
            ("beat_period_s", &beat),
        ])?;
        set(&mo, "name", &JsValue::from_str(&r.name))?;
        set(&mo, "freq_hz", &JsValue::from_f64(r.freq_hz))?;
        set(
            &mo,
            "beat_harmonic",
            &Uint32Array::from(&r.beat_harmonic[..]).into(),
        )?;
        let stable: Vec<u8> = r.stable.iter().map(|&s| u8::from(s)).collect();
        set(&mo, "stable", &Uint8Array::from(&stable[..]).into())?;
        modes.push(&mo);
    }
    set(&o, "modes", &modes)?;
    Ok(o.into())
}
