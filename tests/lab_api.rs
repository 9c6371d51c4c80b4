//! The core functions behind the lab's own-wing and own-kinematics API (src/wasm/wing.rs,
//! kinematicsFromCsv), each against an independent check: the wing parameter table against
//! the FE input checks and a hand-built `FemInput`; the built-in outlines by meshing and
//! solving them; the outline summary against closed forms; strain anywhere against the FE
//! modes' own strain points; strain maps against brute-force time averages; measured
//! kinematics against the known Fourier series sampled, and the CLI flag against the
//! equivalent JSON config.
#![cfg(not(target_arch = "wasm32"))]
// The brute-force checks index parallel arrays by sample, mode and component.
#![allow(clippy::needless_range_loop)]

use wingbeat::error::WingbeatError;
use wingbeat::fem::geometry::{
    builtin_planforms, outline_summary, planform_note_for, validate_outline, MANDUCA_NOTE,
};
use wingbeat::fem::{compute_modes, manduca_planform, Clamp, FemInput, ShellMaterial};
use wingbeat::params::{
    apply_wing_overrides, default_wing, material_presets, wing_input, wing_parameters, WING_PARAMS,
};

fn message<T: std::fmt::Debug>(r: Result<T, WingbeatError>) -> String {
    r.expect_err("expected an error").to_string()
}

#[test]
fn wing_table_has_the_contract_keys_in_order() {
    let keys: Vec<&str> = wing_parameters().iter().map(|p| p.key).collect();
    assert_eq!(
        keys,
        [
            "camber",
            "clamp_mm",
            "e_pa",
            "rho",
            "nu",
            "thickness_um",
            "mesh_mm",
            "n_modes"
        ]
    );
    for p in &WING_PARAMS {
        assert!(p.min <= p.default && p.default <= p.max, "{}", p.key);
        assert!(p.step > 0.0, "{}", p.key);
    }
}

#[test]
fn every_wing_range_end_passes_the_fe_input_checks() {
    let base = FemInput::default();
    for p in &WING_PARAMS {
        for v in [p.min, p.max] {
            let w = apply_wing_overrides(&base, [(p.key, v)])
                .unwrap_or_else(|e| panic!("{} = {v}: {e}", p.key));
            // The same checks compute_modes makes before meshing.
            w.material.validate().unwrap();
            wingbeat::error::check_range("camber", w.camber, 0.0, 0.5, "").unwrap();
            assert!(w.n_modes >= 1 && w.n_modes <= wingbeat::model::MAX_MODES);
            if let Some(h) = w.mesh_size_mm {
                assert!(h > 0.0, "{}", p.key);
            }
        }
    }
}

#[test]
fn wing_overrides_set_the_fields_they_name() {
    let w = apply_wing_overrides(
        &FemInput::default(),
        [
            ("camber", 0.05),
            ("clamp_mm", 2.5),
            ("e_pa", 2e9),
            ("rho", 1200.0),
            ("nu", 0.25),
            ("thickness_um", 50.0),
            ("mesh_mm", 1.5),
            ("n_modes", 6.0),
        ],
    )
    .unwrap();
    let want = FemInput {
        camber: 0.05,
        clamp: Clamp::Strip { x_mm: 2.5 },
        material: ShellMaterial {
            thickness_m: 50e-6,
            e_pa: 2e9,
            rho_kg_m3: 1200.0,
            nu: 0.25,
        },
        n_modes: 6,
        mesh_size_mm: Some(1.5),
        ..FemInput::default()
    };
    assert_eq!(w, want);
    // 0 means the root clamp and the automatic mesh size.
    let w = apply_wing_overrides(&want, [("clamp_mm", 0.0), ("mesh_mm", 0.0)]).unwrap();
    assert_eq!(w.clamp, Clamp::Root);
    assert_eq!(w.mesh_size_mm, None);
}

#[test]
fn wing_override_errors_name_the_key_and_range() {
    let base = FemInput::default();
    for (k, v, want) in [
        ("camber", 0.6, "wing.camber"),
        ("camber", 0.6, "[0, 0.5]"),
        ("n_modes", 9.0, "[1, 8]"),
        ("n_modes", 2.5, "an integer in [1, 8]"),
        ("nu", f64::NAN, "wing.nu"),
        ("thickness_um", 0.0, "µm"),
        ("bogus", 1.0, "wing.bogus"),
        ("bogus", 1.0, "one of camber, clamp_mm"),
    ] {
        let m = message(apply_wing_overrides(&base, [(k, v)]));
        assert!(m.contains(want), "{k} = {v}: `{m}` lacks {want}");
    }
    let m = message(apply_wing_overrides(&base, [("nu", 0.1), ("nu", 0.2)]));
    assert!(m.contains("at most one value"), "{m}");
    // A bad outline is named by the outline check.
    let m = message(wing_input(
        std::iter::empty::<(&str, f64)>(),
        Some(vec![[0.0, 0.0], [1.0, 1.0]]),
    ));
    assert!(m.contains("planform"), "{m}");
}

