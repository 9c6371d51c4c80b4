//! Sensing body rotation through strain (issue 14 items 3–4): the rotation signal, the
//! detectability map and the greedy sensor placement, checked against direct formulas.
#![cfg(not(target_arch = "wasm32"))]

use nalgebra::{DMatrix, DVector};
use wingbeat::analysis::sensing::{
    d_prime_sq, decimation, delta_strain_series, detectability_map, detection_probability,
    modal_rotation_signal, normal_cdf, place_sensors, sense_fe, sensor_series, ModalSignal,
    SensingOptions, COMPONENTS, Z_PFA,
};
use wingbeat::config::SimConfig;
use wingbeat::fem::{compute_modes, FemInput, FemModes};

fn wing(h_mm: f64) -> FemModes {
    compute_modes(&FemInput {
        n_modes: 4,
        mesh_size_mm: Some(h_mm),
        ..Default::default()
    })
    .expect("FE modes")
}

fn config(fe: &FemModes) -> SimConfig {
    SimConfig {
        modes: fe.to_modes(0.0, &[]),
        duration_s: 0.4,
        sample_rate_hz: 5000.0,
        ..SimConfig::paper()
    }
}

fn signal(fe: &FemModes, w: [f64; 3]) -> ModalSignal {
    modal_rotation_signal(&config(fe), w).expect("signal")
}

#[test]
fn zero_rate_gives_exactly_zero_signal_and_detectability() {
    let fe = wing(2.0);
    let sig = signal(&fe, [0.0; 3]);
    assert!(sig.delta.iter().flatten().all(|v| *v == 0.0));
    assert!(sig.flap.iter().flatten().any(|v| *v != 0.0));
    let opts = SensingOptions::default();
    let map = detectability_map(fe.nodes.len(), |k, i| fe.strain_nodes[k][i], &sig, &opts).unwrap();
    assert!(map.d.iter().flatten().all(|v| *v == 0.0));
    assert!(map.e_flap.iter().flatten().any(|v| *v > 0.0));
    let p = place_sensors(&fe.nodes, |k, i| fe.strain_nodes[k][i], &sig, &opts).unwrap();
    assert!(p.d_prime.iter().all(|v| *v == 0.0));
    assert_eq!(p.d_prime_all, 0.0);
}

/// Δε(2ω) − 2Δε(ω), relative, at every node and component (max over the run).
fn nonlinearity(fe: &FemModes, w: f64) -> f64 {
    let s1 = signal(fe, [w, 0.0, w]);
    let s2 = signal(fe, [2.0 * w, 0.0, 2.0 * w]);
    let (mut num, mut den) = (0.0f64, 0.0f64);
    for i in 0..fe.nodes.len() {
        for c in 0..3 {
            for s in decimation(s1.t.len(), 400) {
                let d = |sig: &ModalSignal| -> f64 {
                    (0..sig.delta.len())
                        .map(|k| fe.strain_nodes[k][i][c] * sig.delta[k][s])
                        .sum()
                };
                let (a, b) = (d(&s1), d(&s2));
                num = num.max((b - 2.0 * a).abs());
                den = den.max((2.0 * a).abs());
            }
        }
    }
    num / den
}

#[test]
fn signal_is_linear_in_small_body_rates() {
    let fe = wing(2.0);
    let devs: Vec<(f64, f64)> = [1.0, 1e-1, 1e-2, 1e-3, 1e-4]
        .iter()
        .map(|&w| (w, nonlinearity(&fe, w)))
        .collect();
    for (w, d) in &devs {
        eprintln!("ω = {w:e} rad/s: |Δε(2ω) − 2Δε(ω)| / |2Δε(ω)| = {d:.3e}");
    }
    // first-order linearity: the deviation falls with ω (roughly ∝ ω) ...
    for p in devs.windows(2).take(3) {
        assert!(p[1].1 < 0.3 * p[0].1, "{devs:?}");
    }
    // ... and is tiny at small rates
    assert!(devs[4].1 < 1e-5, "{devs:?}");
    // the deviation is the quadratic term: deviation / ω is constant at small ω
    let (c3, c4) = (devs[3].1 / devs[3].0, devs[4].1 / devs[4].0);
    assert!((c3 - c4).abs() < 0.05 * c3, "{devs:?}");
}

