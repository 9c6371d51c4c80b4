//! The spectra of one mode's Eq. 13 terms (paper Fig. 4): the three force terms, the
//! stiffness force S(t)·q_k and the total response, each a Welch PSD on the output grid.
//!
//! The CLI's `psd` command and the wasm API's `analyze`/`spectra` both build their per-mode
//! spectra here, so "stiffness force" names the same quantity everywhere.

use crate::analysis::psd::{welch, Spectrum, WelchOptions};
use crate::error::Result;
use crate::model::stiffness_force;
use crate::simulate::ForceSeries;
use serde::{Deserialize, Serialize};

/// Welch PSDs of one mode's terms.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ModeSpectra {
    /// Euler force.
    pub euler: Spectrum,
    /// Centrifugal force.
    pub centrifugal: Spectrum,
    /// Coriolis force.
    pub coriolis: Spectrum,
    /// Stiffness force S(t)·q_k(t), S = α̇² cos²β + β̇² (same units as the force terms).
    pub stiffness_force: Spectrum,
    /// Total response q_k(t).
    pub total: Spectrum,
    /// Aerodynamic force F_A,k(t) (in a medium; left out in a vacuum).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub aerodynamic: Option<Spectrum>,
}

/// The spectra of one mode: `forces` sampled by [`crate::simulate::sample_forces`] and
/// `q_total` the same mode's total response on the same grid. Peaks are labelled in
/// multiples of `flap_hz` when given.
pub fn mode_spectra(
    forces: &ForceSeries,
    q_total: &[f64],
    sample_rate_hz: f64,
    opts: &WelchOptions,
    flap_hz: Option<f64>,
) -> Result<ModeSpectra> {
    let psd = |x: &[f64]| welch(x, sample_rate_hz, opts, flap_hz);
    Ok(ModeSpectra {
        euler: psd(&forces.euler)?,
        centrifugal: psd(&forces.centrifugal)?,
        coriolis: psd(&forces.coriolis)?,
        stiffness_force: psd(&stiffness_force(&forces.stiffness_coefficient, q_total))?,
        total: psd(q_total)?,
        aerodynamic: if forces.aerodynamic.is_empty() {
            None
        } else {
            Some(psd(&forces.aerodynamic)?)
        },
    })
}
