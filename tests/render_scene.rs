//! Renderer maths that needs no GPU: rotation convention, camera, mesh input and validation,
//! sanitising, colour map and legend.
#![cfg(feature = "render")]
// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use nalgebra::{Rotation3, Vector3};
use wingbeat::render::scene::{
    diverging, legend_for, legend_for_field, wing_point_to_world, wing_rotation, DIVERGING_STOPS,
};
use wingbeat::render::{ColourMode, FrameParams, OrbitCamera, OrbitKey, WingMesh, MAX_MODES};
use wingbeat::WingbeatError;

fn field_of(e: WingbeatError) -> String {
    match e {
        WingbeatError::InvalidInput { field, .. } => field,
        other => panic!("expected InvalidInput, got {other:?}"),
    }
}

#[test]
fn rotation_matches_nalgebra_composition() {
    let angles = [-2.0f64, -0.8, -0.1, 0.0, 0.3, 0.8, 1.9];
    for &a in &angles {
        for &b in &angles {
            for &g in &[-0.2f64, 0.0, 0.15] {
                let r = Rotation3::from_axis_angle(&Vector3::x_axis(), a)
                    * Rotation3::from_axis_angle(&Vector3::y_axis(), b)
                    * Rotation3::from_axis_angle(&Vector3::z_axis(), g);
                let m = wing_rotation(a as f32, b as f32, g as f32);
                for c in 0..3 {
                    for row in 0..3 {
                        let d = (m[c][row] as f64 - r[(row, c)]).abs();
                        assert!(d < 1e-6, "R[{row}][{c}] at α={a} β={b} γ={g}: {d}");
                    }
                    assert_eq!(m[c][3], 0.0);
                    assert_eq!(m[3][c], 0.0);
                }
            }
        }
    }
}

#[test]
fn rigid_tip_follows_roll_then_pitch() {
    let mesh = WingMesh::synthetic(20, 8);
    let tip = mesh.nodes[mesh.tip_node()];
    assert!((tip[0] - 0.049).abs() < 1e-6);
    let (a, b, g) = (0.8f64, 0.5f64, 0.2f64);
    let r = Rotation3::from_axis_angle(&Vector3::x_axis(), a)
        * Rotation3::from_axis_angle(&Vector3::y_axis(), b)
        * Rotation3::from_axis_angle(&Vector3::z_axis(), g);
    let want = r * Vector3::new(tip[0] as f64, tip[1] as f64, tip[2] as f64);
    let got = wing_point_to_world(a as f32, b as f32, g as f32, tip);
    for c in 0..3 {
        assert!(
            (got[c] as f64 - want[c]).abs() < 1e-7,
            "{got:?} vs {want:?}"
        );
    }
    // Pure roll about I leaves a spanwise point fixed; pure pitch swings it toward −K.
    let p = [0.04, 0.0, 0.0];
    assert_eq!(wing_point_to_world(1.0, 0.0, 0.0, p), p);
    let q = wing_point_to_world(0.0, 0.5, 0.0, p);
    assert!((q[0] - 0.04 * 0.5f32.cos()).abs() < 1e-7);
    assert!((q[2] + 0.04 * 0.5f32.sin()).abs() < 1e-7);
}

#[test]
fn camera_projects_target_to_centre_and_orbits() {
    let mut cam = OrbitCamera::for_span(0.049);
    let c = cam.project(cam.target, 256, 192).unwrap();
    assert!(
        (c[0] - 128.0).abs() < 1e-3 && (c[1] - 96.0).abs() < 1e-3,
        "{c:?}"
    );
    // Points above the target (+K) project above the centre.
    let up = cam
        .project(
            [cam.target[0], cam.target[1], cam.target[2] + 0.01],
            256,
            192,
        )
        .unwrap();
    assert!(up[1] < 96.0);
    let d0 = cam.distance;
    cam.zoom(f32::NAN);
    cam.zoom(-1.0);
    assert_eq!(cam.distance, d0);
    cam.key(OrbitKey::ZoomOut);
    assert!(cam.distance > d0);
    cam.drag(0.0, 1e6);
    assert!(cam.pitch < std::f32::consts::FRAC_PI_2);
    cam.drag(f32::NAN, 3.0);
    assert!(cam.yaw.is_finite() && cam.pitch.is_finite());
    // Behind the eye: None.
    let eye = cam.eye();
    let behind = [
        2.0 * eye[0] - cam.target[0],
        2.0 * eye[1] - cam.target[1],
        2.0 * eye[2] - cam.target[2],
    ];
    assert!(cam.project(behind, 256, 192).is_none());
}

