//! Classification of sensor readings at the published problem's size (Mohren et al. 2018: 1326
//! sensors, two classes × 2700 training samples, 300 test samples each), on synthetic data of
//! the same shape (six smooth "modes" over a 26 × 51 grid driven by sines, plus noise; class 1
//! adds a small seventh pattern). Timed: the discriminant on all sensors, SSPOC (randomised SVD
//! r = 30, discriminant in mode space, the conic program), and the accuracy on the test set.
//! Then the published pipeline end to end on the FE plate (`classify_published_pipeline`): the
//! two 4 s runs, the encoding, and for encoded and raw strain the all-sensor discriminant, one
//! SSPOC solve (10 kept modes), 100 random sets of 10 sensors and the greedy d′ set of 10 (the issue's ≤ 3 s budget;
//! the plate's FE solve is set up once, outside the timing).

use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::DMatrix;
use std::hint::black_box;
use wingbeat::analysis::classify::{Discriminant, ThresholdRule};
use wingbeat::analysis::rotation_classify::{classify, mohren2018_case, ClassifyOptions};
use wingbeat::analysis::sspoc::{sspoc, SensorCount, SspocConfig};

fn data(n: usize, class: usize, t0: f64) -> DMatrix<f64> {
    let (nc, ns) = (26, 51);
    DMatrix::from_fn(n, nc * ns, |i, s| {
        let t = t0 + i as f64 * 1e-3;
        let (c, y) = ((s % nc) as f64 / 25.0, (s / nc) as f64 / 50.0);
        let mut v = 0.0;
        for k in 1..=6 {
            let kf = k as f64;
            v += (kf * y * 1.7).sin()
                * (1.0 + (kf * c).cos())
                * (std::f64::consts::TAU * 25.0 * kf * t + kf).sin()
                / kf;
        }
        if class == 1 {
            v += 0.05 * (c - 0.5) * y * (std::f64::consts::TAU * 50.0 * t).cos();
        }
        // a deterministic hash as noise
        let h = ((i * 7919 + s * 104_729 + class * 13) % 10_007) as f64 / 10_007.0 - 0.5;
        v + 0.01 * h
    })
}

fn bench_classify(c: &mut Criterion) {
    let (train0, train1) = (data(2700, 0, 1.0), data(2700, 1, 1.0));
    let (test0, test1) = (data(300, 0, 3.7), data(300, 1, 3.7));
    let mut g = c.benchmark_group("classify_published_size");
    g.sample_size(10);
    g.bench_function("discriminant_all_1326_sensors", |b| {
        b.iter(|| {
            black_box(Discriminant::fit(&train0, &train1, ThresholdRule::GaussianCrossing).unwrap())
        });
    });
    let cfg = SspocConfig {
        rank: 30,
        kept_modes: 10,
        l1_weight: 0.9,
        sensors: SensorCount::Cutoff,
        seed: 1,
    };
    g.bench_function("sspoc_r30", |b| {
        b.iter(|| black_box(sspoc(&train0, &train1, &cfg).unwrap()));
    });
    let lda = Discriminant::fit(&train0, &train1, ThresholdRule::GaussianCrossing).unwrap();
    g.bench_function("accuracy_600_test_samples", |b| {
        b.iter(|| black_box(lda.accuracy(&test0, &test1)));
    });
    g.finish();
}

fn bench_pipeline(c: &mut Criterion) {
    let (case, _) = mohren2018_case(8, None, 1).expect("the published plate");
    let opts = ClassifyOptions {
        kept_modes: vec![10],
        random_counts: vec![10],
        ..ClassifyOptions::default()
    };
    let mut g = c.benchmark_group("classify_published_pipeline");
    g.sample_size(10);
    g.bench_function("runs_encoding_all_sspoc1_random10x100", |b| {
        b.iter(|| black_box(classify(&case, &opts).unwrap()));
    });
    g.finish();
}

criterion_group!(benches, bench_classify, bench_pipeline);
criterion_main!(benches);
