//! The paper's data (Jankauski & Shen, Tables 3–6) as ready-made inputs.
//!
//! Caveats (see `docs/model.md`): Table 4's a_k are used exactly as printed, although they are not
//! SI values for mass-normalised modes (for a ≈ 60 mg wing, |a_x| of mode 1 should be of order
//! 1e-4 kg^½·m). Every response of a mode scales with its a_k, so relative results — force
//! contributions, spectra shapes, beat periods — are unaffected; absolute q and strain are not
//! physical in SI with this preset.

use crate::kinematics::Kinematics;
use crate::model::{ModalStrain, Mode};

/// Table 3: natural frequencies of the paper wing, Hz.
pub const PAPER_FREQ_HZ: [f64; 2] = [62.5, 86.9];
/// Table 3: frequencies reported for the real Manduca forewing, Hz.
pub const INSECT_FREQ_HZ: [f64; 2] = [60.0, 84.0];
/// Table 4: a_1 (I″, J″) as printed.
pub const PAPER_A1: [f64; 2] = [0.7552e-5, 0.0934e-5];
/// Table 4: a_2 (I″, J″) as printed.
pub const PAPER_A2: [f64; 2] = [-0.1728e-5, -0.0033e-5];
/// Table 6: modal strains at the root point P, mode 1 (ε_x, ε_y, γ_xy).
pub const PAPER_STRAIN1: [f64; 3] = [256.0, -1577.0, 691.0];
/// Table 6: modal strains at P, mode 2.
pub const PAPER_STRAIN2: [f64; 3] = [-161.0, 96.7, 1710.0];

/// The paper's two modes with Table 3 frequencies, Table 4 vectors and Table 6 strains at P,
/// all with damping ratio `zeta` (the paper: 0, and 0.01 in §4.3).
pub fn paper_modes(zeta: f64) -> Vec<Mode> {
    let strain = |s: [f64; 3]| {
        vec![ModalStrain {
            point: "P".into(),
            eps_x: s[0],
            eps_y: s[1],
            gamma_xy: s[2],
        }]
    };
    vec![
        Mode {
            name: "1: spanwise bending".into(),
            freq_hz: PAPER_FREQ_HZ[0],
            a: PAPER_A1,
            zeta,
            strains: strain(PAPER_STRAIN1),
        },
        Mode {
            name: "2: spanwise torsion".into(),
            freq_hz: PAPER_FREQ_HZ[1],
            a: PAPER_A2,
            zeta,
            strains: strain(PAPER_STRAIN2),
        },
    ]
}

/// Forward flight (Table 5): α0 = 0.8, β0 = 0.5, γ0 = 0.2 rad, f_d = 25 Hz.
pub fn paper_kinematics() -> Kinematics {
    Kinematics::paper_forward_flight()
}

/// Number of shell-FE modes in the `fe-wing` preset.
pub const FE_WING_MODES: usize = 4;

/// The modes of the `fe-wing` preset: the first [`FE_WING_MODES`] shell-FE modes of the
/// default wing (the synthetic Manduca-like outline, 13 % camber, root clamp,
/// "paper-frequencies" material, 1 mm elements): SI a_k in kg^½·m and the modal strains at
/// P = [`crate::fem::STRAIN_POINT_P_MM`]. Takes about a second natively. The whole preset
/// (these modes under the paper's kinematics) is [`crate::config::SimConfig::fe_wing`].
pub fn fe_wing_modes() -> crate::Result<Vec<Mode>> {
    Ok(fe_wing_modes_and_wing()?.0)
}

/// [`fe_wing_modes`] and the wing's mesh and mode shapes, which the air needs
/// ([`crate::aero::WingGeometry`]).
pub fn fe_wing_modes_and_wing() -> crate::Result<(Vec<Mode>, crate::aero::WingGeometry)> {
    let input = crate::fem::FemInput {
        n_modes: FE_WING_MODES,
        ..Default::default()
    };
    let fe = crate::fem::compute_modes(&input)?;
    let (x, y) = crate::fem::STRAIN_POINT_P_MM;
    let modes = fe.model_modes(0.0, &[("P".to_string(), x, y)], "strain point")?;
    Ok((modes, crate::aero::WingGeometry::from_fem(&fe)))
}

/// Names of the built-in presets.
pub const PRESETS: [&str; 2] = ["paper", "fe-wing"];

/// Span of the published sensing plate, mm (Eberle et al. 2015; Mohren et al. 2018).
pub const MOHREN2018_SPAN_MM: f64 = 50.0;
/// Chord of the published sensing plate, mm; the clamped root edge has this length.
pub const MOHREN2018_CHORD_MM: f64 = 25.0;
/// Mass-proportional damping of the published plate, C = 63 s⁻¹ · M, in s⁻¹.
pub const MOHREN2018_DAMPING_PER_S: f64 = 63.0;

/// The published plate's material: acrylic, h = 0.127 mm, E = 3 GPa, ρ = 1180 kg/m³, ν = 0.35.
pub fn mohren2018_material() -> crate::fem::ShellMaterial {
    crate::fem::ShellMaterial {
        thickness_m: 0.127e-3,
        e_pa: 3.0e9,
        rho_kg_m3: 1180.0,
        nu: 0.35,
    }
}

/// The sensing plate of Mohren et al. 2018 (PNAS 115:10564) and Weber et al. 2021 (PLOS
/// Comput. Biol. 17:e1009195), taken from Eberle et al. 2015 (J. R. Soc. Interface
/// 12:20141088): a flat rectangle, [`MOHREN2018_SPAN_MM`] span × [`MOHREN2018_CHORD_MM`]
/// chord, its 25 mm root edge (x = 0) clamped, acrylic ([`mohren2018_material`]). The
/// published model is a single Rayleigh–Ritz plate element; this is the same plate for the
/// shell FE. In wingbeat's frame x runs spanwise from the root and the chord lies toward −y.
///
/// `mesh_size_mm`: target element edge (`None` = automatic); `n_modes`: 1 ..= 64. Both are
/// checked when the input is solved ([`crate::fem::compute_modes`]).
pub fn mohren2018_plate_input(mesh_size_mm: Option<f64>, n_modes: usize) -> crate::fem::FemInput {
    crate::fem::FemInput {
        planform_mm: crate::fem::rectangle_planform(MOHREN2018_SPAN_MM, MOHREN2018_CHORD_MM),
        planform_note: "Mohren et al. 2018 plate (Eberle et al. 2015): 50 × 25 mm, root clamped"
            .into(),
        camber: 0.0,
        clamp: crate::fem::Clamp::Root,
        material: mohren2018_material(),
        n_modes,
        mesh_size_mm,
        max_nodes: None,
    }
}

/// Modal damping ratios of the published mass-proportional damping C = 63 s⁻¹ · M:
/// ζ_k = 63 / (2 ω_k) with ω_k = 2π f_k. Every frequency must be finite and positive
/// (error names `freq_hz[k]`).
pub fn mohren2018_damping_ratios(freq_hz: &[f64]) -> crate::Result<Vec<f64>> {
    freq_hz
        .iter()
        .enumerate()
        .map(|(k, &f)| {
            if f.is_finite() && f > 0.0 {
                Ok(MOHREN2018_DAMPING_PER_S / (2.0 * 2.0 * std::f64::consts::PI * f))
            } else {
                Err(crate::error::WingbeatError::invalid(
                    format!("freq_hz[{k}]"),
                    f,
                    "finite and > 0 Hz",
                ))
            }
        })
        .collect()
}
