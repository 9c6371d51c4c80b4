//! The lab's numeric parameters, owned here once: their keys, symbols, labels, units, slider
//! ranges and defaults (the paper's forward-flight case), and how each one changes a
//! [`SimConfig`].
//!
//! A front end (the browser lab, its URLs, the embed attributes) names a parameter by its key
//! and hands the value to [`apply_overrides`]; it never interprets the value itself. The
//! amplitudes, the flap frequency and the damping ratio mean exactly what a sweep over them
//! means ([`crate::analysis::sweep::apply`]); a phase sets the phase of the angle's first
//! harmonic; `duration` sets [`SimConfig::duration_s`]. `tests/params.rs` checks that every
//! slider range lies inside what [`SimConfig::validate`] accepts.

use crate::analysis::sweep::{self, SweepParam};
use crate::config::SimConfig;
use crate::error::{check_range, Result, WingbeatError};
use crate::kinematics::{Angle, Harmonic};
use serde::Serialize;

/// One numeric parameter of the lab: what it is called and the slider that sets it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Param {
    /// Name in URLs, element attributes and [`apply_overrides`], e.g. `gamma0`.
    pub key: &'static str,
    /// Short mathematical symbol, e.g. `γ0`.
    pub symbol: &'static str,
    /// Human label for the slider.
    pub label: &'static str,
    /// Unit (`""` for dimensionless).
    pub unit: &'static str,
    /// Smallest slider value (inclusive).
    pub min: f64,
    /// Largest slider value (inclusive).
    pub max: f64,
    /// Slider step.
    pub step: f64,
    /// Default: the paper's forward-flight case (Tables 3–6), 2 s simulated.
    pub default: f64,
}

/// Roll amplitude key.
pub const ALPHA0: &str = "alpha0";
/// Pitch amplitude key.
pub const BETA0: &str = "beta0";
/// Yaw amplitude key.
pub const GAMMA0: &str = "gamma0";
/// Flap frequency key.
pub const FLAP_HZ: &str = "flap_hz";
/// Damping ratio key.
pub const ZETA: &str = "zeta";
/// Roll phase key.
pub const ALPHA_PHASE: &str = "alpha_phase";
/// Pitch phase key.
pub const BETA_PHASE: &str = "beta_phase";
/// Yaw phase key.
pub const GAMMA_PHASE: &str = "gamma_phase";
/// Simulated duration key.
pub const DURATION: &str = "duration";

/// Largest phase on the sliders, rad: the last point of the 0.01 rad step grid below π
/// (deliberately not π itself, so that the range ends on its step grid).
#[allow(clippy::approx_constant)]
pub const PHASE_LIMIT: f64 = 3.14;

/// Every numeric parameter of the lab, in slider order. The duration reaches 10 s so that the
/// damping experiment (ζ = 0.01, paper §4.3) can run long enough to see the beat die out.
pub const PARAMS: [Param; 9] = [
    Param {
        key: ALPHA0,
        symbol: "α0",
        label: "α0, roll amplitude",
        unit: "rad",
        min: 0.0,
        max: 1.5,
        step: 0.01,
        default: 0.8,
    },
    Param {
        key: BETA0,
        symbol: "β0",
        label: "β0, pitch amplitude",
        unit: "rad",
        min: 0.0,
        max: 1.0,
        step: 0.01,
        default: 0.5,
    },
    Param {
        key: GAMMA0,
        symbol: "γ0",
        label: "γ0, yaw amplitude",
        unit: "rad",
        min: 0.0,
        max: 0.5,
        step: 0.005,
        default: 0.2,
    },
    Param {
        key: FLAP_HZ,
        symbol: "f_d",
        label: "Flap frequency f_d",
        unit: "Hz",
        min: 5.0,
        max: 60.0,
        step: 0.5,
        default: 25.0,
    },
    Param {
        key: ZETA,
        symbol: "ζ",
        label: "ζ, modal damping ratio",
        unit: "",
        min: 0.0,
        max: 0.1,
        step: 0.001,
        default: 0.0,
    },
    Param {
        key: ALPHA_PHASE,
        symbol: "φα",
        label: "Phase of α",
        unit: "rad",
        min: -PHASE_LIMIT,
        max: PHASE_LIMIT,
        step: 0.01,
        default: 0.0,
    },
    Param {
        key: BETA_PHASE,
        symbol: "φβ",
        label: "Phase of β",
        unit: "rad",
        min: -PHASE_LIMIT,
        max: PHASE_LIMIT,
        step: 0.01,
        default: 0.0,
    },
    Param {
        key: GAMMA_PHASE,
        symbol: "φγ",
        label: "Phase of γ",
        unit: "rad",
        min: -PHASE_LIMIT,
        max: PHASE_LIMIT,
        step: 0.01,
        default: 0.0,
    },
    Param {
        key: DURATION,
        symbol: "T_sim",
        label: "Duration",
        unit: "s",
        min: 0.2,
        max: 10.0,
        step: 0.1,
        default: 2.0,
    },
];

