//! The wing in air: quasi-steady aerodynamic loads on the flapping, flexing wing, projected on
//! the modes (docs/model.md, "The wing in air").
//!
//! Every point of the wing moves through still air with the rigid-body velocity of the
//! rotating frame (body rate included, yaw to first order as in Eq. 13) plus the elastic
//! velocity ẇ = Σ φ_k q̇_k along the wing normal K″. The air pushes on the plate along its
//! normal (a flat plate carries no leading-edge suction), per unit area
//!
//! ```text
//! f_n = − ½ ρ C_N(α) |v|² sign(v_n) = − ½ ρ C_N,max |v| v_n      (C_N(α) = C_N,max sin α)
//! ```
//!
//! with α the local angle of attack (sin α = |v_n| / |v|). The normal-force form
//! C_N = C_N,max sin α is the one the translational lift and drag fits of Dickinson, Lehmann &
//! Sane (1999) reduce to when resolved on the plate's normal (C_N = C_L cos α + C_D sin α lies
//! within about 0.1 of 3.4 sin α over 10°–90°; `tests/aero_loads.rs` measures it); it is odd in
//! v_n and smooth where |v| > 0, so it can be linearised in the elastic velocity.
//!
//! The air's inertia enters as a strip-theory added mass (the non-circulatory terms of a flat
//! plate strip, Theodorsen; Sane & Dickinson 2002 use the same strip term for the whole wing):
//! at each span station of half chord b the local normal motion is fitted by a heave h and a
//! pitch θ about mid-chord, whose added mass per unit span is ρπb² and added inertia ρπb⁴/8.
//! It acts on the inertial normal acceleration of the plate: the rigid part gives an
//! aerodynamic force, the elastic part an added-mass matrix M_a (constant) that multiplies
//! q̈ − S(t) q, exactly as the wing's own unit modal mass does in Eq. 13.
//!
//! Projected on the modes (kg^½·m units throughout, like Eq. 13):
//!
//! ```text
//! (I + M_a) q̈ + (D + C_a(t)) q̇ + (Λ − S(t)(I + M_a)) q = F_E + F_C + F_R + F_A(t)
//! F_A,k   = ∫ φ_k f_n(v₀) dA − added mass × rigid normal acceleration      (aerodynamic force)
//! C_a,kl  = ∫ φ_k φ_l ½ ρ C_N,max (|v₀| + v₀ₙ² / |v₀|) dA                  (∂f_n/∂ẇ, linearised)
//! ```
//!
//! The modes couple through M_a and C_a. [`crate::solve::coupled`] solves the 2N-state
//! periodic system; [`nonlinear`] steps the unlinearised |v|v drag directly to measure the
//! linearisation's error.

pub mod floquet;
pub mod nonlinear;
pub mod ode;
pub mod simulate;
pub mod transient;
pub mod wing;

use crate::error::{check_range, Result, WingbeatError};
use serde::{Deserialize, Serialize};

pub use wing::{AeroWing, WingGeometry};

/// Air density of the `air` preset, kg/m³ (sea level, 20 °C).
pub const AIR_DENSITY: f64 = 1.2;
/// Density of the `helium` preset, kg/m³ (Combes & Daniel 2003 flapped wings in helium at
/// about 15 % of air's density).
pub const HELIUM_DENSITY: f64 = 0.18;
/// Largest fluid density accepted, kg/m³ (water is 1000; strip theory is no longer a good
/// model well before that, but the equations stay well posed).
pub const MAX_DENSITY: f64 = 1000.0;
/// Default C_N,max of the normal-force coefficient C_N = C_N,max sin α: the value the
/// translational force coefficients of Dickinson, Lehmann & Sane (1999) give on the plate's
/// normal (Sane & Dickinson 2001 quote C_N ≈ 3.4 sin α).
pub const DEFAULT_CN_MAX: f64 = 3.4;
/// Default number of spanwise strips of the aerodynamic quadrature (two Gauss points each).
pub const DEFAULT_STRIPS: usize = 24;
/// Default chordwise Gauss points per strip.
pub const DEFAULT_CHORD_POINTS: usize = 6;
/// Most strips accepted.
pub const MAX_STRIPS: usize = 400;
/// Most chordwise points accepted.
pub const MAX_CHORD_POINTS: usize = 32;

