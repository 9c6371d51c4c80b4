//! Renders one frame of the synthetic wing to a PNG (the image in `docs/render.md`):
//!
//! ```sh
//! cargo run --release --features render --example render_wing -- docs/render.png [ex|ey|gxy|mag|plain] [fe]
//! ```
//!
//! With `fe`, the wing and its modes come from the shell FE (`wingbeat::fem`, 1.5 mm mesh,
//! default input) through its JSON, as the lab would pass them; otherwise the synthetic wing.

// Offscreen rendering is native-only; on wasm32 (`wasm-pack test` builds every example) this
// example is an empty program.
#[cfg(target_arch = "wasm32")]
fn main() {}

#[cfg(not(target_arch = "wasm32"))]
use wingbeat::render::{ColourMode, FrameParams, Offscreen, WingMesh};

#[cfg(not(target_arch = "wasm32"))]
fn main() -> Result<(), String> {
    let mut args = std::env::args().skip(1);
    let out = args.next().unwrap_or_else(|| "render.png".into());
    let colour = args.next().unwrap_or_else(|| "mag".into());
    let colour = ColourMode::from_name(&colour).ok_or(format!("unknown colouring {colour}"))?;
    let mesh = if args.next().as_deref() == Some("fe") {
        let input = wingbeat::fem::FemInput {
            mesh_size_mm: Some(1.5),
            n_modes: 2,
            ..Default::default()
        };
        let fe = wingbeat::fem::compute_modes(&input).map_err(|e| e.to_string())?;
        let json = serde_json::to_value(&fe).map_err(|e| e.to_string())?;
        WingMesh::from_fe_json(&json).map_err(|e| e.to_string())?
    } else {
        WingMesh::synthetic(80, 24)
    };
    println!(
        "{} nodes, {} triangles",
        mesh.nodes.len(),
        mesh.triangles.len()
    );
    let mut off = Offscreen::new(960, 640, &mesh)?;
    let frame = FrameParams {
        alpha: 0.45,
        beta: -0.3,
        gamma: 0.1,
        q: vec![1.5e-5, -1.5e-5],
        exaggeration: 2.0,
        colour,
        ..FrameParams::default()
    };
    let (img, report) = off.render(&frame)?;
    img.write_png(std::path::Path::new(&out))?;
    println!("wrote {out} on {}", off.adapter_name());
    println!(
        "true largest deflection {:.2} mm, drawn ×{}",
        report.max_deflection_m * 1e3,
        report.exaggeration
    );
    if let Some(l) = report.legend {
        println!("{}: {:.3e} … {:.3e} {}", l.component, l.min, l.max, l.units);
    }
    Ok(())
}
