//! The published sensing plate (Eberle et al. 2015, used by Mohren et al. 2018 and Weber et
//! al. 2021: 50 × 25 mm acrylic, root clamped) solved by the shell FE: convergence under
//! refinement, and the converged frequencies against closed-form plate bounds.
//!
//! References (λ = ω L² √(ρh / D), L = span, D = E h³ / (12 (1 − ν²))):
//! - Euler–Bernoulli cantilever eigenvalues β₁L = 1.8751, β₂L = 4.6941 (roots of
//!   cos β cosh β = −1). A y-independent deflection w = W(x) makes the Kirchhoff energy exactly
//!   D·b·∫W″², so by Rayleigh–Ritz the plate's first and second y-symmetric (bending)
//!   eigenvalues lie at or below (β_kL)²: 3.516 and 22.03. Conversely the energy density
//!   D[w_xx² + w_yy² + 2ν w_xx w_yy + 2(1 − ν) w_xy²] ≥ D(1 − ν²) w_xx², and each spanwise
//!   line is a clamped–free beam, so the first eigenvalue is at least √(1 − ν²)·(β₁L)².
//! - Torsion: w = θ(x)·y restricts the plate to a beam twisting with restrained warping,
//!   D b³/12 θ⁗ − 2(1 − ν) D b θ″ = ω² ρh b³/12 θ, θ(0) = θ′(0) = 0, θ″(L) = 0,
//!   θ‴(L) = (24 (1 − ν)/b²) θ′(L). Its lowest eigenvalue is a Rayleigh–Ritz upper bound of
//!   the plate's first y-antisymmetric mode. Without the warping term this is St-Venant
//!   torsion, λ = (π/2)(L/b)√(24 (1 − ν)), which ignores the clamp's warping restraint and
//!   so lies below the plate.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::fem::{compute_modes, FemModes};
use wingbeat::presets::{
    mohren2018_damping_ratios, mohren2018_material, mohren2018_plate_input,
    MOHREN2018_DAMPING_PER_S,
};

use std::f64::consts::PI;

/// β₁L and β₂L of the clamped–free Euler–Bernoulli beam (cos β cosh β = −1).
const BEAM_BETA_L: [f64; 2] = [1.875_104_07, 4.694_091_13];

/// Mesh sizes of the convergence sequence, mm (the last is the automatic size).
const MESHES_MM: [f64; 3] = [2.5, 1.6, 1.2];

fn solves() -> &'static Vec<FemModes> {
    static CELL: std::sync::OnceLock<Vec<FemModes>> = std::sync::OnceLock::new();
    CELL.get_or_init(|| {
        MESHES_MM
            .iter()
            .map(|&h| compute_modes(&mohren2018_plate_input(Some(h), 6)).expect("plate solves"))
            .collect()
    })
}

/// The published plate's facts (Eberle et al. 2015, as coded by Mohren et al. 2018):
/// span L and chord b (m), E (Pa), ν, thickness h (m), ρ (kg/m³). The references below are
/// computed from these, not from the preset, so a wrong preset material or a swapped
/// span/chord moves the FE frequencies out of the bounds.
const PUBLISHED: (f64, f64, f64, f64, f64, f64) = (0.050, 0.025, 3.0e9, 0.35, 0.127e-3, 1180.0);

/// λ = ω L² √(ρh/D) of a frequency in Hz, with the published L, ρh and D.
fn lambda(f_hz: f64) -> f64 {
    let (l, _, e, nu, h, rho) = PUBLISHED;
    let d = e * h.powi(3) / (12.0 * (1.0 - nu * nu));
    2.0 * PI * f_hz * l * l * (rho * h / d).sqrt()
}

/// Determinant of a 4 × 4 matrix by elimination with partial pivoting.
fn det4(mut a: [[f64; 4]; 4]) -> f64 {
    let mut det = 1.0;
    for c in 0..4 {
        let p = (c..4)
            .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
            .unwrap();
        if a[p][c] == 0.0 {
            return 0.0;
        }
        if p != c {
            a.swap(p, c);
            det = -det;
        }
        det *= a[c][c];
        let pivot_row = a[c];
        for row in a.iter_mut().skip(c + 1) {
            let f = row[c] / pivot_row[c];
            for (x, p) in row.iter_mut().zip(pivot_row).skip(c) {
                *x -= f * p;
            }
        }
    }
    det
}

