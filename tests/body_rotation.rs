//! Issue 14, items 1–2: a body angular velocity ω_b(t) in the kinematics, checked against
//! computations that share no code with `RateState::omega` / `model::coefficients`:
//!
//! (a) Ω and Ω̇ from finite differences of the full orientation Q(t) = R_body(t)·R_x(α)·R_y(β);
//! (b) the rigid-body and deformation accelerations of FE mesh points (finite differences of
//!     their inertial positions) projected on the FE modes, against Eq. 13's terms;
//! (c) zero ω_b reproduces the outputs without it bit for bit;
//! (d) a constant rate: closed form, and an independent RK4 integration of Eq. 13 whose
//!     Ω̇ comes from a complex-step derivative, against `simulate`.

#![cfg(not(target_arch = "wasm32"))]

use nalgebra::Complex;
use wingbeat::config::SimConfig;
use wingbeat::fem;
use wingbeat::kinematics::{Angle, BodyRate, Harmonic, Kinematics, RateState};
use wingbeat::model::{coefficients, stiffness_coefficient, Mode};
use wingbeat::simulate::simulate;

type M3 = [[f64; 3]; 3];

fn mul(a: &M3, b: &M3) -> M3 {
    let mut c = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            c[i][j] = (0..3).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    c
}
fn transpose(a: &M3) -> M3 {
    let mut c = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            c[i][j] = a[j][i];
        }
    }
    c
}
fn apply(a: &M3, v: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|i| a[i][0] * v[0] + a[i][1] * v[1] + a[i][2] * v[2])
}
fn rx(a: f64) -> M3 {
    let (s, c) = a.sin_cos();
    [[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]]
}
fn ry(b: f64) -> M3 {
    let (s, c) = b.sin_cos();
    [[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]]
}
fn rz(g: f64) -> M3 {
    let (s, c) = g.sin_cos();
    [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]
}
/// exp([θ]×): rotation by |θ| about θ/|θ| (Rodrigues).
fn rodrigues(th: [f64; 3]) -> M3 {
    let n = (th[0] * th[0] + th[1] * th[1] + th[2] * th[2]).sqrt();
    if n == 0.0 {
        return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    }
    let k = [th[0] / n, th[1] / n, th[2] / n];
    let (s, c) = n.sin_cos();
    let kx: M3 = [[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]];
    let kk = mul(&kx, &kx);
    let mut r = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            r[i][j] = if i == j { 1.0 } else { 0.0 } + s * kx[i][j] + (1.0 - c) * kk[i][j];
        }
    }
    r
}

/// Eighth-order central stencils: f′ ≈ Σ d1_j (f(t+jh) − f(t−jh)) / h,
/// f″ ≈ (d2_0 f(t) + Σ d2_j (f(t+jh) + f(t−jh))) / h².
const D1: [f64; 4] = [4.0 / 5.0, -1.0 / 5.0, 4.0 / 105.0, -1.0 / 280.0];
const D2_0: f64 = -205.0 / 72.0;
const D2: [f64; 4] = [8.0 / 5.0, -1.0 / 5.0, 8.0 / 315.0, -1.0 / 560.0];

/// First and second derivatives of a matrix-valued function by the stencils above.
fn fd_matrix(f: &dyn Fn(f64) -> M3, t: f64, h: f64) -> (M3, M3, M3) {
    let q0 = f(t);
    let mut d1 = [[0.0; 3]; 3];
    let mut d2 = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            d2[i][j] = D2_0 * q0[i][j];
        }
    }
    for s in 1..=4 {
        let p = f(t + s as f64 * h);
        let m = f(t - s as f64 * h);
        for i in 0..3 {
            for j in 0..3 {
                d1[i][j] += D1[s - 1] * (p[i][j] - m[i][j]);
                d2[i][j] += D2[s - 1] * (p[i][j] + m[i][j]);
            }
        }
    }
    for i in 0..3 {
        for j in 0..3 {
            d1[i][j] /= h;
            d2[i][j] /= h * h;
        }
    }
    (q0, d1, d2)
}