/// The named media a front end offers, with their densities (kg/m³).
pub const MEDIA: [(&str, f64); 3] = [
    ("vacuum", 0.0),
    ("helium", HELIUM_DENSITY),
    ("air", AIR_DENSITY),
];

/// The fluid around the wing and the aerodynamic model's parameters (config key `aero`).
/// The default is a vacuum: no air, and every result exactly as without this key.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct AeroConfig {
    /// Fluid density ρ, kg/m³: 0 = vacuum (the paper), 0.18 helium, 1.2 air.
    pub air_density_kg_m3: f64,
    /// C_N,max of the normal-force coefficient C_N(α) = C_N,max sin α (dimensionless).
    pub normal_force_coefficient: f64,
    /// Whether the fluid's added mass is included (strip theory).
    pub added_mass: bool,
    /// Spanwise strips of the aerodynamic quadrature (two Gauss points per strip).
    pub strips: usize,
    /// Chordwise Gauss points per strip.
    pub chord_points: usize,
}

impl Default for AeroConfig {
    fn default() -> Self {
        AeroConfig {
            air_density_kg_m3: 0.0,
            normal_force_coefficient: DEFAULT_CN_MAX,
            added_mass: true,
            strips: DEFAULT_STRIPS,
            chord_points: DEFAULT_CHORD_POINTS,
        }
    }
}

impl AeroConfig {
    /// A medium of density `rho` (kg/m³) with the default model.
    pub fn with_density(rho: f64) -> Self {
        AeroConfig {
            air_density_kg_m3: rho,
            ..Default::default()
        }
    }

    /// True for the default (vacuum, default model parameters).
    pub fn is_default(&self) -> bool {
        *self == AeroConfig::default()
    }

    /// True for a vacuum (density exactly 0): the per-mode path runs unchanged.
    pub fn is_vacuum(&self) -> bool {
        self.air_density_kg_m3 == 0.0
    }

    /// Validates every field; errors name `aero.<field>` and the allowed range.
    pub fn validate(&self) -> Result<()> {
        check_range(
            "aero.air_density_kg_m3",
            self.air_density_kg_m3,
            0.0,
            MAX_DENSITY,
            "kg/m³ (0 = vacuum, 0.18 helium, 1.2 air)",
        )?;
        check_range(
            "aero.normal_force_coefficient",
            self.normal_force_coefficient,
            0.0,
            10.0,
            "(C_N,max of C_N = C_N,max sin α; 3.4 from Dickinson et al. 1999)",
        )?;
        if self.strips < 1 || self.strips > MAX_STRIPS {
            return Err(WingbeatError::invalid(
                "aero.strips",
                self.strips,
                format!("an integer in [1, {MAX_STRIPS}]"),
            ));
        }
        if self.chord_points < 1 || self.chord_points > MAX_CHORD_POINTS {
            return Err(WingbeatError::invalid(
                "aero.chord_points",
                self.chord_points,
                format!("an integer in [1, {MAX_CHORD_POINTS}]"),
            ));
        }
        Ok(())
    }
}

/// The rigid-body motion of one wing point at one instant: what the air sees before the wing
/// bends. `r` = the point's yawed in-plane position (x − γy, y + γx), m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointFlow {
    /// Normal velocity v₀ₙ along K″, m/s.
    pub vn: f64,
    /// Speed |v₀| (normal and in-plane), m/s.
    pub speed: f64,
}

/// The frame's state the loads need at one instant: Ω, Ω̇ (frame components), γ, γ̇ — the
/// model's [`crate::model::Rotation`] (the same quantities Eq. 13 reads), with the air's point
/// kinematics below.
pub use crate::model::Rotation as FrameState;

