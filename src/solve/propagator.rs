//! Period-by-period propagation, exact to rounding apart from one period's integration.
//!
//! For x′ = A(t) x + F_j(t) with T-periodic A and F_j, let Φ(τ) be the state-transition matrix
//! from 0 to τ and p_j(τ) the zero-start particular solution, τ ∈ [0, T]. Then for t = nT + τ
//!
//! ```text
//! x_j(t) = Φ(τ) X_j,n + p_j(τ),    X_j,n+1 = M X_j,n + p_j(T),    M = Φ(T) (the monodromy),
//! ```
//!
//! so one period is integrated once (order-8 Gauss–Legendre, hitting every output phase
//! exactly) and the rest is 2×2 algebra. The one-period integration error is estimated by
//! repeating it with twice the step and reported; the recursion adds only rounding.

use super::gauss::{step_map, Tableau};
use super::{LinearOde, MAX_FORCES};
use crate::error::{Result, WingbeatError};
use nalgebra::{Complex, Matrix2, Vector2};

/// Fewest Gauss–Legendre steps per period, whatever the frequencies.
pub const MIN_STEPS_PER_PERIOD: usize = 32;
/// Largest ω·h used (ω from [`LinearOde::freq_scale`]).
pub const MAX_OMEGA_H: f64 = 0.25;

/// One period's transition data at a set of checkpoint phases.
#[derive(Debug, Clone)]
pub struct PeriodMap {
    /// Length of the span integrated (s); normally the period T.
    pub span: f64,
    /// Checkpoint phases τ (s), ascending, in [0, span).
    pub phases: Vec<f64>,
    /// Φ(τ) at each checkpoint.
    pub phi: Vec<Matrix2<f64>>,
    /// p_j(τ) at each checkpoint (zero initial state), one per forcing.
    pub part: Vec<[Vector2<f64>; MAX_FORCES]>,
    /// Φ(span): the monodromy matrix when span = T.
    pub monodromy: Matrix2<f64>,
    /// p_j(span).
    pub part_end: [Vector2<f64>; MAX_FORCES],
    /// Estimated relative error of one span's integration (difference to a run with twice the
    /// step, which bounds the error of the finer run from above).
    pub error_estimate: f64,
}

/// The step size bound used for `ode`.
pub fn max_step<O: LinearOde + ?Sized>(ode: &O, span: f64) -> f64 {
    let by_freq = MAX_OMEGA_H / ode.freq_scale().max(1e-300);
    by_freq.min(span / MIN_STEPS_PER_PERIOD as f64)
}

/// Integrates `ode` over [0, span], recording Φ and p_j at each of `phases` (ascending, in
/// [0, span)). Each interval between checkpoints is split into equal steps no longer than
/// [`max_step`].
pub fn period_map<O: LinearOde + ?Sized>(ode: &O, span: f64, phases: &[f64]) -> PeriodMap {
    let tab = Tableau::new();
    let nf = ode.n_forces();
    let hmax = max_step(ode, span);
    let mut phi = Matrix2::identity();
    let mut part = [Vector2::zeros(); MAX_FORCES];
    let mut out_phi = Vec::with_capacity(phases.len());
    let mut out_part = Vec::with_capacity(phases.len());
    let mut t = 0.0;
    let advance =
        |from: f64, to: f64, phi: &mut Matrix2<f64>, part: &mut [Vector2<f64>; MAX_FORCES]| {
            let len = to - from;
            if len <= 0.0 {
                return;
            }
            let n = (len / hmax).ceil().max(1.0) as usize;
            let h = len / n as f64;
            for s in 0..n {
                let m = step_map(ode, &tab, from + s as f64 * h, h);
                *phi = m.r * *phi;
                for j in 0..nf {
                    part[j] = m.r * part[j] + m.p[j];
                }
            }
        };
    for &tau in phases {
        advance(t, tau, &mut phi, &mut part);
        t = t.max(tau);
        out_phi.push(phi);
        out_part.push(part);
    }
    advance(t, span, &mut phi, &mut part);

    // Error estimate: the same span with uniform steps of twice the bound.
    let mut phi_c = Matrix2::identity();
    let mut part_c = [Vector2::zeros(); MAX_FORCES];
    let nc = (span / (2.0 * hmax)).ceil().max(1.0) as usize;
    let hc = span / nc as f64;
    for s in 0..nc {
        let m = step_map(ode, &tab, s as f64 * hc, hc);
        phi_c = m.r * phi_c;
        for j in 0..nf {
            part_c[j] = m.r * part_c[j] + m.p[j];
        }
    }
    // Compare in a scaled state norm: q and q̇/ω have the same units.
    let w = ode.freq_scale().max(1e-300);
    let scale = Matrix2::new(1.0, 0.0, 0.0, 1.0 / w);
    let unscale = Matrix2::new(1.0, 0.0, 0.0, w);
    let mref = (scale * phi * unscale).norm().max(1e-300);
    let mut err = (scale * (phi - phi_c) * unscale).norm() / mref;
    for j in 0..nf {
        let pref = (scale * part[j]).norm();
        if pref > 0.0 {
            err = err.max((scale * (part[j] - part_c[j])).norm() / pref);
        }
    }
    PeriodMap {
        span,
        phases: phases.to_vec(),
        phi: out_phi,
        part: out_part,
        monodromy: phi,
        part_end: part,
        error_estimate: err,
    }
}

