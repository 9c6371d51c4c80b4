//! How a value named by key changes an input: the one interpretation of the lab's sliders, the
//! CLI's parameter flags and the sweeps. [`apply_overrides`] applies named values to a
//! [`SimConfig`] (range-checked against the sliders, then validated); [`set_param`] is the
//! single place where each key's meaning lives (the amplitudes set the first harmonic of an
//! angle, a phase its phase, `flap_hz` the flap frequency, `zeta` every mode's damping ratio,
//! `duration` [`SimConfig::duration_s`]), and [`crate::analysis::sweep::apply`] calls it for
//! every sweep point. The wing's parameters ([`WING_PARAMS`], [`wing_input`]) do the same for
//! the FE wing's [`crate::fem::FemInput`].
//!
//! The ranges themselves are plain data in [`crate::ranges`] (a leaf of the module graph, so
//! the stages that check them — `kinematics`, `fem` — never import this module); everything
//! there is re-exported here. This module sits above `config`, `kinematics`, `fem` and
//! `presets`, the stages whose inputs it sets. `tests/params.rs` checks that every slider range
//! lies inside what [`SimConfig::validate`] accepts.

use crate::config::SimConfig;
use crate::error::{check_range, Result, WingbeatError};
use crate::kinematics::{Angle, Harmonic};
use serde::Serialize;

pub use crate::ranges::{
    body_rate_range, find, material_range, parameters, BodyRateRange, MaterialRange, Param,
    AIR_DENSITY, ALPHA0, ALPHA_PHASE, BETA0, BETA_PHASE, BODY_RATE_RANGES, CAMBER, CLAMP_MM,
    DURATION, E_PA, FLAP_HZ, GAMMA0, GAMMA_PHASE, LAB_MAX_MODES, MATERIAL_RANGES,
    MAX_BODY_RATE_RAD_S, MESH_MM, NU, N_MODES, PARAMS, PHASE_LIMIT, RHO, THICKNESS_UM, ZETA,
};

fn unknown_key(key: &str, field: impl Fn(&str) -> String) -> WingbeatError {
    let keys: Vec<&str> = PARAMS.iter().map(|p| p.key).collect();
    // Never echo an arbitrarily long key back.
    let shown: String = if key.chars().count() > 40 {
        key.chars().take(40).chain("…".chars()).collect()
    } else {
        key.to_string()
    };
    WingbeatError::invalid(
        field(&shown),
        "unknown parameter",
        format!("one of {}", keys.join(", ")),
    )
}

/// Sets the amplitude of the first harmonic of `angle` (adding a first harmonic with zero
/// phase when there is none).
fn set_first_amplitude(angle: &mut Angle, field: &str, v: f64) -> Result<()> {
    match angle {
        Angle::Fourier { harmonics, .. } => {
            if let Some(h) = harmonics.iter_mut().find(|h| h.n == 1) {
                h.amplitude = v;
            } else {
                harmonics.push(Harmonic {
                    n: 1,
                    amplitude: v,
                    phase: 0.0,
                });
            }
            Ok(())
        }
        Angle::Sampled { .. } => Err(WingbeatError::invalid(
            field,
            "sampled kinematics",
            "Fourier kinematics (a sampled table has no amplitude to sweep)",
        )),
    }
}

/// Sets the phase of the first harmonic of `angle` (adding a zero-amplitude first harmonic when
/// there is none, as setting the amplitude adds one with zero phase).
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

