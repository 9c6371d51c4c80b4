//! Lowest eigenpairs of K φ = λ M φ (λ = ω², the discrete form of paper Eq. 10, with the
//! vectors M-orthonormal as in Eq. 9) by shift-invert block Krylov iteration with full
//! M-orthogonalisation and Rayleigh–Ritz on (K, M).
//!
//! The operator is (K − σM)⁻¹M with a small negative shift σ, so K − σM is positive
//! definite even for a free structure (six rigid-body zero modes), and the envelope LDLᵀ of
//! [`super::sparse`] needs no pivoting. The factorisation is any [`SpdFactor`] backend
//! ([`super::linalg`]): [`lowest_modes_with`] is generic over it and [`lowest_modes`] picks
//! one from [`EigenOptions::backend`]. The block size (≥ 6) lets the iteration pick up the
//! six-fold rigid-body null space, and repeated eigenvalues, in one sweep. The basis size is
//! capped: when the requested modes have not met the tolerance by then, the solver returns
//! [`WingbeatError::NoConvergence`] — it never loops without bound.

use super::blocksparse::BlockSym;
use super::linalg::{Backend, SkylineLdlt, SparseLdlt, SpdFactor, SymOperator};
use super::sparse::{dot, Skyline};
use crate::error::{Result, WingbeatError};
use nalgebra::DMatrix;

/// Result of [`lowest_modes`].
#[derive(Debug, Clone)]
pub struct EigenResult {
    /// Eigenvalues λ = ω² (rad²/s²), ascending.
    pub values: Vec<f64>,
    /// M-orthonormal eigenvectors (φᵀ M φ = 1), one per value.
    pub vectors: Vec<Vec<f64>>,
    /// ‖Kφ − λMφ‖ / max(‖Kφ‖, |σ|‖Mφ‖) per mode (the |σ| term keeps the ratio meaningful
    /// for rigid-body modes, where Kφ ≈ 0).
    pub residuals: Vec<f64>,
    /// Block iterations used.
    pub iterations: usize,
    /// The shift σ used (rad²/s², negative).
    pub shift: f64,
    /// Final Krylov basis size.
    pub basis: usize,
}

/// Options of [`lowest_modes`].
#[derive(Debug, Clone, Copy)]
pub struct EigenOptions {
    /// Required relative residual per mode.
    pub tol: f64,
    /// Largest Krylov basis (columns) before giving up.
    pub max_basis: usize,
    /// Block size (at least 6 to catch the rigid-body modes of a free structure).
    pub block: usize,
    /// Sparse factorisation of K − σM (see [`super::linalg`]).
    pub backend: Backend,
}

impl Default for EigenOptions {
    fn default() -> Self {
        EigenOptions {
            tol: 1e-6,
            max_basis: 400,
            block: 8,
            backend: Backend::default(),
        }
    }
}

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    }
}

fn mdot(a: &[f64], b: &[f64], m: &[f64]) -> f64 {
    a.iter().zip(b).zip(m).map(|((x, y), w)| x * y * w).sum()
}

/// Lowest `n_modes` eigenpairs of K φ = λ M φ with K in skyline storage (symmetric positive
/// semi-definite) and M diagonal (`m_diag`, all entries > 0), factoring with the backend
/// named in `opt.backend`.
pub fn lowest_modes(
    k: &Skyline,
    m_diag: &[f64],
    n_modes: usize,
    opt: EigenOptions,
) -> Result<EigenResult> {
    match opt.backend {
        Backend::Sparse => {
            lowest_modes_with::<SparseLdlt>(&BlockSym::from_skyline(k), m_diag, n_modes, opt)
        }
        Backend::Skyline => lowest_modes_with::<SkylineLdlt>(k, m_diag, n_modes, opt),
        #[cfg(feature = "faer")]
        Backend::Faer => lowest_modes_with::<super::linalg::FaerLlt>(k, m_diag, n_modes, opt),
        #[cfg(not(feature = "faer"))]
        Backend::Faer => Err(WingbeatError::invalid(
            "backend",
            "faer",
            "skyline (this build lacks the `faer` cargo feature)",
        )),
    }
}

