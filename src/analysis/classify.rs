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

/// One class's scatter Σ_i (x − μ)(x − μ)ᵀ.
fn scatter(c: &DMatrix<f64>, mu: &DVector<f64>) -> DMatrix<f64> {
    let p = mu.len();
    let mut s = DMatrix::<f64>::zeros(p, p);
    let mut centred = c.clone();
    for mut row in centred.row_iter_mut() {
        row -= mu.transpose();
    }
    // Cᵀ C through `gemm` on an explicit transpose: nalgebra's `gemm` takes the blocked
    // matrix-multiply kernel, `gemm_tr` a dot product per entry (5× slower at 2700 × 1326).
    let ct = centred.transpose();
    s.gemm(1.0, &ct, &centred, 0.0);
    s
}

/// The within-class scatter Σ_c Σ_i (x − μ_c)(x − μ_c)ᵀ.
fn within_scatter(classes: [(&DMatrix<f64>, &DVector<f64>); 2]) -> DMatrix<f64> {
    let [(c0, mu0), (c1, mu1)] = classes;
    scatter(c0, mu0) + scatter(c1, mu1)
}

/// Largest condition number for which S⁺ v is taken from a Cholesky factor (then S⁺ = S⁻¹ to
/// far below the pseudo-inverse's own cutoff of p·ε).
const CHOLESKY_MAX_CONDITION: f64 = 1e9;

/// λ_max / λ_min of a positive definite S from its Cholesky factor: the largest eigenvalue by
/// power iteration on S, the smallest by inverse iteration (two triangular solves a step), 30
/// steps each from a fixed start. An estimate from below (an unconverged λ_min is too large),
/// used only to decide between the two exact routes of [`pinv_apply`].
fn condition_estimate(s: &DMatrix<f64>, ch: &nalgebra::Cholesky<f64, nalgebra::Dyn>) -> f64 {
    let p = s.nrows();
    let start = DVector::from_fn(p, |i, _| 1.0 + ((i * 7919) % 101) as f64 / 101.0);
    let (mut x, mut y) = (start.normalize(), start.normalize());
    let (mut lmax, mut inv_lmin) = (0.0_f64, 0.0_f64);
    for _ in 0..30 {
        let sx = s * &x;
        lmax = x.dot(&sx);
        x = sx.normalize();
        let sy = ch.solve(&y);
        inv_lmin = y.dot(&sy);
        y = sy.normalize();
        if !(lmax.is_finite() && inv_lmin.is_finite()) {
            return f64::INFINITY;
        }
    }
    lmax * inv_lmin
}

/// S⁺ v for a symmetric positive semi-definite S, eigenvalues below p·ε·λ_max treated as zero
/// (the tolerance of the usual pseudo-inverse). A well-conditioned S (estimated condition below
/// [`CHOLESKY_MAX_CONDITION`]) is solved through its Cholesky factor, several times faster than
/// the eigendecomposition and the same S⁻¹ v; any other S through the eigendecomposition.
fn pinv_apply(s: DMatrix<f64>, v: &DVector<f64>) -> DVector<f64> {
    if let Some(ch) = s.clone().cholesky() {
        let cond = condition_estimate(&s, &ch);
        if cond.is_finite() && cond < CHOLESKY_MAX_CONDITION {
            return ch.solve(v);
        }
    }
    if s.nrows() >= LOW_RANK_MIN_SIZE {
        if let Some(x) = pinv_low_rank(&s, v) {
            return x;
        }
    }
    pinv_eigen(s, v)
}

/// Smallest S for which [`pinv_low_rank`] is tried.
const LOW_RANK_MIN_SIZE: usize = 200;

/// Ritz values below the cutoff that a trial subspace must hold for it to be accepted: the
/// subspace then reaches past every eigenvalue the pseudo-inverse keeps.
const LOW_RANK_MARGIN: usize = 16;

