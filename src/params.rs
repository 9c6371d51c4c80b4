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

// ---- The wing's parameters (the lab's FE wing: outline, camber, clamp, material, mesh, modes) ----

/// Camber key: rise at mid-chord as a fraction of the local chord.
pub const CAMBER: &str = "camber";
/// Clamp key: 0 = clamp the root edge on x = 0, else clamp a basal strip this wide, mm.
pub const CLAMP_MM: &str = "clamp_mm";
/// Young's modulus key, Pa.
pub const E_PA: &str = "e_pa";
/// Density key, kg/m³.
pub const RHO: &str = "rho";
/// Poisson's ratio key.
pub const NU: &str = "nu";
/// Membrane thickness key, µm.
pub const THICKNESS_UM: &str = "thickness_um";
/// Mesh size key: 0 = chosen from the planform, else the target element edge, mm.
pub const MESH_MM: &str = "mesh_mm";
/// Number of modes key (1–8 in the lab).
pub const N_MODES: &str = "n_modes";

/// Most modes the lab computes for one wing (the core accepts up to [`crate::model::MAX_MODES`]).
pub const LAB_MAX_MODES: usize = 8;

/// The wing's parameters in the lab, in panel order, with the defaults of the lab's FE wing:
/// the synthetic Manduca-like outline's [`crate::fem::FemInput::default`] (13 % camber, root
/// clamp, the "paper-frequencies" material) with the `fe-wing` preset's
/// [`crate::presets::FE_WING_MODES`] modes and the mesh size chosen from the planform.
/// Each range lies inside what [`crate::fem::compute_modes`] accepts (`tests/params.rs`).
pub const WING_PARAMS: [Param; 8] = [
    Param {
        key: CAMBER,
        symbol: "h/c",
        label: "Camber, rise / local chord",
        unit: "",
        min: 0.0,
        max: 0.5,
        step: 0.01,
        default: 0.13,
    },
    Param {
        key: CLAMP_MM,
        symbol: "x_c",
        label: "Clamp: 0 = root edge, else basal strip width",
        unit: "mm",
        min: 0.0,
        max: 1000.0,
        step: 0.1,
        default: 0.0,
    },
    Param {
        key: E_PA,
        symbol: "E",
        label: "Young's modulus E",
        unit: "Pa",
        min: 1.0e5,
        max: 1.0e12,
        step: 1.0e5,
        default: crate::fem::PAPER_FREQUENCIES_E_PA,
    },
    Param {
        key: RHO,
        symbol: "ρ",
        label: "Density ρ",
        unit: "kg/m³",
        min: 10.0,
        max: 20000.0,
        step: 1.0,
        default: 860.0,
    },
    Param {
        key: NU,
        symbol: "ν",
        label: "Poisson's ratio ν",
        unit: "",
        min: 0.0,
        max: 0.49,
        step: 0.01,
        default: 0.3,
    },
    Param {
        key: THICKNESS_UM,
        symbol: "t",
        label: "Thickness t",
        unit: "µm",
        min: 1.0,
        max: 10000.0,
        step: 0.1,
        default: 81.0,
    },
    Param {
        key: MESH_MM,
        symbol: "h_e",
        label: "Mesh size: 0 = from the planform, else element edge",
        unit: "mm",
        min: 0.0,
        max: 100.0,
        step: 0.05,
        default: 0.0,
    },
    Param {
        key: N_MODES,
        symbol: "N",
        label: "Number of modes",
        unit: "",
        min: 1.0,
        max: LAB_MAX_MODES as f64,
        step: 1.0,
        default: crate::presets::FE_WING_MODES as f64,
    },
];

/// The wing's parameter table.
pub fn wing_parameters() -> &'static [Param] {
    &WING_PARAMS
}

/// The wing parameter with this key, if any.
pub fn find_wing(key: &str) -> Option<&'static Param> {
    WING_PARAMS.iter().find(|p| p.key == key)
}

