//! GPU tests of the renderer, offscreen (lavapipe in CI): golden images, the rendered tip
//! position against the analytic projection, zero-size and NaN robustness, the CLI glue.
//!
//! Without an adapter these tests print a notice and pass, unless `WINGBEAT_REQUIRE_GPU=1`,
//! when they fail. `WINGBEAT_UPDATE_GOLDEN=1` rewrites `tests/golden/*.png`.
#![cfg(all(feature = "render", not(target_arch = "wasm32")))]

use std::path::PathBuf;
use wingbeat::config::SimConfig;
use wingbeat::render::scene::wing_point_to_world;
use wingbeat::render::{
    render_frames, ColourMode, FrameParams, Offscreen, OrbitCamera, RenderError, RenderOptions,
    RgbaImage, WingMesh,
};

const W: u32 = 256;
const H: u32 = 192;
/// A pixel differs when any channel differs by more than this.
const PIXEL_THRESHOLD: u8 = 24;
/// At most this fraction of pixels may differ from the golden image.
const MAX_DIFF_FRACTION: f64 = 0.005;

fn offscreen(width: u32, height: u32, mesh: &WingMesh) -> Option<Offscreen> {
    match Offscreen::new(width, height, mesh) {
        Ok(o) => Some(o),
        Err(e @ (RenderError::NoAdapter(_) | RenderError::Device(_))) => {
            assert!(
                std::env::var("WINGBEAT_REQUIRE_GPU").as_deref() != Ok("1"),
                "WINGBEAT_REQUIRE_GPU=1 but no GPU is usable: {e}"
            );
            // Written to stderr directly, past the test harness's capture, so it shows.
            use std::io::Write;
            let _ = writeln!(
                std::io::stderr(),
                "SKIPPED (no GPU adapter; set WINGBEAT_REQUIRE_GPU=1 to fail instead): {e}"
            );
            None
        }
        Err(e) => panic!("offscreen renderer failed: {e}"),
    }
}

fn golden_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(format!("{name}.png"))
}

fn check_golden(name: &str, img: &RgbaImage) {
    let path = golden_path(name);
    if std::env::var("WINGBEAT_UPDATE_GOLDEN").as_deref() == Ok("1") {
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        img.write_png(&path).unwrap();
        eprintln!("updated {}", path.display());
        return;
    }
    let bytes = std::fs::read(&path).unwrap_or_else(|e| {
        panic!(
            "golden image {} missing ({e}); run with WINGBEAT_UPDATE_GOLDEN=1 to create it",
            path.display()
        )
    });
    let gold = RgbaImage::from_png(&bytes).unwrap();
    assert_eq!(
        (gold.width, gold.height),
        (img.width, img.height),
        "{name}: size"
    );
    let differing = gold
        .pixels
        .chunks(4)
        .zip(img.pixels.chunks(4))
        .filter(|(a, b)| {
            a.iter()
                .zip(b.iter())
                .any(|(x, y)| x.abs_diff(*y) > PIXEL_THRESHOLD)
        })
        .count();
    let frac = differing as f64 / (img.width * img.height) as f64;
    if frac > MAX_DIFF_FRACTION {
        let out = std::env::temp_dir().join(format!("wingbeat-{name}-actual.png"));
        let _ = img.write_png(&out);
        panic!(
            "{name}: {:.3} % of pixels differ from {} by more than {PIXEL_THRESHOLD} (allowed {:.3} %); actual image written to {}",
            frac * 100.0,
            path.display(),
            MAX_DIFF_FRACTION * 100.0,
            out.display()
        );
    }
}

fn is_background(p: [u8; 4]) -> bool {
    p[0] < 40 && p[1] < 40 && p[2] < 40
}

#[test]
fn golden_rest_pose_plain() {
    let mesh = WingMesh::synthetic(40, 16);
    let Some(mut off) = offscreen(W, H, &mesh) else {
        return;
    };
    let (img, report) = off.render(&FrameParams::default()).unwrap();
    assert!(report.legend.is_none());
    assert!(report.warnings.is_empty());
    check_golden("rest_plain", &img);
}

