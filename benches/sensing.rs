//! The sensing analysis (issue 14) on the lab's default FE wing: the shell FE modes of the
//! default outline at 1 mm elements, 2 modes (the lab's `FE_LAB_INPUT`), the paper's
//! kinematics at the lab's 10 kHz for 2 s, a body rate of 1 rad/s about z. Timed: the two runs
//! (with and without ω_b), the detectability map, the greedy placement (K = 1 … 30 and its
//! continuation to 90 % of the all-sensor d′), and the whole analysis as wasm `senseRotation`
//! does it (the FE solve itself is not included: the lab has the modes already).

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use wingbeat::analysis::sensing::{
    delta_strain_series, detectability_map, modal_rotation_signal, place_sensors, SensingOptions,
};
use wingbeat::config::SimConfig;
use wingbeat::fem::{compute_modes, FemInput};

fn bench_sensing(c: &mut Criterion) {
    let fe = compute_modes(&FemInput {
        n_modes: 2,
        mesh_size_mm: Some(1.0),
        ..FemInput::default()
    })
    .expect("the default wing solves");
    let cfg = SimConfig {
        modes: fe.to_modes(0.0, &[]),
        sample_rate_hz: 10_000.0,
        duration_s: 2.0,
        initial_conditions: vec![],
        ..SimConfig::paper()
    };
    let w = [0.0, 0.0, 1.0];
    let opts = SensingOptions::default();
    let strain = |k: usize, i: usize| fe.strain_nodes[k][i];
    let sig = modal_rotation_signal(&cfg, w).unwrap();
    let n = fe.nodes.len();
    println!(
        "default FE wing: {n} nodes, {} modes, {} samples per run",
        fe.strain_nodes.len(),
        sig.t.len()
    );
    let mut g = c.benchmark_group("sensing_default_fe_wing");
    g.sample_size(20);
    g.bench_function("two_runs", |b| {
        b.iter(|| modal_rotation_signal(black_box(&cfg), w).unwrap());
    });
    g.bench_function("detectability_map", |b| {
        b.iter(|| detectability_map(n, strain, black_box(&sig), &opts).unwrap());
    });
    g.bench_function("greedy_placement_k30", |b| {
        b.iter(|| place_sensors(&fe.nodes, strain, black_box(&sig), &opts).unwrap());
    });
    g.bench_function("whole_analysis", |b| {
        b.iter(|| {
            let sig = modal_rotation_signal(black_box(&cfg), w).unwrap();
            let map = detectability_map(n, strain, &sig, &opts).unwrap();
            let pl = place_sensors(&fe.nodes, strain, &sig, &opts).unwrap();
            let s = &pl.sensors[0];
            let modal = vec![(0..fe.strain_nodes.len())
                .map(|k| strain(k, s.node))
                .collect()];
            let series = delta_strain_series(&["P".into()], &modal, &sig).unwrap();
            black_box((map, series))
        });
    });
    g.finish();
}

criterion_group!(benches, bench_sensing);
criterion_main!(benches);
