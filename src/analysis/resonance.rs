//! The resonance map: Floquet analysis of every mode over a range of flap frequencies (and
//! optionally of roll amplitudes α0), without any time series.
//!
//! At each flap frequency f_d the modal equation (Eq. 13) has T-periodic coefficients,
//! T = 1/f_d. [`crate::floquet`] reduces one period to the monodromy matrix and reads off the
//! largest multiplier modulus (> 1: parametric resonance, the free response grows), the effective
//! natural frequency (lowered by centrifugal softening) and the beat period against the nearest
//! flap harmonic n·f_d. A map of these over f_d shows where the beat comes from (f_eff close to
//! n·f_d: slow beats, and forced resonance where they meet) and where the tongues of parametric
//! instability lie (f_eff ≈ n·f_d/2 for the period-T stiffness; max |λ| > 1 there).
//!
//! Every number is exactly what [`crate::simulate::simulate`] reports in its `floquet` summary
//! for the same config (the same function computes it), without propagating the responses, so
//! a map point costs a few periods' integration instead of a whole run.
//!
//! # Caps
//!
//! Checked before any work is done:
//! * `points` ≤ [`MAX_POINTS`] (the sweep's cap) and at most [`MAX_ALPHA0_VALUES`] roll
//!   amplitudes;
//! * the total work, estimated by [`analysis_cost`] in Gauss–Legendre step equivalents summed
//!   over every (α0, f_d, mode), at most [`MAX_WORK`] (some seconds natively). The
//!   cost of one analysis grows like f_k / f_d (steps per flap period), so low flap frequencies
//!   against high modes are what the cap stops.

use crate::analysis::sweep::{self, SweepParam};
use crate::config::SimConfig;
use crate::error::{check_positive, check_range, Result, WingbeatError};
use crate::floquet::FloquetResult;
use crate::kinematics::MAX_FLAP_HZ;
use crate::simulate::floquet_for;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Most flap frequencies in one map (the sweep's cap).
pub const MAX_POINTS: usize = sweep::MAX_POINTS;
/// Most roll amplitudes in one map.
pub const MAX_ALPHA0_VALUES: usize = 201;
/// Most work in one map, in Gauss–Legendre step equivalents (see [`analysis_cost`]). One unit
/// took 1–2 µs in the (lightly optimised) test build here, so the cap keeps a map under about
/// 10–20 s; the paper's wing over 200 flap frequencies from 5 to 60 Hz costs 1.4e5 units.
pub const MAX_WORK: f64 = 1.0e7;

/// What to map.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ResonanceOptions {
    /// First flap frequency, Hz.
    pub from_hz: f64,
    /// Last flap frequency, Hz.
    pub to_hz: f64,
    /// Number of flap frequencies (≥ 2), evenly spaced from `from_hz` to `to_hz`.
    pub points: usize,
    /// Roll amplitudes α0 (first harmonic of α, rad), one map row each; `None`: the config's α.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha0_values: Option<Vec<f64>>,
}

/// One mode's map. Arrays are row-major `[alpha0][flap_hz]` (one row without `alpha0_values`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ResonanceMode {
    /// The mode's label.
    pub name: String,
    /// Natural frequency of the non-rotating wing f_k, Hz.
    pub freq_hz: f64,
    /// Floquet effective natural frequency, Hz ([`FloquetResult::effective_freq_hz`]).
    pub effective_freq_hz: Vec<f64>,
    /// Largest Floquet multiplier modulus over one flap period ([`FloquetResult::max_modulus`]).
    pub max_modulus: Vec<f64>,
    /// Beat period against the nearest flap harmonic, s; `None` where they coincide
    /// ([`FloquetResult::beat_period_s`]).
    pub beat_period_s: Vec<Option<f64>>,
    /// That harmonic n (≥ 1) ([`FloquetResult::beat_harmonic`]).
    pub beat_harmonic: Vec<u32>,
    /// Floquet stability ([`FloquetResult::stable`]).
    pub stable: Vec<bool>,
}

/// A resonance map.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ResonanceMap {
    /// Flap frequencies (columns), Hz.
    pub flap_hz: Vec<f64>,
    /// Roll amplitudes (rows), rad, when asked for.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub alpha0: Option<Vec<f64>>,
    /// Per-mode maps.
    pub modes: Vec<ResonanceMode>,
}

/// The Floquet analysis' cost estimate (moved to [`crate::floquet::analysis_cost`], which
/// the run budget of `simulate` uses as well).
pub use crate::floquet::analysis_cost;

