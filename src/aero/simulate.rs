//! Simulating the wing in air: the coupled Eq. 13 with aerodynamic loads as a
//! [`CoupledOde`], and the driver that turns its responses into the same [`SimResult`] the
//! vacuum path returns (plus the per-mode `air` block and the run's `air` summary).

use super::{AeroConfig, AeroWing, FrameState, WingGeometry};
use crate::analysis::contribution::contributions_with_aero;
use crate::config::SimConfig;
use crate::error::{Result, WingbeatError};
use crate::kinematics::Compiled;
use crate::model::{coefficients, stiffness_coefficient, Mode};
use crate::simulate::{Accuracy, ModeResult, Responses, SimResult};
use crate::solve::coupled::{propagate_coupled, CoupledOde};
use crate::solve::ModalOde;
use serde::{Deserialize, Serialize};
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
        }
    }

    /// The aerodynamic damping matrix C_a(t) (N × N, 1/s) and force F_A(t), unscaled by M⁻¹.
    pub fn loads(&self, t: f64, force: &mut [f64], damping: &mut [f64]) {
        let s = self.kin.state(t);
        let fs = FrameState::from_state(&s);
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
        let s = self.kin.state(t);
        let sc = stiffness_coefficient(&s);
        let fs = FrameState::from_state(&s);
        let mut fa = [0.0; crate::model::MAX_MODES];
        let fa = &mut fa[..n];
        // C_a into b as scratch, then C = M⁻¹ (D + C_a).
        b.fill(0.0);
        self.wing.loads(&fs, self.k, self.rho_am, fa, b);
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
            for k in 0..n {
                let co = coefficients(&self.modes[k], &s);
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
    fn breakpoints(&self) -> Vec<f64> {
        self.kinks.clone()
    }
    fn freq_scale(&self) -> f64 {
        let w = self.modes.iter().map(Mode::omega).fold(0.0, f64::max);
        w.max(4.0 * self.max_harmonic * self.kin.wd)
            .max(self.damping_scale)
    }
}

/// What air does to one mode (the `air` block of a mode's result).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ModeAir {
    /// Natural frequency of the non-rotating wing in still air (added mass), Hz.
    pub still_air_freq_hz: f64,
    /// Its shift from the vacuum frequency, Hz (negative: the air's mass lowers it).
    pub added_mass_shift_hz: f64,
    /// Cycle-averaged aerodynamic damping ratio ⟨C_a,kk⟩ / (2 M_kk ω_air,k).
    pub aero_damping_ratio: f64,
    /// Decay rate of the Floquet mode that continues this mode, 1/s (positive: it decays).
    pub decay_rate_per_s: f64,
    /// Time constant of that free vibration, 1/decay rate, s; None when it does not decay.
    pub decay_time_s: Option<f64>,
    /// The beat's fate: the free vibration (and with it the beat against the forcing) decays
    /// with `decay_time_s`; "no beat" when that is shorter than the beat period.
    pub beat: String,
    /// Share of the Floquet mode's motion in this mode (1 = uncoupled).
    pub participation: f64,
}

/// The run's air summary.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AirSummary {
    /// The medium's parameters.
    pub aero: AeroConfig,
    /// Planform area of the aerodynamic quadrature, m².
    pub area_m2: f64,
    /// Quadrature points.
    pub points: usize,
    /// Added-mass matrix M_a (N × N rows), dimensionless.
    pub added_mass: Vec<Vec<f64>>,
    /// All 2N Floquet multipliers of the coupled system over one flap period, [re, im].
    pub multipliers: Vec<[f64; 2]>,
    /// True when none lies outside the unit circle.
    pub stable: bool,
    /// Gauss–Legendre steps per flap period.
    pub steps_per_period: usize,
}

