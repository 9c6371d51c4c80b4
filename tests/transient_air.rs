//! Non-periodic runs in air (`wingbeat::aero::transient::run_in_air`): from rest under periodic
//! kinematics equal to the periodic air propagator (tabulated loads, period map) within 1e-10
//! of each response's peak; under the start-up ramp and disturbances equal to an independent
//! integrator (classical RK4 on the same 2N-state system, Richardson-extrapolated) within 1e-9;
//! the air's response differs from the vacuum's by the air's share; bad input named, the work
//! cap checked before the first step.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use std::sync::OnceLock;
use wingbeat::aero::nonlinear::rk4_linear;
use wingbeat::aero::ode::{AirOde, AERODYNAMIC, TOTAL};
use wingbeat::aero::transient::{run_in_air, MAX_AIR_PRODUCTS};
use wingbeat::aero::{AeroConfig, AeroWing, WingGeometry};
use wingbeat::config::SimConfig;
use wingbeat::disturbance::DisturbanceSpec;
use wingbeat::solve::coupled::{propagate_coupled, CoupledOde};
use wingbeat::transient::{self, BodyRateFrame, Disturbances, TransientKinematics};
use wingbeat::WingbeatError;

fn fe_wing() -> &'static SimConfig {
    static C: OnceLock<SimConfig> = OnceLock::new();
    C.get_or_init(|| SimConfig::fe_wing().expect("the FE wing preset solves"))
}

/// Air with a coarse quadrature: these tests check the time stepping, not the quadrature.
fn coarse_air() -> AeroConfig {
    AeroConfig {
        strips: 8,
        chord_points: 3,
        ..AeroConfig::with_density(1.2)
    }
}

fn peak(x: &[f64]) -> f64 {
    x.iter().fold(0.0_f64, |m, v| m.max(v.abs()))
}

fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
}

#[test]
fn from_rest_under_periodic_kinematics_it_is_the_periodic_air_propagator() {
    let cfg = fe_wing();
    let geom = cfg.wing.as_deref().expect("the FE wing carries its mesh");
    let aero = coarse_air();
    let (duration, dt) = (0.08, 1e-4);
    let tk = TransientKinematics::periodic(cfg.kinematics.clone());
    let kin = tk.compile().unwrap();
    let run = run_in_air(&kin, &cfg.modes, geom, &aero, duration, dt).unwrap();
    // The periodic path: tabulated loads, the period map reused.
    let wing = AeroWing::build(geom, &aero).unwrap();
    let periodic = cfg.kinematics.compile();
    let mut ode = AirOde::new(&periodic, &cfg.modes, &wing, &aero).unwrap();
    ode.tabulate();
    let n = cfg.modes.len();
    let ns = run.t.len();
    let pr = propagate_coupled(&ode, dt, ns, TOTAL, &vec![0.0; 2 * n], &[]).unwrap();
    for k in 0..n {
        let cases: [(&str, &[f64], &[f64]); 5] = [
            ("Euler", &run.q[k][0], &pr.q[0][k]),
            ("centrifugal", &run.q[k][1], &pr.q[1][k]),
            ("Coriolis", &run.q[k][2], &pr.q[2][k]),
            ("aerodynamic", &run.aerodynamic[k], &pr.q[AERODYNAMIC][k]),
            ("total", &run.q[k][3], &pr.total[k]),
        ];
        for (name, ours, theirs) in cases {
            let d = max_diff(ours, theirs);
            println!("mode {k} {name}: {:.2e} of its peak", d / peak(theirs));
            assert!(peak(theirs) > 0.0);
            assert!(
                d <= 1e-10 * peak(theirs),
                "mode {k} {name}: {:e} of its peak",
                d / peak(theirs)
            );
        }
    }
}