/// The same for a vector-valued function (second derivative only).
fn fd2_vec(f: &dyn Fn(f64) -> Vec<[f64; 3]>, t: f64, h: f64) -> Vec<[f64; 3]> {
    let mut out: Vec<[f64; 3]> = f(t).iter().map(|p| p.map(|x| D2_0 * x)).collect();
    for s in 1..=4 {
        let p = f(t + s as f64 * h);
        let m = f(t - s as f64 * h);
        for (o, (a, b)) in out.iter_mut().zip(p.iter().zip(&m)) {
            for c in 0..3 {
                o[c] += D2[s - 1] * (a[c] + b[c]);
            }
        }
    }
    for o in &mut out {
        for c in o.iter_mut() {
            *c /= h * h;
        }
    }
    out
}

fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}
fn diff(a: [f64; 3], b: [f64; 3]) -> f64 {
    norm([a[0] - b[0], a[1] - b[1], a[2] - b[2]])
}

/// General kinematics: means, phases and a second harmonic on α and β; γ a sine.
fn rich_kinematics() -> Kinematics {
    Kinematics {
        flap_freq_hz: 25.0,
        alpha: Angle::Fourier {
            mean: 0.15,
            harmonics: vec![
                Harmonic {
                    n: 1,
                    amplitude: 0.8,
                    phase: 0.3,
                },
                Harmonic {
                    n: 2,
                    amplitude: 0.1,
                    phase: -0.7,
                },
            ],
        },
        beta: Angle::Fourier {
            mean: -0.1,
            harmonics: vec![Harmonic {
                n: 1,
                amplitude: 0.5,
                phase: 1.1,
            }],
        },
        gamma: Angle::sine(0.2),
        body_rate: BodyRate::default(),
    }
}

/// Ω and Ω̇ from the orientation `q(t)` (wing frame → inertial): [Ω]× = QᵀQ̇ and
/// [Ω̇]× = skew(QᵀQ̈) (Q̇ᵀQ̇ is symmetric).
fn omega_fd(q: &dyn Fn(f64) -> M3, t: f64, h: f64) -> ([f64; 3], [f64; 3]) {
    let (q0, d1, d2) = fd_matrix(q, t, h);
    let qt = transpose(&q0);
    let s = mul(&qt, &d1);
    let a = mul(&qt, &d2);
    let w = [
        0.5 * (s[2][1] - s[1][2]),
        0.5 * (s[0][2] - s[2][0]),
        0.5 * (s[1][0] - s[0][1]),
    ];
    let wd = [
        0.5 * (a[2][1] - a[1][2]),
        0.5 * (a[0][2] - a[2][0]),
        0.5 * (a[1][0] - a[0][1]),
    ];
    (w, wd)
}

/// (a) Ω, Ω̇ against finite differences of Q(t) = R_body(t) R_x(α) R_y(β).
#[test]
fn omega_matches_finite_differences_of_the_orientation() {
    let base = rich_kinematics();
    let wd = base.omega_d();
    let h = base.period() / 200.0; // ω_d h ≈ 0.03: 8th-order truncation and rounding both ≲ 1e-12
    let mut worst = (0.0f64, 0.0f64);
    // 1. A constant rate about a general axis: R_body = exp(t [ω_b]×).
    let wb = [1.3, -0.7, 2.1];
    let kin = base.clone().with_body_rate(wb);
    let ck = kin.compile();
    let q = |t: f64| {
        let s = ck.state(t);
        mul(
            &rodrigues([wb[0] * t, wb[1] * t, wb[2] * t]),
            &mul(&rx(s.alpha), &ry(s.beta)),
        )
    };
    // 2. A time-varying rate about a fixed axis n: ω_b = n w(t), w = w0 + A sin(2 ω_d t + φ),
    //    R_body = exp(θ(t) [n]×) with θ = w0 t − A cos(2 ω_d t + φ) / (2 ω_d).
    let n = [0.48, 0.6, 0.64];
    let (w0, amp, ph) = (20.0, 35.0, 0.4);
    let comp = |c: f64| Angle::Fourier {
        mean: c * w0,
        harmonics: vec![Harmonic {
            n: 2,
            amplitude: c * amp,
            phase: ph,
        }],
    };
    let mut kin2 = base;
    kin2.body_rate = BodyRate {
        x: comp(n[0]),
        y: comp(n[1]),
        z: comp(n[2]),
    };
    kin2.validate().unwrap();
    let ck2 = kin2.compile();
    let q2 = |t: f64| {
        let s = ck2.state(t);
        let th = w0 * t - amp * (2.0 * wd * t + ph).cos() / (2.0 * wd);
        mul(
            &rodrigues([n[0] * th, n[1] * th, n[2] * th]),
            &mul(&rx(s.alpha), &ry(s.beta)),
        )
    };
    let cases: [(&dyn Fn(f64) -> M3, &wingbeat::kinematics::Compiled); 2] =
        [(&q, &ck), (&q2, &ck2)];
    for (qf, c) in cases {
        for i in 0..40 {
            let t = 0.0013 + i as f64 * 0.00237;
            let s = c.state(t);
            let (w_fd, wd_fd) = omega_fd(qf, t, h);
            let e1 = diff(s.omega(), w_fd) / norm(w_fd);
            let e2 = diff(s.omega_dot(), wd_fd) / norm(wd_fd);
            worst = (worst.0.max(e1), worst.1.max(e2));
        }
    }
    println!(
        "(a) max relative error vs finite differences of Q: Ω {:.2e}, Ω̇ {:.2e}",
        worst.0, worst.1
    );
    assert!(worst.0 < 1e-10, "Ω: {:e}", worst.0);
    assert!(worst.1 < 1e-10, "Ω̇: {:e}", worst.1);
}

