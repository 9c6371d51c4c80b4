//! Non-periodic runs of Eq. 13 (`wingbeat::transient`): the direct time stepping against the
//! periodic propagator where both apply, against the classical Runge–Kutta method under a
//! start-up ramp and disturbances, the kinematics against finite differences and closed forms,
//! and bad input named.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::disturbance::{Disturbance, DisturbanceSpec};
use wingbeat::kinematics::{Angle, Harmonic, Kinematics, RateState};
use wingbeat::model::{coefficients, Mode};
use wingbeat::simulate::propagate_mode;
use wingbeat::solve::{rk4, LinearOde};
use wingbeat::transient::{
    run, startup_ramp, BodyRateFrame, CompiledTransient, Disturbances, TransientKinematics,
};
use wingbeat::WingbeatError;

fn mode(freq_hz: f64, zeta: f64, a: [f64; 2]) -> Mode {
    Mode {
        name: format!("{freq_hz} Hz"),
        freq_hz,
        a,
        zeta,
        strains: vec![],
    }
}

fn peak(x: &[f64]) -> f64 {
    x.iter().fold(0.0_f64, |m, v| m.max(v.abs()))
}

/// The published flapping in wingbeat's angles: β = −15°·[sin(ω_d t) + 0.2 sin(2ω_d t)].
fn published_flapping() -> Kinematics {
    let deg = std::f64::consts::PI / 180.0;
    Kinematics {
        flap_freq_hz: 25.0,
        alpha: Angle::constant(0.0),
        beta: Angle::Fourier {
            mean: 0.0,
            harmonics: vec![
                Harmonic {
                    n: 1,
                    amplitude: -15.0 * deg,
                    phase: 0.0,
                },
                Harmonic {
                    n: 2,
                    amplitude: -3.0 * deg,
                    phase: 0.0,
                },
            ],
        },
        gamma: Angle::constant(0.0),
        body_rate: Default::default(),
    }
}

fn disturbed(frame: BodyRateFrame) -> TransientKinematics {
    TransientKinematics {
        flapping: Kinematics {
            alpha: Angle::sine(0.4),
            gamma: Angle::sine(0.1),
            ..published_flapping()
        },
        startup_ramp: true,
        body_rate_rad_s: [1.0, -2.0, 10.0],
        body_rate_frame: frame,
        disturbances: Disturbances {
            beta: Some(DisturbanceSpec::published(0.312, 7)),
            body_z: Some(DisturbanceSpec::published(0.1, 8)),
            gamma: Some(DisturbanceSpec::published(0.05, 9)),
            ..Default::default()
        },
    }
}

#[test]
fn without_ramp_or_disturbance_it_is_the_periodic_propagator() {
    // The paper's kinematics with a constant body rate in body axes: periodic, so the period
    // propagator applies; both start from rest.
    let kin = Kinematics::paper_forward_flight().with_body_rate([0.3, -0.2, 1.5]);
    let mut tk = TransientKinematics::periodic(Kinematics::paper_forward_flight());
    tk.body_rate_rad_s = [0.3, -0.2, 1.5];
    let ct = tk.compile().unwrap();
    let modes = [
        mode(13.5, 0.05, [2e-3, -1e-3]),
        mode(62.5, 0.02, [4e-4, 9e-4]),
    ];
    let (dt, n) = (1e-3, 501);
    let tr = run(&ct, &modes, (n - 1) as f64 * dt, dt).unwrap();
    assert_eq!(tr.t.len(), n);
    let compiled = kin.compile();
    for (k, m) in modes.iter().enumerate() {
        let p = propagate_mode(&compiled, m, dt, n).unwrap();
        for j in 0..4 {
            let scale = peak(&p.q[j]);
            assert!(scale > 0.0);
            let err = tr.q[k][j]
                .iter()
                .zip(&p.q[j])
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            assert!(
                err <= 1e-10 * scale,
                "mode {k} column {j}: {err:e} of {scale:e}"
            );
        }
    }
}

/// Eq. 13 of one mode under non-periodic kinematics, for the independent integrator.
struct Ode<'a> {
    kin: &'a CompiledTransient,
    mode: &'a Mode,
}

impl LinearOde for Ode<'_> {
    fn n_forces(&self) -> usize {
        4
    }
    fn damping(&self) -> f64 {
        2.0 * self.mode.zeta * self.mode.omega()
    }
    fn eval(&self, t: f64, f: &mut [f64]) -> f64 {
        let c = coefficients(self.mode, &self.kin.state(t));
        f.copy_from_slice(&[c.euler, c.centrifugal, c.coriolis, c.total_force()]);
        c.stiffness
    }
    fn period(&self) -> f64 {
        1.0
    }
    fn freq_scale(&self) -> f64 {
        self.mode.omega()
    }
}

