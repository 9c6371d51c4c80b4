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
use super::propagator::{omega_h_for, schedule, MIN_STEPS_PER_PERIOD};
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
        for r in k + 1..n {
            let l = a[r * n + k] * d;
            a[r * n + k] = l;
            if l != 0.0 {
                for c in k + 1..n {
                    a[r * n + c] -= l * a[k * n + c];
                }
            }
        }
    }
    true
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
    /// Step map R (2N × 2N row-major) and increments r_j (2N each, column j at j·2N).
    r: Vec<f64>,
    p: Vec<f64>,
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
            r: vec![0.0; 4 * n * n],
            p: vec![0.0; 2 * n * nf],
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
        // Right-hand sides: q = e_m, q̇ = e_m (zero forcing), then each forcing from rest.
        let ncol = 2 * n + nf;
        for i in 0..STAGES {
            let bi = &self.b[i * nn..(i + 1) * nn];
            let ci = &self.c[i * nn..(i + 1) * nn];
            let hc = h * self.tab.c[i];
            for m in 0..n {
                for r in 0..n {
                    self.rhs[m * s + i * n + r] = -bi[r * n + m];
                    self.rhs[(n + m) * s + i * n + r] = -hc * bi[r * n + m] - ci[r * n + m];
                }
            }
            for j in 0..nf {
                for r in 0..n {
                    self.rhs[(2 * n + j) * s + i * n + r] = self.f[i * n * nf + j * n + r];
                }
            }
        }
        if !lu_factor(&mut self.g, s, &mut self.piv) {
            return Err(WingbeatError::NonFinite {
                what: "coupled modal step".into(),
                detail: "the stage system is singular (step too long for the damping)".into(),
            });
        }
        lu_solve(&self.g, s, &self.piv, &mut self.rhs, ncol);
        // New states: q' = q + h q̇ + h² Σ (bᵀA)_l K_l, q̇' = q̇ + h Σ b_i K_i.
        let d = 2 * n;
        for col in 0..ncol {
            let k = &self.rhs[col * s..(col + 1) * s];
            for r in 0..n {
                let mut dq = 0.0;
                let mut dv = 0.0;
                for i in 0..STAGES {
                    dq += self.ba[i] * k[i * n + r];
                    dv += self.tab.b[i] * k[i * n + r];
                }
                let (q0, v0) = if col < n {
                    (if r == col { 1.0 } else { 0.0 }, 0.0)
                } else if col < 2 * n {
                    (0.0, if r == col - n { 1.0 } else { 0.0 })
                } else {
                    (0.0, 0.0)
                };
                let qn = q0 + h * v0 + h * h * dq;
                let vn = v0 + h * dv;
                if col < d {
                    self.r[r * d + col] = qn;
                    self.r[(n + r) * d + col] = vn;
                } else {
                    let j = col - d;
                    self.p[j * d + r] = qn;
                    self.p[j * d + n + r] = vn;
                }
            }
        }
        Ok(())
    }
}

/// Φ ← R Φ for d × d row-major matrices (`tmp` scratch of d²).
fn left_mul(r: &[f64], phi: &mut [f64], d: usize, tmp: &mut [f64]) {
    for i in 0..d {
        for j in 0..d {
            let mut s = 0.0;
            for k in 0..d {
                s += r[i * d + k] * phi[k * d + j];
            }
            tmp[i * d + j] = s;
        }
    }
    phi.copy_from_slice(tmp);
}

