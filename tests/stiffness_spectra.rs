//! The stiffness force S(t)·q_k(t) (S = α̇²cos²β + β̇², the stiffness coefficient) is one
//! quantity in every front end: the CLI's `psd` prints the spectrum the core's
//! `analysis::spectra::mode_spectra` computes, which is Welch's PSD of S·q_k; and the same
//! numbers, hard-coded here as `STIFFNESS_FORCE_REFERENCE`, are what the wasm API's `spectra`
//! returns (tests/wasm_common/mod.rs, `stiffness_spectra_match_reference`). If the core
//! changes them on purpose, update both constants together (this test prints them).
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::analysis::psd::{welch, WelchOptions};
use wingbeat::analysis::spectra::mode_spectra;
use wingbeat::config::SimConfig;
use wingbeat::simulate::{force_series, simulate};

const TOL: f64 = 1e-12;

/// The shared case: the paper's forward flight for 0.4 s, Welch segments of 1024 samples.
fn case() -> (SimConfig, WelchOptions) {
    let cfg = SimConfig {
        duration_s: 0.4,
        ..SimConfig::paper()
    };
    let opts = WelchOptions {
        segment_len: 1024,
        ..WelchOptions::default()
    };
    (cfg, opts)
}

/// (mode, PSD bin, value): the stiffness-force PSD of [`case`], native x86_64.
pub const STIFFNESS_FORCE_REFERENCE: [(usize, usize, f64); 6] = [
    (0, 0, 4.408644852178396e-6),
    (0, 5, 6.626491355668749e-6),
    (0, 10, 1.1366600536284352e-6),
    (1, 0, 1.2682627419937116e-8),
    (1, 5, 1.63832584735356e-8),
    (1, 10, 5.1592553304086635e-9),
];

fn close_all(name: &str, got: &[f64], want: &[f64]) {
    assert_eq!(got.len(), want.len(), "{name}: length");
    let scale = want.iter().fold(0.0f64, |m, v| m.max(v.abs())).max(1e-300);
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        assert!((g - w).abs() <= TOL * scale, "{name}[{i}]: {g:e} vs {w:e}");
    }
}

#[cfg(feature = "cli")]
fn floats(v: &serde_json::Value) -> Vec<f64> {
    v.as_array()
        .expect("an array")
        .iter()
        .map(|x| x.as_f64().expect("a number"))
        .collect()
}

#[test]
fn core_stiffness_force_spectrum_is_the_psd_of_s_times_q() {
    let (cfg, opts) = case();
    let sim = simulate(&cfg).unwrap();
    let forces = force_series(&cfg).unwrap();
    let fd = Some(cfg.kinematics.flap_freq_hz);
    let mut got = Vec::new();
    for (k, (m, f)) in sim.modes.iter().zip(&forces).enumerate() {
        let s = mode_spectra(f, &m.q.total, cfg.sample_rate_hz, &opts, fd).unwrap();
        let product: Vec<f64> = f
            .stiffness_coefficient
            .iter()
            .zip(&m.q.total)
            .map(|(s, q)| s * q)
            .collect();
        let want = welch(&product, cfg.sample_rate_hz, &opts, fd).unwrap();
        close_all(&format!("mode {k}"), &s.stiffness_force.psd, &want.psd);
        for &(mode, bin, _) in &STIFFNESS_FORCE_REFERENCE {
            if mode == k {
                got.push((mode, bin, s.stiffness_force.psd[bin]));
            }
        }
    }
    for (mode, bin, v) in &got {
        println!("({mode}, {bin}, {v:e}),");
    }
    for ((mode, bin, v), (_, _, want)) in got.iter().zip(&STIFFNESS_FORCE_REFERENCE) {
        assert!(
            (v - want).abs() <= TOL * want.abs(),
            "reference mode {mode} bin {bin}: {v:e} vs {want:e}"
        );
    }
}

#[cfg(feature = "cli")]
#[test]
fn cli_psd_prints_the_core_stiffness_spectra() {
    use serde_json::Value;
    use std::process::Command;
    let (cfg, opts) = case();
    let out = Command::new(env!("CARGO_BIN_EXE_wingbeat"))
        .args(["psd", "--duration", "0.4", "--segment-len", "1024"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    let sim = simulate(&cfg).unwrap();
    let forces = force_series(&cfg).unwrap();
    let fd = Some(cfg.kinematics.flap_freq_hz);
    for (k, (m, f)) in sim.modes.iter().zip(&forces).enumerate() {
        let want = mode_spectra(f, &m.q.total, cfg.sample_rate_hz, &opts, fd).unwrap();
        let got = &v["modes"][k];
        close_all(
            &format!("modes[{k}].stiffness_force"),
            &floats(&got["stiffness_force"]["psd"]),
            &want.stiffness_force.psd,
        );
        let coefficient = welch(&f.stiffness_coefficient, cfg.sample_rate_hz, &opts, fd).unwrap();
        close_all(
            &format!("modes[{k}].stiffness_coefficient"),
            &floats(&got["stiffness_coefficient"]["psd"]),
            &coefficient.psd,
        );
        for &(mode, bin, value) in &STIFFNESS_FORCE_REFERENCE {
            if mode == k {
                let g = got["stiffness_force"]["psd"][bin].as_f64().unwrap();
                assert!((g - value).abs() <= TOL * value.abs(), "{g:e} vs {value:e}");
            }
        }
    }
    // The old, ambiguous key is gone, and `--help` says what each key is.
    assert!(v["modes"][0].get("softening").is_none());
    let help = Command::new(env!("CARGO_BIN_EXE_wingbeat"))
        .args(["psd", "--help"])
        .output()
        .unwrap();
    let help = String::from_utf8_lossy(&help.stdout);
    assert!(help.contains("`stiffness_coefficient`"), "{help}");
    assert!(help.contains("`stiffness_force`"), "{help}");
    assert!(help.contains("S(t)·q_k(t)"), "{help}");
}
