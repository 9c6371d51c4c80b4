//! Parameter sweeps (paper §4.1, Fig. 6: contributions versus yaw amplitude γ0), generalised to
//! any scalar input: γ0, α0, β0 (amplitude of the first harmonic), flap frequency, damping.

use crate::config::SimConfig;
use crate::error::{Result, WingbeatError};
use crate::simulate::simulate_reusing;
use serde::{Deserialize, Serialize};

/// The swept quantity.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SweepParam {
    /// Yaw amplitude of the first harmonic, rad.
    Gamma0,
    /// Roll amplitude of the first harmonic, rad.
    Alpha0,
    /// Pitch amplitude of the first harmonic, rad.
    Beta0,
    /// Flap frequency, Hz.
    FlapHz,
    /// Damping ratio of every mode.
    Zeta,
}

impl SweepParam {
    /// The parameter's key in [`crate::params::PARAMS`] (`gamma0`, `alpha0`, `beta0`,
    /// `flap_hz`, `zeta`).
    pub fn key(self) -> &'static str {
        use crate::params as p;
        match self {
            SweepParam::Gamma0 => p::GAMMA0,
            SweepParam::Alpha0 => p::ALPHA0,
            SweepParam::Beta0 => p::BETA0,
            SweepParam::FlapHz => p::FLAP_HZ,
            SweepParam::Zeta => p::ZETA,
        }
    }

    /// Parses a CLI name.
    pub fn parse(s: &str) -> Result<Self> {
        Ok(match s {
            "gamma0" => SweepParam::Gamma0,
            "alpha0" => SweepParam::Alpha0,
            "beta0" => SweepParam::Beta0,
            "flap_hz" | "flap-hz" => SweepParam::FlapHz,
            "zeta" => SweepParam::Zeta,
            _ => {
                return Err(WingbeatError::invalid(
                    "sweep.param",
                    s,
                    "one of gamma0, alpha0, beta0, flap_hz, zeta",
                ))
            }
        })
    }
}

/// Sweep options.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepOptions {
    /// What to sweep.
    pub param: SweepParam,
    /// First value.
    pub from: f64,
    /// Last value.
    pub to: f64,
    /// Number of points (≥ 2), evenly spaced.
    pub points: usize,
}

/// Adds where an input error happened to its field, `{field} ({at})` (e.g. `kinematics.gamma
/// (sweep value 0.3)`); other errors come back unchanged. Sweeps and resonance maps name the
/// point that failed with it.
pub fn in_context(e: WingbeatError, at: &str) -> WingbeatError {
    e.map_field(|field| format!("{field} ({at})"))
}

/// Names the sweep value in an input error.
fn at_value(e: WingbeatError, v: f64) -> WingbeatError {
    in_context(e, &format!("sweep value {}", crate::error::num(v)))
}

/// `n` evenly spaced values from `from` to `to`, both included (n ≥ 2): value i is
/// from + (to − from)·i/(n − 1). The points of a sweep and the flap frequencies of a resonance
/// map.
pub fn grid(from: f64, to: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| from + (to - from) * i as f64 / (n - 1) as f64)
        .collect()
}

/// Refuses a number of points outside [2, [`MAX_POINTS`]], naming `field`.
pub fn check_points(field: &str, n: usize) -> Result<()> {
    if !(2..=MAX_POINTS).contains(&n) {
        return Err(WingbeatError::invalid(
            field,
            n,
            format!("an integer in [2, {MAX_POINTS}]"),
        ));
    }
    Ok(())
}

/// Most sweep points.
pub const MAX_POINTS: usize = 2001;

/// Most work one sweep may take: the sum over its points of each run's cost
/// ([`crate::simulate::run_cost`] in a vacuum, [`crate::aero::simulate::air_run_cost`] in
/// air; step equivalents, about 1 µs each natively), checked before the first point runs:
/// about 20 s natively. The paper's Fig. 6 sweep (31 points of 2 s) costs 3e5.
pub const MAX_SWEEP_WORK: f64 = 2.0e7;

/// How a sweep prices its points: in a vacuum [`crate::simulate::run_cost`]; in air
/// [`crate::aero::simulate::air_run_cost`] with the number of quadrature points of the
/// config's wing, counted once (a swept parameter changes neither the wing nor the air).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RunPricing {
    /// Every point runs in a vacuum.
    Vacuum,
    /// Every point runs in air on a quadrature of this many points.
    Air {
        /// Quadrature points of the wing.
        points: usize,
    },
}

impl RunPricing {
    /// The pricing of runs of `cfg` and of configs that differ from it only in a swept
    /// parameter. In air the wing's geometry and `cfg.aero` are checked and the quadrature
    /// is built once to count its points (the errors of [`crate::simulate::simulate`] for a
    /// density above 0 without a wing, bad shapes or bad air settings).
    pub fn of(cfg: &SimConfig) -> Result<RunPricing> {
        if cfg.aero.is_vacuum() {
            return Ok(RunPricing::Vacuum);
        }
        let geom = cfg.wing.as_deref().ok_or_else(crate::aero::no_wing_error)?;
        geom.validate(cfg.modes.len())?;
        cfg.aero.validate()?;
        let wing = crate::aero::AeroWing::build(geom, &cfg.aero)?;
        Ok(RunPricing::Air {
            points: wing.points.len(),
        })
    }

