//! Kinematics (Eq. 1): the angular velocity formula against rotation matrices, and the
//! sampled-table interpolant against the series it was sampled from.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use nalgebra::{Matrix3, Rotation3, Vector3};
use wingbeat::kinematics::{Angle, Harmonic, Kinematics};

fn rot(alpha: f64, beta: f64) -> Matrix3<f64> {
    // Roll α about I, then pitch β about the rolled J′ (intrinsic): R = R_x(α) R_y(β).
    (Rotation3::from_axis_angle(&Vector3::x_axis(), alpha)
        * Rotation3::from_axis_angle(&Vector3::y_axis(), beta))
    .into_inner()
}

#[test]
fn omega_matches_rotation_matrix_derivative() {
    let k = Kinematics {
        flap_freq_hz: 25.0,
        alpha: Angle::Fourier {
            mean: 0.1,
            harmonics: vec![
                Harmonic {
                    n: 1,
                    amplitude: 0.8,
                    phase: 0.3,
                },
                Harmonic {
                    n: 2,
                    amplitude: 0.1,
                    phase: -1.0,
                },
            ],
        },
        beta: Angle::Fourier {
            mean: -0.2,
            harmonics: vec![Harmonic {
                n: 1,
                amplitude: 0.5,
                phase: 1.1,
            }],
        },
        gamma: Angle::sine(0.2),
        body_rate: Default::default(),
    };
    let c = k.compile();
    let h = 1e-6;
    for j in 0..17 {
        let t = j as f64 * 0.04 / 17.0 + 0.0013;
        let s = c.state(t);
        let r = rot(s.alpha, s.beta);
        let sp = c.state(t + h);
        let sm = c.state(t - h);
        let rdot = (rot(sp.alpha, sp.beta) - rot(sm.alpha, sm.beta)) / (2.0 * h);
        // Body-frame angular velocity: [Ω]× = Rᵀ Ṙ.
        let w = r.transpose() * rdot;
        let om = s.omega();
        let scale = 2.0 * std::f64::consts::PI * 25.0;
        assert!(
            (w[(2, 1)] - om[0]).abs() < 1e-6 * scale,
            "Ω_x at t={t}: {} vs {}",
            w[(2, 1)],
            om[0]
        );
        assert!((w[(0, 2)] - om[1]).abs() < 1e-6 * scale, "Ω_y at t={t}");
        assert!((w[(1, 0)] - om[2]).abs() < 1e-6 * scale, "Ω_z at t={t}");
        // Ω̇ against a central difference of Ω.
        let omd = s.omega_dot();
        let (op, omm) = (sp.omega(), sm.omega());
        for i in 0..3 {
            let fd = (op[i] - omm[i]) / (2.0 * h);
            assert!(
                (fd - omd[i]).abs() < 1e-5 * scale * scale,
                "Ω̇[{i}] at t={t}: {fd} vs {}",
                omd[i]
            );
        }
    }
}

#[test]
fn sampled_table_reproduces_its_fourier_series_exactly() {
    // Sample a band-limited series on 32 points: the trigonometric interpolant must give it back,
    // with derivatives, everywhere (not just at the samples).
    let truth = Angle::Fourier {
        mean: 0.05,
        harmonics: vec![
            Harmonic {
                n: 1,
                amplitude: 0.7,
                phase: 0.4,
            },
            Harmonic {
                n: 3,
                amplitude: -0.1,
                phase: 2.0,
            },
        ],
    };
    let fd = 26.0;
    let wd = 2.0 * std::f64::consts::PI * fd;
    let s_truth = truth.series();
    let n = 32;
    let values: Vec<f64> = (0..n)
        .map(|j| s_truth.eval(j as f64 / (n as f64 * fd), wd).0)
        .collect();
    let sampled = Angle::Sampled {
        values,
        max_harmonic: None,
    };
    sampled.validate("alpha").unwrap();
    let s = sampled.series();
    for j in 0..50 {
        let t = j as f64 * 0.000771;
        let (a, b) = (s.eval(t, wd), s_truth.eval(t, wd));
        assert!((a.0 - b.0).abs() < 1e-13, "value");
        assert!((a.1 - b.1).abs() < 1e-10 * wd, "rate");
        assert!((a.2 - b.2).abs() < 1e-9 * wd * wd, "acceleration");
    }
}