/// Sets the parameter `key` ([`PARAMS`]) to `v` in `c`: what each key means, in one place.
/// `alpha0`, `beta0`, `gamma0`: the amplitude of the angle's first harmonic, rad (added with
/// zero phase when missing); `alpha_phase`, `beta_phase`, `gamma_phase`: its phase, rad;
/// `flap_hz`: the flap frequency, Hz; `zeta`: every mode's damping ratio; `duration`: the
/// simulated time, s; `air_density`: the medium's density, kg/m³ (`aero.air_density_kg_m3`;
/// above 0 the run needs the FE wing's shapes, `SimConfig::wing`). No range check (sweeps may go past the sliders; [`SimConfig::validate`]
/// judges the result). Errors: an unknown key (named `overrides.KEY`, the known ones listed),
/// an amplitude or phase of a sampled angle (named `kinematics.ANGLE`); `c` is unchanged then.
pub fn set_param(c: &mut SimConfig, key: &str, v: f64) -> Result<()> {
    let k = &mut c.kinematics;
    match key {
        ALPHA0 => set_first_amplitude(&mut k.alpha, "kinematics.alpha", v),
        BETA0 => set_first_amplitude(&mut k.beta, "kinematics.beta", v),
        GAMMA0 => set_first_amplitude(&mut k.gamma, "kinematics.gamma", v),
        FLAP_HZ => {
            k.flap_freq_hz = v;
            Ok(())
        }
        ZETA => {
            c.modes.iter_mut().for_each(|m| m.zeta = v);
            Ok(())
        }
        ALPHA_PHASE => set_first_phase(&mut k.alpha, "kinematics.alpha", v),
        BETA_PHASE => set_first_phase(&mut k.beta, "kinematics.beta", v),
        GAMMA_PHASE => set_first_phase(&mut k.gamma, "kinematics.gamma", v),
        DURATION => {
            c.duration_s = v;
            Ok(())
        }
        AIR_DENSITY => {
            c.aero.air_density_kg_m3 = v;
            Ok(())
        }
        other => Err(unknown_key(other, |k| format!("overrides.{k}"))),
    }
}

/// Which range a named value is checked against before [`set_param`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Limits {
    /// The lab's slider range [[`Param::min`], [`Param::max`]] (with the unit), per value.
    Sliders,
    /// Only that the value is a finite number; the caller validates the finished config
    /// ([`SimConfig::validate`]), whose ranges are the core's (the CLI's flags, which reach
    /// past the sliders: any flap frequency, duration or amplitude the core accepts).
    Core,
}

/// `base` with the named values set through [`set_param`], each key at most once, in the
/// order given. `field(key)` names a value in errors (`overrides.gamma0` for the lab,
/// `--gamma0` for the CLI); `limits` says which range each value must lie in. The result is
/// not validated (see [`apply_overrides`], which does). The one loop every front end's named
/// values go through.
pub fn apply_values<K: AsRef<str>>(
    base: &SimConfig,
    values: impl IntoIterator<Item = (K, f64)>,
    field: impl Fn(&str) -> String,
    limits: Limits,
) -> Result<SimConfig> {
    let mut c = base.clone();
    let mut seen: Vec<&'static str> = Vec::new();
    for (key, v) in values {
        let key = key.as_ref();
        let p = find(key).ok_or_else(|| unknown_key(key, &field))?;
        if seen.contains(&p.key) {
            return Err(WingbeatError::invalid(
                field(p.key),
                v,
                "at most one value per parameter",
            ));
        }
        seen.push(p.key);
        match limits {
            Limits::Sliders => check_range(&field(p.key), v, p.min, p.max, p.unit)?,
            Limits::Core if !v.is_finite() => {
                return Err(WingbeatError::invalid(field(p.key), v, "a finite number"))
            }
            Limits::Core => {}
        }
        set_param(&mut c, p.key, v)?;
    }
    Ok(c)
}

/// `base` with the named parameters set: `alpha0`, `beta0`, `gamma0` (first-harmonic
/// amplitudes, rad), `flap_hz` (Hz), `zeta` (every mode's damping ratio), `alpha_phase`,
/// `beta_phase`, `gamma_phase` (first-harmonic phases, rad), `duration` (s), `air_density`
/// (kg/m³). What the lab
/// calls (wasm `applyOverrides`): [`apply_values`] with the slider ranges, then
/// [`SimConfig::validate`].
///
/// Errors: an unknown key (named, with the known ones listed); a value outside its slider
/// range [[`Param::min`], [`Param::max`]] (named `overrides.KEY`, with the range and unit);
/// a phase or amplitude for a sampled angle; and whatever [`SimConfig::validate`] rejects in
/// the result. Keys may come in any order; each is applied once, independently of the others.
pub fn apply_overrides<K: AsRef<str>>(
    base: &SimConfig,
    overrides: impl IntoIterator<Item = (K, f64)>,
) -> Result<SimConfig> {
    let c = apply_values(
        base,
        overrides,
        |k| format!("overrides.{k}"),
        Limits::Sliders,
    )?;
    c.validate()?;
    Ok(c)
}

/// The defaults of every parameter as `(key, value)` pairs (the paper case).
pub fn defaults() -> Vec<(&'static str, f64)> {
    PARAMS.iter().map(|p| (p.key, p.default)).collect()
}

// ---- The wing's parameters (the lab's FE wing: outline, camber, clamp, material, mesh, modes) ----

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
