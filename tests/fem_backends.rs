//! The sparse factorisation backends (`wingbeat::fem::linalg`) agree: same frequencies to
//! 1e-9 relative and residuals within tolerance on a plate and on the default wing at a coarse
//! mesh; the Sturm count works through the backend trait (skyline: inertia of an indefinite
//! K − μM; faer's Cholesky reports no inertia there, so the Sturm check stays on the skyline).

use wingbeat::fem::assembly::assemble;
use wingbeat::fem::linalg::{sturm_count, SkylineLdlt};
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
fn default_backend_is_skyline_and_always_available() {
    assert_eq!(EigenOptions::default().backend, Backend::Skyline);
    assert!(Backend::Skyline.available());
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
