//! Mesh + assemble + solve 6 modes of the default (synthetic Manduca-like) wing at three
//! mesh sizes. Prints nodes, free DOFs and f1 for each size before timing it.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use wingbeat::fem::{compute_modes, FemInput};

fn bench_wing(c: &mut Criterion) {
    let mut group = c.benchmark_group("fem_default_wing_6_modes");
    for h in [2.0, 1.25, 0.75] {
        let input = FemInput {
            mesh_size_mm: h,
            ..FemInput::default()
        };
        let r = compute_modes(&input).expect("default wing solves");
        println!(
            "mesh {h} mm: {} nodes, {} triangles, {} free DOFs, f1 = {:.2} Hz, f2 = {:.2} Hz",
            r.nodes.len(),
            r.triangles.len(),
            r.n_dofs,
            r.freq_hz[0],
            r.freq_hz[1]
        );
        group.bench_function(format!("h={h}mm"), |b| {
            b.iter(|| compute_modes(black_box(&input)).unwrap())
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench_wing
}
criterion_main!(benches);
