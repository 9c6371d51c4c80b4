//! The simulation driver: a [`SimConfig`] in, every mode's partial and total responses,
//! contributions, Floquet summary and strains out. Used by the CLI, the wasm API and the tests.

use crate::analysis::contribution::contributions_with;
use crate::config::SimConfig;
use crate::error::{Result, WingbeatError};
use crate::floquet::{self, FloquetResult};
use crate::kinematics::Compiled;
use crate::model::{stiffness_coefficient, Mode};
use crate::pool::SeriesPool;
use crate::run::assemble_in;
pub use crate::run::{
    Accuracy, AirSummary, ModeAir, ModeResult, Responses, SimResult, StrainSeries, MAX_RUN_WORK,
};
use crate::solve::propagator::{propagate, propagate_responses_in, Propagated};
use crate::solve::{LinearOde, ModalOde, RotationMemo};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Mean of the stiffness coefficient S(t) = α̇² cos²β + β̇² over one period (1/s²), by a
/// 256-point rectangle rule (spectrally accurate for smooth periodic integrands).
pub fn mean_stiffness_coefficient(kin: &Compiled) -> f64 {
    let n = 256;
    let t = 2.0 * PI / kin.wd;
    (0..n)
        .map(|j| stiffness_coefficient(&kin.state(j as f64 * t / n as f64)))
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
    floquet::analyse_with(
        &ode,
        kin.wd / (2.0 * PI),
        averaged_freq_hz(mode, mean_stiffness_coefficient(kin)),
        monodromy,
    )
}

/// The mode's frequency with the period-mean softening `mean_s` = ⟨S⟩ (1/s²,
/// [`mean_stiffness_coefficient`]), √(ω_k² − ⟨S⟩) / 2π (Hz; NaN when ⟨S⟩ ≥ ω_k²).
fn averaged_freq_hz(mode: &Mode, mean_s: f64) -> f64 {
    let w = mode.omega();
    let w2 = w * w - mean_s;
    if w2 > 0.0 {
        w2.sqrt() / (2.0 * PI)
    } else {
        f64::NAN
    }
}

/// Propagates one mode: returns the raw propagation.
pub fn propagate_mode(kin: &Compiled, mode: &Mode, dt: f64, n: usize) -> Result<Propagated> {
    propagate(&ModalOde::new(kin, mode), dt, n)
}

/// Output cost per sample and mode, in step equivalents (responses, contributions, strain:
/// measured 0.17 s per million sample-modes in a sweep).
const SAMPLE_WORK: f64 = 0.2;

/// Estimated cost of `simulate(cfg)` in step equivalents (see [`MAX_RUN_WORK`]), and the mode
/// that costs most. Per mode: one flap period integrated for the responses and once more at
/// twice the step (the error estimate), the Floquet analysis over the homogeneous period
/// (`resonance::analysis_cost`), each step weighted by the kinematic terms evaluated per step
/// (27 for the paper's three sines; a body rate adds its terms and 6 for the rotation Rᵀω_b); plus the output, 0.2 unit per sample and mode. It mirrors
/// the step-size rule of [`crate::solve::propagator`] (steps per period = max(32, T·ω/0.25),
/// ω the largest of ω_k, 2ζ_kω_k and 4·H·ω_d with H the highest kinematic harmonic).
pub fn run_cost(cfg: &SimConfig) -> (f64, Option<usize>) {
    let kin = cfg.kinematics.compile();
    run_cost_with(cfg, &kin)
}

fn run_cost_with(cfg: &SimConfig, kin: &Compiled) -> (f64, Option<usize>) {
    let mut terms = (kin.alpha.terms.len() + kin.beta.terms.len() + kin.gamma.terms.len()) as f64;
    if let Some(b) = &kin.body_rate {
        // its series plus the rotation Rᵀ ω_b (two sin_cos and a few products per step)
        terms += b.iter().map(|s| s.terms.len() as f64).sum::<f64>() + 6.0;
    }
    let weight = (24.0 + terms) / 27.0;
    let mut total = 0.0;
    let mut worst = (None, -1.0);
    for (k, m) in cfg.modes.iter().enumerate() {
        let c = floquet::analysis_cost(kin, m) * weight;
        let c = if c.is_nan() { f64::INFINITY } else { c };
        if c > worst.1 {
            worst = (Some(k), c);
        }
        total += c;
    }
    let samples = cfg.duration_s * cfg.sample_rate_hz + 1.0;
    total += samples * cfg.modes.len() as f64 * SAMPLE_WORK;
    (total, worst.0)
}

