//! Sparse sensor placement for classification, SSPOC (Brunton, Brunton, Proctor & Kutz, SIAM J.
//! Appl. Math. 76:2099, 2016), as Mohren et al. 2018 used it (docs/sensing.md):
//!
//! 1. the r leading left singular vectors Ψ of the training data X (sensors × samples, not
//!    centred);
//! 2. Fisher's discriminant w in the r-dimensional mode space (analysis::classify);
//! 3. the modes T with the largest |w_i| σ_i kept (`kept_modes` of them);
//! 4. the sparse sensor weights s = argmin α‖s‖₁ + (1 − α)‖s‖₂ subject to Ψ_Tᵀ s = w_T, a
//!    second-order cone program solved by Clarabel (an interior-point conic solver);
//! 5. the sensors: the largest |s_i|, either the K asked for or, as published, those of the r
//!    largest with |s_i| ≥ ‖s‖₂ / r.
//!
//! The singular vectors come from a seeded randomised subspace iteration (Halko, Martinsson &
//! Tropp 2011): on the data itself ([`leading_singular`]) or, as the sweep takes them, on the
//! p × p Gram matrix X Xᵀ assembled from the training moments ([`leading_eigen`],
//! [`Moments::gram`]), which costs products with a 1326 × 1326 matrix instead of a
//! 1326 × 5400 one; both are checked against a full SVD in the tests.

use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettingsBuilder, DefaultSolver, IPSolver, SolverStatus, SupportedConeT,
};
use nalgebra::{DMatrix, DVector};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::StandardNormal;

use super::classify::{Moments, ThresholdRule};
use crate::{Result, WingbeatError};

/// How many sensors SSPOC returns.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SensorCount {
    /// The published rule: of the r largest |s_i|, those with |s_i| ≥ ‖s‖₂ / r.
    Cutoff,
    /// The K largest |s_i| (K ≥ 1).
    Top(usize),
}

/// SSPOC's settings.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SspocConfig {
    /// r, the number of singular vectors (published: 30).
    pub rank: usize,
    /// How many of them constrain the sensor weights, by |w_i| σ_i (published: swept 1…30).
    pub kept_modes: usize,
    /// α, the weight of ‖s‖₁ against ‖s‖₂ (published: 0.9).
    pub l1_weight: f64,
    /// How many sensors are returned.
    pub sensors: SensorCount,
    /// Seed of the randomised SVD's start.
    pub seed: u64,
}

impl Default for SspocConfig {
    fn default() -> Self {
        SspocConfig {
            rank: 30,
            kept_modes: 10,
            l1_weight: 0.9,
            sensors: SensorCount::Cutoff,
            seed: 1,
        }
    }
}

/// What SSPOC found.
#[derive(Clone, Debug, PartialEq)]
pub struct Sspoc {
    /// The chosen sensors (column indices of the training data), largest |s_i| first.
    pub sensors: Vec<usize>,
    /// The sparse weight vector s (one entry per sensor).
    pub weights: Vec<f64>,
    /// The r leading singular values of the training data.
    pub singular_values: Vec<f64>,
    /// The kept modes T (indices into the singular vectors).
    pub kept_modes: Vec<usize>,
}

/// The r leading left singular vectors and values of `x` (rows × columns), by randomised subspace
/// iteration with `power` power iterations and 10 extra columns, seeded.
pub fn leading_singular(
    x: &DMatrix<f64>,
    r: usize,
    power: usize,
    seed: u64,
) -> (DMatrix<f64>, Vec<f64>) {
    let (m, n) = x.shape();
    let l = (r + 10).min(m).min(n);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let omega = DMatrix::from_fn(n, l, |_, _| rng.sample::<f64, _>(StandardNormal));
    let mut q = (x * omega).qr().q();
    for _ in 0..power {
        let z = (x.transpose() * &q).qr().q();
        q = (x * z).qr().q();
    }
    let b = q.transpose() * x; // l × n
    let svd = b.svd(true, false);
    let u_b = svd.u.expect("requested");
    // nalgebra's SVD does not sort: order by singular value.
    let mut order: Vec<usize> = (0..svd.singular_values.len()).collect();
    order.sort_by(|&i, &j| svd.singular_values[j].total_cmp(&svd.singular_values[i]));
    let k = r.min(order.len());
    let u = q * DMatrix::from_fn(l, k, |i, j| u_b[(i, order[j])]);
    (
        u,
        order[..k].iter().map(|&i| svd.singular_values[i]).collect(),
    )
}

