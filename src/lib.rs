//! # wingbeat
//!
//! Inertial-elastic dynamics of a flapping insect wing, after Jankauski & Shen,
//! "Dynamic Modeling of a Rotating Insect Wing". The pipeline, one module each:
//!
//! * [`kinematics`] — roll α, pitch β, yaw γ and the frame's angular velocity Ω (Eq. 1);
//!   [`kinematics_table`] turns a measured CSV table of them into periodic kinematics;
//!   [`disturbance`] draws a seeded, non-periodic angular-velocity disturbance;
//! * [`model`] — the modal equation of motion, Eq. 13, and its three force terms;
//! * [`aero`] — the wing in air: quadrature over the FE wing, aerodynamic force, damping and
//!   added mass, the coupled solve and its Floquet analysis;
//! * [`solve`] — exact-to-rounding period propagation plus two independent time steppers;
//! * [`floquet`] — monodromy, multipliers, stability, effective frequency and beat period;
//! * [`simulate`] — the driver: a [`config::SimConfig`] in, responses and summaries out
//!   ([`run`]: the result types and work budget it shares with the air path);
//! * [`analysis`] — spectra, contributions, sweeps, initial-condition maps, beats, strain;
//! * [`fem`] — shell finite elements: modes of any planform with camber (paper §3.1);
//! * [`reproduce`] — every claim of the paper's §3–4 against what wingbeat computes;
//! * [`modes_doc`] — reading a `wingbeat modes` document (CLI `--modes` and the lab);
//! * [`presets`] and [`config`] — the paper's data and the serde types every front end shares;
//! * [`ranges`] and [`params`] — every input's accepted range as plain data, and the one
//!   interpretation of a named value (the lab's sliders, the CLI's flags, the sweeps).
//!
//! Which module may use which is fixed by the layer list in ARCHITECTURE.md, checked with the
//! absence of import cycles by `tests/module_graph.rs`.
//!
//! The core is `f64` throughout, single-threaded, and uses no filesystem or web APIs, so it
//! builds natively and for `wasm32-unknown-unknown` alike.
//!
//! ```
//! use wingbeat::config::SimConfig;
//! use wingbeat::simulate::simulate;
//!
//! // The paper's forward flight: α0 = 0.8, β0 = 0.5, γ0 = 0.2 rad at 25 Hz, Tables 3–6.
//! let r = simulate(&SimConfig::paper()).unwrap();
//! let m1 = &r.modes[0];
//! // Centrifugal softening lowers mode 1 from 62.5 Hz to about 60.3 Hz ...
//! assert!((m1.floquet.effective_freq_hz - 60.31).abs() < 0.01);
//! // ... so its Coriolis response (forced at 2 × 25 Hz) beats with a period of about 0.097 s.
//! assert!((m1.floquet.beat_period_s.unwrap() - 0.097).abs() < 0.001);
//! // Mode 1 is Coriolis-dominated at γ0 = 0.2.
//! assert_eq!(m1.contribution_percent.dominant().0, "coriolis");
//! ```

// Numerical kernels index several parallel arrays with one loop variable; that reads better
// than zipped iterators there.
#![allow(clippy::needless_range_loop)]

pub mod aero;
pub mod analysis;
pub mod config;
pub mod disturbance;
pub mod error;
pub mod fem;
pub mod floquet;
pub mod kinematics;
pub mod kinematics_table;
pub mod model;
pub mod modes_doc;
pub mod parallel;
pub mod params;
pub mod pool;
pub mod presets;
pub mod ranges;
#[cfg(feature = "render")]
pub mod render;
pub mod reproduce;
pub mod run;
pub mod simulate;
pub mod solve;
pub mod transient;
#[cfg(feature = "web-live")]
pub mod wasm;

pub use error::{Result, WingbeatError};

// Building this crate itself for wasm32 without its JS API gives a cdylib that exports
// nothing (a 489-byte module from a plain `wasm-pack build`): refuse that loudly. Only when
// wingbeat is the package being built (cargo sets CARGO_PRIMARY_PACKAGE then); as a
// dependency of another wasm crate the Rust core builds without the API as before.
#[cfg(all(target_arch = "wasm32", not(feature = "web-live")))]
const _: () = assert!(
    option_env!("CARGO_PRIMARY_PACKAGE").is_none(),
    "wingbeat for wasm32 needs its JS API: build with `--no-default-features --features web,render` \
     (wasm-pack: `wasm-pack build --target web -- --no-default-features --features web,render`; see docs/embedding.md, section 3)"
);
