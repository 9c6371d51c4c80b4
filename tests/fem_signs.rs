//! The sign convention of the mode shapes ([`sign_of_shape`]) and the mode labels
//! ([`classify`]) do not change with the mesh: the default wing's first six modes, and a
//! symmetric rectangle whose torsion modes have two equal and opposite largest displacements
//! (where "the largest displacement is positive" picked a sign by rounding).

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::fem::*;

fn solve(input: &FemInput, h: f64) -> FemModes {
    compute_modes(&FemInput {
        mesh_size_mm: Some(h),
        ..input.clone()
    })
    .unwrap()
}

/// Σ w_a(node) w_b(nearest node of b) over the nodes of `a`: > 0 when the shapes have the
/// same sign.
fn overlap(a: &FemModes, b: &FemModes, k: usize) -> f64 {
    a.nodes
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let j = (0..b.nodes.len())
                .min_by(|&u, &v| {
                    let du = (b.nodes[u][0] - p[0]).powi(2) + (b.nodes[u][1] - p[1]).powi(2);
                    let dv = (b.nodes[v][0] - p[0]).powi(2) + (b.nodes[v][1] - p[1]).powi(2);
                    du.total_cmp(&dv)
                })
                .unwrap();
            a.shapes[k][i] * b.shapes[k][j]
        })
        .sum()
}

/// Largest |w| entry's sign (the former convention) of mode k.
fn largest_sign(r: &FemModes, k: usize) -> f64 {
    let big = r.shapes[k]
        .iter()
        .copied()
        .fold(0.0f64, |m, x| if x.abs() > m.abs() { x } else { m });
    big.signum()
}

fn check(name: &str, input: &FemInput, h1: f64, h2: f64, n: usize) {
    let (a, b) = (solve(input, h1), solve(input, h2));
    println!("{name}: kinds {:?}", a.kinds);
    assert_eq!(
        a.kinds[..n],
        b.kinds[..n],
        "{name}: labels at h = {h1} and {h2} mm"
    );
    for k in 0..n {
        let o = overlap(&a, &b, k);
        println!(
            "{name} mode {}: f {:.1} / {:.1} Hz, overlap {o:+.3}, largest-|w| sign {} / {}",
            k + 1,
            a.freq_hz[k],
            b.freq_hz[k],
            largest_sign(&a, k),
            largest_sign(&b, k)
        );
        assert!(
            o > 0.0,
            "{name} mode {}: the sign flips between meshes",
            k + 1
        );
    }
}

#[test]
fn default_wing_signs_and_labels_do_not_depend_on_the_mesh() {
    let input = FemInput::default();
    check("default wing", &input, 1.25, 0.8, 6);
    // bending lifts the tip (a_x > 0), torsion lifts the trailing edge (a_y < 0 for a
    // mass centre behind the root point)
    let r = solve(&input, 1.25);
    assert_eq!(r.kinds[0], "spanwise bending");
    assert!(r.a[0][0] > 0.0);
    assert_eq!(r.kinds[1], "torsion");
    assert!(r.a[1][1] < 0.0, "{:?}", r.a[1]);
}

#[test]
fn symmetric_rectangle_antisymmetric_modes_keep_their_sign() {
    let input = FemInput {
        planform_mm: rectangle_planform(40.0, 10.0),
        planform_note: "flat rectangle".into(),
        camber: 0.0,
        n_modes: 5,
        ..FemInput::default()
    };
    check("rectangle", &input, 2.0, 1.0, 5);
}
