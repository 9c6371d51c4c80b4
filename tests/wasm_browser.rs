//! The wasm API against the core, in headless Chromium (wasm-bindgen-test-runner + chromedriver). Run:
//! `CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER=wasm-bindgen-test-runner cargo test --release
//!  --target wasm32-unknown-unknown --no-default-features --features web,render --test wasm_browser` with chromedriver on PATH
//! (`npm run test:wasm` does this and the Chromium suite).
#![cfg(target_arch = "wasm32")]

wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

mod wasm_common;
use wasm_bindgen_test::wasm_bindgen_test;

#[wasm_bindgen_test]
fn simulate_matches_core() {
    wasm_common::simulate_matches_core();
}

#[wasm_bindgen_test]
fn paper_reference_numbers() {
    wasm_common::paper_reference_numbers();
}

#[wasm_bindgen_test]
fn analyze_matches_core() {
    wasm_common::analyze_matches_core();
}

#[wasm_bindgen_test]
fn coriolis_force_peaks_at_twice_the_flap_frequency() {
    wasm_common::coriolis_force_peaks_at_twice_the_flap_frequency();
}

#[wasm_bindgen_test]
fn psd_matches_core() {
    wasm_common::psd_matches_core();
}

#[wasm_bindgen_test]
fn sweep_matches_core_and_reports_progress() {
    wasm_common::sweep_matches_core_and_reports_progress();
}

#[wasm_bindgen_test]
fn ic_map_matches_core() {
    wasm_common::ic_map_matches_core();
}

#[wasm_bindgen_test]
fn defaults_limits_reproduce() {
    wasm_common::defaults_limits_reproduce();
}

#[wasm_bindgen_test]
fn reproduce_matches_core() {
    wasm_common::reproduce_matches_core();
}

#[wasm_bindgen_test]
fn bad_input_names_the_field() {
    wasm_common::bad_input_names_the_field();
}

#[wasm_bindgen_test]
fn fe_modes_match_core() {
    wasm_common::fe_modes_match_core();
}

#[wasm_bindgen_test]
fn angles_match_core() {
    wasm_common::angles_match_core();
}

#[wasm_bindgen_test]
fn stiffness_spectra_match_reference() {
    wasm_common::stiffness_spectra_match_reference();
}

#[wasm_bindgen_test]
fn ts_declarations_match_results() {
    wasm_common::ts_declarations_match_results();
}