/// Still-air natural frequencies (Hz) of the modes with the added mass M = I + M_a: the
/// square roots of the eigenvalues of M^{-½} Λ M^{-½}, ascending, and for each mode the
/// eigenvalue whose eigenvector it dominates.
pub fn still_air_frequencies(modes: &[Mode], mass: &[f64]) -> Vec<f64> {
    let n = modes.len();
    let m = nalgebra::DMatrix::from_row_slice(n, n, mass);
    let chol = match m.cholesky() {
        Some(c) => c,
        None => return modes.iter().map(|m| m.freq_hz).collect(),
    };
    let l = chol.l();
    let linv = l.clone().try_inverse().unwrap_or_else(|| l.clone());
    let lam = nalgebra::DMatrix::from_fn(n, n, |i, j| {
        if i == j {
            modes[i].omega().powi(2)
        } else {
            0.0
        }
    });
    let a = &linv * lam * linv.transpose();
    let a = (&a + a.transpose()) * 0.5;
    let eig = a.symmetric_eigen();
    // Eigenvectors in modal coordinates: x = L⁻ᵀ y.
    let x = linv.transpose() * &eig.eigenvectors;
    let mut out = vec![f64::NAN; n];
    let mut taken = vec![false; n];
    let mut order: Vec<(f64, usize, usize)> = Vec::new();
    for e in 0..n {
        let col = x.column(e);
        let tot: f64 = col.iter().map(|v| v * v).sum();
        for k in 0..n {
            order.push((col[k] * col[k] / tot.max(1e-300), e, k));
        }
    }
    order.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut used = vec![false; n];
    for (_, e, k) in order {
        if !taken[k] && !used[e] {
            taken[k] = true;
            used[e] = true;
            out[k] = eig.eigenvalues[e].max(0.0).sqrt() / (2.0 * PI);
        }
    }
    out
}

/// Estimated cost of an air run in step equivalents (as [`crate::simulate::run_cost`]): per
/// Gauss step four load evaluations over the quadrature (N + N(N+1)/2 products per point) and
/// a 4N LU with 2N + 5 right-hand sides, about 1 ns per product, 1 000 per unit; one period
/// three times (responses, error estimate, Floquet) plus the output.
pub fn air_run_cost(cfg: &SimConfig, wing_points: usize) -> f64 {
    let kin = cfg.kinematics.compile();
    let n = cfg.modes.len() as f64;
    let w = cfg.modes.iter().map(Mode::omega).fold(0.0, f64::max);
    let h = ModalOde::new(&kin, &cfg.modes[0]).max_harmonic;
    let t = 2.0 * PI / kin.wd;
    let steps = crate::solve::propagator::steps_per_span(w.max(4.0 * h * kin.wd), t);
    let s = 4.0 * n;
    let per_step = 4.0 * wing_points as f64 * (n + n * (n + 1.0) / 2.0 + 12.0)
        + (2.0 / 3.0) * s * s * s
        + 2.0 * s * s * (2.0 * n + 5.0)
        + 8.0 * n * n * n * 6.0;
    let samples = cfg.duration_s * cfg.sample_rate_hz + 1.0;
    3.0 * steps * per_step / 1000.0 + samples * n * (10.0 * n + 5.0) / 1000.0 + samples * n * 0.2
}