/// Refuses a run whose [`run_cost`] exceeds `cap`, naming the input that drives it (the
/// costliest mode's frequency or damping, the kinematic harmonics, or the flap period).
pub fn check_run_cost(cfg: &SimConfig, cap: f64, who: &str) -> Result<()> {
    let kin = cfg.kinematics.compile();
    check_cost_with(cfg, &kin, cap, who)
}

fn check_cost_with(cfg: &SimConfig, kin: &Compiled, cap: f64, who: &str) -> Result<()> {
    let (cost, worst) = run_cost_with(cfg, kin);
    if cost <= cap {
        return Ok(());
    }
    let num = crate::error::num;
    let fd = cfg.kinematics.flap_freq_hz;
    let driver = match worst.map(|k| (k, &cfg.modes[k])) {
        Some((k, m)) => {
            let ode = ModalOde::new(kin, m);
            let w = m.omega();
            let harm = 4.0 * ode.max_harmonic * kin.wd;
            let what = if harm > w && harm > 2.0 * m.zeta * w {
                format!(
                    "the kinematics' highest harmonic (n = {}: fewer harmonics, or `max_harmonic` on a sampled table)",
                    ode.max_harmonic
                )
            } else if 2.0 * m.zeta * w > w {
                format!(
                    "`modes[{k}].zeta` = {} (at f_k = {} Hz)",
                    num(m.zeta),
                    num(m.freq_hz)
                )
            } else {
                format!("`modes[{k}].freq_hz` = {} Hz", num(m.freq_hz))
            };
            format!(
                "driven by {what} over one flap period of {} s (`kinematics.flap_freq_hz` = {} Hz); about {} steps per period",
                num(1.0 / fd),
                num(fd),
                num(crate::solve::propagator::steps_per_span(ode.freq_scale(), ode.period()))
            )
        }
        None => "driven by the output samples".into(),
    };
    Err(WingbeatError::ResourceCap {
        field: format!("{who} (modes × steps per flap period × kinematic terms)"),
        requested: format!("{} step equivalents, {driver}", num(cost.round())),
        cap: format!("{} step equivalents", num(cap)),
        why: "computing time, about 1 µs per unit natively; raise the flap frequency, drop the stiffest modes or lower the harmonics".into(),
    })
}

/// The sample rate nearest `sample_rate_hz` (Hz) with a whole number of samples per flap
/// period: P·f_d with P = max(1, round(rate / f_d)). Opt-in: a front end that wants the exactly
/// periodic output grid (every flap period sampled at the same phases) sets
/// `cfg.sample_rate_hz` to it; [`simulate`] never changes the rate by itself. Non-finite or
/// non-positive inputs come back unchanged. Example: 25.5 Hz at 10 kHz → 9996 Hz (392 samples
/// per period).
pub fn commensurate_sample_rate(flap_freq_hz: f64, sample_rate_hz: f64) -> f64 {
    if !(flap_freq_hz.is_finite() && sample_rate_hz.is_finite())
        || flap_freq_hz <= 0.0
        || sample_rate_hz <= 0.0
    {
        return sample_rate_hz;
    }
    (sample_rate_hz / flap_freq_hz).round().max(1.0) * flap_freq_hz
}

/// Names the mode and the inputs behind a response that overflowed (a parametrically unstable
/// mode over a long run): the solver's own message says why, not which field drives it.
fn name_overflow(e: WingbeatError, cfg: &SimConfig, k: usize) -> WingbeatError {
    match e {
        WingbeatError::NonFinite { what, detail } => {
            let num = crate::error::num;
            WingbeatError::NonFinite {
                what: format!(
                    "{what} of `modes[{k}]` ({} Hz) over `duration_s` = {} s",
                    num(cfg.modes[k].freq_hz),
                    num(cfg.duration_s)
                ),
                detail: format!(
                    "{detail} (the mode sits in a parametric-resonance tongue of the kinematics at `kinematics.flap_freq_hz` = {} Hz: raise `modes[{k}].zeta`, move the flap frequency, or lower the amplitudes)",
                    num(cfg.kinematics.flap_freq_hz)
                ),
            }
        }
        other => other,
    }
}