#[test]
fn synthetic_wing_is_manduca_like() {
    let m = WingMesh::synthetic(40, 16);
    m.validate().unwrap();
    assert_eq!(m.triangles.len(), 40 * 16 * 2 - 16);
    assert_eq!(m.n_modes(), 2);
    let area: f32 = m
        .triangles
        .iter()
        .map(|t| {
            let [p, q, r] = t.map(|k| m.nodes[k as usize]);
            0.5 * ((q[0] - p[0]) * (r[1] - p[1]) - (r[0] - p[0]) * (q[1] - p[1])).abs()
        })
        .sum();
    let span = m.span();
    assert!((span - 0.049).abs() < 1e-6);
    let mean_chord = area / span;
    assert!(
        (mean_chord - 0.018).abs() < 0.001,
        "mean chord {mean_chord}"
    );
    // Camber: the largest z is ≈ 13 % of the largest chord (≈ 24.7 mm).
    let zmax = m.nodes.iter().map(|p| p[2]).fold(0.0, f32::max);
    assert!(zmax > 0.13 * 0.022 && zmax < 0.13 * 0.026, "zmax {zmax}");
    // Bending ∝ (x/L)²; torsion changes sign across y_c.
    let tip = m.tip_node();
    for (i, p) in m.nodes.iter().enumerate() {
        let want = m.shapes[0][tip] * (p[0] / span).powi(2);
        assert!((m.shapes[0][i] - want).abs() < 1e-4 * m.shapes[0][tip].abs());
    }
    let (lo, hi) = m.shapes[1]
        .iter()
        .fold((0.0f32, 0.0f32), |(a, b), v| (a.min(*v), b.max(*v)));
    assert!(lo < 0.0 && hi > 0.0);
    // Bending strain is spanwise only, torsion is shear only.
    assert!(m.strains[0]
        .iter()
        .all(|e| e[0] < 0.0 && e[1] == 0.0 && e[2] == 0.0));
    assert!(m.strains[1]
        .iter()
        .all(|e| e[0] == 0.0 && e[1] == 0.0 && e[2] != 0.0));
    // Degenerate sizes are clamped, not panics.
    WingMesh::synthetic(0, 0).validate().unwrap();
}

#[test]
fn validation_names_the_field() {
    let good = WingMesh::synthetic(4, 2);
    let mut m = good.clone();
    m.nodes[3][1] = f32::NAN;
    assert_eq!(field_of(m.validate().unwrap_err()), "nodes[3][1]");
    let mut m = good.clone();
    m.triangles[2][2] = 10_000;
    assert_eq!(field_of(m.validate().unwrap_err()), "triangles[2][2]");
    let mut m = good.clone();
    m.shapes[1].pop();
    assert_eq!(field_of(m.validate().unwrap_err()), "shapes[1]");
    let mut m = good.clone();
    m.shapes[0][5] = f32::INFINITY;
    assert_eq!(field_of(m.validate().unwrap_err()), "shapes[0][5]");
    let mut m = good.clone();
    m.strains.pop();
    assert_eq!(field_of(m.validate().unwrap_err()), "strains");
    let mut m = good.clone();
    m.strains[1][7][2] = f32::NAN;
    assert_eq!(field_of(m.validate().unwrap_err()), "strains[1][7][2]");
    let mut m = good;
    m.triangles.clear();
    assert_eq!(field_of(m.validate().unwrap_err()), "triangles");
    let m = WingMesh::default();
    assert_eq!(field_of(m.validate().unwrap_err()), "nodes");
}

