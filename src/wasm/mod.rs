//! The browser lab's WebAssembly API (feature `web`), built with wasm-bindgen.
//!
//! Feature `web-live` alone compiles the live analysis ([`sim`], [`analysis`]) and the wing's
//! outlines, parameter tables and FE inputs ([`wing`]): the small module the lab loads first and paints its
//! first plot from, while the full module (`web`: also the FE wing's strains and modes files, [`fe`],
//! [`sensing`], [`classify`], `reproduce` and, with `render`, the renderer) loads behind it.
//!
//! It exposes the same inputs as the CLI — [`SimConfig`](crate::config::SimConfig),
//! [`WelchOptions`](crate::analysis::psd::WelchOptions),
//! [`SweepOptions`](crate::analysis::sweep::SweepOptions),
//! [`IcMapOptions`](crate::analysis::ic_map::IcMapOptions) — as plain JS objects, and returns
//! JS objects whose small metadata comes through serde and whose long series are
//! `Float64Array`s (copied once out of wasm memory, never JSON). One file per topic:
//!
//! * [`marshal`]: JS values in and out (the seam itself);
//! * [`sim`]: configs, limits, the lab's `parameters` and `applyOverrides`, `simulate`,
//!   `forceSeries`, `anglesAt`, `kinematicsFromCsv`, `reproduce`;
//! * [`analysis`]: `psd`, `spectra`, `analyze`, `envelope`, `sweep`, `icMap`,
//!   `resonanceMap`;
//! * [`fe`]: `feModes`, the shell finite elements;
//! * [`wing`]: the lab's own wing: `planforms`, `parsePlanform`, `checkPlanform`,
//!   `wingParameters`, `materialPresets`, `wingInput`, `modalStrainAt`, `strainField`,
//!   `modesFromJson`;
//! * `view` (wasm32 with feature `render`): `WingView`, the 3-D view of the flexing wing;
//! * [`types`]: the TypeScript declarations of all of the above;
//! * [`helpers`]: plain-Rust helpers (web caps, series checks, the fast envelope, ...) tested natively.
//!
//! Every entry point returns `Result<_, JsError>`; the error message is the core's
//! [`WingbeatError`](crate::WingbeatError) text, which names the field and the allowed range.
//! Every argument is taken as a `JsValue` and read through the checks in [`marshal`] (type
//! without coercion, length before any copy into wasm memory, finiteness, size and depth of
//! objects), objects are deserialised with their path tracked (a type error says where),
//! validated by the core, then checked against the web caps in [`helpers`], so nothing reaches
//! code that could panic. tests/js/wasm_hostile_inputs.test.mjs calls every export with random
//! values of every JS type and checks this. Should a bug panic anyway, the panic hook logs it
//! (`console_error_panic_hook`) and schedules a fresh instance: the call that panicked throws a
//! `RuntimeError` (wasm32 aborts on panic), the next call runs on a new instance, so one bug
//! cannot leave the page's module dead.

pub mod analysis;
#[cfg(feature = "web")]
pub mod classify;
#[cfg(feature = "web")]
pub mod fe;
// Some readers and checks serve only the full module's exports.
#[cfg_attr(not(feature = "web"), allow(dead_code))]
pub mod helpers;
#[cfg_attr(not(feature = "web"), allow(dead_code))]
pub mod marshal;
#[cfg(feature = "web")]
pub mod sensing;
pub mod sim;
pub mod types;
#[cfg(all(feature = "render", target_arch = "wasm32"))]
pub mod view;
#[cfg_attr(not(feature = "web"), allow(dead_code, unused_imports))]
pub mod wing;

pub use analysis::{analyze, envelope, ic_map, psd, resonance_map, spectra, sweep};
#[cfg(feature = "web")]
pub use classify::classify_rotation;
#[cfg(feature = "web")]
pub use fe::fe_modes;
pub use sim::{
    angles_at, apply_overrides, default_config, force_series, kinematics_from_csv, limits,
    parameters, simulate, validate_config,
};
#[cfg(feature = "web")]
pub use sim::{reproduce, reproduce_text};
pub use wing::{
    check_planform, material_presets, parse_planform, planforms, wing_input, wing_parameters,
};
#[cfg(feature = "web")]
pub use wing::{modal_strain_at, modes_from_json, strain_field};

use wasm_bindgen::prelude::*;

/// Installs the panic hook (runs when the module is instantiated). Designed never to fire: it
/// logs the panic and has wasm-bindgen replace the instance before the next call (objects made
/// by the old one, such as a `WingView`, then throw "stale object" instead of trapping).
#[wasm_bindgen(start)]
pub fn start() {
    std::panic::set_hook(Box::new(|info| {
        console_error_panic_hook::hook(info);
        wasm_bindgen::handler::schedule_reinit();
    }));
}

/// The crate version.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}