/// [`pinv_eigen`] for an S of low numerical rank (strain of a few modes through a smooth
/// encoder is that: 7 of 1326 eigenvalues above the cutoff for raw strain, 60 for encoded, in
/// the published case), from the eigenpairs of S restricted to a subspace instead of all of
/// them. The subspace: ℓ seeded random vectors through S and four rounds of subspace iteration
/// (Halko, Martinsson & Tropp 2011); Rayleigh–Ritz on it gives S's leading eigenpairs. It is
/// accepted when (a) at least [`LOW_RANK_MARGIN`] of its Ritz values fall below the cutoff
/// p·ε·λ_max, and (b) on eight fresh random probes ω, ‖(I − QQᵀ) S ω‖ is below a tenth of the
/// cutoff times ‖ω‖, so that what the subspace leaves out of S is below what the pseudo-inverse
/// treats as zero anyway (Halko et al. §4.3). Else ℓ doubles; `None` once ℓ would pass p / 2
/// (the full eigendecomposition is then as cheap).
fn pinv_low_rank(s: &DMatrix<f64>, v: &DVector<f64>) -> Option<DVector<f64>> {
    use rand::SeedableRng;
    use rand_distr::{Distribution, StandardNormal};
    let p = s.nrows();
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0x5eed_2016);
    let mut gauss = |rows: usize, cols: usize| {
        DMatrix::from_fn(rows, cols, |_, _| {
            <StandardNormal as Distribution<f64>>::sample(&StandardNormal, &mut rng)
        })
    };
    let mut l = 64;
    while 2 * l <= p {
        let mut q = (s * gauss(p, l)).qr().q();
        for _ in 0..4 {
            q = (s * &q).qr().q();
        }
        let sq = s * &q;
        let t = q.transpose() * &sq;
        let t = (&t + t.transpose()) * 0.5;
        let eig = SymmetricEigen::new(t);
        let lmax = eig.eigenvalues.iter().fold(0.0_f64, |a, &b| a.max(b.abs()));
        let tol = p as f64 * f64::EPSILON * lmax;
        let kept = eig.eigenvalues.iter().filter(|&&e| e > tol).count();
        if lmax > 0.0 && kept + LOW_RANK_MARGIN <= l {
            let probes = gauss(p, 8);
            let sw = s * &probes;
            let left = &sw - &q * (q.transpose() * &sw);
            let worst = (0..8)
                .map(|j| left.column(j).norm() / probes.column(j).norm())
                .fold(0.0_f64, f64::max);
            if worst.is_finite() && worst <= 0.1 * tol {
                let coeffs = eig.eigenvectors.transpose() * (q.transpose() * v);
                let scaled = DVector::from_iterator(
                    l,
                    coeffs.iter().zip(eig.eigenvalues.iter()).map(|(c, &e)| {
                        if e > tol {
                            c / e
                        } else {
                            0.0
                        }
                    }),
                );
                return Some(q * (eig.eigenvectors * scaled));
            }
        }
        l *= 2;
    }
    None
}