/// The r leading eigenvectors of a symmetric positive semi-definite `g` (p × p) and the square
/// roots of their eigenvalues, by seeded randomised subspace iteration (r + 10 columns, `power`
/// products with g after the first) and Rayleigh–Ritz. With g = X Xᵀ these are X's r leading
/// left singular vectors and values ([`leading_singular`]) at the cost of products with a p × p
/// matrix instead of the p × n data.
pub fn leading_eigen(
    g: &DMatrix<f64>,
    r: usize,
    power: usize,
    seed: u64,
) -> (DMatrix<f64>, Vec<f64>) {
    let p = g.nrows();
    let l = (r + 10).min(p);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let omega = DMatrix::from_fn(p, l, |_, _| rng.sample::<f64, _>(StandardNormal));
    let mut q = (g * omega).qr().q();
    for _ in 0..power {
        q = (g * &q).qr().q();
    }
    let t = q.transpose() * g * &q;
    let eig = nalgebra::SymmetricEigen::new((&t + t.transpose()) * 0.5);
    let mut order: Vec<usize> = (0..eig.eigenvalues.len()).collect();
    order.sort_by(|&i, &j| eig.eigenvalues[j].total_cmp(&eig.eigenvalues[i]));
    let k = r.min(order.len());
    let u = q * DMatrix::from_fn(l, k, |i, j| eig.eigenvectors[(i, order[j])]);
    (
        u,
        order[..k]
            .iter()
            .map(|&i| eig.eigenvalues[i].max(0.0).sqrt())
            .collect(),
    )
}

fn check_config(cfg: &SspocConfig, sensors: usize, samples: usize) -> Result<()> {
    let max_rank = sensors.min(samples);
    if cfg.rank == 0 || cfg.rank > max_rank {
        return Err(WingbeatError::invalid(
            "sspoc.rank",
            cfg.rank,
            format!("1 to {max_rank} (sensors and samples)"),
        ));
    }
    if cfg.kept_modes == 0 || cfg.kept_modes > cfg.rank {
        return Err(WingbeatError::invalid(
            "sspoc.kept_modes",
            cfg.kept_modes,
            format!("1 to sspoc.rank ({})", cfg.rank),
        ));
    }
    if !(cfg.l1_weight.is_finite() && cfg.l1_weight > 0.0 && cfg.l1_weight <= 1.0) {
        return Err(WingbeatError::invalid(
            "sspoc.l1_weight",
            cfg.l1_weight,
            "above 0, at most 1",
        ));
    }
    if let SensorCount::Top(k) = cfg.sensors {
        if k == 0 || k > sensors {
            return Err(WingbeatError::invalid(
                "sspoc.sensors",
                k,
                format!("1 to {sensors} (the sensors there are)"),
            ));
        }
    }
    Ok(())
}

/// min α‖s‖₁ + (1 − α)‖s‖₂ subject to Φᵀ s = c (Φ: sensors × t), as a conic program in
/// x = (s, u, v): s ∈ ℝᵖ, |s_i| ≤ u_i, ‖s‖₂ ≤ v; minimise α Σu + (1 − α) v.
pub fn elastic_net_equality(phi: &DMatrix<f64>, c: &DVector<f64>, alpha: f64) -> Result<Vec<f64>> {
    let (p, t) = phi.shape();
    let n = 2 * p + 1;
    let (mut rows, mut cols, mut vals) = (Vec::new(), Vec::new(), Vec::new());
    let mut push = |r: usize, c: usize, v: f64| {
        rows.push(r);
        cols.push(c);
        vals.push(v);
    };
    // Zero cone: Φᵀ s = c.
    for j in 0..t {
        for i in 0..p {
            let v = phi[(i, j)];
            if v != 0.0 {
                push(j, i, v);
            }
        }
    }
    // Non-negative cone: u − s ≥ 0 and u + s ≥ 0 (slack = b − A x).
    for i in 0..p {
        push(t + i, i, 1.0);
        push(t + i, p + i, -1.0);
        push(t + p + i, i, -1.0);
        push(t + p + i, p + i, -1.0);
    }
    // Second-order cone: (v, s) with ‖s‖₂ ≤ v.
    let soc = t + 2 * p;
    push(soc, 2 * p, -1.0);
    for i in 0..p {
        push(soc + 1 + i, i, -1.0);
    }
    let m = soc + 1 + p;
    let a = CscMatrix::new_from_triplets(m, n, rows, cols, vals);
    let mut b = vec![0.0; m];
    b[..t].copy_from_slice(c.as_slice());
    let mut q = vec![0.0; n];
    q[p..2 * p].fill(alpha);
    q[2 * p] = 1.0 - alpha;
    let pmat = CscMatrix::zeros((n, n));
    let cones = [
        SupportedConeT::ZeroConeT(t),
        SupportedConeT::NonnegativeConeT(2 * p),
        SupportedConeT::SecondOrderConeT(p + 1),
    ];
    let settings = DefaultSettingsBuilder::default()
        .verbose(false)
        .build()
        .expect("valid settings");
    let mut solver = DefaultSolver::new(&pmat, &q, &a, &b, &cones, settings).map_err(|e| {
        WingbeatError::NoConvergence {
            method: "SSPOC's conic program".into(),
            detail: e.to_string(),
        }
    })?;
    solver.solve();
    match solver.solution.status {
        SolverStatus::Solved | SolverStatus::AlmostSolved => Ok(solver.solution.x[..p].to_vec()),
        s => Err(WingbeatError::NoConvergence {
            method: "SSPOC's conic program (Clarabel)".into(),
            detail: format!(
                "status {s:?} after {} iterations",
                solver.solution.iterations
            ),
        }),
    }
}

