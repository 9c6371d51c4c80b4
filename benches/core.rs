//! Criterion benchmarks of the physics core (issue: paper case, γ0 sweep, IC map).
//! Run: `cargo bench --bench core`. Medians are reported in the README.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use wingbeat::analysis::ic_map::{ic_map, IcMapOptions};
use wingbeat::analysis::sweep::{sweep, SweepOptions, SweepParam};
use wingbeat::config::SimConfig;
use wingbeat::pool::SeriesPool;
use wingbeat::simulate::{simulate, simulate_reusing};

fn paper_case(c: &mut Criterion) {
    let cfg = SimConfig::paper();
    c.bench_function(
        "paper case: 2 modes × 4 responses, 2 s at 10 kHz (+Floquet)",
        |b| b.iter(|| simulate(black_box(&cfg)).unwrap()),
    );
    // The same run writing into the previous result's series (a timing loop, a sweep, the
    // lab's recomputations): no fresh pages per run.
    let mut pool = SeriesPool::new();
    c.bench_function("paper case, series reused", |b| {
        b.iter(|| {
            let r = simulate_reusing(black_box(&cfg), &mut pool).unwrap();
            r.recycle(&mut pool);
        });
    });
}

/// The same run at a flap frequency that does not divide the sample rate (25.5 Hz at 10 kHz:
/// dense output), at 2 s and 4 s, and the commensurate snap of the rate (9996 Hz).
fn incommensurate(c: &mut Criterion) {
    let mut g = c.benchmark_group("f_d = 25.5 Hz");
    for d in [2.0, 4.0] {
        let mut cfg = SimConfig::paper();
        cfg.kinematics.flap_freq_hz = 25.5;
        cfg.duration_s = d;
        g.bench_function(format!("{d} s at 10 kHz (dense output)"), |b| {
            b.iter(|| simulate(black_box(&cfg)).unwrap());
        });
    }
    let mut cfg = SimConfig::paper();
    cfg.kinematics.flap_freq_hz = 25.5;
    cfg.sample_rate_hz = wingbeat::simulate::commensurate_sample_rate(25.5, 10_000.0);
    g.bench_function("2 s at the snapped 9996 Hz", |b| {
        b.iter(|| simulate(black_box(&cfg)).unwrap());
    });
    g.finish();
}

/// The floor: allocating and writing as many f64 as the paper case's result holds (t, 6 series
/// per mode × 2 modes, 3 strain series: 16 × 20 001), and just the 160 000 response samples.
fn floor(c: &mut Criterion) {
    let n = SimConfig::paper().n_samples();
    let mut g = c.benchmark_group("floor");
    for (name, series) in [
        ("160 000 samples (8 × 20 000)", 8),
        ("the result's 16 series", 16),
    ] {
        g.bench_function(name, |b| {
            b.iter(|| {
                let v: Vec<Vec<f64>> = (0..series)
                    .map(|j| (0..n).map(|i| (i + j) as f64).collect())
                    .collect();
                black_box(v)
            });
        });
    }
    g.finish();
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

criterion_group!(benches, paper_case, incommensurate, floor, gamma_sweep, ic);
criterion_main!(benches);
