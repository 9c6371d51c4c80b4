//! Criterion benchmarks of the physics core (issue: paper case, γ0 sweep, IC map).
//! Run: `cargo bench --bench core`. Medians are reported in the README.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use wingbeat::analysis::ic_map::{ic_map, IcMapOptions};
use wingbeat::analysis::sweep::{sweep, SweepOptions, SweepParam};
use wingbeat::config::SimConfig;
use wingbeat::simulate::simulate;

fn paper_case(c: &mut Criterion) {
    let cfg = SimConfig::paper();
    c.bench_function(
        "paper case: 2 modes × 4 responses, 2 s at 10 kHz (+Floquet)",
        |b| b.iter(|| simulate(black_box(&cfg)).unwrap()),
    );
}

fn gamma_sweep(c: &mut Criterion) {
    let cfg = SimConfig::paper();
    let opts = SweepOptions {
        param: SweepParam::Gamma0,
        from: 0.0,
        to: 0.3,
        points: 31,
    };
    let mut g = c.benchmark_group("sweep");
    g.sample_size(20);
    g.bench_function("γ0 sweep, 31 points, 2 s each", |b| {
        b.iter(|| sweep(black_box(&cfg), &opts, |_, _| {}).unwrap());
    });
    g.finish();
}

fn ic(c: &mut Criterion) {
    let cfg = SimConfig::paper();
    let opts = IcMapOptions::default();
    c.bench_function("IC map 101×101, mode 1, 2 s", |b| {
        b.iter(|| ic_map(black_box(&cfg), &opts).unwrap());
    });
}

criterion_group!(benches, paper_case, gamma_sweep, ic);
criterion_main!(benches);
