//! Geometry that floating point cannot mesh is refused before meshing, by the check the lab's
//! `checkPlanform` and the CLI share (`geometry::validate_outline`), naming the points; and the
//! mesher itself returns an error, never panics, on any outline (it checks its input again).
//! The outline `[[0,0],[0,-5],[30,-5],[30,0],[1e-300,0]]` made spade index out of bounds.
// proptest is a native-only dev-dependency.
#![cfg(not(target_arch = "wasm32"))]

use proptest::prelude::*;
use wingbeat::fem::geometry::{validate_outline, MIN_SEPARATION_FRACTION};
use wingbeat::fem::mesh::{mesh_planform, mesh_planform_with, MeshOptions};
use wingbeat::WingbeatError;

fn err_text<T: std::fmt::Debug>(r: Result<T, WingbeatError>) -> String {
    r.expect_err("should be refused").to_string()
}

#[test]
fn the_issues_outline_is_refused_naming_both_points() {
    let p = [
        [0.0, 0.0],
        [0.0, -5.0],
        [30.0, -5.0],
        [30.0, 0.0],
        [1e-300, 0.0],
    ];
    let m = err_text(validate_outline(&p));
    assert!(
        m.contains("planform[4]") && m.contains("planform[0]"),
        "{m}"
    );
    assert!(m.contains("1e-300"), "{m}");
    // the allowed distance: 1e-6 of the size (30 mm)
    assert!(m.contains("0.00003 mm"), "{m}");
    // and the mesher, given it unvalidated, answers with an error instead of a panic
    let m = err_text(mesh_planform(&p, 1.0, 0.0));
    assert!(m.contains("planform[4]"), "{m}");
}

#[test]
fn nearly_coincident_touching_and_spiky_outlines_are_refused_by_name() {
    let size = 30.0;
    let tol = MIN_SEPARATION_FRACTION * size;
    let cases: Vec<(Vec<[f64; 2]>, &str)> = vec![
        // two neighbours 0.1 × tol apart: a zero-length edge
        (
            vec![
                [0.0, 0.0],
                [0.0, -5.0],
                [30.0, -5.0],
                [30.0, 0.0],
                [0.1 * tol, 0.0],
            ],
            "zero-length edge",
        ),
        // two points that are not neighbours, nearly coincident
        (
            vec![
                [0.0, 0.0],
                [0.0, -5.0],
                [15.0, -0.2 * tol],
                [30.0, -5.0],
                [30.0, 0.0],
                [15.0, 0.0],
            ],
            "planform[2]",
        ),
        // a point within tol/2 of an edge it is not an end of (self-touching)
        (
            vec![
                [0.0, 0.0],
                [0.0, -5.0],
                [30.0, -5.0],
                [30.0, 0.0],
                [15.0, 0.0],
                [15.0, -5.0 + 0.5 * tol],
                [14.0, 0.0],
            ],
            "touches itself",
        ),
        // a spike of 0.1°, sharper than the limit
        (
            vec![
                [0.0, 0.0],
                [0.0, -5.0],
                [30.0, -5.0],
                [30.0, -2.5],
                [60.0, -2.5 + 30.0 * (0.1f64).to_radians().tan()],
                [30.0, -2.4],
                [30.0, 0.0],
            ],
            "spike",
        ),
    ];
    for (p, want) in cases {
        let m = err_text(validate_outline(&p));
        assert!(m.contains(want), "{p:?}: {m}");
        assert!(m.contains("planform["), "names a point: {m}");
        assert!(m.contains("allowed"), "says what is allowed: {m}");
        // unvalidated, straight into the mesher: an error too
        assert!(mesh_planform(&p, 2.0, 0.1).is_err(), "{p:?}");
    }
    // just inside the limits: accepted and meshed
    let ok = vec![
        [0.0, 0.0],
        [0.0, -5.0],
        [30.0, -5.0],
        [30.0, 0.0],
        [2.0 * tol, 0.0],
    ];
    let v = validate_outline(&ok).expect("2 × tol apart is accepted");
    let mesh = mesh_planform(&v, 2.0, 0.0).expect("and meshes");
    assert!(!mesh.triangles.is_empty());
}