impl FrameState {
    /// Rigid velocity of the wing point (x, y) (m, wing frame, before yaw): Ω × r plus the
    /// in-plane velocity γ̇ K × (x, y) of the yawing point.
    #[inline]
    pub fn flow(&self, x: f64, y: f64) -> PointFlow {
        let [ox, oy, oz] = self.omega;
        let g = self.gamma;
        let rx = x - g * y;
        let ry = y + g * x;
        let vn = ox * ry - oy * rx;
        let vx = -oz * ry - self.gamma_dot * y;
        let vy = oz * rx + self.gamma_dot * x;
        PointFlow {
            vn,
            speed: (vx * vx + vy * vy + vn * vn).sqrt(),
        }
    }

    /// Inertial normal acceleration of the rigid wing point (x, y) along K″, m/s²: the
    /// same terms whose mass moments give Eq. 13's Euler, centrifugal and Coriolis forces
    /// (to first order in γ): Ω̇ × r + Ω × (Ω × r) + 2 Ω × ṙ_rel.
    #[inline]
    pub fn normal_acceleration(&self, x: f64, y: f64) -> f64 {
        let [ox, oy, oz] = self.omega;
        let [ax, ay, _] = self.omega_dot;
        let g = self.gamma;
        let rx = x - g * y;
        let ry = y + g * x;
        (ax * ry - ay * rx) + oz * (ox * rx + oy * ry) + 2.0 * self.gamma_dot * (ox * x + oy * y)
    }

    /// ∂/∂y of [`FrameState::normal_acceleration`] (exact: the acceleration is linear in the
    /// chordwise position), 1/s².
    #[inline]
    pub fn normal_acceleration_slope(&self, _x: f64, _y: f64) -> f64 {
        let [ox, oy, oz] = self.omega;
        let [ax, ay, _] = self.omega_dot;
        let g = self.gamma;
        ax + g * ay + oz * (oy - g * ox) + 2.0 * self.gamma_dot * oy
    }
}

/// The normal force per unit area on a plate element with normal velocity `vn` and speed
/// `speed` (m/s), N/m², for `k` = ½ ρ C_N,max: − k |v| v_n.
#[inline]
pub fn normal_pressure(k: f64, vn: f64, speed: f64) -> f64 {
    -k * speed * vn
}

/// ∂f_n/∂ẇ at (v_n, |v|) for `k` = ½ ρ C_N,max: the local aerodynamic damping per unit area,
/// N·s/m³: k (|v| + v_n² / |v|); 0 where the point is at rest (there the drag is quadratic in
/// the elastic velocity and has no linear part).
#[inline]
pub fn damping_density(k: f64, vn: f64, speed: f64) -> f64 {
    if speed > 0.0 {
        k * (speed + vn * vn / speed)
    } else {
        0.0
    }
}

/// The translational lift and drag coefficients of Dickinson, Lehmann & Sane (1999, Science
/// 284:1954), their fits to the robotic fly wing at Re ≈ 100–200, α in radians:
/// C_L = 0.225 + 1.58 sin(2.13α − 7.20°), C_D = 1.92 − 1.55 cos(2.04α − 9.82°). Used only to
/// document how close C_N,max sin α is to their normal component.
pub fn dickinson_1999_cl_cd(alpha: f64) -> (f64, f64) {
    let d = std::f64::consts::PI / 180.0;
    let cl = 0.225 + 1.58 * (2.13 * alpha - 7.20 * d).sin();
    let cd = 1.92 - 1.55 * (2.04 * alpha - 9.82 * d).cos();
    (cl, cd)
}

/// The error for air without mode shapes over the wing (the paper's table modes).
pub fn no_wing_error() -> WingbeatError {
    WingbeatError::invalid(
        "aero.air_density_kg_m3",
        "a density above 0 with modes that have no shapes over the wing",
        "0 (vacuum) for the paper's table modes: air loads a wing point by point, so they need an FE wing's mode shapes (`--preset fe-wing`, or `--modes FILE` from `wingbeat modes`)",
    )
}
