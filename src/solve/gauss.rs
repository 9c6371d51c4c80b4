//! One step of 4-stage Gauss–Legendre collocation (order 8) for the linear system
//! x′ = A(t) x + F_j(t), x = (q, q̇), A = [[0, 1], [−k(t), −c]], F_j = (0, f_j(t)).
//!
//! Because the system is linear, the step is an affine map x ↦ R x + r_j; this module returns
//! R (2×2) and every r_j at once from one 4×4 solve with two right-hand sides (the 8×8 stage
//! system reduced by its q-rows and solved transposed for the two functionals the end state
//! reads; [`step_map_from`]).
//! The Butcher tableau is built from the Gauss nodes by the collocation conditions
//! Σ_j a_ij c_j^(m−1) = c_i^m / m, Σ_j b_j c_j^(m−1) = 1/m (m = 1..4).

use super::{LinearOde, MAX_FORCES};
use nalgebra::{Matrix2, SMatrix, SVector, Vector2};

pub use super::STAGES;
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
    /// Products of the coefficients the step reads ([`step_map_from`]).
    pre: Products,
}

/// Coefficient products fixed by the tableau, formed once: the step's transposed stage
/// matrix is then a sum of scaled 16-entry arrays.
#[derive(Debug, Clone, Copy)]
struct Products {
    /// aᵀ, flat: `at[4 j + i]` = a_ij.
    at: [f64; STAGES * STAGES],
    /// (a e_l)(e_lᵀ a) transposed, flat: `pt[l][4 j + i]` = a_il a_lj.
    pt: [[f64; STAGES * STAGES]; STAGES],
    /// `ba[i][j]` = b_i a_ij.
    ba: [[f64; STAGES]; STAGES],
}

