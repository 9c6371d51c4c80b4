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
use super::stats::SeriesStats;
use super::{LinearOde, MAX_FORCES};
use crate::error::{Result, WingbeatError};
use crate::pool::SeriesPool;
use nalgebra::{Complex, Matrix2, Vector2};

/// Fewest Gauss–Legendre steps per period, whatever the frequencies.
pub const MIN_STEPS_PER_PERIOD: usize = 32;
/// Largest ω·h ever used (ω from [`LinearOde::freq_scale`]); the accuracy rule of
/// [`max_step`] usually asks for less.
pub const MAX_OMEGA_H: f64 = 0.25;
/// The one-span relative error the step-size rule aims at. Every mode's one-period error stays
/// ≤ 1e-11 (`tests/one_period_accuracy.rs`); the rule aims a factor 10 lower because its error
/// constant is an asymptotic estimate.
pub const TARGET_PERIOD_ERROR: f64 = 1.0e-12;
/// Error constant of the 4-stage Gauss–Legendre method on an oscillation e^{iωt}: one step's
/// relative error is about `GAUSS_ERROR_CONSTANT · (ωh)⁹` (the leading term of the Padé
/// (4,4) approximant's error, (4!)⁴ / ((8!)² · 9) ≈ 2.3e-5; measured 2.1e-5 on a harmonic
/// oscillator).
pub const GAUSS_ERROR_CONSTANT: f64 = 2.3e-5;

/// ω·h for an oscillation of angular frequency `w` (rad/s) integrated over `span` (s) so that
/// the accumulated error over the span, (ω·span / ωh) steps × C (ωh)⁹ = C ω·span (ωh)⁸, stays at
/// [`TARGET_PERIOD_ERROR`]; never above [`MAX_OMEGA_H`].
pub fn omega_h_for(w: f64, span: f64) -> f64 {
    omega_h_with(GAUSS_ERROR_CONSTANT, w, span)
}

/// [`omega_h_for`] with the error constant `c` of the method's (ωh)⁹ local error (the coupled
/// propagator uses its own, `solve::coupled::COUPLED_ERROR_CONSTANT`).
pub(crate) fn omega_h_with(c: f64, w: f64, span: f64) -> f64 {
    let wt = (w * span).max(1.0);
    (TARGET_PERIOD_ERROR / (c * wt))
        .powf(0.125)
        .min(MAX_OMEGA_H)
}

/// Steps over `span` at the largest angular frequency `freq_scale` with the ω·h rule `omega_h`,
/// at least [`MIN_STEPS_PER_PERIOD`].
pub(crate) fn steps_with(omega_h: impl Fn(f64, f64) -> f64, freq_scale: f64, span: f64) -> f64 {
    let w = freq_scale.max(1e-300);
    let hmax = (omega_h(w, span) / w).min(span / MIN_STEPS_PER_PERIOD as f64);
    (span / hmax).ceil()
}

/// Number of Gauss–Legendre steps [`period_map`] takes over `span` (s) when the largest
/// relevant angular frequency is `freq_scale` (rad/s): the accuracy rule of [`omega_h_for`],
/// at least [`MIN_STEPS_PER_PERIOD`]. Cost estimates elsewhere (`floquet::analysis_cost`,
/// `simulate::run_cost`) call this, so they follow the rule.
pub fn steps_per_span(freq_scale: f64, span: f64) -> f64 {
    steps_with(omega_h_for, freq_scale, span)
}

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
    /// Estimated relative error of one span's integration: the difference to a run with twice
    /// the largest step, divided by 2⁸ − 1 (Richardson: the method has order 8, so that is the
    /// error of a run at the largest step; the run itself never steps longer), plus a rounding
    /// allowance of one ε per step. Relative to Φ in the scaled norm (q, q̇/ω) and to each
    /// particular solution's largest size over the recorded phases and the end. Zero when the
    /// estimate was not asked for.
    pub error_estimate: f64,
}

/// The step size bound used for `ode` over `span`: ω·h from [`omega_h_for`] with ω the
/// equation's [`LinearOde::freq_scale`], and at least [`MIN_STEPS_PER_PERIOD`] steps.
pub fn max_step<O: LinearOde + ?Sized>(ode: &O, span: f64) -> f64 {
    span / steps_per_span(ode.freq_scale(), span)
}

