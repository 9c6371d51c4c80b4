//! The wing in air as an ODE: Eq. 13 of every mode with the aerodynamic loads, mass-normalised
//! by M = I + M_a, as a [`CoupledOde`] ([`AirOde`]); the instants where the loads kink
//! ([`rest_instants`]); the loads tabulated over one period ([`LoadTable`], which the air run
//! reads instead of summing over the quadrature at every stage). Used by the air run
//! ([`super::simulate`]), its Floquet analysis ([`super::floquet`]) and the nonlinear
//! reference ([`super::nonlinear`]).

use super::{AeroConfig, AeroWing, FrameState};
use crate::error::{Result, WingbeatError};
use crate::kinematics::Compiled;
use crate::model::{coefficients_of, stiffness_coefficient, Mode, Rotation};
use crate::solve::coupled::CoupledOde;
use crate::solve::ModalOde;
use crate::transient::CompiledTransient;
use std::f64::consts::PI;

/// Forcing columns of [`AirOde`].
pub const EULER: usize = 0;
/// Centrifugal column.
pub const CENTRIFUGAL: usize = 1;
/// Coriolis column.
pub const CORIOLIS: usize = 2;
/// Aerodynamic column.
pub const AERODYNAMIC: usize = 3;
/// Total column.
pub const TOTAL: usize = 4;

/// Eq. 13 of every mode with the air's loads, mass-normalised by M = I + M_a:
/// B(t) = M⁻¹Λ − S(t) I, C(t) = M⁻¹(D + C_a(t)), f_j = M⁻¹ F_j.
pub struct AirOde<'a> {
    /// Compiled kinematics.
    pub kin: &'a Compiled,
    /// The modes.
    pub modes: &'a [Mode],
    /// The aerodynamic quadrature.
    pub wing: &'a AeroWing,
    /// ½ ρ C_N,max, kg/m³.
    pub k: f64,
    /// ρ for the added-mass force (0 when added mass is off).
    pub rho_am: f64,
    /// M = I + M_a (N × N).
    pub mass: Vec<f64>,
    /// M⁻¹.
    pub mass_inv: Vec<f64>,
    /// M⁻¹ Λ.
    pub p: Vec<f64>,
    /// Whether the forcing columns are evaluated (false: homogeneous part only, 0 columns).
    pub forces: bool,
    /// Highest kinematic harmonic (for the step size).
    pub max_harmonic: f64,
    /// Largest ‖C(t)‖∞ over a period, 1/s (for the step size).
    pub damping_scale: f64,
    /// Instants of one period where the whole wing is at rest (Ω and γ̇ all vanish, e.g. the
    /// stroke reversals of in-phase kinematics): |v₀| has a kink there, and so do the loads.
    pub kinks: Vec<f64>,
    /// The loads tabulated over one period ([`AirOde::tabulate`]); `None`: every evaluation
    /// computes them over the quadrature.
    pub table: Option<std::sync::Arc<LoadTable>>,
    /// Non-periodic kinematics ([`AirOde::new_transient`]): the state at t comes from them
    /// instead of `kin` (then their periodic flapping), and nothing is tabulated.
    pub transient: Option<&'a CompiledTransient>,
}

