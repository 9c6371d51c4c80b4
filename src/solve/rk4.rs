//! The classical fourth-order Runge–Kutta method for q̈ + c q̇ + k(t) q = f_j(t): an explicit,
//! independent second method used to cross-check the period propagator.

use super::{LinearOde, MAX_FORCES};

/// Integrates every forcing column from the same initial state (q0, v0) with fixed step
/// `h = dt / substeps` and records q and q̇ at `t = i dt`, i = 0..n_out.
/// Returns, per forcing column, the vectors (q, q̇).
pub fn solve<O: LinearOde + ?Sized>(
    ode: &O,
    q0: f64,
    v0: f64,
    dt: f64,
    n_out: usize,
    substeps: usize,
) -> Vec<(Vec<f64>, Vec<f64>)> {
    let nf = ode.n_forces();
    let c = ode.damping();
    let h = dt / substeps as f64;
    let mut out: Vec<(Vec<f64>, Vec<f64>)> = (0..nf)
        .map(|_| (Vec::with_capacity(n_out), Vec::with_capacity(n_out)))
        .collect();
    let mut q = [q0; MAX_FORCES];
    let mut v = [v0; MAX_FORCES];
    let mut f1 = [0.0; MAX_FORCES];
    let mut f2 = [0.0; MAX_FORCES];
    let mut f3 = [0.0; MAX_FORCES];
    for i in 0..n_out {
        for j in 0..nf {
            out[j].0.push(q[j]);
            out[j].1.push(v[j]);
        }
        if i + 1 == n_out {
            break;
        }
        for s in 0..substeps {
            let t = i as f64 * dt + s as f64 * h;
            let k1 = ode.eval(t, &mut f1[..nf]);
            let k2 = ode.eval(t + 0.5 * h, &mut f2[..nf]);
            let k3 = ode.eval(t + h, &mut f3[..nf]);
            for j in 0..nf {
                let acc = |qq: f64, vv: f64, k: f64, f: f64| f - c * vv - k * qq;
                let (a1q, a1v) = (v[j], acc(q[j], v[j], k1, f1[j]));
                let (q2, v2) = (q[j] + 0.5 * h * a1q, v[j] + 0.5 * h * a1v);
                let (a2q, a2v) = (v2, acc(q2, v2, k2, f2[j]));
                let (q3, v3) = (q[j] + 0.5 * h * a2q, v[j] + 0.5 * h * a2v);
                let (a3q, a3v) = (v3, acc(q3, v3, k2, f2[j]));
                let (q4, v4) = (q[j] + h * a3q, v[j] + h * a3v);
                let (a4q, a4v) = (v4, acc(q4, v4, k3, f3[j]));
                q[j] += h / 6.0 * (a1q + 2.0 * a2q + 2.0 * a3q + a4q);
                v[j] += h / 6.0 * (a1v + 2.0 * a2v + 2.0 * a3v + a4v);
            }
        }
    }
    out
}
