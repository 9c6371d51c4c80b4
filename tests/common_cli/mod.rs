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