/// SSPOC on two classes of training data (rows samples, columns sensors).
pub fn sspoc(class0: &DMatrix<f64>, class1: &DMatrix<f64>, cfg: &SspocConfig) -> Result<Sspoc> {
    let mut v = sspoc_sweep(class0, class1, cfg, &[cfg.kept_modes])?;
    Ok(v.remove(0))
}

/// SSPOC for several numbers of kept modes (`cfg.kept_modes` is ignored; each entry of
/// `kept_modes` is checked as it would be): the SVD and the discriminant in mode space are
/// computed once, the sparse weights once per entry.
pub fn sspoc_sweep(
    class0: &DMatrix<f64>,
    class1: &DMatrix<f64>,
    cfg: &SspocConfig,
    kept_modes: &[usize],
) -> Result<Vec<Sspoc>> {
    sspoc_sweep_moments(&Moments::new(class0, class1)?, cfg, kept_modes)
}

/// [`sspoc_sweep`] from the training data's moments: the left singular vectors are the
/// eigenvectors of X Xᵀ ([`Moments::gram`], [`leading_eigen`]) and the discriminant in mode
/// space is fitted from the projected moments, so neither pass touches the samples.
pub fn sspoc_sweep_moments(
    moments: &Moments,
    cfg: &SspocConfig,
    kept_modes: &[usize],
) -> Result<Vec<Sspoc>> {
    let p = moments.features();
    let [n0, n1] = moments.counts();
    for &k in kept_modes {
        check_config(
            &SspocConfig {
                kept_modes: k,
                ..*cfg
            },
            p,
            n0 + n1,
        )?;
    }
    let (psi, sigma) = leading_eigen(&moments.gram(), cfg.rank, 4, cfg.seed);
    let r = psi.ncols();
    let lda = moments
        .project(&psi)
        .fit(None, ThresholdRule::GaussianCrossing)?;
    let w = &lda.direction;
    let mut ranked: Vec<usize> = (0..r).collect();
    ranked.sort_by(|&i, &j| (w[j].abs() * sigma[j]).total_cmp(&(w[i].abs() * sigma[i])));
    kept_modes
        .iter()
        .map(|&kept| {
            let modes: Vec<usize> = ranked.iter().copied().take(kept.min(r)).collect();
            let phi = DMatrix::from_fn(p, modes.len(), |i, j| psi[(i, modes[j])]);
            let c = DVector::from_iterator(modes.len(), modes.iter().map(|&k| w[k]));
            let s = elastic_net_equality(&phi, &c, cfg.l1_weight)?;
            let mut order: Vec<usize> = (0..p).collect();
            order.sort_by(|&i, &j| s[j].abs().total_cmp(&s[i].abs()).then(i.cmp(&j)));
            let sensors = match cfg.sensors {
                SensorCount::Top(k) => order[..k].to_vec(),
                SensorCount::Cutoff => {
                    let norm = s.iter().map(|v| v * v).sum::<f64>().sqrt();
                    order
                        .iter()
                        .take(r)
                        .copied()
                        .filter(|&i| s[i].abs() >= norm / r as f64)
                        .collect()
                }
            };
            Ok(Sspoc {
                sensors,
                weights: s,
                singular_values: sigma.clone(),
                kept_modes: modes,
            })
        })
        .collect()
}
