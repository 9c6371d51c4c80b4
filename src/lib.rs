//! # wingbeat
//!
//! Inertial-elastic dynamics of a flapping insect wing, after Jankauski & Shen,
//! "Dynamic Modeling of a Rotating Insect Wing". The pipeline, one module each:
//!
//! * [`kinematics`] — roll α, pitch β, yaw γ and the frame's angular velocity Ω (Eq. 1);
//! * [`model`] — the modal equation of motion, Eq. 13, and its three force terms;
//! * [`solve`] — exact-to-rounding period propagation plus two independent time steppers;
//! * [`floquet`] — monodromy, multipliers, stability, effective frequency and beat period;
//! * [`analysis`] — spectra, contributions, sweeps, initial-condition maps, strain;
//! * [`presets`] and [`config`] — the paper's data and the serde types every front end shares.
//!
//! The core is `f64` throughout, single-threaded, and uses no filesystem or web APIs, so it
//! builds natively and for `wasm32-unknown-unknown` alike.

pub mod error;
pub mod fem;
pub mod kinematics;
pub mod model;

pub use error::{Result, WingbeatError};