#[test]
fn a_mesh_line_through_a_hair_off_an_outline_point_is_an_error_not_a_panic() {
    let p = validate_outline(&[
        [0.0, 0.0],
        [0.0, -5.0],
        [10.0, -6.0],
        [30.0, -5.0],
        [30.0, 0.0],
    ])
    .unwrap();
    for dx in [0.0, 1e-300, 1e-12, 1e-9, 1e-6, 1e-3] {
        let opts = MeshOptions {
            lines_x_mm: vec![10.0 + dx],
            ..MeshOptions::default()
        };
        // Ok or Err, never a panic; a line exactly through the point is fine
        let r = mesh_planform_with(&p, 2.0, 0.0, &opts);
        if dx == 0.0 || dx >= 1e-3 {
            assert!(r.is_ok(), "dx = {dx}: {:?}", r.err());
        }
    }
}

#[test]
fn the_mesher_refuses_bad_sizes_by_name() {
    let p = validate_outline(&[[0.0, 0.0], [0.0, -5.0], [30.0, -5.0], [30.0, 0.0]]).unwrap();
    for h in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let m = err_text(mesh_planform(&p, h, 0.0));
        assert!(m.contains("mesh_size_mm"), "{h}: {m}");
    }
}

/// A rectangle-like outline with a random number of extra points on or near its edges,
/// perturbed at scales from 1e-300 to 1 relative to its size, scaled by 10^k: the hostile
/// family of near-degenerate geometry.
fn hostile_outline() -> impl Strategy<Value = Vec<[f64; 2]>> {
    let scale = prop_oneof![
        Just(1.0),
        Just(1e-2),
        Just(1e3),
        Just(1e5),
        (-2.0f64..5.0).prop_map(|e| 10f64.powf(e))
    ];
    let eps = prop_oneof![
        Just(0.0),
        Just(1e-300),
        Just(1e-15),
        Just(1e-9),
        Just(1e-7),
        Just(1e-6),
        Just(2e-6),
        Just(1e-3),
        Just(0.1)
    ];
    (
        scale,
        proptest::collection::vec((0.0f64..1.0, eps.clone(), eps, 0usize..4), 0..8),
        1.0f64..20.0,
    )
        .prop_map(|(s, extra, aspect)| {
            let (w, h) = (aspect, 1.0);
            let mut pts = vec![[0.0, 0.0], [0.0, -h], [w, -h], [w, 0.0]];
            for (t, ex, ey, side) in extra {
                // a point on side `side` at parameter t, pushed off by (ex, ey) of the size
                let q = match side {
                    0 => [0.0, -h * t],
                    1 => [w * t, -h],
                    2 => [w, -h + h * t],
                    _ => [w - w * t, 0.0],
                };
                let at = (side + 1).min(pts.len());
                pts.insert(at, [q[0] + ex * w, q[1] + ey * h]);
            }
            pts.iter().map(|p| [p[0] * s, p[1] * s]).collect()
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, .. ProptestConfig::default() })]

    /// Whatever the validation accepts, the mesher meshes or refuses with an error; it never
    /// panics. Whatever it refuses, it refuses by name.
    #[test]
    fn meshing_any_accepted_outline_never_panics(p in hostile_outline()) {
        match validate_outline(&p) {
            Ok(v) => {
                let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
                for q in &v {
                    for k in 0..2 {
                        lo[k] = lo[k].min(q[k]);
                        hi[k] = hi[k].max(q[k]);
                    }
                }
                // about 100 elements' worth, so the test stays fast
                let h = ((hi[0] - lo[0]) * (hi[1] - lo[1])).sqrt() / 10.0;
                let r = std::panic::catch_unwind(|| mesh_planform(&v, h, 0.1));
                prop_assert!(r.is_ok(), "the mesher panicked on {:?}", v);
                if let Ok(Err(e)) = r {
                    prop_assert!(!e.to_string().is_empty());
                }
            }
            Err(e) => {
                let m = e.to_string();
                prop_assert!(m.contains("planform"), "{}", m);
            }
        }
    }

    /// The mesher on the same outlines unvalidated (as any caller could): no panic.
    #[test]
    fn the_mesher_never_panics_on_unvalidated_outlines(p in hostile_outline()) {
        let r = std::panic::catch_unwind(|| mesh_planform(&p, 0.5 * p[2][0].abs().max(1e-3), 0.0));
        prop_assert!(r.is_ok(), "the mesher panicked on {:?}", p);
    }
}
