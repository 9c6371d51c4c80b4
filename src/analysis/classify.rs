//! Two-class linear classification of sensor readings (Mohren et al. 2018; docs/sensing.md):
//! Fisher's linear discriminant and a threshold on the projection.
//!
//! The direction is w = S_w⁺ (μ₁ − μ₀), S_w the within-class scatter and ⁺ its pseudo-inverse
//! (for two classes this is the one eigenvector of S_w⁺ S_b with a non-zero eigenvalue), scaled
//! to unit length and signed so that class 1 projects higher. The threshold is either the point
//! between the two class means where the Gaussians fitted to the projected classes cross (the
//! published classifier) or the midpoint of the means (nearest centroid on the projection).

use nalgebra::{DMatrix, DVector, SymmetricEigen};

use crate::{Result, WingbeatError};

/// Where the projected classes are split.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ThresholdRule {
    /// Where the two fitted Gaussians cross between the means (the midpoint when they do not).
    GaussianCrossing,
    /// The midpoint of the two projected means.
    Midpoint,
}

/// A fitted two-class linear discriminant.
#[derive(Clone, Debug, PartialEq)]
pub struct Discriminant {
    /// Unit projection direction (one entry per feature).
    pub direction: DVector<f64>,
    /// Projections above this are class 1.
    pub threshold: f64,
    /// Mean projection of each class (class 0 ≤ class 1).
    pub means: [f64; 2],
    /// Standard deviation (n − 1) of each class's projection.
    pub stds: [f64; 2],
}

/// Rows are samples, columns features; both classes must have the same features and at least
/// two samples each, every value finite.
fn check_classes(c0: &DMatrix<f64>, c1: &DMatrix<f64>) -> Result<()> {
    for (k, c) in [c0, c1].into_iter().enumerate() {
        if c.nrows() < 2 {
            return Err(WingbeatError::invalid(
                format!("class {k} training samples"),
                c.nrows(),
                "at least 2 samples per class",
            ));
        }
        if let Some(i) = c.iter().position(|v| !v.is_finite()) {
            return Err(WingbeatError::invalid(
                format!("class {k} feature value {i}"),
                c[i],
                "finite numbers",
            ));
        }
    }
    if c0.ncols() != c1.ncols() || c0.ncols() == 0 {
        return Err(WingbeatError::invalid(
            "features per sample",
            format!("{} and {}", c0.ncols(), c1.ncols()),
            "the same positive number for both classes",
        ));
    }
    Ok(())
}

fn column_means(c: &DMatrix<f64>) -> DVector<f64> {
    DVector::from_iterator(c.ncols(), c.column_iter().map(|col| col.mean()))
}

/// The within-class scatter Σ_c Σ_i (x − μ_c)(x − μ_c)ᵀ.
fn within_scatter(classes: [(&DMatrix<f64>, &DVector<f64>); 2]) -> DMatrix<f64> {
    let p = classes[0].1.len();
    let mut s = DMatrix::<f64>::zeros(p, p);
    for (c, mu) in classes {
        let mut centred = c.clone();
        for mut row in centred.row_iter_mut() {
            row -= mu.transpose();
        }
        s.gemm_tr(1.0, &centred, &centred, 1.0);
    }
    s
}

/// S⁺ v for a symmetric positive semi-definite S, eigenvalues below p·ε·λ_max treated as zero
/// (the tolerance of the usual pseudo-inverse).
fn pinv_apply(s: DMatrix<f64>, v: &DVector<f64>) -> DVector<f64> {
    let p = s.nrows();
    let eig = SymmetricEigen::new(s);
    let lmax = eig.eigenvalues.iter().fold(0.0_f64, |a, &b| a.max(b.abs()));
    let tol = p as f64 * f64::EPSILON * lmax;
    let coeffs = eig.eigenvectors.transpose() * v;
    let scaled = DVector::from_iterator(
        p,
        coeffs
            .iter()
            .zip(eig.eigenvalues.iter())
            .map(|(c, &l)| if l > tol { c / l } else { 0.0 }),
    );
    eig.eigenvectors * scaled
}

fn mean_std(x: &[f64]) -> (f64, f64) {
    let n = x.len() as f64;
    let m = x.iter().sum::<f64>() / n;
    let v = x.iter().map(|v| (v - m) * (v - m)).sum::<f64>() / (n - 1.0);
    (m, v.sqrt())
}