#[test]
fn fe_json_round_trip_and_errors() {
    let m = WingMesh::synthetic(6, 3);
    let v = serde_json::json!({
        "nodes": m.nodes,
        "triangles": m.triangles,
        "shapes": m.shapes,
        "strain_nodes": m.strains,
        "freq_hz": [60.0, 84.0],
    });
    let back = WingMesh::from_fe_json(&v).unwrap();
    assert_eq!(back, m);
    // Strains are optional; [ux, uy, uz] shape entries use uz.
    let v = serde_json::json!({
        "nodes": [[0.0, 0.0, 0.0], [0.01, 0.0, 0.0], [0.0, -0.01, 0.0]],
        "triangles": [[0, 1, 2]],
        "shapes": [[[0.0, 0.0, 0.0], [0.0, 0.0, 2.0], [0.0, 0.0, 1.0]]],
    });
    let m = WingMesh::from_fe_json(&v).unwrap();
    assert_eq!(m.shapes, vec![vec![0.0, 2.0, 1.0]]);
    assert_eq!(m.strains, vec![vec![[0.0; 3]; 3]]);
    let bad = |v: serde_json::Value| field_of(WingMesh::from_fe_json(&v).unwrap_err());
    assert_eq!(bad(serde_json::json!({})), "nodes");
    assert_eq!(
        bad(serde_json::json!({"nodes": [[0, 0, 0], [1, 0]], "triangles": [], "shapes": []})),
        "nodes[1]"
    );
    assert_eq!(
        bad(
            serde_json::json!({"nodes": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
            "triangles": [[0, 1, -2]], "shapes": []})
        ),
        "triangles[0][2]"
    );
    assert_eq!(
        bad(
            serde_json::json!({"nodes": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
            "triangles": [[0, 1, 2]], "shapes": [[0, 1, 2]],
            "strain_nodes": [[[0, 0, 0], [0, 0, 0], [0, "x", 0]]]})
        ),
        "strain_nodes[0][2][1]"
    );
    assert_eq!(
        bad(
            serde_json::json!({"nodes": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
            "triangles": [[0, 1, 2]], "shapes": [[0, 1, 2]],
            "strain_nodes": [[[0, 0, 0], [0, 0, 0]]]})
        ),
        "strain_nodes[0]"
    );
}

/// Guards `WingMesh::from_flat`, the path the browser lab's FE wing takes (typed arrays from
/// the wasm `feModes`): it must rebuild exactly the mesh the FE JSON path gives, and name the
/// array that is wrong.
#[test]
fn flat_arrays_round_trip_and_errors() {
    let m = WingMesh::synthetic(6, 3);
    let nodes: Vec<f64> = m.nodes.iter().flatten().map(|&v| v as f64).collect();
    let tris: Vec<u32> = m.triangles.iter().flatten().copied().collect();
    let shapes: Vec<f64> = m.shapes.iter().flatten().map(|&v| v as f64).collect();
    let strains: Vec<f64> = m
        .strains
        .iter()
        .flatten()
        .flatten()
        .map(|&v| v as f64)
        .collect();
    assert_eq!(
        WingMesh::from_flat(&nodes, &tris, &shapes, &strains).unwrap(),
        m
    );
    // No strains: zero strain fields, one per mode.
    let plain = WingMesh::from_flat(&nodes, &tris, &shapes, &[]).unwrap();
    assert_eq!(plain.strains.len(), m.shapes.len());
    assert!(plain.strains.iter().flatten().flatten().all(|&v| v == 0.0));
    let bad = |n: &[f64], t: &[u32], s: &[f64], e: &[f64]| {
        field_of(WingMesh::from_flat(n, t, s, e).unwrap_err())
    };
    assert_eq!(bad(&nodes[..7], &tris, &shapes, &strains), "nodes");
    assert_eq!(bad(&[], &tris, &shapes, &strains), "nodes");
    assert_eq!(bad(&nodes, &tris[..4], &shapes, &strains), "triangles");
    assert_eq!(bad(&nodes, &tris, &shapes[..5], &strains), "shapes");
    assert_eq!(bad(&nodes, &tris, &shapes, &strains[..9]), "strain_nodes");
    let mut t2 = tris.clone();
    t2[5] = 10_000;
    assert_eq!(bad(&nodes, &t2, &shapes, &strains), "triangles[1][2]");
    let mut s2 = shapes.clone();
    s2[3] = f64::NAN;
    assert_eq!(bad(&nodes, &tris, &s2, &strains), "shapes[0][3]");
    let mut e2 = strains;
    e2[4] = f64::INFINITY;
    assert_eq!(bad(&nodes, &tris, &shapes, &e2), "strain_nodes[0][1][1]");
}

