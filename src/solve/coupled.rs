//! The coupled modal system: N second-order equations sharing periodic mass-normalised
//! stiffness and damping matrices (the wing in air, where added mass and aerodynamic damping
//! couple the modes),
//!
//! ```text
//! q̈ + C(t) q̇ + B(t) q = f_j(t),   j = 0..n_forces,   B, C: N × N, T-periodic,
//! ```
//!
//! solved as the propagator of [`super::propagator`] solves one mode: one period integrated
//! once with 4-stage Gauss–Legendre collocation (order 8) hitting every output phase, then
//! exact period-to-period affine maps x_{n+1} = M x_n + p(T) for the 2N-state x = (q, q̇).
//!
//! The stage system is reduced to the velocity stages: with q′ = q̇ the position stages are
//! Q_i = q + h c_i q̇ + h² Σ_l (A²)_il K_l, so the 4N unknowns K_i = q̈ at the stages solve
//!
//! ```text
//! K_i + Σ_l [h² (A²)_il B_i + h A_il C_i] K_l = − B_i (q + h c_i q̇) − C_i q̇ + f_i
//! ```
//!
//! (A the Butcher matrix), one dense LU of size 4N per step shared by the 2N homogeneous
//! columns and the forcings.

use super::gauss::{Tableau, STAGES};
use super::propagator::schedule;
use crate::error::{Result, WingbeatError};

/// A coupled linear periodic system of N modes (see the module docs).
pub trait CoupledOde {
    /// N, the number of modal coordinates.
    fn n_modes(&self) -> usize;
    /// Number of forcing columns.
    fn n_forces(&self) -> usize;
    /// Writes B(t) and C(t) (N × N, row-major) and the forcings f (column-major: `f[j·N + k]`).
    fn eval(&self, t: f64, b: &mut [f64], c: &mut [f64], f: &mut [f64]);
    /// Period T of the coefficients, s.
    fn period(&self) -> f64;
    /// The highest angular frequency (rad/s) the solution or forcings contain to relevant
    /// accuracy; the step size is chosen from it as for one mode.
    fn freq_scale(&self) -> f64;
    /// Times in [0, period) where the coefficients have a kink (a discontinuous derivative);
    /// steps end there so the method keeps its order. Default: none.
    fn breakpoints(&self) -> Vec<f64> {
        Vec::new()
    }
}

/// In-place LU with partial pivoting of the n × n row-major `a`; `piv` gets the row swaps.
/// Returns false when a pivot is exactly zero.
pub fn lu_factor(a: &mut [f64], n: usize, piv: &mut [usize]) -> bool {
    for k in 0..n {
        let mut p = k;
        let mut best = a[k * n + k].abs();
        for r in k + 1..n {
            let v = a[r * n + k].abs();
            if v > best {
                best = v;
                p = r;
            }
        }
        piv[k] = p;
        if best == 0.0 {
            return false;
        }
        if p != k {
            for c in 0..n {
                a.swap(k * n + c, p * n + c);
            }
        }
        let d = 1.0 / a[k * n + k];
        let (top, below) = a.split_at_mut((k + 1) * n);
        let pivot_row = &top[k * n + k + 1..(k + 1) * n];
        for row in below.chunks_exact_mut(n) {
            let l = row[k] * d;
            row[k] = l;
            if l != 0.0 {
                for (x, u) in row[k + 1..].iter_mut().zip(pivot_row) {
                    *x -= l * u;
                }
            }
        }
    }
    true
}

/// Solves with the factors of [`lu_factor`] for `m` right-hand sides stored row-major in `x`
/// (`x[i·m + j]`: row i of all of them at once), in place.
pub fn lu_solve_rows(a: &[f64], n: usize, piv: &[usize], x: &mut [f64], m: usize) {
    for k in 0..n {
        if piv[k] != k {
            for c in 0..m {
                x.swap(k * m + c, piv[k] * m + c);
            }
        }
    }
    for i in 1..n {
        let (done, rest) = x.split_at_mut(i * m);
        let xi = &mut rest[..m];
        for (k, xk) in done.chunks_exact(m).enumerate() {
            let l = a[i * n + k];
            if l != 0.0 {
                for (v, w) in xi.iter_mut().zip(xk) {
                    *v -= l * w;
                }
            }
        }
    }
    for i in (0..n).rev() {
        let (head, tail) = x.split_at_mut((i + 1) * m);
        let xi = &mut head[i * m..];
        for (k, xk) in tail.chunks_exact(m).enumerate() {
            let u = a[i * n + i + 1 + k];
            for (v, w) in xi.iter_mut().zip(xk) {
                *v -= u * w;
            }
        }
        let inv = 1.0 / a[i * n + i];
        for v in xi.iter_mut() {
            *v *= inv;
        }
    }
}

