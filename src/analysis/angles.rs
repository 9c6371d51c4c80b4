//! The rotation angles α (roll), β (pitch) and γ (yaw) sampled on a simulation's time grid
//! (paper §2.1), from the compiled kinematics — what a view needs to pose the wing at the same
//! instants as the responses, computed once per run rather than once per frame.

use crate::config::SimConfig;
use crate::error::Result;
use crate::kinematics::Compiled;
use serde::{Deserialize, Serialize};

/// α(t_i), β(t_i), γ(t_i), rad.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AngleSeries {
    /// Roll α about I, rad.
    pub alpha: Vec<f64>,
    /// Pitch β about J′, rad.
    pub beta: Vec<f64>,
    /// Yaw γ (small), rad.
    pub gamma: Vec<f64>,
}

/// The angles of `kin` at each of `times` (s).
pub fn angles_on(kin: &Compiled, times: &[f64]) -> AngleSeries {
    let n = times.len();
    let mut out = AngleSeries {
        alpha: Vec::with_capacity(n),
        beta: Vec::with_capacity(n),
        gamma: Vec::with_capacity(n),
    };
    for &t in times {
        let s = kin.state(t);
        out.alpha.push(s.alpha);
        out.beta.push(s.beta);
        out.gamma.push(s.gamma);
    }
    out
}

/// The angles of `cfg`'s kinematics on its simulation grid t_i = i / sample_rate_hz,
/// i = 0..n_samples (the same instants as [`crate::simulate::SimResult::t`]).
pub fn angle_series(cfg: &SimConfig) -> Result<AngleSeries> {
    cfg.validate()?;
    let kin = cfg.kinematics.compile();
    let dt = 1.0 / cfg.sample_rate_hz;
    let t: Vec<f64> = (0..cfg.n_samples()).map(|i| i as f64 * dt).collect();
    Ok(angles_on(&kin, &t))
}
