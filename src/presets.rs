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