/// Solves with the factors of [`lu_factor`] for `m` right-hand sides stored column-major in
/// `x` (`x[j·n + i]`), in place.
pub fn lu_solve(a: &[f64], n: usize, piv: &[usize], x: &mut [f64], m: usize) {
    for j in 0..m {
        let col = &mut x[j * n..(j + 1) * n];
        for k in 0..n {
            col.swap(k, piv[k]);
        }
        for i in 0..n {
            let mut s = col[i];
            for k in 0..i {
                s -= a[i * n + k] * col[k];
            }
            col[i] = s;
        }
        for i in (0..n).rev() {
            let mut s = col[i];
            for k in i + 1..n {
                s -= a[i * n + k] * col[k];
            }
            col[i] = s / a[i * n + i];
        }
    }
}

/// Scratch space of one step, allocated once per integration.
struct Work {
    n: usize,
    nf: usize,
    b: Vec<f64>,
    c: Vec<f64>,
    f: Vec<f64>,
    g: Vec<f64>,
    piv: Vec<usize>,
    rhs: Vec<f64>,
    /// The step's affine map [R | P]: 2N rows of 2N + n_forces columns (R the transition,
    /// column 2N + j the increment of forcing j from rest).
    rp: Vec<f64>,
    a2: [[f64; STAGES]; STAGES],
    ba: [f64; STAGES],
    tab: Tableau,
}

impl Work {
    fn new(n: usize, nf: usize) -> Self {
        let tab = Tableau::new();
        let mut a2 = [[0.0; STAGES]; STAGES];
        let mut ba = [0.0; STAGES];
        for i in 0..STAGES {
            for l in 0..STAGES {
                a2[i][l] = (0..STAGES).map(|m| tab.a[i][m] * tab.a[m][l]).sum();
            }
        }
        for l in 0..STAGES {
            ba[l] = (0..STAGES).map(|i| tab.b[i] * tab.a[i][l]).sum();
        }
        let s = STAGES * n;
        Work {
            n,
            nf,
            b: vec![0.0; STAGES * n * n],
            c: vec![0.0; STAGES * n * n],
            f: vec![0.0; STAGES * n * nf],
            g: vec![0.0; s * s],
            piv: vec![0; s],
            rhs: vec![0.0; s * (2 * n + nf)],
            rp: vec![0.0; 2 * n * (2 * n + nf)],
            a2,
            ba,
            tab,
        }
    }