impl Products {
    fn of(a: &[[f64; STAGES]; STAGES], b: &[f64; STAGES]) -> Self {
        Products {
            at: std::array::from_fn(|x| a[x % STAGES][x / STAGES]),
            pt: std::array::from_fn(|l| {
                std::array::from_fn(|x| a[x % STAGES][l] * a[l][x / STAGES])
            }),
            ba: std::array::from_fn(|i| std::array::from_fn(|j| b[i] * a[i][j])),
        }
    }
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
        let b = [bv[0], bv[1], bv[2], bv[3]];
        Tableau {
            c,
            b,
            a,
            pre: Products::of(&a, &b),
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

/// Computes the step map of `ode` from `t0` over `h` with the tableau `tab`.
///
/// See [`step_map_from`] for how the stage system is solved.
pub fn step_map<O: LinearOde + ?Sized>(ode: &O, tab: &Tableau, t0: f64, h: f64) -> StepMap {
    let mut ks = [0.0; STAGES];
    let mut fs = [[0.0; MAX_FORCES]; STAGES];
    ode.eval_stages(t0, h, &tab.c, &mut ks, &mut fs);
    step_map_from(tab, ode.damping(), h, &ks, &fs, ode.n_forces())
}

/// [`step_map`] from the stiffness `ks` and forcings `fs` already evaluated at the four stage
/// times t0 + c_i h (so a caller can share one evaluation of the kinematics between modes).
///
/// With stage values Y_i = (Q_i, V_i) = x0 + h Σ_j a_ij K_j and K_j = A_j Y_j + F_j, the q-rows
/// give Q = q0·1 + h a V, and the v-rows then leave one 4×4 system for the stage velocities,
///
/// ```text
/// M V = v0·1 − h q0 (a k) + h a f_j,     M = I + h c a + h² a K a,   K = diag(k_1..k_4),
/// ```
///
/// and the end state is linear in V:
///
/// ```text
/// q1 = q0 + h bᵀV,    v1 = v0 + h bᵀf − h q0 bᵀk − h uᵀV,    u_j = c b_j + h Σ_i b_i k_i a_ij.
/// ```
///
/// Only the two functionals bᵀV and uᵀV of each column are needed, so instead of solving
/// M V = rhs for every column (two starts and each forcing) the transposed system
/// Mᵀ [s r] = [b u] is solved once, with two right-hand sides: bᵀV = sᵀ rhs and uᵀV = rᵀ rhs.
/// With σ = aᵀs and ρ = aᵀr,
///
/// ```text
/// R = [[1 − h² σ·k,  h Σ s], [−h b·k + h² ρ·k,  1 − h Σ r]],   r_j = (h² σ·f_j, h b·f_j − h² ρ·f_j).
/// ```
///
/// Same method and order as solving the stage system column by column; the work per step no
/// longer grows with the columns but by three dot products of four terms per forcing.
pub fn step_map_from(
    tab: &Tableau,
    c: f64,
    h: f64,
    ks: &[f64; STAGES],
    fs: &[[f64; MAX_FORCES]; STAGES],
    nf: usize,
) -> StepMap {
    let nf = nf.min(MAX_FORCES);
    let (a, b, pre) = (&tab.a, &tab.b, &tab.pre);
    let (hc, hh) = (h * c, h * h);
    // Mᵀ = I + h c aᵀ + h² Σ_l k_l (a e_l e_lᵀ a)ᵀ, flat (row j of Mᵀ at 4 j), and
    // g_j = Σ_i b_i k_i a_ij.
    let mut mt = [0.0; STAGES * STAGES];
    for x in 0..STAGES * STAGES {
        mt[x] = hc * pre.at[x];
    }
    let mut g = [0.0; STAGES];
    for l in 0..STAGES {
        let kl = hh * ks[l];
        for x in 0..STAGES * STAGES {
            mt[x] += kl * pre.pt[l][x];
        }
        for j in 0..STAGES {
            g[j] += ks[l] * pre.ba[l][j];
        }
    }
    for j in 0..STAGES {
        mt[STAGES * j + j] += 1.0;
    }
    // Right-hand sides b and u, one row per equation.
    let rhs: [[f64; 2]; STAGES] = std::array::from_fn(|j| [b[j], c * b[j] + h * g[j]]);
    let Some(sol) = solve4(&mt, &rhs) else {
        return StepMap {
            r: Matrix2::from_element(f64::NAN),
            p: [Vector2::from_element(f64::NAN); MAX_FORCES],
        };
    };
    // σ = aᵀs, ρ = aᵀr, Σs, Σr.
    let (mut sig, mut rho) = ([0.0; STAGES], [0.0; STAGES]);
    let (mut sum_s, mut sum_r) = (0.0, 0.0);
    for i in 0..STAGES {
        let [s, r] = sol[i];
        sum_s += s;
        sum_r += r;
        for l in 0..STAGES {
            sig[l] += a[i][l] * s;
            rho[l] += a[i][l] * r;
        }
    }
    let r = Matrix2::new(
        1.0 - hh * dot4(&sig, ks),
        h * sum_s,
        hh * dot4(&rho, ks) - h * dot4(b, ks),
        1.0 - h * sum_r,
    );
    let mut p = [Vector2::zeros(); MAX_FORCES];
    for (j, pj) in p.iter_mut().enumerate().take(nf) {
        let f = [fs[0][j], fs[1][j], fs[2][j], fs[3][j]];
        *pj = Vector2::new(hh * dot4(&sig, &f), h * dot4(b, &f) - hh * dot4(&rho, &f));
    }
    StepMap { r, p }
}

/// Solves the 4×4 system m x = rhs (`m` flat by rows, two right-hand sides). The step's matrix
/// is the identity plus terms of order h·c and h²·k, so elimination in the given order meets
/// pivots near 1; it is taken when every pivot is at least 1/2 in magnitude (multipliers then
/// stay small and no row exchange is needed), else the system is solved again with partial
/// pivoting. None on a zero or non-finite pivot.
#[inline(always)]
fn solve4(m: &[f64; STAGES * STAGES], rhs: &[[f64; 2]; STAGES]) -> Option<[[f64; 2]; STAGES]> {
    let mut u = [[0.0; STAGES]; STAGES];
    for (r, row) in u.iter_mut().enumerate() {
        row.copy_from_slice(&m[STAGES * r..STAGES * r + STAGES]);
    }
    let mut x = *rhs;
    let mut ok = true;
    let mut inv = [0.0; STAGES];
    for col in 0..STAGES {
        let d = u[col][col];
        ok &= d.abs() >= 0.5;
        inv[col] = 1.0 / d;
        eliminate_below(&mut u, &mut x, col, inv[col]);
    }
    // NaN fails the comparison above too, so a finite result means finite pivots.
    if !ok {
        let mut u = [[0.0; STAGES]; STAGES];
        for (r, row) in u.iter_mut().enumerate() {
            row.copy_from_slice(&m[STAGES * r..STAGES * r + STAGES]);
        }
        let mut x = *rhs;
        return solve_pivoting(&mut u, &mut x).then_some(x);
    }
    back_substitute(&u, &inv, &mut x);
    Some(x)
}

/// Removes column `col` below its pivot row from `u` and the right-hand sides `x` (`inv` the
/// pivot's reciprocal).
#[inline(always)]
fn eliminate_below(
    u: &mut [[f64; STAGES]; STAGES],
    x: &mut [[f64; 2]; STAGES],
    col: usize,
    inv: f64,
) {
    let (pivot_u, pivot_x) = (u[col], x[col]);
    for r in col + 1..STAGES {
        let fac = u[r][col] * inv;
        for k in col + 1..STAGES {
            u[r][k] -= fac * pivot_u[k];
        }
        for k in 0..2 {
            x[r][k] -= fac * pivot_x[k];
        }
    }
}

/// Back substitution of an upper-triangular `u` into `x`, with `inv` the reciprocals of its
/// (nonzero) diagonal.
#[inline(always)]
fn back_substitute(u: &[[f64; STAGES]; STAGES], inv: &[f64; STAGES], x: &mut [[f64; 2]; STAGES]) {
    for col in (0..STAGES).rev() {
        let inv = inv[col];
        let mut s = x[col];
        for j in col + 1..STAGES {
            for k in 0..2 {
                s[k] -= u[col][j] * x[j][k];
            }
        }
        for k in 0..2 {
            x[col][k] = s[k] * inv;
        }
    }
}

/// x·y over the four stages, summed pairwise.
#[inline(always)]
fn dot4(x: &[f64; STAGES], y: &[f64; STAGES]) -> f64 {
    (x[0] * y[0] + x[1] * y[1]) + (x[2] * y[2] + x[3] * y[3])
}

/// Solves `m x = rhs` (two right-hand sides) in place by Gaussian elimination with partial
/// pivoting; `rhs` then holds x. False (and `rhs` unusable) on a zero or non-finite pivot.
#[cold]
fn solve_pivoting(m: &mut [[f64; STAGES]; STAGES], rhs: &mut [[f64; 2]; STAGES]) -> bool {
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
        eliminate_below(m, rhs, col, 1.0 / d);
    }
    let inv = std::array::from_fn(|c| 1.0 / m[c][c]);
    back_substitute(m, &inv, rhs);
    true
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

    /// The transposed 4×4 solve against the plain one: the full 8×8 stage system (unknowns
    /// K_i = (Q̇_i, V̇_i)) solved column by column with nalgebra's LU, then x1 = x0 + h Σ b_i K_i.
    /// Stiffer and softer stages, damping from none to large, forcings of mixed sign and size,
    /// and steps far longer than any rule takes (where the pivoting solve is used).
    #[test]
    fn the_transposed_solve_equals_the_full_stage_system() {
        let tab = Tableau::new();
        let cases = [
            (1e-4, 0.0, [3.0e5, 2.9e5, 3.1e5, 3.05e5]),
            (2e-3, 12.0, [4.0e4, -1.0e4, 2.0e4, 5.0e3]),
            (0.01, 50.0, [600.0, 610.0, 590.0, 620.0]),
            (0.05, 0.3, [-40.0, 10.0, 25.0, -5.0]),
            // Far from the identity (h c = 10, h² k up to 25): pivots below 1/2, so the
            // pivoting solve runs.
            (0.5, 20.0, [100.0, -30.0, 60.0, 10.0]),
            (0.3, 0.0, [-400.0, 500.0, -200.0, 300.0]),
        ];
        for (h, c, ks) in cases {
            let fs = [
                [1.0, -2.0, 0.5, 1e3],
                [0.7, 2.5, -1.5, -1e3],
                [-0.2, 1.0, 3.0, 2e3],
                [0.4, -0.1, 0.0, 0.5],
            ];
            let got = step_map_from(&tab, c, h, &ks, &fs, MAX_FORCES);
            // Unknowns k = (K_1q..K_4q, K_1v..K_4v): K_iq = q0 + h Σ a_ij K_jv (= V_i) and
            // K_iv = f_i − k_i (q0 + h Σ a_ij K_jq) − c (v0 + h Σ a_ij K_jv).
            let mut m = SMatrix::<f64, 8, 8>::identity();
            for i in 0..STAGES {
                for j in 0..STAGES {
                    m[(i, 4 + j)] -= h * tab.a[i][j];
                    m[(4 + i, j)] += h * ks[i] * tab.a[i][j];
                    m[(4 + i, 4 + j)] += h * c * tab.a[i][j];
                }
            }
            let lu = m.lu();
            let end = |q0: f64, v0: f64, f: &dyn Fn(usize) -> f64| {
                let rhs = SVector::<f64, 8>::from_fn(|r, _| {
                    if r < 4 {
                        v0
                    } else {
                        f(r - 4) - ks[r - 4] * q0 - c * v0
                    }
                });
                let k = lu.solve(&rhs).unwrap();
                let (mut q1, mut v1) = (q0, v0);
                for i in 0..STAGES {
                    q1 += h * tab.b[i] * k[i];
                    v1 += h * tab.b[i] * k[4 + i];
                }
                Vector2::new(q1, v1)
            };
            let close = |a: Vector2<f64>, b: Vector2<f64>, what: &str| {
                let scale = b.norm().max(1e-300);
                assert!(
                    (a - b).norm() <= 1e-13 * scale,
                    "h = {h}, c = {c}, {what}: {a:?} against {b:?}"
                );
            };
            close(got.r.column(0).into(), end(1.0, 0.0, &|_| 0.0), "R e1");
            close(got.r.column(1).into(), end(0.0, 1.0, &|_| 0.0), "R e2");
            for j in 0..MAX_FORCES {
                close(got.p[j], end(0.0, 0.0, &|i| fs[i][j]), &format!("r_{j}"));
            }
        }
    }

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
