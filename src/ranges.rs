//! The ranges of every input a front end sets by name, as plain data: the lab's numeric
//! parameters ([`PARAMS`]: key, symbol, label, unit, slider range, step, default), the keys of
//! the wing's parameters, the FE material's physical ranges ([`MATERIAL_RANGES`]) and the body
//! angular velocity's ranges ([`BODY_RATE_RANGES`]).
//!
//! A leaf of the crate's module graph: it uses nothing of the crate but [`crate::error`] (for
//! the range checks' messages), so every stage can read its own limits here — `kinematics`
//! checks the body rate, `fem` the material — and [`crate::params`], which interprets the
//! values (`apply_overrides`), sits above those stages. [`crate::params`] re-exports
//! everything here, so `wingbeat::params::PARAMS` and the like keep working.

use crate::error::{check_range, Result, WingbeatError};
use serde::Serialize;

/// One numeric parameter of the lab: what it is called and the slider that sets it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Param {
    /// Name in URLs, element attributes and [`crate::params::apply_overrides`], e.g. `gamma0`.
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
/// Fluid density key (the medium: 0 vacuum, 0.18 helium, 1.2 air).
pub const AIR_DENSITY: &str = "air_density";

/// Largest phase on the sliders, rad: the last point of the 0.01 rad step grid below π
/// (deliberately not π itself, so that the range ends on its step grid).
#[allow(clippy::approx_constant)]
pub const PHASE_LIMIT: f64 = 3.14;

/// Every numeric parameter of the lab, in slider order. The duration reaches 10 s so that the
/// damping experiment (ζ = 0.01, paper §4.3) can run long enough to see the beat die out. The
/// fluid density's slider stops at 2 kg/m³ (gases an insect flies in; the core accepts up to
/// [`crate::aero::MAX_DENSITY`] through the config and the CLI).
pub const PARAMS: [Param; 10] = [
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
    Param {
        key: AIR_DENSITY,
        symbol: "ρ_air",
        label: "ρ_air, fluid density (0 = vacuum)",
        unit: "kg/m³",
        min: 0.0,
        max: 2.0,
        step: 0.01,
        default: 0.0,
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

/// The range the FE core accepts for one material property ([`MATERIAL_RANGES`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MaterialRange {
    /// Field path in an FE input and in error messages, e.g. `material.e_pa`.
    pub field: &'static str,
    /// The lab's wing parameter for the same property ([`crate::params::WING_PARAMS`]), e.g. `e_pa`.
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
/// bounds, wider than the lab's sliders ([`crate::params::WING_PARAMS`], which lie inside them —
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