/// Where N(m0, s0) and N(m1, s1) have equal density between m0 < m1; the midpoint when they
/// do not cross there (or a spread is zero).
pub fn gaussian_crossing(m0: f64, s0: f64, m1: f64, s1: f64) -> f64 {
    let mid = 0.5 * (m0 + m1);
    if !(s0 > 0.0 && s1 > 0.0) || m0 == m1 {
        return mid;
    }
    // ln N0 = ln N1:  a x² + b x + c = 0.
    let a = 1.0 / (s1 * s1) - 1.0 / (s0 * s0);
    let b = 2.0 * (m0 / (s0 * s0) - m1 / (s1 * s1));
    let c = m1 * m1 / (s1 * s1) - m0 * m0 / (s0 * s0) + 2.0 * (s1 / s0).ln();
    let (lo, hi) = (m0.min(m1), m0.max(m1));
    let inside = |x: f64| x.is_finite() && x >= lo && x <= hi;
    if a.abs() <= 1e-12 * (1.0 / (s0 * s0)).max(1.0 / (s1 * s1)) {
        let x = -c / b;
        return if inside(x) { x } else { mid };
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return mid;
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    [q / a, c / q]
        .into_iter()
        .find(|&x| inside(x))
        .unwrap_or(mid)
}

impl Discriminant {
    /// Fits the discriminant to two classes (rows samples, columns features).
    pub fn fit(
        class0: &DMatrix<f64>,
        class1: &DMatrix<f64>,
        rule: ThresholdRule,
    ) -> Result<Discriminant> {
        check_classes(class0, class1)?;
        let (mu0, mu1) = (column_means(class0), column_means(class1));
        let sw = within_scatter([(class0, &mu0), (class1, &mu1)]);
        let mut w = pinv_apply(sw, &(&mu1 - &mu0));
        let norm = w.norm();
        if !(norm > 0.0 && norm.is_finite()) {
            return Err(WingbeatError::invalid(
                "training data",
                "no direction separates the class means",
                "two classes whose means differ",
            ));
        }
        w /= norm;
        let project = |c: &DMatrix<f64>| (c * &w).iter().copied().collect::<Vec<f64>>();
        let (mut p0, mut p1) = (project(class0), project(class1));
        if mean_std(&p1).0 < mean_std(&p0).0 {
            w = -w;
            for v in p0.iter_mut().chain(p1.iter_mut()) {
                *v = -*v;
            }
        }
        let ((m0, s0), (m1, s1)) = (mean_std(&p0), mean_std(&p1));
        let threshold = match rule {
            ThresholdRule::GaussianCrossing => gaussian_crossing(m0, s0, m1, s1),
            ThresholdRule::Midpoint => 0.5 * (m0 + m1),
        };
        Ok(Discriminant {
            direction: w,
            threshold,
            means: [m0, m1],
            stds: [s0, s1],
        })
    }

    /// Whether a sample (one value per feature) is classed as class 1.
    pub fn is_class1(&self, sample: &[f64]) -> bool {
        sample
            .iter()
            .zip(self.direction.iter())
            .map(|(a, b)| a * b)
            .sum::<f64>()
            > self.threshold
    }

    /// The fraction of test samples classed correctly, over both classes together.
    pub fn accuracy(&self, test0: &DMatrix<f64>, test1: &DMatrix<f64>) -> f64 {
        let right0 = (test0 * &self.direction)
            .iter()
            .filter(|&&v| v <= self.threshold)
            .count();
        let right1 = (test1 * &self.direction)
            .iter()
            .filter(|&&v| v > self.threshold)
            .count();
        (right0 + right1) as f64 / (test0.nrows() + test1.nrows()) as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gaussians_cross_where_their_densities_agree() {
        let n = |x: f64, m: f64, s: f64| (-(x - m) * (x - m) / (2.0 * s * s)).exp() / s;
        for &(m0, s0, m1, s1) in &[
            (0.0, 1.0, 3.0, 2.0),
            (-1.0, 0.3, 1.0, 0.1),
            (2.0, 1.0, 5.0, 1.0),
        ] {
            let x = gaussian_crossing(m0, s0, m1, s1);
            assert!(x > m0 && x < m1);
            assert!(
                (n(x, m0, s0) / n(x, m1, s1) - 1.0).abs() < 1e-10,
                "{m0} {s0} {m1} {s1}: {x}"
            );
        }
        assert_eq!(gaussian_crossing(2.0, 1.0, 5.0, 1.0), 3.5);
    }
}
