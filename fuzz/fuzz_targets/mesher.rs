//! Fuzz target: the mesher and the clamp on arbitrary outlines, mesh sizes and cambers
//! (`wingbeat modes`, wasm `feModes`), with small meshes also solved for two modes. Never a
//! panic; a mesh respects its node cap, has finite nodes and valid triangles; modes are
//! finite. Extended (issue 20) to near-degenerate geometry: near-copies of points at distances
//! down to subnormal, and strip-clamp mesh lines a hair off an outline point.
#![no_main]

use libfuzzer_sys::fuzz_target;
use wingbeat::fem::{self, Clamp, FemInput, ShellMaterial};

/// Node cap of the fuzzed meshes (keeps one execution short).
const CAP: usize = 3000;

fuzz_target!(|data: &[u8]| {
    if data.len() < 8 {
        return;
    }
    let (head, rest) = data.split_at(4);
    // outline: 3..=40 points, coordinates in 0.01 mm steps within ±327 mm; a byte of
    // `head[3]` selects a scale so that tiny and huge outlines are reached too
    let scale = [1.0, 1e-6, 1e-3, 1e3, 1e5][usize::from(head[3]) % 5];
    let pts: Vec<[f64; 2]> = rest
        .chunks_exact(4)
        .take(40)
        .map(|c| {
            let x = f64::from(i16::from_le_bytes([c[0], c[1]])) * 0.01 * scale;
            let y = f64::from(i16::from_le_bytes([c[2], c[3]])) * 0.01 * scale;
            [x, y]
        })
        .collect();
    if pts.len() < 3 {
        return;
    }
    // Near-degenerate geometry (issue 20): the bytes after the points are 3-byte edits, each
    // inserting a near-copy of point `e[0]` displaced by 10^-(e[1] % 310) of the outline's size
    // (down to 1e-309, a subnormal) in direction `e[2]`, after it or before it; the last one
    // also puts a strip clamp's mesh line that far off that point's x.
    let mut pts = pts;
    let size = pts
        .iter()
        .flat_map(|p| p.iter())
        .fold(0.0f64, |m, v| m.max(v.abs()))
        .max(1e-300);
    let mut near_x = None;
    for e in rest.chunks_exact(4).skip(40).flat_map(|c| c.chunks_exact(3)).take(8) {
        let i = usize::from(e[0]) % pts.len();
        let d = size * 10f64.powi(-i32::from(e[1] % 155) * 2);
        let ang = f64::from(e[2]) * std::f64::consts::TAU / 256.0;
        let q = [pts[i][0] + d * ang.cos(), pts[i][1] + d * ang.sin()];
        near_x = Some(q[0]);
        if e[2] % 2 == 0 {
            pts.insert(i + 1, q);
        } else {
            pts.insert(i, q);
        }
    }
    // the mesher on the outline as given (unvalidated): an error or a mesh, never a panic
    if let Some(x) = near_x {
        let opts = fem::mesh::MeshOptions {
            max_nodes: CAP,
            lines_x_mm: vec![x],
        };
        if let Err(e) = fem::mesh::mesh_planform_with(&pts, size / 4.0, 0.1, &opts) {
            assert!(!e.to_string().trim().is_empty());
        }
    }
    let mesh_size_mm = match head[0] {
        0..=127 => None,
        b => Some(f64::from(b - 127) * 0.05 * scale),
    };
    let camber = f64::from(head[1]) / 510.0;
    let clamp = match (head[2] % 3, near_x) {
        (0, _) => Clamp::Root,
        (1, _) => Clamp::Free,
        (_, Some(x)) => Clamp::Strip { x_mm: x },
        _ => Clamp::Strip {
            x_mm: f64::from(head[2]) * 0.1 * scale,
        },
    };
    let input = FemInput {
        planform_mm: pts,
        planform_note: "fuzz".into(),
        camber,
        clamp,
        material: ShellMaterial::paper_frequencies(),
        n_modes: 2,
        mesh_size_mm,
        max_nodes: Some(CAP),
    };
    let (outline, mesh, h) = match fem::mesh_input(&input) {
        Err(e) => {
            assert!(!e.to_string().trim().is_empty());
            return;
        }
        Ok(m) => m,
    };
    assert!(h.is_finite() && h > 0.0);
    let n = mesh.nodes.len();
    assert!(n <= CAP, "{n} nodes over the cap {CAP}");
    assert!(mesh.nodes.iter().flatten().all(|v| v.is_finite()));
    assert!(mesh.triangles.iter().flatten().all(|&i| i < n));
    let clamped = match fem::clamp_nodes(&outline, &mesh, input.clamp) {
        Err(e) => {
            assert!(!e.to_string().trim().is_empty());
            return;
        }
        Ok(c) => c,
    };
    assert_eq!(clamped.len(), n);
    if n <= 120 {
        match fem::solve_mesh(&mesh, &clamped, &input.material, 2, "fuzz") {
            Err(e) => assert!(!e.to_string().trim().is_empty()),
            Ok(fe) => {
                assert!(fe.freq_hz.iter().all(|f| f.is_finite()), "{:?}", fe.freq_hz);
                assert!(fe.shapes.iter().flatten().all(|v| v.is_finite()));
            }
        }
    }
});