/// (c, part) Zero body rate: Ω and Ω̇ are Eq. 1 and its derivative, bit for bit.
#[test]
fn zero_body_rate_is_equation_1_bit_for_bit() {
    let c = rich_kinematics().compile();
    assert!(c.body_rate.is_none());
    for i in 0..200 {
        let s = c.state(i as f64 * 1.7e-4);
        assert_eq!(s.body_rate, [0.0; 3]);
        let (sb, cb) = s.beta.sin_cos();
        let w = [s.alpha_dot * cb, s.beta_dot, s.alpha_dot * sb];
        let wd = [
            s.alpha_ddot * cb - s.alpha_dot * s.beta_dot * sb,
            s.beta_ddot,
            s.alpha_ddot * sb + s.alpha_dot * s.beta_dot * cb,
        ];
        assert_eq!(s.omega().map(f64::to_bits), w.map(f64::to_bits));
        assert_eq!(s.omega_dot().map(f64::to_bits), wd.map(f64::to_bits));
    }
}

/// (c) `simulate` with the body rate omitted, explicitly zero, or written as `{}` in JSON:
/// identical results, bit for bit; and the field is not written back when zero.
#[test]
fn zero_body_rate_reproduces_simulate_bit_for_bit() {
    let plain = SimConfig::paper();
    let mut zero = SimConfig::paper();
    zero.kinematics.body_rate = BodyRate::constant([0.0, 0.0, 0.0]);
    let mut json: serde_json::Value = serde_json::to_value(&plain).unwrap();
    assert!(json["kinematics"].get("body_rate").is_none());
    json["kinematics"]["body_rate"] = serde_json::json!({});
    let from_json = SimConfig::from_json(&json.to_string()).unwrap();
    assert_eq!(from_json, plain);
    let a = simulate(&plain).unwrap();
    let b = simulate(&zero).unwrap();
    let bits = |r: &wingbeat::simulate::SimResult| -> Vec<u64> {
        r.modes
            .iter()
            .flat_map(|m| {
                m.q.total
                    .iter()
                    .chain(&m.q.euler)
                    .chain(&m.q.centrifugal)
                    .chain(&m.q.coriolis)
                    .chain(&m.qdot_total)
                    .map(|x| x.to_bits())
                    .collect::<Vec<_>>()
            })
            .collect()
    };
    assert_eq!(bits(&a), bits(&b));
    assert_eq!(a, b);
    // the symmetric paper case keeps its half-period Floquet analysis
    assert!((a.modes[0].floquet.homogeneous_period_s - 0.02).abs() < 1e-15);
}