/// The instants in [0, T) where the frame's rates (Ω, γ̇) all vanish: local minima of
/// |Ω|² + γ̇² on a 4096-point grid that are below 1e-20 of its maximum after refinement by
/// golden-section search.
pub fn rest_instants(kin: &Compiled) -> Vec<f64> {
    let t = 2.0 * PI / kin.wd;
    let g = |tau: f64| {
        let s = kin.state(tau);
        let om = s.omega();
        om[0] * om[0] + om[1] * om[1] + om[2] * om[2] + s.gamma_dot * s.gamma_dot
    };
    let m = 4096;
    let vals: Vec<f64> = (0..m).map(|j| g(j as f64 * t / m as f64)).collect();
    let top = vals.iter().fold(0.0f64, |a, &b| a.max(b));
    if top <= 0.0 {
        return Vec::new();
    }
    let mut out = Vec::new();
    for j in 0..m {
        let (a, b, c) = (vals[(j + m - 1) % m], vals[j], vals[(j + 1) % m]);
        if !(b <= a && b < c) {
            continue;
        }
        // Golden-section search on [t_{j−1}, t_{j+1}].
        let (mut lo, mut hi) = (
            (j as f64 - 1.0) * t / m as f64,
            (j as f64 + 1.0) * t / m as f64,
        );
        let r = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..80 {
            let x1 = hi - r * (hi - lo);
            let x2 = lo + r * (hi - lo);
            if g(x1) < g(x2) {
                hi = x2;
            } else {
                lo = x1;
            }
        }
        let tm = 0.5 * (lo + hi);
        if g(tm) <= 1e-20 * top {
            out.push(tm.rem_euclid(t));
        }
    }
    out.sort_by(f64::total_cmp);
    out
}

/// Inverse of a small symmetric positive definite matrix (Gauss–Jordan with pivoting).
fn invert(a: &[f64], n: usize) -> Result<Vec<f64>> {
    let mut m = a.to_vec();
    let mut piv = vec![0; n];
    if !crate::solve::coupled::lu_factor(&mut m, n, &mut piv) {
        return Err(WingbeatError::NonFinite {
            what: "added-mass matrix".into(),
            detail: "I + M_a is singular".into(),
        });
    }
    let mut inv = vec![0.0; n * n];
    for i in 0..n {
        inv[i * n + i] = 1.0;
    }
    crate::solve::coupled::lu_solve(&m, n, &piv, &mut inv, n);
    // lu_solve works on columns: inv holds (M⁻¹)ᵀ column-major = M⁻¹ row-major for symmetric M.
    Ok(inv)
}

