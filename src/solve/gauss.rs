//! One step of 4-stage Gauss–Legendre collocation (order 8) for the linear system
//! x′ = A(t) x + F_j(t), x = (q, q̇), A = [[0, 1], [−k(t), −c]], F_j = (0, f_j(t)).
//!
//! Because the system is linear, the step is an affine map x ↦ R x + r_j; this module returns
//! R (2×2) and every r_j at once by solving the 8×8 stage system with several right-hand sides.
//! The Butcher tableau is built from the Gauss nodes by the collocation conditions
//! Σ_j a_ij c_j^(m−1) = c_i^m / m, Σ_j b_j c_j^(m−1) = 1/m (m = 1..4).

use super::{LinearOde, MAX_FORCES};
use nalgebra::{Matrix2, SMatrix, SVector, Vector2};

/// Number of stages.
pub const STAGES: usize = 4;
/// Order of accuracy (2 × stages).
pub const ORDER: u32 = 8;

/// The Gauss–Legendre tableau (nodes c, weights b, matrix a) on [0, 1].
#[derive(Debug, Clone, Copy)]
pub struct Tableau {
    /// Nodes.
    pub c: [f64; STAGES],
    /// Weights.
    pub b: [f64; STAGES],
    /// Runge–Kutta matrix.
    pub a: [[f64; STAGES]; STAGES],
}

impl Tableau {
    /// Builds the 4-stage tableau from the closed-form Legendre roots.
    pub fn new() -> Self {
        let r = (6.0_f64 / 5.0).sqrt();
        let x1 = (3.0 / 7.0 - 2.0 / 7.0 * r).sqrt();
        let x2 = (3.0 / 7.0 + 2.0 / 7.0 * r).sqrt();
        let c = [
            0.5 * (1.0 - x2),
            0.5 * (1.0 - x1),
            0.5 * (1.0 + x1),
            0.5 * (1.0 + x2),
        ];
        // Vandermonde V[m][j] = c_j^m.
        let v = SMatrix::<f64, STAGES, STAGES>::from_fn(|m, j| c[j].powi(m as i32));
        let lu = v.lu();
        let rhs_b = SVector::<f64, STAGES>::from_fn(|m, _| 1.0 / (m as f64 + 1.0));
        let bv = lu.solve(&rhs_b).expect("Gauss nodes are distinct");
        let mut a = [[0.0; STAGES]; STAGES];
        for (i, row) in a.iter_mut().enumerate() {
            let rhs =
                SVector::<f64, STAGES>::from_fn(|m, _| c[i].powi(m as i32 + 1) / (m as f64 + 1.0));
            let ai = lu.solve(&rhs).expect("Gauss nodes are distinct");
            for j in 0..STAGES {
                row[j] = ai[j];
            }
        }
        Tableau {
            c,
            b: [bv[0], bv[1], bv[2], bv[3]],
            a,
        }
    }
}

impl Default for Tableau {
    fn default() -> Self {
        Self::new()
    }
}

/// The affine step map x ↦ R x + r_j over one step.
#[derive(Debug, Clone, Copy)]
pub struct StepMap {
    /// Homogeneous transition over the step.
    pub r: Matrix2<f64>,
    /// Particular increments, one per forcing (unused entries zero).
    pub p: [Vector2<f64>; MAX_FORCES],
}

/// Columns of the reduced stage system: the two homogeneous starts and the forcings.
const COLS: usize = 2 + MAX_FORCES;

/// Computes the step map of `ode` from `t0` over `h` with the tableau `tab`.
///
/// The 8×8 stage system is reduced to 4×4 before it is solved: with stage values
/// Y_i = (Q_i, V_i) = x0 + h Σ_j a_ij K_j and K_j = A_j Y_j + F_j, the q-rows give
/// Q = q0·1 + h a V, and substituting them into the v-rows leaves
///
/// ```text
/// (I + h c a + h² a K a) V = v0·1 − q0·h a k + h a f_j,     K = diag(k_1..k_4),
/// ```
///
/// one small system with six right-hand sides (the starts e1, e2 and the forcings), solved by
/// Gaussian elimination with partial pivoting. Same method, same order; only the linear algebra
/// is cheaper.
pub fn step_map<O: LinearOde + ?Sized>(ode: &O, tab: &Tableau, t0: f64, h: f64) -> StepMap {
    let nf = ode.n_forces();
    let mut ks = [0.0; STAGES];
    let mut fs = [[0.0; MAX_FORCES]; STAGES];
    for i in 0..STAGES {
        ks[i] = ode.eval(t0 + tab.c[i] * h, &mut fs[i][..nf]);
    }
    step_map_from(tab, ode.damping(), h, &ks, &fs, nf)
}

