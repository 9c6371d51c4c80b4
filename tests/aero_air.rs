//! The wing in air (src/aero): loads against closed forms, the coupled propagator against an
//! independent integrator, the vacuum limit against the per-mode path, free decay against the
//! quadratic-damping envelope, and the linearised drag against the nonlinear reference.
#![allow(clippy::needless_range_loop)]
// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use std::sync::{Arc, OnceLock};
use wingbeat::aero::nonlinear::{rk4_linear, simulate_nonlinear};
use wingbeat::aero::ode::{LoadTable, TABLE_TOLERANCE};
use wingbeat::aero::simulate::{AirOde, AERODYNAMIC, TOTAL};
use wingbeat::aero::{AeroConfig, AeroWing, FrameState, WingGeometry};
use wingbeat::config::SimConfig;
use wingbeat::fem::{self, FemInput, ShellMaterial};
use wingbeat::kinematics::Kinematics;
use wingbeat::simulate::simulate;
use wingbeat::solve::coupled::{
    coupled_map, map_difference, max_step, propagate_coupled, CoupledOde,
};

fn fe_wing() -> &'static SimConfig {
    static C: OnceLock<SimConfig> = OnceLock::new();
    C.get_or_init(|| SimConfig::fe_wing().expect("the FE wing preset solves"))
}

/// The published plate of Eberle et al. 2015 (50 × 25 mm acrylic, 0.127 mm), flat, root
/// clamped, its first `n` FE modes.
fn plate(n: usize) -> fem::FemModes {
    let input = FemInput {
        planform_mm: fem::rectangle_planform(50.0, 25.0),
        camber: 0.0,
        material: ShellMaterial {
            thickness_m: 0.127e-3,
            e_pa: 3.0e9,
            rho_kg_m3: 1180.0,
            nu: 0.35,
        },
        n_modes: n,
        mesh_size_mm: Some(1.25),
        ..Default::default()
    };
    fem::compute_modes(&input).expect("the plate solves")
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |m, x| m.max(x.abs()))
}

fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).fold(0.0, |m, (x, y)| m.max((x - y).abs()))
}

/// A rectangle R × c (m) meshed by the project's mesher, with the "shapes" 1 and x (a rigid
/// heave and a rigid rotation about the root edge).
fn rigid_rectangle(span_m: f64, chord_m: f64, h_mm: f64) -> WingGeometry {
    let input = FemInput {
        planform_mm: fem::rectangle_planform(span_m * 1e3, chord_m * 1e3),
        camber: 0.0,
        mesh_size_mm: Some(h_mm),
        ..Default::default()
    };
    let (_, mesh, _) = fem::mesh_input(&input).expect("meshes");
    let nodes: Vec<[f64; 2]> = mesh.nodes.iter().map(|p| [p[0], p[1]]).collect();
    let shapes = vec![vec![1.0; nodes.len()], nodes.iter().map(|p| p[0]).collect()];
    WingGeometry {
        nodes,
        triangles: mesh.triangles,
        shapes,
    }
}

#[test]
fn face_on_flapping_plate_force_and_root_moment_match_the_closed_form() {
    // Flapping about the chord axis through the root (Ω = Ω_y J″) with the plate face-on:
    // v_n = −Ω_y x, f_n = ½ρC_N Ω_y|Ω_y| x², so F = k Ω|Ω| c R³/3 and the root moment (the
    // generalised force of φ = x) M = k Ω|Ω| c R⁴/4, k = ½ ρ C_N,max.
    let (r, c) = (0.05, 0.025);
    let aero = AeroConfig::with_density(1.2);
    let k = 0.5 * 1.2 * aero.normal_force_coefficient;
    for h_mm in [5.0, 2.5, 1.25] {
        let g = rigid_rectangle(r, c, h_mm);
        let wing = AeroWing::build(&g, &aero).unwrap();
        assert!(
            (wing.area() - r * c).abs() < 1e-12 * r * c,
            "area {}",
            wing.area()
        );
        for om in [37.0, -52.0] {
            let fs = FrameState {
                omega: [0.0, om, 0.0],
                omega_dot: [0.0; 3],
                gamma: 0.0,
                gamma_dot: 0.0,
            };
            let (mut f, mut cm) = ([0.0; 2], [0.0; 4]);
            wing.loads(&fs, k, 0.0, &mut f, &mut cm);
            let force = k * om * om.abs() * c * r.powi(3) / 3.0;
            let moment = k * om * om.abs() * c * r.powi(4) / 4.0;
            assert!(
                (f[0] - force).abs() <= 1e-12 * force.abs(),
                "{h_mm} mm: F {} vs {force}",
                f[0]
            );
            assert!(
                (f[1] - moment).abs() <= 1e-12 * moment.abs(),
                "{h_mm} mm: M {} vs {moment}",
                f[1]
            );
            // Linearised damping of the rigid rotation: ∂f/∂ẇ = 2k|v_n| here (v = v_n), so
            // C_a = ∫ x² · 2k|Ω| x dA = 2k|Ω| c R⁴/4.
            let c11 = 2.0 * k * om.abs() * c * r.powi(4) / 4.0;
            assert!((cm[3] - c11).abs() <= 1e-12 * c11, "C_a {} vs {c11}", cm[3]);
        }
    }
}