fn shown_key(key: &str) -> String {
    // Never echo an arbitrarily long key back.
    if key.chars().count() > 40 {
        key.chars().take(40).chain("…".chars()).collect()
    } else {
        key.to_string()
    }
}

fn unknown_wing_key(key: &str) -> WingbeatError {
    let keys: Vec<&str> = WING_PARAMS.iter().map(|p| p.key).collect();
    WingbeatError::invalid(
        format!("wing.{}", shown_key(key)),
        "unknown wing parameter",
        format!("one of {}", keys.join(", ")),
    )
}

/// The range the FE core accepts for one material property ([`MATERIAL_RANGES`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MaterialRange {
    /// Field path in an FE input and in error messages, e.g. `material.e_pa`.
    pub field: &'static str,
    /// The lab's wing parameter for the same property ([`WING_PARAMS`]), e.g. `e_pa`.
    pub wing_key: &'static str,
    /// Smallest value accepted, in the field's unit.
    pub min: f64,
    /// Largest value accepted, in the field's unit.
    pub max: f64,
    /// Whether `min` and `max` themselves are excluded (Poisson's ratio: −1 < ν < 0.5).
    pub open: bool,
    /// Unit of the field (SI, as [`crate::fem::ShellMaterial`] stores it).
    pub unit: &'static str,
}

/// What [`crate::fem::ShellMaterial::validate`] accepts, one entry per field: physical
/// bounds, wider than the lab's sliders ([`WING_PARAMS`], which lie inside them —
/// `tests/clear_errors_and_url_ranges.rs`), narrow enough that the element matrices stay far from
/// underflow and overflow (E = 1e-300 Pa used to end in "Krylov space exhausted"; any
/// E ≥ 1e-100 Pa still solves, so these bounds leave a wide margin). From a soft gel
/// (1 kPa) to above diamond (1e13 Pa); 0.1 µm to 1 m thick; 1 to 1e5 kg/m³.
pub const MATERIAL_RANGES: [MaterialRange; 4] = [
    MaterialRange {
        field: "material.thickness_m",
        wing_key: THICKNESS_UM,
        min: 1e-7,
        max: 1.0,
        open: false,
        unit: "m",
    },
    MaterialRange {
        field: "material.e_pa",
        wing_key: E_PA,
        min: 1e3,
        max: 1e13,
        open: false,
        unit: "Pa",
    },
    MaterialRange {
        field: "material.rho_kg_m3",
        wing_key: RHO,
        min: 1.0,
        max: 1e5,
        open: false,
        unit: "kg/m^3",
    },
    MaterialRange {
        field: "material.nu",
        wing_key: NU,
        min: -1.0,
        max: 0.5,
        open: true,
        unit: "",
    },
];

impl MaterialRange {
    /// Checks `v` against the range; the error names [`MaterialRange::field`], the range
    /// and the unit.
    pub fn check(&self, v: f64) -> Result<()> {
        if !self.open {
            return check_range(self.field, v, self.min, self.max, self.unit);
        }
        if v.is_finite() && v > self.min && v < self.max {
            return Ok(());
        }
        Err(WingbeatError::invalid(
            self.field,
            v,
            format!(
                "a finite number in the open interval ({}, {})",
                crate::error::num(self.min),
                crate::error::num(self.max)
            ),
        ))
    }
}

/// The core's accepted range of a material field (`material.e_pa`, …), if any.
pub fn material_range(field: &str) -> Option<&'static MaterialRange> {
    MATERIAL_RANGES.iter().find(|r| r.field == field)
}

/// One of the two material presets of the paper (Table 2), in the lab's units.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MaterialPreset {
    /// Identifier, as the CLI's `--material`.
    pub id: &'static str,
    /// Human label.
    pub label: &'static str,
    /// Young's modulus, Pa.
    pub e_pa: f64,
    /// Density, kg/m³.
    pub rho: f64,
    /// Poisson's ratio.
    pub nu: f64,
    /// Thickness, µm.
    pub thickness_um: f64,
}