impl<'a> AirOde<'a> {
    /// Sets up the system for `modes` under `kin` in the medium `aero` on `wing`.
    pub fn new(
        kin: &'a Compiled,
        modes: &'a [Mode],
        wing: &'a AeroWing,
        aero: &AeroConfig,
    ) -> Result<Self> {
        let n = modes.len();
        let rho = aero.air_density_kg_m3;
        let mut mass = if aero.added_mass {
            wing.added_mass(rho)
        } else {
            vec![0.0; n * n]
        };
        for i in 0..n {
            mass[i * n + i] += 1.0;
        }
        let mass_inv = invert(&mass, n)?;
        let mut p = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                let w = modes[j].omega();
                p[i * n + j] = mass_inv[i * n + j] * w * w;
            }
        }
        let max_harmonic = ModalOde::new(kin, &modes[0]).max_harmonic;
        let mut ode = AirOde {
            kin,
            modes,
            wing,
            k: 0.5 * rho * aero.normal_force_coefficient,
            rho_am: if aero.added_mass { rho } else { 0.0 },
            mass,
            mass_inv,
            p,
            forces: true,
            max_harmonic,
            damping_scale: 0.0,
            kinks: rest_instants(kin),
            table: None,
            transient: None,
        };
        let t = ode.period();
        let (mut b, mut c, mut f) = (vec![0.0; n * n], vec![0.0; n * n], vec![0.0; 5 * n]);
        let mut scale: f64 = 0.0;
        for j in 0..32 {
            ode.eval(j as f64 * t / 32.0, &mut b, &mut c, &mut f);
            for r in 0..n {
                scale = scale.max((0..n).map(|col| c[r * n + col].abs()).sum());
            }
        }
        ode.damping_scale = scale;
        Ok(ode)
    }

    /// The same system without forcing columns (Floquet analysis).
    pub fn homogeneous(&self) -> AirOde<'a> {
        AirOde {
            kin: self.kin,
            modes: self.modes,
            wing: self.wing,
            k: self.k,
            rho_am: self.rho_am,
            mass: self.mass.clone(),
            mass_inv: self.mass_inv.clone(),
            p: self.p.clone(),
            forces: false,
            max_harmonic: self.max_harmonic,
            damping_scale: self.damping_scale,
            kinks: self.kinks.clone(),
            table: self.table.clone(),
            transient: self.transient,
        }
    }

    /// The system under non-periodic kinematics ([`crate::transient`]): set up on their
    /// periodic flapping, then evaluated at `kin.state(t)`. Nothing repeats, so there are no
    /// rest instants to mark and no load table; the damping scale of the step rule is the
    /// largest ‖C(t)‖∞ over 512 instants of [0, `duration_s`], the disturbances included.
    pub fn new_transient(
        kin: &'a CompiledTransient,
        modes: &'a [Mode],
        wing: &'a AeroWing,
        aero: &AeroConfig,
        duration_s: f64,
    ) -> Result<Self> {
        let mut ode = AirOde::new(&kin.flapping, modes, wing, aero)?;
        ode.transient = Some(kin);
        ode.kinks.clear();
        let n = modes.len();
        let (mut b, mut c, mut f) = (vec![0.0; n * n], vec![0.0; n * n], vec![0.0; 5 * n]);
        for j in 0..=512 {
            ode.eval(j as f64 * duration_s / 512.0, &mut b, &mut c, &mut f);
            for r in 0..n {
                let row: f64 = (0..n).map(|col| c[r * n + col].abs()).sum();
                ode.damping_scale = ode.damping_scale.max(row);
            }
        }
        Ok(ode)
    }

    /// The kinematic state at t: the non-periodic kinematics' where there are some.
    fn state(&self, t: f64) -> crate::kinematics::RateState {
        match self.transient {
            Some(k) => k.state(t),
            None => self.kin.state(t),
        }
    }

    /// Tabulates the loads over one period ([`LoadTable`]); [`CoupledOde::eval`] reads them
    /// there from then on. Not for non-periodic kinematics (their loads do not repeat): then
    /// nothing is tabulated.
    pub fn tabulate(&mut self) {
        if self.transient.is_none() {
            self.table = Some(std::sync::Arc::new(LoadTable::build(self)));
        }
    }

    /// The aerodynamic damping matrix C_a(t) (N × N, 1/s) and force F_A(t), unscaled by M⁻¹:
    /// from the [`LoadTable`] where there is one, else [`AirOde::exact_loads`].
    pub fn loads(&self, t: f64, force: &mut [f64], damping: &mut [f64]) {
        if !self
            .table
            .as_ref()
            .is_some_and(|tb| tb.eval(t, force, damping))
        {
            self.exact_loads(t, force, damping);
        }
    }

    /// C_a(t) and F_A(t) as [`AirOde::loads`], always summed over the quadrature.
    pub fn exact_loads(&self, t: f64, force: &mut [f64], damping: &mut [f64]) {
        let s = self.state(t);
        let fs = FrameState::of(&s);
        force.fill(0.0);
        damping.fill(0.0);
        self.wing.loads(&fs, self.k, self.rho_am, force, damping);
    }
}