/// Validation names the field and the range.
#[test]
fn body_rate_validation_names_the_field() {
    let mut k = Kinematics::paper_forward_flight().with_body_rate([0.0, 150.0, 0.0]);
    let e = k.validate().unwrap_err().to_string();
    assert!(e.contains("kinematics.body_rate.y.mean"), "{e}");
    assert!(e.contains("100"), "{e}");
    k.body_rate = BodyRate {
        z: Angle::Fourier {
            mean: 60.0,
            harmonics: vec![Harmonic {
                n: 1,
                amplitude: 60.0,
                phase: 0.0,
            }],
        },
        ..BodyRate::default()
    };
    let e = k.validate().unwrap_err().to_string();
    assert!(e.contains("kinematics.body_rate.z"), "{e}");
    let bad = r#"{"kinematics": {"flap_freq_hz": 25, "alpha": {"kind": "fourier"},
        "beta": {"kind": "fourier"}, "gamma": {"kind": "fourier"},
        "body_rate": {"w": {"kind": "fourier", "mean": 1}}}}"#;
    let e = SimConfig::from_json(bad).unwrap_err().to_string();
    assert!(
        e.contains("body_rate") && e.contains("unknown field"),
        "{e}"
    );
    // sampled components are allowed (a measured rate)
    k.body_rate = BodyRate {
        x: Angle::Sampled {
            values: vec![1.0, 2.0, 3.0, 2.0],
            max_harmonic: None,
        },
        ..BodyRate::default()
    };
    k.validate().unwrap();
    assert!(!k.body_rate.is_zero());
    // round trip through JSON keeps a non-zero rate
    let k2: Kinematics = serde_json::from_str(&serde_json::to_string(&k).unwrap()).unwrap();
    assert_eq!(k2, k);
}

