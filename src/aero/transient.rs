//! Non-periodic runs in a fluid ([`crate::transient`]'s kinematics, the air's loads of
//! [`super::ode`]): the coupled 2N-state system of every mode stepped from rest with the
//! propagator's order-8 Gauss–Legendre step at the coupled ω·h rule
//! ([`crate::solve::coupled::step_from_rest`]), the loads summed over the quadrature at every
//! stage (nothing repeats, so there is no load table). In a vacuum it is the same as
//! [`crate::transient::run`] (checked in `tests/transient_air.rs`).

use super::ode::{AirOde, AERODYNAMIC, CENTRIFUGAL, CORIOLIS, EULER, TOTAL};
use super::{AeroConfig, AeroWing, WingGeometry};
use crate::model::Mode;
use crate::solve::coupled::{coupled_omega_h, step_from_rest, CoupledOde};
use crate::transient::{check_modes, check_run_cost, CompiledTransient, TransientRun};
use crate::{Result, WingbeatError};

/// Most multiply-adds of one run in a fluid: about 90 s natively (measured 2026-12-02: the
/// published plate's 4 s run in air, 8 modes, 288 quadrature points, 20 Gauss steps per ms,
/// is 1.1e10 by [`air_run_products`] and takes 5.1 s).
pub const MAX_AIR_PRODUCTS: f64 = 2e11;

/// Gauss steps per output interval `dt` for `ode`: the coupled rule's ω·h at its highest
/// frequency, the error target holding per flap period (as the periodic air run's).
pub fn air_steps_per_sample(ode: &AirOde<'_>, dt: f64, duration_s: f64) -> usize {
    let w = ode.freq_scale().max(1e-300);
    let span = ode.period().min(duration_s);
    let h = coupled_omega_h(w, span) / w;
    ((dt / h).ceil() as usize).max(1)
}

/// Multiply-adds of a run of `steps` Gauss steps with `n` modes on `points` quadrature points:
/// per step four load evaluations (N + N(N+1)/2 + 20 products per point), the 4N stage LU with
/// its 2N + 5 right-hand sides, and the state update.
pub fn air_run_products(steps: f64, n: usize, points: usize) -> f64 {
    let n = n as f64;
    let width = n + n * (n + 1.0) / 2.0;
    let s = 4.0 * n;
    let ncol = 2.0 * n + 5.0;
    steps
        * (4.0 * points as f64 * (width + 20.0)
            + 4.0 * 10.0 * n * n
            + (2.0 / 3.0) * s * s * s
            + 2.0 * s * s * ncol
            + 10.0 * n * n)
}

/// Steps every mode from rest in the fluid `aero` (density > 0) on the wing `geom` under the
/// non-periodic kinematics `kin`, sampling every `dt_s` over `duration_s`. Columns of `q` as in
/// a vacuum (Euler, centrifugal, Coriolis, total, the total now including the air's force);
/// the response to the aerodynamic force alone in `aerodynamic`. Sizes and the work cap are
/// checked before the first step.
pub fn run_in_air(
    kin: &CompiledTransient,
    modes: &[Mode],
    geom: &WingGeometry,
    aero: &AeroConfig,
    duration_s: f64,
    dt_s: f64,
) -> Result<TransientRun> {
    check_modes(modes)?;
    aero.validate()?;
    if aero.is_vacuum() {
        return Err(WingbeatError::invalid(
            "aero.air_density_kg_m3",
            aero.air_density_kg_m3,
            "above 0 for a run in a fluid (0 is the vacuum run, transient::run)",
        ));
    }
    geom.validate(modes.len())?;
    // Sample count and the vacuum rule's step cap first (cheap), then the fluid's own cost.
    let (n, _) = check_run_cost(kin, modes, duration_s, dt_s)?;
    let wing = AeroWing::build(geom, aero)?;
    let ode = AirOde::new_transient(kin, modes, &wing, aero, duration_s)?;
    let m = air_steps_per_sample(&ode, dt_s, duration_s);
    let products = air_run_products((n - 1) as f64 * m as f64, modes.len(), wing.points.len());
    if products > MAX_AIR_PRODUCTS {
        return Err(WingbeatError::ResourceCap {
            field: "duration_s (a run in a fluid)".into(),
            requested: format!("{products:.3e} multiply-adds"),
            cap: format!("{MAX_AIR_PRODUCTS:e} multiply-adds"),
            why: "run time; shorten the run, use fewer modes or fewer aero.strips / aero.chord_points".into(),
        });
    }
    let nm = modes.len();
    let d = 2 * nm;
    let cols = [EULER, CENTRIFUGAL, CORIOLIS, TOTAL];
    let mut q: Vec<[Vec<f64>; 4]> = (0..nm)
        .map(|_| std::array::from_fn(|_| Vec::with_capacity(n)))
        .collect();
    let mut aerodynamic: Vec<Vec<f64>> = (0..nm).map(|_| Vec::with_capacity(n)).collect();
    step_from_rest(&ode, dt_s, n - 1, m, |_, x| {
        for k in 0..nm {
            for (slot, &j) in cols.iter().enumerate() {
                q[k][slot].push(x[j * d + k]);
            }
            aerodynamic[k].push(x[AERODYNAMIC * d + k]);
        }
    })?;
    Ok(TransientRun {
        t: (0..n).map(|i| i as f64 * dt_s).collect(),
        q,
        steps_per_sample: m,
        aerodynamic,
    })
}