#[test]
fn default_wing_is_the_table_defaults_on_the_default_outline() {
    let w = default_wing().unwrap();
    assert_eq!(
        w,
        FemInput {
            n_modes: wingbeat::presets::FE_WING_MODES,
            mesh_size_mm: None,
            ..FemInput::default()
        }
    );
    assert_eq!(w.planform_note, MANDUCA_NOTE);
    // The material presets are the core's materials.
    let p = material_presets();
    assert_eq!(p.len(), 2);
    assert_eq!(p[0].id, "paper-frequencies");
    assert_eq!(p[0].e_pa, ShellMaterial::paper_frequencies().e_pa);
    assert_eq!(p[1].e_pa, 10e6);
    assert_eq!(p[1].thickness_um, 81.0);
    assert_eq!(p[1].thickness_um / 1e6, 81e-6);
    for m in &p {
        for (k, v) in [
            ("e_pa", m.e_pa),
            ("rho", m.rho),
            ("nu", m.nu),
            ("thickness_um", m.thickness_um),
        ] {
            let r = WING_PARAMS.iter().find(|q| q.key == k).unwrap();
            assert!(v >= r.min && v <= r.max, "{} {k}", m.id);
        }
    }
}

/// The wing input path solves to the same numbers as `compute_modes` on the equivalent
/// hand-built input (bit for bit: the same core function on the same input).
#[test]
fn wing_input_gives_the_same_modes_as_compute_modes() {
    let rect = builtin_planforms()
        .into_iter()
        .find(|b| b.id == "rect")
        .unwrap();
    let w = wing_input(
        [("n_modes", 3.0), ("mesh_mm", 2.0), ("camber", 0.0)],
        Some(rect.points_mm.clone()),
    )
    .unwrap();
    assert_eq!(w.planform_note, rect.note);
    let hand = FemInput {
        planform_mm: rect.points_mm.clone(),
        planform_note: rect.note.to_string(),
        camber: 0.0,
        n_modes: 3,
        mesh_size_mm: Some(2.0),
        ..FemInput::default()
    };
    let a = compute_modes(&w).unwrap();
    let b = compute_modes(&hand).unwrap();
    assert_eq!(a.freq_hz, b.freq_hz);
    assert_eq!(a.a, b.a);
    assert_eq!(a.strain_nodes, b.strain_nodes);
    // A flat 40 x 10 mm cantilever plate: f1 between the Euler-Bernoulli beam values
    // f1 = (1.875^2 / 2π) sqrt(B / (ρ t L^4)) with the beam stiffness B = E t^3 / 12 (narrow
    // strip) and the plate stiffness B = E t^3 / 12 (1 − ν^2) (wide plate).
    let m = ShellMaterial::paper_frequencies();
    let l: f64 = 0.040;
    let beam = |b: f64| {
        1.875f64.powi(2) / (2.0 * std::f64::consts::PI)
            * (b / (m.rho_kg_m3 * m.thickness_m * l.powi(4))).sqrt()
    };
    let narrow = beam(m.e_pa * m.thickness_m.powi(3) / 12.0);
    let wide = narrow / (1.0 - m.nu * m.nu).sqrt();
    assert!(
        a.freq_hz[0] > narrow && a.freq_hz[0] < wide,
        "f1 {} Hz outside the beam bracket [{narrow}, {wide}] Hz",
        a.freq_hz[0]
    );
}

#[test]
fn builtin_planforms_are_synthetic_valid_and_solve() {
    let b = builtin_planforms();
    let ids: Vec<&str> = b.iter().map(|p| p.id).collect();
    assert_eq!(ids, ["manduca", "slender", "broad", "rect"]);
    assert_eq!(b[0].points_mm, manduca_planform());
    for p in &b {
        assert!(p.label.contains("synthetic"), "{}", p.label);
        assert!(p.note.contains("synthetic"), "{}", p.note);
        // Already counter-clockwise and free of repeats: validation returns it unchanged.
        assert_eq!(
            validate_outline(&p.points_mm).unwrap(),
            p.points_mm,
            "{}",
            p.id
        );
        let s = outline_summary(&p.points_mm).unwrap();
        assert!(s.root_edge, "{}", p.id);
        assert_eq!(planform_note_for(&p.points_mm), p.note);
        // Meshes and solves with the root clamp at the automatic mesh size.
        let input = FemInput {
            planform_mm: p.points_mm.clone(),
            n_modes: 2,
            ..FemInput::default()
        };
        let fe = compute_modes(&input).unwrap_or_else(|e| panic!("{}: {e}", p.id));
        assert!(
            fe.freq_hz[0] > 1.0 && fe.freq_hz[1] > fe.freq_hz[0],
            "{}",
            p.id
        );
        // The paper's P lies inside every built-in outline.
        fe.strain_at(0, 3.0, -6.0)
            .unwrap_or_else(|e| panic!("{}: {e}", p.id));
    }
    assert!(planform_note_for(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]).contains("3 points"));
}