/// [`step_map`] from the stiffness `ks` and forcings `fs` already evaluated at the four stage
/// times t0 + c_i h (so a caller can share one evaluation of the kinematics between modes).
pub fn step_map_from(
    tab: &Tableau,
    c: f64,
    h: f64,
    ks: &[f64; STAGES],
    fs: &[[f64; MAX_FORCES]; STAGES],
    nf: usize,
) -> StepMap {
    // Every loop in the three stages runs over all COLS columns (the unused forcings are zero
    // columns, whose results are dropped): fixed trip counts the compiler unrolls and vectorises
    // across columns. Each value is still formed by the same operations in the same order.
    let nf = nf.min(MAX_FORCES);
    let mut f = [[0.0; MAX_FORCES]; STAGES];
    for (fi, si) in f.iter_mut().zip(fs) {
        fi[..nf].copy_from_slice(&si[..nf]);
    }
    let (mut m, mut rhs) = stage_system(&tab.a, c, h, ks, &f);
    if !solve_stages(&mut m, &mut rhs) {
        return StepMap {
            r: Matrix2::from_element(f64::NAN),
            p: [Vector2::from_element(f64::NAN); MAX_FORCES],
        };
    }
    let (q1, v1) = end_state(tab, c, h, ks, &f, &rhs);
    let col = |k: usize| Vector2::new(q1[k], v1[k]);
    let (c0, c1) = (col(0), col(1));
    let mut out = StepMap {
        r: Matrix2::new(c0[0], c1[0], c0[1], c1[1]),
        p: [Vector2::zeros(); MAX_FORCES],
    };
    for j in 0..nf {
        out.p[j] = col(2 + j);
    }
    out
}

/// The reduced stage system of [`step_map_from`]: M = I + h c a + h² a K a and its COLS
/// right-hand sides (the starts (1, 0), (0, 1), then the forcings).
#[inline(always)]
fn stage_system(
    a: &[[f64; STAGES]; STAGES],
    c: f64,
    h: f64,
    ks: &[f64; STAGES],
    f: &[[f64; MAX_FORCES]; STAGES],
) -> ([[f64; STAGES]; STAGES], [[f64; COLS]; STAGES]) {
    // a_il k_l, then M and the right-hand sides.
    let mut ak = [[0.0; STAGES]; STAGES];
    for i in 0..STAGES {
        for l in 0..STAGES {
            ak[i][l] = a[i][l] * ks[l];
        }
    }
    let (hc, hh) = (h * c, h * h);
    let mut m = [[0.0; STAGES]; STAGES];
    for i in 0..STAGES {
        for j in 0..STAGES {
            let mut aka = 0.0;
            for l in 0..STAGES {
                aka += ak[i][l] * a[l][j];
            }
            m[i][j] = hc * a[i][j] + hh * aka;
        }
        m[i][i] += 1.0;
    }
    let mut rhs = [[0.0; COLS]; STAGES];
    for i in 0..STAGES {
        let mut aks = 0.0;
        for l in 0..STAGES {
            aks += ak[i][l];
        }
        rhs[i][0] = -h * aks; // start (q0, v0) = (1, 0)
        rhs[i][1] = 1.0; // start (0, 1)
        let mut af = [0.0; MAX_FORCES];
        for l in 0..STAGES {
            for j in 0..MAX_FORCES {
                af[j] += a[i][l] * f[l][j];
            }
        }
        for j in 0..MAX_FORCES {
            rhs[i][2 + j] = h * af[j];
        }
    }
    (m, rhs)
}