#[test]
fn golden_flapping_strain() {
    let mesh = WingMesh::synthetic(40, 16);
    let Some(mut off) = offscreen(W, H, &mesh) else {
        return;
    };
    let frame = FrameParams {
        alpha: 0.5,
        beta: -0.35,
        gamma: 0.1,
        q: vec![1.5e-5, -2e-5],
        exaggeration: 2.0,
        colour: ColourMode::ShearXY,
        ..FrameParams::default()
    };
    let (img, report) = off.render(&frame).unwrap();
    let legend = report.legend.unwrap();
    assert_eq!(legend.units, "strain");
    assert!(legend.max > 0.0 && legend.min == -legend.max);
    check_golden("flap_shear", &img);

    let frame = FrameParams {
        colour: ColourMode::Magnitude,
        ..frame
    };
    let (img, _) = off.render(&frame).unwrap();
    check_golden("flap_magnitude", &img);
}

/// The rendered wing lands where the analytic projection of the CPU mirror of the shader's
/// rotation puts it: bounding box and tip pixel within ±2 px.
#[test]
fn rendered_tip_matches_projection() {
    let mesh = WingMesh::synthetic(40, 16);
    let Some(mut off) = offscreen(W, H, &mesh) else {
        return;
    };
    let cam = OrbitCamera {
        target: [0.02, -0.01, 0.0],
        yaw: -1.7,
        pitch: 0.35,
        distance: 0.16,
        fov_y: 45f32.to_radians(),
    };
    off.renderer().camera = cam;
    for &(a, b, g) in &[
        (0.0f32, 0.0f32, 0.0f32),
        (0.6, 0.0, 0.0),
        (0.8, 0.5, 0.2),
        (-0.7, -0.4, 0.0),
    ] {
        let frame = FrameParams {
            alpha: a as f64,
            beta: b as f64,
            gamma: g as f64,
            show_axes: false,
            show_body_axis: false,
            show_stroke_plane: false,
            ..FrameParams::default()
        };
        let (img, _) = off.render(&frame).unwrap();
        let mut lo = [f32::INFINITY; 2];
        let mut hi = [f32::NEG_INFINITY; 2];
        for p in &mesh.nodes {
            let s = cam.project(wing_point_to_world(a, b, g, *p), W, H).unwrap();
            for c in 0..2 {
                lo[c] = lo[c].min(s[c]);
                hi[c] = hi[c].max(s[c]);
            }
        }
        let mut mlo = [u32::MAX; 2];
        let mut mhi = [0u32; 2];
        for y in 0..H {
            for x in 0..W {
                if !is_background(img.pixel(x, y)) {
                    mlo = [mlo[0].min(x), mlo[1].min(y)];
                    mhi = [mhi[0].max(x), mhi[1].max(y)];
                }
            }
        }
        assert!(mlo[0] != u32::MAX, "no wing pixels at α={a} β={b} γ={g}");
        for c in 0..2 {
            assert!(
                (mlo[c] as f32 + 0.5 - lo[c]).abs() <= 2.0
                    && (mhi[c] as f32 + 0.5 - hi[c]).abs() <= 2.0,
                "axis {c} at α={a} β={b} γ={g}: rendered [{}, {}] vs projected [{}, {}]",
                mlo[c],
                mhi[c],
                lo[c],
                hi[c]
            );
        }
        // The tip vertex itself: a wing pixel within 2 px of its projection.
        let tip = cam
            .project(
                wing_point_to_world(a, b, g, mesh.nodes[mesh.tip_node()]),
                W,
                H,
            )
            .unwrap();
        let near = (-2i32..=2).any(|dy| {
            (-2i32..=2).any(|dx| {
                let (x, y) = (tip[0] as i32 + dx, tip[1] as i32 + dy);
                x >= 0
                    && y >= 0
                    && (x as u32) < W
                    && (y as u32) < H
                    && !is_background(img.pixel(x as u32, y as u32))
            })
        });
        assert!(
            near,
            "no wing pixel within 2 px of the projected tip {tip:?} at α={a} β={b} γ={g}"
        );
    }
}

