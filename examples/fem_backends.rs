//! Times `compute_modes` (mesh + assemble + 6 modes) of the default wing per sparse
//! factorisation backend and mesh size, and checks that the backends agree.
//!
//! `cargo run --release --example fem_backends --features faer [-- REPS]`
//! (without `--features faer` only the skyline backend runs).

use std::time::Instant;
use wingbeat::fem::{compute_modes_with, Backend, EigenOptions, FemInput};

fn main() {
    let reps: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(5);
    let backends: Vec<Backend> = [Backend::Skyline, Backend::Faer]
        .into_iter()
        .filter(|b| b.available())
        .collect();
    println!("| mesh (mm) | nodes | free DOFs | backend | median (ms) | min (ms) | max rel. Δf vs skyline |");
    println!("|---|---|---|---|---|---|---|");
    for h in [2.0, 1.25, 1.0, 0.75] {
        let input = FemInput {
            mesh_size_mm: Some(h),
            ..FemInput::default()
        };
        let mut reference: Option<Vec<f64>> = None;
        for &b in &backends {
            let opt = EigenOptions {
                backend: b,
                ..EigenOptions::default()
            };
            let mut times = Vec::with_capacity(reps);
            let mut last = None;
            for _ in 0..reps.max(1) {
                let t = Instant::now();
                let r = compute_modes_with(&input, opt).expect("default wing solves");
                times.push(t.elapsed().as_secs_f64() * 1e3);
                last = Some(r);
            }
            let r = last.expect("at least one run");
            times.sort_by(f64::total_cmp);
            let median = times[times.len() / 2];
            let diff = match &reference {
                None => {
                    reference = Some(r.freq_hz.clone());
                    0.0
                }
                Some(f0) => f0
                    .iter()
                    .zip(&r.freq_hz)
                    .map(|(a, b)| ((a - b) / a).abs())
                    .fold(0.0, f64::max),
            };
            println!(
                "| {h} | {} | {} | {} | {median:.1} | {:.1} | {diff:.1e} |",
                r.nodes.len(),
                r.n_dofs,
                b.name(),
                times[0]
            );
        }
    }
}