/// Runs a simulation.
pub fn simulate(cfg: &SimConfig) -> Result<SimResult> {
    simulate_reusing(cfg, &mut SeriesPool::new())
}

/// [`simulate`] writing the result's series into memory from `pool` (the same numbers): hand
/// each result back with [`SimResult::recycle`] when done with it, and a loop of runs stops
/// paying for fresh pages every time. (In air the run takes fresh series.)
pub fn simulate_reusing(cfg: &SimConfig, pool: &mut SeriesPool) -> Result<SimResult> {
    cfg.validate()?;
    if !cfg.aero.is_vacuum() {
        let geom = cfg.wing.as_deref().ok_or_else(crate::aero::no_wing_error)?;
        return crate::aero::simulate::simulate_in_air(cfg, geom);
    }
    let kin = cfg.kinematics.compile();
    check_cost_with(cfg, &kin, MAX_RUN_WORK, "simulate")?;
    let n = cfg.n_samples();
    let dt = 1.0 / cfg.sample_rate_hz;
    let mut t = pool.take(n);
    t.extend((0..n).map(|i| i as f64 * dt));
    let mut modes = Vec::with_capacity(cfg.modes.len());
    // One evaluation of the kinematics per solver time, shared by the modes that step alike.
    let memo = RotationMemo::new();
    let mean_s = mean_stiffness_coefficient(&kin);
    for (k, mode) in cfg.modes.iter().enumerate() {
        memo.rewind();
        let ode = ModalOde::sharing(&kin, mode, &memo);
        let mut p = propagate_responses_in(&ode, dt, n, ModalOde::TOTAL, cfg.ic(k), pool)
            .map_err(|e| name_overflow(e, cfg, k))?;
        let q = Responses {
            euler: std::mem::take(&mut p.q[ModalOde::EULER]),
            centrifugal: std::mem::take(&mut p.q[ModalOde::CENTRIFUGAL]),
            coriolis: std::mem::take(&mut p.q[ModalOde::CORIOLIS]),
            aerodynamic: Vec::new(),
            free: p.free,
            total: p.total,
        };
        let qdot_total = p.qdot_total;
        // The series' (max |x|, Σ x²) were taken as they were written.
        let st = |j: usize| (p.q_stats[j].max_abs(), p.q_stats[j].sum_sq());
        let contribution_percent = contributions_with(
            &q.euler,
            &q.centrifugal,
            &q.coriolis,
            &q.total,
            [
                ModalOde::EULER,
                ModalOde::CENTRIFUGAL,
                ModalOde::CORIOLIS,
                ModalOde::TOTAL,
            ]
            .map(st),
        );
        // Floquet reads Φ over the homogeneous period off this run's own grid when it holds it.
        let floquet = floquet::analyse_sampled(
            &ode,
            kin.wd / (2.0 * PI),
            averaged_freq_hz(mode, mean_s),
            p.monodromy,
            p.homogeneous.as_ref(),
        );
        let accuracy = Accuracy {
            method: if p.dense {
                "one-period Gauss–Legendre (order 8) propagator, dense output (Chebyshev degree 8) at the sample phases + exact period recursion"
            } else {
                "one-period Gauss–Legendre (order 8) propagator + exact period recursion"
            }
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
            air: None,
        });
    }
    Ok(assemble_in(cfg, t, modes, None, pool))
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
    /// The stiffness coefficient S(t) = α̇² cos²β + β̇², 1/s² (the time-varying part of the
    /// stiffness; the same for every mode). Times q_k it is the stiffness force, see
    /// [`crate::model::stiffness_force`].
    pub stiffness_coefficient: Vec<f64>,
    /// The aerodynamic force F_A,k(t) of the rigid motion in the config's medium (kg^½·m/s²,
    /// like the other terms; docs/model.md, "The wing in air"): the quasi-steady normal
    /// force and the added-mass reaction projected on the mode. Empty (and left out of the
    /// JSON) in a vacuum.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub aerodynamic: Vec<f64>,
}

