//! Fuzz target: the JSON readers of a run — a `SimConfig` (`wingbeat simulate --config`,
//! wasm `simulate`), a modes document (`--modes FILE`, wasm `modesFromJson`) and an FE input
//! (`wingbeat modes` JSON, wasm `feModes`). Never a panic; a parsed config that validates and
//! is cheap enough is simulated, and its outputs must be finite.
#![no_main]

use libfuzzer_sys::fuzz_target;
use wingbeat::config::SimConfig;
use wingbeat::error::WingbeatError;

/// Runs the simulation only when its estimated work is below this (step equivalents), so
/// that the fuzzer keeps a high execution rate; the cap itself is checked for every input.
const FUZZ_RUN_WORK: f64 = 5.0e3;

fn message_ok(e: &WingbeatError) {
    assert!(!e.to_string().trim().is_empty(), "empty error message");
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    match SimConfig::from_json(text) {
        Err(e) => message_ok(&e),
        Ok(cfg) => match cfg.validate() {
            Err(e) => message_ok(&e),
            Ok(()) => {
                let (cost, _) = wingbeat::simulate::run_cost(&cfg);
                assert!(!cost.is_nan(), "run cost NaN");
                if let Err(e) = wingbeat::simulate::check_run_cost(
                    &cfg,
                    wingbeat::simulate::MAX_RUN_WORK,
                    "simulate",
                ) {
                    message_ok(&e);
                } else if cost <= FUZZ_RUN_WORK && cfg.n_samples() <= 4000 {
                    match wingbeat::simulate::simulate(&cfg) {
                        Err(e) => message_ok(&e),
                        Ok(r) => {
                            assert!(r.t.iter().all(|v| v.is_finite()));
                            for m in &r.modes {
                                assert!(
                                    m.qdot_total.iter().all(|v| v.is_finite()),
                                    "non-finite response returned as Ok"
                                );
                            }
                            assert!(serde_json::to_string(&r).is_ok());
                        }
                    }
                }
            }
        },
    }
    if let Err(e) = wingbeat::modes_doc::read_modes_document(text, "fuzz modes") {
        message_ok(&e);
    }
    match wingbeat::error::parse_json::<wingbeat::fem::FemInput>(text, "fuzz FE input") {
        Err(e) => message_ok(&e),
        Ok(input) => {
            // the checks that run before meshing
            if let Err(e) = input.material.validate() {
                message_ok(&e);
            }
            if let Err(e) = wingbeat::fem::resolved_mesh_size_mm(&input) {
                message_ok(&e);
            }
            if let Err(e) = wingbeat::fem::node_cap(&input) {
                message_ok(&e);
            }
        }
    }
});