/// The frequency determinant of the restrained-warping torsion beam in ξ = x/L, with
/// κ² = 24 (1 − ν)(L/b)² and μ⁴ = λ²: θ⁗ − κ²θ″ − μ⁴θ = 0, θ = A cosh aξ + B sinh aξ +
/// C cos bξ + D sin bξ with a² − b² = κ², a²b² = μ⁴.
fn torsion_det(lam: f64, kappa2: f64) -> f64 {
    let root = (kappa2 * kappa2 + 4.0 * lam * lam).sqrt();
    let (a, b) = (
        ((kappa2 + root) / 2.0).sqrt(),
        ((root - kappa2) / 2.0).sqrt(),
    );
    let derivs = |x: f64| {
        let (ch, sh, c, s) = ((a * x).cosh(), (a * x).sinh(), (b * x).cos(), (b * x).sin());
        [
            [ch, sh, c, s],
            [a * sh, a * ch, -b * s, b * c],
            [a * a * ch, a * a * sh, -b * b * c, -b * b * s],
            [
                a.powi(3) * sh,
                a.powi(3) * ch,
                b.powi(3) * s,
                -b.powi(3) * c,
            ],
        ]
    };
    let (z, e) = (derivs(0.0), derivs(1.0));
    let mut shear = [0.0; 4];
    for k in 0..4 {
        shear[k] = e[3][k] - kappa2 * e[1][k];
    }
    det4([z[0], z[1], e[2], shear])
}

/// Lowest λ of the restrained-warping torsion beam: scan for the first sign change, bisect.
fn torsion_upper_bound(kappa2: f64) -> f64 {
    let (mut lo, step) = (0.5, 0.01);
    let mut f_lo = torsion_det(lo, kappa2);
    loop {
        let hi = lo + step;
        let f_hi = torsion_det(hi, kappa2);
        if f_lo.signum() != f_hi.signum() {
            let (mut a, mut b) = (lo, hi);
            for _ in 0..60 {
                let m = 0.5 * (a + b);
                if torsion_det(m, kappa2).signum() == f_lo.signum() {
                    a = m;
                } else {
                    b = m;
                }
            }
            return 0.5 * (a + b);
        }
        assert!(hi < 200.0, "no torsion root below λ = 200");
        lo = hi;
        f_lo = f_hi;
    }
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b) / b
}

#[test]
fn published_plate_frequencies_rise_monotonically_and_settle_under_refinement() {
    let s = solves();
    for (r, h) in s.iter().zip(MESHES_MM) {
        println!(
            "h = {h} mm: nodes {}, f = {:.3?} Hz, kinds {:?}",
            r.nodes.len(),
            r.freq_hz,
            r.kinds
        );
        assert!(r.mass_orthonormality_error < 1e-10);
        assert!(r.residuals.iter().all(|&x| x < 1e-6), "{:?}", r.residuals);
    }
    for w in s.windows(2) {
        for k in 0..6 {
            // the DKT plate approaches the thin-plate answer from below on this plate
            assert!(
                w[1].freq_hz[k] > w[0].freq_hz[k],
                "mode {}: {} then {}",
                k + 1,
                w[0].freq_hz[k],
                w[1].freq_hz[k]
            );
        }
    }
    // the last refinement step moves every mode by well under 1 %
    let (a, b) = (&s[1], &s[2]);
    for k in 0..6 {
        let step = rel(b.freq_hz[k], a.freq_hz[k]);
        assert!(step < 0.002, "mode {}: last step {step}", k + 1);
    }
}

