//! Simulating the wing in air: the driver that propagates the coupled system ([`AirOde`],
//! [`super::ode`]) and turns its responses into the same [`SimResult`] the vacuum path returns
//! (plus the per-mode `air` block and the run's `air` summary, whose types live with the
//! run's result in [`crate::run`]). [`crate::simulate::simulate`] calls [`simulate_in_air`]
//! when the density is above 0; this module never calls back into it.

use super::floquet::{analyse_coupled, FloquetGrid};
pub use super::ode::{AirOde, AERODYNAMIC, CENTRIFUGAL, CORIOLIS, EULER, TOTAL};
use super::ode::{TABLE_FIRST_PANELS, TABLE_NODES};
use super::{AeroWing, WingGeometry};
use crate::analysis::contribution::contributions_with_aero;
use crate::config::SimConfig;
use crate::error::{Result, WingbeatError};
use crate::model::Mode;
use crate::run::{assemble, Accuracy, ModeResult, Responses, SimResult, MAX_RUN_WORK};
pub use crate::run::{AirSummary, ModeAir};
use crate::solve::coupled::{coupled_steps_per_span, propagate_coupled, CoupledOde};
use crate::solve::ModalOde;
use std::f64::consts::PI;

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

/// Estimated cost of an air run in step equivalents (as [`crate::simulate::run_cost`]; one
/// unit is about 1 µs natively), counted in multiply-adds at [`AIR_PRODUCTS_PER_UNIT`] per
/// unit:
/// - the load table ([`super::ode::LoadTable`]): [`TABLE_NODES`] load evaluations for each
///   of eight times its first panels (allowing for the halving where the loads change fast:
///   the paper's kinematics take 1.1 times, a steady body roll rate of 3 rad/s 8 times),
///   every one N + N(N+1)/2 + 20 products per quadrature point;
/// - the Gauss steps: one period by the coupled rule ([`coupled_steps_per_span`]) plus one
///   step per output phase and per Floquet phase (checkpoints split steps), and half as many
///   again for the error estimate; per step four table reads, the 4N LU with its 2N + 5
///   right-hand sides and the composition of the step's affine map;
/// - the output: per sample and mode Φ(τ) applied to the six period-start states, and the
///   rest of the result (contributions, strain), 0.2 unit per sample and mode as in a vacuum.
pub fn air_run_cost(cfg: &SimConfig, wing_points: usize) -> f64 {
    let kin = cfg.kinematics.compile();
    let n = cfg.modes.len() as f64;
    let w = cfg.modes.iter().map(Mode::omega).fold(0.0, f64::max);
    let h = ModalOde::new(&kin, &cfg.modes[0]).max_harmonic;
    let t = 2.0 * PI / kin.wd;
    let wmax = w.max(4.0 * h * kin.wd);
    let steps = coupled_steps_per_span(wmax, t);
    let samples = cfg.duration_s * cfg.sample_rate_hz + 1.0;
    // Distinct output phases per period: T/dt on a commensurate grid, else every sample.
    let per_period = t * cfg.sample_rate_hz;
    let phases = if (per_period.round() - per_period).abs() <= 1e-9 * per_period {
        per_period.round().min(samples)
    } else {
        samples
    };
    let floquet = (4.0 * wmax * t / (2.0 * PI) + 16.0).clamp(32.0, 16384.0);
    let width = n + n * (n + 1.0) / 2.0;
    let table =
        4.0 * TABLE_FIRST_PANELS as f64 * TABLE_NODES as f64 * wing_points as f64 * (width + 20.0);
    let s = 4.0 * n;
    let ncol = 2.0 * n + 5.0;
    let per_step = 4.0 * (3.0 * width * TABLE_NODES as f64 + 10.0 * n * n + 60.0)
        + (2.0 / 3.0) * s * s * s
        + 2.0 * s * s * ncol
        + 4.0 * n * n * ncol;
    let all_steps = 1.5 * steps + phases + floquet;
    let output = samples * n * 18.0 * n;
    (table + all_steps * per_step + output) / AIR_PRODUCTS_PER_UNIT + samples * n * 0.2
}

/// Multiply-adds per step equivalent in [`air_run_cost`] (about 1 µs natively). Measured on
/// the FE wing in air (2026-12-02, load 1–3): 2 s at 10 kHz 25.5e3 units against 13–16 ms;
/// 0.5 s 12.6e3 against 11 ms; 0.5 s with a steady body roll rate 12.6e3 against 18 ms (its
/// load table halves its panels more); 0.3 s at the incommensurate 25.5 Hz (a checkpoint per
/// sample) 18.7e3 against 19 ms.
pub const AIR_PRODUCTS_PER_UNIT: f64 = 5000.0;

/// Runs `cfg` in its medium (`cfg.aero`, density > 0) on the wing `geom`.
pub fn simulate_in_air(cfg: &SimConfig, geom: &WingGeometry) -> Result<SimResult> {
    let n = cfg.modes.len();
    geom.validate(n)?;
    cfg.aero.validate()?;
    let wing = AeroWing::build(geom, &cfg.aero)?;
    let cost = air_run_cost(cfg, wing.points.len());
    if cost > MAX_RUN_WORK {
        return Err(WingbeatError::ResourceCap {
            field: "simulate in air (modes² × quadrature points × steps per flap period)".into(),
            requested: format!("{} step equivalents", crate::error::num(cost.round())),
            cap: format!("{} step equivalents", crate::error::num(MAX_RUN_WORK)),
            why: "computing time; fewer modes, fewer `aero.strips` / `aero.chord_points`, or a higher flap frequency".into(),
        });
    }
    let kin = cfg.kinematics.compile();
    let mut ode = AirOde::new(&kin, &cfg.modes, &wing, &cfg.aero)?;
    ode.tabulate();
    let ns = cfg.n_samples();
    let dt = 1.0 / cfg.sample_rate_hz;
    let mut x0 = vec![0.0; 2 * n];
    for k in 0..n {
        let ic = cfg.ic(k);
        x0[k] = ic[0];
        x0[n + k] = ic[1];
    }
    // Output samples per flap period when they repeat on the same phases.
    let per_period = ode.period() / dt;
    let commensurate = (per_period.round() - per_period).abs() <= 1e-12 * per_period
        && per_period.round() >= 1.0
        && ns as f64 >= per_period.round();
    let grid = FloquetGrid::new(&ode, commensurate.then_some(per_period.round() as usize));
    let mut pr = propagate_coupled(&ode, dt, ns, TOTAL, &x0, &grid.checkpoints())?;
    let fl = analyse_coupled(
        &ode,
        &pr.monodromy,
        cfg.kinematics.flap_freq_hz,
        &grid,
        &pr.extra_phi,
    )?;
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
        let beat = beat_fate(decay_time, f.floquet.beat_period_s);
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
    Ok(assemble(cfg, t_axis, modes, Some(summary)))
}

/// `v` rounded to `sig` significant digits (for messages).
/// What happens to a mode's beat in air, in words: whether its free vibration (time constant
/// `decay_time`, s) outlives the beat period (s); `None` periods and times as in [`ModeAir`].
fn beat_fate(decay_time: Option<f64>, beat_period_s: Option<f64>) -> String {
    match (decay_time, beat_period_s) {
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
    }
}

fn round_sig(v: f64, sig: i32) -> f64 {
    if v == 0.0 || !v.is_finite() {
        return v;
    }
    let e = v.abs().log10().floor() as i32;
    let f = 10f64.powi(sig - 1 - e);
    (v * f).round() / f
}