#[test]
fn quadrature_converges_with_strips_for_a_general_motion() {
    let fe = fe_wing();
    let g = fe.wing.as_deref().unwrap();
    let fs = FrameState {
        omega: [11.0, -23.0, 7.0],
        omega_dot: [0.0; 3],
        gamma: 0.1,
        gamma_dot: 3.0,
    };
    let eval = |strips: usize, chord: usize| {
        let a = AeroConfig {
            strips,
            chord_points: chord,
            ..AeroConfig::with_density(1.2)
        };
        let w = AeroWing::build(g, &a).unwrap();
        let (mut f, mut c) = (vec![0.0; 4], vec![0.0; 16]);
        w.loads(&fs, 2.04, 0.0, &mut f, &mut c);
        f
    };
    let reference = eval(192, 16);
    let scale = max_abs(&reference);
    let errs: Vec<f64> = [6, 12, 24, 48]
        .iter()
        .map(|&s| max_diff(&eval(s, 6), &reference) / scale)
        .collect();
    println!("relative error of F_A vs strips 6/12/24/48 (6 chord points): {errs:?}");
    // The |v|v load has a kink along the line where v_n changes sign, so the convergence is
    // not smooth, but it is steady: a tenth of the error at eight times the strips.
    assert!(
        errs[1] < 0.5 * errs[0] && errs[2] < 0.3 * errs[0] && errs[3] < 0.1 * errs[0],
        "not converging: {errs:?}"
    );
    assert!(errs[2] < 2e-3, "default strips err {}", errs[2]);
}

#[test]
fn added_mass_lowers_a_cantilever_plates_first_frequency_as_strip_theory_says() {
    // Strip theory for a uniform plate of chord c, areal mass m_s in a bending mode that is
    // uniform across the chord: M_a = ρπc²/4 per unit span over m_s c, so
    // f_air / f_vac = 1 / √(1 + ρπc / (4 m_s)), independent of the mode's spanwise shape.
    let fe = plate(1);
    let g = WingGeometry::from_fem(&fe);
    let rho = 1.2;
    let wing = AeroWing::build(&g, &AeroConfig::with_density(rho)).unwrap();
    let ma = wing.added_mass(rho)[0];
    let ms = 1180.0 * 0.127e-3;
    let strip = rho * std::f64::consts::PI * 0.025 / (4.0 * ms);
    let ratio = 1.0 / (1.0 + ma).sqrt();
    let expected = 1.0 / (1.0 + strip).sqrt();
    println!(
        "plate f1 {} Hz; M_a {ma} vs strip {strip}; ratio {ratio} vs {expected}",
        fe.freq_hz[0]
    );
    assert!((ratio - expected).abs() < 2e-3, "{ratio} vs {expected}");
    // And the simulation reports that frequency for the non-rotating wing.
    let modes = fe.model_modes(0.0, &[], "p").unwrap();
    let mass = vec![1.0 + ma];
    let f = wingbeat::aero::simulate::still_air_frequencies(&modes, &mass);
    assert!((f[0] - fe.freq_hz[0] * ratio).abs() < 1e-9 * fe.freq_hz[0]);
}