/// Integrates `ode` over [0, span], recording Φ and p_j at each of `phases` (ascending, in
/// [0, span)). Each interval between checkpoints is split into equal steps no longer than
/// [`max_step`]. Also estimates the error (see [`PeriodMap::error_estimate`]).
pub fn period_map<O: LinearOde + ?Sized>(ode: &O, span: f64, phases: &[f64]) -> PeriodMap {
    period_map_with(ode, span, phases, true)
}

/// Advances Φ and p_j from `from` to `to` in equal steps no longer than `hmax`.
fn advance<O: LinearOde + ?Sized>(
    ode: &O,
    tab: &Tableau,
    hmax: f64,
    from: f64,
    to: f64,
    phi: &mut Matrix2<f64>,
    part: &mut [Vector2<f64>; MAX_FORCES],
) {
    let nf = ode.n_forces();
    let len = to - from;
    if len <= 0.0 {
        return;
    }
    let n = (len / hmax).ceil().max(1.0) as usize;
    let h = len / n as f64;
    for s in 0..n {
        let m = step_map(ode, tab, from + s as f64 * h, h);
        *phi = m.r * *phi;
        for j in 0..nf {
            part[j] = m.r * part[j] + m.p[j];
        }
    }
}

/// The error estimate of a span integrated to `phi`, `part`: the same span with uniform steps
/// of twice `hmax`, compared in a scaled state norm (q and q̇/ω), divided by 2⁸ − 1.
fn error_estimate<O: LinearOde + ?Sized>(
    ode: &O,
    tab: &Tableau,
    span: f64,
    hmax: f64,
    phi: &Matrix2<f64>,
    part: &[Vector2<f64>; MAX_FORCES],
    part_scale: &[f64; MAX_FORCES],
) -> f64 {
    let nf = ode.n_forces();
    let mut phi_c = Matrix2::identity();
    let mut part_c = [Vector2::zeros(); MAX_FORCES];
    advance(ode, tab, 2.0 * hmax, 0.0, span, &mut phi_c, &mut part_c);
    let w = ode.freq_scale().max(1e-300);
    let scale = Matrix2::new(1.0, 0.0, 0.0, 1.0 / w);
    let unscale = Matrix2::new(1.0, 0.0, 0.0, w);
    let mref = (scale * phi * unscale).norm().max(1e-300);
    let mut err = (scale * (phi - phi_c) * unscale).norm() / mref;
    for j in 0..nf {
        let pref = (scale * part[j]).norm().max(part_scale[j]);
        if pref > 0.0 {
            err = err.max((scale * (part[j] - part_c[j])).norm() / pref);
        }
    }
    // Truncation (Richardson) plus a rounding allowance of one ε per step of the finer run.
    let steps = (span / hmax).ceil();
    err / 255.0 + steps * f64::EPSILON
}

/// Largest scaled |p_j| (q and q̇/ω) over recorded values: the size of each particular
/// solution over the span, which the relative error refers to (its end value alone can be
/// small by cancellation, e.g. an undamped mode far above the forcing).
fn part_scale<'a>(
    w: f64,
    parts: impl Iterator<Item = &'a [Vector2<f64>; MAX_FORCES]>,
) -> [f64; MAX_FORCES] {
    // The largest q² + (q̇/ω)² first, its square root once (√ is monotonic); `hypot` over
    // every value again only if a square overflowed.
    let parts: Vec<_> = parts.collect();
    let mut sq = [0.0_f64; MAX_FORCES];
    for p in &parts {
        for j in 0..MAX_FORCES {
            let v = p[j][1] / w;
            sq[j] = sq[j].max(p[j][0] * p[j][0] + v * v);
        }
    }
    std::array::from_fn(|j| {
        if sq[j].is_finite() {
            sq[j].sqrt()
        } else {
            parts
                .iter()
                .fold(0.0_f64, |m, p| m.max(p[j][0].hypot(p[j][1] / w)))
        }
    })
}

