//! Criterion benchmarks of the wing in air (src/aero): the default FE wing, 4 modes, paper
//! kinematics, 2 s at 10 kHz in air, and the pieces of its cost.
//! Run: `cargo bench --bench aero`. Target (the wing-in-air issue): ≤ 10 ms natively.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use wingbeat::aero::ode::{AirOde, LoadTable};
use wingbeat::aero::{AeroConfig, AeroWing, FrameState};
use wingbeat::config::SimConfig;
use wingbeat::simulate::simulate;

fn air(c: &mut Criterion) {
    let base = SimConfig::fe_wing().expect("the FE wing solves");
    let mut g = c.benchmark_group("FE wing, 4 modes, 2 s at 10 kHz");
    g.sample_size(20);
    g.bench_function("vacuum (per-mode path)", |b| {
        b.iter(|| simulate(black_box(&base)).unwrap());
    });
    for (name, aero) in [
        (
            "air, default quadrature (24 strips × 2 × 6)",
            AeroConfig::with_density(1.2),
        ),
        (
            "air, coarse quadrature (12 strips × 2 × 4)",
            AeroConfig {
                strips: 12,
                chord_points: 4,
                ..AeroConfig::with_density(1.2)
            },
        ),
    ] {
        let cfg = SimConfig {
            aero,
            ..base.clone()
        };
        g.bench_function(name, |b| b.iter(|| simulate(black_box(&cfg)).unwrap()));
    }
    g.finish();
    let wing = AeroWing::build(
        base.wing.as_deref().unwrap(),
        &AeroConfig::with_density(1.2),
    )
    .unwrap();
    let kin = base.kinematics.compile();
    let fs = FrameState::of(&kin.state(0.0123));
    c.bench_function("one load evaluation (288 points, 4 modes)", |b| {
        b.iter(|| {
            let (mut f, mut d) = ([0.0; 4], [0.0; 16]);
            wing.loads(black_box(&fs), 2.04, 1.2, &mut f, &mut d);
            black_box((f, d))
        });
    });
    // The run reads the loads from a table over one period (src/aero/ode.rs): its build and
    // one read.
    let air = AeroConfig::with_density(1.2);
    let ode = AirOde::new(&kin, &base.modes, &wing, &air).unwrap();
    c.bench_function("load table over one period (build)", |b| {
        b.iter(|| black_box(LoadTable::build(black_box(&ode))));
    });
    let table = LoadTable::build(&ode);
    c.bench_function("one load table read (4 modes)", |b| {
        b.iter(|| {
            let (mut f, mut d) = ([0.0; 4], [0.0; 16]);
            table.eval_at(black_box(0.0123), &mut f, &mut d);
            black_box((f, d))
        });
    });
}

criterion_group!(benches, air);
criterion_main!(benches);