#[test]
fn free_decay_in_still_air_follows_the_quadratic_damping_envelope() {
    // No flapping: the air only resists the elastic velocity, f = −k|ẇ|ẇ, so one mode obeys
    // M q̈ + ω² q = −k S₃ |q̇| q̇ with S₃ = ∫|φ|³ dA; averaging gives the amplitude
    // A(t) = A₀ / (1 + (4 β ω_a A₀ / 3π) t), β = k S₃ / M, ω_a = ω/√M.
    let fe = plate(1);
    let g = WingGeometry::from_fem(&fe);
    let aero = AeroConfig::with_density(1.2);
    let wing = AeroWing::build(&g, &aero).unwrap();
    let k = 0.5 * 1.2 * aero.normal_force_coefficient;
    let s3: f64 = (0..wing.points.len())
        .map(|p| wing.weights[p] * wing.phi[p].abs().powi(3))
        .sum();
    let m = 1.0 + wing.added_mass(1.2)[0];
    let w = 2.0 * std::f64::consts::PI * fe.freq_hz[0] / m.sqrt();
    let beta = k * s3 / m;
    // Start amplitude: decays to about half in 0.6 s.
    let a0 = 3.0 * std::f64::consts::PI / (4.0 * beta * w * 0.6);
    let mut cfg = SimConfig {
        kinematics: Kinematics::sinusoidal(25.0, 0.0, 0.0, 0.0),
        modes: fe.model_modes(0.0, &[], "p").unwrap(),
        duration_s: 1.2,
        sample_rate_hz: 5_000.0,
        initial_conditions: vec![[0.0, a0 * w]],
        aero,
        ..SimConfig::paper()
    };
    cfg.wing = Some(Arc::new(g.clone()));
    let q = simulate_nonlinear(&cfg, &g, 4).unwrap();
    let q = &q[0];
    // Peaks of |q| against the envelope.
    let dt = 1.0 / cfg.sample_rate_hz;
    let mut worst: f64 = 0.0;
    let mut checked = 0;
    for i in 1..q.len() - 1 {
        if q[i] > q[i - 1] && q[i] >= q[i + 1] && i as f64 * dt > 0.02 {
            let t = i as f64 * dt;
            let env = a0 / (1.0 + 4.0 * beta * w * a0 * t / (3.0 * std::f64::consts::PI));
            worst = worst.max((q[i] - env).abs() / env);
            checked += 1;
        }
    }
    println!("free decay: {checked} peaks, worst relative deviation from the envelope {worst:.2e}");
    assert!(checked >= 12, "{checked} peaks");
    assert!(worst < 0.02, "envelope deviation {worst}");
    // The linearised path has no damping at rest (∂f/∂ẇ = 0 at v₀ = 0): it keeps the amplitude.
    let lin = simulate(&cfg).unwrap();
    let peak_late = max_abs(&lin.modes[0].q.total[q.len() * 9 / 10..]);
    assert!(
        (peak_late - a0).abs() < 1e-3 * a0,
        "linearised amplitude {peak_late} vs {a0}"
    );
}

fn air_cfg(rho: f64, duration: f64) -> SimConfig {
    SimConfig {
        aero: AeroConfig::with_density(rho),
        duration_s: duration,
        ..fe_wing().clone()
    }
}

/// RK4 at `sub` and 2·`sub` substeps per sample, Richardson-extrapolated (order 4 → 6): an
/// integrator independent of the Gauss–Legendre propagator. Also returns how much closer to
/// `ours` the finer run came (≈ 16 for a fourth-order method converging to our answer).
fn rk4_extrapolated<O: CoupledOde + ?Sized>(
    ode: &O,
    col: usize,
    x0: &[f64],
    dt: f64,
    ns: usize,
    sub: usize,
) -> Vec<Vec<f64>> {
    let a = rk4_linear(ode, col, x0, dt, ns, sub).unwrap();
    let b = rk4_linear(ode, col, x0, dt, ns, 2 * sub).unwrap();
    a.iter()
        .zip(&b)
        .map(|(a, b)| a.iter().zip(b).map(|(a, b)| b + (b - a) / 15.0).collect())
        .collect()
}

/// The FE wing in air with a coarse aerodynamic quadrature (the integrator tests check the
/// time stepping, not the quadrature).
fn coarse_air(duration: f64) -> SimConfig {
    let mut c = air_cfg(1.2, duration);
    c.aero.strips = 8;
    c.aero.chord_points = 3;
    c
}

