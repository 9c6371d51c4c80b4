//! The two-class discriminant (analysis::classify) on synthetic Gaussian classes with a known
//! answer: equal covariance Σ, means 0 and d. The Bayes-optimal rule projects on Σ⁻¹d and its
//! accuracy is Φ(Δ/2), Δ² = dᵀΣ⁻¹d; a fitted discriminant must find that direction and, on
//! fresh test samples, that accuracy within the sampling error (a wrong sign gives 1 − Φ(Δ/2)).

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use nalgebra::{DMatrix, DVector};
use wingbeat::analysis::classify::{Discriminant, ThresholdRule};

mod normals_common;
use normals_common::Normals;

/// Φ(x) from erfc by its continued-fraction-free series (Abramowitz & Stegun 7.1.26, |error| ≤ 1.5e-7).
fn phi(x: f64) -> f64 {
    let z = x / std::f64::consts::SQRT_2;
    let t = 1.0 / (1.0 + 0.327_591_1 * z.abs());
    let poly = t
        * (0.254_829_592
            + t * (-0.284_496_736
                + t * (1.421_413_741 + t * (-1.453_152_027 + t * 1.061_405_429))));
    let erf = 1.0 - poly * (-z * z).exp();
    0.5 * (1.0 + if z >= 0.0 { erf } else { -erf })
}

fn samples(rng: &mut Normals, n: usize, l: &DMatrix<f64>, mean: &DVector<f64>) -> DMatrix<f64> {
    let p = mean.len();
    let mut m = DMatrix::zeros(n, p);
    for i in 0..n {
        let z = DVector::from_iterator(p, (0..p).map(|_| rng.normal()));
        let x = l * z + mean;
        m.row_mut(i).copy_from(&x.transpose());
    }
    m
}

#[test]
fn the_fitted_discriminant_reaches_the_bayes_accuracy_of_gaussian_classes() {
    let l = DMatrix::from_row_slice(
        4,
        4,
        &[
            1.0, 0.0, 0.0, 0.0, //
            0.6, 0.8, 0.0, 0.0, //
            -0.3, 0.2, 0.5, 0.0, //
            0.1, -0.4, 0.3, 1.5,
        ],
    );
    let sigma: DMatrix<f64> = &l * l.transpose();
    let d: DVector<f64> = DVector::from_vec(vec![0.4, -0.3, 0.25, 0.5]);
    let sinv_d = sigma.cholesky().unwrap().solve(&d);
    let delta = d.dot(&sinv_d).sqrt();
    let bayes = phi(delta / 2.0);
    assert!(
        bayes > 0.7 && bayes < 0.95,
        "a case where the answer is neither trivial nor chance: {bayes}"
    );

    let mut rng = Normals(20_260_101);
    let zero = DVector::zeros(4);
    let (train0, train1) = (
        samples(&mut rng, 20_000, &l, &zero),
        samples(&mut rng, 20_000, &l, &d),
    );
    let (test0, test1) = (
        samples(&mut rng, 20_000, &l, &zero),
        samples(&mut rng, 20_000, &l, &d),
    );
    for rule in [ThresholdRule::GaussianCrossing, ThresholdRule::Midpoint] {
        let lda = Discriminant::fit(&train0, &train1, rule).unwrap();
        let cos = lda.direction.dot(&sinv_d) / sinv_d.norm();
        assert!(cos > 0.999, "{rule:?}: direction against Σ⁻¹d: cos = {cos}");
        let acc = lda.accuracy(&test0, &test1);
        // Sampling sd of the accuracy with 40 000 test samples ≈ 0.002.
        assert!(
            (acc - bayes).abs() < 0.01,
            "{rule:?}: accuracy {acc} vs Bayes {bayes}"
        );
    }
}

#[test]
fn unequal_spreads_move_the_threshold_towards_the_narrow_class() {
    // One feature: class 0 ~ N(0, 1), class 1 ~ N(3, 0.5²). The densities cross between the means
    // where the narrow class's density has fallen to the wide one's: nearer class 1's mean than
    // the midpoint, which the Gaussian-crossing rule must find (and then classify better).
    let mut rng = Normals(7);
    let mk = |rng: &mut Normals, n: usize, m: f64, s: f64| {
        DMatrix::from_fn(n, 1, |_, _| m + s * rng.normal())
    };
    let (a0, a1) = (
        mk(&mut rng, 50_000, 0.0, 1.0),
        mk(&mut rng, 50_000, 3.0, 0.5),
    );
    let (t0, t1) = (
        mk(&mut rng, 50_000, 0.0, 1.0),
        mk(&mut rng, 50_000, 3.0, 0.5),
    );
    let cross = Discriminant::fit(&a0, &a1, ThresholdRule::GaussianCrossing).unwrap();
    let mid = Discriminant::fit(&a0, &a1, ThresholdRule::Midpoint).unwrap();
    assert!(
        cross.threshold > mid.threshold + 0.2,
        "{} vs {}",
        cross.threshold,
        mid.threshold
    );
    // The exact crossing of N(0,1) and N(3,0.25): 2.0 + ... solved here independently.
    let f = |x: f64| -x * x / 2.0 + (x - 3.0) * (x - 3.0) / (2.0 * 0.25) - (2.0_f64).ln();
    let (mut lo, mut hi) = (0.0, 3.0);
    for _ in 0..200 {
        let m = 0.5 * (lo + hi);
        if f(m) > 0.0 {
            lo = m;
        } else {
            hi = m;
        }
    }
    assert!(
        (cross.threshold - lo).abs() < 0.02,
        "crossing {} vs exact {lo}",
        cross.threshold
    );
    assert!(cross.accuracy(&t0, &t1) > mid.accuracy(&t0, &t1));
}

#[test]
fn bad_training_data_is_refused_by_name() {
    let one = DMatrix::from_row_slice(1, 2, &[1.0, 2.0]);
    let two = DMatrix::from_row_slice(2, 2, &[1.0, 2.0, 3.0, 4.0]);
    let e = Discriminant::fit(&one, &two, ThresholdRule::Midpoint)
        .unwrap_err()
        .to_string();
    assert!(e.contains("class 0 training samples"), "{e}");
    let nan = DMatrix::from_row_slice(2, 2, &[1.0, f64::NAN, 3.0, 4.0]);
    let e = Discriminant::fit(&two, &nan, ThresholdRule::Midpoint)
        .unwrap_err()
        .to_string();
    assert!(e.contains("class 1"), "{e}");
    let three = DMatrix::from_row_slice(2, 3, &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    assert!(Discriminant::fit(&two, &three, ThresholdRule::Midpoint).is_err());
    assert!(
        Discriminant::fit(&two, &two, ThresholdRule::Midpoint).is_err(),
        "equal means: no direction"
    );
}