/// Runs `cfg` in its medium (`cfg.aero`, density > 0) on the wing `geom`.
pub fn simulate_in_air(cfg: &SimConfig, geom: &WingGeometry) -> Result<SimResult> {
    let n = cfg.modes.len();
    geom.validate(n)?;
    cfg.aero.validate()?;
    let wing = AeroWing::build(geom, &cfg.aero)?;
    let cost = air_run_cost(cfg, wing.points.len());
    if cost > crate::simulate::MAX_RUN_WORK {
        return Err(WingbeatError::ResourceCap {
            field: "simulate in air (modes² × quadrature points × steps per flap period)".into(),
            requested: format!("{} step equivalents", crate::error::num(cost.round())),
            cap: format!("{} step equivalents", crate::error::num(crate::simulate::MAX_RUN_WORK)),
            why: "computing time; fewer modes, fewer `aero.strips` / `aero.chord_points`, or a higher flap frequency".into(),
        });
    }
    let kin = cfg.kinematics.compile();
    let ode = AirOde::new(&kin, &cfg.modes, &wing, &cfg.aero)?;
    let ns = cfg.n_samples();
    let dt = 1.0 / cfg.sample_rate_hz;
    let mut x0 = vec![0.0; 2 * n];
    for k in 0..n {
        let ic = cfg.ic(k);
        x0[k] = ic[0];
        x0[n + k] = ic[1];
    }
    let mut pr = propagate_coupled(&ode, dt, ns, TOTAL, &x0)?;
    let fl = super::floquet::analyse_coupled(&ode, &pr.monodromy, cfg.kinematics.flap_freq_hz)?;
    let still = still_air_frequencies(&cfg.modes, &ode.mass);
    // Cycle-averaged aerodynamic damping per mode.
    let t = ode.period();
    let mut cbar = vec![0.0; n];
    {
        let (mut fa, mut ca) = (vec![0.0; n], vec![0.0; n * n]);
        let m = 64;
        for j in 0..m {
            ode.loads(j as f64 * t / m as f64, &mut fa, &mut ca);
            for k in 0..n {
                cbar[k] += ca[k * n + k] / m as f64;
            }
        }
    }
    let t_axis: Vec<f64> = (0..ns).map(|i| i as f64 * dt).collect();
    let mut modes = Vec::with_capacity(n);
    for k in 0..n {
        let mode = &cfg.modes[k];
        let q = Responses {
            euler: std::mem::take(&mut pr.q[EULER][k]),
            centrifugal: std::mem::take(&mut pr.q[CENTRIFUGAL][k]),
            coriolis: std::mem::take(&mut pr.q[CORIOLIS][k]),
            aerodynamic: std::mem::take(&mut pr.q[AERODYNAMIC][k]),
            free: std::mem::take(&mut pr.free[k]),
            total: std::mem::take(&mut pr.total[k]),
        };
        let contribution_percent = contributions_with_aero(
            &q.euler,
            &q.centrifugal,
            &q.coriolis,
            &q.aerodynamic,
            &q.total,
        );
        let f = &fl.modes[k];
        let w_air = 2.0 * PI * still[k];
        let zeta_a = cbar[k] / (2.0 * ode.mass[k * n + k] * w_air.max(1e-300));
        let decay = f.decay_rate_per_s;
        let decay_time = (decay > 0.0).then(|| 1.0 / decay);
        let beat = match (decay_time, f.floquet.beat_period_s) {
            (_, None) => "no beat (the effective frequency sits on a flap harmonic, or the mode is unstable)".to_string(),
            (Some(tau), Some(tb)) if tau < tb => format!(
                "no beat: the free vibration decays with a time constant of {} s, shorter than the beat period {} s",
                crate::error::num(round_sig(tau, 3)),
                crate::error::num(round_sig(tb, 3))
            ),
            (Some(tau), Some(tb)) => format!(
                "the beat (period {} s) fades with the free vibration, time constant {} s",
                crate::error::num(round_sig(tb, 3)),
                crate::error::num(round_sig(tau, 3))
            ),
            (None, Some(tb)) => format!(
                "the beat (period {} s) does not fade (no decay)",
                crate::error::num(round_sig(tb, 3))
            ),
        };
        modes.push(ModeResult {
            name: mode.name.clone(),
            freq_hz: mode.freq_hz,
            zeta: mode.zeta,
            qdot_total: std::mem::take(&mut pr.qdot_total[k]),
            q,
            contribution_percent,
            floquet: f.floquet.clone(),
            accuracy: Accuracy {
                method: "coupled modes in air: one-period Gauss–Legendre (order 8) propagator of the 2N-state system + exact period recursion".into(),
                period_error_estimate: pr.period_error,
                periods: pr.periods,
                run_error_bound: pr.period_error * pr.periods as f64,
            },
            air: Some(ModeAir {
                still_air_freq_hz: still[k],
                added_mass_shift_hz: still[k] - mode.freq_hz,
                aero_damping_ratio: zeta_a,
                decay_rate_per_s: decay,
                decay_time_s: decay_time,
                beat,
                participation: f.participation,
            }),
        });
    }
    let summary = AirSummary {
        aero: cfg.aero,
        area_m2: wing.area(),
        points: wing.points.len(),
        added_mass: (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| ode.mass[i * n + j] - if i == j { 1.0 } else { 0.0 })
                    .collect()
            })
            .collect(),
        multipliers: fl.multipliers.clone(),
        stable: fl.stable,
        steps_per_period: pr.steps,
    };
    Ok(crate::simulate::assemble(cfg, t_axis, modes, Some(summary)))
}

/// `v` rounded to `sig` significant digits (for messages).
fn round_sig(v: f64, sig: i32) -> f64 {
    if v == 0.0 || !v.is_finite() {
        return v;
    }
    let e = v.abs().log10().floor() as i32;
    let f = 10f64.powi(sig - 1 - e);
    (v * f).round() / f
}