/// Checks the options and the caps; returns the flap-frequency grid and the α0 rows.
fn plan(cfg: &SimConfig, opts: &ResonanceOptions) -> Result<(Vec<f64>, Option<Vec<f64>>)> {
    cfg.validate()?;
    sweep::check_points("resonance.points", opts.points)?;
    check_positive("resonance.from_hz", opts.from_hz, MAX_FLAP_HZ, "Hz")?;
    check_positive("resonance.to_hz", opts.to_hz, MAX_FLAP_HZ, "Hz")?;
    if let Some(a) = &opts.alpha0_values {
        if a.is_empty() || a.len() > MAX_ALPHA0_VALUES {
            return Err(WingbeatError::invalid(
                "resonance.alpha0_values",
                format!("{} values", a.len()),
                format!("1 to {MAX_ALPHA0_VALUES} roll amplitudes"),
            ));
        }
        for (i, &v) in a.iter().enumerate() {
            check_range(
                &format!("resonance.alpha0_values[{i}]"),
                v,
                -2.0 * PI,
                2.0 * PI,
                "rad",
            )?;
        }
        // Only the first harmonic of a Fourier α can be set.
        sweep::apply(cfg, SweepParam::Alpha0, a[0])?;
    }
    let flap = sweep::grid(opts.from_hz, opts.to_hz, opts.points);
    let rows = opts.alpha0_values.as_ref().map_or(1, Vec::len) as f64;
    // The step size does not depend on α0 (only on the harmonics present and f_d), so one row's
    // estimate times the number of rows is the total.
    let mut work = 0.0;
    for &f in &flap {
        let c = sweep::apply(cfg, SweepParam::FlapHz, f)?;
        let kin = c.kinematics.compile();
        work += cfg
            .modes
            .iter()
            .map(|m| analysis_cost(&kin, m))
            .sum::<f64>();
    }
    work *= rows;
    if work.is_nan() || work > MAX_WORK {
        return Err(WingbeatError::ResourceCap {
            field: "resonance (points × α0 values × modes, weighted by f_k / f_d)".into(),
            requested: format!("{work:.3e} integration steps"),
            cap: format!("{MAX_WORK:.1e} steps"),
            why: "computing time; raise the lowest flap frequency, use fewer points or fewer modes"
                .into(),
        });
    }
    Ok((flap, opts.alpha0_values.clone()))
}

/// The Floquet summary of every mode at each (α0, f_d); `progress(done, total)` is called after
/// each map point (all modes of one (α0, f_d)).
pub fn resonance_map(
    cfg: &SimConfig,
    opts: &ResonanceOptions,
    mut progress: impl FnMut(usize, usize),
) -> Result<ResonanceMap> {
    if !cfg.aero.is_vacuum() {
        return Err(WingbeatError::invalid(
            "aero.air_density_kg_m3",
            cfg.aero.air_density_kg_m3,
            "0 for the resonance map (its Floquet numbers are per mode, in a vacuum; a fluid couples the modes: run `simulate` in air for their coupled Floquet numbers)",
        ));
    }
    let (flap, alpha0) = plan(cfg, opts)?;
    let rows: Vec<Option<f64>> = match &alpha0 {
        Some(a) => a.iter().map(|&v| Some(v)).collect(),
        None => vec![None],
    };
    let total = rows.len() * flap.len();
    let mut modes: Vec<ResonanceMode> = cfg
        .modes
        .iter()
        .map(|m| ResonanceMode {
            name: m.name.clone(),
            freq_hz: m.freq_hz,
            effective_freq_hz: Vec::with_capacity(total),
            max_modulus: Vec::with_capacity(total),
            beat_period_s: Vec::with_capacity(total),
            beat_harmonic: Vec::with_capacity(total),
            stable: Vec::with_capacity(total),
        })
        .collect();
    let mut done = 0;
    for row in &rows {
        let base = match row {
            Some(a) => sweep::apply(cfg, SweepParam::Alpha0, *a)?,
            None => cfg.clone(),
        };
        for &f in &flap {
            let c = sweep::apply(&base, SweepParam::FlapHz, f)?;
            let at = match row {
                Some(a) => format!("resonance point α0 = {a}, f_d = {f} Hz"),
                None => format!("resonance point f_d = {f} Hz"),
            };
            c.model()
                .validate()
                .map_err(|e| sweep::in_context(e, &at))?;
            let kin = c.kinematics.compile();
            for (m, out) in c.modes.iter().zip(modes.iter_mut()) {
                let r: FloquetResult = floquet_for(&kin, m);
                out.effective_freq_hz.push(r.effective_freq_hz);
                out.max_modulus.push(r.max_modulus);
                out.beat_period_s.push(r.beat_period_s);
                out.beat_harmonic.push(r.beat_harmonic);
                out.stable.push(r.stable);
            }
            done += 1;
            progress(done, total);
        }
    }
    Ok(ResonanceMap {
        flap_hz: flap,
        alpha0,
        modes,
    })
}