#[test]
fn coupled_propagator_matches_rk4_on_the_2n_system() {
    let cfg = coarse_air(0.04);
    let g = cfg.wing.as_deref().unwrap();
    let wing = AeroWing::build(g, &cfg.aero).unwrap();
    let kin = cfg.kinematics.compile();
    let ode = AirOde::new(&kin, &cfg.modes, &wing, &cfg.aero).unwrap();
    let n = cfg.modes.len();
    let mut x0 = vec![0.0; 2 * n];
    x0[0] = 1e-6;
    x0[n + 1] = -3e-4;
    let dt = 1.0 / cfg.sample_rate_hz;
    let ns = cfg.n_samples();
    // The run tabulates the loads in time; the RK4 reference evaluates them exactly.
    let mut tabulated = AirOde::new(&kin, &cfg.modes, &wing, &cfg.aero).unwrap();
    tabulated.tabulate();
    let pr = propagate_coupled(&tabulated, dt, ns, TOTAL, &x0, &[]).unwrap();
    let largest = pr.total.iter().map(|v| max_abs(v)).fold(0.0, f64::max);
    for col in [AERODYNAMIC, TOTAL] {
        let start = if col == TOTAL {
            x0.clone()
        } else {
            vec![0.0; 2 * n]
        };
        let rk = rk4_extrapolated(&ode, col, &start, dt, ns, 20);
        for k in 0..n {
            let ours = if col == TOTAL {
                &pr.total[k]
            } else {
                &pr.q[col][k]
            };
            let d = max_diff(ours, &rk[k]);
            println!(
                "column {col} mode {k}: max |Gauss − RK4 (extrapolated)| = {:.2e} of the largest peak, {:.2e} of its own",
                d / largest,
                d / max_abs(ours)
            );
            assert!(
                d <= 1e-10 * max_abs(ours),
                "column {col} mode {k}: {:e} of its peak",
                d / max_abs(ours)
            );
        }
    }
    // Steps end at the stroke reversals, where the loads have a kink, so the order-8
    // Richardson estimate holds.
    assert!(
        pr.period_error < 1e-10,
        "period error estimate {}",
        pr.period_error
    );
}

/// The loads at `t` summed over the quadrature and read from `table`, and each group's largest
/// size over the period (F_A, C_a), for the table check.
fn table_error(ode: &AirOde<'_>, table: &LoadTable, m: usize) -> (f64, f64) {
    let n = ode.n_modes();
    let t = ode.period();
    let (mut fe, mut ce) = (vec![0.0; n], vec![0.0; n * n]);
    let (mut ft, mut ct) = (vec![0.0; n], vec![0.0; n * n]);
    let (mut fsize, mut csize, mut fdiff, mut cdiff) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for j in 0..m {
        // Off every grid: an irrational fraction of the period apart.
        let tau = ((j as f64 + 0.5) * 0.618_033_988_749_894_9 * t / m as f64 * 7.0).rem_euclid(t);
        ode.exact_loads(tau, &mut fe, &mut ce);
        if !table.eval_at(tau, &mut ft, &mut ct) {
            continue;
        }
        fsize = fsize.max(max_abs(&fe));
        csize = csize.max(max_abs(&ce));
        fdiff = fdiff.max(max_diff(&fe, &ft));
        cdiff = cdiff.max(max_diff(&ce, &ct));
    }
    (fdiff / fsize, cdiff / csize)
}

