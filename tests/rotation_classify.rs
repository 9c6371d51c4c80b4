//! Classifying rotation from wing strain (`wingbeat::analysis::rotation_classify`): SSPOC's
//! sweep against single solves, the published setup's headline in kind (encoding separates the
//! classes, raw strain does not, a few sparse sensors do as well as many random ones),
//! determinism under a seed, and bad options named before any work.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use nalgebra::DMatrix;
use wingbeat::analysis::rotation_classify::{
    classify, mohren2018_case, mohren2018_grid_mm, ClassifyOptions,
};
use wingbeat::analysis::sspoc::{sspoc, sspoc_sweep, SensorCount, SspocConfig};
use wingbeat::WingbeatError;

#[test]
fn sspoc_sweep_is_the_single_solves() {
    let data = |class: usize, n: usize| {
        DMatrix::from_fn(n, 40, |i, s| {
            let t = i as f64 * 0.013;
            let base = ((s + 1) as f64 * t).sin() + 0.3 * ((s * s) as f64 * 0.1 + 2.0 * t).cos();
            let signal = if class == 1 && s % 7 == 3 { 0.4 } else { 0.0 };
            base + signal + 0.05 * (((i * 31 + s * 17 + class) % 23) as f64 / 23.0 - 0.5)
        })
    };
    let (c0, c1) = (data(0, 120), data(1, 120));
    let cfg = SspocConfig {
        rank: 12,
        kept_modes: 1,
        l1_weight: 0.9,
        sensors: SensorCount::Cutoff,
        seed: 3,
    };
    let sweep = sspoc_sweep(&c0, &c1, &cfg, &[2, 5, 12]).unwrap();
    for (s, k) in sweep.iter().zip([2, 5, 12]) {
        let one = sspoc(
            &c0,
            &c1,
            &SspocConfig {
                kept_modes: k,
                ..cfg
            },
        )
        .unwrap();
        assert_eq!(s.sensors, one.sensors, "kept {k}");
        assert_eq!(s.kept_modes, one.kept_modes);
        assert!(!s.sensors.is_empty());
    }
    match sspoc_sweep(&c0, &c1, &cfg, &[2, 13]) {
        Err(WingbeatError::InvalidInput { field, .. }) => assert_eq!(field, "sspoc.kept_modes"),
        other => panic!("{other:?}"),
    }
}

fn quick() -> ClassifyOptions {
    ClassifyOptions {
        kept_modes: vec![3, 8],
        random_counts: vec![1, 10],
        random_draws: 12,
        ..ClassifyOptions::default()
    }
}

#[test]
fn published_setup_in_kind() {
    let (case, fe) = mohren2018_case(6, None, 1).unwrap();
    assert_eq!(case.sensors.len(), 26 * 51);
    assert_eq!(mohren2018_grid_mm()[26 * 50 + 25], (50.0, -25.0));
    assert!((fe.freq_hz[0] - 13.54).abs() < 0.05, "{}", fe.freq_hz[0]);
    let r = classify(&case, &quick()).unwrap();
    assert_eq!((r.train_samples, r.test_samples), (2700, 300));
    let e = &r.encoded;
    let raw = &r.raw;
    eprintln!(
        "encoded all {:.3}, raw all {:.3}; sparse {:?}; random {:?}; raw sparse {:?}",
        e.all_sensors,
        raw.all_sensors,
        e.sparse
            .iter()
            .map(|p| (p.sensors.len(), p.accuracy))
            .collect::<Vec<_>>(),
        e.random
            .iter()
            .map(|p| (p.sensors, p.mean, p.sd))
            .collect::<Vec<_>>(),
        raw.sparse
            .iter()
            .map(|p| (p.sensors.len(), p.accuracy))
            .collect::<Vec<_>>(),
    );
    // Published (Mohren et al. 2018, Fig. 3): all sensors 0.900 encoded, 0.488 raw.
    assert!(
        e.all_sensors >= 0.8,
        "encoded, all sensors: {}",
        e.all_sensors
    );
    assert!(
        raw.all_sensors <= 0.7,
        "raw, all sensors: {}",
        raw.all_sensors
    );
    // A few SSPOC sensors beat the same number of random ones.
    let sparse = e.sparse.iter().find(|p| p.kept_modes == 8).unwrap();
    assert!(sparse.sensors.len() <= 30, "{}", sparse.sensors.len());
    let one = &e.random[0];
    assert!(
        one.mean < e.all_sensors - 0.1,
        "one random sensor: {}",
        one.mean
    );
    assert!(e.s0 > 0.0 && raw.s0 > 0.0);
}

#[test]
fn same_seed_same_report_and_bad_options_named() {
    // Every 13th sensor of the grid: the same pipeline on 102 sensors.
    let thin = |mut c: wingbeat::analysis::rotation_classify::ClassifyCase| {
        c.sensors = c.sensors.into_iter().step_by(13).collect();
        c
    };
    let case = thin(mohren2018_case(3, Some(2.5), 4).unwrap().0);
    let opts = ClassifyOptions {
        duration_s: 1.6,
        discard_s: 0.5,
        kept_modes: vec![2],
        random_counts: vec![2],
        random_draws: 3,
        ..ClassifyOptions::default()
    };
    let a = classify(&case, &opts).unwrap();
    let b = classify(&case, &opts).unwrap();
    assert_eq!(a, b);
    let other = thin(mohren2018_case(3, Some(2.5), 5).unwrap().0);
    let c = classify(&other, &opts).unwrap();
    assert_ne!(a.encoded.s0, c.encoded.s0);

    let named = |o: ClassifyOptions, want: &str| match classify(&case, &o) {
        Err(WingbeatError::InvalidInput { field, .. }) => assert_eq!(field, want),
        other => panic!("{want}: {other:?}"),
    };
    named(
        ClassifyOptions {
            train_fraction: 1.0,
            ..opts.clone()
        },
        "options.train_fraction",
    );
    named(
        ClassifyOptions {
            discard_s: 2.0,
            ..opts.clone()
        },
        "options.discard_s",
    );
    named(
        ClassifyOptions {
            random_counts: vec![0],
            ..opts.clone()
        },
        "options.random_counts[0]",
    );
    named(
        ClassifyOptions {
            random_draws: 0,
            ..opts.clone()
        },
        "options.random_draws",
    );
    named(
        ClassifyOptions {
            s0: Some(f64::NAN),
            ..opts.clone()
        },
        "options.s0",
    );
    named(
        ClassifyOptions {
            kept_modes: vec![31],
            ..opts.clone()
        },
        "options.kept_modes[0]",
    );
    named(
        ClassifyOptions {
            duration_s: f64::INFINITY,
            ..opts.clone()
        },
        "options.duration_s",
    );
    let mut bad = case.clone();
    bad.sensors[7].per_mode.pop();
    match classify(&bad, &opts) {
        Err(WingbeatError::InvalidInput { field, .. }) => assert_eq!(field, "sensors[7].per_mode"),
        other => panic!("{other:?}"),
    }
    // Too many readings: refused before the runs.
    let long = ClassifyOptions {
        duration_s: 1e4,
        discard_s: 0.0,
        ..opts
    };
    assert!(matches!(
        classify(&case, &long),
        Err(WingbeatError::ResourceCap { .. })
    ));
}
