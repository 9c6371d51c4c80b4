//! The default (synthetic Manduca-like) wing: calibrated frequencies, the camber effect,
//! the root boundary-condition sensitivity, a_k / mass bookkeeping and modal strains.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::fem::*;

fn wing(h: f64, camber: f64, clamp: Clamp) -> FemModes {
    compute_modes(&FemInput {
        mesh_size_mm: Some(h),
        camber,
        clamp,
        ..FemInput::default()
    })
    .expect("wing solves")
}

#[test]
fn default_wing_reproduces_paper_f1_and_mode_types() {
    let input = FemInput::default();
    // the default input leaves the mesh size automatic, which gives the default wing 1.0 mm
    assert_eq!(input.mesh_size_mm, None);
    assert_eq!(
        default_mesh_size_mm(&input.planform_mm),
        DEFAULT_MESH_SIZE_MM
    );
    let r = compute_modes(&input).unwrap();
    assert_eq!(r.mesh_size_mm, DEFAULT_MESH_SIZE_MM);
    println!(
        "default wing: nodes {}, dofs {}, f = {:.2?}, kinds {:?}",
        r.nodes.len(),
        r.n_dofs,
        r.freq_hz,
        r.kinds
    );
    assert!((r.freq_hz[0] - 62.5).abs() < 0.6, "f1 = {}", r.freq_hz[0]);
    assert_eq!(r.kinds[0], "spanwise bending");
    assert_eq!(r.kinds[1], "torsion");
    assert!(r.mass_orthonormality_error < 1e-10);
    assert!(r.residuals.iter().all(|&x| x < 1e-6), "{:?}", r.residuals);
    assert!(r.planform_note.contains("NOT digitised"));
    // mass: ρ t × (cambered) area; the flat area is 8.70 cm²
    let flat = 860.0 * 81e-6 * 8.70e-4;
    assert!(
        r.mass_kg > flat && r.mass_kg < 1.08 * flat,
        "mass {}",
        r.mass_kg
    );
    // a_k: mode 1 (bending, all same sign) has a_x of order 1e-4 kg^½·m, and b = rot90(a)
    assert!(r.a[0][0] > 5e-5 && r.a[0][0] < 5e-4, "a1 = {:?}", r.a[0]);
    for (a, b) in r.a.iter().zip(&r.b) {
        assert_eq!(*b, [-a[1], a[0]]);
    }
    // a_k from the JSON-facing fields: Σ m_i w_i (x_i, y_i) recomputed from shapes
    let json = serde_json::to_value(&r).unwrap();
    for key in [
        "freq_hz",
        "a",
        "b",
        "mass_kg",
        "centre_of_mass_m",
        "nodes",
        "triangles",
        "shapes",
        "strain_nodes",
        "residuals",
        "kinds",
        "planform_note",
    ] {
        assert!(json.get(key).is_some(), "missing {key}");
    }
}

#[test]
fn paper_as_printed_material_gives_under_2_hz() {
    let r = compute_modes(&FemInput {
        material: ShellMaterial::paper_as_printed(),
        mesh_size_mm: Some(2.0),
        n_modes: 2,
        ..FemInput::default()
    })
    .unwrap();
    // frequencies scale with √E: 10 MPa instead of ≈ 12 GPa
    println!("paper-as-printed: f = {:.3?}", r.freq_hz);
    assert!(r.freq_hz[0] > 1.6 && r.freq_hz[0] < 2.0, "{:?}", r.freq_hz);
}

#[test]
fn camber_raises_f1_about_three_and_a_half_times() {
    let flat = wing(2.0, 0.0, Clamp::Root);
    let curved = wing(2.0, 0.13, Clamp::Root);
    let ratio = curved.freq_hz[0] / flat.freq_hz[0];
    println!(
        "f1 flat {:.2} Hz, cambered {:.2} Hz, ratio {ratio:.3}",
        flat.freq_hz[0], curved.freq_hz[0]
    );
    assert!(ratio > 3.3 && ratio < 3.8, "ratio {ratio}");
    // a plate (no membrane–bending coupling) would not feel the camber at all: the flat wing
    // keeps the same mesh-converged f1 within 1 % at two meshes
    let flat2 = wing(3.0, 0.0, Clamp::Root);
    assert!((flat2.freq_hz[0] / flat.freq_hz[0] - 1.0).abs() < 0.01);
}

#[test]
fn root_clamp_vs_basal_strip_changes_f2_over_f1() {
    let root = wing(2.0, 0.13, Clamp::Root);
    let strip = wing(2.0, 0.13, Clamp::Strip { x_mm: 3.0 });
    let (r1, r2) = (
        root.freq_hz[1] / root.freq_hz[0],
        strip.freq_hz[1] / strip.freq_hz[0],
    );
    println!(
        "f2/f1: root clamp {r1:.3}, 3 mm strip {r2:.3}; strip f = {:.1?}",
        strip.freq_hz
    );
    assert!(r1 > 2.8 && r1 < 3.4, "{r1}");
    assert!(r2 > 1.2 && r2 < 1.5, "{r2}");
    assert!(strip.clamped_nodes.len() > root.clamped_nodes.len());
}

#[test]
fn modal_strains_and_to_modes() {
    let r = wing(2.0, 0.13, Clamp::Root);
    let pts = vec![
        ("root".to_string(), 2.0, -2.0),
        ("mid".to_string(), 20.0, -10.0),
    ];
    let modes = r.to_modes(0.01, &pts);
    assert_eq!(modes.len(), 6);
    for (k, m) in modes.iter().enumerate() {
        assert_eq!(m.freq_hz, r.freq_hz[k]);
        assert_eq!(m.a, r.a[k]);
        assert_eq!(m.zeta, 0.01);
        assert!(m.name.starts_with(&format!("{}: ", k + 1)));
        assert_eq!(m.strains.len(), 2);
        m.validate(k).unwrap();
        for s in &m.strains {
            assert!(s.eps_x.is_finite() && s.eps_y.is_finite() && s.gamma_xy.is_finite());
        }
        let e = r.strain_at(k, 2.0, -2.0).unwrap();
        assert_eq!(
            [
                m.strains[0].eps_x,
                m.strains[0].eps_y,
                m.strains[0].gamma_xy
            ],
            e
        );
    }
    // mode 1 (spanwise bending) strains the root region far more than the outer wing
    let root = r.strain_at(0, 2.0, -2.0).unwrap();
    let tip = r.strain_at(0, 45.0, -5.0).unwrap();
    let mag = |e: [f64; 3]| e.iter().map(|x| x * x).sum::<f64>().sqrt();
    assert!(mag(root) > 3.0 * mag(tip), "{root:?} vs {tip:?}");
    assert!(r.strain_at(0, 80.0, 0.0).is_err());
    assert!(r.strain_at(9, 2.0, -2.0).is_err());
}
