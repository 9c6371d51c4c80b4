//! The wing in air as an ODE: Eq. 13 of every mode with the aerodynamic loads, mass-normalised
//! by M = I + M_a, as a [`CoupledOde`] ([`AirOde`]); the instants where the loads kink
//! ([`rest_instants`]). Used by the air run ([`super::simulate`]), its Floquet analysis
//! ([`super::floquet`]) and the nonlinear reference ([`super::nonlinear`]).

use super::{AeroConfig, AeroWing, FrameState};
use crate::error::{Result, WingbeatError};
use crate::kinematics::Compiled;
use crate::model::{coefficients, stiffness_coefficient, Mode};
use crate::solve::coupled::CoupledOde;
use crate::solve::ModalOde;
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