#[test]
fn non_finite_frame_values_are_sanitised() {
    let p = FrameParams {
        alpha: f64::NAN,
        beta: f64::INFINITY,
        gamma: 0.1,
        q: vec![1.0, f64::NAN, 1e300, 0.0, 0.0, 0.0, 0.0, 0.0, 9.0, 9.0],
        exaggeration: f64::NEG_INFINITY,
        strain_range: Some(f64::NAN),
        ..FrameParams::default()
    };
    let (c, warnings) = p.sanitise();
    assert_eq!((c.alpha, c.beta, c.gamma), (0.0, 0.0, 0.1));
    assert_eq!(c.q[0], 1.0);
    assert_eq!(c.q[1], 0.0);
    assert_eq!(c.q[2], 1.0e6);
    assert_eq!(c.exaggeration, 0.0);
    assert_eq!(c.strain_range, None);
    assert_eq!(c.q.len(), MAX_MODES);
    for w in [
        "alpha",
        "beta",
        "q[1]",
        "q[2]",
        "exaggeration",
        "strain_range",
        "10 modal",
    ] {
        assert!(
            warnings.iter().any(|s| s.contains(w)),
            "no warning for {w}: {warnings:?}"
        );
    }
    let (_, none) = FrameParams::default().sanitise();
    assert!(none.is_empty());
}

#[test]
fn colour_map_and_legend() {
    let close = |a: [f32; 3], b: [f32; 3]| a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-6);
    assert!(close(diverging(0.0), DIVERGING_STOPS[0].1));
    assert!(close(diverging(1.0), DIVERGING_STOPS[4].1));
    assert!(close(diverging(0.5), DIVERGING_STOPS[2].1));
    assert!(close(diverging(f32::NAN), DIVERGING_STOPS[2].1));
    let field = vec![[1e-3, -2e-3, 0.0], [-4e-3, 0.0, 3e-3]];
    let l = legend_for(ColourMode::StrainX, &field, None).unwrap();
    assert_eq!((l.min, l.max, l.units), (-4e-3, 4e-3, "strain"));
    assert_eq!((l.data_min, l.data_max), (-4e-3, 1e-3));
    let l = legend_for(ColourMode::Magnitude, &field, None).unwrap();
    assert_eq!(l.min, 0.0);
    let m = ((16e-6f32) + 0.5 * 9e-6).sqrt();
    assert!((l.max - m).abs() < 1e-9);
    assert!(close(l.stops().first().unwrap().1, DIVERGING_STOPS[2].1));
    let l = legend_for(ColourMode::ShearXY, &field, Some(0.01)).unwrap();
    assert_eq!((l.min, l.max), (-0.01, 0.01));
    assert!(legend_for(ColourMode::Plain, &field, None).is_none());
    for m in ColourMode::ALL {
        assert_eq!(ColourMode::from_index(m.index()), Some(m));
    }
    assert_eq!(ColourMode::from_name("gxy"), Some(ColourMode::ShearXY));
    assert_eq!(ColourMode::from_name("field"), Some(ColourMode::Field));
    assert_eq!(ColourMode::Field.index(), 5);
    // The node field's legend: 0…M for a non-negative field, ±M when a value is negative.
    let l = legend_for_field(&[0.0, 1e-3, 4e-3, f32::NAN], Some(2e-3));
    assert_eq!((l.component, l.min, l.max), ("field", 0.0, 2e-3));
    assert_eq!((l.data_min, l.data_max), (0.0, 4e-3));
    assert!(close(l.stops().first().unwrap().1, DIVERGING_STOPS[2].1));
    let l = legend_for_field(&[-3e-3, 1e-3], None);
    assert_eq!((l.min, l.max), (-3e-3, 3e-3));
    assert_eq!(legend_for_field(&[], None).max, 1e-12);
    assert_eq!(ColourMode::from_name("nope"), None);
}