#[test]
fn outline_summary_against_closed_forms() {
    let s = outline_summary(&wingbeat::fem::rectangle_planform(40.0, 10.0)).unwrap();
    assert_eq!(s.area_mm2, 400.0);
    assert_eq!(s.span_mm, 40.0);
    assert_eq!(s.chord_mm, 10.0);
    assert_eq!(s.n_points, 4);
    assert!(s.root_edge);
    // Clockwise input with a closing copy: same area, three distinct points, no root edge.
    let tri = [[1.0, 0.0], [1.0, 2.0], [4.0, 0.0], [1.0, 0.0]];
    let s = outline_summary(&tri).unwrap();
    assert_eq!(s.area_mm2, 3.0);
    assert_eq!(s.n_points, 3);
    assert!(!s.root_edge);
    // The slender ellipse: area close to π/4 · span · root chord (polygon inscribed).
    let b = builtin_planforms();
    let s = outline_summary(&b[1].points_mm).unwrap();
    let ellipse = std::f64::consts::PI / 4.0 * 45.0 * 9.0;
    assert!(
        s.area_mm2 < ellipse && s.area_mm2 > 0.98 * ellipse,
        "{}",
        s.area_mm2
    );
    let m = message(outline_summary(&[
        [0.0, 0.0],
        [1.0, 1.0],
        [0.0, 1.0],
        [1.0, 0.0],
    ]));
    assert!(m.contains("self-intersecting"), "{m}");
}

// ---- Strain anywhere and whole-wing strain maps (src/analysis/strain.rs) ----

use wingbeat::analysis::strain::{
    modal_strains_at, strain_field, StrainComponent, StrainFieldOptions, StrainStat,
    MAX_STRAIN_FIELD_WORK,
};

fn coarse_wing() -> wingbeat::fem::FemModes {
    compute_modes(&FemInput {
        n_modes: 3,
        mesh_size_mm: Some(2.5),
        ..FemInput::default()
    })
    .unwrap()
}

/// `modal_strains_at` gives exactly the strains the FE modes report for their strain points
/// (`FemModes::strain_at` and the `modes` of `model_modes`), at P and elsewhere.
#[test]
fn modal_strains_at_equals_the_fe_modes_strain_points() {
    let fe = coarse_wing();
    let at = |x: f64, y: f64| {
        modal_strains_at(
            &fe.nodes,
            &fe.triangles,
            3,
            |k, i| fe.strain_nodes[k][i],
            x,
            y,
        )
    };
    let pts = [("P", 3.0, -6.0), ("Q", 20.0, -10.0), ("R", 40.0, -6.0)];
    let named: Vec<(String, f64, f64)> = pts
        .iter()
        .map(|(n, x, y)| (n.to_string(), *x, *y))
        .collect();
    let modes = fe.model_modes(0.0, &named, "point").unwrap();
    for (j, (name, x, y)) in pts.iter().enumerate() {
        let e = at(*x, *y).unwrap();
        assert_eq!(e.len(), 3);
        for k in 0..3 {
            let want = fe.strain_at(k, *x, *y).unwrap();
            for c in 0..3 {
                let tol = 1e-12 * want[c].abs().max(1e-300);
                assert!((e[k][c] - want[c]).abs() <= tol, "{name} mode {k} [{c}]");
            }
            let s = &modes[k].strains[j];
            assert_eq!(s.point, *name);
            for (got, want) in [
                (e[k][0], s.eps_x),
                (e[k][1], s.eps_y),
                (e[k][2], s.gamma_xy),
            ] {
                assert!(
                    (got - want).abs() <= 1e-12 * want.abs().max(1e-300),
                    "{name} {k}"
                );
            }
        }
    }
    // Outside the wing, and non-finite: errors naming the point.
    let m = message(at(60.0, -6.0));
    assert!(
        m.contains("point")
            && m.contains("(60, -6) mm")
            && m.contains("inside the meshed planform"),
        "{m}"
    );
    let m = message(at(f64::NAN, 0.0));
    assert!(m.contains("point"), "{m}");
}

fn series(n: usize, modes: usize) -> Vec<Vec<f64>> {
    (0..modes)
        .map(|k| {
            (0..n)
                .map(|i| {
                    let t = i as f64 * 1e-4;
                    (1.0 + k as f64)
                        * 1e-4
                        * (2.0 * std::f64::consts::PI * (62.5 + 20.0 * k as f64) * t).sin()
                        + 3e-5 * (2.0 * std::f64::consts::PI * 50.0 * t + k as f64).cos()
                })
                .collect()
        })
        .collect()
}