#[test]
fn zero_size_and_nan_do_not_panic() {
    let mesh = WingMesh::synthetic(10, 4);
    let Some(mut off) = offscreen(64, 48, &mesh) else {
        return;
    };
    assert!(matches!(
        off.renderer().resize(0, 48),
        Err(RenderError::ZeroSize {
            width: 0,
            height: 48
        })
    ));
    assert!(matches!(
        off.renderer().resize(u32::MAX, 1),
        Err(RenderError::TooLarge { .. })
    ));
    assert_eq!(off.renderer().size(), (64, 48));
    let nan = FrameParams {
        alpha: f64::NAN,
        beta: f64::NAN,
        gamma: f64::INFINITY,
        q: vec![f64::NAN, f64::NAN],
        exaggeration: f64::NAN,
        colour: ColourMode::StrainX,
        ..FrameParams::default()
    };
    let (a, report) = off.render(&nan).unwrap();
    assert!(report.warnings.len() >= 5, "{:?}", report.warnings);
    let zero = FrameParams {
        q: vec![0.0, 0.0],
        exaggeration: 0.0,
        colour: ColourMode::StrainX,
        ..FrameParams::default()
    };
    let (b, _) = off.render(&zero).unwrap();
    assert_eq!(a, b, "a NaN frame draws exactly like the all-zero frame");
    assert!(matches!(
        Offscreen::new(0, 10, &mesh),
        Err(RenderError::ZeroSize { .. })
    ));
}

#[test]
fn more_modes_than_the_cap_warn() {
    let mut mesh = WingMesh::synthetic(6, 3);
    for _ in 0..8 {
        mesh.shapes.push(mesh.shapes[0].clone());
        mesh.strains.push(mesh.strains[0].clone());
    }
    let Some(mut off) = offscreen(32, 32, &mesh) else {
        return;
    };
    assert_eq!(off.renderer().mesh().n_modes(), 8);
    assert!(off.renderer().warnings()[0].contains("10 modes"));
}

#[test]
fn frames_from_a_simulation() {
    let mesh = WingMesh::synthetic(12, 5);
    if offscreen(8, 8, &mesh).is_none() {
        return;
    }
    let mut cfg = SimConfig::paper();
    cfg.duration_s = 0.2;
    cfg.sample_rate_hz = 2000.0;
    let opts = RenderOptions {
        width: 96,
        height: 64,
        frames: 3,
        ..RenderOptions::default()
    };
    let imgs = render_frames(&cfg, &mesh, &opts).unwrap();
    assert_eq!(imgs.len(), 3);
    assert!(imgs
        .iter()
        .all(|i| i.width == 96 && i.pixels.len() == 96 * 64 * 4));
    assert_ne!(imgs[0], imgs[1], "the wing moves between frames");
}