impl CoupledOde for AirOde<'_> {
    fn n_modes(&self) -> usize {
        self.modes.len()
    }
    fn n_forces(&self) -> usize {
        if self.forces {
            5
        } else {
            0
        }
    }
    fn eval(&self, t: f64, b: &mut [f64], c: &mut [f64], f: &mut [f64]) {
        let n = self.modes.len();
        let s = self.state(t);
        let sc = stiffness_coefficient(&s);
        let mut fa = [0.0; crate::model::MAX_MODES];
        let fa = &mut fa[..n];
        // C_a into b as scratch, then C = M⁻¹ (D + C_a).
        b.fill(0.0);
        if !self.table.as_ref().is_some_and(|tb| tb.eval(t, fa, b)) {
            fa.fill(0.0);
            b.fill(0.0);
            let fs = FrameState::of(&s);
            self.wing.loads(&fs, self.k, self.rho_am, fa, b);
        }
        for k in 0..n {
            let m = &self.modes[k];
            b[k * n + k] += 2.0 * m.zeta * m.omega();
        }
        for i in 0..n {
            for j in 0..n {
                c[i * n + j] = (0..n)
                    .map(|l| self.mass_inv[i * n + l] * b[l * n + j])
                    .sum();
            }
        }
        for i in 0..n {
            for j in 0..n {
                b[i * n + j] = self.p[i * n + j];
            }
            b[i * n + i] -= sc;
        }
        if self.forces {
            let mut raw = [[0.0; 5]; crate::model::MAX_MODES];
            // The rotation once for every mode (the same bits as per mode).
            let rot = Rotation::of(&s);
            for k in 0..n {
                let co = coefficients_of(&self.modes[k], &rot);
                raw[k] = [
                    co.euler,
                    co.centrifugal,
                    co.coriolis,
                    fa[k],
                    co.total_force() + fa[k],
                ];
            }
            for j in 0..5 {
                for i in 0..n {
                    f[j * n + i] = (0..n).map(|l| self.mass_inv[i * n + l] * raw[l][j]).sum();
                }
            }
        }
    }
    fn period(&self) -> f64 {
        2.0 * PI / self.kin.wd
    }
    /// The kinks, and with a [`LoadTable`] its panel edges too: a panel that had to be short
    /// marks loads that change fast there, and steps that end at its edges stay inside it.
    fn breakpoints(&self) -> Vec<f64> {
        let mut b = self.kinks.clone();
        if let Some(tb) = &self.table {
            let t = self.period();
            b.extend(tb.edges.iter().map(|e| e.rem_euclid(t)));
            b.sort_by(f64::total_cmp);
            b.dedup_by(|x, y| (*x - *y).abs() <= 1e-12 * t);
        }
        b
    }
    fn freq_scale(&self) -> f64 {
        let w = self.modes.iter().map(Mode::omega).fold(0.0, f64::max);
        let forcing = match self.transient {
            Some(k) => k.freq_scale(),
            None => 4.0 * self.max_harmonic * self.kin.wd,
        };
        w.max(forcing).max(self.damping_scale)
    }
}

/// Chebyshev points per panel of a [`LoadTable`] (degree 23 interpolants).
pub const TABLE_NODES: usize = 24;
const _: () = assert!(TABLE_NODES <= MAX_TABLE_NODES);
/// Panels per period a [`LoadTable`] starts from (between the kinks).
pub const TABLE_FIRST_PANELS: usize = 8;
/// The tolerance of a [`LoadTable`] panel: its last two Chebyshev coefficients of every load
/// stay below this fraction of that load group's largest size over the period (F_A, C_a).
pub const TABLE_TOLERANCE: f64 = 1e-14;
/// Shortest panel of a [`LoadTable`], as a fraction of the period; a panel that would need to
/// be shorter keeps the exact loads.
pub const TABLE_MIN_PANEL: f64 = 1.0 / 8192.0;
/// Most panels of a [`LoadTable`]; past it the remaining panels keep the exact loads.
pub const TABLE_MAX_PANELS: usize = 2048;
/// Most coefficients a [`LoadTable`] stores (32 MB); with many modes this, not
/// [`TABLE_MAX_PANELS`], bounds the panels that are interpolated.
pub const TABLE_MAX_VALUES: usize = 1 << 22;