#[test]
fn ramped_disturbed_run_agrees_with_runge_kutta() {
    for frame in [BodyRateFrame::Body, BodyRateFrame::Wing] {
        let ct = disturbed(frame).compile().unwrap();
        let modes = [
            mode(13.5, 0.37, [3e-3, -1e-3]),
            mode(57.0, 0.09, [5e-4, 2e-3]),
        ];
        let (dt, n) = (1e-3, 301);
        let tr = run(&ct, &modes, (n - 1) as f64 * dt, dt).unwrap();
        for (k, m) in modes.iter().enumerate() {
            let reference = rk4::solve(&Ode { kin: &ct, mode: m }, 0.0, 0.0, dt, n, 400);
            for (j, (want, _)) in reference.iter().enumerate() {
                let scale = peak(want);
                assert!(scale > 0.0, "{frame:?} mode {k} column {j} is zero");
                let err = tr.q[k][j]
                    .iter()
                    .zip(want)
                    .map(|(a, b)| (a - b).abs())
                    .fold(0.0, f64::max);
                assert!(
                    err <= 1e-9 * scale,
                    "{frame:?} mode {k} column {j}: {err:e} of {scale:e}"
                );
            }
        }
    }
}

fn wing_rate(s: &RateState) -> [f64; 3] {
    let (sb, cb) = s.beta.sin_cos();
    [s.alpha_dot * cb, s.beta_dot, s.alpha_dot * sb]
}

#[test]
fn kinematics_follow_the_ramp_and_disturbances() {
    let spec = disturbed(BodyRateFrame::Wing);
    let ct = spec.compile().unwrap();
    let db = Disturbance::new(&DisturbanceSpec::published(0.312, 7)).unwrap();
    let dz = Disturbance::new(&DisturbanceSpec::published(0.1, 8)).unwrap();
    let flap = spec.flapping.compile();
    let wd = flap.wd;
    for &t in &[0.003, 0.021, 0.05, 0.137, 0.6, 2.9] {
        let s = ct.state(t);
        // σ from its formula, its derivatives from the closed form checked by differences.
        let u = wd * t;
        let sig = u.powi(3) / (10.0 + u.powi(3));
        let (r, rd, rdd) = startup_ramp(t, wd);
        assert!((r - sig).abs() < 1e-15);
        let e = 1e-6;
        let fd1 = (startup_ramp(t + e, wd).0 - startup_ramp(t - e, wd).0) / (2.0 * e);
        let fd2 = (startup_ramp(t + e, wd).1 - startup_ramp(t - e, wd).1) / (2.0 * e);
        assert!((rd - fd1).abs() <= 1e-6 * rd.abs().max(1.0), "σ′ at {t}");
        assert!((rdd - fd2).abs() <= 1e-5 * rdd.abs().max(1.0), "σ″ at {t}");
        // β is the ramped flapping plus the disturbance's angle.
        let b = flap.state(t).beta;
        assert!((s.beta - (b * sig + db.angle(t))).abs() < 1e-13, "β at {t}");
        // Angle derivatives against central differences of the state itself.
        let (p, m) = (ct.state(t + e), ct.state(t - e));
        for (v, d, dd, vp, vm, dp, dm) in [
            (
                s.alpha,
                s.alpha_dot,
                s.alpha_ddot,
                p.alpha,
                m.alpha,
                p.alpha_dot,
                m.alpha_dot,
            ),
            (
                s.beta,
                s.beta_dot,
                s.beta_ddot,
                p.beta,
                m.beta,
                p.beta_dot,
                m.beta_dot,
            ),
            (
                s.gamma,
                s.gamma_dot,
                s.gamma_ddot,
                p.gamma,
                m.gamma,
                p.gamma_dot,
                m.gamma_dot,
            ),
        ] {
            let _ = v;
            assert!((d - (vp - vm) / (2.0 * e)).abs() <= 1e-6 * d.abs().max(1.0));
            assert!((dd - (dp - dm) / (2.0 * e)).abs() <= 1e-5 * dd.abs().max(1.0));
        }
        // In the wing frame the body rate is added unchanged: Ω − Ω_wing = w (σ + t σ′) + d(t).
        let f = sig + t * rd;
        let want = [1.0 * f, -2.0 * f, 10.0 * f + dz.rate(t)];
        let om = s.omega();
        let ww = wing_rate(&s);
        for i in 0..3 {
            assert!(
                (om[i] - ww[i] - want[i]).abs() < 1e-12,
                "Ω[{i}] at {t}: {} vs {}",
                om[i] - ww[i],
                want[i]
            );
        }
        // Ω̇ is the derivative of Ω.
        let (op, omn) = (p.omega(), m.omega());
        let od = s.omega_dot();
        for i in 0..3 {
            let fd = (op[i] - omn[i]) / (2.0 * e);
            assert!(
                (od[i] - fd).abs() <= 1e-5 * od[i].abs().max(1.0),
                "Ω̇[{i}] at {t}: {} vs {fd}",
                od[i]
            );
        }
    }
    // In body axes the same rate is turned by Rᵀ: its K component differs by O(1 − cos β).
    let body = disturbed(BodyRateFrame::Body).compile().unwrap();
    let s = body.state(0.31);
    assert!((s.omega()[2] - ct.state(0.31).omega()[2]).abs() > 1e-3);
}