#[test]
fn half_period_detection() {
    assert!(Kinematics::paper_forward_flight()
        .compile()
        .stiffness_coefficient_has_half_period());
    let mut k = Kinematics::paper_forward_flight();
    k.beta = Angle::Fourier {
        mean: 0.1,
        harmonics: vec![Harmonic {
            n: 1,
            amplitude: 0.5,
            phase: 0.0,
        }],
    };
    assert!(!k.compile().stiffness_coefficient_has_half_period());
}

#[test]
fn invalid_angles_name_the_field() {
    let bad = Angle::Fourier {
        mean: f64::NAN,
        harmonics: vec![],
    };
    let e = bad.validate("kinematics.beta").unwrap_err().to_string();
    assert!(e.contains("kinematics.beta.mean"), "{e}");
    let bad = Angle::Fourier {
        mean: 0.0,
        harmonics: vec![Harmonic {
            n: 0,
            amplitude: 0.1,
            phase: 0.0,
        }],
    };
    assert!(bad
        .validate("a")
        .unwrap_err()
        .to_string()
        .contains("a.harmonics[0].n"));
    let bad = Angle::Sampled {
        values: vec![0.0, 1.0],
        max_harmonic: None,
    };
    assert!(bad
        .validate("g")
        .unwrap_err()
        .to_string()
        .contains("g.values"));
}

/// The four stage times of a Gauss step evaluated together (each harmonic's sine turned from the
/// step start) agree with evaluating each time alone to a few units in the last place, for
/// several harmonics with phases and means, over a period's steps of lengths equal, nearly equal
/// and not equal, with turns kept between steps; with a body rate they are the per-time
/// evaluation exactly.
#[test]
fn stage_states_agree_with_states_at_each_time() {
    use wingbeat::kinematics::StageTurns;
    use wingbeat::solve::gauss::Tableau;
    let harm = |n, amplitude, phase| Harmonic {
        n,
        amplitude,
        phase,
    };
    let mut k = Kinematics {
        flap_freq_hz: 25.0,
        alpha: Angle::Fourier {
            mean: 0.1,
            harmonics: vec![harm(1, 0.8, 0.3), harm(3, 0.1, -1.0)],
        },
        beta: Angle::Fourier {
            mean: -0.2,
            harmonics: vec![harm(1, 0.5, 1.1), harm(2, 0.05, 0.4)],
        },
        gamma: Angle::sine(0.2),
        body_rate: Default::default(),
    };
    let c = Tableau::new().c;
    let check = |k: &Kinematics, exact: bool| {
        let comp = k.compile();
        let mut turns = StageTurns::default();
        // Step lengths as a propagator's intervals give them (equal to a few units in the last
        // place), and lengths 1e-10 apart (turns kept and corrected) or 1e-6 apart (new turns).
        for (steps, wobble) in [(400usize, 3e-14), (157, 0.0), (200, 1e-10), (100, 1e-6)] {
            let h0 = 0.04 / steps as f64;
            for m in 0..steps {
                let h = h0 * (1.0 + ((m % 7) as f64 - 3.0) * wobble);
                let t0 = m as f64 * h0;
                let got = comp.stage_states(t0, h, &c, &mut turns);
                for (i, g) in got.iter().enumerate() {
                    let w = comp.state(t0 + c[i] * h);
                    if exact {
                        assert_eq!(*g, w);
                        continue;
                    }
                    let wd = comp.wd;
                    for (a, b, scale) in [
                        (g.alpha, w.alpha, 1.0),
                        (g.alpha_dot, w.alpha_dot, wd),
                        (g.alpha_ddot, w.alpha_ddot, wd * wd * 9.0),
                        (g.beta, w.beta, 1.0),
                        (g.beta_dot, w.beta_dot, wd),
                        (g.beta_ddot, w.beta_ddot, wd * wd * 4.0),
                        (g.gamma, w.gamma, 1.0),
                        (g.gamma_dot, w.gamma_dot, wd),
                        (g.gamma_ddot, w.gamma_ddot, wd * wd),
                    ] {
                        assert!(
                            (a - b).abs() <= 8.0 * f64::EPSILON * scale,
                            "{steps} steps, step {m}, stage {i}: {a} vs {b}"
                        );
                    }
                }
            }
        }
    };
    check(&k, false);
    k.body_rate.z = Angle::constant(3.0);
    check(&k, true);
}