/// The parameter table.
pub fn parameters() -> &'static [Param] {
    &PARAMS
}

/// The parameter with this key, if any.
pub fn find(key: &str) -> Option<&'static Param> {
    PARAMS.iter().find(|p| p.key == key)
}

fn unknown_key(key: &str) -> WingbeatError {
    let keys: Vec<&str> = PARAMS.iter().map(|p| p.key).collect();
    // Never echo an arbitrarily long key back.
    let shown: String = if key.chars().count() > 40 {
        key.chars().take(40).chain("…".chars()).collect()
    } else {
        key.to_string()
    };
    WingbeatError::invalid(
        format!("overrides.{shown}"),
        "unknown parameter",
        format!("one of {}", keys.join(", ")),
    )
}

/// Sets the phase of the first harmonic of `angle` (adding a zero-amplitude first harmonic when
/// there is none, as a sweep over the amplitude adds one with zero phase).
fn set_first_phase(angle: &mut Angle, field: &str, v: f64) -> Result<()> {
    match angle {
        Angle::Fourier { harmonics, .. } => {
            if let Some(h) = harmonics.iter_mut().find(|h| h.n == 1) {
                h.phase = v;
            } else {
                harmonics.push(Harmonic {
                    n: 1,
                    amplitude: 0.0,
                    phase: v,
                });
            }
            Ok(())
        }
        Angle::Sampled { .. } => Err(WingbeatError::invalid(
            field,
            "sampled kinematics",
            "Fourier kinematics (a sampled table has no first-harmonic phase to set)",
        )),
    }
}

/// Applies one parameter to `c` in place (the value is already range-checked).
fn apply_one(c: &mut SimConfig, p: &Param, v: f64) -> Result<()> {
    let swept = match p.key {
        ALPHA0 => Some(SweepParam::Alpha0),
        BETA0 => Some(SweepParam::Beta0),
        GAMMA0 => Some(SweepParam::Gamma0),
        FLAP_HZ => Some(SweepParam::FlapHz),
        ZETA => Some(SweepParam::Zeta),
        _ => None,
    };
    if let Some(s) = swept {
        *c = sweep::apply(c, s, v)?;
        return Ok(());
    }
    match p.key {
        ALPHA_PHASE => set_first_phase(&mut c.kinematics.alpha, "kinematics.alpha", v),
        BETA_PHASE => set_first_phase(&mut c.kinematics.beta, "kinematics.beta", v),
        GAMMA_PHASE => set_first_phase(&mut c.kinematics.gamma, "kinematics.gamma", v),
        DURATION => {
            c.duration_s = v;
            Ok(())
        }
        other => Err(unknown_key(other)),
    }
}

/// `base` with the named parameters set: `alpha0`, `beta0`, `gamma0` (first-harmonic
/// amplitudes, rad), `flap_hz` (Hz), `zeta` (every mode's damping ratio), `alpha_phase`,
/// `beta_phase`, `gamma_phase` (first-harmonic phases, rad), `duration` (s).
///
/// Errors: an unknown key (named, with the known ones listed); a value outside its slider
/// range [[`Param::min`], [`Param::max`]] (named `overrides.KEY`, with the range and unit);
/// a phase or amplitude for a sampled angle; and whatever [`SimConfig::validate`] rejects in
/// the result. Keys may come in any order; each is applied once, independently of the others.
pub fn apply_overrides<K: AsRef<str>>(
    base: &SimConfig,
    overrides: impl IntoIterator<Item = (K, f64)>,
) -> Result<SimConfig> {
    let mut c = base.clone();
    let mut seen: Vec<&'static str> = Vec::new();
    for (key, v) in overrides {
        let key = key.as_ref();
        let p = find(key).ok_or_else(|| unknown_key(key))?;
        if seen.contains(&p.key) {
            return Err(WingbeatError::invalid(
                format!("overrides.{}", p.key),
                v,
                "at most one value per parameter",
            ));
        }
        seen.push(p.key);
        check_range(&format!("overrides.{}", p.key), v, p.min, p.max, p.unit)?;
        apply_one(&mut c, p, v)?;
    }
    c.validate()?;
    Ok(c)
}

/// The defaults of every parameter as `(key, value)` pairs (the paper case).
pub fn defaults() -> Vec<(&'static str, f64)> {
    PARAMS.iter().map(|p| (p.key, p.default)).collect()
}