/// Solves `m V = rhs` in place by Gaussian elimination with partial pivoting; `rhs` then holds
/// V, one column per start. False (and `rhs` unusable) on a zero or non-finite pivot.
#[inline(always)]
fn solve_stages(m: &mut [[f64; STAGES]; STAGES], rhs: &mut [[f64; COLS]; STAGES]) -> bool {
    for col in 0..STAGES {
        let mut piv = col;
        for r in col + 1..STAGES {
            if m[r][col].abs() > m[piv][col].abs() {
                piv = r;
            }
        }
        if piv != col {
            m.swap(piv, col);
            rhs.swap(piv, col);
        }
        let d = m[col][col];
        if d == 0.0 || !d.is_finite() {
            return false;
        }
        let inv = 1.0 / d;
        let (pivot_m, pivot_rhs) = (m[col], rhs[col]);
        for r in col + 1..STAGES {
            let fac = m[r][col] * inv;
            if fac != 0.0 {
                for k in col + 1..STAGES {
                    m[r][k] -= fac * pivot_m[k];
                }
                for k in 0..COLS {
                    rhs[r][k] -= fac * pivot_rhs[k];
                }
            }
        }
    }
    for col in (0..STAGES).rev() {
        let inv = 1.0 / m[col][col];
        let mut s = rhs[col];
        for j in col + 1..STAGES {
            for k in 0..COLS {
                s[k] -= m[col][j] * rhs[j][k];
            }
        }
        for k in 0..COLS {
            rhs[col][k] = s[k] * inv;
        }
    }
    true
}

/// The step's end state for each column from the stage velocities V (`v`):
/// x1 = x0 + h Σ b_i (V_i, −k_i Q_i − c V_i + f_i) with Q = q0 + h a V; the starts are (1, 0),
/// (0, 1) and zero for the forcings. Returns (q1, v1) per column.
#[inline(always)]
fn end_state(
    tab: &Tableau,
    c: f64,
    h: f64,
    ks: &[f64; STAGES],
    f: &[[f64; MAX_FORCES]; STAGES],
    v: &[[f64; COLS]; STAGES],
) -> ([f64; COLS], [f64; COLS]) {
    let a = &tab.a;
    let mut q0 = [0.0; COLS];
    let mut v0 = [0.0; COLS];
    q0[0] = 1.0;
    v0[1] = 1.0;
    let (mut dq, mut dv) = ([0.0; COLS], [0.0; COLS]);
    for i in 0..STAGES {
        let mut av = [0.0; COLS];
        for j in 0..STAGES {
            for k in 0..COLS {
                av[k] += a[i][j] * v[j][k];
            }
        }
        let mut fi = [0.0; COLS];
        fi[2..].copy_from_slice(&f[i]);
        for k in 0..COLS {
            let qi = q0[k] + h * av[k];
            dq[k] += tab.b[i] * v[i][k];
            dv[k] += tab.b[i] * (fi[k] - ks[i] * qi - c * v[i][k]);
        }
    }
    let mut q1 = [0.0; COLS];
    let mut v1 = [0.0; COLS];
    for k in 0..COLS {
        q1[k] = q0[k] + h * dq[k];
        v1[k] = v0[k] + h * dv[k];
    }
    (q1, v1)
}

/// Integrates x′ = A x + F_j from `t0` over `n` equal steps of size `h`, starting every
/// forcing column from `x0`; returns the final states, one per forcing. Used by the
/// convergence tests and as a direct (non-periodic) solver.
pub fn integrate<O: LinearOde + ?Sized>(
    ode: &O,
    t0: f64,
    h: f64,
    n: usize,
    x0: Vector2<f64>,
) -> Vec<Vector2<f64>> {
    let tab = Tableau::new();
    let nf = ode.n_forces();
    let mut xs = vec![x0; nf];
    for i in 0..n {
        let m = step_map(ode, &tab, t0 + i as f64 * h, h);
        for (j, x) in xs.iter_mut().enumerate() {
            *x = m.r * *x + m.p[j];
        }
    }
    xs
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tableau_meets_the_order_eight_conditions() {
        let t = Tableau::new();
        // Gauss quadrature with 4 nodes integrates polynomials up to degree 7 exactly.
        for m in 0..8 {
            let q: f64 = (0..STAGES).map(|j| t.b[j] * t.c[j].powi(m)).sum();
            assert!(
                (q - 1.0 / (m as f64 + 1.0)).abs() < 1e-14,
                "degree {m}: {q}"
            );
        }
        // Nodes symmetric about 1/2, weights symmetric, collocation rows sum to c_i.
        for i in 0..STAGES {
            assert!((t.c[i] + t.c[STAGES - 1 - i] - 1.0).abs() < 1e-14);
            assert!((t.b[i] - t.b[STAGES - 1 - i]).abs() < 1e-14);
            assert!((t.a[i].iter().sum::<f64>() - t.c[i]).abs() < 1e-14);
        }
    }
}