/// x ← R x + r for a d-vector.
fn affine(r: &[f64], x: &mut [f64], add: &[f64], d: usize, tmp: &mut [f64]) {
    for i in 0..d {
        let mut s = add[i];
        for k in 0..d {
            s += r[i * d + k] * x[k];
        }
        tmp[i] = s;
    }
    x.copy_from_slice(&tmp[..d]);
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

/// The step length for `ode` over `span`: the one-period error rule of the single-mode
/// propagator ([`omega_h_for`]) with ω the system's [`CoupledOde::freq_scale`].
pub fn max_step<O: CoupledOde + ?Sized>(ode: &O, span: f64) -> f64 {
    let w = ode.freq_scale().max(1e-300);
    (omega_h_for(w, span) / w).min(span / MIN_STEPS_PER_PERIOD as f64)
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
    let mut phi = vec![0.0; d * d];
    for i in 0..d {
        phi[i * d + i] = 1.0;
    }
    let mut part = vec![0.0; d * nf];
    let mut tmp = vec![0.0; d * d];
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
    let mut t = 0.0;
    let kinks: Vec<f64> = ode
        .breakpoints()
        .into_iter()
        .filter(|&b| b > 0.0 && b < span)
        .collect();
    let mut advance = |from: f64, to: f64, phi: &mut [f64], part: &mut [f64]| -> Result<usize> {
        let len = to - from;
        if len <= 0.0 {
            return Ok(0);
        }
        // Pieces between the kinks inside (from, to), each in equal steps.
        let mut edges = vec![from];
        edges.extend(kinks.iter().copied().filter(|&b| b > from && b < to));
        edges.push(to);
        let mut steps = 0;
        for piece in edges.windows(2) {
            let (a, b) = (piece[0], piece[1]);
            let m = ((b - a) / hmax).ceil().max(1.0) as usize;
            let h = (b - a) / m as f64;
            for s in 0..m {
                w.step(ode, a + s as f64 * h, h)?;
                left_mul(&w.r, phi, d, &mut tmp);
                for j in 0..nf {
                    affine(
                        &w.r,
                        &mut part[j * d..(j + 1) * d],
                        &w.p[j * d..(j + 1) * d],
                        d,
                        &mut tmp,
                    );
                }
            }
            steps += m;
        }
        Ok(steps)
    };
    for &tau in phases {
        out.steps += advance(t, tau, &mut phi, &mut part)?;
        t = t.max(tau);
        out.phi.extend_from_slice(&phi);
        out.part.extend_from_slice(&part);
    }
    out.steps += advance(t, span, &mut phi, &mut part)?;
    out.monodromy = phi;
    out.part_end = part;
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
}

/// The Richardson estimate of one period's relative error from the maps at the step
/// (`map`) and twice it (`coarse`): the difference of the monodromies in the scaled norm
/// (q, q̇/ω, ω = `w`) and of each column's p(T) relative to its largest size over the phases
/// and the end, divided by 2⁸ − 1, plus one ε of rounding per step.
fn richardson_error(map: &CoupledMap, coarse: &CoupledMap, w: f64) -> f64 {
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
    err / 255.0 + map.steps as f64 * f64::EPSILON
}

/// Propagates `ode` to t_i = i·dt, i = 0..n: every forcing column's response from rest, and
/// for the column `total` also with the initial state `x0` = (q(0), q̇(0)) (2N values).
pub fn propagate_coupled<O: CoupledOde + ?Sized>(
    ode: &O,
    dt: f64,
    n_samples: usize,
    total: usize,
    x0: &[f64],
) -> Result<CoupledResponses> {
    let n = ode.n_modes();
    let nf = ode.n_forces();
    let d = 2 * n;
    let period = ode.period();
    let sched = schedule(dt, n_samples, period);
    let hmax = max_step(ode, period);
    let map = coupled_map(ode, period, &sched.phases, hmax)?;
    // Error estimate: the same period with twice the step (end values only).
    let coarse = coupled_map(ode, period, &[], 2.0 * hmax)?;
    let period_error = richardson_error(&map, &coarse, ode.freq_scale().max(1e-300));

    let mut q: Vec<Vec<Vec<f64>>> = (0..nf)
        .map(|_| (0..n).map(|_| Vec::with_capacity(n_samples)).collect())
        .collect();
    let mut free: Vec<Vec<f64>> = (0..n).map(|_| Vec::with_capacity(n_samples)).collect();
    let mut tot: Vec<Vec<f64>> = (0..n).map(|_| Vec::with_capacity(n_samples)).collect();
    let mut totd: Vec<Vec<f64>> = (0..n).map(|_| Vec::with_capacity(n_samples)).collect();
    // Period-start states per column and of the free response.
    let mut xs = vec![0.0; d * nf];
    let mut xf = x0.to_vec();
    let mut tmp = vec![0.0; d];
    let mut cur = 0u64;
    let mut periods = 0u64;
    let zero = vec![0.0; d];
    let mut fr = vec![0.0; d];
    for &(k, slot) in &sched.slots {
        while cur < k {
            for j in 0..nf {
                affine(
                    &map.monodromy,
                    &mut xs[j * d..(j + 1) * d],
                    &map.part_end[j * d..(j + 1) * d],
                    d,
                    &mut tmp,
                );
            }
            affine(&map.monodromy, &mut xf, &zero, d, &mut tmp);
            cur += 1;
        }
        periods = periods.max(k + 1);
        let slot = slot as usize;
        let ph = &map.phi[slot * d * d..(slot + 1) * d * d];
        let pt = &map.part[slot * d * nf..(slot + 1) * d * nf];
        for i in 0..d {
            fr[i] = (0..d).map(|c| ph[i * d + c] * xf[c]).sum();
        }
        for j in 0..nf {
            let x = &xs[j * d..(j + 1) * d];
            for r in 0..n {
                let mut v = pt[j * d + r];
                for c in 0..d {
                    v += ph[r * d + c] * x[c];
                }
                q[j][r].push(v);
                if j == total {
                    let mut vd = pt[j * d + n + r];
                    for c in 0..d {
                        vd += ph[(n + r) * d + c] * x[c];
                    }
                    tot[r].push(v + fr[r]);
                    totd[r].push(vd + fr[n + r]);
                    free[r].push(fr[r]);
                }
            }
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
    })
}