#[test]
fn bad_input_is_named() {
    let err = |tk: &TransientKinematics| match tk.validate() {
        Err(WingbeatError::InvalidInput { field, .. }) => field,
        other => panic!("expected an invalid-input error, got {other:?}"),
    };
    let mut tk = disturbed(BodyRateFrame::Wing);
    tk.body_rate_rad_s[2] = f64::NAN;
    assert_eq!(err(&tk), "body_rate_rad_s[2]");
    let mut tk = disturbed(BodyRateFrame::Wing);
    tk.disturbances.beta.as_mut().unwrap().sines = 0;
    assert_eq!(err(&tk), "disturbances.beta.sines");
    let mut tk = disturbed(BodyRateFrame::Wing);
    tk.disturbances.body_z.as_mut().unwrap().f_max_hz = -1.0;
    assert_eq!(err(&tk), "disturbances.body_z.f_max_hz");
    let mut tk = disturbed(BodyRateFrame::Wing);
    tk.flapping.body_rate = wingbeat::kinematics::BodyRate::constant([0.0, 0.0, 1.0]);
    assert_eq!(err(&tk), "kinematics.body_rate");
    let mut tk = disturbed(BodyRateFrame::Wing);
    tk.flapping.flap_freq_hz = f64::INFINITY;
    assert_eq!(err(&tk), "kinematics.flap_freq_hz");

    let ct = disturbed(BodyRateFrame::Wing).compile().unwrap();
    let m = [mode(50.0, 0.1, [1e-3, 1e-3])];
    for (d, dt, field) in [
        (f64::NAN, 1e-3, "duration_s"),
        (1.0, 0.0, "sample_step_s"),
        (1.0, 2.0, "sample_step_s"),
        (-1.0, 1e-3, "duration_s"),
    ] {
        match run(&ct, &m, d, dt) {
            Err(WingbeatError::InvalidInput { field: f, .. }) => assert_eq!(f, field),
            other => panic!("{d} {dt}: {other:?}"),
        }
    }
    // A run over the caps is refused before any step is taken.
    match run(&ct, &m, 1e4, 1e-7) {
        Err(WingbeatError::ResourceCap { field, .. }) => {
            assert_eq!(field, "duration_s / sample_step_s");
        }
        other => panic!("{other:?}"),
    }
    match run(&ct, &[mode(5e4, 0.01, [1e-3, 0.0])], 1e3, 1e-2) {
        Err(WingbeatError::ResourceCap { field, .. }) => assert_eq!(field, "duration_s"),
        other => panic!("{other:?}"),
    }
    assert!(run(&ct, &[], 1.0, 1e-3).is_err());
}

/// The run's stepped disturbances (`StageClock`: phasors turned by one step at a time, exact
/// again every `ANCHOR_EVERY` steps) against the state computed from sines at every stage time:
/// after a full stretch of steps every angle, rate and body rate still agrees to a few ε of its
/// size, and a wrong rotation (the step taken twice) would be off by far more.
#[test]
fn stepped_disturbances_stay_on_the_exact_state() {
    use wingbeat::solve::gauss::Tableau;
    use wingbeat::transient::StageClock;
    let kin = disturbed(BodyRateFrame::Wing).compile().unwrap();
    let c = Tableau::new().c;
    let (t0, h) = (0.37, 2.3e-5);
    let mut clock = StageClock::new(&kin, &c, t0, h);
    let fields = |s: &RateState| {
        let mut v = vec![
            s.alpha,
            s.alpha_dot,
            s.alpha_ddot,
            s.beta,
            s.beta_dot,
            s.beta_ddot,
        ];
        v.extend(s.body_rate);
        v.extend(s.body_rate_dot);
        v
    };
    let mut worst = 0.0_f64;
    for k in 0..StageClock::ANCHOR_EVERY {
        let t = t0 + k as f64 * h;
        for (l, cl) in c.iter().enumerate() {
            let (a, b) = (
                fields(&kin.state_clocked(t + cl * h, &clock, l)),
                fields(&kin.state(t + cl * h)),
            );
            for (x, y) in a.iter().zip(&b) {
                worst = worst.max((x - y).abs() / y.abs().max(1e-3));
            }
        }
        clock.advance();
    }
    assert!(worst < 1e-12, "stepped state off by {worst:e}");
    // Re-anchored, it is exact again; advanced twice per step it is not.
    let t = t0 + StageClock::ANCHOR_EVERY as f64 * h;
    clock.anchor(&kin, &c, t, h);
    let exact = |cl: f64| fields(&kin.state(t + cl * h));
    assert_eq!(
        fields(&kin.state_clocked(t + c[2] * h, &clock, 2)),
        exact(c[2])
    );
    clock.advance();
    clock.advance();
    let off = fields(&kin.state_clocked(t + h + c[2] * h, &clock, 2))
        .iter()
        .zip(exact(c[2] + 1.0))
        .map(|(x, y)| (x - y).abs() / y.abs().max(1e-3))
        .fold(0.0, f64::max);
    assert!(off > 1e-9, "a doubled step went unnoticed ({off:e})");
}
