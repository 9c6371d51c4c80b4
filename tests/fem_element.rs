//! Element-level checks of the shell triangle: rigid-body motions carry no strain energy,
//! constant membrane strain and constant curvature are reproduced exactly (patch tests).

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::fem::element::{
    corner_surface_strain, global_stiffness, Frame, ShellMaterial, Vec18,
};

fn mat() -> ShellMaterial {
    ShellMaterial {
        thickness_m: 1e-3,
        e_pa: 70e9,
        rho_kg_m3: 2700.0,
        nu: 0.3,
    }
}

/// A skewed, tilted (non-horizontal) triangle, metres.
fn tri() -> [[f64; 3]; 3] {
    [
        [0.01, 0.02, 0.003],
        [0.05, 0.025, -0.002],
        [0.02, 0.06, 0.01],
    ]
}

/// Global displacement vector of a field u(x) (translation) and rotation field θ(x).
fn field(p: &[[f64; 3]; 3], f: impl Fn([f64; 3]) -> ([f64; 3], [f64; 3])) -> Vec18 {
    let mut u = Vec18::zeros();
    for (c, x) in p.iter().enumerate() {
        let (t, r) = f(*x);
        for k in 0..3 {
            u[6 * c + k] = t[k];
            u[6 * c + 3 + k] = r[k];
        }
    }
    u
}

#[test]
fn rigid_body_motions_have_zero_energy() {
    let p = tri();
    let k = global_stiffness(&p, &mat()).unwrap();
    let scale = k.amax();
    // three translations and three (small) rotations about an arbitrary point
    let c = [0.02, 0.03, 0.0];
    for i in 0..6 {
        let u = field(&p, |x| {
            let mut t = [0.0; 3];
            let mut th = [0.0; 3];
            if i < 3 {
                t[i] = 1.0;
            } else {
                th[i - 3] = 1.0;
                let r = [x[0] - c[0], x[1] - c[1], x[2] - c[2]];
                t = [
                    th[1] * r[2] - th[2] * r[1],
                    th[2] * r[0] - th[0] * r[2],
                    th[0] * r[1] - th[1] * r[0],
                ];
            }
            (t, th)
        });
        let f = k * u;
        assert!(
            f.amax() <= 1e-9 * scale * u.amax(),
            "mode {i}: |K u| = {:e}",
            f.amax()
        );
        let energy = u.dot(&f);
        assert!(
            energy.abs() <= 1e-12 * scale * u.norm_squared(),
            "mode {i}: energy {energy:e}"
        );
    }
}

#[test]
fn membrane_patch_constant_strain() {
    // flat triangle in the x–y plane: u = ex x + g/2 y, v = g/2 x + ey y, θz = in-plane rotation (0)
    let p = [[0.0, 0.0, 0.0], [0.04, 0.01, 0.0], [0.015, 0.05, 0.0]];
    let (ex, ey, g) = (1e-4, -3e-5, 2e-4);
    let u = field(&p, |x| {
        (
            [ex * x[0] + 0.5 * g * x[1], 0.5 * g * x[0] + ey * x[1], 0.0],
            [0.0; 3],
        )
    });
    for c in 0..3 {
        let e = corner_surface_strain(&p, &mat(), &u, c).unwrap();
        assert!(
            (e[0] - ex).abs() < 1e-14 && (e[1] - ey).abs() < 1e-14 && (e[2] - g).abs() < 1e-14,
            "{e:?}"
        );
    }
    // energy equals t A ½ εᵀ C ε
    let m = mat();
    let k = global_stiffness(&p, &m).unwrap();
    let f = m.e_pa / (1.0 - m.nu * m.nu);
    let w = 0.5 * f * (ex * ex + ey * ey + 2.0 * m.nu * ex * ey + 0.5 * (1.0 - m.nu) * g * g);
    let area = Frame::new(&p).unwrap().area;
    let e_fe = 0.5 * u.dot(&(k * u));
    assert!(
        (e_fe - w * m.thickness_m * area).abs() < 1e-10 * e_fe.abs(),
        "{e_fe} vs {}",
        w * m.thickness_m * area
    );
}

