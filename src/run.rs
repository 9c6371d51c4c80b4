//! One run's result and budget, shared by the vacuum path ([`crate::simulate`]) and the air
//! path ([`crate::aero::simulate`]): the types `simulate` returns ([`SimResult`],
//! [`ModeResult`], [`Responses`], [`Accuracy`], and in air [`ModeAir`] and [`AirSummary`]),
//! their assembly from per-mode results (`assemble`: strain at the named points, warnings),
//! and the work budget of one run ([`MAX_RUN_WORK`]). Both paths import this module and
//! neither imports the other's result code, so `simulate` can dispatch to the air path without
//! a cycle. [`crate::simulate`] re-exports everything here under its old paths.

use crate::aero::AeroConfig;
use crate::analysis::contribution::Contributions;
use crate::config::SimConfig;
use crate::floquet::FloquetResult;
use crate::pool::SeriesPool;
use serde::{Deserialize, Serialize};

/// Partial and total responses of one mode (kg^½·m for mass-normalised modes).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Responses {
    /// Response to the Euler force alone, zero initial conditions.
    pub euler: Vec<f64>,
    /// Response to the centrifugal force alone, zero initial conditions.
    pub centrifugal: Vec<f64>,
    /// Response to the Coriolis force alone, zero initial conditions.
    pub coriolis: Vec<f64>,
    /// Response to the aerodynamic force alone (in air; empty and left out in a vacuum).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub aerodynamic: Vec<f64>,
    /// Free response to the initial conditions alone (zero when they are zero).
    pub free: Vec<f64>,
    /// Total response: all forces together plus the initial conditions.
    /// Equals euler + centrifugal + coriolis + free to rounding (linearity).
    pub total: Vec<f64>,
}

/// Accuracy report of one mode's solve.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Accuracy {
    /// Method used.
    pub method: String,
    /// Estimated relative error of the one-period integration.
    pub period_error_estimate: f64,
    /// Periods spanned; the state error grows at most linearly with them for a stable mode.
    pub periods: u64,
    /// Conservative relative error bound for the whole run: period error × periods.
    pub run_error_bound: f64,
}

/// Everything computed for one mode.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ModeResult {
    /// The mode's label.
    pub name: String,
    /// Natural frequency of the non-rotating wing, Hz.
    pub freq_hz: f64,
    /// Damping ratio used.
    pub zeta: f64,
    /// Responses.
    pub q: Responses,
    /// q̇ of the total response.
    pub qdot_total: Vec<f64>,
    /// Share of each force term (paper §4.1): 100 Σ q_term² / Σ q_total².
    pub contribution_percent: Contributions,
    /// Floquet summary: effective frequency, beat, multipliers, stability.
    pub floquet: FloquetResult,
    /// Accuracy report.
    pub accuracy: Accuracy,
    /// What the air does to this mode (absent in a vacuum).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub air: Option<ModeAir>,
}

pub use crate::analysis::strain::StrainSeries;

/// A simulation's output.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SimResult {
    /// Sample times, s.
    pub t: Vec<f64>,
    /// Flap frequency, Hz.
    pub flap_freq_hz: f64,
    /// Per-mode results.
    pub modes: Vec<ModeResult>,
    /// Strain at the first named point (absent when no mode carries strains).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub strain: Option<StrainSeries>,
    /// Strain at every named point (also the first), when there is more than one.
    #[serde(skip_serializing_if = "Vec::is_empty", default)]
    pub strain_points: Vec<StrainSeries>,
    /// Non-fatal warnings (e.g. yaw beyond the small-angle range).
    pub warnings: Vec<String>,
    /// The medium and the coupled system's Floquet multipliers (absent in a vacuum).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub air: Option<AirSummary>,
}

impl SimResult {
    /// Hands every series of this result (times, responses, velocities, strains) to `pool`,
    /// for the next run to write into ([`crate::simulate::simulate_reusing`]).
    pub fn recycle(self, pool: &mut SeriesPool) {
        pool.give(self.t);
        for m in self.modes {
            let q = m.q;
            for v in [
                q.euler,
                q.centrifugal,
                q.coriolis,
                q.aerodynamic,
                q.free,
                q.total,
                m.qdot_total,
            ] {
                pool.give(v);
            }
        }
        for s in self.strain.into_iter().chain(self.strain_points) {
            for v in [s.eps_x, s.eps_y, s.gamma_xy] {
                pool.give(v);
            }
        }
    }
}