/// The aerodynamic loads of one period (F_A, and C_a's upper triangle) as piecewise Chebyshev
/// interpolants in time: [`TABLE_NODES`] points per panel, panels between the kinks
/// ([`rest_instants`]) halved until their last two coefficients are below
/// [`TABLE_TOLERANCE`] of each load group's size. One load evaluation over the quadrature
/// costs as much as a whole panel's interpolant evaluated about 40 times, and the propagator
/// asks for the loads at several thousand instants per period, so it reads them here.
/// A panel that does not converge before [`TABLE_MIN_PANEL`] (or past [`TABLE_MAX_PANELS`] or
/// [`TABLE_MAX_VALUES`])
/// is marked exact: the loads are computed directly there.
#[derive(Debug, Clone)]
pub struct LoadTable {
    n: usize,
    width: usize,
    /// Chebyshev points per panel.
    m: usize,
    /// (row, column) of C_a for each packed slot after the N forces.
    pairs: Vec<(usize, usize)>,
    period: f64,
    /// Start of the table's period (the first kink, or 0).
    start: f64,
    /// Panel edges, ascending, from `start` to `start + period`.
    edges: Vec<f64>,
    /// Per panel: the coefficients, coefficient-major, rows padded to whole blocks of
    /// [`TABLE_LANES`] (`coef[(p·m + j)·wp + w]`).
    coef: Vec<f64>,
    /// Per panel: where its coefficients start in `coef`.
    offset: Vec<usize>,
    /// Per panel: whether it keeps the exact loads.
    exact: Vec<bool>,
    /// Largest tail over the interpolated panels, relative to its load group's size.
    pub tail: f64,
    /// Load evaluations the table cost.
    pub evaluations: usize,
}

impl LoadTable {
    /// Width of one instant's packed loads for `n` modes: F_A (n) and C_a's upper triangle.
    fn width_for(n: usize) -> usize {
        n + n * (n + 1) / 2
    }

    /// The packed loads at `t`.
    fn sample(ode: &AirOde<'_>, t: f64, force: &mut [f64], damping: &mut [f64], out: &mut [f64]) {
        let n = ode.modes.len();
        ode.exact_loads(t, force, damping);
        out[..n].copy_from_slice(force);
        let mut w = n;
        for a in 0..n {
            for b in a..n {
                out[w] = damping[a * n + b];
                w += 1;
            }
        }
    }