/// RMS from the modal covariance equals the brute-force time average over the samples to
/// 1e-12; the peak equals a brute-force maximum.
#[test]
fn strain_field_against_brute_force() {
    let fe = coarse_wing();
    let nn = fe.nodes.len();
    let qs = series(2001, 3);
    let refs: Vec<&[f64]> = qs.iter().map(Vec::as_slice).collect();
    let strain = |k: usize, i: usize| fe.strain_nodes[k][i];
    let brute = |i: usize, comp: StrainComponent| -> (f64, f64) {
        let (mut ss, mut peak) = (0.0, 0.0f64);
        for t in 0..qs[0].len() {
            let mut e = [0.0; 3];
            for k in 0..3 {
                for c in 0..3 {
                    e[c] += fe.strain_nodes[k][i][c] * qs[k][t];
                }
            }
            let v = match comp {
                StrainComponent::EpsX => e[0],
                StrainComponent::EpsY => e[1],
                StrainComponent::GammaXy => e[2],
                StrainComponent::VonMises => {
                    (e[0] * e[0] - e[0] * e[1] + e[1] * e[1] + 3.0 * (e[2] / 2.0).powi(2)).sqrt()
                }
            };
            ss += v * v;
            peak = peak.max(v.abs());
        }
        ((ss / qs[0].len() as f64).sqrt(), peak)
    };
    for comp in [
        StrainComponent::EpsX,
        StrainComponent::EpsY,
        StrainComponent::GammaXy,
        StrainComponent::VonMises,
    ] {
        let rms = strain_field(
            nn,
            3,
            strain,
            &refs,
            &StrainFieldOptions {
                component: comp,
                stat: StrainStat::Rms,
            },
        )
        .unwrap();
        let peak = strain_field(
            nn,
            3,
            strain,
            &refs,
            &StrainFieldOptions {
                component: comp,
                stat: StrainStat::Peak,
            },
        )
        .unwrap();
        assert_eq!(rms.len(), nn);
        let scale = rms.iter().fold(0.0f64, |m, v| m.max(*v));
        assert!(scale > 0.0);
        for i in (0..nn).step_by(7) {
            let (r, p) = brute(i, comp);
            assert!(
                (rms[i] - r).abs() <= 1e-12 * scale,
                "{comp:?} node {i}: {} vs {r}",
                rms[i]
            );
            assert!(
                (peak[i] - p).abs() <= 1e-12 * p.max(1e-300),
                "{comp:?} node {i}: {} vs {p}",
                peak[i]
            );
            assert!(peak[i] >= rms[i] * (1.0 - 1e-12));
        }
    }
    // The clamped root has no strain... but is never NaN; the default component is von Mises.
    let opts: StrainFieldOptions = serde_json::from_str(r#"{"stat": "rms"}"#).unwrap();
    assert_eq!(opts.component, StrainComponent::VonMises);
    assert!(serde_json::from_str::<StrainFieldOptions>(r#"{"stat": "rms", "x": 1}"#).is_err());
}

#[test]
fn strain_field_checks_its_series_and_caps_the_peak() {
    let strain = |_: usize, _: usize| [1.0, 0.0, 0.0];
    let rms = StrainFieldOptions {
        component: StrainComponent::EpsX,
        stat: StrainStat::Rms,
    };
    let q = [1.0, -1.0, 1.0];
    let short = [1.0, 2.0];
    let bad = [1.0, f64::NAN, 1.0];
    for (qs, want) in [
        (vec![&q[..]], "one series per mode (2)"),
        (vec![&q[..], &short[..]], "qs[1]"),
        (vec![&q[..], &bad[..]], "qs[1][1]"),
        (vec![&[][..], &[][..]], "qs[0]"),
    ] {
        let m = message(strain_field(4, 2, strain, &qs, &rms));
        assert!(m.contains(want), "`{m}` lacks {want}");
    }
    // Unit strain and q = ±1: RMS 1 and peak 1 everywhere (mode 1 only).
    let v = strain_field(4, 1, strain, &[&q[..]], &rms).unwrap();
    assert_eq!(v, vec![1.0; 4]);
    let n = (MAX_STRAIN_FIELD_WORK / 1000.0) as usize + 1;
    let long = vec![0.0; n];
    let peak = StrainFieldOptions {
        component: StrainComponent::EpsX,
        stat: StrainStat::Peak,
    };
    let m = message(strain_field(1000, 1, strain, &[&long[..]], &peak));
    assert!(m.contains("strain peak map") && m.contains("5e8"), "{m}");
}

// ---- Measured kinematics from a CSV table (src/kinematics_table.rs) ----

use wingbeat::kinematics::{Angle, Kinematics};
use wingbeat::kinematics_table::{
    kinematics_from_csv, AngleUnits, CsvKinematicsOptions, TableMethod,
};

const FD: f64 = 25.0;

/// The known stroke, rad: α = 0.1 + 0.8 sin θ + 0.05 sin(3θ + 0.4),
/// β = 0.5 sin(θ + 0.2) − 0.03 cos 2θ, γ = 0.2 sin θ, θ = 2π f_d t.
fn known(t: f64) -> [f64; 3] {
    let th = 2.0 * std::f64::consts::PI * FD * t;
    [
        0.1 + 0.8 * th.sin() + 0.05 * (3.0 * th + 0.4).sin(),
        0.5 * (th + 0.2).sin() - 0.03 * (2.0 * th).cos(),
        0.2 * th.sin(),
    ]
}

/// (n, sine coefficient, cosine coefficient) of the known series, per angle, and the means.
type Terms = [Vec<(f64, f64, f64)>; 3];

fn known_terms() -> ([f64; 3], Terms) {
    (
        [0.1, 0.0, 0.0],
        [
            vec![
                (1.0, 0.8, 0.0),
                (3.0, 0.05 * 0.4f64.cos(), 0.05 * 0.4f64.sin()),
            ],
            vec![
                (1.0, 0.5 * 0.2f64.cos(), 0.5 * 0.2f64.sin()),
                (2.0, 0.0, -0.03),
            ],
            vec![(1.0, 0.2, 0.0)],
        ],
    )
}

fn csv_of(times: &[f64], deg: bool) -> String {
    let mut s = String::from("# a synthetic measured stroke\nt,alpha,beta,gamma\n");
    for &t in times {
        let a = known(t);
        let f = |v: f64| if deg { v.to_degrees() } else { v };
        s.push_str(&format!(
            "{t:.17e},{:.17e},{:.17e},{:.17e}\n",
            f(a[0]),
            f(a[1]),
            f(a[2])
        ));
    }
    s
}

fn check_series_equal(k: &Kinematics, tol: f64) {
    let c = k.compile();
    let (means, terms) = known_terms();
    for (a, s) in [&c.alpha, &c.beta, &c.gamma].iter().enumerate() {
        assert!(
            (s.mean - means[a]).abs() <= tol,
            "angle {a} mean {}",
            s.mean
        );
        for t in &s.terms {
            let want = terms[a]
                .iter()
                .find(|w| w.0 == t.n)
                .map_or((0.0, 0.0), |w| (w.1, w.2));
            assert!(
                (t.s - want.0).abs() <= tol && (t.c - want.1).abs() <= tol,
                "angle {a} harmonic {}: ({}, {}) vs {want:?}",
                t.n,
                t.s,
                t.c
            );
        }
    }
}

#[test]
fn csv_on_a_grid_returns_the_known_series() {
    let period = 1.0 / FD;
    let times: Vec<f64> = (0..3 * 64).map(|i| i as f64 * period / 64.0).collect();
    let opts = CsvKinematicsOptions {
        units: AngleUnits::Deg,
        flap_hz: FD,
        max_harmonic: None,
    };
    let r = kinematics_from_csv(&csv_of(&times, true), &opts).unwrap();
    assert_eq!(r.method, TableMethod::Grid);
    assert_eq!(r.grid_points, 64);
    assert_eq!(r.n_periods, 3.0);
    check_series_equal(&r.kinematics, 1e-12);
    // The folded samples: t in [0, T), angles in rad, file order.
    assert_eq!(r.samples.t.len(), 192);
    assert!(r.samples.t.iter().all(|&x| (0.0..period).contains(&x)));
    assert!((r.samples.alpha[5] - known(times[5])[0]).abs() < 1e-12);
    // Ending on the period boundary (t = 3T included) is the same.
    let closed: Vec<f64> = (0..=3 * 64).map(|i| i as f64 * period / 64.0).collect();
    let r2 = kinematics_from_csv(&csv_of(&closed, true), &opts).unwrap();
    assert_eq!(r2.n_periods, 3.0);
    assert_eq!(r2.method, TableMethod::Grid);
    check_series_equal(&r2.kinematics, 1e-12);
    // A low-pass keeps the first two harmonics only.
    let lp = CsvKinematicsOptions {
        max_harmonic: Some(2),
        ..opts
    };
    let r3 = kinematics_from_csv(&csv_of(&times, true), &lp).unwrap();
    let a = r3.kinematics.alpha.series();
    assert_eq!(a.terms.len(), 2);
    assert!((a.terms[0].s - 0.8).abs() < 1e-12);
}

#[test]
fn csv_off_the_grid_is_fitted_by_least_squares() {
    let period = 1.0 / FD;
    // 4 periods of 50 samples each, jittered by up to ±0.3 of a step, starting off t = 0.
    let times: Vec<f64> = (0..200)
        .map(|i| {
            let jitter = 0.3 * ((i as f64 * 12.9898).sin() * 43758.5453).fract();
            0.0123 + (i as f64 + jitter) * period / 50.0
        })
        .collect();
    let opts = CsvKinematicsOptions {
        units: AngleUnits::Rad,
        flap_hz: FD,
        max_harmonic: Some(6),
    };
    let r = kinematics_from_csv(&csv_of(&times, false), &opts).unwrap();
    assert_eq!(r.method, TableMethod::LeastSquares);
    assert_eq!(r.max_harmonic, 6);
    assert_eq!(r.grid_points, 13);
    assert_eq!(r.n_periods, 4.0);
    check_series_equal(&r.kinematics, 1e-10);
    assert!(r.warnings.iter().any(|w| w.contains("least squares")));
    // The interpolant passes through the samples at their own times (the file's time axis).
    let c = r.kinematics.compile();
    for &t in times.iter().step_by(17) {
        let s = c.state(t);
        assert!((s.alpha - known(t)[0]).abs() < 1e-10);
        assert!((s.gamma - known(t)[2]).abs() < 1e-10);
    }
}

#[test]
fn csv_errors_name_the_column_line_and_range() {
    let o = |units| CsvKinematicsOptions {
        units,
        flap_hz: FD,
        max_harmonic: None,
    };
    let deg = o(AngleUnits::Deg);
    // Missing angles are zero; a `_deg` suffix matching the units is fine.
    let text = "t_s,alpha_deg\n0,0\n0.01,10\n0.02,0\n0.03,-10\n";
    let r = kinematics_from_csv(text, &deg).unwrap();
    assert_eq!(r.kinematics.beta, Angle::constant(0.0));
    assert_eq!(r.samples.beta, vec![0.0; 4]);
    assert!((r.kinematics.compile().state(0.01).alpha - 10f64.to_radians()).abs() < 1e-12);
    for (text, opts, want) in [
        (
            "t,alpha_rad\n0,0\n0.01,1\n0.02,0\n0.03,-1\n",
            deg,
            "column `alpha_rad`",
        ),
        ("t,alpha,wing\n0,0,0\n", deg, "column `wing`"),
        ("t,alpha\n0,0\n0.02,1\n0.01,0\n0.03,0\n", deg, "line 4 t"),
        ("t,alpha\n0,0\n0.01,1\n0.02,x\n", deg, "line 4"),
        ("t,alpha\n0,0\n0.01,400\n0.02,0\n", deg, "±2π rad"),
        ("t,alpha\n0,0\n0.01,1\n", deg, "3 to"),
        (
            "t,alpha\n0,0\n0.01,1\n0.02,0\n",
            deg,
            "one or more whole flap periods",
        ),
        ("alpha,beta\n0,0\n", deg, "`t`"),
        ("t\n0\n0.01\n0.02\n", deg, "at least one angle column"),
        ("t,alpha,alpha_deg\n0,0,0\n", deg, "repeats"),
    ] {
        let m = message(kinematics_from_csv(text, &opts));
        assert!(m.contains(want), "{text:?}: `{m}` lacks {want}");
    }
    let m = message(kinematics_from_csv(
        text,
        &CsvKinematicsOptions {
            flap_hz: 0.0,
            ..deg
        },
    ));
    assert!(m.contains("flap_hz"), "{m}");
    // A spreadsheet export: byte-order mark, quoted header, CRLF line ends.
    let xl = "\u{feff}\"t\",\"alpha\"\r\n0,0\r\n0.01,10\r\n0.02,0\r\n0.03,-10\r\n";
    assert_eq!(
        kinematics_from_csv(xl, &deg).unwrap().kinematics,
        kinematics_from_csv("t,alpha\n0,0\n0.01,10\n0.02,0\n0.03,-10\n", &deg)
            .unwrap()
            .kinematics
    );
    // Not a whole number of periods: folded anyway, with a warning.
    let r = kinematics_from_csv(
        "t,alpha\n0,0\n0.01,1\n0.02,0\n0.03,-1\n0.04,0\n0.05,1\n",
        &deg,
    )
    .unwrap();
    assert!(
        r.warnings.iter().any(|w| w.contains("not a whole number")),
        "{:?}",
        r.warnings
    );
}

/// A CSV through `wingbeat simulate --kinematics-csv` equals the same run from an equivalent
/// JSON config: sampled angles whose values are the known stroke on the grid, written by hand.
#[test]
fn cli_csv_flag_equals_the_equivalent_json_config() {
    let period = 1.0 / FD;
    let n = 40;
    let times: Vec<f64> = (0..2 * n).map(|i| i as f64 * period / n as f64).collect();
    let dir = std::env::temp_dir().join(format!("wingbeat-lab-api-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("stroke.csv");
    std::fs::write(&csv, csv_of(&times, true)).unwrap();
    let grid: Vec<[f64; 3]> = (0..n)
        .map(|j| known(j as f64 * period / n as f64))
        .collect();
    let sampled = |a: usize| Angle::Sampled {
        values: grid.iter().map(|v| v[a]).collect(),
        max_harmonic: None,
    };
    let cfg = wingbeat::config::SimConfig {
        kinematics: Kinematics {
            flap_freq_hz: FD,
            alpha: sampled(0),
            beta: sampled(1),
            gamma: sampled(2),
            body_rate: Default::default(),
        },
        duration_s: 0.2,
        ..wingbeat::config::SimConfig::paper()
    };
    let json = dir.join("config.json");
    std::fs::write(&json, serde_json::to_string(&cfg).unwrap()).unwrap();
    let run = |args: &[&str]| -> serde_json::Value {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_wingbeat"))
            .args(args)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice(&out.stdout).unwrap()
    };
    let a = run(&[
        "simulate",
        "--kinematics-csv",
        csv.to_str().unwrap(),
        "--kinematics-units",
        "deg",
        "--flap-hz",
        "25",
        "--duration",
        "0.2",
    ]);
    let b = run(&["simulate", "--config", json.to_str().unwrap()]);
    let mut compared = 0;
    for k in 0..2 {
        for key in ["total", "coriolis", "euler"] {
            let x = a["modes"][k]["q"][key].as_array().unwrap();
            let y = b["modes"][k]["q"][key].as_array().unwrap();
            assert_eq!(x.len(), y.len());
            let scale = y
                .iter()
                .fold(0.0f64, |m, v| m.max(v.as_f64().unwrap().abs()));
            for (u, v) in x.iter().zip(y) {
                let (u, v) = (u.as_f64().unwrap(), v.as_f64().unwrap());
                assert!((u - v).abs() <= 1e-10 * scale, "mode {k} {key}: {u} vs {v}");
                compared += 1;
            }
        }
        let fa = a["modes"][k]["floquet"]["effective_freq_hz"]
            .as_f64()
            .unwrap();
        let fb = b["modes"][k]["floquet"]["effective_freq_hz"]
            .as_f64()
            .unwrap();
        assert!((fa - fb).abs() <= 1e-10 * fb, "{fa} vs {fb}");
    }
    assert!(compared > 10_000);
    // In rad, with every period's samples the same numbers, the two runs agree to the bit: the
    // table's grid means are exactly the config's values. (The values are rounded to 1e-6 rad
    // so that the JSON config's short decimals parse exactly: serde_json's default float
    // parser may land one unit in the last place off a 17-digit number.)
    let grid6: Vec<[f64; 3]> = grid
        .iter()
        .map(|v| v.map(|x| (x * 1e6).round() / 1e6))
        .collect();
    let mut text = String::from("t,alpha,beta,gamma\n");
    for (i, &t) in times.iter().enumerate() {
        let v = grid6[i % n];
        text.push_str(&format!("{t:.17e},{},{},{}\n", v[0], v[1], v[2]));
    }
    std::fs::write(&csv, text).unwrap();
    let sampled6 = |a: usize| Angle::Sampled {
        values: grid6.iter().map(|v| v[a]).collect(),
        max_harmonic: None,
    };
    let cfg6 = wingbeat::config::SimConfig {
        kinematics: Kinematics {
            flap_freq_hz: FD,
            alpha: sampled6(0),
            beta: sampled6(1),
            gamma: sampled6(2),
            body_rate: Default::default(),
        },
        ..cfg
    };
    std::fs::write(&json, serde_json::to_string(&cfg6).unwrap()).unwrap();
    let raw = |args: &[&str]| -> Vec<u8> {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_wingbeat"))
            .args(args)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        out.stdout
    };
    let a = raw(&[
        "simulate",
        "--kinematics-csv",
        csv.to_str().unwrap(),
        "--kinematics-units",
        "rad",
        "--flap-hz",
        "25",
        "--duration",
        "0.2",
        "--format",
        "csv",
    ]);
    let b = raw(&[
        "simulate",
        "--config",
        json.to_str().unwrap(),
        "--format",
        "csv",
    ]);
    assert!(a.len() > 10_000);
    assert!(a == b, "CSV-flag run and JSON-config run differ");
    // Without units: an error naming the flag.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_wingbeat"))
        .args(["simulate", "--kinematics-csv", csv.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--kinematics-units"));
    let _ = std::fs::remove_dir_all(&dir);
}

// ---- Reading modes documents (src/modes_doc.rs) ----

use wingbeat::modes_doc::{modes_from_json, read_modes_document};

/// Numbers equal to within 2 units in the last place (serde_json writes the shortest
/// round-tripping text, but its default parser may land one ulp off).
fn ulps(a: f64, b: f64) -> bool {
    (a - b).abs() <= 4.5e-16 * a.abs().max(b.abs())
}

fn same_modes(a: &[wingbeat::model::Mode], b: &[wingbeat::model::Mode]) {
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(b) {
        assert_eq!((&x.name, x.zeta), (&y.name, y.zeta));
        assert!(ulps(x.freq_hz, y.freq_hz) && ulps(x.a[0], y.a[0]) && ulps(x.a[1], y.a[1]));
        assert_eq!(x.strains.len(), y.strains.len());
        for (s, t) in x.strains.iter().zip(&y.strains) {
            assert_eq!(s.point, t.point);
            assert!(
                ulps(s.eps_x, t.eps_x) && ulps(s.eps_y, t.eps_y) && ulps(s.gamma_xy, t.gamma_xy)
            );
        }
    }
}

/// A `wingbeat modes` document (the one writer, `fem::modes_document`) reads back to the same
/// modes and the same FE result (to the last place).
#[test]
fn modes_document_round_trips() {
    let fe = coarse_wing();
    let modes = fe
        .model_modes(0.02, &[("P".to_string(), 3.0, -6.0)], "point")
        .unwrap();
    let text = wingbeat::fem::modes_document(&fe, &modes).unwrap();
    let doc = read_modes_document(&text, "doc").unwrap();
    same_modes(&doc.modes, &modes);
    let back = doc.fe.as_ref().unwrap();
    assert_eq!(back.triangles, fe.triangles);
    assert_eq!(back.kinds, fe.kinds);
    assert_eq!(back.mesh_size_mm, fe.mesh_size_mm);
    for (k, (x, y)) in back.strain_nodes.iter().zip(&fe.strain_nodes).enumerate() {
        for (p, q) in x.iter().zip(y) {
            assert!((0..3).all(|c| ulps(p[c], q[c])), "mode {k}");
        }
    }
    for (x, y) in back.shapes.iter().flatten().zip(fe.shapes.iter().flatten()) {
        assert!(ulps(*x, *y));
    }
    same_modes(&modes_from_json(&text, "doc").unwrap(), &modes);
    // A plain `{"modes": [...]}` has no FE part; a key outside a `wingbeat modes` document's
    // is refused (issue 13: no key silently ignored).
    let plain = format!(
        r#"{{"units": {{}}, "modes": {}}}"#,
        serde_json::to_string(&modes).unwrap()
    );
    let extra = plain.replacen('{', r#"{"comment": "x", "#, 1);
    let e = read_modes_document(&extra, "doc").unwrap_err().to_string();
    assert!(e.contains("unknown top-level key `comment`"), "{e}");
    let doc = read_modes_document(&plain, "doc").unwrap();
    same_modes(&doc.modes, &modes);
    assert!(doc.fe.is_none());
    // The FE arrays alone: modes from freq_hz, a and kinds.
    let arrays = r#"{"freq_hz": [60, 90], "a": [[1e-4, 2e-5], [3e-5, -1e-5]], "kinds": ["spanwise bending"]}"#;
    let m = modes_from_json(arrays, "doc").unwrap();
    assert_eq!(m[0].name, "1: spanwise bending");
    assert_eq!(m[1].name, "2: FE mode");
    assert_eq!(m[1].a, [3e-5, -1e-5]);
}

#[test]
fn modes_document_errors_name_the_part() {
    let fe = coarse_wing();
    let modes = fe.to_modes(0.0, &[]);
    let good: serde_json::Value =
        serde_json::from_str(&wingbeat::fem::modes_document(&fe, &modes).unwrap()).unwrap();
    let broken = |f: &dyn Fn(&mut serde_json::Value)| {
        let mut v = good.clone();
        f(&mut v);
        message(read_modes_document(&v.to_string(), "wing.json"))
    };
    let m = broken(&|v| {
        v["shapes"].as_array_mut().unwrap().pop();
    });
    assert!(m.contains("wing.json: fe") && m.contains("`shapes`"), "{m}");
    let m = broken(&|v| {
        v["shapes"][1].as_array_mut().unwrap().pop();
    });
    assert!(m.contains("mode 2"), "{m}");
    let m = broken(&|v| v["triangles"][0][1] = serde_json::json!(1_000_000));
    assert!(m.contains("triangle 0"), "{m}");
    let m = broken(&|v| v["modes"][0]["freq_hz"] = serde_json::json!(-1));
    assert!(m.contains("modes[0].freq_hz"), "{m}");
    let m = broken(&|v| v["nodes"] = serde_json::json!("x"));
    assert!(m.contains("wing.json: fe"), "{m}");
    for (text, want) in [
        ("{", "wing.json"),
        (r#"{"x": 1}"#, "expected `modes` or `freq_hz`"),
        (
            r#"{"freq_hz": [1], "a": []}"#,
            "1 frequencies but 0 a-vectors",
        ),
        (r#"{"modes": []}"#, "1 to 64 modes"),
        (r#"{"modes": [{"freq_hz": 5}]}"#, "wing.json: at `modes[0]`"),
    ] {
        let m = message(read_modes_document(text, "wing.json"));
        assert!(m.contains(want), "{text}: `{m}` lacks {want}");
    }
}

/// Extreme inputs give named errors, never NaN or infinite values.
#[test]
fn extreme_inputs_never_give_nan() {
    let big = |_: usize, _: usize| [1e300, -1e300, 1e300];
    let q = [1e300, -1e300];
    for stat in [StrainStat::Rms, StrainStat::Peak] {
        let opts = StrainFieldOptions {
            component: StrainComponent::VonMises,
            stat,
        };
        let m = message(strain_field(2, 1, big, &[&q[..]], &opts));
        assert!(m.contains("strain map at node 0"), "{m}");
    }
    let nodes = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let tris = [[0usize, 1, 2]];
    let s = |_: usize, _: usize| [1.0, 2.0, 3.0];
    let e = modal_strains_at(&nodes, &tris, 1, s, 100.0, 100.0).unwrap();
    assert_eq!(e, vec![[1.0, 2.0, 3.0]]);
    let m = message(modal_strains_at(&nodes, &tris, 1, s, 1e305, 0.0));
    assert!(m.contains("point") && m.contains("within"), "{m}");
    let opts = CsvKinematicsOptions {
        units: AngleUnits::Rad,
        flap_hz: FD,
        max_harmonic: None,
    };
    let m = message(kinematics_from_csv(
        "t,alpha\n-1e308,0\n0,1\n1e308,0\n",
        &opts,
    ));
    assert!(m.contains("t"), "{m}");
}