/// (b) FE rigid-body check: inertial accelerations of the mesh points, projected on the
/// modes, against Eq. 13's forcing (q = 0) and its q-dependent part.
#[test]
fn fe_mesh_accelerations_projected_on_modes_give_equation_13() {
    // A flat wing: its bending modes move the nodes along K″ only, which is the kinematics
    // Eq. 13 assumes (a cambered shell's modes also move in-plane).
    let input = fem::FemInput {
        camber: 0.0,
        mesh_size_mm: Some(3.0),
        n_modes: 3,
        ..fem::FemInput::default()
    };
    let fe = fem::compute_modes(&input).unwrap();
    let (outline, mesh, _) = fem::mesh_input(&input).unwrap();
    let clamped = fem::clamp_nodes(&outline, &mesh, input.clamp).unwrap();
    let asm = fem::assembly::assemble(&mesh, &input.material, &clamped).unwrap();
    assert_eq!(mesh.nodes, fe.nodes);
    let m = &asm.node_mass;
    let r: Vec<[f64; 3]> = fe.nodes.clone();
    assert!(r.iter().all(|p| p[2] == 0.0));
    let modes: Vec<Mode> = (0..fe.freq_hz.len())
        .map(|k| Mode {
            name: String::new(),
            freq_hz: fe.freq_hz[k],
            a: fe.a[k],
            zeta: 0.0,
            strains: vec![],
        })
        .collect();
    // modal mass matrix of the translational (K″) part: Eq. 13 takes it as δ_ke
    let nm = modes.len();
    let mkk: Vec<Vec<f64>> = (0..nm)
        .map(|k| {
            (0..nm)
                .map(|e| {
                    (0..r.len())
                        .map(|i| m[i] * fe.shapes[k][i] * fe.shapes[e][i])
                        .sum()
                })
                .collect()
        })
        .collect();

    let run = |gamma0: f64, linear_yaw: bool, wb: [f64; 3]| -> (f64, f64, f64) {
        let kin = Kinematics::sinusoidal(25.0, 0.8, 0.5, gamma0).with_body_rate(wb);
        let ck = kin.compile();
        let h = kin.period() / 200.0;
        let orient = |t: f64| {
            let s = ck.state(t);
            mul(
                &rodrigues([wb[0] * t, wb[1] * t, wb[2] * t]),
                &mul(&rx(s.alpha), &ry(s.beta)),
            )
        };
        // rigid positions (q = 0): P = r + γ K×r (Eq. 13's linearised yaw) or R_z(γ) r
        let rigid = |t: f64| -> Vec<[f64; 3]> {
            let s = ck.state(t);
            let q = orient(t);
            let g = rz(s.gamma);
            r.iter()
                .map(|p| {
                    let pw = if linear_yaw {
                        [p[0] - s.gamma * p[1], p[1] + s.gamma * p[0], p[2]]
                    } else {
                        apply(&g, *p)
                    };
                    apply(&q, pw)
                })
                .collect()
        };
        // deformation alone: q_e(t) = sin(ν t) in mode e, positions Q(t) q_e(t) φ_e K″
        let nu = 300.0;
        let defo = |e: usize| {
            let q = &orient;
            let shape = &fe.shapes[e];
            move |t: f64| -> Vec<[f64; 3]> {
                let qt = q(t);
                let amp = (nu * t).sin();
                shape
                    .iter()
                    .map(|w| apply(&qt, [0.0, 0.0, amp * w]))
                    .collect()
            }
        };
        let (mut err_f, mut ref_f, mut err_k) = (0.0f64, 0.0f64, 0.0f64);
        for i in 0..25 {
            let t = 0.0011 + i as f64 * 0.00163;
            let s = ck.state(t);
            let qt = transpose(&orient(t));
            let acc = fd2_vec(&rigid, t, h);
            for (k, mode) in modes.iter().enumerate() {
                // generalised force: −Σ m_i φ_k,i (Qᵀ Ẍ_i)_K″
                let f: f64 = -(0..r.len())
                    .map(|i| m[i] * fe.shapes[k][i] * apply(&qt, acc[i])[2])
                    .sum::<f64>();
                let c = coefficients(mode, &s);
                err_f = err_f.max((f - c.total_force()).abs());
                ref_f = ref_f.max(c.total_force().abs());
            }
            // q-dependent part: −Σ m φ_k (QᵀẌ)_K″ = −q̈_e M_ke + S q_e M_ke (no q̇ term)
            let sc = stiffness_coefficient(&s);
            for e in 0..nm {
                let acc = fd2_vec(&defo(e), t, h);
                let (qe, qedd) = ((nu * t).sin(), -nu * nu * (nu * t).sin());
                for k in 0..nm {
                    let g: f64 = -(0..r.len())
                        .map(|i| m[i] * fe.shapes[k][i] * apply(&qt, acc[i])[2])
                        .sum::<f64>();
                    let want = (-qedd + sc * qe) * mkk[k][e];
                    let scale = (nu * nu + sc) * mkk[k][k].abs().max(mkk[e][e].abs());
                    err_k = err_k.max((g - want).abs() / scale);
                }
            }
        }
        (err_f / ref_f, ref_f, err_k)
    };
    let wb = [10.0, -20.0, 30.0];
    let (lin, fref, stiff) = run(0.2, true, wb);
    let (g0, _, _) = run(0.0, false, wb);
    let (ex2, _, _) = run(0.2, false, wb);
    let (ex1, _, _) = run(0.1, false, wb);
    let modal_mass_dev = (0..nm)
        .flat_map(|k| (0..nm).map(move |e| (k, e)))
        .map(|(k, e)| (mkk[k][e] - if k == e { 1.0 } else { 0.0 }).abs())
        .fold(0.0, f64::max);
    println!(
        "(b) ω_b = {wb:?} rad/s, flat FE wing ({} nodes, {nm} modes), max |F| = {fref:.3e}:\n\
         forcing vs Eq. 13, linearised yaw γ0 = 0.2: {lin:.2e}; γ = 0: {g0:.2e};\n\
         exact yaw rotation: γ0 = 0.2 {ex2:.2e}, γ0 = 0.1 {ex1:.2e} (ratio {:.2}: second order in γ);\n\
         q-dependent part (−q̈ + S q) M_ke: {stiff:.2e}; translational modal mass vs δ_ke: {modal_mass_dev:.2e}",
        r.len(),
        ex2 / ex1
    );
    assert!(lin < 1e-6, "{lin:e}");
    assert!(g0 < 1e-6, "{g0:e}");
    assert!(stiff < 1e-6, "{stiff:e}");
    let ratio = ex2 / ex1;
    assert!(ratio > 3.0 && ratio < 5.0, "{ratio}");
}

// ---- (d): an independent Eq. 13 with a complex-step Ω̇ ----

type C = Complex<f64>;

/// Ω(t) for α = α0 sin ω_d t, β = β0 sin ω_d t and a constant ω_b, with complex t (for the
/// complex-step derivative): Ω = R_y(β)ᵀ R_x(α)ᵀ ω_b + (α̇ cos β, β̇, α̇ sin β), written out.
fn omega_c(t: C, wd: f64, a0: f64, b0: f64, wb: [f64; 3]) -> [C; 3] {
    let ph = t * wd;
    let (al, ald) = (ph.sin() * a0, ph.cos() * (a0 * wd));
    let (be, bed) = (ph.sin() * b0, ph.cos() * (b0 * wd));
    let (sa, ca, sb, cb) = (al.sin(), al.cos(), be.sin(), be.cos());
    let u = [
        C::new(wb[0], 0.0),
        ca * wb[1] + sa * wb[2],
        -sa * wb[1] + ca * wb[2],
    ];
    let v = [cb * u[0] - sb * u[2], u[1], sb * u[0] + cb * u[2]];
    [v[0] + ald * cb, v[1] + bed, v[2] + ald * sb]
}