/// What to change when the eigen-solver fails, appended to its messages.
pub const SOLVER_REMEDY: &str = "what to change: fewer modes (`n_modes`), a coarser mesh \
(`mesh_size_mm`), a clamp that holds the wing (`clamp`), or material values nearer a real \
wing (`material.e_pa`, `material.thickness_m`, `material.rho_kg_m3`)";

/// [`lowest_modes`] with the factorisation backend `F` fixed at compile time
/// (`opt.backend` is ignored).
pub fn lowest_modes_with<F: SpdFactor>(
    k: &F::Matrix,
    m_diag: &[f64],
    n_modes: usize,
    opt: EigenOptions,
) -> Result<EigenResult> {
    let n = k.dim();
    if n_modes == 0 || n_modes > n {
        return Err(WingbeatError::invalid(
            "n_modes",
            n_modes,
            format!("1 ..= number of free DOFs ({n})"),
        ));
    }
    let (fac, sigma) = initial_shift::<F>(k, m_diag)?;
    let (fac, sigma) = reshift(k, m_diag, opt.block, fac, sigma);
    let op = |x: &[f64]| -> Vec<f64> {
        let mut y: Vec<f64> = x.iter().zip(m_diag).map(|(a, b)| a * b).collect();
        fac.solve_in_place(&mut y);
        y
    };
    let p = opt.block.max(6).min(n);
    let max_basis = opt.max_basis.max(n_modes + 2 * p).min(n);
    let mut basis: Vec<Vec<f64>> = Vec::new();
    let mut kr: Vec<Vec<f64>> = Vec::new(); // kr[j][i] = v_iᵀ K v_j, i ≤ j

    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let start: Vec<Vec<f64>> = (0..p)
        .map(|_| op(&(0..n).map(|_| rng.next()).collect::<Vec<_>>()))
        .collect();
    extend(k, m_diag, max_basis, start, &mut basis, &mut kr);
    let mut last = 0;
    let mut iterations = 0;
    let mut best_detail = String::new();
    let mut prev_ritz: Vec<f64> = Vec::new();
    loop {
        iterations += 1;
        let m = basis.len();
        // Rayleigh–Ritz once the basis can hold the wanted modes
        if m >= n_modes {
            let eig = projected(&kr, m).symmetric_eigen();
            let mut idx: Vec<usize> = (0..m).collect();
            idx.sort_by(|&x, &y| eig.eigenvalues[x].total_cmp(&eig.eigenvalues[y]));
            idx.truncate(n_modes);
            // cheap test first: only form Ritz vectors and true residuals once the wanted
            // Ritz values have settled (relative change below 1e-9 of the spectrum scale)
            let ritz: Vec<f64> = idx.iter().map(|&c| eig.eigenvalues[c]).collect();
            let settled = settled(&ritz, &prev_ritz, sigma);
            prev_ritz = ritz;
            if !settled && m < n && m < max_basis {
                best_detail = format!(
                    "Ritz values still moving after {iterations} block iterations (basis {m})"
                );
            } else {
                let found = ritz_pairs(k, m_diag, &basis, &eig, &idx, sigma);
                let result = |(values, vectors, residuals, _): Pairs| EigenResult {
                    values,
                    vectors,
                    residuals,
                    iterations,
                    shift: sigma,
                    basis: m,
                };
                let worst = found.3;
                if worst > opt.tol && m < n {
                    if let Some(better) = refine(k, m_diag, &op, &found.1, sigma) {
                        if better.3 <= opt.tol {
                            return Ok(result(better));
                        }
                    }
                }
                if worst <= opt.tol || m == n {
                    return Ok(result(found));
                }
                best_detail = format!(
                "worst relative residual {worst:.3e} > tol {:.1e} after {iterations} block iterations (basis {m})",
                opt.tol
            );
            }
        }
        if m >= max_basis || !best_detail.is_empty() && m == last {
            return Err(WingbeatError::NoConvergence {
                method: "shift-invert block Krylov".into(),
                detail: format!(
                    "{}; {SOLVER_REMEDY}",
                    if best_detail.is_empty() {
                        format!("basis stalled at {m} vectors")
                    } else {
                        best_detail
                    }
                ),
            });
        }
        let block: Vec<Vec<f64>> = basis[last..m].iter().map(|v| op(v)).collect();
        last = m;
        let added = extend(k, m_diag, max_basis, block, &mut basis, &mut kr);
        if added == 0 && basis.len() < n_modes {
            return Err(WingbeatError::NoConvergence {
                method: "shift-invert block Krylov".into(),
                detail: format!(
                    "the Krylov space ran out at {} independent vectors, fewer than the {n_modes} modes asked for; {SOLVER_REMEDY}",
                    basis.len()
                ),
            });
        }
    }
}

