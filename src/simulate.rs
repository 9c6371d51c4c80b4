//! The simulation driver: a [`SimConfig`] in, every mode's partial and total responses,
//! contributions, Floquet summary and strains out. Used by the CLI, the wasm API and the tests.

use crate::analysis::contribution::{contributions, Contributions};
use crate::config::SimConfig;
use crate::error::Result;
use crate::floquet::{self, FloquetResult};
use crate::kinematics::Compiled;
use crate::model::{softening, Mode};
use crate::solve::propagator::{propagate, Propagated};
use crate::solve::ModalOde;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Partial and total responses of one mode (kg^½·m for mass-normalised modes).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Responses {
    /// Response to the Euler force alone, zero initial conditions.
    pub euler: Vec<f64>,
    /// Response to the centrifugal force alone, zero initial conditions.
    pub centrifugal: Vec<f64>,
    /// Response to the Coriolis force alone, zero initial conditions.
    pub coriolis: Vec<f64>,
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
}

/// Strain time series at one point (Eqs. 16–18): Σ_k ε_k q_k(t).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StrainSeries {
    /// Point label.
    pub point: String,
    /// ε_x(t).
    pub eps_x: Vec<f64>,
    /// ε_y(t).
    pub eps_y: Vec<f64>,
    /// γ_xy(t).
    pub gamma_xy: Vec<f64>,
}

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
}

/// Mean centrifugal softening over one period (rad²/s²), by a 256-point rectangle rule
/// (spectrally accurate for smooth periodic integrands).
pub fn mean_softening(kin: &Compiled) -> f64 {
    let n = 256;
    let t = 2.0 * PI / kin.wd;
    (0..n)
        .map(|j| softening(&kin.state(j as f64 * t / n as f64)))
        .sum::<f64>()
        / n as f64
}

/// Floquet analysis of one mode under compiled kinematics.
pub fn floquet_for(kin: &Compiled, mode: &Mode) -> FloquetResult {
    floquet_with(kin, mode, None)
}

fn floquet_with(
    kin: &Compiled,
    mode: &Mode,
    monodromy: Option<nalgebra::Matrix2<f64>>,
) -> FloquetResult {
    let ode = ModalOde::new(kin, mode);
    let w = mode.omega();
    let w2 = w * w - mean_softening(kin);
    let naive = if w2 > 0.0 {
        w2.sqrt() / (2.0 * PI)
    } else {
        f64::NAN
    };
    floquet::analyse_with(&ode, kin.wd / (2.0 * PI), naive, monodromy)
}

/// Propagates one mode: returns the raw propagation.
pub fn propagate_mode(kin: &Compiled, mode: &Mode, dt: f64, n: usize) -> Result<Propagated> {
    propagate(&ModalOde::new(kin, mode), dt, n)
}

/// Runs a simulation.
pub fn simulate(cfg: &SimConfig) -> Result<SimResult> {
    cfg.validate()?;
    let kin = cfg.kinematics.compile();
    let n = cfg.n_samples();
    let dt = 1.0 / cfg.sample_rate_hz;
    let t: Vec<f64> = (0..n).map(|i| i as f64 * dt).collect();
    let mut modes = Vec::with_capacity(cfg.modes.len());
    for (k, mode) in cfg.modes.iter().enumerate() {
        let p = propagate_mode(&kin, mode, dt, n)?;
        let [q0, v0] = cfg.ic(k);
        let free: Vec<f64> = (0..n)
            .map(|i| q0 * p.h_q[0][i] + v0 * p.h_q[1][i])
            .collect();
        let total: Vec<f64> = (0..n).map(|i| p.q[ModalOde::TOTAL][i] + free[i]).collect();
        let qdot_total: Vec<f64> = (0..n)
            .map(|i| p.qdot[ModalOde::TOTAL][i] + q0 * p.h_qdot[0][i] + v0 * p.h_qdot[1][i])
            .collect();
        let q = Responses {
            euler: p.q[ModalOde::EULER].clone(),
            centrifugal: p.q[ModalOde::CENTRIFUGAL].clone(),
            coriolis: p.q[ModalOde::CORIOLIS].clone(),
            free,
            total,
        };
        let contribution_percent = contributions(&q.euler, &q.centrifugal, &q.coriolis, &q.total);
        let floquet = floquet_with(&kin, mode, Some(p.monodromy));
        let accuracy = Accuracy {
            method: "one-period Gauss–Legendre (order 8) propagator + exact period recursion"
                .into(),
            period_error_estimate: p.period_error,
            periods: p.periods,
            run_error_bound: p.period_error * p.periods as f64,
        };
        modes.push(ModeResult {
            name: mode.name.clone(),
            freq_hz: mode.freq_hz,
            zeta: mode.zeta,
            q,
            qdot_total,
            contribution_percent,
            floquet,
            accuracy,
        });
    }
    let strain_points = crate::analysis::strain::strain_series(&cfg.modes, &modes);
    Ok(SimResult {
        t,
        flap_freq_hz: cfg.kinematics.flap_freq_hz,
        strain: strain_points.first().cloned(),
        strain_points: if strain_points.len() > 1 {
            strain_points
        } else {
            vec![]
        },
        modes,
        warnings: cfg.warnings(),
    })
}

/// The Eq. 13 terms of one mode sampled on a time grid (paper Fig. 4).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ForceSeries {
    /// Euler forcing.
    pub euler: Vec<f64>,
    /// Centrifugal forcing.
    pub centrifugal: Vec<f64>,
    /// Coriolis forcing.
    pub coriolis: Vec<f64>,
    /// Centrifugal softening α̇² cos²β + β̇², rad²/s² (the time-varying part of the stiffness).
    pub softening: Vec<f64>,
}

/// Samples the forcing terms and the softening of every mode at t_i = i / rate, i = 0..n.
pub fn force_series(cfg: &SimConfig) -> Result<Vec<ForceSeries>> {
    cfg.validate()?;
    let kin = cfg.kinematics.compile();
    let n = cfg.n_samples();
    let dt = 1.0 / cfg.sample_rate_hz;
    let states: Vec<_> = (0..n).map(|i| kin.state(i as f64 * dt)).collect();
    Ok(cfg
        .modes
        .iter()
        .map(|m| {
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
                fs.softening.push(softening(s));
            }
            fs
        })
        .collect())
}
