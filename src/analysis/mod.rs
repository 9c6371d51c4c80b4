//! Analyses built on the solver: spectra, force contributions, parameter sweeps, the
//! initial-condition map, beat measurement, strain (paper §3.3–§4.4) and sensing body rotation
//! through strain (issue 14).

pub mod angles;
pub mod beat;
pub mod contribution;
pub mod ic_map;
pub mod psd;
pub mod resonance;
pub mod sensing;
pub mod spectra;
pub mod strain;
pub mod sweep;