// `frame_path` (numbered PNG names) moved with the CLI glue: `src/cli/render.rs`'s unit tests.

#[test]
fn frame_at_time_uses_the_kinematics() {
    let cfg = wingbeat::config::SimConfig::paper();
    let kin = cfg.kinematics.compile();
    let t = 0.0123;
    let s = kin.state(t);
    let f = FrameParams::at_time(&kin, t, vec![1e-5]);
    assert_eq!((f.alpha, f.beta, f.gamma), (s.alpha, s.beta, s.gamma));
    assert_eq!(f.q, vec![1e-5]);
    assert_eq!(f.exaggeration, 1.0);
}

/// Guards the WebGPU canvas background: on a plain-UNORM target the clear colour is
/// sRGB-encoded by hand (as the shaders encode their output), on sRGB targets left linear.
#[test]
fn background_is_encoded_for_unorm_targets() {
    use wingbeat::render::gpu::{background_for, BACKGROUND};
    let srgb = background_for(wgpu::TextureFormat::Rgba8UnormSrgb);
    assert_eq!(srgb, BACKGROUND);
    let unorm = background_for(wgpu::TextureFormat::Bgra8Unorm);
    let dec = |c: f64| {
        if c <= 0.04045 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    };
    for (e, l) in [
        (unorm.r, BACKGROUND.r),
        (unorm.g, BACKGROUND.g),
        (unorm.b, BACKGROUND.b),
    ] {
        assert!(e > 5.0 * l, "encoded {e} vs linear {l}");
        assert!((dec(e) - l).abs() < 1e-12);
    }
    assert_eq!(unorm.a, 1.0);
}

/// Normalised device coordinates of `p` through the camera's own view–projection matrix.
fn ndc(cam: &OrbitCamera, aspect: f32, p: [f32; 3]) -> (f32, f32, f32) {
    let c = wingbeat::render::scene::transform(&cam.view_proj(aspect), p);
    (c[0] / c[3], c[1] / c[3], c[3])
}

/// A wing-sized cloud of points (a flapping stroke's worth), deterministic.
fn stroke_cloud() -> Vec<[f32; 3]> {
    let mut pts = Vec::new();
    for i in 0..32 {
        let a = 0.8 * (std::f32::consts::TAU * i as f32 / 32.0).sin();
        for &(x, y) in &[
            (0.0, 0.0),
            (0.05, -0.005),
            (0.045, -0.02),
            (0.01, -0.025),
            (0.03, 0.004),
        ] {
            // roll about I by a: (x, y, z) -> (x, y cos a, y sin a), then lift along K by x·a/4
            pts.push([x, y * a.cos(), y * a.sin() + 0.25 * x * a]);
        }
    }
    pts
}

