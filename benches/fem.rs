//! Mesh + assemble + solve 6 modes of the default (synthetic Manduca-like) wing at three
//! mesh sizes. Prints nodes, free DOFs and f1 for each size before timing it. A second group
//! times each sparse factorisation backend at four mesh sizes (the faer one only with
//! `--features faer`).

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use wingbeat::fem::{compute_modes, compute_modes_with, Backend, EigenOptions, FemInput};

fn bench_wing(c: &mut Criterion) {
    let mut group = c.benchmark_group("fem_default_wing_6_modes");
    for h in [2.0, 1.25, 0.75] {
        let input = FemInput {
            mesh_size_mm: Some(h),
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
            b.iter(|| compute_modes(black_box(&input)).unwrap());
        });
    }
    group.finish();
}

fn bench_backends(c: &mut Criterion) {
    let mut group = c.benchmark_group("fem_backends_default_wing_6_modes");
    for h in [2.0, 1.25, 1.0, 0.75] {
        let input = FemInput {
            mesh_size_mm: Some(h),
            ..FemInput::default()
        };
        for backend in [Backend::Skyline, Backend::Faer] {
            if !backend.available() {
                continue;
            }
            let opt = EigenOptions {
                backend,
                ..EigenOptions::default()
            };
            group.bench_function(format!("{}/h={h}mm", backend.name()), |b| {
                b.iter(|| compute_modes_with(black_box(&input), opt).unwrap());
            });
        }
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench_wing, bench_backends
}
criterion_main!(benches);