    /// The affine map of one step from `t0` over `h` into `self.r`, `self.p`.
    fn step<O: CoupledOde + ?Sized>(&mut self, ode: &O, t0: f64, h: f64) -> Result<()> {
        let n = self.n;
        let nf = self.nf;
        let nn = n * n;
        let s = STAGES * n;
        for i in 0..STAGES {
            ode.eval(
                t0 + self.tab.c[i] * h,
                &mut self.b[i * nn..(i + 1) * nn],
                &mut self.c[i * nn..(i + 1) * nn],
                &mut self.f[i * n * nf..(i + 1) * n * nf],
            );
        }
        // G: block (i, l) = δ_il I + h² (A²)_il B_i + h A_il C_i.
        for i in 0..STAGES {
            let bi = &self.b[i * nn..(i + 1) * nn];
            let ci = &self.c[i * nn..(i + 1) * nn];
            for l in 0..STAGES {
                let wb = h * h * self.a2[i][l];
                let wc = h * self.tab.a[i][l];
                for r in 0..n {
                    let row = (i * n + r) * s + l * n;
                    for col in 0..n {
                        self.g[row + col] = wb * bi[r * n + col] + wc * ci[r * n + col];
                    }
                    if i == l {
                        self.g[row + r] += 1.0;
                    }
                }
            }
        }
        // Right-hand sides, row-major (row i·N + r of stage i): q = e_m, q̇ = e_m (zero
        // forcing), then each forcing from rest.
        let ncol = 2 * n + nf;
        for i in 0..STAGES {
            let bi = &self.b[i * nn..(i + 1) * nn];
            let ci = &self.c[i * nn..(i + 1) * nn];
            let hc = h * self.tab.c[i];
            for r in 0..n {
                let row = &mut self.rhs[(i * n + r) * ncol..(i * n + r + 1) * ncol];
                for m in 0..n {
                    row[m] = -bi[r * n + m];
                    row[n + m] = -hc * bi[r * n + m] - ci[r * n + m];
                }
                for j in 0..nf {
                    row[2 * n + j] = self.f[i * n * nf + j * n + r];
                }
            }
        }
        if !lu_factor(&mut self.g, s, &mut self.piv) {
            return Err(WingbeatError::NonFinite {
                what: "coupled modal step".into(),
                detail: "the stage system is singular (step too long for the damping)".into(),
            });
        }
        lu_solve_rows(&self.g, s, &self.piv, &mut self.rhs, ncol);
        // New states: q' = q + h q̇ + h² Σ (bᵀA)_l K_l, q̇' = q̇ + h Σ b_i K_i.
        let (q_rows, v_rows) = self.rp.split_at_mut(n * ncol);
        for r in 0..n {
            let qr = &mut q_rows[r * ncol..(r + 1) * ncol];
            let vr = &mut v_rows[r * ncol..(r + 1) * ncol];
            qr.fill(0.0);
            vr.fill(0.0);
            for i in 0..STAGES {
                let k = &self.rhs[(i * n + r) * ncol..(i * n + r + 1) * ncol];
                let (wq, wv) = (h * h * self.ba[i], h * self.tab.b[i]);
                for ((q, v), kk) in qr.iter_mut().zip(vr.iter_mut()).zip(k) {
                    *q += wq * kk;
                    *v += wv * kk;
                }
            }
            qr[r] += 1.0;
            qr[n + r] += h;
            vr[n + r] += 1.0;
        }
        Ok(())
    }
}

/// Steps `ode` from rest (q = q̇ = 0 at t = 0) with `m` Gauss steps in each of `intervals`
/// intervals of `dt`, the same order-8 step as the propagator, and calls `sample(i, x)` at
/// t = i·dt (i = 0 … `intervals`) with the 2N-state [q, q̇] of each forcing column, column j at
/// `x[j·2N .. (j + 1)·2N]`. For kinematics that do not repeat ([`crate::transient`]): no
/// period is reused, every step is taken.
pub fn step_from_rest<O: CoupledOde + ?Sized>(
    ode: &O,
    dt: f64,
    intervals: usize,
    m: usize,
    mut sample: impl FnMut(usize, &[f64]),
) -> Result<()> {
    let (n, nf) = (ode.n_modes(), ode.n_forces());
    let d = 2 * n;
    let ncol = d + nf;
    let mut work = Work::new(n, nf);
    let mut x = vec![0.0; nf * d];
    let mut next = vec![0.0; d];
    let h = dt / m.max(1) as f64;
    sample(0, &x);
    for i in 0..intervals {
        for k in 0..m.max(1) {
            work.step(ode, i as f64 * dt + k as f64 * h, h)?;
            for j in 0..nf {
                let xj = &mut x[j * d..(j + 1) * d];
                for (r, out) in next.iter_mut().enumerate() {
                    let row = &work.rp[r * ncol..(r + 1) * ncol];
                    *out = row[d + j]
                        + row[..d]
                            .iter()
                            .zip(xj.iter())
                            .map(|(a, b)| a * b)
                            .sum::<f64>();
                }
                xj.copy_from_slice(&next);
            }
        }
        if x.iter().any(|v| !v.is_finite()) {
            return Err(WingbeatError::NonFinite {
                what: "coupled run from rest".into(),
                detail: format!("the state is not finite at t = {} s", (i + 1) as f64 * dt),
            });
        }
        sample(i + 1, &x);
    }
    Ok(())
}

/// S ← [R | P] applied to the affine state S = [Φ | p] (d rows, `ncol` = d + n_forces columns,
/// row-major): Φ ← R Φ, p_j ← R p_j + P_j. `tmp` is scratch of the same size.
fn compose(rp: &[f64], st: &mut [f64], d: usize, ncol: usize, tmp: &mut [f64]) {
    for i in 0..d {
        let out = &mut tmp[i * ncol..(i + 1) * ncol];
        out[..d].fill(0.0);
        out[d..].copy_from_slice(&rp[i * ncol + d..(i + 1) * ncol]);
        for k in 0..d {
            let r = rp[i * ncol + k];
            for (o, v) in out.iter_mut().zip(&st[k * ncol..(k + 1) * ncol]) {
                *o += r * v;
            }
        }
    }
    st.copy_from_slice(tmp);
}

