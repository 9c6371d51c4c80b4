//! Reference numbers of the paper case, computed natively and hard-coded in the wasm test
//! suites (tests/wasm_api.rs, tests/wasm_browser.rs) as an independent check that the wasm
//! build computes what the native build computes. If the core changes these on purpose, update
//! `PAPER_REFERENCE` here and in tests/wasm_common/mod.rs together (this test prints them).

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::config::SimConfig;
use wingbeat::simulate::simulate;

/// (name, value): native x86_64, Rust 1.95, SimConfig::paper() (2 s at 10 kHz, ζ = 0).
pub const PAPER_REFERENCE: [(&str, f64); 8] = [
    ("mode1.effective_freq_hz", 6.030639396854428e1),
    ("mode2.effective_freq_hz", 8.534646215176787e1),
    ("mode1.beat_period_vs_2fd_s", 9.70271467452204e-2),
    ("mode1.contribution.euler", 1.7770071621035974e1),
    ("mode1.contribution.centrifugal", 3.1608272606377934e0),
    ("mode1.contribution.coriolis", 5.379178730437413e1),
    ("mode2.contribution.coriolis", 2.463981694964878e1),
    ("mode1.q_total[12345]", -6.941943076968708e-7),
];

fn computed() -> Vec<(&'static str, f64)> {
    let r = simulate(&SimConfig::paper()).unwrap();
    let (m1, m2) = (&r.modes[0], &r.modes[1]);
    vec![
        ("mode1.effective_freq_hz", m1.floquet.effective_freq_hz),
        ("mode2.effective_freq_hz", m2.floquet.effective_freq_hz),
        (
            "mode1.beat_period_vs_2fd_s",
            m1.floquet.beat_period_vs_2fd_s.unwrap(),
        ),
        ("mode1.contribution.euler", m1.contribution_percent.euler),
        (
            "mode1.contribution.centrifugal",
            m1.contribution_percent.centrifugal,
        ),
        (
            "mode1.contribution.coriolis",
            m1.contribution_percent.coriolis,
        ),
        (
            "mode2.contribution.coriolis",
            m2.contribution_percent.coriolis,
        ),
        ("mode1.q_total[12345]", m1.q.total[12345]),
    ]
}

#[test]
fn paper_reference_numbers() {
    let got = computed();
    for (name, v) in &got {
        println!("    (\"{name}\", {v:e}),");
    }
    for ((name, want), (name2, got)) in PAPER_REFERENCE.iter().zip(got) {
        assert_eq!(*name, name2);
        let rel = ((got - want) / want).abs();
        assert!(
            rel <= 1e-12,
            "{name}: computed {got:e}, reference {want:e} (rel {rel:e})"
        );
    }
}
