//! The studies that are per-mode by construction refuse a fluid by name instead of computing a
//! vacuum silently: the initial-condition map (it superposes one mode's free responses) and
//! the resonance map (per-mode Floquet numbers). A vacuum config still runs.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::analysis::ic_map::{ic_map, IcMapOptions};
use wingbeat::analysis::resonance::{resonance_map, ResonanceOptions};
use wingbeat::config::SimConfig;

fn in_air() -> SimConfig {
    SimConfig {
        duration_s: 0.2,
        aero: wingbeat::aero::AeroConfig::with_density(1.2),
        ..SimConfig::paper()
    }
}

#[test]
fn ic_and_resonance_maps_refuse_a_fluid_by_name() {
    let opts = IcMapOptions {
        n_q: 3,
        n_qdot: 3,
        ..IcMapOptions::default()
    };
    let e = ic_map(&in_air(), &opts).unwrap_err().to_string();
    assert!(
        e.contains("aero.air_density_kg_m3") && e.contains("initial-condition map"),
        "{e}"
    );
    let vac = SimConfig {
        aero: Default::default(),
        ..in_air()
    };
    assert!(ic_map(&vac, &opts).is_ok());
    let r = ResonanceOptions {
        from_hz: 20.0,
        to_hz: 30.0,
        points: 3,
        alpha0_values: None,
    };
    let e = resonance_map(&in_air(), &r, |_, _| {})
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("aero.air_density_kg_m3") && e.contains("resonance map"),
        "{e}"
    );
    assert!(resonance_map(&vac, &r, |_, _| {}).is_ok());
}