/// The published kind of run on the FE wing: ramp, a body rate in wing axes, disturbances on
/// the flapping and the rotation.
fn disturbed() -> TransientKinematics {
    TransientKinematics {
        flapping: fe_wing().kinematics.clone(),
        startup_ramp: true,
        body_rate_rad_s: [0.0, 0.0, 10.0],
        body_rate_frame: BodyRateFrame::Wing,
        disturbances: Disturbances {
            beta: Some(DisturbanceSpec::published(0.312, 7)),
            body_z: Some(DisturbanceSpec::published(0.1, 8)),
            ..Default::default()
        },
    }
}

#[test]
fn under_ramp_and_disturbances_it_agrees_with_rk4() {
    let cfg = fe_wing();
    let geom = cfg.wing.as_deref().unwrap();
    let aero = coarse_air();
    let (duration, dt) = (0.06, 1e-4);
    let kin = disturbed().compile().unwrap();
    let run = run_in_air(&kin, &cfg.modes, geom, &aero, duration, dt).unwrap();
    let wing = AeroWing::build(geom, &aero).unwrap();
    let ode = AirOde::new_transient(&kin, &cfg.modes, &wing, &aero, duration).unwrap();
    let n = ode.n_modes();
    let ns = run.t.len();
    for (col, name) in [(AERODYNAMIC, "aerodynamic"), (TOTAL, "total")] {
        let rk = |sub| rk4_linear(&ode, col, &vec![0.0; 2 * n], dt, ns, sub).unwrap();
        let (a, b) = (rk(20), rk(40));
        for k in 0..n {
            let ours = if col == TOTAL {
                &run.q[k][3]
            } else {
                &run.aerodynamic[k]
            };
            // Richardson: order 4 → 6.
            let reference: Vec<f64> = a[k]
                .iter()
                .zip(&b[k])
                .map(|(a, b)| b + (b - a) / 15.0)
                .collect();
            let d = max_diff(ours, &reference);
            println!("{name} mode {k}: {:.2e} of its peak", d / peak(ours));
            assert!(peak(ours) > 0.0);
            assert!(
                d <= 1e-9 * peak(ours),
                "{name} mode {k}: {:e} of its peak",
                d / peak(ours)
            );
        }
    }
    // Air changes the answer: the vacuum run of the same kinematics differs by more than the
    // air's own share would allow to be rounding.
    let vac = transient::run(&kin, &cfg.modes, duration, dt).unwrap();
    let d = max_diff(&vac.q[0][3], &run.q[0][3]);
    assert!(
        d > 1e-3 * peak(&vac.q[0][3]),
        "air and vacuum differ by only {d:e}"
    );
    assert!(vac.aerodynamic.is_empty());
}

#[test]
fn bad_input_is_named_and_the_work_is_capped_first() {
    let cfg = fe_wing();
    let geom = cfg.wing.as_deref().unwrap();
    let kin = disturbed().compile().unwrap();
    let e = run_in_air(&kin, &cfg.modes, geom, &AeroConfig::default(), 0.01, 1e-4).unwrap_err();
    assert!(e.to_string().contains("aero.air_density_kg_m3"), "{e}");
    let no_shapes = WingGeometry {
        shapes: vec![],
        ..geom.clone()
    };
    let e = run_in_air(&kin, &cfg.modes, &no_shapes, &coarse_air(), 0.01, 1e-4).unwrap_err();
    assert!(e.to_string().contains("wing.shapes"), "{e}");
    // A long run at the full quadrature: refused by the cap before any step is taken.
    let t0 = std::time::Instant::now();
    let e = run_in_air(
        &kin,
        &cfg.modes,
        geom,
        &AeroConfig::with_density(1.2),
        1500.0,
        1e-3,
    )
    .unwrap_err();
    assert!(matches!(e, WingbeatError::ResourceCap { .. }), "{e}");
    assert!(
        e.to_string().contains(&format!("{MAX_AIR_PRODUCTS:e}")),
        "{e}"
    );
    assert!(t0.elapsed().as_secs_f64() < 5.0, "refused before the run");
}
