//! The sparse factorisation backends (`wingbeat::fem::linalg`) agree: same frequencies to
//! 1e-9 relative (the default block-sparse LDLᵀ and the skyline: 1e-10), the same mode shapes
//! and strains, residuals within tolerance on a plate and on the default wing; the Sturm count
//! works through the backend trait (skyline and block-sparse LDLᵀ: inertia of an indefinite
//! K − μM; faer's Cholesky reports no inertia there).

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::fem::assembly::{assemble, assemble_blocks};
use wingbeat::fem::blocksparse::{BlockLdlt, BlockSym};
use wingbeat::fem::linalg::{sturm_count, SkylineLdlt, SparseLdlt};
use wingbeat::fem::mesh::mesh_planform;
use wingbeat::fem::*;

fn steel() -> ShellMaterial {
    ShellMaterial {
        thickness_m: 0.05,
        e_pa: 200e9,
        rho_kg_m3: 8000.0,
        nu: 0.3,
    }
}

fn plate_input(n_modes: usize) -> FemInput {
    FemInput {
        planform_mm: rectangle_planform(10_000.0, 10_000.0),
        planform_note: "10 m square plate".into(),
        camber: 0.0,
        clamp: Clamp::Root,
        material: steel(),
        n_modes,
        mesh_size_mm: Some(1000.0),
        max_nodes: None,
    }
}

fn with(backend: Backend) -> EigenOptions {
    EigenOptions {
        backend,
        ..EigenOptions::default()
    }
}

#[test]
fn default_backend_is_sparse_and_always_available() {
    assert_eq!(EigenOptions::default().backend, Backend::Sparse);
    assert!(Backend::Sparse.available());
    assert!(Backend::Skyline.available());
    let b: Backend = serde_json::from_str("\"sparse\"").unwrap();
    assert_eq!(b, Backend::Sparse);
    assert_eq!(Backend::Faer.available(), cfg!(feature = "faer"));
    let b: Backend = serde_json::from_str("\"faer\"").unwrap();
    assert_eq!(b, Backend::Faer);
}

#[cfg(not(feature = "faer"))]
#[test]
fn faer_backend_without_the_feature_is_an_input_error() {
    let input = plate_input(3);
    let e = compute_modes_with(&input, with(Backend::Faer)).unwrap_err();
    assert!(e.to_string().contains("faer"), "{e}");
}

#[test]
fn sturm_count_through_the_backend_trait() {
    let input = plate_input(7);
    let r = compute_modes_with(&input, with(Backend::Skyline)).unwrap();
    let lam: Vec<f64> = r
        .freq_hz
        .iter()
        .map(|f| (2.0 * std::f64::consts::PI * f).powi(2))
        .collect();
    let outline = geometry::validate_outline(&input.planform_mm).unwrap();
    let mesh = mesh_planform(&outline, input.mesh_size_mm.unwrap(), 0.0).unwrap();
    let clamped = clamp_nodes(&outline, &mesh, Clamp::Root).unwrap();
    let asm = assemble(&mesh, &steel(), &clamped).unwrap();
    for k in 1..7 {
        let mu = 0.5 * (lam[k - 1] + lam[k]);
        assert_eq!(
            sturm_count::<SkylineLdlt>(&asm.k, &asm.m, mu),
            Some(k),
            "{k} eigenvalues below μ"
        );
    }
    assert_eq!(
        sturm_count::<SkylineLdlt>(&asm.k, &asm.m, 0.5 * lam[0]),
        Some(0)
    );
    // the block-sparse LDLᵀ has the inertia too (its own assembly and ordering)
    let blk = assemble_blocks(&mesh, &steel(), &clamped).unwrap();
    for k in 1..7 {
        let mu = 0.5 * (lam[k - 1] + lam[k]);
        assert_eq!(
            sturm_count::<SparseLdlt>(&blk.k, &blk.m, mu),
            Some(k),
            "{k} eigenvalues below μ (sparse)"
        );
    }
    assert_eq!(
        sturm_count::<SparseLdlt>(&blk.k, &blk.m, 0.5 * lam[0]),
        Some(0)
    );
    #[cfg(feature = "faer")]
    {
        use wingbeat::fem::linalg::FaerLlt;
        // below λ1 the Cholesky succeeds (no negative pivot); above it, it fails: no inertia
        assert_eq!(
            sturm_count::<FaerLlt>(&asm.k, &asm.m, 0.5 * lam[0]),
            Some(0)
        );
        assert_eq!(
            sturm_count::<FaerLlt>(&asm.k, &asm.m, 0.5 * (lam[5] + lam[6])),
            None
        );
    }
}