/// [`period_map`], with the error estimate (one more integration of the span at twice the
/// step) only when `estimate` is true.
pub fn period_map_with<O: LinearOde + ?Sized>(
    ode: &O,
    span: f64,
    phases: &[f64],
    estimate: bool,
) -> PeriodMap {
    let tab = Tableau::new();
    let hmax = max_step(ode, span);
    let mut phi = Matrix2::identity();
    let mut part = [Vector2::zeros(); MAX_FORCES];
    let mut out_phi = Vec::with_capacity(phases.len());
    let mut out_part = Vec::with_capacity(phases.len());
    let mut t = 0.0;
    for &tau in phases {
        advance(ode, &tab, hmax, t, tau, &mut phi, &mut part);
        t = t.max(tau);
        out_phi.push(phi);
        out_part.push(part);
    }
    advance(ode, &tab, hmax, t, span, &mut phi, &mut part);
    let error_estimate = if estimate {
        let ps = part_scale(
            ode.freq_scale().max(1e-300),
            out_part.iter().chain(std::iter::once(&part)),
        );
        error_estimate(ode, &tab, span, hmax, &phi, &part, &ps)
    } else {
        0.0
    };
    PeriodMap {
        span,
        phases: phases.to_vec(),
        phi: out_phi,
        part: out_part,
        monodromy: phi,
        part_end: part,
        error_estimate,
    }
}

/// Degree of the dense-output interpolant ([`DenseMap`]).
pub const DENSE_DEGREE: usize = 8;
/// Largest ω·H of one dense-output interval (ω the equation's [`LinearOde::freq_scale`]).
/// Chebyshev interpolation of degree m of e^{iωt} over an interval of length H errs by about
/// 4 (ωH/4)^(m+1) / (m+1)!: 1.5e-13 at ωH = 0.5, m = 8.
pub const DENSE_OMEGA_H: f64 = 0.5;

/// Φ(τ) and p_j(τ) at any phase of one span, from their values at the Chebyshev–Lobatto points
/// of equal intervals (integrated as in [`period_map`]) and barycentric interpolation of
/// degree [`DENSE_DEGREE`] between them. Used when a run needs many more distinct phases
/// than steps (an output grid incommensurate with the period), where one Gauss–Legendre step
/// per sample phase would cost far more than the integration itself.
#[derive(Debug, Clone)]
pub struct DenseMap {
    /// Interval length H, s.
    pub h: f64,
    /// Number of intervals.
    pub intervals: usize,
    /// Chebyshev–Lobatto nodes on [0, 1].
    nodes: [f64; DENSE_DEGREE + 1],
    /// Barycentric weights.
    weights: [f64; DENSE_DEGREE + 1],
    /// Per interval and node: Φ row-major (4) then p_j (q, q̇) for j < MAX_FORCES.
    values: Vec<[[f64; 4 + 2 * MAX_FORCES]; DENSE_DEGREE + 1]>,
    /// Φ(span).
    pub monodromy: Matrix2<f64>,
    /// p_j(span).
    pub part_end: [Vector2<f64>; MAX_FORCES],
    /// As [`PeriodMap::error_estimate`].
    pub error_estimate: f64,
}

impl DenseMap {
    /// Integrates `ode` over [0, span] and records the interpolation data.
    pub fn new<O: LinearOde + ?Sized>(ode: &O, span: f64, estimate: bool) -> Self {
        let tab = Tableau::new();
        let hmax = max_step(ode, span);
        let w = ode.freq_scale().max(1e-300);
        let intervals = ((span * w / DENSE_OMEGA_H).ceil().max(1.0) as usize).max(1);
        let h = span / intervals as f64;
        let m = DENSE_DEGREE;
        let nodes: [f64; DENSE_DEGREE + 1] = std::array::from_fn(|l| {
            0.5 * (1.0 - (std::f64::consts::PI * l as f64 / m as f64).cos())
        });
        let weights: [f64; DENSE_DEGREE + 1] = std::array::from_fn(|l| {
            let s = if l % 2 == 0 { 1.0 } else { -1.0 };
            if l == 0 || l == m {
                0.5 * s
            } else {
                s
            }
        });
        let mut phi = Matrix2::identity();
        let mut part = [Vector2::zeros(); MAX_FORCES];
        let mut values = Vec::with_capacity(intervals);
        let mut t = 0.0;
        for k in 0..intervals {
            let t0 = k as f64 * h;
            let mut row = [[0.0; 4 + 2 * MAX_FORCES]; DENSE_DEGREE + 1];
            for (l, node) in nodes.iter().enumerate() {
                let tau = if l == m && k + 1 == intervals {
                    span
                } else {
                    t0 + node * h
                };
                advance(ode, &tab, hmax, t, tau, &mut phi, &mut part);
                t = t.max(tau);
                let v = &mut row[l];
                v[0] = phi[(0, 0)];
                v[1] = phi[(0, 1)];
                v[2] = phi[(1, 0)];
                v[3] = phi[(1, 1)];
                for j in 0..MAX_FORCES {
                    v[4 + 2 * j] = part[j][0];
                    v[5 + 2 * j] = part[j][1];
                }
            }
            values.push(row);
        }
        let error_estimate = if estimate {
            let nodes_p: Vec<[Vector2<f64>; MAX_FORCES]> = values
                .iter()
                .flat_map(|row| row.iter())
                .map(|v| std::array::from_fn(|j| Vector2::new(v[4 + 2 * j], v[5 + 2 * j])))
                .collect();
            let ps = part_scale(w, nodes_p.iter());
            error_estimate(ode, &tab, span, hmax, &phi, &part, &ps)
        } else {
            0.0
        };
        DenseMap {
            h,
            intervals,
            nodes,
            weights,
            values,
            monodromy: phi,
            part_end: part,
            error_estimate,
        }
    }