/// RK4 of Eq. 13 (total forcing), zero start, recording q every `every` steps.
#[allow(clippy::too_many_arguments)]
fn rk4_eq13(
    mode: &Mode,
    wd: f64,
    (a0, b0, g0): (f64, f64, f64),
    wb: [f64; 3],
    h: f64,
    steps: usize,
    every: usize,
) -> Vec<f64> {
    let a = mode.a;
    let b = [-a[1], a[0]];
    let w2 = mode.omega() * mode.omega();
    let coef = |t: f64| -> (f64, f64) {
        let om = omega_c(C::new(t, 0.0), wd, a0, b0, wb).map(|z| z.re);
        let eps = 1e-30;
        let omd = omega_c(C::new(t, eps), wd, a0, b0, wb).map(|z| z.im / eps);
        let g = g0 * (wd * t).sin();
        let gd = g0 * wd * (wd * t).cos();
        let f = -(omd[0] * (g * a[0] - b[0]) + omd[1] * (g * a[1] - b[1]))
            - om[2] * (om[0] * (a[0] + g * b[0]) + om[1] * (a[1] + g * b[1]))
            - 2.0 * gd * (om[0] * a[0] + om[1] * a[1]);
        (w2 - (om[0] * om[0] + om[1] * om[1]), f)
    };
    let acc = |t: f64, q: f64, v: f64| {
        let (k, f) = coef(t);
        (v, f - k * q)
    };
    let (mut q, mut v) = (0.0, 0.0);
    let mut out = vec![0.0];
    for n in 0..steps {
        let t = n as f64 * h;
        let k1 = acc(t, q, v);
        let k2 = acc(t + 0.5 * h, q + 0.5 * h * k1.0, v + 0.5 * h * k1.1);
        let k3 = acc(t + 0.5 * h, q + 0.5 * h * k2.0, v + 0.5 * h * k2.1);
        let k4 = acc(t + h, q + h * k3.0, v + h * k3.1);
        q += h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
        v += h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
        if (n + 1) % every == 0 {
            out.push(q);
        }
    }
    out
}

/// (d) A constant rate about one axis: an independent RK4 of Eq. 13 (Ω from rotation
/// matrices, Ω̇ by complex step) matches `simulate` to 1e-9 relative.
#[test]
fn constant_rate_matches_independent_rk4() {
    let (a0, b0, g0) = (0.8, 0.5, 0.2);
    let mut worst = 0.0f64;
    for wb in [[0.0, 0.0, 8.0], [6.0, 0.0, 0.0]] {
        let mut cfg = SimConfig::paper();
        cfg.kinematics = Kinematics::sinusoidal(25.0, a0, b0, g0).with_body_rate(wb);
        cfg.duration_s = 0.2;
        cfg.sample_rate_hz = 2000.0;
        let res = simulate(&cfg).unwrap();
        // the rate matters: the response without it differs by much more than the tolerance
        let mut still = cfg.clone();
        still.kinematics.body_rate = BodyRate::default();
        let r0 = simulate(&still).unwrap();
        let d = res.modes[0]
            .q
            .total
            .iter()
            .zip(&r0.modes[0].q.total)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max);
        println!("(d) ω_b = {wb:?}: mode-0 response changes by {d:.3e} against no body rate");
        assert!(
            d > 1e-3
                * res.modes[0]
                    .q
                    .total
                    .iter()
                    .fold(0.0f64, |m, x| m.max(x.abs()))
        );
        let wd = cfg.kinematics.omega_d();
        for (k, mode) in cfg.modes.iter().enumerate() {
            // 400 RK4 steps per output sample (h = 1.25 µs); the step error is below 1e-11
            let every = 400;
            let h = 1.0 / (cfg.sample_rate_hz * every as f64);
            let q = rk4_eq13(mode, wd, (a0, b0, g0), wb, h, 400 * every, every);
            let sol = &res.modes[k].q.total;
            assert_eq!(q.len(), sol.len());
            let scale = sol.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let e = q
                .iter()
                .zip(sol)
                .map(|(x, y)| (x - y).abs())
                .fold(0.0, f64::max)
                / scale;
            println!("(d) ω_b = {wb:?}, mode {k}: RK4 vs simulate {e:.2e} (max |q| {scale:.3e})");
            worst = worst.max(e);
        }
    }
    assert!(worst < 1e-9, "{worst:e}");
}