/// Eigenvalues, M-normalised vectors, residuals and the worst residual of a set of modes.
type Pairs = (Vec<f64>, Vec<Vec<f64>>, Vec<f64>, f64);

/// The a-priori shift and its factorisation: σ a small fraction of the smallest diagonal
/// ratio K_ii / M_ii, which scales like the lowest eigenvalue × (L/h)⁴ — far below the wanted
/// eigenvalues but far above rounding — made ten times larger (up to 6 tries) until K − σM
/// factors with no negative pivot.
fn initial_shift<F: SpdFactor>(k: &F::Matrix, m_diag: &[f64]) -> Result<(F, f64)> {
    let mut ratio = f64::INFINITY;
    for i in 0..k.dim() {
        let r = k.diag_entry(i) / m_diag[i];
        if r > 0.0 {
            ratio = ratio.min(r);
        }
    }
    if !ratio.is_finite() {
        return Err(WingbeatError::NonFinite {
            what: "stiffness matrix".into(),
            detail: format!("no positive diagonal entry; {SOLVER_REMEDY}"),
        });
    }
    let mut sigma = -1e-3 * ratio;
    for _ in 0..6 {
        match F::factor(k, sigma, m_diag) {
            Ok(f) if f.negative_pivots().unwrap_or(0) == 0 => return Ok((f, sigma)),
            _ => sigma *= 10.0,
        }
    }
    Err(WingbeatError::NoConvergence {
        method: "shifted LDLᵀ factorisation".into(),
        detail: format!("K − σM is not positive definite for any tried σ < 0; {SOLVER_REMEDY}"),
    })
}

/// Re-shift. The a-priori σ of [`initial_shift`] sits near λ1·(L/h)⁴·10⁻³, far below the
/// wanted modes on a fine mesh, where (K − σM)⁻¹M then barely separates them (the Krylov
/// basis needed grew with the mesh: 80 vectors at 1 653 nodes, 208 at 10 000). Two
/// applications of the operator to a block of random vectors give Ritz values whose
/// smallest, θ, is an upper bound of λ1; σ ← −θ/10 keeps K − σM positive definite and puts σ
/// on the scale of the lowest modes. Repeated while σ still drops by 3× (at most 4 times),
/// never below 10⁻⁶ of the a-priori |σ| (the rounding guard of a free structure's zero
/// modes). Returns the factorisation and shift in use.
fn reshift<F: SpdFactor>(
    k: &F::Matrix,
    m_diag: &[f64],
    block: usize,
    mut fac: F,
    mut sigma: f64,
) -> (F, f64) {
    let n = k.dim();
    let sigma0 = sigma;
    for _ in 0..4 {
        let mut r2 = Rng(0x2545_F491_4F6C_DD1D);
        let p0 = block.max(6).min(n);
        let start: Vec<Vec<f64>> = (0..p0)
            .map(|_| {
                let mut y: Vec<f64> = m_diag.iter().map(|m| r2.next() * m).collect();
                fac.solve_in_place(&mut y);
                y.iter_mut().zip(m_diag).for_each(|(a, b)| *a *= b);
                fac.solve_in_place(&mut y);
                y
            })
            .collect();
        let (mut b0, mut kr0) = (Vec::new(), Vec::new());
        extend(k, m_diag, p0, start, &mut b0, &mut kr0);
        let q = b0.len();
        if q == 0 {
            break;
        }
        let theta = projected(&kr0, q)
            .symmetric_eigen()
            .eigenvalues
            .iter()
            .fold(f64::INFINITY, |m, &v| m.min(v));
        let s1 = -0.1 * theta;
        if !(s1.is_finite() && s1 > 0.3 * sigma && s1 <= 1e-6 * sigma0) {
            break;
        }
        match fac.refactor(k, s1, m_diag) {
            Ok(f) if f.negative_pivots().unwrap_or(0) == 0 => {
                fac = f;
                sigma = s1;
            }
            _ => break,
        }
    }
    (fac, sigma)
}