/// Where each output sample falls: period number and checkpoint index.
#[derive(Debug, Clone)]
pub struct Schedule {
    /// Checkpoint phases (s), ascending.
    pub phases: Vec<f64>,
    /// For each sample: (period number n, checkpoint index).
    pub slots: Vec<(u64, u32)>,
}

/// Builds the schedule for samples t_i = i·dt, i = 0..n, with period `period`.
/// When `period` is an integer multiple P of `dt` (to 1e-12 relative), only P checkpoints are
/// needed; otherwise every sample gets its own phase.
pub fn schedule(dt: f64, n: usize, period: f64) -> Schedule {
    let p = period / dt;
    let pr = p.round();
    if pr >= 1.0 && (pr * dt - period).abs() <= 1e-12 * period {
        let pp = pr as usize;
        let count = pp.min(n.max(1));
        let phases = (0..count).map(|j| j as f64 * dt).collect();
        let slots = (0..n).map(|i| ((i / pp) as u64, (i % pp) as u32)).collect();
        return Schedule { phases, slots };
    }
    let mut tagged: Vec<(f64, u64, usize)> = (0..n)
        .map(|i| {
            let t = i as f64 * dt;
            let k = (t / period).floor();
            let mut tau = t - k * period;
            if tau < 0.0 {
                tau = 0.0;
            }
            if tau >= period {
                tau = period * (1.0 - f64::EPSILON);
            }
            (tau, k as u64, i)
        })
        .collect();
    tagged.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut phases = Vec::with_capacity(n);
    let mut slots = vec![(0u64, 0u32); n];
    for (tau, k, i) in tagged {
        if phases.last().is_none_or(|&last: &f64| tau > last) {
            phases.push(tau);
        }
        slots[i] = (k, (phases.len() - 1) as u32);
    }
    Schedule { phases, slots }
}

/// Responses at the output samples.
#[derive(Debug, Clone)]
pub struct Propagated {
    /// q_j(t_i) for each forcing column j (zero initial state).
    pub q: Vec<Vec<f64>>,
    /// q̇_j(t_i) for each forcing column.
    pub qdot: Vec<Vec<f64>>,
    /// Homogeneous basis: first row of Φ(t_i) — q from (q0, v0) = (1, 0) and (0, 1).
    pub h_q: [Vec<f64>; 2],
    /// Second row of Φ(t_i) — q̇ from the same starts.
    pub h_qdot: [Vec<f64>; 2],
    /// Monodromy over one period T.
    pub monodromy: Matrix2<f64>,
    /// Estimated relative error of the one-period integration.
    pub period_error: f64,
    /// Number of periods spanned.
    pub periods: u64,
}