#[cfg(feature = "faer")]
mod faer_vs_skyline {
    use super::*;

    fn agree(input: &FemInput) {
        let a = compute_modes_with(input, with(Backend::Skyline)).unwrap();
        let b = compute_modes_with(input, with(Backend::Faer)).unwrap();
        assert_eq!(a.freq_hz.len(), b.freq_hz.len());
        for (k, (fa, fb)) in a.freq_hz.iter().zip(&b.freq_hz).enumerate() {
            let rel = ((fa - fb) / fa).abs();
            println!(
                "mode {}: skyline {fa:.9} Hz, faer {fb:.9} Hz, rel {rel:.1e}",
                k + 1
            );
            assert!(rel < 1e-9, "mode {}: {fa} vs {fb} ({rel:e})", k + 1);
        }
        for r in [&a, &b] {
            assert!(r.residuals.iter().all(|&x| x < 1e-6), "{:?}", r.residuals);
            assert!(
                r.mass_orthonormality_error < 1e-10,
                "{}",
                r.mass_orthonormality_error
            );
        }
        // same modes: the shapes match up to sign
        for (sa, sb) in a.shapes.iter().zip(&b.shapes) {
            let dot: f64 = sa.iter().zip(sb).map(|(x, y)| x * y).sum();
            let na: f64 = sa.iter().map(|x| x * x).sum::<f64>().sqrt();
            let nb: f64 = sb.iter().map(|x| x * x).sum::<f64>().sqrt();
            assert!(
                (dot.abs() / (na * nb) - 1.0).abs() < 1e-6,
                "{dot} {na} {nb}"
            );
        }
    }

    #[test]
    fn plate_frequencies_and_residuals_agree() {
        agree(&plate_input(7));
    }

    #[test]
    fn default_wing_coarse_mesh_agrees() {
        agree(&FemInput {
            mesh_size_mm: Some(2.0),
            ..FemInput::default()
        });
    }
}