/// One span's transition data of a coupled system at checkpoint phases.
#[derive(Debug, Clone)]
pub struct CoupledMap {
    /// N.
    pub n: usize,
    /// Forcing columns.
    pub nf: usize,
    /// Checkpoint phases, s.
    pub phases: Vec<f64>,
    /// Φ(τ) per checkpoint, 2N × 2N row-major, concatenated.
    pub phi: Vec<f64>,
    /// p_j(τ) per checkpoint, (2N per forcing), concatenated.
    pub part: Vec<f64>,
    /// Φ(span).
    pub monodromy: Vec<f64>,
    /// p_j(span), 2N per forcing.
    pub part_end: Vec<f64>,
    /// Steps taken.
    pub steps: usize,
}

/// Leading error constant of the 4-stage Gauss–Legendre method on an oscillation e^{iωt}: its
/// stability function is the Padé (4,4) approximant of e^z, whose error is
/// (4!)² / (8!·9!) z⁹ ≈ 3.9e-8 z⁹ per step. (The single-mode rule,
/// [`super::propagator::GAUSS_ERROR_CONSTANT`], uses a constant about 580× larger and so
/// takes about 2.2× more steps than its target needs; the vacuum path keeps it.)
pub const COUPLED_ERROR_CONSTANT: f64 = 576.0 / (40320.0 * 362880.0);

/// ω·h for the coupled propagator: the accumulated error over `span`, (ω·span / ωh) steps ×
/// C (ωh)⁹, at [`super::propagator::TARGET_PERIOD_ERROR`] with C = [`COUPLED_ERROR_CONSTANT`]; never above
/// [`super::propagator::MAX_OMEGA_H`]. For the FE wing in air this takes 1207 steps per period (the single-mode
/// rule: 2579) and the measured one-period error is 1.7e-13 (`tests/aero_air.rs`,
/// `coupled_step_rule_meets_the_one_period_target_and_the_estimate_bounds_the_error`).
pub fn coupled_omega_h(w: f64, span: f64) -> f64 {
    super::propagator::omega_h_with(COUPLED_ERROR_CONSTANT, w, span)
}

/// Steps over `span` at the highest angular frequency `freq_scale` (rad/s) by the coupled
/// rule ([`coupled_omega_h`]), at least [`super::propagator::MIN_STEPS_PER_PERIOD`]; kinks and checkpoints add
/// more. The air run's cost estimate (`aero::simulate::air_run_cost`) calls this.
pub fn coupled_steps_per_span(freq_scale: f64, span: f64) -> f64 {
    super::propagator::steps_with(coupled_omega_h, freq_scale, span)
}

/// The step length for `ode` over `span`: [`coupled_omega_h`] with ω the system's
/// [`CoupledOde::freq_scale`], and at least [`super::propagator::MIN_STEPS_PER_PERIOD`] steps.
pub fn max_step<O: CoupledOde + ?Sized>(ode: &O, span: f64) -> f64 {
    span / coupled_steps_per_span(ode.freq_scale(), span)
}