    /// The cost of one run of `cfg`, step equivalents.
    pub fn cost(self, cfg: &SimConfig) -> f64 {
        match self {
            RunPricing::Vacuum => crate::simulate::run_cost(cfg).0,
            RunPricing::Air { points } => crate::aero::simulate::air_run_cost(cfg, points),
        }
    }
}

/// Result at one sweep value for one mode.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepModePoint {
    /// Contribution shares, percent.
    pub contribution_percent: crate::analysis::contribution::Contributions,
    /// Floquet effective frequency, Hz.
    pub effective_freq_hz: f64,
    /// Beat period against the nearest flap harmonic, s.
    pub beat_period_s: Option<f64>,
    /// Peak |q_total|.
    pub peak_abs_q: f64,
    /// Whether the mode is Floquet-stable.
    pub stable: bool,
}

/// One sweep value.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepPoint {
    /// The swept value.
    pub value: f64,
    /// Per-mode results.
    pub modes: Vec<SweepModePoint>,
}

/// A sweep's output.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Sweep {
    /// What was swept.
    pub param: SweepParam,
    /// The points.
    pub points: Vec<SweepPoint>,
}

/// Applies `param = v` to a copy of `cfg`: [`crate::params::set_param`] with the parameter's
/// key, the one interpretation the lab's sliders and the CLI's flags use too.
pub fn apply(cfg: &SimConfig, param: SweepParam, v: f64) -> Result<SimConfig> {
    let mut c = cfg.clone();
    crate::params::set_param(&mut c, param.key(), v)?;
    Ok(c)
}

/// Runs the sweep; `progress(done, total)` is called after each point.
pub fn sweep(
    cfg: &SimConfig,
    opts: &SweepOptions,
    mut progress: impl FnMut(usize, usize),
) -> Result<Sweep> {
    check_points("sweep.points", opts.points)?;
    crate::error::check_range("sweep.from", opts.from, -1e6, 1e6, "")?;
    crate::error::check_range("sweep.to", opts.to, -1e6, 1e6, "")?;
    // The whole sweep's cost, before any work: every point's config is built (and checked)
    // first, and the sum of their run costs must fit.
    let values = grid(opts.from, opts.to, opts.points);
    let pricing = RunPricing::of(cfg)?;
    let air = matches!(pricing, RunPricing::Air { .. });
    let mut work = 0.0;
    for (i, &v) in values.iter().enumerate() {
        let c = apply(cfg, opts.param, v)?;
        c.validate().map_err(|e| at_value(e, v))?;
        let cost = pricing.cost(&c);
        if air && (cost.is_nan() || cost > crate::run::MAX_RUN_WORK) {
            // In air a point over the run's own cap would be refused only when its turn
            // came, after the points before it had run: refuse it here, naming its value.
            return Err(WingbeatError::ResourceCap {
                field: format!(
                    "sweep in air, one run (modes² × quadrature points × steps per flap period) at sweep value {}",
                    crate::error::num(v)
                ),
                requested: format!("{} step equivalents", crate::error::num(cost.round())),
                cap: format!("{} step equivalents", crate::error::num(crate::run::MAX_RUN_WORK)),
                why: "computing time; fewer modes, fewer `aero.strips` / `aero.chord_points`, or a higher flap frequency".into(),
            });
        }
        work += cost;
        if work.is_nan() || work > MAX_SWEEP_WORK {
            return Err(WingbeatError::ResourceCap {
                field: if air {
                    "sweep in air (points × each run's modes² × quadrature points × steps per flap period, and samples)"
                } else {
                    "sweep (points × each run's modes × steps per flap period, and samples)"
                }
                .into(),
                requested: format!(
                    "more than {} step equivalents by point {} of {} ({} = {})",
                    crate::error::num(MAX_SWEEP_WORK),
                    i + 1,
                    opts.points,
                    serde_json::to_value(opts.param)
                        .ok()
                        .and_then(|n| n.as_str().map(str::to_string))
                        .unwrap_or_default(),
                    crate::error::num(v)
                ),
                cap: format!("{} step equivalents", crate::error::num(MAX_SWEEP_WORK)),
                why: "computing time; use fewer points, a shorter duration or a lower sample rate, or keep the flap frequency up".into(),
            });
        }
    }
    let mut points = Vec::with_capacity(opts.points);
    // Each point writes into the previous point's series.
    let mut pool = crate::pool::SeriesPool::new();
    for (i, &v) in values.iter().enumerate() {
        let c = apply(cfg, opts.param, v)?;
        let r = simulate_reusing(&c, &mut pool).map_err(|e| at_value(e, v))?;
        let modes = r
            .modes
            .iter()
            .map(|m| SweepModePoint {
                contribution_percent: m.contribution_percent,
                effective_freq_hz: m.floquet.effective_freq_hz,
                beat_period_s: m.floquet.beat_period_s,
                peak_abs_q: crate::analysis::strain::peak_abs(&m.q.total),
                stable: m.floquet.stable,
            })
            .collect();
        points.push(SweepPoint { value: v, modes });
        r.recycle(&mut pool);
        progress(i + 1, opts.points);
    }
    Ok(Sweep {
        param: opts.param,
        points,
    })
}
