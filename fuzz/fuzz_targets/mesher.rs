//! Fuzz target: the mesher and the clamp on arbitrary outlines, mesh sizes and cambers
//! (`wingbeat modes`, wasm `feModes`), with small meshes also solved for two modes. Never a
//! panic; a mesh respects its node cap, has finite nodes and valid triangles; modes are
//! finite.
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
    let mesh_size_mm = match head[0] {
        0..=127 => None,
        b => Some(f64::from(b - 127) * 0.05 * scale),
    };
    let camber = f64::from(head[1]) / 510.0;
    let clamp = match head[2] % 3 {
        0 => Clamp::Root,
        1 => Clamp::Free,
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