/// Integrates `ode` over [0, span] with steps no longer than `hmax`, recording Φ and p_j at
/// each of `phases` (ascending, in [0, span)).
pub fn coupled_map<O: CoupledOde + ?Sized>(
    ode: &O,
    span: f64,
    phases: &[f64],
    hmax: f64,
) -> Result<CoupledMap> {
    let n = ode.n_modes();
    let nf = ode.n_forces();
    let d = 2 * n;
    let mut w = Work::new(n, nf);
    let ncol = d + nf;
    // The affine state S = [Φ | p_0 … p_{nf−1}], d rows, row-major.
    let mut st = vec![0.0; d * ncol];
    for i in 0..d {
        st[i * ncol + i] = 1.0;
    }
    let mut tmp = vec![0.0; d * ncol];
    let mut out = CoupledMap {
        n,
        nf,
        phases: phases.to_vec(),
        phi: Vec::with_capacity(phases.len() * d * d),
        part: Vec::with_capacity(phases.len() * d * nf),
        monodromy: vec![],
        part_end: vec![],
        steps: 0,
    };
    let mut kinks: Vec<f64> = ode
        .breakpoints()
        .into_iter()
        .filter(|&b| b > 0.0 && b < span)
        .collect();
    kinks.sort_by(f64::total_cmp);
    let mut advance = |from: f64, to: f64, st: &mut [f64]| -> Result<usize> {
        if to - from <= 0.0 {
            return Ok(0);
        }
        // Pieces between the kinks inside (from, to), each in equal steps.
        let lo = kinks.partition_point(|&b| b <= from);
        let hi = kinks.partition_point(|&b| b < to);
        let mut steps = 0;
        let mut a = from;
        for &b in kinks[lo..hi.max(lo)].iter().chain(std::iter::once(&to)) {
            let m = ((b - a) / hmax).ceil().max(1.0) as usize;
            let h = (b - a) / m as f64;
            for s in 0..m {
                w.step(ode, a + s as f64 * h, h)?;
                compose(&w.rp, st, d, ncol, &mut tmp);
            }
            steps += m;
            a = b;
        }
        Ok(steps)
    };
    let record = |st: &[f64], phi: &mut Vec<f64>, part: &mut Vec<f64>| {
        for i in 0..d {
            phi.extend_from_slice(&st[i * ncol..i * ncol + d]);
        }
        for j in 0..nf {
            part.extend((0..d).map(|i| st[i * ncol + d + j]));
        }
    };
    let mut t = 0.0;
    for &tau in phases {
        out.steps += advance(t, tau, &mut st)?;
        t = t.max(tau);
        record(&st, &mut out.phi, &mut out.part);
    }
    out.steps += advance(t, span, &mut st)?;
    record(&st, &mut out.monodromy, &mut out.part_end);
    Ok(out)
}

/// Responses of a coupled system at the output samples.
#[derive(Debug, Clone)]
pub struct CoupledResponses {
    /// `q[j][k]`: mode k's response to forcing column j from rest, at every sample.
    pub q: Vec<Vec<Vec<f64>>>,
    /// `free[k]`: mode k's free response to the initial state.
    pub free: Vec<Vec<f64>>,
    /// `total[k]`: the response of column `total` plus the free response.
    pub total: Vec<Vec<f64>>,
    /// q̇ of `total`.
    pub qdot_total: Vec<Vec<f64>>,
    /// The monodromy over one period (2N × 2N row-major).
    pub monodromy: Vec<f64>,
    /// Estimated relative error of the one-period integration (Richardson against twice the
    /// step, as for one mode).
    pub period_error: f64,
    /// Periods spanned.
    pub periods: u64,
    /// Steps per period.
    pub steps: usize,
    /// Φ at each of the extra phases asked for (2N × 2N row-major each, concatenated).
    pub extra_phi: Vec<f64>,
}

/// The union of the ascending phase lists `a` and `b` (each in [0, span]), phases closer than
/// `tol` taken as one, without `span` itself; and for each phase of `a` and of `b` its index in
/// the union (`usize::MAX` for a phase of `b` at `span`; `a` lies in [0, span)).
fn merge_phases(a: &[f64], b: &[f64], span: f64, tol: f64) -> (Vec<f64>, Vec<usize>, Vec<usize>) {
    let mut all: Vec<f64> = Vec::with_capacity(a.len() + b.len());
    let (mut ia, mut ib) = (vec![usize::MAX; a.len()], vec![usize::MAX; b.len()]);
    let (mut i, mut j) = (0, 0);
    while i < a.len() || j < b.len() {
        let take_a = j >= b.len() || (i < a.len() && a[i] <= b[j]);
        let v = if take_a { a[i] } else { b[j] };
        let idx = if !take_a && v >= span - tol {
            usize::MAX
        } else if all.last().is_some_and(|&l| v - l <= tol) {
            all.len() - 1
        } else {
            all.push(v);
            all.len() - 1
        };
        if take_a {
            ia[i] = idx;
            i += 1;
        } else {
            ib[j] = idx;
            j += 1;
        }
    }
    (all, ia, ib)
}

