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

const N: usize = 2 * STAGES;
const COLS: usize = 2 + MAX_FORCES;

/// Computes the step map of `ode` from `t0` over `h` with the tableau `tab`.
pub fn step_map<O: LinearOde + ?Sized>(ode: &O, tab: &Tableau, t0: f64, h: f64) -> StepMap {
    let nf = ode.n_forces();
    let c = ode.damping();
    let mut ks = [0.0; STAGES];
    let mut fs = [[0.0; MAX_FORCES]; STAGES];
    for i in 0..STAGES {
        ks[i] = ode.eval(t0 + tab.c[i] * h, &mut fs[i][..nf]);
    }
    // S = I − h (a_ij A_i), stage unknowns K = (K_1, ..., K_4), each K_i = (q̇-stage, q̈-stage).
    let mut s = SMatrix::<f64, N, N>::identity();
    let mut rhs = SMatrix::<f64, N, COLS>::zeros();
    for i in 0..STAGES {
        for j in 0..STAGES {
            let w = h * tab.a[i][j];
            // A_i = [[0, 1], [−k_i, −c]]
            s[(2 * i, 2 * j + 1)] -= w;
            s[(2 * i + 1, 2 * j)] += w * ks[i];
            s[(2 * i + 1, 2 * j + 1)] += w * c;
        }
        // Homogeneous columns: A_i x for x = e1, e2.
        rhs[(2 * i, 1)] = 1.0;
        rhs[(2 * i + 1, 0)] = -ks[i];
        rhs[(2 * i + 1, 1)] = -c;
        for j in 0..nf {
            rhs[(2 * i + 1, 2 + j)] = fs[i][j];
        }
    }
    let k = s
        .lu()
        .solve(&rhs)
        .unwrap_or_else(|| SMatrix::<f64, N, COLS>::from_element(f64::NAN));
    let mut out = StepMap {
        r: Matrix2::identity(),
        p: [Vector2::zeros(); MAX_FORCES],
    };
    for i in 0..STAGES {
        let w = h * tab.b[i];
        out.r[(0, 0)] += w * k[(2 * i, 0)];
        out.r[(0, 1)] += w * k[(2 * i, 1)];
        out.r[(1, 0)] += w * k[(2 * i + 1, 0)];
        out.r[(1, 1)] += w * k[(2 * i + 1, 1)];
        for j in 0..nf {
            out.p[j][0] += w * k[(2 * i, 2 + j)];
            out.p[j][1] += w * k[(2 * i + 1, 2 + j)];
        }
    }
    out
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
