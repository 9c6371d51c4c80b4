//! # wingbeat
//!
//! Inertial-elastic dynamics of a flapping insect wing, after Jankauski & Shen,
//! "Dynamic Modeling of a Rotating Insect Wing". The pipeline, one module each:
//!
//! * [`kinematics`] — roll α, pitch β, yaw γ and the frame's angular velocity Ω (Eq. 1);
//! * [`model`] — the modal equation of motion, Eq. 13, and its three force terms;
//! * [`solve`] — exact-to-rounding period propagation plus two independent time steppers;
//! * [`floquet`] — monodromy, multipliers, stability, effective frequency and beat period;
//! * [`simulate`] — the driver: a [`config::SimConfig`] in, responses and summaries out;
//! * [`analysis`] — spectra, contributions, sweeps, initial-condition maps, beats, strain;
//! * [`reproduce`] — every claim of the paper's §3–4 against what wingbeat computes;
//! * [`presets`] and [`config`] — the paper's data and the serde types every front end shares.
//!
//! The core is `f64` throughout, single-threaded, and uses no filesystem or web APIs, so it
//! builds natively and for `wasm32-unknown-unknown` alike.

// Numerical kernels index several parallel arrays with one loop variable; that reads better
// than zipped iterators there.
#![allow(clippy::needless_range_loop)]

pub mod analysis;
pub mod config;
pub mod error;
pub mod floquet;
pub mod kinematics;
pub mod model;
pub mod presets;
#[cfg(feature = "render")]
pub mod render;
pub mod reproduce;
pub mod simulate;
pub mod solve;

pub use error::{Result, WingbeatError};