/// The relative difference of two integrations of the same span, `map` and `other`: of the
/// monodromies in the scaled norm (q, q̇/ω, ω = `w`), and of each column's p(span) relative to
/// its largest size over `map`'s phases and the end; the largest of these.
pub fn map_difference(map: &CoupledMap, other: &CoupledMap, w: f64) -> f64 {
    let coarse = other;
    let (n, nf) = (map.n, map.nf);
    let d = 2 * n;
    let scaled = |v: &[f64], i: usize| if i % d < n { v[i] } else { v[i] / w };
    let mut err: f64 = 0.0;
    // Φ in the scaled norm (q, q̇/ω): S Φ S⁻¹.
    let (mut num, mut den) = (0.0f64, 0.0f64);
    for i in 0..d {
        for j in 0..d {
            let sc = (if i < n { 1.0 } else { 1.0 / w }) * (if j < n { 1.0 } else { w });
            let a = map.monodromy[i * d + j] * sc;
            let b = coarse.monodromy[i * d + j] * sc;
            num += (a - b) * (a - b);
            den += a * a;
        }
    }
    err = err.max(num.sqrt() / den.sqrt().max(1e-300));
    for j in 0..nf {
        let mut size: f64 = 0.0;
        for c in 0..map.phases.len() {
            let p = &map.part[c * d * nf + j * d..c * d * nf + (j + 1) * d];
            size = size.max((0..d).map(|i| scaled(p, i).powi(2)).sum::<f64>().sqrt());
        }
        let pe = &map.part_end[j * d..(j + 1) * d];
        let pc = &coarse.part_end[j * d..(j + 1) * d];
        size = size.max((0..d).map(|i| scaled(pe, i).powi(2)).sum::<f64>().sqrt());
        let diff = (0..d)
            .map(|i| (scaled(pe, i) - scaled(pc, i)).powi(2))
            .sum::<f64>()
            .sqrt();
        if size > 0.0 {
            err = err.max(diff / size);
        }
    }
    err
}

/// The Richardson estimate of one period's relative error from the maps at the step
/// (`map`) and twice it (`coarse`): their [`map_difference`] divided by 2⁸ − 1, plus one ε
/// of rounding per step.
fn richardson_error(map: &CoupledMap, coarse: &CoupledMap, w: f64) -> f64 {
    map_difference(map, coarse, w) / 255.0 + map.steps as f64 * f64::EPSILON
}

/// Columns per block of the output's products (rows of the period-start states are padded to
/// a whole number of blocks).
const LANES: usize = 8;

/// The next period's start states X' = M X + [p(T) | 0] (d rows, padded to `mp` columns; the
/// first n_forces columns are the forcings' responses from rest, the next the free one).
fn next_period(map: &CoupledMap, xs: &[f64], next: &mut [f64], mp: usize) {
    let (d, nf) = (2 * map.n, map.nf);
    for i in 0..d {
        let row = &mut next[i * mp..(i + 1) * mp];
        row.fill(0.0);
        for j in 0..nf {
            row[j] = map.part_end[j * d + i];
        }
        for c in 0..d {
            let mc = map.monodromy[i * d + c];
            for (o, x) in row.iter_mut().zip(&xs[c * mp..(c + 1) * mp]) {
                *o += mc * x;
            }
        }
    }
}

/// `acc` ← one row of Φ(τ) times the period-start states `xs` (rows of `mp` columns), in
/// blocks of [`LANES`] columns on fixed accumulators.
fn row_times_states(ph_row: &[f64], xs: &[f64], mp: usize, acc: &mut [f64]) {
    for (blk, out) in acc.chunks_exact_mut(LANES).enumerate() {
        let (mut a0, mut a1, mut a2, mut a3) = ([0.0f64; 2], [0.0; 2], [0.0; 2], [0.0; 2]);
        for (pc, xrow) in ph_row.iter().zip(xs.chunks_exact(mp)) {
            let x = &xrow[blk * LANES..(blk + 1) * LANES];
            a0[0] += pc * x[0];
            a0[1] += pc * x[1];
            a1[0] += pc * x[2];
            a1[1] += pc * x[3];
            a2[0] += pc * x[4];
            a2[1] += pc * x[5];
            a3[0] += pc * x[6];
            a3[1] += pc * x[7];
        }
        out.copy_from_slice(&[a0[0], a0[1], a1[0], a1[1], a2[0], a2[1], a3[0], a3[1]]);
    }
}

