//! The modal model: one linear, time-varying ODE per mode (paper Eq. 13).
//!
//! For mode k with natural frequency ω_k (rad/s), damping ratio ζ_k and in-plane vector a_k:
//!
//! ```text
//! q̈_k + 2 ζ_k ω_k q̇_k + [ω_k² − (Ω_x² + Ω_y²)] q_k = F_E + F_C + F_R
//! F_E (Euler)       = − Ω̇ · (γ a_k − b_k)
//! F_C (centrifugal) = − Ω_z [Ω · (a_k + γ b_k)]
//! F_R (Coriolis)    = − 2 γ̇ Ω · a_k
//! ```
//!
//! with Ω_x² + Ω_y² = α̇² cos²β + β̇² =: S(t), the **stiffness coefficient** (1/s², the same for
//! every mode; [`stiffness_coefficient`]), and b_k = a_k turned 90°
//! counter-clockwise in the I″–J″ plane (paper Eq. 12, Table 4). Each term is defined exactly
//! once, here, and used by the solver, the analyses, the CLI and the wasm API alike.
//!
//! Units: with mass-normalised mode shapes (∫φ_k φ_e dm = δ_ke, φ in kg^-½) a_k is in
//! kg^½·m, q_k in kg^½·m, the forcing terms in kg^½·m/s². The paper's Table 4 vectors are not
//! in those units (see `docs/model.md`); the `paper` preset uses them as printed.

use crate::error::{check_range, Result, WingbeatError};
use crate::kinematics::{Kinematics, RateState};
use serde::{Deserialize, Serialize};

/// The three inertial force terms of Eq. 13 (paper Table 1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ForceTerm {
    /// Euler force, − Ω̇ · (γ a − b).
    Euler,
    /// Centrifugal force, − Ω_z [Ω · (a + γ b)].
    Centrifugal,
    /// Coriolis force, − 2 γ̇ Ω · a.
    Coriolis,
}

impl ForceTerm {
    /// All three, in the paper's order.
    pub const ALL: [ForceTerm; 3] = [
        ForceTerm::Euler,
        ForceTerm::Centrifugal,
        ForceTerm::Coriolis,
    ];

    /// Lower-case name used in JSON and CSV output.
    pub fn name(self) -> &'static str {
        match self {
            ForceTerm::Euler => "euler",
            ForceTerm::Centrifugal => "centrifugal",
            ForceTerm::Coriolis => "coriolis",
        }
    }
}

/// Modal strain (surface strain per unit modal coordinate) of one mode at a named point
/// (paper Eqs. 16–18, Table 6). Units: strain per (kg^½·m) for mass-normalised modes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModalStrain {
    /// A label for the point, e.g. "P" or "root-centre".
    pub point: String,
    /// Normal strain ε_x per unit q.
    pub eps_x: f64,
    /// Normal strain ε_y per unit q.
    pub eps_y: f64,
    /// Engineering shear strain γ_xy per unit q.
    pub gamma_xy: f64,
}

/// One vibration mode as the modal model needs it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Mode {
    /// Human label, e.g. "1: spanwise bending".
    #[serde(default)]
    pub name: String,
    /// Natural frequency of the non-rotating wing, Hz (ω_k / 2π).
    pub freq_hz: f64,
    /// a_k = ∫ φ_k (x, y) dm in the I″–J″ plane (paper Eq. 11), kg^½·m for mass-normalised modes.
    pub a: [f64; 2],
    /// Modal damping ratio ζ_k (dimensionless; the paper uses 0 and 0.01).
    #[serde(default)]
    pub zeta: f64,
    /// Modal strains at named points (optional).
    #[serde(default)]
    pub strains: Vec<ModalStrain>,
}

/// Cap on the number of modes one model may carry.
pub const MAX_MODES: usize = 64;
/// Most strain points one mode may carry (and one run may name). Each point adds three output
/// series as long as the run, so the points also count towards the run's sample-value cap.
pub const MAX_STRAIN_POINTS: usize = 256;
/// Largest natural frequency accepted, Hz.
pub const MAX_FREQ_HZ: f64 = 1.0e5;

impl Mode {
    /// ω_k in rad/s.
    pub fn omega(&self) -> f64 {
        2.0 * std::f64::consts::PI * self.freq_hz
    }

    /// b_k = a_k turned 90° counter-clockwise: (−a_y, a_x) (paper Eq. 12).
    pub fn b(&self) -> [f64; 2] {
        [-self.a[1], self.a[0]]
    }

    /// Validates the mode; `idx` is used in the field names of errors.
    pub fn validate(&self, idx: usize) -> Result<()> {
        let f = |s: &str| format!("modes[{idx}].{s}");
        crate::error::check_positive(&f("freq_hz"), self.freq_hz, MAX_FREQ_HZ, "Hz")?;
        check_range(&f("zeta"), self.zeta, 0.0, 10.0, "(damping ratio)")?;
        for (i, c) in self.a.iter().enumerate() {
            check_range(&f(&format!("a[{i}]")), *c, -1.0e3, 1.0e3, "kg^0.5 m")?;
        }
        if self.strains.len() > MAX_STRAIN_POINTS {
            return Err(WingbeatError::invalid(
                f("strains"),
                format!("{} points", self.strains.len()),
                format!("at most {MAX_STRAIN_POINTS} strain points per mode"),
            ));
        }
        for (j, s) in self.strains.iter().enumerate() {
            for (name, v) in [
                ("eps_x", s.eps_x),
                ("eps_y", s.eps_y),
                ("gamma_xy", s.gamma_xy),
            ] {
                check_range(
                    &f(&format!("strains[{j}].{name}")),
                    v,
                    -1.0e12,
                    1.0e12,
                    "strain per unit q",
                )?;
            }
        }
        Ok(())
    }
}