/// VᵀKV (m × m, symmetric) from its upper triangle kept by column in `kr`.
fn projected(kr: &[Vec<f64>], m: usize) -> DMatrix<f64> {
    let mut a = DMatrix::<f64>::zeros(m, m);
    for j in 0..m {
        for i in 0..=j {
            a[(i, j)] = kr[j][i];
            a[(j, i)] = kr[j][i];
        }
    }
    a
}

/// Whether each wanted Ritz value moved by at most 1e-9 of the spectrum's scale (the largest
/// of |σ| and the values) since the previous iteration.
fn settled(ritz: &[f64], prev: &[f64], sigma: f64) -> bool {
    let scale = ritz.iter().fold(sigma.abs(), |s, v| s.max(v.abs()));
    prev.len() == ritz.len()
        && ritz
            .iter()
            .zip(prev)
            .all(|(a, b)| (a - b).abs() <= 1e-9 * scale.max(a.abs()))
}

/// The Ritz pairs of columns `idx` of the projected problem's eigen-decomposition: vectors
/// formed from the basis and M-normalised, with their true residuals ([`residual`]).
fn ritz_pairs<K: SymOperator>(
    k: &K,
    m_diag: &[f64],
    basis: &[Vec<f64>],
    eig: &nalgebra::SymmetricEigen<f64, nalgebra::Dyn>,
    idx: &[usize],
    sigma: f64,
) -> Pairs {
    let n = k.dim();
    let mut kv = vec![0.0; n];
    let mut values = Vec::with_capacity(idx.len());
    let mut vectors = Vec::with_capacity(idx.len());
    let mut residuals = Vec::with_capacity(idx.len());
    let mut worst: f64 = 0.0;
    for &c in idx {
        let lam = eig.eigenvalues[c];
        let mut phi = vec![0.0; n];
        for (r, v) in basis.iter().enumerate() {
            let y = eig.eigenvectors[(r, c)];
            phi.iter_mut().zip(v).for_each(|(a, b)| *a += y * b);
        }
        let nm = mdot(&phi, &phi, m_diag).sqrt();
        phi.iter_mut().for_each(|a| *a /= nm);
        k.mul(&phi, &mut kv);
        let res = residual(&kv, &phi, lam, m_diag, sigma);
        worst = worst.max(res);
        values.push(lam);
        vectors.push(phi);
        residuals.push(res);
    }
    (values, vectors, residuals, worst)
}

/// The residual measure of [`EigenResult::residuals`] for an M-normalised φ with Kφ = `kv`.
fn residual(kv: &[f64], phi: &[f64], lam: f64, m_diag: &[f64], sigma: f64) -> f64 {
    let mut rr = 0.0;
    let mut kk = 0.0;
    let mut mm = 0.0;
    for i in 0..phi.len() {
        let mphi = m_diag[i] * phi[i];
        rr += (kv[i] - lam * mphi).powi(2);
        kk += kv[i] * kv[i];
        mm += mphi * mphi;
    }
    rr.sqrt() / kk.sqrt().max(sigma.abs() * mm.sqrt())
}