/// Propagates `ode` to t_i = i·dt, i = 0..n: every forcing column's response from rest, and
/// for the column `total` also with the initial state `x0` = (q(0), q̇(0)) (2N values). The
/// same pass records Φ at the `extra` phases (ascending, in (0, period]; the Floquet analysis'
/// grid), so they need no integration of their own.
pub fn propagate_coupled<O: CoupledOde + ?Sized>(
    ode: &O,
    dt: f64,
    n_samples: usize,
    total: usize,
    x0: &[f64],
    extra: &[f64],
) -> Result<CoupledResponses> {
    let n = ode.n_modes();
    let nf = ode.n_forces();
    let d = 2 * n;
    let period = ode.period();
    let sched = schedule(dt, n_samples, period);
    let hmax = max_step(ode, period);
    let (all, out_idx, extra_idx) = merge_phases(&sched.phases, extra, period, 1e-12 * period);
    let map = coupled_map(ode, period, &all, hmax)?;
    let mut extra_phi = Vec::with_capacity(extra.len() * d * d);
    for &e in &extra_idx {
        extra_phi.extend_from_slice(if e == usize::MAX {
            &map.monodromy
        } else {
            &map.phi[e * d * d..(e + 1) * d * d]
        });
    }
    // Error estimate: the same period with twice the step (end values only).
    let coarse = coupled_map(ode, period, &[], 2.0 * hmax)?;
    let period_error = richardson_error(&map, &coarse, ode.freq_scale().max(1e-300));

    let mut q: Vec<Vec<Vec<f64>>> = (0..nf)
        .map(|_| (0..n).map(|_| Vec::with_capacity(n_samples)).collect())
        .collect();
    let mut free: Vec<Vec<f64>> = (0..n).map(|_| Vec::with_capacity(n_samples)).collect();
    let mut tot: Vec<Vec<f64>> = (0..n).map(|_| Vec::with_capacity(n_samples)).collect();
    let mut totd: Vec<Vec<f64>> = (0..n).map(|_| Vec::with_capacity(n_samples)).collect();
    // Period-start states X = [x_0 … x_{nf−1} | x_free]: d rows of m columns (each forcing's
    // response from rest and the free response), row-major with rows padded to `mp`, a
    // multiple of LANES, so the per-sample products run on fixed-size accumulators.
    let m = nf + 1;
    let mp = m.div_ceil(LANES) * LANES;
    let mut xs = vec![0.0; d * mp];
    for i in 0..d {
        xs[i * mp + nf] = x0[i];
    }
    let mut next = vec![0.0; d * mp];
    let mut acc = vec![0.0; mp];
    // The total's and the free response's period-start states added (for q̇ of the total).
    let mut y = vec![0.0; d];
    let mut y_of = u64::MAX;
    let mut cur = 0u64;
    let mut periods = 0u64;
    for &(k, slot) in &sched.slots {
        while cur < k {
            next_period(&map, &xs, &mut next, mp);
            std::mem::swap(&mut xs, &mut next);
            cur += 1;
        }
        if y_of != cur {
            for c in 0..d {
                y[c] = xs[c * mp + total] + xs[c * mp + nf];
            }
            y_of = cur;
        }
        periods = periods.max(k + 1);
        let slot = out_idx[slot as usize];
        let ph = &map.phi[slot * d * d..(slot + 1) * d * d];
        let pt = &map.part[slot * d * nf..(slot + 1) * d * nf];
        // q rows of Φ(τ) X + p(τ), every column at once.
        for r in 0..n {
            row_times_states(&ph[r * d..(r + 1) * d], &xs, mp, &mut acc);
            for j in 0..nf {
                q[j][r].push(acc[j] + pt[j * d + r]);
            }
            free[r].push(acc[nf]);
            tot[r].push(acc[total] + pt[total * d + r] + acc[nf]);
        }
        // q̇ of the total: the total column plus the free response.
        for r in 0..n {
            let row = &ph[(n + r) * d..(n + r + 1) * d];
            let v: f64 = row.iter().zip(&y).map(|(a, b)| a * b).sum();
            totd[r].push(v + pt[total * d + n + r]);
        }
    }
    let finite = tot.iter().flatten().all(|v| v.is_finite())
        && q.iter().flatten().flatten().all(|v| v.is_finite());
    if !finite {
        return Err(WingbeatError::NonFinite {
            what: "coupled modal response".into(),
            detail: "the response overflowed: the coupled system is unstable over this duration; shorten it or reduce the rotation rates".into(),
        });
    }
    Ok(CoupledResponses {
        q,
        free,
        total: tot,
        qdot_total: totd,
        monodromy: map.monodromy,
        period_error,
        periods,
        steps: map.steps,
        extra_phi,
    })
}