/// The time-varying coefficients of Eq. 13 for one mode at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coefficients {
    /// Total stiffness of the mode, ω_k² − S(t) with S the [`stiffness_coefficient`], rad²/s².
    pub stiffness: f64,
    /// Euler forcing, − Ω̇ · (γ a − b).
    pub euler: f64,
    /// Centrifugal forcing, − Ω_z [Ω · (a + γ b)].
    pub centrifugal: f64,
    /// Coriolis forcing, − 2 γ̇ Ω · a.
    pub coriolis: f64,
}

impl Coefficients {
    /// The forcing of one term.
    pub fn force(&self, term: ForceTerm) -> f64 {
        match term {
            ForceTerm::Euler => self.euler,
            ForceTerm::Centrifugal => self.centrifugal,
            ForceTerm::Coriolis => self.coriolis,
        }
    }

    /// Sum of the three forcing terms (right-hand side of Eq. 13).
    pub fn total_force(&self) -> f64 {
        self.euler + self.centrifugal + self.coriolis
    }
}

/// The stiffness coefficient S = Ω_x² + Ω_y² = α̇² cos²β + β̇² (1/s², i.e. rad²/s²): the
/// centrifugal softening Eq. 13 subtracts from ω_k². Independent of the mode. Moved to the
/// right-hand side, S(t)·q_k is the **stiffness force** ([`stiffness_force`]).
pub fn stiffness_coefficient(s: &RateState) -> f64 {
    let om = s.omega();
    om[0] * om[0] + om[1] * om[1]
}

/// The stiffness force S(t)·q_k(t) (same units as the force terms): the stiffness
/// coefficient's part of Eq. 13 written as a force, sample by sample. `coefficient` and `q`
/// are series on the same time grid (the shorter one sets the length). The only place the
/// product is formed: the CLI's `psd` and the wasm `analyze`/`spectra` both call it.
pub fn stiffness_force(coefficient: &[f64], q: &[f64]) -> Vec<f64> {
    coefficient.iter().zip(q).map(|(s, q)| s * q).collect()
}

/// The part of a rotation state that Eq. 13 reads, the same for every mode: Ω and Ω̇ in the
/// wing frame (rad/s, rad/s²), the yaw γ (rad) and its rate γ̇ (rad/s). Worked out once per
/// instant ([`Rotation::of`]) and shared by the modes ([`coefficients_of`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Rotation {
    /// Ω (rad/s).
    pub omega: [f64; 3],
    /// Ω̇ (rad/s²).
    pub omega_dot: [f64; 3],
    /// γ (rad).
    pub gamma: f64,
    /// γ̇ (rad/s).
    pub gamma_dot: f64,
}

impl Rotation {
    /// The rotation Eq. 13 reads from the state `s`.
    pub fn of(s: &RateState) -> Self {
        let (omega, omega_dot) = s.omega_and_dot();
        Rotation {
            omega,
            omega_dot,
            gamma: s.gamma,
            gamma_dot: s.gamma_dot,
        }
    }
}

/// The Eq. 13 coefficients of `mode` for the rotation state `s` (angles and rates at one instant).
pub fn coefficients(mode: &Mode, s: &RateState) -> Coefficients {
    coefficients_of(mode, &Rotation::of(s))
}

/// [`coefficients`] from the mode-independent [`Rotation`] (the same arithmetic, so the same
/// bits): the solver works the rotation out once per instant for all modes.
pub fn coefficients_of(mode: &Mode, r: &Rotation) -> Coefficients {
    let (om, omd) = (r.omega, r.omega_dot);
    let a = mode.a;
    let b = mode.b();
    let g = r.gamma;
    let w = mode.omega();
    // Euler: − Ω̇ · (γ a − b), in-plane components only (a, b have no K″ part).
    let euler = -(omd[0] * (g * a[0] - b[0]) + omd[1] * (g * a[1] - b[1]));
    // Centrifugal: − Ω_z [Ω · (a + γ b)].
    let centrifugal = -om[2] * (om[0] * (a[0] + g * b[0]) + om[1] * (a[1] + g * b[1]));
    // Coriolis: − 2 γ̇ Ω · a.
    let coriolis = -2.0 * r.gamma_dot * (om[0] * a[0] + om[1] * a[1]);
    Coefficients {
        // stiffness_coefficient(s), from the Ω already computed (same arithmetic).
        stiffness: w * w - (om[0] * om[0] + om[1] * om[1]),
        euler,
        centrifugal,
        coriolis,
    }
}

/// A modal model: the wing's modes under one set of kinematics.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModalModel {
    /// Rotation kinematics α(t), β(t), γ(t).
    pub kinematics: Kinematics,
    /// The retained modes.
    pub modes: Vec<Mode>,
}

impl ModalModel {
    /// Validates kinematics and every mode.
    pub fn validate(&self) -> Result<()> {
        self.kinematics.validate()?;
        if self.modes.is_empty() || self.modes.len() > MAX_MODES {
            return Err(WingbeatError::invalid(
                "modes",
                format!("{} modes", self.modes.len()),
                format!("1 to {MAX_MODES} modes"),
            ));
        }
        for (i, m) in self.modes.iter().enumerate() {
            m.validate(i)?;
        }
        Ok(())
    }

    /// Eq. 13 coefficients of mode `k` at time `t` (s).
    pub fn coefficients(&self, k: usize, t: f64) -> Coefficients {
        coefficients(&self.modes[k], &self.kinematics.rate_state(t))
    }
}