/// What air does to one mode (the `air` block of a mode's result).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ModeAir {
    /// Natural frequency of the non-rotating wing in still air (added mass), Hz.
    pub still_air_freq_hz: f64,
    /// Its shift from the vacuum frequency, Hz (negative: the air's mass lowers it).
    pub added_mass_shift_hz: f64,
    /// Cycle-averaged aerodynamic damping ratio ⟨C_a,kk⟩ / (2 M_kk ω_air,k).
    pub aero_damping_ratio: f64,
    /// Decay rate of the Floquet mode that continues this mode, 1/s (positive: it decays).
    pub decay_rate_per_s: f64,
    /// Time constant of that free vibration, 1/decay rate, s; None when it does not decay.
    pub decay_time_s: Option<f64>,
    /// The beat's fate: the free vibration (and with it the beat against the forcing) decays
    /// with `decay_time_s`; "no beat" when that is shorter than the beat period.
    pub beat: String,
    /// Share of the Floquet mode's motion in this mode (1 = uncoupled).
    pub participation: f64,
}

/// The run's air summary.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AirSummary {
    /// The medium's parameters.
    pub aero: AeroConfig,
    /// Planform area of the aerodynamic quadrature, m².
    pub area_m2: f64,
    /// Quadrature points.
    pub points: usize,
    /// Added-mass matrix M_a (N × N rows), dimensionless.
    pub added_mass: Vec<Vec<f64>>,
    /// All 2N Floquet multipliers of the coupled system over one flap period, [re, im].
    pub multipliers: Vec<[f64; 2]>,
    /// True when none lies outside the unit circle.
    pub stable: bool,
    /// Gauss–Legendre steps per flap period.
    pub steps_per_period: usize,
}

/// Most work one run may take, in step equivalents ([`crate::simulate::run_cost`] in a vacuum,
/// [`crate::aero::simulate::air_run_cost`] in air; one unit is about one
/// Gauss–Legendre step of one mode under the paper's three-term kinematics). Measured in a
/// release build on the project's 2-core machine: `--flap-hz 0.1 --duration 0.1`, 4.2e5
/// units, 0.39 s; an α table at 64 harmonics, 1.2e6 units, 1.1 s; so about 0.9 µs per unit
/// and the cap keeps a native run under about 5 s. The paper case costs 1e4 units.
pub const MAX_RUN_WORK: f64 = 5.0e6;

/// The result of a run from its per-mode results: the strain at every named point from the
/// total responses, the warnings, and the air summary when there is one (the vacuum and the
/// air paths both end here).
pub(crate) fn assemble(
    cfg: &SimConfig,
    t: Vec<f64>,
    modes: Vec<ModeResult>,
    air: Option<AirSummary>,
) -> SimResult {
    assemble_in(cfg, t, modes, air, &mut SeriesPool::new())
}

/// [`assemble`] with the strain series taken from `pool`.
pub(crate) fn assemble_in(
    cfg: &SimConfig,
    t: Vec<f64>,
    modes: Vec<ModeResult>,
    air: Option<AirSummary>,
    pool: &mut SeriesPool,
) -> SimResult {
    let totals: Vec<&[f64]> = modes.iter().map(|m| m.q.total.as_slice()).collect();
    let mut strain_points = crate::analysis::strain::strain_series_in(&cfg.modes, &totals, pool);
    // One point: its series move into `strain` (no copy); several: `strain` is the first's copy.
    let strain = match strain_points.len() {
        1 => strain_points.pop(),
        _ => strain_points.first().cloned(),
    };
    SimResult {
        t,
        flap_freq_hz: cfg.kinematics.flap_freq_hz,
        strain,
        strain_points,
        modes,
        warnings: cfg.warnings(),
        air,
    }
}