#[test]
fn the_load_table_reproduces_the_quadrature_loads_between_its_nodes() {
    // The default FE wing in air (rest instants at the stroke reversals) and with a steady
    // body roll rate (no rest instant; single points pass through rest, so the loads change
    // fast there and the table halves its panels).
    let mut rolling = air_cfg(1.2, 0.04);
    rolling.kinematics.body_rate.x = wingbeat::kinematics::Angle::Fourier {
        mean: 3.0,
        harmonics: vec![],
    };
    for (name, cfg) in [
        ("paper kinematics", air_cfg(1.2, 0.04)),
        ("body roll 3 rad/s", rolling),
    ] {
        let wing = AeroWing::build(cfg.wing.as_deref().unwrap(), &cfg.aero).unwrap();
        let kin = cfg.kinematics.compile();
        let ode = AirOde::new(&kin, &cfg.modes, &wing, &cfg.aero).unwrap();
        let table = LoadTable::build(&ode);
        let (panels, exact) = table.panels();
        let (fe, ce) = table_error(&ode, &table, 500);
        println!(
            "{name}: {panels} panels ({exact} exact), {} load evaluations, tail {:.1e}; max error F_A {fe:.1e}, C_a {ce:.1e} of their size",
            table.evaluations, table.tail
        );
        assert!(table.tail <= TABLE_TOLERANCE, "{}", table.tail);
        assert!(fe < 5e-14 && ce < 5e-14, "F_A {fe:e}, C_a {ce:e}");
        // Far fewer evaluations than the propagator's four per step.
        assert!(table.evaluations < 2000, "{}", table.evaluations);
    }
}

#[test]
fn coupled_step_rule_meets_the_one_period_target_and_the_estimate_bounds_the_error() {
    // The default FE wing in air, loads tabulated as the run does: one period at the rule's
    // step against the same period at a quarter of it; the propagator's Richardson estimate
    // must not be below that measured error.
    let cfg = air_cfg(1.2, 0.04);
    let wing = AeroWing::build(cfg.wing.as_deref().unwrap(), &cfg.aero).unwrap();
    let kin = cfg.kinematics.compile();
    let mut ode = AirOde::new(&kin, &cfg.modes, &wing, &cfg.aero).unwrap();
    ode.tabulate();
    let t = ode.period();
    let dt = 1.0 / cfg.sample_rate_hz;
    let phases: Vec<f64> = (0..(t / dt).round() as usize)
        .map(|j| j as f64 * dt)
        .collect();
    let h = max_step(&ode, t);
    let map = coupled_map(&ode, t, &phases, h).unwrap();
    let fine = coupled_map(&ode, t, &phases, h / 4.0).unwrap();
    let measured = map_difference(&map, &fine, ode.freq_scale());
    let n = ode.n_modes();
    let pr = propagate_coupled(&ode, dt, phases.len() + 1, TOTAL, &vec![0.0; 2 * n], &[]).unwrap();
    println!(
        "{} steps per period (the vacuum rule would take {}): measured one-period error {measured:.2e}, estimate {:.2e}",
        map.steps,
        wingbeat::solve::propagator::steps_per_span(ode.freq_scale(), t),
        pr.period_error
    );
    assert!(measured < 1e-12, "{measured:e}");
    assert!(
        pr.period_error >= measured,
        "{} < {measured:e}",
        pr.period_error
    );
    assert!(pr.period_error < 1e-11, "{}", pr.period_error);
}

#[test]
fn coupled_multipliers_match_an_rk4_monodromy() {
    let cfg = coarse_air(0.1);
    let g = cfg.wing.as_deref().unwrap();
    let wing = AeroWing::build(g, &cfg.aero).unwrap();
    let kin = cfg.kinematics.compile();
    let ode = AirOde::new(&kin, &cfg.modes, &wing, &cfg.aero).unwrap();
    let hom = ode.homogeneous();
    let n = ode.n_modes();
    let d = 2 * n;
    let t = hom.period();
    let map = coupled_map(&hom, t, &[], max_step(&hom, t)).unwrap();
    // The q rows of Φ(T) from RK4 runs out of each unit start (T/400 samples).
    let mut mono = vec![0.0; d * d];
    for j in 0..d {
        let mut x0 = vec![0.0; d];
        x0[j] = 1.0;
        let rk = rk4_extrapolated(&hom, 0, &x0, t / 400.0, 401, 40);
        for i in 0..n {
            mono[i * d + j] = rk[i][400];
        }
    }
    let mut worst: f64 = 0.0;
    for i in 0..n {
        for j in 0..d {
            worst = worst.max((mono[i * d + j] - map.monodromy[i * d + j]).abs());
        }
    }
    let scale = max_abs(&map.monodromy[..n * d]);
    println!(
        "monodromy q rows: max |Gauss − RK4| = {:.2e} of {scale:.3e}",
        worst / scale
    );
    assert!(worst <= 1e-10 * scale, "{:e}", worst / scale);
    let r = simulate(&cfg).unwrap();
    let air = r.air.as_ref().unwrap();
    assert_eq!(air.multipliers.len(), d);
    // The multipliers are the eigenvalues of that monodromy: |λ| product = det Φ(T).
    let det = nalgebra::DMatrix::from_row_slice(d, d, &map.monodromy).determinant();
    let prod: f64 = air.multipliers.iter().map(|m| m[0].hypot(m[1])).product();
    assert!(
        (prod - det.abs()).abs() < 1e-9 * det.abs(),
        "{prod} vs {det}"
    );
    // Air damps every Floquet mode: all multipliers strictly inside the unit circle.
    for m in &air.multipliers {
        assert!(m[0].hypot(m[1]) < 1.0, "multiplier {m:?}");
    }
}