/// The `wingbeat render` command: numbered PNGs, the legend line, readable errors.
#[cfg(feature = "cli")]
#[test]
fn cli_render_command() {
    if offscreen(8, 8, &WingMesh::synthetic(12, 5)).is_none() {
        return;
    }
    let dir = std::env::temp_dir().join(format!("wingbeat-render-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let cfg_path = dir.join("cfg.json");
    std::fs::write(&cfg_path, r#"{"duration_s": 0.1, "sample_rate_hz": 2000}"#).unwrap();
    let out = dir.join("f.png");
    let msg = render_cli(&[
        "--config",
        cfg_path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--frames",
        "2",
        "--width",
        "64",
        "--height",
        "48",
        "--colour",
        "gxy",
    ])
    .unwrap();
    assert!(
        msg.contains("f_000.png") && msg.contains("f_001.png"),
        "{msg}"
    );
    assert!(msg.contains("γ_xy") && msg.contains("strain"), "{msg}");
    let png = std::fs::read(dir.join("f_001.png")).unwrap();
    assert_eq!(RgbaImage::from_png(&png).unwrap().width, 64);
    let x = dir.join("x.png");
    let x = x.to_str().unwrap();
    let err = render_cli(&[
        "--out", x, "--width", "8", "--height", "8", "--colour", "purple",
    ])
    .unwrap_err();
    assert!(err.contains("colour"), "{err}");
    let err =
        render_cli(&["--out", x, "--width", "8", "--height", "8", "--frames", "0"]).unwrap_err();
    assert!(err.contains("frames"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Runs `wingbeat render ARGS`: the summary on success, the error message otherwise. (The CLI
/// glue lives in the binary, `src/cli/render.rs`.)
#[cfg(feature = "cli")]
fn render_cli(args: &[&str]) -> Result<String, String> {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_wingbeat"))
        .arg("render")
        .args(args)
        .output()
        .unwrap();
    let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    if out.status.success() {
        Ok(text(&out.stdout))
    } else {
        Err(text(&out.stderr))
    }
}

/// Frame time at 1280×720 with a ~10k-triangle mesh. Run with
/// `cargo test --release --features render --test render_gpu -- --ignored --nocapture`.
#[test]
#[ignore]
fn perf_1280x720_10k_triangles() {
    let mesh = WingMesh::synthetic(160, 32);
    let Some(mut off) = offscreen(1280, 720, &mesh) else {
        return;
    };
    println!("adapter: {}", off.adapter_name());
    println!(
        "triangles: {}, nodes: {}",
        mesh.triangles.len(),
        mesh.nodes.len()
    );
    let mut frame = FrameParams {
        q: vec![5e-4, -4e-4],
        exaggeration: 3.0,
        colour: ColourMode::Magnitude,
        ..FrameParams::default()
    };
    for _ in 0..3 {
        off.render_only(&frame).unwrap();
    }
    let n = 30;
    let t0 = std::time::Instant::now();
    for i in 0..n {
        frame.alpha = 0.8 * (i as f64 * 0.2).sin();
        frame.beta = 0.5 * (i as f64 * 0.2).sin();
        off.render_only(&frame).unwrap();
    }
    let render_ms = t0.elapsed().as_secs_f64() * 1e3 / n as f64;
    let t0 = std::time::Instant::now();
    for _ in 0..10 {
        off.render(&frame).unwrap();
    }
    let readback_ms = t0.elapsed().as_secs_f64() * 1e3 / 10.0;
    println!("frame time (render + wait): {render_ms:.2} ms; with 1280×720 read-back: {readback_ms:.2} ms");
}

/// The FE module's JSON output feeds the renderer unchanged.
#[test]
fn fe_modes_json_renders() {
    use wingbeat::fem::{compute_modes, FemInput};
    let input = FemInput {
        mesh_size_mm: Some(3.0),
        n_modes: 3,
        ..FemInput::default()
    };
    let fe = compute_modes(&input).unwrap();
    let v = serde_json::to_value(&fe).unwrap();
    let mesh = WingMesh::from_fe_json(&v).unwrap();
    assert_eq!(mesh.n_modes(), 3);
    assert_eq!(mesh.nodes.len(), fe.nodes.len());
    assert!(mesh.strains[0].iter().any(|e| e[0] != 0.0));
    let Some(mut off) = offscreen(128, 96, &mesh) else {
        return;
    };
    let frame = FrameParams {
        alpha: 0.3,
        q: vec![1e-5, -1e-5, 0.0],
        exaggeration: 2.0,
        colour: ColourMode::StrainY,
        show_axes: false,
        show_body_axis: false,
        show_stroke_plane: false,
        ..FrameParams::default()
    };
    let (img, report) = off.render(&frame).unwrap();
    assert!(report.warnings.is_empty(), "{:?}", report.warnings);
    let legend = report.legend.unwrap();
    assert!(legend.data_min < 0.0 || legend.data_max > 0.0);
    let wing_pixels = img
        .pixels
        .chunks(4)
        .filter(|p| !is_background([p[0], p[1], p[2], p[3]]))
        .count();
    assert!(wing_pixels > 500, "only {wing_pixels} wing pixels");
}

/// A node field (colour mode 5, e.g. a run's RMS strain) colours the wing: a field rising from
/// root to tip draws the root in the map's middle grey and the tip in its warm end; the legend
/// spans 0…limit; a wrong length is refused and non-finite values are reported.
#[test]
fn node_field_colours_the_wing() {
    let mesh = WingMesh::synthetic(40, 16);
    let Some(mut off) = offscreen(W, H, &mesh) else {
        return;
    };
    let span = mesh.span();
    let field: Vec<f64> = mesh.nodes.iter().map(|p| (p[0] / span) as f64).collect();
    assert!(off.renderer().set_node_field(&field[1..]).is_err());
    assert_eq!(off.renderer().set_node_field(&field).unwrap(), None);
    let frame = FrameParams {
        colour: ColourMode::Field,
        strain_range: Some(1.0),
        show_axes: false,
        show_body_axis: false,
        show_stroke_plane: false,
        ..FrameParams::default()
    };
    let (img, report) = off.render(&frame).unwrap();
    let legend = report.legend.unwrap();
    assert_eq!(
        (legend.component, legend.min, legend.max),
        ("field", 0.0, 1.0)
    );
    assert!(legend.data_max > 0.99 && legend.data_min.abs() < 1e-6);
    // Warm (red well above blue) and neutral wing pixels both occur; plain shading has no red.
    let (mut warm, mut neutral) = (0, 0);
    for y in 0..H {
        for x in 0..W {
            let p = img.pixel(x, y);
            if is_background(p) {
                continue;
            }
            if p[0] as i32 > p[2] as i32 + 60 && (p[1] as i32) < p[0] as i32 - 40 {
                warm += 1;
            } else if (p[0] as i32 - p[2] as i32).abs() < 20 {
                neutral += 1;
            }
        }
    }
    assert!(
        warm > 100 && neutral > 100,
        "warm {warm}, neutral {neutral}"
    );
    let (plain, _) = off
        .render(&FrameParams {
            colour: ColourMode::Plain,
            ..frame.clone()
        })
        .unwrap();
    assert_ne!(plain.pixels, img.pixels);
    let mut bad = field;
    bad[3] = f64::NAN;
    let note = off.renderer().set_node_field(&bad).unwrap().unwrap();
    assert!(note.contains("1 non-finite"), "{note}");
    assert_eq!(off.renderer().node_field()[3], 0.0);
}

/// The animation's per-frame path (`update_pose`: pose and q only, the uniform block alone)
/// draws exactly what a full `update` with the same pose and the held colouring draws, and
/// sanitises non-finite values to the all-zero pose as `update` does.
#[test]
fn pose_only_update_matches_full_update() {
    let mesh = WingMesh::synthetic(12, 5);
    let Some(mut off) = offscreen(96, 72, &mesh) else {
        return;
    };
    let base = FrameParams {
        alpha: 0.1,
        beta: -0.2,
        gamma: 0.0,
        q: vec![1.5e-5, -1.5e-5],
        exaggeration: 50.0,
        colour: ColourMode::Magnitude,
        strain_range: Some(1e-3),
        ..FrameParams::default()
    };
    let moved = FrameParams {
        alpha: 0.45,
        beta: -0.3,
        gamma: 0.1,
        q: vec![-1.0e-5, 2.0e-5],
        ..base.clone()
    };
    let (full, _) = off.render(&moved).unwrap();
    off.render(&base).unwrap();
    let changed = off
        .renderer()
        .update_pose(0.45, -0.3, 0.1, &[-1.0e-5, 2.0e-5]);
    assert_eq!(changed, 0);
    let fast = off.render_current().unwrap();
    assert_eq!(fast, full, "setPose draws what set_frame draws");
    assert_ne!(
        fast,
        off.render(&base).unwrap().0,
        "the pose changed the picture"
    );

    let zero = FrameParams {
        alpha: 0.0,
        beta: 0.0,
        gamma: 0.0,
        q: vec![0.0, 0.0],
        ..base.clone()
    };
    let (z, _) = off.render(&zero).unwrap();
    off.render(&base).unwrap();
    let changed = off
        .renderer()
        .update_pose(f64::NAN, f64::INFINITY, 0.0, &[f64::NAN, 0.0]);
    assert_eq!(changed, 3);
    assert_eq!(
        off.render_current().unwrap(),
        z,
        "non-finite values draw as 0"
    );
}
