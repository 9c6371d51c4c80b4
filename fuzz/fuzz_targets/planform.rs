//! Fuzz target: the planform readers (CSV and JSON, `wingbeat modes --planform`, the lab's
//! outline upload) and the outline checks behind them. Never a panic; an accepted outline
//! has a finite positive area, a finite automatic mesh size and a default strain point.
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