    /// Builds the table of `ode`'s loads over one period: [`TABLE_FIRST_PANELS`] panels per
    /// period between the kinks, sampled first (each load group's size is the largest value
    /// seen there), then every panel whose tail is above [`TABLE_TOLERANCE`] of that size
    /// halved until it is not.
    pub fn build(ode: &AirOde<'_>) -> LoadTable {
        let n = ode.modes.len();
        let width = Self::width_for(n);
        let period = ode.period();
        let m = TABLE_NODES;
        let wp = width.div_ceil(TABLE_LANES) * TABLE_LANES;
        let nodes: Vec<f64> = (0..m)
            .map(|j| (PI * (j as f64 + 0.5) / m as f64).cos())
            .collect();
        let start = ode.kinks.first().copied().unwrap_or(0.0);
        let mut cuts: Vec<f64> = ode.kinks.iter().skip(1).copied().collect();
        cuts.push(start + period);
        let mut first: Vec<(f64, f64)> = Vec::new();
        let mut from = start;
        for &to in &cuts {
            let pieces = ((to - from) / period * TABLE_FIRST_PANELS as f64)
                .ceil()
                .max(1.0) as usize;
            let len = (to - from) / pieces as f64;
            for i in 0..pieces {
                let b = if i + 1 == pieces {
                    to
                } else {
                    from + (i + 1) as f64 * len
                };
                first.push((from + i as f64 * len, b));
            }
            from = to;
        }
        let mut sampler = PanelSampler {
            ode,
            nodes,
            width,
            force: vec![0.0; n],
            damping: vec![0.0; n * n],
            vals: vec![0.0; m * width],
            buf: vec![0.0; width],
            evaluations: 0,
        };
        let first_coef: Vec<Vec<f64>> = first.iter().map(|&(a, b)| sampler.panel(a, b)).collect();
        // Each group's size: the largest |value| of the first panels (c₀ ± Σ|c_k| bounds it
        // within the tail; the sampled values are what the loads reach).
        let (mut fsize, mut csize) = (0.0f64, 0.0f64);
        for c in &first_coef {
            for w in 0..width {
                let v = (0..m).map(|k| c[k * width + w].abs()).sum::<f64>();
                if w < n {
                    fsize = fsize.max(v);
                } else {
                    csize = csize.max(v);
                }
            }
        }
        let limit: Vec<f64> = (0..width)
            .map(|w| (TABLE_TOLERANCE * if w < n { fsize } else { csize }).max(1e-300))
            .collect();
        let tail_of = |c: &[f64]| {
            (0..width).fold(0.0f64, |worst, w| {
                let t = c[(m - 1) * width + w]
                    .abs()
                    .max(c[(m - 2) * width + w].abs());
                worst.max(t / limit[w])
            })
        };
        let mut table = LoadTable {
            n,
            width,
            m,
            pairs: (0..n).flat_map(|a| (a..n).map(move |b| (a, b))).collect(),
            period,
            start,
            edges: vec![start],
            coef: Vec::new(),
            offset: Vec::new(),
            exact: Vec::new(),
            tail: 0.0,
            evaluations: 0,
        };
        for ((a, b), c) in first.into_iter().zip(first_coef) {
            // Depth-first halving, left half first, so the panels stay in time order.
            let mut stack = vec![(a, b, Some(c))];
            while let Some((a, b, c)) = stack.pop() {
                let c = c.unwrap_or_else(|| sampler.panel(a, b));
                let tail = tail_of(&c);
                if tail <= 1.0 {
                    table.tail = table.tail.max(tail * TABLE_TOLERANCE);
                    table.push(b, &c, false);
                } else if table.exact.len() + stack.len() >= TABLE_MAX_PANELS
                    || table.coef.len() + (stack.len() + 2) * m * wp > TABLE_MAX_VALUES
                    || b - a < 2.0 * TABLE_MIN_PANEL * period
                {
                    table.push(b, &c, true);
                } else {
                    let mid = 0.5 * (a + b);
                    stack.push((mid, b, None));
                    stack.push((a, mid, None));
                }
            }
        }
        table.evaluations = sampler.evaluations;
        table
    }

    /// Appends a panel ending at `b` with the coefficients `c` (coefficient-major, `width`
    /// per row; stored with rows padded to whole blocks of [`TABLE_LANES`]).
    /// An exact panel stores no coefficients.
    fn push(&mut self, b: f64, c: &[f64], exact: bool) {
        let wp = self.width.div_ceil(TABLE_LANES) * TABLE_LANES;
        self.edges.push(b);
        self.offset.push(self.coef.len());
        if !exact {
            for row in c.chunks_exact(self.width) {
                self.coef.extend_from_slice(row);
                self.coef.extend(std::iter::repeat_n(0.0, wp - self.width));
            }
        }
        self.exact.push(exact);
    }

    /// Panels, and how many of them keep the exact loads.
    pub fn panels(&self) -> (usize, usize) {
        (self.exact.len(), self.exact.iter().filter(|&&e| e).count())
    }

    /// F_A (N) and C_a (N × N) at `t` from the table written into `force` and `damping`;
    /// false (nothing written) where the panel keeps the exact loads.
    pub fn eval_at(&self, t: f64, force: &mut [f64], damping: &mut [f64]) -> bool {
        self.eval(t, force, damping)
    }

