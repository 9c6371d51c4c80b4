//! The memory ceiling of docs/limits.md ("Memory": no run above about 1.5 GB) at a scale a
//! test can afford: each kind of run whose memory grows with the run's size is run by the
//! CLI binary in a child process at 1/8 of its cap, and its peak resident memory (from
//! `/usr/bin/time -v`, or, where that tool is missing, an address-space limit set with
//! `ulimit -v` that the run must finish under) must stay within 1/8 of the ceiling plus a
//! fixed base. A run that is linear in its size and passes here stays under the ceiling at
//! the cap; `wingbeat psd` at 4 modes peaked at 4.3 GB before issue 20 (about 540 MB at this
//! scale), `wingbeat sense` with 60 points at 13.5 GB; both would fail here.
#![cfg(all(not(target_arch = "wasm32"), target_os = "linux"))]

use std::process::Command;

/// The documented ceiling, MB.
const CEILING_MB: f64 = 1500.0;
/// What a run costs before its size matters (binary, allocator, a small run), MB.
const BASE_MB: f64 = 60.0;
/// The scale of the runs here relative to their caps.
const SCALE: f64 = 1.0 / 8.0;

fn budget_mb() -> f64 {
    BASE_MB + (CEILING_MB - BASE_MB) * SCALE
}

/// Runs `wingbeat args` with the output to /dev/null; the peak RSS in MB, or `None` when it
/// ran under the address-space limit instead (no /usr/bin/time). Panics when the run fails.
fn peak_mb(args: &[&str]) -> Option<f64> {
    let bin = env!("CARGO_BIN_EXE_wingbeat");
    if std::path::Path::new("/usr/bin/time").exists() {
        let out = Command::new("/usr/bin/time")
            .arg("-v")
            .arg(bin)
            .args(args)
            .stdout(std::process::Stdio::null())
            .output()
            .expect("/usr/bin/time runs");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{args:?} failed: {err}");
        let kb: f64 = err
            .lines()
            .find_map(|l| {
                l.trim()
                    .strip_prefix("Maximum resident set size (kbytes): ")
            })
            .and_then(|v| v.trim().parse().ok())
            .unwrap_or_else(|| panic!("no peak RSS in {err}"));
        Some(kb / 1024.0)
    } else {
        // virtual memory is at least the resident memory, so a run that finishes under the
        // limit stayed under it
        let kb = (budget_mb() * 1024.0 * 2.0) as u64; // allocator and thread reservations
        let quoted: Vec<String> = args.iter().map(|a| format!("'{a}'")).collect();
        let status = Command::new("sh")
            .arg("-c")
            .arg(format!(
                "ulimit -v {kb} && exec '{bin}' {} > /dev/null",
                quoted.join(" ")
            ))
            .status()
            .expect("sh runs");
        assert!(
            status.success(),
            "{args:?} failed under a {kb} kB address-space limit"
        );
        None
    }
}

/// A modes file with four modes (the paper's two plus 70 and 95 Hz), as the cap measurements.
fn four_modes(test: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("wingbeat-mem-{test}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("modes4.json");
    let mode = |f: f64, a: [f64; 2]| serde_json::json!({"freq_hz": f, "a": a});
    let doc = serde_json::json!({"modes": [
        mode(62.5, [7.552e-6, 9.34e-7]), mode(86.9, [-1.728e-6, -3.3e-8]),
        mode(70.0, [5e-6, 1e-6]), mode(95.0, [-2e-6, 1e-7])]});
    std::fs::write(&p, doc.to_string()).unwrap();
    p
}

#[test]
fn runs_at_an_eighth_of_their_caps_stay_within_an_eighth_of_the_ceiling() {
    let modes = four_modes("caps");
    let m = modes.to_str().unwrap();
    // samples × modes = 8e6 / 8 = 1e6: 4 modes × 250 000 samples (24.9999 s at 10 kHz)
    let dur = "24.9999";
    // psd's spectrum cap for 4 modes is a 500 000-sample segment; the run has 250 000
    // an FE wing of 4 modes for `sense` (its Δε series at 4 points: 1/8 of the series cap)
    let fe = modes.with_file_name("fe4.json");
    let out = Command::new(env!("CARGO_BIN_EXE_wingbeat"))
        .args(["modes", "--mesh-size-mm", "3", "--n-modes", "4"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    std::fs::write(&fe, &out.stdout).unwrap();
    let f = fe.to_str().unwrap();
    let runs: [&[&str]; 4] = [
        &["simulate", "--modes", m, "--duration", dur],
        &[
            "simulate",
            "--modes",
            m,
            "--duration",
            dur,
            "--format",
            "csv",
        ],
        &[
            "psd",
            "--modes",
            m,
            "--duration",
            dur,
            "--segment-len",
            "250000",
        ],
        &[
            "sense",
            "--modes",
            f,
            "--duration",
            dur,
            "--points",
            "5,-5;6,-5;7,-5;8,-5",
        ],
    ];
    let budget = budget_mb();
    let mut report = Vec::new();
    for a in &runs {
        if let Some(mb) = peak_mb(a) {
            report.push(format!("{a:?}: {mb:.0} MB"));
            assert!(mb <= budget, "{a:?} peaked at {mb:.0} MB, over {budget:.0} MB (1/8 of the 1.5 GB ceiling plus {BASE_MB} MB): {report:?}");
        }
    }
    eprintln!("{}", report.join("\n"));
    let _ = std::fs::remove_dir_all(modes.parent().unwrap());
}

/// The psd's output cap is checked before any work: far over it, the refusal is immediate
/// and names the segment flag.
#[test]
fn psd_output_over_its_cap_is_refused_first_by_name() {
    let modes = four_modes("refusal");
    let m = modes.to_str().unwrap();
    let t0 = std::time::Instant::now();
    let out = Command::new(env!("CARGO_BIN_EXE_wingbeat"))
        .args([
            "psd",
            "--modes",
            m,
            "--duration",
            "199.99",
            "--segment-len",
            "2000000",
        ])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("--segment-len") && err.contains("spectrum bins"),
        "{err}"
    );
    assert!(
        t0.elapsed().as_secs_f64() < 5.0,
        "refused only after {:?}",
        t0.elapsed()
    );
    let _ = std::fs::remove_dir_all(modes.parent().unwrap());
}
