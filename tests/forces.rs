//! The Eq. 13 force terms against a first-principles computation: the out-of-plane inertial
//! force −[Ω̇×r + Ω×(Ω×r) + 2Ω×ṙ_rel]·K″ on point masses, projected on a mode shape.
//! Each term is checked separately, so a sign error in any one of them fails.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use nalgebra::Vector3;
use wingbeat::kinematics::{Angle, Harmonic, Kinematics, RateState};
use wingbeat::model::{coefficients, stiffness_coefficient, Mode};

/// A point mass: (x m, y m, mode-shape value φ, mass kg).
type Point = (f64, f64, f64, f64);

/// A "wing" of point masses with mode-shape values: returns (a, list of (x, y, φ, m)).
fn wing() -> ([f64; 2], Vec<Point>) {
    let pts: Vec<Point> = (0..40)
        .map(|i| {
            let x = 0.001 + 0.045 * (i % 8) as f64 / 7.0;
            let y = -0.002 - 0.02 * (i / 8) as f64 / 4.0;
            let phi = 3.0 * x * x / 0.002 + 0.7 * y * x / 0.001; // bending + twist
            let m = 1e-6 * (1.0 + 0.1 * (i % 3) as f64);
            (x, y, phi, m)
        })
        .collect();
    let a = pts.iter().fold([0.0, 0.0], |a, &(x, y, p, m)| {
        [a[0] + p * x * m, a[1] + p * y * m]
    });
    (a, pts)
}

fn first_principles(s: &RateState, pts: &[Point]) -> (f64, f64, f64) {
    let om = Vector3::from(s.omega());
    let omd = Vector3::from(s.omega_dot());
    let (mut e, mut c, mut r) = (0.0, 0.0, 0.0);
    for &(x, y, phi, m) in pts {
        // Position with small yaw, and the yaw's relative velocity, in the rotating frame.
        let pos = Vector3::new(x - s.gamma * y, y + s.gamma * x, 0.0);
        let vrel = Vector3::new(-s.gamma_dot * y, s.gamma_dot * x, 0.0);
        e += -omd.cross(&pos)[2] * phi * m;
        c += -om.cross(&om.cross(&pos))[2] * phi * m;
        r += -2.0 * om.cross(&vrel)[2] * phi * m;
    }
    (e, c, r)
}

#[test]
fn force_terms_match_rigid_body_inertial_forces() {
    let (a, pts) = wing();
    let mode = Mode {
        name: "t".into(),
        freq_hz: 60.0,
        a,
        zeta: 0.0,
        strains: vec![],
    };
    let k = Kinematics {
        flap_freq_hz: 25.0,
        alpha: Angle::Fourier {
            mean: 0.2,
            harmonics: vec![
                Harmonic {
                    n: 1,
                    amplitude: 0.8,
                    phase: 0.0,
                },
                Harmonic {
                    n: 2,
                    amplitude: 0.05,
                    phase: 0.5,
                },
            ],
        },
        beta: Angle::Fourier {
            mean: 0.1,
            harmonics: vec![Harmonic {
                n: 1,
                amplitude: 0.5,
                phase: 0.7,
            }],
        },
        gamma: Angle::Fourier {
            mean: 0.0,
            harmonics: vec![Harmonic {
                n: 1,
                amplitude: 0.2,
                phase: -0.4,
            }],
        },
        body_rate: Default::default(),
    };
    let c = k.compile();
    let mut worst = 0.0_f64;
    for j in 0..64 {
        let s = c.state(j as f64 * 0.04 / 64.0);
        let co = coefficients(&mode, &s);
        let (e, cf, r) = first_principles(&s, &pts);
        let scale = e.abs().max(cf.abs()).max(r.abs()).max(1e-30);
        for (got, want, name) in [
            (co.euler, e, "Euler"),
            (co.centrifugal, cf, "centrifugal"),
            (co.coriolis, r, "Coriolis"),
        ] {
            let err = (got - want).abs() / scale;
            worst = worst.max(err);
            assert!(
                err < 1e-12,
                "{name} at sample {j}: Eq. 13 gives {got:e}, first principles {want:e}"
            );
        }
        // The K″ part of −Ω×(Ω×W K″) is (Ω_x² + Ω_y²) W: the softening in the stiffness.
        let om = s.omega();
        let kz = Vector3::new(0.0, 0.0, 1.0);
        let om3 = Vector3::from(om);
        let soft = om3.cross(&om3.cross(&kz))[2];
        assert!(
            (-soft - stiffness_coefficient(&s)).abs() < 1e-12 * stiffness_coefficient(&s).max(1.0)
        );
        assert!((co.stiffness - (mode.omega().powi(2) - stiffness_coefficient(&s))).abs() < 1e-9);
    }
    assert!(worst < 1e-12);
}

#[test]
fn pure_pitch_has_no_centrifugal_or_coriolis_force() {
    let mode = Mode {
        name: "m".into(),
        freq_hz: 60.0,
        a: [1e-4, 2e-5],
        zeta: 0.0,
        strains: vec![],
    };
    let k = Kinematics::sinusoidal(25.0, 0.0, 0.5, 0.0);
    let c = k.compile();
    for j in 0..20 {
        let s = c.state(j as f64 * 0.002);
        let co = coefficients(&mode, &s);
        assert_eq!(co.centrifugal, 0.0);
        assert_eq!(co.coriolis, 0.0);
        // Euler = β̈ b_y = β̈ a_x for pure pitch.
        assert!((co.euler - s.beta_ddot * mode.a[0]).abs() <= 1e-15 * co.euler.abs().max(1e-300));
    }
}

#[test]
fn no_yaw_means_no_coriolis_and_b_is_a_turned_left() {
    let mode = Mode {
        name: "m".into(),
        freq_hz: 60.0,
        a: [3.0, -1.0],
        zeta: 0.0,
        strains: vec![],
    };
    assert_eq!(mode.b(), [1.0, 3.0]);
    let c = Kinematics::sinusoidal(25.0, 0.8, 0.5, 0.0).compile();
    for j in 0..20 {
        assert_eq!(
            coefficients(&mode, &c.state(j as f64 * 0.0021)).coriolis,
            0.0
        );
    }
}

#[test]
fn stiffness_force_multiplies_pointwise() {
    // S(t)·q_k(t), sample by sample (moved here from the wasm helpers' `stiffness_term`).
    assert_eq!(
        wingbeat::model::stiffness_force(&[1.0, 2.0, 3.0], &[4.0, 5.0, 6.0]),
        [4.0, 10.0, 18.0]
    );
}