    #[inline]
    fn eval(&self, t: f64, force: &mut [f64], damping: &mut [f64]) -> bool {
        let mut tau = if t < self.start { t + self.period } else { t };
        if !(tau >= self.start && tau < self.start + self.period) {
            tau = t.rem_euclid(self.period);
            if tau < self.start {
                tau += self.period;
            }
        }
        let p = self
            .edges
            .partition_point(|&e| e <= tau)
            .clamp(1, self.exact.len())
            - 1;
        if self.exact[p] {
            return false;
        }
        let (a, b) = (self.edges[p], self.edges[p + 1]);
        let x = ((2.0 * tau - a - b) / (b - a)).clamp(-1.0, 1.0);
        let m = self.m;
        let w = self.width;
        let wp = w.div_ceil(TABLE_LANES) * TABLE_LANES;
        let n = self.n;
        let c = &self.coef[self.offset[p]..self.offset[p] + m * wp];
        // T_k(x) by the three-term recurrence, then every load's Σ c_k T_k(x) at once.
        let mut tk = [0.0f64; MAX_TABLE_NODES];
        tk[0] = 1.0;
        if m > 1 {
            tk[1] = x;
        }
        for k in 2..m {
            tk[k] = 2.0 * x * tk[k - 1] - tk[k - 2];
        }
        for blk in 0..wp / TABLE_LANES {
            let mut acc = [0.0f64; TABLE_LANES];
            for (cj, t) in c.chunks_exact(wp).zip(&tk[..m]) {
                let cj = &cj[blk * TABLE_LANES..(blk + 1) * TABLE_LANES];
                for i in 0..TABLE_LANES {
                    acc[i] += cj[i] * t;
                }
            }
            for i in 0..TABLE_LANES {
                let k = blk * TABLE_LANES + i;
                if k >= w {
                    break;
                }
                let v = acc[i];
                if k < n {
                    force[k] = v;
                } else {
                    let (r, col) = self.pairs[k - n];
                    damping[r * n + col] = v;
                    damping[col * n + r] = v;
                }
            }
        }
        true
    }
}

/// Loads per block of the table's Chebyshev sums.
const TABLE_LANES: usize = 8;
/// Most Chebyshev points per panel the table's reader supports.
const MAX_TABLE_NODES: usize = 32;

/// Samples the loads at one panel's Chebyshev points.
struct PanelSampler<'o, 'a> {
    ode: &'o AirOde<'a>,
    nodes: Vec<f64>,
    width: usize,
    force: Vec<f64>,
    damping: Vec<f64>,
    vals: Vec<f64>,
    buf: Vec<f64>,
    evaluations: usize,
}

impl PanelSampler<'_, '_> {
    /// The Chebyshev coefficients of the packed loads on [a, b] (coefficient-major).
    fn panel(&mut self, a: f64, b: f64) -> Vec<f64> {
        let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
        let period = self.ode.period();
        let w = self.width;
        for (j, x) in self.nodes.iter().enumerate() {
            let t = (mid + half * x).rem_euclid(period);
            LoadTable::sample(
                self.ode,
                t,
                &mut self.force,
                &mut self.damping,
                &mut self.buf,
            );
            self.vals[j * w..(j + 1) * w].copy_from_slice(&self.buf);
        }
        self.evaluations += self.nodes.len();
        let mut coef = vec![0.0; self.nodes.len() * w];
        chebyshev_coefficients(&self.vals, &self.nodes, w, &mut coef);
        coef
    }
}

/// Chebyshev coefficients of `width` functions sampled at the first-kind points `nodes`
/// (`vals[j·width + w]`), coefficient-major into `coef` (the first one halved, so f = Σ c_k T_k).
fn chebyshev_coefficients(vals: &[f64], nodes: &[f64], width: usize, coef: &mut [f64]) {
    let m = nodes.len();
    coef.fill(0.0);
    for k in 0..m {
        let scale = if k == 0 { 1.0 } else { 2.0 } / m as f64;
        for j in 0..m {
            let ck = scale * (PI * k as f64 * (j as f64 + 0.5) / m as f64).cos();
            let (row, v) = (
                &mut coef[k * width..(k + 1) * width],
                &vals[j * width..(j + 1) * width],
            );
            for w in 0..width {
                row[w] += ck * v[w];
            }
        }
    }
}