/// Thickness in µm such that `um / 1e6` gives `m` back exactly when a short decimal does.
fn um_of(m: f64) -> f64 {
    let t = m * 1e6;
    let r = (t * 1e6).round() / 1e6;
    if r / 1e6 == m {
        r
    } else {
        t
    }
}

/// The paper's two materials (values owned by [`crate::fem::ShellMaterial`]):
/// `paper-frequencies` (E = 13.11 GPa, the default wing's f1 ≈ 62.5 Hz) and
/// `paper-as-printed` (Table 2 as printed, E = 10 MPa, a unit slip: f1 ≈ 1.7 Hz).
pub fn material_presets() -> Vec<MaterialPreset> {
    let of = |id, label, m: crate::fem::ShellMaterial| MaterialPreset {
        id,
        label,
        e_pa: m.e_pa,
        rho: m.rho_kg_m3,
        nu: m.nu,
        thickness_um: um_of(m.thickness_m),
    };
    vec![
        of(
            "paper-frequencies",
            "Paper, E = 13.11 GPa (reproduces f1 ≈ 62.5 Hz)",
            crate::fem::ShellMaterial::paper_frequencies(),
        ),
        of(
            "paper-as-printed",
            "Paper as printed, E = 10 MPa (unit slip: f1 ≈ 1.7 Hz)",
            crate::fem::ShellMaterial::paper_as_printed(),
        ),
    ]
}

/// Sets the mesh size from the `mesh_mm` value (0 = chosen from the planform).
fn set_mesh_size(input: &mut crate::fem::FemInput, v: f64) {
    input.mesh_size_mm = if v == 0.0 { None } else { Some(v) };
}

/// Applies the wing parameters to `w` (no final checks; see [`apply_wing_overrides`]).
fn apply_wing_keys<K: AsRef<str>>(
    w: &mut crate::fem::FemInput,
    overrides: impl IntoIterator<Item = (K, f64)>,
) -> Result<()> {
    use crate::fem::Clamp;
    let mut seen: Vec<&'static str> = Vec::new();
    for (key, v) in overrides {
        let key = key.as_ref();
        let p = find_wing(key).ok_or_else(|| unknown_wing_key(key))?;
        let field = format!("wing.{}", p.key);
        if seen.contains(&p.key) {
            return Err(WingbeatError::invalid(
                field,
                v,
                "at most one value per parameter",
            ));
        }
        seen.push(p.key);
        check_range(&field, v, p.min, p.max, p.unit)?;
        match p.key {
            CAMBER => w.camber = v,
            CLAMP_MM => {
                w.clamp = if v == 0.0 {
                    Clamp::Root
                } else {
                    Clamp::Strip { x_mm: v }
                }
            }
            E_PA => w.material.e_pa = v,
            RHO => w.material.rho_kg_m3 = v,
            NU => w.material.nu = v,
            // Division, not × 1e-6: 81 / 1e6 is the double nearest 81 µm, as the literal 81e-6.
            THICKNESS_UM => w.material.thickness_m = v / 1e6,
            MESH_MM => set_mesh_size(w, v),
            N_MODES => {
                if v.fract() != 0.0 {
                    return Err(WingbeatError::invalid(
                        field,
                        v,
                        format!("an integer in [1, {LAB_MAX_MODES}]"),
                    ));
                }
                w.n_modes = v as usize;
            }
            other => return Err(unknown_wing_key(other)),
        }
    }
    Ok(())
}

/// `base` with the named wing parameters set (see [`WING_PARAMS`] for keys, units and ranges):
/// `camber` (rise / chord), `clamp_mm` (0 = [`crate::fem::Clamp::Root`], else a basal strip
/// [`crate::fem::Clamp::Strip`] of that width, mm), `e_pa` (Pa), `rho` (kg/m³), `nu`,
/// `thickness_um` (µm), `mesh_mm` (0 = from the planform, else mm), `n_modes` (an integer).
///
/// Errors name the key as `wing.KEY`: an unknown key (the known ones listed), a repeated key,
/// a value outside its range (with the range and unit), a fractional `n_modes`; then whatever
/// the material's and the outline's checks reject in the result.
pub fn apply_wing_overrides<K: AsRef<str>>(
    base: &crate::fem::FemInput,
    overrides: impl IntoIterator<Item = (K, f64)>,
) -> Result<crate::fem::FemInput> {
    let mut w = base.clone();
    apply_wing_keys(&mut w, overrides)?;
    w.material.validate()?;
    crate::fem::geometry::validate_outline(&w.planform_mm)?;
    Ok(w)
}