/// Which modes [`sample_forces`] samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ModeSelection {
    /// Every mode of the config.
    #[default]
    All,
    /// Only the mode with this index (the others come back as `None`): the live lab view pays
    /// for one mode.
    Only(usize),
}

impl ModeSelection {
    /// `Only(k)` for `Some(k)`, `All` for `None`.
    pub fn from_option(mode: Option<usize>) -> Self {
        mode.map_or(ModeSelection::All, ModeSelection::Only)
    }

    /// Whether mode `k` is selected.
    pub fn includes(self, k: usize) -> bool {
        match self {
            ModeSelection::All => true,
            ModeSelection::Only(w) => w == k,
        }
    }
}

/// Samples the forcing terms and the stiffness coefficient of the selected modes at
/// t_i = i / rate, i = 0..n (the simulation's output grid): the kinematic state once per
/// sample, then [`crate::model::coefficients`] per mode; in a medium also the aerodynamic
/// force (which needs `cfg.wing`: an error names the density otherwise). Unselected modes are
/// `None`. The one force-sampling loop of the project; `cfg` must already be valid.
pub fn sample_forces(cfg: &SimConfig, which: ModeSelection) -> Result<Vec<Option<ForceSeries>>> {
    let kin = cfg.kinematics.compile();
    let n = cfg.n_samples();
    let dt = 1.0 / cfg.sample_rate_hz;
    let states: Vec<_> = (0..n).map(|i| kin.state(i as f64 * dt)).collect();
    let coefficient: Vec<f64> = states.iter().map(stiffness_coefficient).collect();
    let mut aero = aerodynamic_forces(cfg, &kin, n, dt)?;
    Ok(cfg
        .modes
        .iter()
        .enumerate()
        .map(|(k, m)| {
            if !which.includes(k) {
                return None;
            }
            let mut fs = ForceSeries {
                euler: Vec::with_capacity(n),
                centrifugal: Vec::with_capacity(n),
                coriolis: Vec::with_capacity(n),
                stiffness_coefficient: coefficient.clone(),
                aerodynamic: aero.get_mut(k).map(std::mem::take).unwrap_or_default(),
            };
            for s in &states {
                let c = crate::model::coefficients(m, s);
                fs.euler.push(c.euler);
                fs.centrifugal.push(c.centrifugal);
                fs.coriolis.push(c.coriolis);
            }
            Some(fs)
        })
        .collect())
}

/// The aerodynamic force of the rigid motion on every mode at t_i = i·`dt`, i < `n` (one vector
/// per mode), or none in a vacuum: the loads the air run integrates, read from the same
/// one-period table ([`crate::aero::ode::LoadTable`], within 1e-14 of each load group's size
/// of the quadrature sum) instead of a quadrature sum per sample.
fn aerodynamic_forces(cfg: &SimConfig, kin: &Compiled, n: usize, dt: f64) -> Result<Vec<Vec<f64>>> {
    if cfg.aero.is_vacuum() {
        return Ok(Vec::new());
    }
    let geom = cfg.wing.as_deref().ok_or_else(crate::aero::no_wing_error)?;
    let m = cfg.modes.len();
    geom.validate(m)?;
    cfg.aero.validate()?;
    let wing = crate::aero::AeroWing::build(geom, &cfg.aero)?;
    let mut ode = crate::aero::ode::AirOde::new(kin, &cfg.modes, &wing, &cfg.aero)?;
    ode.tabulate();
    let (mut f, mut c) = (vec![0.0; m], vec![0.0; m * m]);
    let mut out = vec![Vec::with_capacity(n); m];
    for i in 0..n {
        ode.loads(i as f64 * dt, &mut f, &mut c);
        for (o, v) in out.iter_mut().zip(&f) {
            o.push(*v);
        }
    }
    Ok(out)
}

/// Samples the forcing terms and the stiffness coefficient of every mode at t_i = i / rate,
/// i = 0..n (validates the config, then [`sample_forces`] with [`ModeSelection::All`]).
pub fn force_series(cfg: &SimConfig) -> Result<Vec<ForceSeries>> {
    cfg.validate()?;
    Ok(sample_forces(cfg, ModeSelection::All)?
        .into_iter()
        .flatten()
        .collect())
}
