//! Eigen-solver block size vs work: basis size, iterations and time for the default wing.
//! `cargo run --release --example fem_blocksize -- 0.57 6 8 12 16`
use std::time::Instant;
use wingbeat::fem::*;
fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    let h = args[0];
    let input = FemInput {
        mesh_size_mm: Some(h),
        max_nodes: Some(MAX_NODES),
        ..FemInput::default()
    };
    let (outline, mesh, _) = mesh_input(&input).unwrap();
    let clamped = clamp_nodes(&outline, &mesh, input.clamp).unwrap();
    let asm = assembly::assemble_blocks(&mesh, &input.material, &clamped).unwrap();
    for &b in &args[1..] {
        let opt = EigenOptions {
            block: b as usize,
            ..EigenOptions::default()
        };
        let t = Instant::now();
        let e = eigen::lowest_modes_with::<linalg::SparseLdlt>(&asm.k, &asm.m, 6, opt).unwrap();
        println!(
            "block {b}: basis {} iterations {} {:.3} s f6 {:.9} res {:?}",
            e.basis,
            e.iterations,
            t.elapsed().as_secs_f64(),
            e.values[5].sqrt() / 2.0 / std::f64::consts::PI,
            e.residuals
        );
    }
}
