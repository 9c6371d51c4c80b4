//! The basal strip clamp (`Clamp::Strip { x_mm }`) is exact: the mesher puts a line of nodes
//! on x = X, so a plate clamped by a strip converges at the element's order (h², like the
//! root-clamped plate) to the same plate with its outline cut at x = X and the root clamped.
//! Without that line the clamped edge falls short by up to one element and the error falls
//! only about linearly with h.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::fem::*;

const SPAN: f64 = 30.0; // free span, mm
const CHORD: f64 = 10.0; // mm
const X: f64 = 3.3; // strip width, mm (not a multiple of any mesh size below)
const N: usize = 3;

fn plate(planform: Vec<[f64; 2]>, clamp: Clamp, h: f64) -> FemModes {
    compute_modes(&FemInput {
        planform_mm: planform,
        planform_note: "flat plate".into(),
        camber: 0.0,
        clamp,
        material: ShellMaterial::paper_frequencies(),
        n_modes: N,
        mesh_size_mm: Some(h),
        max_nodes: None,
    })
    .expect("plate solves")
}

#[test]
#[allow(clippy::needless_range_loop)] // err[i][k]: mesh i, mode k
fn strip_clamp_converges_at_the_element_order_to_the_cut_plate() {
    // Reference: the free part alone (outline cut at x = X) with the root clamped,
    // Richardson-extrapolated (h²) from h = 1 and 0.5 mm.
    let r1 = plate(rectangle_planform(SPAN, CHORD), Clamp::Root, 1.0);
    let r2 = plate(rectangle_planform(SPAN, CHORD), Clamp::Root, 0.5);
    let reference: Vec<f64> = (0..N)
        .map(|k| r2.freq_hz[k] + (r2.freq_hz[k] - r1.freq_hz[k]) / 3.0)
        .collect();
    println!("reference (cut plate, Richardson) f = {reference:.4?} Hz");
    let hs = [2.0, 1.0, 0.5];
    let mut err = vec![[0.0; N]; hs.len()];
    for (i, &h) in hs.iter().enumerate() {
        let s = plate(
            rectangle_planform(SPAN + X, CHORD),
            Clamp::Strip { x_mm: X },
            h,
        );
        // the clamped edge is exact: clamped nodes reach x = X and none lies beyond it
        let xs: Vec<f64> = s
            .clamped_nodes
            .iter()
            .map(|&n| s.nodes[n][0] * 1e3)
            .collect();
        assert!(xs.iter().all(|&x| x <= X + 1e-9));
        let on_line = xs.iter().filter(|&&x| (x - X).abs() < 1e-9).count();
        assert!(
            on_line as f64 >= CHORD / h,
            "{on_line} nodes on x = X at h = {h}"
        );
        for (e, (f, r)) in err[i].iter_mut().zip(s.freq_hz.iter().zip(&reference)) {
            *e = f / r - 1.0;
        }
        println!(
            "h = {h} mm: {} nodes, {on_line} on the clamp line, errors {:.4?} %",
            s.nodes.len(),
            err[i].map(|e| 100.0 * e)
        );
    }
    for k in 0..N {
        // every halving of h divides the error by at least 2^1.3 (linear would be 2), and
        // over the two halvings the fitted order is at least 1.7 (the element's is 2)
        for i in 0..hs.len() - 1 {
            let ratio = err[i][k].abs() / err[i + 1][k].abs();
            assert!(
                ratio > 2f64.powf(1.3),
                "mode {}: error ratio {ratio:.2} from h = {} to {}",
                k + 1,
                hs[i],
                hs[i + 1]
            );
        }
        let order = (err[0][k].abs() / err[2][k].abs()).log2() / 2.0;
        println!("mode {}: observed order {order:.2}", k + 1);
        assert!(order > 1.7, "mode {}: order {order:.2}", k + 1);
        // and the strip model is already close at h = 1 mm
        assert!(
            err[1][k].abs() < 0.01,
            "mode {}: {:.3} %",
            k + 1,
            100.0 * err[1][k]
        );
    }
}

#[test]
fn strip_clamp_on_the_default_wing_is_exact_and_well_shaped() {
    // The line x = 3 mm crosses the synthetic outline 0.05 mm from one of its points; the
    // mesh still has a node row on x = 3 mm and no degenerate triangle.
    let input = FemInput {
        clamp: Clamp::Strip { x_mm: 3.0 },
        mesh_size_mm: Some(1.0),
        n_modes: 2,
        ..FemInput::default()
    };
    let (outline, mesh, _) = mesh_input(&input).unwrap();
    let clamped = clamp_nodes(&outline, &mesh, input.clamp).unwrap();
    let on_line = mesh
        .nodes
        .iter()
        .zip(&clamped)
        .filter(|(p, &c)| c && (p[0] * 1e3 - 3.0).abs() < 1e-9)
        .count();
    let chord = geometry::chord_extent(&outline, 3.0)
        .map(|(a, b)| a - b)
        .unwrap();
    assert!(
        on_line as f64 >= chord,
        "{on_line} nodes for a {chord} mm chord"
    );
    let mut min_angle = 180.0f64;
    for t in &mesh.triangles {
        for c in 0..3 {
            let (a, b, d) = (
                mesh.nodes[t[c]],
                mesh.nodes[t[(c + 1) % 3]],
                mesh.nodes[t[(c + 2) % 3]],
            );
            let u = [b[0] - a[0], b[1] - a[1]];
            let v = [d[0] - a[0], d[1] - a[1]];
            let cos = (u[0] * v[0] + u[1] * v[1]) / (u[0].hypot(u[1]) * v[0].hypot(v[1]));
            min_angle = min_angle.min(cos.clamp(-1.0, 1.0).acos().to_degrees());
        }
    }
    println!(
        "{} nodes, {on_line} on the line, smallest angle {min_angle:.1}°",
        mesh.nodes.len()
    );
    assert!(min_angle > 5.0, "{min_angle}");
    // the mesh covers the outline exactly
    let area: f64 = mesh
        .triangles
        .iter()
        .map(|t| {
            let (a, b, c) = (mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]]);
            0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]))
        })
        .sum::<f64>()
        * 1e6;
    assert!(
        (area / geometry::signed_area(&outline) - 1.0).abs() < 1e-9,
        "{area}"
    );
    compute_modes(&input).unwrap();
}