/// Propagates `ode` to the samples t_i = i·dt, i = 0..n.
pub fn propagate<O: LinearOde + ?Sized>(ode: &O, dt: f64, n: usize) -> Result<Propagated> {
    let period = ode.period();
    let sched = schedule(dt, n, period);
    let map = period_map(ode, period, &sched.phases);
    let nf = ode.n_forces();
    let mut q: Vec<Vec<f64>> = (0..nf).map(|_| Vec::with_capacity(n)).collect();
    let mut qdot: Vec<Vec<f64>> = (0..nf).map(|_| Vec::with_capacity(n)).collect();
    let mut h_q = [Vec::with_capacity(n), Vec::with_capacity(n)];
    let mut h_qdot = [Vec::with_capacity(n), Vec::with_capacity(n)];
    // Plain arrays in the hot loop: Φ(τ) row-major and p_j(τ), per checkpoint.
    let phi: Vec<[f64; 4]> = map
        .phi
        .iter()
        .map(|m| [m[(0, 0)], m[(0, 1)], m[(1, 0)], m[(1, 1)]])
        .collect();
    let part: Vec<[[f64; 2]; MAX_FORCES]> = map
        .part
        .iter()
        .map(|p| std::array::from_fn(|j| [p[j][0], p[j][1]]))
        .collect();
    // States at the start of period `cur`, and M^cur.
    let mut cur: u64 = 0;
    let mut xs = [Vector2::zeros(); MAX_FORCES];
    let mut mn = Matrix2::identity();
    let mut x_arr = [[0.0; 2]; MAX_FORCES];
    let mut mn_arr = [1.0, 0.0, 0.0, 1.0];
    let mut periods = 0;
    for &(k, slot) in &sched.slots {
        if cur < k {
            while cur < k {
                for j in 0..nf {
                    xs[j] = map.monodromy * xs[j] + map.part_end[j];
                }
                mn = map.monodromy * mn;
                cur += 1;
            }
            for j in 0..nf {
                x_arr[j] = [xs[j][0], xs[j][1]];
            }
            mn_arr = [mn[(0, 0)], mn[(0, 1)], mn[(1, 0)], mn[(1, 1)]];
        }
        periods = periods.max(k + 1);
        let ph = &phi[slot as usize];
        let pt = &part[slot as usize];
        for j in 0..nf {
            let x = &x_arr[j];
            q[j].push(ph[0] * x[0] + ph[1] * x[1] + pt[j][0]);
            qdot[j].push(ph[2] * x[0] + ph[3] * x[1] + pt[j][1]);
        }
        let m = &mn_arr;
        h_q[0].push(ph[0] * m[0] + ph[1] * m[2]);
        h_q[1].push(ph[0] * m[1] + ph[1] * m[3]);
        h_qdot[0].push(ph[2] * m[0] + ph[3] * m[2]);
        h_qdot[1].push(ph[2] * m[1] + ph[3] * m[3]);
    }
    let finite = q
        .iter()
        .chain(qdot.iter())
        .chain(h_q.iter())
        .all(|v| v.iter().all(|x| x.is_finite()));
    if !finite {
        let ev = multipliers(&map.monodromy);
        let m = ev.iter().map(|z| z.norm()).fold(0.0, f64::max);
        return Err(WingbeatError::NonFinite {
            what: "modal response".into(),
            detail: format!(
                "the response overflowed: the equation is parametrically unstable (largest Floquet multiplier |λ| = {m:.6e} per period); shorten the duration or reduce the rotation rates"
            ),
        });
    }
    Ok(Propagated {
        q,
        qdot,
        h_q,
        h_qdot,
        monodromy: map.monodromy,
        period_error: map.error_estimate,
        periods,
    })
}

/// Eigenvalues of a real 2×2 matrix: for a monodromy matrix, the Floquet multipliers (also
/// `crate::floquet::multipliers`).
pub fn multipliers(m: &Matrix2<f64>) -> [Complex<f64>; 2] {
    let tr = m[(0, 0)] + m[(1, 1)];
    let det = m[(0, 0)] * m[(1, 1)] - m[(0, 1)] * m[(1, 0)];
    let disc = tr * tr - 4.0 * det;
    if disc >= 0.0 {
        let s = disc.sqrt();
        // Numerically stable pair: larger root first, the other from det / larger.
        let l1 = if tr >= 0.0 {
            0.5 * (tr + s)
        } else {
            0.5 * (tr - s)
        };
        let l2 = if l1 != 0.0 { det / l1 } else { 0.0 };
        [Complex::new(l1, 0.0), Complex::new(l2, 0.0)]
    } else {
        let s = (-disc).sqrt();
        [
            Complex::new(0.5 * tr, 0.5 * s),
            Complex::new(0.5 * tr, -0.5 * s),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn commensurate_grid_uses_one_period_of_checkpoints() {
        let s = schedule(1e-4, 1001, 0.04);
        assert_eq!(s.phases.len(), 400);
        assert_eq!(s.slots[0], (0, 0));
        assert_eq!(s.slots[399], (0, 399));
        assert_eq!(s.slots[400], (1, 0));
        assert_eq!(s.slots[1000], (2, 200));
    }

    #[test]
    fn incommensurate_grid_gets_a_phase_per_sample() {
        let s = schedule(1.0 / 7777.0, 1000, 0.04);
        assert!(s.phases.windows(2).all(|w| w[1] > w[0]));
        for (i, &(k, slot)) in s.slots.iter().enumerate() {
            let t = i as f64 / 7777.0;
            assert!((k as f64 * 0.04 + s.phases[slot as usize] - t).abs() < 1e-15);
        }
    }
}