/// The lab's wing input: the default wing ([`default_wing`]), on `points` (mm) when given
/// (with [`crate::fem::geometry::planform_note_for`] as its note), with `overrides` applied
/// as in [`apply_wing_overrides`]. What wasm `wingInput` returns and the lab hands to
/// `feModes`.
pub fn wing_input<K: AsRef<str>>(
    overrides: impl IntoIterator<Item = (K, f64)>,
    points: Option<Vec<[f64; 2]>>,
) -> Result<crate::fem::FemInput> {
    let mut w = crate::fem::FemInput::default();
    if let Some(p) = points {
        w.planform_note = crate::fem::geometry::planform_note_for(&p);
        w.planform_mm = p;
    }
    apply_wing_keys(&mut w, WING_PARAMS.iter().map(|p| (p.key, p.default)))?;
    apply_wing_overrides(&w, overrides)
}

/// The lab's default wing: [`crate::fem::FemInput::default`] with every [`WING_PARAMS`]
/// default applied (so the table's defaults are the wing the lab starts with).
pub fn default_wing() -> Result<crate::fem::FemInput> {
    wing_input(std::iter::empty::<(&str, f64)>(), None)
}

/// One accepted range of the body angular velocity ω_b ([`BODY_RATE_RANGES`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BodyRateRange {
    /// Which quantity: `mean`, `amplitude`, `phase`, `value` (a sampled table's entry) or
    /// `peak` (|mean| + Σ|amplitude| of one component).
    pub what: &'static str,
    /// Smallest value accepted.
    pub min: f64,
    /// Largest value accepted.
    pub max: f64,
    /// Unit.
    pub unit: &'static str,
}

impl BodyRateRange {
    /// Checks `v`; the error names `field`, the range and the unit.
    pub fn check(&self, field: &str, v: f64) -> Result<()> {
        check_range(field, v, self.min, self.max, self.unit)
    }
}

/// Largest body rate per component, rad/s: about 5700°/s, above the fastest body saccades of
/// flies (a few thousand °/s); hawkmoths turn at a few rad/s.
pub const MAX_BODY_RATE_RAD_S: f64 = 100.0;

/// What [`crate::kinematics::BodyRate::validate`] accepts, one entry per quantity of each
/// component (`kinematics.body_rate.x`, `.y`, `.z`).
pub const BODY_RATE_RANGES: [BodyRateRange; 5] = [
    BodyRateRange {
        what: "mean",
        min: -MAX_BODY_RATE_RAD_S,
        max: MAX_BODY_RATE_RAD_S,
        unit: "rad/s",
    },
    BodyRateRange {
        what: "amplitude",
        min: -MAX_BODY_RATE_RAD_S,
        max: MAX_BODY_RATE_RAD_S,
        unit: "rad/s",
    },
    BodyRateRange {
        what: "phase",
        min: -1.0e3,
        max: 1.0e3,
        unit: "rad",
    },
    BodyRateRange {
        what: "value",
        min: -MAX_BODY_RATE_RAD_S,
        max: MAX_BODY_RATE_RAD_S,
        unit: "rad/s",
    },
    BodyRateRange {
        what: "peak",
        min: 0.0,
        max: MAX_BODY_RATE_RAD_S,
        unit: "rad/s",
    },
];

/// The entry of [`BODY_RATE_RANGES`] for `what` (panics on an unknown name: a programming error).
pub fn body_rate_range(what: &str) -> &'static BodyRateRange {
    BODY_RATE_RANGES
        .iter()
        .find(|r| r.what == what)
        .expect("a BODY_RATE_RANGES entry")
}