#[test]
fn a_vanishing_density_reproduces_the_vacuum_per_mode_path() {
    let vac = simulate(&SimConfig {
        duration_s: 0.3,
        ..fe_wing().clone()
    })
    .unwrap();
    let air = simulate(&air_cfg(1e-9, 0.3)).unwrap();
    for (k, (a, v)) in air.modes.iter().zip(&vac.modes).enumerate() {
        let peak = max_abs(&v.q.total);
        for (name, x, y) in [
            ("euler", &a.q.euler, &v.q.euler),
            ("centrifugal", &a.q.centrifugal, &v.q.centrifugal),
            ("coriolis", &a.q.coriolis, &v.q.coriolis),
            ("total", &a.q.total, &v.q.total),
        ] {
            let d = max_diff(x, y) / peak;
            assert!(d < 1e-8, "mode {k} {name}: {d:e} of peak");
        }
        assert!(max_abs(&a.q.aerodynamic) < 1e-6 * peak);
        let (fa, fv) = (a.floquet.effective_freq_hz, v.floquet.effective_freq_hz);
        assert!((fa - fv).abs() < 1e-6 * fv, "mode {k}: f_eff {fa} vs {fv}");
    }
}

#[test]
fn air_lowers_the_frequencies_and_erases_the_beat_within_a_few_wingbeats() {
    let air = simulate(&air_cfg(wingbeat::aero::AIR_DENSITY, 0.5)).unwrap();
    let helium = simulate(&air_cfg(wingbeat::aero::HELIUM_DENSITY, 0.5)).unwrap();
    let vac = simulate(&SimConfig {
        duration_s: 0.5,
        ..fe_wing().clone()
    })
    .unwrap();
    for k in 0..air.modes.len() {
        let a = air.modes[k].air.as_ref().unwrap();
        let h = helium.modes[k].air.as_ref().unwrap();
        println!(
            "mode {k}: f {} Hz; still air {:.2} Hz (helium {:.2}); ζ_aero {:.4} (helium {:.4}); decay time {:?} s (helium {:?}); f_eff air {:.2} vacuum {:.2}; {}",
            air.modes[k].freq_hz, a.still_air_freq_hz, h.still_air_freq_hz, a.aero_damping_ratio,
            h.aero_damping_ratio, a.decay_time_s, h.decay_time_s,
            air.modes[k].floquet.effective_freq_hz, vac.modes[k].floquet.effective_freq_hz, a.beat
        );
        assert!(
            a.still_air_freq_hz < h.still_air_freq_hz && h.still_air_freq_hz < air.modes[k].freq_hz
        );
        assert!(a.aero_damping_ratio > h.aero_damping_ratio && h.aero_damping_ratio > 0.0);
        assert!(a.decay_rate_per_s > h.decay_rate_per_s && h.decay_rate_per_s > 0.0);
    }
    // Mode 1's free vibration in air dies within a fraction of a second.
    let a1 = air.modes[0].air.as_ref().unwrap();
    assert!(a1.decay_time_s.unwrap() < 0.25, "{:?}", a1.decay_time_s);
    let c = &air.modes[0].contribution_percent;
    assert!(c.aerodynamic.unwrap() > 0.0);
}

