//! SSPOC (analysis::sspoc) on problems with known answers: the conic solver recovers a sparse
//! vector from random measurements (basis pursuit, exact recovery); the randomised SVD matches a
//! full SVD; with every mode kept, SSPOC's weights are the full-space discriminant and its sensors
//! are the ones that carry the class difference; bad settings are named.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use nalgebra::{DMatrix, DVector};
use wingbeat::analysis::sspoc::{
    elastic_net_equality, leading_eigen, leading_singular, sspoc, SensorCount, SspocConfig,
};

mod normals_common;
use normals_common::Normals;

#[test]
fn basis_pursuit_recovers_a_sparse_vector_from_random_measurements() {
    // p = 80 unknowns, 30 Gaussian measurements, 4 non-zeros: far inside the region where ℓ1
    // minimisation recovers the sparse vector exactly (Donoho–Tanner), so with α = 1 the answer
    // is known.
    let mut g = Normals(11);
    let (p, t) = (80, 30);
    let phi = DMatrix::from_fn(p, t, |_, _| g.normal());
    let mut truth = vec![0.0; p];
    for (i, v) in [(3, 1.5), (17, -0.7), (42, 2.0), (71, 0.4)] {
        truth[i] = v;
    }
    let c = phi.transpose() * DVector::from_vec(truth.clone());
    let s = elastic_net_equality(&phi, &c, 1.0).unwrap();
    let err = s
        .iter()
        .zip(&truth)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(err < 1e-6, "largest error {err}");
    // With α = 0.9 (the published weight) the support is the same.
    let s9 = elastic_net_equality(&phi, &c, 0.9).unwrap();
    let mut order: Vec<usize> = (0..p).collect();
    order.sort_by(|&i, &j| s9[j].abs().total_cmp(&s9[i].abs()));
    let mut top: Vec<usize> = order[..4].to_vec();
    top.sort_unstable();
    assert_eq!(top, vec![3, 17, 42, 71]);
    // The constraint holds.
    let resid = (phi.transpose() * DVector::from_vec(s9) - &c).amax();
    assert!(resid < 1e-7, "constraint residual {resid}");
}

#[test]
fn the_randomised_svd_matches_a_full_svd() {
    // 120 × 400 with singular values 0.7^k: the 12 leading vectors and values.
    let mut g = Normals(5);
    let (m, n) = (120, 400);
    let u = DMatrix::from_fn(m, m, |_, _| g.normal()).qr().q();
    let v = DMatrix::from_fn(n, m, |_, _| g.normal()).qr().q();
    let s = DMatrix::from_diagonal(&DVector::from_iterator(
        m,
        (0..m).map(|k| 0.7_f64.powi(k as i32)),
    ));
    let x = &u * s * v.transpose();
    // From the data, and from its Gram matrix X Xᵀ (the route SSPOC takes from the moments).
    for (uu, sv) in [
        leading_singular(&x, 12, 4, 3),
        leading_eigen(&(&x * x.transpose()), 12, 4, 3),
    ] {
        for (k, val) in sv.iter().enumerate() {
            let want = 0.7_f64.powi(k as i32);
            assert!(
                (val - want).abs() < 1e-10 * want.max(1e-3),
                "σ_{k}: {val} vs {want}"
            );
            let cos = uu.column(k).dot(&u.column(k)).abs();
            assert!((1.0 - cos) < 1e-9, "singular vector {k}: |cos| = {cos}");
        }
    }
}

#[test]
fn with_every_mode_kept_sspoc_picks_the_sensors_that_carry_the_difference() {
    // 12 sensors with independent noise; the class means differ on sensors 2 and 9 only, so the
    // full-space discriminant Σ⁻¹(μ₁ − μ₀) lives on those two, and SSPOC with r = p and every
    // mode kept must return them.
    let mut g = Normals(21);
    let (p, n) = (12, 3000);
    let spread: Vec<f64> = (0..p).map(|i| 0.5 + 0.1 * i as f64).collect();
    let mk = |g: &mut Normals, shift: bool| {
        DMatrix::from_fn(n, p, |_, j| {
            let mean = if shift && (j == 2 || j == 9) {
                0.8
            } else {
                0.0
            };
            1.0 + mean + spread[j] * g.normal()
        })
    };
    let (c0, c1) = (mk(&mut g, false), mk(&mut g, true));
    let cfg = SspocConfig {
        rank: p,
        kept_modes: p,
        l1_weight: 0.9,
        sensors: SensorCount::Top(2),
        seed: 1,
    };
    let out = sspoc(&c0, &c1, &cfg).unwrap();
    let mut chosen = out.sensors.clone();
    chosen.sort_unstable();
    assert_eq!(chosen, vec![2, 9], "weights {:?}", out.weights);
    assert_eq!(out.singular_values.len(), p);
}

#[test]
fn bad_settings_are_named() {
    let c = DMatrix::from_fn(10, 4, |i, j| (i * 4 + j) as f64);
    for (cfg, field) in [
        (
            SspocConfig {
                rank: 0,
                ..SspocConfig::default()
            },
            "sspoc.rank",
        ),
        (
            SspocConfig {
                rank: 4,
                kept_modes: 5,
                ..SspocConfig::default()
            },
            "sspoc.kept_modes",
        ),
        (
            SspocConfig {
                rank: 4,
                kept_modes: 2,
                l1_weight: 0.0,
                ..SspocConfig::default()
            },
            "sspoc.l1_weight",
        ),
        (
            SspocConfig {
                rank: 4,
                kept_modes: 2,
                sensors: SensorCount::Top(9),
                ..SspocConfig::default()
            },
            "sspoc.sensors",
        ),
    ] {
        let e = sspoc(&c, &c, &cfg).unwrap_err().to_string();
        assert!(e.contains(field), "{field}: {e}");
    }
}
