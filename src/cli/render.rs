//! The `wingbeat render` subcommand (feature `render`): plain parameters in, a summary or an
//! error message out (`cmd_render` wires clap to [`run_render`] and prints the result).

use std::path::{Path, PathBuf};
use wingbeat::config::SimConfig;
use wingbeat::render::offscreen::{render_frames_report, RenderOptions};
use wingbeat::render::{ColourMode, WingMesh};

/// The file name of frame `i` of `n`: `out` itself for one frame, else `stem_000.png`, ...
pub fn frame_path(out: &Path, i: usize, n: usize) -> PathBuf {
    if n <= 1 {
        return out.to_path_buf();
    }
    let stem = out
        .file_stem()
        .map_or_else(|| "frame".to_string(), |s| s.to_string_lossy().into_owned());
    let ext = out
        .extension()
        .map_or_else(|| "png".to_string(), |s| s.to_string_lossy().into_owned());
    let digits = (n - 1).to_string().len().max(3);
    out.with_file_name(format!("{stem}_{i:0digits$}.{ext}"))
}

/// Renders `frames` PNGs of the simulated wing.
///
/// * `config`: a SimConfig JSON file, or `None` for the paper's case;
/// * `mesh`: an FE mesh JSON file (see [`WingMesh::from_fe_json`]), or `None` for
///   [`WingMesh::synthetic`]`(40, 16)`;
/// * `out`: the PNG path (numbered `_000`, `_001`, ... when `frames > 1`);
/// * `exaggeration`: `None` for automatic (largest drawn deflection 15 % of the span);
/// * `colour`: `plain`, `ex`, `ey`, `gxy` or `mag`.
///
/// Returns a human-readable summary: files written, times, exaggeration, true deflection,
/// legend range, adapter and warnings.
#[allow(clippy::too_many_arguments)]
pub fn run_render(
    config: Option<&str>,
    mesh: Option<&str>,
    out: &str,
    frames: usize,
    width: u32,
    height: u32,
    exaggeration: Option<f64>,
    colour: &str,
) -> Result<String, String> {
    // An FE mesh from `wingbeat modes` also carries its modal-model modes: without a config,
    // simulate with those, so that the drawn shapes and the responses belong together.
    let mut fe_modes = None;
    let mesh = match mesh {
        Some(p) => {
            // the CLI's capped reader (64 MiB, also for devices and pipes) and the modes
            // document's reader (objects only, duplicate names refused)
            let text = super::read_file(Path::new(p)).map_err(|e| e.to_string())?;
            let v: serde_json::Value =
                serde_json::from_str(&text).map_err(|e| format!("{p}: invalid JSON: {e}"))?;
            if v.get("modes").is_some() {
                fe_modes = Some(
                    wingbeat::modes_doc::modes_from_json(&text, p).map_err(|e| e.to_string())?,
                );
            }
            WingMesh::from_fe_json(&v).map_err(|e| format!("{p}: {e}"))?
        }
        None => WingMesh::synthetic(40, 16),
    };
    let cfg = match (config, fe_modes) {
        (Some(p), _) => {
            let text = super::read_file(Path::new(p)).map_err(|e| e.to_string())?;
            SimConfig::from_json(&text).map_err(|e| format!("{p}: {e}"))?
        }
        (None, Some(modes)) => SimConfig {
            modes,
            ..SimConfig::paper()
        },
        (None, None) => SimConfig::paper(),
    };
    let colour = ColourMode::from_name(colour).ok_or_else(|| {
        format!("invalid value for `colour`: {colour} (allowed: plain, ex, ey, gxy, mag)")
    })?;
    if let Some(e) = exaggeration {
        if !e.is_finite() || e < 0.0 {
            return Err(format!(
                "invalid value for `exaggeration`: {e} (allowed: a finite number ≥ 0)"
            ));
        }
    }
    let opts = RenderOptions {
        width,
        height,
        frames,
        exaggeration,
        colour,
        ..RenderOptions::default()
    };
    let (images, summary) = render_frames_report(&cfg, &mesh, &opts)?;
    let out = Path::new(out);
    let mut lines = Vec::new();
    for (i, img) in images.iter().enumerate() {
        let path = frame_path(out, i, images.len());
        img.write_png(&path)?;
        lines.push(format!(
            "wrote {} (t = {:.6} s)",
            path.display(),
            summary.times[i]
        ));
    }
    lines.push(format!(
        "deflection drawn ×{:.3} (true largest deflection {:.4} mm)",
        summary.exaggeration,
        summary.max_deflection_m * 1e3
    ));
    if let Some(l) = &summary.legend {
        lines.push(format!(
            "colour: {} from {:.4e} to {:.4e} {}",
            l.component, l.min, l.max, l.units
        ));
    }
    lines.push(format!("adapter: {}", summary.adapter));
    for w in &summary.warnings {
        lines.push(format!("warning: {w}"));
    }
    Ok(lines.join("\n"))
}

#[cfg(test)]
mod tests {
    use super::frame_path;
    use std::path::Path;

    #[test]
    fn frame_paths_are_numbered() {
        assert_eq!(frame_path(Path::new("a/f.png"), 0, 1), Path::new("a/f.png"));
        assert_eq!(
            frame_path(Path::new("a/f.png"), 3, 12),
            Path::new("a/f_003.png")
        );
        assert_eq!(frame_path(Path::new("f"), 2, 1500), Path::new("f_0002.png"));
    }
}