/// [`pinv_apply`] through the eigendecomposition.
fn pinv_eigen(s: DMatrix<f64>, v: &DVector<f64>) -> DVector<f64> {
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

/// The first two moments of two classes' training data: each class's sample count, column
/// means and scatter Σ_i (x − μ)(x − μ)ᵀ. A discriminant on any subset of the features is fitted
/// from them without touching the samples again ([`Moments::fit`]): the subset's means and
/// scatters are the entries of the full ones, so a random or sparse sensor set costs a solve of
/// its own size, not a pass over every sample.
#[derive(Clone, Debug)]
pub struct Moments {
    counts: [usize; 2],
    means: [DVector<f64>; 2],
    scatters: [DMatrix<f64>; 2],
}

impl Moments {
    /// The moments of two classes (rows samples, columns features), checked as
    /// [`Discriminant::fit`] checks them.
    pub fn new(class0: &DMatrix<f64>, class1: &DMatrix<f64>) -> Result<Moments> {
        check_classes(class0, class1)?;
        let (mu0, mu1) = (column_means(class0), column_means(class1));
        let (s0, s1) = (scatter(class0, &mu0), scatter(class1, &mu1));
        Ok(Moments {
            counts: [class0.nrows(), class1.nrows()],
            means: [mu0, mu1],
            scatters: [s0, s1],
        })
    }

    /// Features per sample.
    pub fn features(&self) -> usize {
        self.means[0].len()
    }

    /// Training samples of each class.
    pub fn counts(&self) -> [usize; 2] {
        self.counts
    }

    /// The uncentred second moment X Xᵀ of all the training samples together (X: features ×
    /// samples), Σ_c (S_c + n_c μ_c μ_cᵀ): its eigenvectors are X's left singular vectors.
    pub fn gram(&self) -> DMatrix<f64> {
        let mut g = &self.scatters[0] + &self.scatters[1];
        for (mu, &n) in self.means.iter().zip(&self.counts) {
            g.ger(n as f64, mu, mu, 1.0);
        }
        g
    }

    /// The moments of the data projected on the columns of `basis` (features × r): the means
    /// Bᵀμ_c and the scatters Bᵀ S_c B, those of the samples' coordinates in that basis.
    pub fn project(&self, basis: &DMatrix<f64>) -> Moments {
        let bt = basis.transpose();
        Moments {
            counts: self.counts,
            means: [&bt * &self.means[0], &bt * &self.means[1]],
            scatters: [
                &bt * &self.scatters[0] * basis,
                &bt * &self.scatters[1] * basis,
            ],
        }
    }

    /// The separation d′² = Δμᵀ Σ⁺ Δμ of the features `idx` (Σ = S_w / (n₀ + n₁ − 2), the
    /// pooled within-class covariance): the squared distance between the class means in units
    /// of their spread along the discriminant, what a greedy sensor choice maximises.
    pub fn separation(&self, idx: &[usize]) -> f64 {
        let q = idx.len();
        if q == 0 {
            return 0.0;
        }
        let dof = (self.counts[0] + self.counts[1]).saturating_sub(2).max(1) as f64;
        let cov = DMatrix::from_fn(q, q, |i, j| {
            (self.scatters[0][(idx[i], idx[j])] + self.scatters[1][(idx[i], idx[j])]) / dof
        });
        let d = DVector::from_fn(q, |i, _| self.means[1][idx[i]] - self.means[0][idx[i]]);
        let x = pinv_apply(cov, &d);
        d.dot(&x).max(0.0)
    }

    /// Greedy forward selection of up to `k` features by [`Moments::separation`]: each step
    /// adds the feature that raises d′² most (the lowest index on a tie). Returns the order in
    /// which they were chosen and d′² after each.
    pub fn greedy(&self, k: usize) -> (Vec<usize>, Vec<f64>) {
        let p = self.features();
        let mut chosen: Vec<usize> = Vec::with_capacity(k.min(p));
        let mut gains = Vec::with_capacity(k.min(p));
        let mut taken = vec![false; p];
        for _ in 0..k.min(p) {
            let mut best: Option<(usize, f64)> = None;
            let mut trial = chosen.clone();
            trial.push(0);
            for j in (0..p).filter(|&j| !taken[j]) {
                *trial.last_mut().expect("pushed") = j;
                let v = self.separation(&trial);
                if v.is_finite() && best.is_none_or(|(_, b)| v > b) {
                    best = Some((j, v));
                }
            }
            let Some((j, v)) = best else { break };
            taken[j] = true;
            chosen.push(j);
            gains.push(v);
        }
        (chosen, gains)
    }

    /// The discriminant on the features `idx` (all when `None`); the same as
    /// [`Discriminant::fit`] on those columns of the training data, up to rounding. Errors when
    /// an index is out of range or no direction separates the class means.
    pub fn fit(&self, idx: Option<&[usize]>, rule: ThresholdRule) -> Result<Discriminant> {
        let p = self.features();
        let all: Vec<usize>;
        let idx = match idx {
            Some(i) => i,
            None => {
                all = (0..p).collect();
                &all
            }
        };
        if let Some(&bad) = idx.iter().find(|&&i| i >= p) {
            return Err(WingbeatError::invalid(
                "feature index",
                bad,
                format!("0 to {}", p - 1),
            ));
        }
        if idx.is_empty() {
            return Err(WingbeatError::invalid(
                "features",
                0,
                "at least one feature",
            ));
        }
        let q = idx.len();
        let sub = |s: &DMatrix<f64>| DMatrix::from_fn(q, q, |i, j| s[(idx[i], idx[j])]);
        let subv = |v: &DVector<f64>| DVector::from_fn(q, |i, _| v[idx[i]]);
        let (s0, s1) = (sub(&self.scatters[0]), sub(&self.scatters[1]));
        let (mu0, mu1) = (subv(&self.means[0]), subv(&self.means[1]));
        let w = pinv_apply(&s0 + &s1, &(&mu1 - &mu0));
        let spread = |s: &DMatrix<f64>, w: &DVector<f64>, n: usize| {
            (w.dot(&(s * w)).max(0.0) / (n as f64 - 1.0)).sqrt()
        };
        finish(
            w,
            |w| [mu0.dot(w), mu1.dot(w)],
            |w| {
                [
                    spread(&s0, w, self.counts[0]),
                    spread(&s1, w, self.counts[1]),
                ]
            },
            rule,
        )
    }
}

/// The discriminant from an unnormalised direction `w`, the projected class means and spreads
/// of a direction: normalised, signed so that class 1 projects higher, its threshold set.
fn finish(
    mut w: DVector<f64>,
    means: impl Fn(&DVector<f64>) -> [f64; 2],
    stds: impl Fn(&DVector<f64>) -> [f64; 2],
    rule: ThresholdRule,
) -> Result<Discriminant> {
    let norm = w.norm();
    if !(norm > 0.0 && norm.is_finite()) {
        return Err(WingbeatError::invalid(
            "training data",
            "no direction separates the class means",
            "two classes whose means differ",
        ));
    }
    w /= norm;
    let [m0, m1] = means(&w);
    if m1 < m0 {
        w = -w;
    }
    let ([m0, m1], [s0, s1]) = (means(&w), stds(&w));
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
        let w = pinv_apply(sw, &(&mu1 - &mu0));
        let project =
            |c: &DMatrix<f64>, w: &DVector<f64>| (c * w).iter().copied().collect::<Vec<f64>>();
        finish(
            w,
            |w| {
                [
                    mean_std(&project(class0, w)).0,
                    mean_std(&project(class1, w)).0,
                ]
            },
            |w| {
                [
                    mean_std(&project(class0, w)).1,
                    mean_std(&project(class1, w)).1,
                ]
            },
            rule,
        )
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

    #[test]
    fn both_pseudo_inverse_routes_agree() {
        // Well conditioned: the Cholesky route, equal to the eigendecomposition's S⁺ v.
        let p = 40;
        let x = DMatrix::from_fn(200, p, |i, j| ((i * 31 + j * 17) % 97) as f64 / 97.0 - 0.5);
        let s = x.transpose() * &x;
        let v = DVector::from_fn(p, |i, _| (i as f64 * 0.37).sin());
        let ch = s.clone().cholesky().unwrap();
        assert!(condition_estimate(&s, &ch) < CHOLESKY_MAX_CONDITION);
        let (a, b) = (pinv_apply(s.clone(), &v), pinv_eigen(s, &v));
        assert!((&a - &b).norm() <= 1e-9 * b.norm(), "{}", (&a - &b).norm());
        // Rank 5 in 40 dimensions: the pseudo-inverse, never the (meaningless) inverse.
        let low = DMatrix::from_fn(200, 5, |i, j| ((i * 13 + j * 7) % 29) as f64 / 29.0 - 0.5);
        let mix = DMatrix::from_fn(5, p, |i, j| ((i + 2 * j) as f64 * 0.71).cos());
        let x = low * mix;
        let s = x.transpose() * &x;
        let (a, b) = (pinv_apply(s.clone(), &v), pinv_eigen(s, &v));
        assert!(
            (&a - &b).norm() <= 1e-12 * b.norm().max(1e-300),
            "{}",
            (&a - &b).norm()
        );
    }

    #[test]
    fn moments_fit_equals_the_fit_on_the_columns() {
        // Two correlated, overlapping classes; the subsets' discriminants from the full moments
        // must be the discriminants of those columns' samples.
        let p = 12;
        let gen = |n: usize, shift: f64, seed: usize| {
            DMatrix::from_fn(n, p, |i, j| {
                let a = ((i * 7919 + j * 104_729 + seed) % 1009) as f64 / 1009.0 - 0.5;
                let b = ((i * 31 + seed * 17) % 97) as f64 / 97.0 - 0.5;
                a + 0.6 * b * (j as f64 * 0.4).cos() + shift * (j as f64 * 0.3).sin()
            })
        };
        let (c0, c1) = (gen(300, 0.0, 1), gen(250, 0.2, 5));
        let m = Moments::new(&c0, &c1).unwrap();
        for idx in [
            vec![3usize],
            vec![0, 5, 11],
            vec![2, 4, 6, 8, 10, 1],
            (0..p).collect(),
        ] {
            for rule in [ThresholdRule::GaussianCrossing, ThresholdRule::Midpoint] {
                let pick = |c: &DMatrix<f64>| {
                    DMatrix::from_fn(c.nrows(), idx.len(), |i, j| c[(i, idx[j])])
                };
                let a = m.fit(Some(&idx), rule).unwrap();
                let b = Discriminant::fit(&pick(&c0), &pick(&c1), rule).unwrap();
                assert!((&a.direction - &b.direction).norm() < 1e-10, "{idx:?}");
                for (x, y) in [
                    (a.threshold, b.threshold),
                    (a.means[0], b.means[0]),
                    (a.means[1], b.means[1]),
                    (a.stds[0], b.stds[0]),
                    (a.stds[1], b.stds[1]),
                ] {
                    assert!(
                        (x - y).abs() < 1e-10 * (1.0 + y.abs()),
                        "{idx:?}: {x} vs {y}"
                    );
                }
            }
        }
        let all = m.fit(None, ThresholdRule::GaussianCrossing).unwrap();
        let direct = Discriminant::fit(&c0, &c1, ThresholdRule::GaussianCrossing).unwrap();
        assert!((&all.direction - &direct.direction).norm() < 1e-10);
        assert!(m.fit(Some(&[p]), ThresholdRule::Midpoint).is_err());
        assert!(m.fit(Some(&[]), ThresholdRule::Midpoint).is_err());
    }

    #[test]
    fn the_low_rank_route_is_the_pseudo_inverse() {
        // 400 features of rank 25 with a spread-out spectrum (1 … 1e-6): accepted on the first
        // trial subspace and equal to the eigendecomposition's S⁺ v.
        let (p, r) = (400, 25);
        let basis = DMatrix::from_fn(p, r, |i, j| ((i * 37 + j * 91) % 211) as f64 / 211.0 - 0.5)
            .qr()
            .q();
        let lam = DMatrix::from_diagonal(&DVector::from_fn(r, |k, _| {
            10f64.powf(-6.0 * k as f64 / 24.0)
        }));
        let s = &basis * lam * basis.transpose();
        let s = (&s + s.transpose()) * 0.5;
        let v = DVector::from_fn(p, |i, _| (i as f64 * 0.13).cos());
        let fast = pinv_low_rank(&s, &v).expect("rank 25 of 400 is low");
        let full = pinv_eigen(s, &v);
        assert!(
            (&fast - &full).norm() <= 1e-8 * full.norm(),
            "{}",
            (&fast - &full).norm() / full.norm()
        );
        // Full rank: no subspace below p / 2 holds it, so the route declines.
        let x = DMatrix::from_fn(900, 300, |i, j| {
            ((i * 7919 + j * 104_729) % 1009) as f64 / 1009.0 - 0.5
        });
        let full_rank = x.transpose() * &x;
        let w = DVector::from_element(300, 1.0);
        assert!(pinv_low_rank(&full_rank, &w).is_none());
    }

    #[test]
    fn the_gram_and_projected_moments_are_those_of_the_data() {
        let gen = |n: usize, seed: usize| {
            DMatrix::from_fn(n, 6, |i, j| {
                ((i * 131 + j * 71 + seed) % 53) as f64 / 53.0 + 0.1 * j as f64
            })
        };
        let (c0, c1) = (gen(40, 1), gen(30, 9));
        let m = Moments::new(&c0, &c1).unwrap();
        // X Xᵀ with X the features × samples matrix of both classes.
        let gram = c0.transpose() * &c0 + c1.transpose() * &c1;
        assert!((m.gram() - &gram).amax() < 1e-12 * gram.amax());
        let b = DMatrix::from_fn(6, 2, |i, j| ((i + 3 * j) as f64 * 0.7).sin());
        let direct = Moments::new(&(&c0 * &b), &(&c1 * &b)).unwrap();
        let projected = m.project(&b);
        for c in 0..2 {
            assert!((&projected.means[c] - &direct.means[c]).amax() < 1e-12);
            assert!((&projected.scatters[c] - &direct.scatters[c]).amax() < 1e-10);
        }
    }

    #[test]
    fn greedy_separation_picks_the_informative_features_first() {
        // 12 features of pseudo-random noise (spread growing with the index); the class means
        // differ on features 2 (by 0.5) and 9 (by 0.3) only. Feature 2 alone separates best,
        // then 9; d′² of one feature is Δμ² / σ̂² exactly, and of a set Δμᵀ Σ̂⁻¹ Δμ.
        let p = 12;
        let noise = |i: usize, j: usize, c: usize| {
            let x = ((i * 7919 + j * 104_729 + c * 15_485_863) as f64 * 0.618_033_988_75).fract();
            let y = ((i * 104_723 + j * 7907 + c * 3) as f64 * 0.414_213_562_37).fract();
            (x + y - 1.0) * 2.0
        };
        let mk = |c: usize, n: usize| {
            DMatrix::from_fn(n, p, |i, j| {
                let shift = if c == 1 && j == 2 {
                    0.5
                } else if c == 1 && j == 9 {
                    0.3
                } else {
                    0.0
                };
                shift + (0.5 + 0.1 * j as f64) * noise(i, j, c)
            })
        };
        let (c0, c1) = (mk(0, 2000), mk(1, 2000));
        let m = Moments::new(&c0, &c1).unwrap();
        let (order, gains) = m.greedy(3);
        assert_eq!(&order[..2], &[2, 9], "{order:?}");
        assert!(
            gains.windows(2).all(|w| w[1] >= w[0]),
            "d′² never falls: {gains:?}"
        );
        let dof = (4000 - 2) as f64;
        let var2 = (m.scatters[0][(2, 2)] + m.scatters[1][(2, 2)]) / dof;
        let d2 = m.means[1][2] - m.means[0][2];
        assert!((m.separation(&[2]) - d2 * d2 / var2).abs() < 1e-12 * d2 * d2 / var2);
        let idx = [2usize, 9, 5];
        let cov = DMatrix::from_fn(3, 3, |a, b| {
            (m.scatters[0][(idx[a], idx[b])] + m.scatters[1][(idx[a], idx[b])]) / dof
        });
        let d = DVector::from_fn(3, |a, _| m.means[1][idx[a]] - m.means[0][idx[a]]);
        let want = d.dot(&(cov.try_inverse().unwrap() * &d));
        assert!((m.separation(&idx) - want).abs() < 1e-10 * want);
    }
}
