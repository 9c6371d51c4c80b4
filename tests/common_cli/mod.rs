//! The one runner of the `wingbeat` binary for the CLI tests (`mod common_cli;`).
#![allow(dead_code)]

use std::process::Command;
use std::time::{Duration, Instant};

/// `wingbeat ARGS`: exit code (−1 when killed by a signal), stdout, stderr and wall time.
pub fn run_timed(args: &[&str]) -> (i32, String, String, Duration) {
    let t0 = Instant::now();
    let out = Command::new(env!("CARGO_BIN_EXE_wingbeat"))
        .args(args)
        .output()
        .expect("the wingbeat binary runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
        t0.elapsed(),
    )
}

/// [`run_timed`] without the time.
pub fn run(args: &[&str]) -> (i32, String, String) {
    let (code, out, err, _) = run_timed(args);
    (code, out, err)
}

/// Writes a small `wingbeat modes` document (the default wing, 2 mm elements, 3 modes) into a
/// fresh temporary folder named after `tag`; returns the folder (remove it when done) and the
/// file's path.
pub fn modes_document(tag: &str) -> (std::path::PathBuf, String) {
    let dir = std::env::temp_dir().join(format!("wingbeat_{tag}_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("modes.json");
    let (code, out, err) = run(&["modes", "--mesh-size-mm", "2", "--n-modes", "3"]);
    assert_eq!(code, 0, "{err}");
    std::fs::write(&file, out).unwrap();
    let f = file.to_str().unwrap().to_string();
    (dir, f)
}