    /// Φ row-major and p_j (q, q̇) at phase `tau` ∈ [0, span].
    pub fn eval(&self, tau: f64) -> [f64; 4 + 2 * MAX_FORCES] {
        let x = tau / self.h;
        // Truncation (one instruction; NaN goes to 0), then negatives to 0: floor(x).max(0)
        // without a library call.
        let k = ((x as i64).max(0) as usize).min(self.intervals - 1);
        let x = x - k as f64;
        let vals = &self.values[k];
        let mut lw = [0.0; DENSE_DEGREE + 1];
        let mut sum = 0.0;
        for l in 0..=DENSE_DEGREE {
            let d = x - self.nodes[l];
            if d == 0.0 {
                return vals[l];
            }
            lw[l] = self.weights[l] / d;
            sum += lw[l];
        }
        let inv = 1.0 / sum;
        let mut out = [0.0; 4 + 2 * MAX_FORCES];
        for (l, v) in vals.iter().enumerate() {
            let wl = lw[l] * inv;
            for (o, vi) in out.iter_mut().zip(v) {
                *o += wl * vi;
            }
        }
        out
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
        return Err(overflow_error(&map.monodromy));
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

/// What [`propagate_responses`] returns: the series a simulation outputs, nothing more.
#[derive(Debug, Clone)]
pub struct Responses {
    /// q_j(t_i) of each forcing column from a zero initial state; the column `total` asked for
    /// is left empty (its response is in [`Responses::total`]).
    pub q: Vec<Vec<f64>>,
    /// Free response to the initial state (zeros when it is zero).
    pub free: Vec<f64>,
    /// Response of the `total` column plus the free response.
    pub total: Vec<f64>,
    /// q̇ of [`Responses::total`].
    pub qdot_total: Vec<f64>,
    /// Monodromy over one period T.
    pub monodromy: Matrix2<f64>,
    /// Estimated relative error of the one-period integration.
    pub period_error: f64,
    /// Number of periods spanned.
    pub periods: u64,
    /// Whether the phases came from the dense interpolant ([`DenseMap`]) rather than from
    /// checkpoints on the sample grid.
    pub dense: bool,
    /// Statistics of each column's output series, taken as it was written: `q_stats[j]` for
    /// the series in `q[j]`, and for the `total` column those of [`Responses::total`].
    pub q_stats: Vec<SeriesStats>,
    /// Φ over the first homogeneous period, read off the run's own phase table (what Floquet
    /// analysis samples: `floquet::analyse_sampled`); None where the grid does not hold it.
    pub homogeneous: Option<HomogeneousSamples>,
}

/// Φ at equally spaced phases of the homogeneous period T_p (the period of the equation's
/// coefficients, [`LinearOde::homogeneous_period`]) and at its end, from a run's phase table.
#[derive(Debug, Clone)]
pub struct HomogeneousSamples {
    /// T_p, s.
    pub span: f64,
    /// Φ(j·T_p/m), j = 0..m (m = `phi.len()`).
    pub phi: Vec<Matrix2<f64>>,
    /// Φ(T_p).
    pub end: Matrix2<f64>,
}

/// The homogeneous-period samples a commensurate table of `p` phases per period T holds: when
/// T_p = T/k for a whole k dividing p (the table's row p/k is Φ(T_p); for k = 1 the
/// monodromy). None for the dense interpolant or a table shorter than a period.
fn homogeneous_samples<O: LinearOde + ?Sized>(
    ode: &O,
    map: &PhaseTable,
    p: usize,
) -> Option<HomogeneousSamples> {
    let (period, tp) = (ode.period(), ode.homogeneous_period());
    let k = (period / tp).round();
    if map.dense.is_some()
        || map.table.len() < p
        || k.is_nan()
        || k < 1.0
        || (k * tp - period).abs() > 1e-12 * period
    {
        return None;
    }
    let k = k as usize;
    if p % k != 0 {
        return None;
    }
    let m = p / k;
    let row = |v: &PhaseRow| Matrix2::new(v[0], v[1], v[2], v[3]);
    Some(HomogeneousSamples {
        span: tp,
        phi: map.table[..m].iter().map(row).collect(),
        end: if k == 1 {
            map.monodromy
        } else {
            row(&map.table[m])
        },
    })
}

/// Samples per period, when the output step `dt` divides `period` to 1e-12 relative.
pub fn commensurate_samples(dt: f64, period: f64) -> Option<usize> {
    let pr = (period / dt).round();
    (pr >= 1.0 && (pr * dt - period).abs() <= 1e-12 * period).then_some(pr as usize)
}

/// Propagates `ode` to the samples t_i = i·dt, i = 0..n, and forms what a simulation outputs:
/// every forcing column's response from rest, and for the column `total` the response with the
/// initial state `ic` = (q0, q̇0) added, its q̇, and the free response alone. The same numbers
/// as [`propagate`] (the same arithmetic per sample), without the series nobody reads.
///
/// Phases: on a grid commensurate with the period (P samples per period) one period is
/// integrated with a checkpoint at each of the P phases, unless P is so large that the dense
/// interpolant ([`DenseMap`]) needs fewer steps; on an incommensurate grid (a flap frequency
/// that does not divide the sample rate) every sample phase comes from the dense interpolant,
/// so the cost no longer grows with the number of samples per period.
pub fn propagate_responses<O: LinearOde + ?Sized>(
    ode: &O,
    dt: f64,
    n: usize,
    total: usize,
    ic: [f64; 2],
) -> Result<Responses> {
    propagate_responses_in(ode, dt, n, total, ic, &mut SeriesPool::new())
}

/// [`propagate_responses`] writing into series taken from `pool` (the same numbers).
pub fn propagate_responses_in<O: LinearOde + ?Sized>(
    ode: &O,
    dt: f64,
    n: usize,
    total: usize,
    ic: [f64; 2],
    pool: &mut SeriesPool,
) -> Result<Responses> {
    let period = ode.period();
    let nf = ode.n_forces();
    let pp = commensurate_samples(dt, period);
    let map = phase_table(ode, dt, n, pp);
    let used_dense = map.dense.is_some() || pp.is_some_and(|p| map.table.len() < p.min(n.max(1)));
    let mut out = ResponseWriter::new(nf, n, total, ic, pool);
    let mut state = PeriodState::new();
    let mut periods = 0;
    if let Some(d) = &map.dense {
        // Incommensurate grid: each sample's own phase; periods advance monotonically.
        let mut vals = PhaseColumns::default();
        let mut i = 0;
        while i < n {
            let t = i as f64 * dt;
            let k = whole_periods(t, period);
            state.step_to(k as u64, &map, nf);
            // Samples of this period, their phase tables, then the columns.
            vals.clear();
            while i < n {
                let t = i as f64 * dt;
                let kk = whole_periods(t, period);
                if kk != k {
                    break;
                }
                vals.push(&d.eval((t - kk * period).clamp(0.0, period)));
                i += 1;
            }
            out.write_period(&vals, vals.len, &state);
            periods = k as u64 + 1;
        }
    } else if let Some(p) = pp {
        let cols = PhaseColumns::of(&map.table);
        let mut i = 0;
        let mut k = 0u64;
        while i < n {
            state.step_to(k, &map, nf);
            let cnt = (n - i).min(p);
            out.write_period(&cols, cnt, &state);
            periods = k + 1;
            i += p;
            k += 1;
        }
    }
    let finite = out.stats.iter().all(SeriesStats::all_finite)
        && out.qdot_finite
        && all_finite(&state.arrays().1);
    if !finite {
        return Err(overflow_error(&map.monodromy));
    }
    Ok(Responses {
        q: out.q,
        q_stats: out.stats,
        free: out.free,
        total: out.tot,
        qdot_total: out.qdot_tot,
        monodromy: map.monodromy,
        period_error: map.period_error,
        periods,
        dense: used_dense,
        homogeneous: pp.and_then(|p| homogeneous_samples(ode, &map, p)),
    })
}

/// ⌊t / period⌋ for t ≥ 0 (a sample time), by truncation: the same value as `floor`, which is
/// a library call on the baseline x86-64 target and ran once per sample and mode.
fn whole_periods(t: f64, period: f64) -> f64 {
    ((t / period) as i64) as f64
}

/// Whether every value of `x` is finite: x·0 is 0 for a finite x and NaN otherwise, summed
/// in eight lanes (vectorised; the series are checked whole, without an early exit).
pub fn all_finite(x: &[f64]) -> bool {
    const L: usize = 8;
    let mut acc = [0.0_f64; L];
    let chunks = x.chunks_exact(L);
    let rest = chunks.remainder();
    for c in chunks {
        for k in 0..L {
            acc[k] += c[k] * 0.0;
        }
    }
    for (k, v) in rest.iter().enumerate() {
        acc[k] += v * 0.0;
    }
    acc.iter().sum::<f64>() == 0.0
}

/// The error of a response that overflowed, with the largest Floquet multiplier of
/// `monodromy` and what to change.
fn overflow_error(monodromy: &Matrix2<f64>) -> WingbeatError {
    let ev = multipliers(monodromy);
    let m = ev.iter().map(|z| z.norm()).fold(0.0, f64::max);
    WingbeatError::NonFinite {
        what: "modal response".into(),
        detail: format!(
            "the response overflowed: the equation is parametrically unstable (largest Floquet multiplier |λ| = {m:.6e} per period); shorten the duration or reduce the rotation rates"
        ),
    }
}

/// One phase's Φ row-major then p_j (q, q̇) for each forcing column.
type PhaseRow = [f64; ROW];
/// Entries of a [`PhaseRow`].
const ROW: usize = 4 + 2 * MAX_FORCES;

/// Phase rows stored entry by entry (column c holds entry c of every row): the writer's loops
/// then read contiguous memory and vectorise.
#[derive(Default)]
struct PhaseColumns {
    cols: [Vec<f64>; ROW],
    len: usize,
}

impl PhaseColumns {
    fn of(rows: &[PhaseRow]) -> Self {
        PhaseColumns {
            cols: std::array::from_fn(|c| rows.iter().map(|r| r[c]).collect()),
            len: rows.len(),
        }
    }

    fn clear(&mut self) {
        self.cols.iter_mut().for_each(Vec::clear);
        self.len = 0;
    }

    fn push(&mut self, row: &PhaseRow) {
        for (c, v) in self.cols.iter_mut().zip(row) {
            c.push(*v);
        }
        self.len += 1;
    }

    /// Entry `c` of the first `cnt` rows.
    fn col(&self, c: usize, cnt: usize) -> &[f64] {
        &self.cols[c][..cnt]
    }
}

/// The one-period integration [`propagate_responses`] reads: a row per phase of a
/// commensurate grid, or the dense interpolant for an incommensurate one, with the period's
/// monodromy, p_j(T) and error estimate.
struct PhaseTable {
    table: Vec<PhaseRow>,
    dense: Option<DenseMap>,
    monodromy: Matrix2<f64>,
    part_end: [Vector2<f64>; MAX_FORCES],
    period_error: f64,
}

/// Integrates one period of `ode` for the grid t_i = i·dt, i = 0..n, with `pp` samples per
/// period when commensurate: checkpoints at the phases when they cost fewer steps than the
/// dense interpolant (whose rows are then tabulated), else the interpolant itself.
fn phase_table<O: LinearOde + ?Sized>(ode: &O, dt: f64, n: usize, pp: Option<usize>) -> PhaseTable {
    let period = ode.period();
    let hmax = max_step(ode, period);
    let w = ode.freq_scale().max(1e-300);
    let dense_steps = {
        let intervals = (period * w / DENSE_OMEGA_H).ceil().max(1.0);
        let per = (period / intervals / hmax).ceil().max(1.0) * DENSE_DEGREE as f64;
        intervals * per
    };
    match pp {
        Some(p) if (p.min(n.max(1)) as f64) <= dense_steps.max(4.0 * period / hmax) => {
            let count = p.min(n.max(1));
            let phases: Vec<f64> = (0..count).map(|j| j as f64 * dt).collect();
            let map = period_map_with(ode, period, &phases, true);
            let table = map
                .phi
                .iter()
                .zip(&map.part)
                .map(|(m, pt)| {
                    let mut v = [0.0; 4 + 2 * MAX_FORCES];
                    v[..4].copy_from_slice(&[m[(0, 0)], m[(0, 1)], m[(1, 0)], m[(1, 1)]]);
                    for j in 0..MAX_FORCES {
                        v[4 + 2 * j] = pt[j][0];
                        v[5 + 2 * j] = pt[j][1];
                    }
                    v
                })
                .collect();
            PhaseTable {
                table,
                dense: None,
                monodromy: map.monodromy,
                part_end: map.part_end,
                period_error: map.error_estimate,
            }
        }
        Some(p) => {
            let d = DenseMap::new(ode, period, true);
            let count = p.min(n.max(1));
            PhaseTable {
                table: (0..count).map(|j| d.eval(j as f64 * dt)).collect(),
                dense: None,
                monodromy: d.monodromy,
                part_end: d.part_end,
                period_error: d.error_estimate,
            }
        }
        None => {
            let d = DenseMap::new(ode, period, true);
            PhaseTable {
                table: Vec::new(),
                monodromy: d.monodromy,
                part_end: d.part_end,
                period_error: d.error_estimate,
                dense: Some(d),
            }
        }
    }
}

/// The states X_j,k at the start of period `cur` and M^cur, advanced by the exact
/// period-to-period map.
struct PeriodState {
    cur: u64,
    xs: [Vector2<f64>; MAX_FORCES],
    mn: Matrix2<f64>,
}

impl PeriodState {
    fn new() -> Self {
        PeriodState {
            cur: 0,
            xs: [Vector2::zeros(); MAX_FORCES],
            mn: Matrix2::identity(),
        }
    }

    /// Advances to the start of period `k` (no-op when already there).
    fn step_to(&mut self, k: u64, map: &PhaseTable, nf: usize) {
        while self.cur < k {
            for j in 0..nf {
                self.xs[j] = map.monodromy * self.xs[j] + map.part_end[j];
            }
            self.mn = map.monodromy * self.mn;
            self.cur += 1;
        }
    }

    /// The states as (q, q̇) pairs and M^cur row-major: plain arrays for the hot loops.
    fn arrays(&self) -> ([[f64; 2]; MAX_FORCES], [f64; 4]) {
        let (xs, mn) = (&self.xs, &self.mn);
        (
            std::array::from_fn::<[f64; 2], MAX_FORCES, _>(|j| [xs[j][0], xs[j][1]]),
            [mn[(0, 0)], mn[(0, 1)], mn[(1, 0)], mn[(1, 1)]],
        )
    }
}

/// The output series of [`propagate_responses`] as they are written, period by period.
struct ResponseWriter {
    q: Vec<Vec<f64>>,
    /// Statistics of each column's series as written (`total`'s: of `tot`).
    stats: Vec<SeriesStats>,
    /// Whether every q̇ of the total written so far is finite (its only check).
    qdot_finite: bool,
    tot: Vec<f64>,
    qdot_tot: Vec<f64>,
    free: Vec<f64>,
    total: usize,
    with_ic: bool,
    ic: [f64; 2],
}

impl ResponseWriter {
    fn new(nf: usize, n: usize, total: usize, ic: [f64; 2], pool: &mut SeriesPool) -> Self {
        let with_ic = ic != [0.0, 0.0];
        let mut free = pool.take(n);
        if !with_ic {
            free.resize(n, 0.0);
        }
        ResponseWriter {
            q: (0..nf)
                .map(|j| if j == total { Vec::new() } else { pool.take(n) })
                .collect(),
            stats: vec![SeriesStats::new(); nf],
            qdot_finite: true,
            tot: pool.take(n),
            qdot_tot: pool.take(n),
            free,
            total,
            with_ic,
            ic,
        }
    }

    /// Writes the first `cnt` samples whose phases are `vals` in the period `state` stands at,
    /// from the states at its start and M^k: first the `total` column (with the free response),
    /// then each other column. Column by column over contiguous entries, so each loop is tight.
    fn write_period(&mut self, vals: &PhaseColumns, cnt: usize, state: &PeriodState) {
        let (x_arr, m) = state.arrays();
        let [x0, x1] = x_arr[self.total];
        let (c0, c1, c2, c3) = (
            vals.col(0, cnt),
            vals.col(1, cnt),
            vals.col(2, cnt),
            vals.col(3, cnt),
        );
        let (cp, cpd) = (
            vals.col(4 + 2 * self.total, cnt),
            vals.col(5 + 2 * self.total, cnt),
        );
        // x·(Φ row) + p over the period: one pass per series, each value the same expression
        // as a sample-by-sample loop's.
        let affine = |a: &[f64], b: &[f64], p: &[f64], x0: f64, x1: f64, out: &mut Vec<f64>| {
            out.extend(
                a.iter()
                    .zip(b)
                    .zip(p)
                    .map(|((a, b), p)| a * x0 + b * x1 + p),
            );
        };
        let start = self.tot.len();
        if self.with_ic {
            let [q0, v0] = self.ic;
            self.free.extend(c0.iter().zip(c1).map(|(a, b)| {
                let hq0 = a * m[0] + b * m[2];
                let hq1 = a * m[1] + b * m[3];
                q0 * hq0 + v0 * hq1
            }));
            self.tot.extend(
                c0.iter()
                    .zip(c1)
                    .zip(cp)
                    .zip(&self.free[start..])
                    .map(|(((a, b), p), fr)| (a * x0 + b * x1 + p) + fr),
            );
            self.qdot_tot
                .extend(c2.iter().zip(c3).zip(cpd).map(|((a, b), p)| {
                    let qd = a * x0 + b * x1 + p;
                    let hqd0 = a * m[0] + b * m[2];
                    let hqd1 = a * m[1] + b * m[3];
                    qd + q0 * hqd0 + v0 * hqd1
                }));
        } else {
            affine(c0, c1, cp, x0, x1, &mut self.tot);
            affine(c2, c3, cpd, x0, x1, &mut self.qdot_tot);
        }
        // Each series' statistics from the values just written (still in cache).
        self.stats[self.total].push(&self.tot[start..]);
        self.qdot_finite &= all_finite(&self.qdot_tot[start..]);
        let total = self.total;
        for (j, qj) in self.q.iter_mut().enumerate().filter(|&(j, _)| j != total) {
            let [x0, x1] = x_arr[j];
            affine(c0, c1, vals.col(4 + 2 * j, cnt), x0, x1, qj);
            self.stats[j].push(&qj[start..]);
        }
    }
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
    fn all_finite_finds_any_non_finite_value_at_any_position() {
        for n in [0, 1, 7, 8, 9, 17, 100] {
            let x: Vec<f64> = (0..n).map(|i| i as f64 * 1e300).collect();
            assert!(all_finite(&x), "n = {n}");
            for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                for i in 0..n {
                    let mut y = x.clone();
                    y[i] = bad;
                    assert!(!all_finite(&y), "n = {n}, {bad} at {i}");
                }
            }
        }
        assert!(all_finite(&[f64::MAX, -f64::MAX, f64::MIN_POSITIVE, -0.0]));
    }

    /// The homogeneous-period samples a run hands to Floquet analysis: Φ at the grid's phases
    /// over [0, T_p) and Φ(T_p), equal to a separate integration of that span; none where the
    /// grid does not hold them.
    #[test]
    fn a_commensurate_run_holds_the_homogeneous_period() {
        let cfg = crate::config::SimConfig::paper();
        let kin = cfg.kinematics.compile();
        let ode = crate::solve::ModalOde::new(&kin, &cfg.modes[0]);
        let (dt, tp) = (1.0 / cfg.sample_rate_hz, ode.homogeneous_period());
        assert_eq!(tp, 0.02);
        let r = propagate_responses(&ode, dt, 20_001, 3, [0.0; 2]).unwrap();
        let h = r.homogeneous.expect("400 phases a period hold T/2");
        assert_eq!((h.span, h.phi.len()), (tp, 200));
        let phases: Vec<f64> = (0..200).map(|j| j as f64 * dt).collect();
        let sep = period_map_with(&crate::solve::Homogeneous(&ode), tp, &phases, false);
        let dist = |a: &Matrix2<f64>, b: &Matrix2<f64>| (a - b).norm() / b.norm();
        assert!(dist(&h.end, &sep.monodromy) < 1e-12);
        for (a, b) in h.phi.iter().zip(&sep.phi) {
            assert!(dist(a, b) < 1e-12);
        }
        // Odd samples per period (no Φ(T/2) on the grid), a run shorter than a period, and an
        // incommensurate grid: none.
        for (dt, n) in [(1.0 / 2525.0, 1000), (dt, 300), (1.0 / 7777.0, 1000)] {
            let r = propagate_responses(&ode, dt, n, 3, [0.0; 2]).unwrap();
            assert!(r.homogeneous.is_none(), "dt = {dt}, n = {n}");
        }
    }

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