#[test]
fn published_plate_is_clamped_on_its_short_edge_with_the_first_modes_bending_torsion_bending() {
    let r = &solves()[2];
    assert_eq!(r.mesh_size_mm, 1.2);
    assert_eq!(r.kinds[0], "spanwise bending");
    assert_eq!(r.kinds[1], "torsion");
    assert_eq!(r.kinds[2], "spanwise bending");
    // the automatic size of a 50 × 25 mm outline is the finest mesh of the sequence
    let auto = compute_modes(&mohren2018_plate_input(None, 1)).expect("plate solves");
    assert_eq!(auto.mesh_size_mm, MESHES_MM[2]);
    // the root edge (x = 0) is the 25 mm chord: the plate spans 0 ..= 50 mm in x
    let (xmin, xmax, ymin, ymax) = r.nodes.iter().fold(
        (f64::MAX, f64::MIN, f64::MAX, f64::MIN),
        |(a, b, c, d), n| (a.min(n[0]), b.max(n[0]), c.min(n[1]), d.max(n[1])),
    );
    println!("nodes span x {xmin}..{xmax} mm, y {ymin}..{ymax} mm");
    // node coordinates are in metres
    assert!((xmax - xmin - PUBLISHED.0).abs() < 1e-12 && xmin.abs() < 1e-12);
    assert!((ymax - ymin - PUBLISHED.1).abs() < 1e-12);
    assert_eq!(mohren2018_material().e_pa, PUBLISHED.2);
}

#[test]
fn published_plate_bending_lies_within_the_beam_bounds() {
    let r = &solves()[2];
    let nu = PUBLISHED.3;
    let upper = [BEAM_BETA_L[0].powi(2), BEAM_BETA_L[1].powi(2)];
    let lower1 = (1.0 - nu * nu).sqrt() * upper[0];
    let (l1, l2) = (lambda(r.freq_hz[0]), lambda(r.freq_hz[2]));
    println!(
        "1st bending λ = {l1:.4} in [{lower1:.4}, {:.4}] ({:+.2} % from the upper bound); \
         2nd bending λ = {l2:.3} ≤ {:.3} ({:+.2} %)",
        upper[0],
        100.0 * rel(l1, upper[0]),
        upper[1],
        100.0 * rel(l2, upper[1])
    );
    assert!(l1 > lower1 && l1 < upper[0], "λ1 = {l1}");
    // a plate twice as long as wide stays close to its plate-strip beam: anticlastic
    // relief costs a few percent (Leissa's square cantilever, 3.492, is 0.7 % below)
    assert!(rel(l1, upper[0]) > -0.05, "λ1 = {l1}");
    assert!(l2 < upper[1] && rel(l2, upper[1]) > -0.06, "λ2 = {l2}");
}

#[test]
fn published_plate_torsion_lies_between_st_venant_and_the_restrained_warping_bound() {
    let r = &solves()[2];
    let nu = PUBLISHED.3;
    let aspect = PUBLISHED.0 / PUBLISHED.1;
    let kappa2 = 24.0 * (1.0 - nu) * aspect * aspect;
    let st_venant = PI / 2.0 * kappa2.sqrt();
    let upper = torsion_upper_bound(kappa2);
    let lt = lambda(r.freq_hz[1]);
    println!(
        "1st torsion λ = {lt:.3}: St-Venant {st_venant:.3} ({:+.2} %), \
         restrained-warping bound {upper:.3} ({:+.2} %)",
        100.0 * rel(lt, st_venant),
        100.0 * rel(lt, upper)
    );
    // the bound itself must sit above St-Venant (warping restraint only stiffens)
    assert!(upper > st_venant);
    assert!(lt > st_venant && lt < upper, "λt = {lt}");
    // the linear-across-the-chord twist is nearly the whole story on a 2:1 plate
    assert!(rel(lt, upper) > -0.02, "λt = {lt}");
}

#[test]
fn published_damping_ratios_are_63_over_two_omega_and_bad_frequencies_are_refused() {
    let r = &solves()[2];
    let z = mohren2018_damping_ratios(&r.freq_hz).expect("positive frequencies");
    for (f, zeta) in r.freq_hz.iter().zip(&z) {
        let omega = 2.0 * PI * f;
        assert!((zeta * 2.0 * omega - MOHREN2018_DAMPING_PER_S).abs() < 1e-9);
    }
    println!("ζ_k = {z:.4?}");
    // the damping falls with frequency: heavy on the first bending mode, light above
    assert!(z.windows(2).all(|w| w[1] < w[0]));
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let e = mohren2018_damping_ratios(&[10.0, bad])
            .unwrap_err()
            .to_string();
        assert!(e.contains("freq_hz[1]"), "{e}");
    }
}