/// The block-sparse LDLᵀ solves K − σM exactly: ‖(K − σM)x − b‖ at rounding level, on the
/// default wing's coarse mesh, and its matrix equals the skyline's (same assembly, blocks).
#[test]
fn block_ldlt_solves_and_matches_the_skyline_matrix() {
    let input = FemInput {
        mesh_size_mm: Some(2.0),
        ..FemInput::default()
    };
    let outline = geometry::validate_outline(&input.planform_mm).unwrap();
    let mesh = mesh_planform(&outline, 2.0, input.camber).unwrap();
    let clamped = clamp_nodes(&outline, &mesh, Clamp::Root).unwrap();
    let sky = assemble(&mesh, &input.material, &clamped).unwrap();
    let blk = assemble_blocks(&mesh, &input.material, &clamped).unwrap();
    let n = blk.k.n();
    assert_eq!(n, sky.k.n);
    // K x through both storages, in the skyline's and the block numbering
    let x_node: Vec<f64> = (0..n)
        .map(|i| ((i * 37 % 101) as f64 - 50.0) / 50.0)
        .collect();
    let mut xs = vec![0.0; n];
    let mut xb = vec![0.0; n];
    for (node, e) in sky.eq.iter().enumerate() {
        for d in 0..6 {
            if e[d] != assembly::CLAMPED {
                xs[e[d]] = x_node[blk.eq[node][d]];
                xb[blk.eq[node][d]] = x_node[blk.eq[node][d]];
            }
        }
    }
    let (mut ys, mut yb) = (vec![0.0; n], vec![0.0; n]);
    sky.k.matvec(&xs, &mut ys);
    blk.k.matvec(&xb, &mut yb);
    let scale = yb.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for (node, e) in sky.eq.iter().enumerate() {
        for d in 0..6 {
            if e[d] != assembly::CLAMPED {
                let diff = (ys[e[d]] - yb[blk.eq[node][d]]).abs();
                assert!(diff <= 1e-12 * scale, "node {node} dof {d}: {diff:e}");
            }
        }
    }
    // from_skyline gives the same operator in the skyline's numbering
    let conv = BlockSym::from_skyline(&sky.k);
    let mut yc = vec![0.0; n];
    conv.matvec(&xs, &mut yc);
    for i in 0..n {
        assert!((yc[i] - ys[i]).abs() <= 1e-12 * scale);
    }
    // solve with a shift and check the residual
    let shift = -1e3;
    let f = BlockLdlt::factor(&blk.k, shift, &blk.m).unwrap();
    assert_eq!(f.negatives(), 0);
    let mut sol = xb.clone();
    f.solve_in_place(&mut sol);
    let mut r = vec![0.0; n];
    blk.k.matvec(&sol, &mut r);
    let bnorm = xb.iter().map(|v| v * v).sum::<f64>().sqrt();
    let res = r
        .iter()
        .zip(&sol)
        .zip(&blk.m)
        .zip(&xb)
        .map(|(((kx, x), m), b)| (kx - shift * m * x - b).powi(2))
        .sum::<f64>()
        .sqrt();
    // normwise backward error (K spans ~10 decades between translations and rotations, so
    // the residual is measured against ‖K − σM‖_F ‖x‖ + ‖b‖)
    let knorm = (blk.k.val.iter().enumerate().fold(0.0, |s, (p, b)| {
        let w = if blk.k.row[p] == blk.k.row[blk.k.col_ptr.partition_point(|&c| c <= p) - 1] {
            1.0
        } else {
            2.0
        };
        s + w * b.iter().map(|v| v * v).sum::<f64>()
    }))
    .sqrt();
    let xnorm = sol.iter().map(|v| v * v).sum::<f64>().sqrt();
    let backward = res / (knorm * xnorm + bnorm);
    println!("backward error {backward:.2e}");
    assert!(backward <= 1e-13, "backward error {backward:e}");
    // the factor is much smaller than the RCM envelope
    let sym = f.symbolic();
    assert!(36 * sym.fill_blocks() + 21 * blk.k.nb < sky.k.stored());
}

fn agree_sparse_skyline(input: &FemInput, tol: f64) {
    let a = compute_modes_with(input, with(Backend::Skyline)).unwrap();
    let b = compute_modes_with(input, with(Backend::Sparse)).unwrap();
    assert_eq!(a.freq_hz.len(), b.freq_hz.len());
    for (k, (fa, fb)) in a.freq_hz.iter().zip(&b.freq_hz).enumerate() {
        let rel = ((fa - fb) / fa).abs();
        println!(
            "mode {}: skyline {fa:.12} Hz, sparse {fb:.12} Hz, rel {rel:.1e}",
            k + 1
        );
        assert!(rel < tol, "mode {}: {fa} vs {fb} ({rel:e})", k + 1);
    }
    assert!(b.residuals.iter().all(|&x| x < 1e-6), "{:?}", b.residuals);
    assert!(b.mass_orthonormality_error < 1e-10);
    // the same nodes, the same signed shapes and strains (both sign conventions applied)
    assert_eq!(a.nodes, b.nodes);
    for (sa, sb) in a.shapes.iter().zip(&b.shapes) {
        let na = sa.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (x, y) in sa.iter().zip(sb) {
            assert!((x - y).abs() <= 1e-6 * na, "{x} vs {y}");
        }
    }
}

#[test]
fn sparse_and_skyline_agree_on_the_plate() {
    agree_sparse_skyline(&plate_input(7), 1e-9);
}

#[test]
fn sparse_and_skyline_agree_on_the_default_wing() {
    agree_sparse_skyline(&FemInput::default(), 1e-9);
}