#[test]
fn greedy_index_is_monotone_and_matches_a_dense_solve() {
    let fe = wing(2.0);
    let sig = signal(&fe, [1.0, 0.0, 1.0]);
    let opts = SensingOptions {
        k_max: 8,
        samples_per_sensor: 64,
        ..Default::default()
    };
    let p = place_sensors(&fe.nodes, |k, i| fe.strain_nodes[k][i], &sig, &opts).unwrap();
    assert_eq!(p.sensors.len(), 8);
    for w in p.d_prime.windows(2) {
        assert!(w[1] >= w[0], "{:?}", p.d_prime);
    }
    assert!(p.d_prime_all >= *p.d_prime.last().unwrap());
    // greedy is at least as good as the best single sensor, and ties it at K = 1
    assert_eq!(p.d_prime_ranked.len(), 8);
    assert!((p.d_prime_ranked[0] - p.d_prime[0]).abs() <= 1e-12 * p.d_prime[0]);
    eprintln!(
        "greedy d' {:?}\nranked d' {:?}",
        p.d_prime, p.d_prime_ranked
    );
    let idx = decimation(sig.t.len(), opts.samples_per_sensor);
    for k in 1..=5 {
        let (mut dl, mut fl) = (Vec::new(), Vec::new());
        for s in &p.sensors[..k] {
            let c = COMPONENTS.iter().position(|n| *n == s.component).unwrap();
            let e: Vec<f64> = (0..4).map(|m| fe.strain_nodes[m][s.node][c]).collect();
            let (d, f) = sensor_series(&e, &sig, &idx);
            dl.extend(d);
            fl.extend(f);
        }
        let n = dl.len();
        let delta = DVector::from_vec(dl);
        let f = DVector::from_vec(fl);
        let cov = &f * f.transpose() * (opts.rho * opts.rho)
            + DMatrix::identity(n, n) * (opts.noise * opts.noise);
        let x = cov.lu().solve(&delta).expect("solve");
        let dense = delta.dot(&x);
        let greedy = p.d_prime[k - 1].powi(2);
        let rel = (dense - greedy).abs() / dense;
        eprintln!("K = {k}: d'² greedy {greedy:.9e}, dense {dense:.9e}, rel {rel:.2e}");
        assert!(rel < 1e-8, "K = {k}: {greedy} vs {dense}");
        assert!((p.pd[k - 1] - detection_probability(greedy.sqrt())).abs() < 1e-15);
    }
}

#[test]
fn single_sensor_detectability_is_the_direct_formula() {
    let fe = wing(2.0);
    let sig = signal(&fe, [0.0, 0.0, 1.0]);
    let opts = SensingOptions {
        rho: 0.02,
        noise: 3e-7,
        ..Default::default()
    };
    let map = detectability_map(fe.nodes.len(), |k, i| fe.strain_nodes[k][i], &sig, &opts).unwrap();
    let pts: Vec<usize> = (0..fe.nodes.len()).step_by(37).collect();
    let names: Vec<String> = pts.iter().map(|i| format!("n{i}")).collect();
    let modal: Vec<Vec<[f64; 3]>> = pts
        .iter()
        .map(|&i| (0..4).map(|k| fe.strain_nodes[k][i]).collect())
        .collect();
    let series = delta_strain_series(&names, &modal, &sig).unwrap();
    let ms = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64;
    for (&i, (d, f)) in pts.iter().zip(&series) {
        for (c, (dv, fv)) in [
            (&d.eps_x, &f.eps_x),
            (&d.eps_y, &f.eps_y),
            (&d.gamma_xy, &f.gamma_xy),
        ]
        .into_iter()
        .enumerate()
        {
            let direct = ms(dv) / (opts.rho.powi(2) * ms(fv) + opts.noise.powi(2));
            let got = map.d[i][c];
            assert!(
                (got - direct).abs() <= 1e-9 * direct.max(1e-300),
                "node {i} {c}: {got} vs {direct}"
            );
        }
    }
    // one sensor's d'² against the closed form for one sensor
    let idx = decimation(sig.t.len(), opts.samples_per_sensor);
    let e: Vec<f64> = (0..4).map(|k| fe.strain_nodes[k][0][1]).collect();
    let (dd, ff) = sensor_series(&e, &sig, &idx);
    let a: f64 = dd.iter().map(|x| x * x).sum();
    let b: f64 = dd.iter().zip(&ff).map(|(x, y)| x * y).sum();
    let g: f64 = ff.iter().map(|x| x * x).sum();
    let v = d_prime_sq(a, b, g, opts.rho, opts.noise);
    let s2 = opts.noise.powi(2);
    let r2 = opts.rho.powi(2);
    let direct = a / s2 - r2 * b * b / (s2 * (s2 + r2 * g));
    assert!((v - direct).abs() <= 1e-12 * direct.abs());
}

#[test]
fn normal_cdf_and_detection_probability() {
    assert!((normal_cdf(0.0) - 0.5).abs() < 2e-7);
    assert!((normal_cdf(Z_PFA) - 0.99).abs() < 2e-7);
    assert!((normal_cdf(-1.0) - 0.158_655_253_931_457).abs() < 2e-7);
    assert!((detection_probability(0.0) - 0.01).abs() < 2e-7);
    assert!(detection_probability(10.0) > 0.9999);
}

#[test]
fn top_sensors_are_stable_under_mesh_refinement() {
    let rate = [1.0, 0.0, 1.0];
    let opts = SensingOptions {
        k_max: 3,
        ..Default::default()
    };
    let place = |h: f64| {
        let fe = wing(h);
        let sig = signal(&fe, rate);
        sense_fe(&fe, &sig, &opts).unwrap().placement
    };
    let (coarse, fine) = (place(2.0), place(1.4));
    for (c, f) in coarse.sensors.iter().zip(&fine.sensors) {
        eprintln!(
            "rank {}: 2.0 mm ({:.2}, {:.2}) {} / 1.4 mm ({:.2}, {:.2}) {}",
            c.rank, c.x_mm, c.y_mm, c.component, f.x_mm, f.y_mm, f.component
        );
    }
    // the best sensor of the finer mesh lies within one coarse element of the coarse one's
    let (c, f) = (&coarse.sensors[0], &fine.sensors[0]);
    let dist = (c.x_mm - f.x_mm).hypot(c.y_mm - f.y_mm);
    eprintln!("top-sensor distance {dist:.3} mm");
    assert!(dist <= 2.0, "top sensors {dist} mm apart");
    assert_eq!(c.component, f.component);
}
