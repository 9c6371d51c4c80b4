//! The nonlinear reference: the wing in air stepped directly in time with the full |v|v
//! normal force evaluated at the elastic velocity of every quadrature point, at every stage
//! (classical Runge–Kutta, fixed small steps). It measures what linearising the drag in the
//! elastic velocity ([`super::simulate`]) costs; it is not a production path.
//!
//! Also here: [`rk4_linear`], the same explicit method on the linearised coupled system, an
//! integrator independent of the Gauss–Legendre propagator for cross-checks.

use super::ode::AirOde;
use super::{FrameState, WingGeometry};
use crate::config::SimConfig;
use crate::error::{Result, WingbeatError};
use crate::model::{coefficients, stiffness_coefficient};
use crate::solve::coupled::CoupledOde;

/// Most RK4 steps one reference run may take (each evaluates the loads four times).
pub const MAX_REFERENCE_STEPS: f64 = 2.0e7;

fn check_steps(steps: f64) -> Result<()> {
    if steps > MAX_REFERENCE_STEPS {
        return Err(WingbeatError::ResourceCap {
            field: "reference run (duration × sample rate × substeps)".into(),
            requested: format!("{} RK4 steps", crate::error::num(steps)),
            cap: format!("{} steps", crate::error::num(MAX_REFERENCE_STEPS)),
            why: "computing time of the nonlinear reference".into(),
        });
    }
    Ok(())
}

/// q(t_i) of every mode (total response, from the config's initial conditions) with the
/// unlinearised drag, RK4 with `substeps` steps per output sample.
pub fn simulate_nonlinear(
    cfg: &SimConfig,
    geom: &WingGeometry,
    substeps: usize,
) -> Result<Vec<Vec<f64>>> {
    cfg.validate()?;
    let n = cfg.modes.len();
    geom.validate(n)?;
    let wing = super::AeroWing::build(geom, &cfg.aero)?;
    let kin = cfg.kinematics.compile();
    let ode = AirOde::new(&kin, &cfg.modes, &wing, &cfg.aero)?;
    let ns = cfg.n_samples();
    check_steps(ns as f64 * substeps as f64)?;
    let dt = 1.0 / cfg.sample_rate_hz;
    let h = dt / substeps.max(1) as f64;
    let rhs = |t: f64, x: &[f64], out: &mut [f64]| {
        let s = kin.state(t);
        let sc = stiffness_coefficient(&s);
        let fs = FrameState::of(&s);
        let mut f = [0.0; crate::model::MAX_MODES];
        let f = &mut f[..n];
        wing.loads_nonlinear(&fs, ode.k, ode.rho_am, &x[n..], f);
        let mut raw = [0.0; crate::model::MAX_MODES];
        for k in 0..n {
            let m = &cfg.modes[k];
            let c = coefficients(m, &s);
            let w = m.omega();
            // Λ q − S M q and D q̇ on the left: move to the right.
            let mut mq = 0.0;
            for l in 0..n {
                mq += ode.mass[k * n + l] * x[l];
            }
            raw[k] = c.total_force() + f[k] - 2.0 * m.zeta * w * x[n + k] - w * w * x[k] + sc * mq;
        }
        for k in 0..n {
            out[k] = x[n + k];
            out[n + k] = (0..n).map(|l| ode.mass_inv[k * n + l] * raw[l]).sum();
        }
    };
    let mut x = vec![0.0; 2 * n];
    for k in 0..n {
        let ic = cfg.ic(k);
        x[k] = ic[0];
        x[n + k] = ic[1];
    }
    rk4_run(&rhs, &mut x, n, ns, dt, h)
}

/// A right-hand side x′ = rhs(t, x), written into the last argument.
type Rhs<'a> = dyn Fn(f64, &[f64], &mut [f64]) + 'a;

/// Classical RK4 from t = 0 with step `h`, recording q (first n entries of x) at t_i = i·dt.
fn rk4_run(
    rhs: &Rhs<'_>,
    x: &mut [f64],
    n: usize,
    ns: usize,
    dt: f64,
    h: f64,
) -> Result<Vec<Vec<f64>>> {
    let d = x.len();
    let sub = (dt / h).round().max(1.0) as usize;
    let h = dt / sub as f64;
    let mut out: Vec<Vec<f64>> = (0..n).map(|_| Vec::with_capacity(ns)).collect();
    let (mut k1, mut k2, mut k3, mut k4, mut y) = (
        vec![0.0; d],
        vec![0.0; d],
        vec![0.0; d],
        vec![0.0; d],
        vec![0.0; d],
    );
    for i in 0..ns {
        for k in 0..n {
            out[k].push(x[k]);
        }
        if i + 1 == ns {
            break;
        }
        for s in 0..sub {
            let t = i as f64 * dt + s as f64 * h;
            rhs(t, x, &mut k1);
            for j in 0..d {
                y[j] = x[j] + 0.5 * h * k1[j];
            }
            rhs(t + 0.5 * h, &y, &mut k2);
            for j in 0..d {
                y[j] = x[j] + 0.5 * h * k2[j];
            }
            rhs(t + 0.5 * h, &y, &mut k3);
            for j in 0..d {
                y[j] = x[j] + h * k3[j];
            }
            rhs(t + h, &y, &mut k4);
            for j in 0..d {
                x[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
            }
        }
        if x.iter().any(|v| !v.is_finite()) {
            return Err(WingbeatError::NonFinite {
                what: "RK4 reference".into(),
                detail: format!("the state overflowed at t = {} s", i as f64 * dt),
            });
        }
    }
    Ok(out)
}

/// The linearised coupled system `ode` stepped by classical RK4 (`substeps` per output
/// sample) from `x0`: q of forcing column `col` plus the free response, at t_i = i·dt.
pub fn rk4_linear<O: CoupledOde + ?Sized>(
    ode: &O,
    col: usize,
    x0: &[f64],
    dt: f64,
    ns: usize,
    substeps: usize,
) -> Result<Vec<Vec<f64>>> {
    let n = ode.n_modes();
    let nf = ode.n_forces();
    check_steps(ns as f64 * substeps as f64)?;
    let rhs = |t: f64, x: &[f64], out: &mut [f64]| {
        let (mut b, mut c, mut f) = (vec![0.0; n * n], vec![0.0; n * n], vec![0.0; n * nf]);
        ode.eval(t, &mut b, &mut c, &mut f);
        for k in 0..n {
            out[k] = x[n + k];
            let mut a = if nf > 0 { f[col * n + k] } else { 0.0 };
            for l in 0..n {
                a -= b[k * n + l] * x[l] + c[k * n + l] * x[n + l];
            }
            out[n + k] = a;
        }
    };
    let mut x = x0.to_vec();
    rk4_run(&rhs, &mut x, n, ns, dt, dt / substeps.max(1) as f64)
}