#[test]
fn fit_points_keeps_every_point_inside_with_margin_and_centres_them() {
    let pts = stroke_cloud();
    for &(yaw, pitch) in &[(-1.95f32, 0.8f32), (-1.05, 0.7), (0.4, -0.3), (2.6, 1.3)] {
        for &aspect in &[1280.0f32 / 560.0, 1.0, 370.0 / 420.0, 0.46] {
            for &margin in &[0.0f32, 0.04, 0.1] {
                let mut cam = OrbitCamera::for_span(0.05);
                cam.yaw = yaw;
                cam.pitch = pitch;
                assert!(cam.fit_points(&pts, aspect, margin));
                assert_eq!(
                    (cam.yaw, cam.pitch),
                    (yaw, pitch),
                    "the direction is the caller's"
                );
                let lim = 1.0 - margin;
                let (mut x0, mut x1, mut y0, mut y1) = (f32::MAX, f32::MIN, f32::MAX, f32::MIN);
                for &p in &pts {
                    let (nx, ny, w) = ndc(&cam, aspect, p);
                    assert!(w > 0.0, "in front of the eye");
                    assert!(
                        nx.abs() <= lim + 1e-4 && ny.abs() <= lim + 1e-4,
                        "({nx}, {ny}) outside ±{lim} at yaw {yaw}, pitch {pitch}, aspect {aspect}"
                    );
                    x0 = x0.min(nx);
                    x1 = x1.max(nx);
                    y0 = y0.min(ny);
                    y1 = y1.max(ny);
                }
                // Tight: the box touches the margin on one axis (no wasted zoom) ...
                let reach = (x1 - x0).max(y1 - y0) * 0.5;
                let touch = ((x1 - x0) * 0.5 - lim)
                    .abs()
                    .min(((y1 - y0) * 0.5 - lim).abs());
                assert!(
                    touch < 2e-3,
                    "tight fit: half-extents {} × {} vs {lim}",
                    (x1 - x0) * 0.5,
                    (y1 - y0) * 0.5
                );
                assert!(reach <= lim + 1e-4);
                // ... and centred on both.
                assert!(
                    (0.5 * (x0 + x1)).abs() < 2e-3 && (0.5 * (y0 + y1)).abs() < 2e-3,
                    "centred: x {x0}..{x1}, y {y0}..{y1}"
                );
                // The pixel projection agrees (the page's canvas): inside with the margin.
                let (w, h) = ((aspect * 400.0).round() as u32, 400u32);
                for &p in &pts {
                    let px = cam.project(p, w, h).expect("in front");
                    let (mx, my) = (0.5 * margin * w as f32, 0.5 * margin * h as f32);
                    assert!(
                        px[0] >= mx - 0.6
                            && px[0] <= w as f32 - mx + 0.6
                            && px[1] >= my - 0.6
                            && px[1] <= h as f32 - my + 0.6
                    );
                }
            }
        }
    }
}

#[test]
fn fit_points_is_independent_of_the_starting_target_and_distance() {
    let pts = stroke_cloud();
    let mut a = OrbitCamera::for_span(0.05);
    let mut b = OrbitCamera::for_span(0.05);
    b.target = [1.0, -2.0, 3.0];
    b.distance = 40.0;
    assert!(a.fit_points(&pts, 1.5, 0.05));
    assert!(b.fit_points(&pts, 1.5, 0.05));
    let eye_a = a.eye();
    let eye_b = b.eye();
    for k in 0..3 {
        assert!(
            (eye_a[k] - eye_b[k]).abs() < 1e-5,
            "same framing from any start: {eye_a:?} vs {eye_b:?}"
        );
    }
}

#[test]
fn fit_points_leaves_the_camera_alone_when_there_is_nothing_to_fit() {
    let cam0 = OrbitCamera::for_span(0.05);
    let mut cam = cam0;
    assert!(!cam.fit_points(&[], 1.0, 0.05));
    assert!(!cam.fit_points(
        &[[f32::NAN, 0.0, 0.0], [0.0, f32::INFINITY, 0.0]],
        1.0,
        0.05
    ));
    assert!(!cam.fit_points(&stroke_cloud(), 0.0, 0.05));
    assert!(!cam.fit_points(&stroke_cloud(), f32::NAN, 0.05));
    assert_eq!(cam, cam0);
    // Non-finite points among finite ones are skipped; a single point is framed at its centre.
    assert!(cam.fit_points(&[[0.01, 0.02, 0.03], [f32::NAN, 0.0, 0.0]], 1.0, 0.05));
    let (nx, ny, _) = ndc(&cam, 1.0, [0.01, 0.02, 0.03]);
    assert!(nx.abs() < 1e-4 && ny.abs() < 1e-4);
    assert!(cam.distance.is_finite() && cam.distance > 0.0);
}
