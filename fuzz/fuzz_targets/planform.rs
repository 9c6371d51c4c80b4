//! Fuzz target: the planform readers (CSV and JSON, `wingbeat modes --planform`, the lab's
//! outline upload) and the outline checks behind them. Never a panic; an accepted outline
//! has a finite positive area, a finite automatic mesh size and a default strain point, and
//! meshes coarsely without a panic; near-copies of its points (down to 1e-300 of its size) are
//! refused naming a point, or mesh (issue 20).
#![no_main]

use libfuzzer_sys::fuzz_target;
use wingbeat::fem::geometry;

fn check(points: &[[f64; 2]]) {
    match geometry::outline_summary(points) {
        Err(e) => assert!(!e.to_string().trim().is_empty()),
        Ok(s) => {
            assert!(
                s.area_mm2.is_finite() && s.area_mm2 > 0.0,
                "area {}",
                s.area_mm2
            );
            assert!(s.span_mm.is_finite() && s.span_mm > 0.0);
            assert!(s.chord_mm.is_finite() && s.chord_mm > 0.0);
            let outline = geometry::validate_outline(points).expect("summary accepted it");
            let h = wingbeat::fem::default_mesh_size_mm(&outline);
            assert!(h.is_finite() && h > 0.0, "automatic mesh size {h}");
            let (x, y) = wingbeat::fem::default_strain_point_mm(&outline);
            assert!(x.is_finite() && y.is_finite());
            let _ = geometry::planform_note_for(points);
            // an accepted outline meshes (coarsely) or is refused with an error, no panic
            let size = s.span_mm.max(s.chord_mm);
            let opts = wingbeat::fem::mesh::MeshOptions {
                max_nodes: 2000,
                lines_x_mm: vec![],
            };
            if let Err(e) = wingbeat::fem::mesh::mesh_planform_with(&outline, size / 8.0, 0.1, &opts) {
                assert!(!e.to_string().trim().is_empty());
            }
            // near-copies of each point (issue 20): refused by the same check, or meshable
            for (k, d) in [1e-300, 1e-12, 1e-7].into_iter().enumerate() {
                let i = k % outline.len();
                let mut p = outline.clone();
                p.insert(i + 1, [p[i][0] + d * size, p[i][1]]);
                match geometry::validate_outline(&p) {
                    Err(e) => assert!(e.to_string().contains("planform["), "{e}"),
                    Ok(v) => {
                        if let Err(e) =
                            wingbeat::fem::mesh::mesh_planform_with(&v, size / 8.0, 0.1, &opts)
                        {
                            assert!(!e.to_string().trim().is_empty());
                        }
                    }
                }
            }
        }
    }
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    match geometry::parse_planform_csv(text) {
        Err(e) => assert!(!e.to_string().trim().is_empty()),
        Ok(p) => check(&p),
    }
    match geometry::parse_planform_json(text) {
        Err(e) => assert!(!e.to_string().trim().is_empty()),
        Ok(p) => check(&p),
    }
});