#[test]
fn bending_patch_constant_curvature() {
    // w = ½(kx x² + ky y²) + kxy x y → θx = ∂w/∂y, θy = −∂w/∂x
    let p = [[0.0, 0.0, 0.0], [0.04, 0.01, 0.0], [0.015, 0.05, 0.0]];
    let (kx, ky, kxy) = (2.0, -1.0, 0.7);
    let m = mat();
    let u = field(&p, |x| {
        let w = 0.5 * (kx * x[0] * x[0] + ky * x[1] * x[1]) + kxy * x[0] * x[1];
        let wx = kx * x[0] + kxy * x[1];
        let wy = ky * x[1] + kxy * x[0];
        ([0.0, 0.0, w], [wy, -wx, 0.0])
    });
    for c in 0..3 {
        let e = corner_surface_strain(&p, &m, &u, c).unwrap();
        let h = 0.5 * m.thickness_m;
        let want = [-h * kx, -h * ky, -h * 2.0 * kxy];
        for q in 0..3 {
            assert!(
                (e[q] - want[q]).abs() < 1e-12,
                "corner {c}: {e:?} vs {want:?}"
            );
        }
    }
    let k = global_stiffness(&p, &m).unwrap();
    let d = m.bending_stiffness();
    let w = 0.5 * d * (kx * kx + ky * ky + 2.0 * m.nu * kx * ky + 2.0 * (1.0 - m.nu) * kxy * kxy);
    let area = Frame::new(&p).unwrap().area;
    let e_fe = 0.5 * u.dot(&(k * u));
    assert!(
        (e_fe - w * area).abs() < 1e-9 * e_fe,
        "{e_fe} vs {}",
        w * area
    );
}

/// In-plane bending of a cantilever strip (length 100 mm, depth 10 mm) resolved by only a few
/// elements across the depth: the Allman-type membrane with drilling rotations reproduces the
/// Euler–Bernoulli frequency closely (constant-strain triangles are known to be too stiff in
/// in-plane bending at such a coarse resolution).
#[test]
fn membrane_in_plane_bending_of_a_cantilever_strip() {
    use wingbeat::fem::*;
    let m = ShellMaterial {
        thickness_m: 1e-4,
        e_pa: 70e9,
        rho_kg_m3: 2700.0,
        nu: 0.3,
    };
    let (l, b) = (0.1f64, 0.01f64);
    let input = FemInput {
        planform_mm: rectangle_planform(100.0, 10.0),
        planform_note: "strip".into(),
        camber: 0.0,
        clamp: Clamp::Root,
        material: m,
        n_modes: 12,
        mesh_size_mm: Some(2.5),
        max_nodes: None,
    };
    let r = compute_modes(&input).unwrap();
    // the in-plane mode is the first one with (numerically) no out-of-plane motion
    let k = (0..r.freq_hz.len())
        .find(|&k| r.shapes[k].iter().fold(0.0f64, |a, w| a.max(w.abs())) < 1e-6 / r.mass_kg.sqrt())
        .expect("an in-plane mode among the first 12");
    let i = m.thickness_m * b * b * b / 12.0;
    let beam = 1.875104f64.powi(2) / (2.0 * std::f64::consts::PI)
        * (m.e_pa * i / (m.rho_kg_m3 * b * m.thickness_m * l.powi(4))).sqrt();
    let err = r.freq_hz[k] / beam - 1.0;
    println!(
        "in-plane bending: mode {}, {:.2} Hz vs beam {beam:.2} Hz ({:+.2} %)",
        k + 1,
        r.freq_hz[k],
        100.0 * err
    );
    assert!(err.abs() < 0.03, "{err}");
}