/// (d) Closed form: no flapping (α = β = γ = 0), a constant ω_b: Ω = ω_b, so Eq. 13 is
/// q̈ + (ω_k² − ω_x² − ω_y²) q = −ω_z (ω_b · a), q = F/k (1 − cos √k t).
#[test]
fn constant_rate_without_flapping_has_a_closed_form() {
    let wb = [3.0, -4.0, 12.0];
    let mut cfg = SimConfig::paper();
    cfg.kinematics = Kinematics {
        flap_freq_hz: 25.0,
        alpha: Angle::constant(0.0),
        beta: Angle::constant(0.0),
        gamma: Angle::constant(0.0),
        body_rate: BodyRate::constant(wb),
    };
    cfg.duration_s = 0.5;
    let res = simulate(&cfg).unwrap();
    let mut worst = 0.0f64;
    for (k, mode) in cfg.modes.iter().enumerate() {
        let kk = mode.omega().powi(2) - wb[0] * wb[0] - wb[1] * wb[1];
        let f = -wb[2] * (wb[0] * mode.a[0] + wb[1] * mode.a[1]);
        let q = &res.modes[k].q;
        let scale = 2.0 * (f / kk).abs();
        for (i, &t) in res.t.iter().enumerate() {
            let want = f / kk * (1.0 - (kk.sqrt() * t).cos());
            worst = worst.max((q.total[i] - want).abs() / scale);
        }
        // the whole forcing is centrifugal here
        assert_eq!(q.total, q.centrifugal);
    }
    println!("(d) closed form, no flapping, ω_b = {wb:?}: {worst:.2e}");
    assert!(worst < 1e-9, "{worst:e}");
}

/// A body rate removes the half-period symmetry of the softening; the step size counts its
/// harmonics.
#[test]
fn body_rate_breaks_the_half_period_and_counts_harmonics() {
    let k = Kinematics::paper_forward_flight().with_body_rate([0.0, 0.0, 5.0]);
    let c = k.compile();
    assert!(!c.stiffness_coefficient_has_half_period());
    assert!(Kinematics::paper_forward_flight()
        .compile()
        .stiffness_coefficient_has_half_period());
    let mut k3 = k;
    k3.body_rate.x = Angle::Fourier {
        mean: 0.0,
        harmonics: vec![Harmonic {
            n: 3,
            amplitude: 1.0,
            phase: 0.0,
        }],
    };
    let c3 = k3.compile();
    let m = &wingbeat::presets::paper_modes(0.0)[0];
    assert_eq!(wingbeat::solve::ModalOde::new(&c3, m).max_harmonic, 3.0);
    let _ = RateState::default();
}

/// The CLI's `--body-rate X,Y,Z`: the same run as the library's constant rate; wrong counts
/// and out-of-range values are errors that name the flag.
#[test]
fn cli_body_rate_flag() {
    use std::process::Command;
    let run = |args: &[&str]| {
        let o = Command::new(env!("CARGO_BIN_EXE_wingbeat"))
            .args(args)
            .output()
            .unwrap();
        (
            o.status.code().unwrap_or(-1),
            String::from_utf8_lossy(&o.stdout).to_string(),
            String::from_utf8_lossy(&o.stderr).to_string(),
        )
    };
    let (code, out, err) = run(&["simulate", "--body-rate", "0,-3,8", "--duration", "0.05"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let mut cfg = SimConfig::paper();
    cfg.kinematics = cfg.kinematics.with_body_rate([0.0, -3.0, 8.0]);
    cfg.duration_s = 0.05;
    let lib = simulate(&cfg).unwrap();
    let q: Vec<f64> = serde_json::from_value(v["modes"][0]["q"]["total"].clone()).unwrap();
    assert_eq!(q, lib.modes[0].q.total);
    let (code, _, err) = run(&["simulate", "--body-rate", "0,200,0"]);
    assert_ne!(code, 0);
    assert!(
        err.contains("--body-rate[1]") && err.contains("100"),
        "{err}"
    );
    let (code, _, err) = run(&["simulate", "--body-rate", "1,2"]);
    assert_ne!(code, 0);
    assert!(
        err.contains("--body-rate") && err.contains("three"),
        "{err}"
    );
}