#[test]
fn the_nonlinear_load_linearises_to_the_aerodynamic_damping_matrix() {
    // F_nl(q̇) = F_A − C_a q̇ + O(|q̇|²): a finite-difference check of the linearisation at a
    // flapping instant.
    let cfg = air_cfg(1.2, 0.1);
    let g = cfg.wing.as_deref().unwrap();
    let wing = AeroWing::build(g, &cfg.aero).unwrap();
    let kin = cfg.kinematics.compile();
    let fs = FrameState::of(&kin.state(0.0123));
    let k = 0.5 * 1.2 * cfg.aero.normal_force_coefficient;
    let n = 4;
    let (mut f0, mut c) = (vec![0.0; n], vec![0.0; n * n]);
    wing.loads(&fs, k, 1.2, &mut f0, &mut c);
    let mut fz = vec![0.0; n];
    wing.loads_nonlinear(&fs, k, 1.2, &[0.0; 4], &mut fz);
    assert!(max_diff(&f0, &fz) <= 1e-14 * max_abs(&f0));
    let dir = [1e-3, -2e-3, 5e-4, 3e-4];
    let mut errs = vec![];
    for eps in [1e-2, 5e-3] {
        let qd: Vec<f64> = dir.iter().map(|d| d * eps).collect();
        let mut f = vec![0.0; n];
        wing.loads_nonlinear(&fs, k, 1.2, &qd, &mut f);
        let lin: Vec<f64> = (0..n)
            .map(|a| f0[a] - (0..n).map(|b| c[a * n + b] * qd[b]).sum::<f64>())
            .collect();
        errs.push(max_diff(&f, &lin));
    }
    // second order: halving ε quarters the remainder
    let ratio = errs[0] / errs[1];
    assert!(
        (3.0..5.0).contains(&ratio),
        "remainder ratio {ratio} ({errs:?})"
    );
}

#[test]
fn linearised_drag_against_the_nonlinear_reference_while_flapping() {
    // Reported, not a tolerance on a method: the difference is the physics the linearisation
    // leaves out (docs/model.md, "The wing in air"). It must shrink with the density, like
    // the quadratic drag term it comes from.
    let mut rel = vec![];
    for rho in [1.2, 0.18] {
        let mut cfg = air_cfg(rho, 0.2);
        cfg.sample_rate_hz = 5000.0;
        let g = cfg.wing.clone().unwrap();
        let lin = simulate(&cfg).unwrap();
        let nl = simulate_nonlinear(&cfg, &g, 8).unwrap();
        let mut worst: f64 = 0.0;
        for k in 0..cfg.modes.len() {
            let peak = max_abs(&lin.modes[k].q.total);
            let d = max_diff(&lin.modes[k].q.total, &nl[k]) / peak;
            println!(
                "ρ = {rho}: mode {k}: linearised vs nonlinear drag, max difference {d:.3e} of peak"
            );
            worst = worst.max(d);
        }
        rel.push(worst);
    }
    assert!(rel[0] < 0.4 && rel[1] < 0.5 * rel[0], "{rel:?}");
}

#[test]
fn the_normal_force_form_stays_close_to_the_dickinson_fits() {
    let mut worst: f64 = 0.0;
    for deg in 10..=90 {
        let a = (deg as f64).to_radians();
        let (cl, cd) = wingbeat::aero::dickinson_1999_cl_cd(a);
        let cn = cl * a.cos() + cd * a.sin();
        worst = worst.max((cn - wingbeat::aero::DEFAULT_CN_MAX * a.sin()).abs());
    }
    println!("max |C_N(DLS 1999) − 3.4 sin α| over 10°–90°: {worst:.3}");
    assert!(worst < 0.25, "{worst}");
}

#[test]
fn air_without_mode_shapes_is_refused_by_name() {
    let cfg = SimConfig {
        aero: AeroConfig::with_density(1.2),
        ..SimConfig::paper()
    };
    let e = simulate(&cfg).unwrap_err().to_string();
    assert!(e.contains("aero.air_density_kg_m3"), "{e}");
    let bad = SimConfig {
        aero: AeroConfig::with_density(-1.0),
        ..fe_wing().clone()
    };
    let e = simulate(&bad).unwrap_err().to_string();
    assert!(
        e.contains("aero.air_density_kg_m3") && e.contains("1000"),
        "{e}"
    );
    let e = SimConfig::from_json(r#"{"aero": {"air_density_kg_m3": 1.2, "speed": 3}}"#)
        .unwrap_err()
        .to_string();
    assert!(e.contains("speed"), "{e}");
}