/// One step of block inverse iteration on converged-looking Ritz vectors: Y = op(Φ),
/// M-orthonormalised, then Rayleigh–Ritz on span(Y). Each unwanted component of mode j in
/// φ_i shrinks by (λ_i − σ)/(λ_j − σ), which removes the high-frequency remainder that
/// dominates the residual once the Ritz values have settled, for one solve per mode instead
/// of further Krylov blocks. Returns (values, vectors, residuals, worst) or `None` when Y
/// loses rank.
fn refine<K: SymOperator>(
    k: &K,
    m_diag: &[f64],
    op: &dyn Fn(&[f64]) -> Vec<f64>,
    phis: &[Vec<f64>],
    sigma: f64,
) -> Option<Pairs> {
    let q = phis.len();
    let n = m_diag.len();
    let mut ys: Vec<Vec<f64>> = Vec::with_capacity(q);
    for phi in phis {
        let mut w = op(phi);
        let norm0 = mdot(&w, &w, m_diag).sqrt();
        if !(norm0 > 0.0 && norm0.is_finite()) {
            return None;
        }
        for _ in 0..2 {
            let mw: Vec<f64> = w.iter().zip(m_diag).map(|(a, b)| a * b).collect();
            for v in &ys {
                let c = dot(v, &mw);
                w.iter_mut().zip(v).for_each(|(a, b)| *a -= c * b);
            }
        }
        let norm = mdot(&w, &w, m_diag).sqrt();
        if norm <= 1e-10 * norm0 {
            return None;
        }
        w.iter_mut().for_each(|a| *a /= norm);
        ys.push(w);
    }
    let kys: Vec<Vec<f64>> = ys
        .iter()
        .map(|y| {
            let mut kv = vec![0.0; n];
            k.mul(y, &mut kv);
            kv
        })
        .collect();
    let mut a = DMatrix::<f64>::zeros(q, q);
    for j in 0..q {
        for i in 0..=j {
            let v = dot(&ys[i], &kys[j]);
            a[(i, j)] = v;
            a[(j, i)] = v;
        }
    }
    let eig = a.symmetric_eigen();
    let mut idx: Vec<usize> = (0..q).collect();
    idx.sort_by(|&x, &y| eig.eigenvalues[x].total_cmp(&eig.eigenvalues[y]));
    let mut values = Vec::with_capacity(q);
    let mut vectors = Vec::with_capacity(q);
    let mut residuals = Vec::with_capacity(q);
    let mut worst: f64 = 0.0;
    for &c in &idx {
        let lam = eig.eigenvalues[c];
        let mut phi = vec![0.0; n];
        let mut kv = vec![0.0; n];
        for r in 0..q {
            let z = eig.eigenvectors[(r, c)];
            phi.iter_mut().zip(&ys[r]).for_each(|(a, b)| *a += z * b);
            kv.iter_mut().zip(&kys[r]).for_each(|(a, b)| *a += z * b);
        }
        let nm = mdot(&phi, &phi, m_diag).sqrt();
        phi.iter_mut().for_each(|a| *a /= nm);
        kv.iter_mut().for_each(|a| *a /= nm);
        let res = residual(&kv, &phi, lam, m_diag, sigma);
        worst = worst.max(res);
        values.push(lam);
        vectors.push(phi);
        residuals.push(res);
    }
    Some((values, vectors, residuals, worst))
}

/// Adds M-orthonormalised copies of `block` to `basis` (two Gram–Schmidt passes; vectors
/// already in the span are dropped) and the new columns of VᵀKV to `kr`. Returns the count.
fn extend<K: SymOperator>(
    k: &K,
    m_diag: &[f64],
    max_basis: usize,
    block: Vec<Vec<f64>>,
    basis: &mut Vec<Vec<f64>>,
    kr: &mut Vec<Vec<f64>>,
) -> usize {
    let mut kv = vec![0.0; k.dim()];
    let mut added = 0;
    for mut w in block {
        if basis.len() >= max_basis {
            break;
        }
        let norm0 = mdot(&w, &w, m_diag).sqrt();
        if !(norm0 > 0.0 && norm0.is_finite()) {
            continue;
        }
        for _ in 0..2 {
            let mw: Vec<f64> = w.iter().zip(m_diag).map(|(a, b)| a * b).collect();
            for v in basis.iter() {
                let c = dot(v, &mw);
                w.iter_mut().zip(v).for_each(|(a, b)| *a -= c * b);
            }
        }
        let norm = mdot(&w, &w, m_diag).sqrt();
        if norm <= 1e-10 * norm0 {
            continue; // numerically in the span already: deflate
        }
        w.iter_mut().for_each(|a| *a /= norm);
        k.mul(&w, &mut kv);
        let mut col: Vec<f64> = basis.iter().map(|v| dot(v, &kv)).collect();
        col.push(dot(&w, &kv));
        kr.push(col);
        basis.push(w);
        added += 1;
    }
    added
}
