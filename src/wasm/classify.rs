//! `classifyRotation`: the published sensing study (Mohren et al. 2018) on the shell-FE plate
//! in the browser (docs/sensing.md, "Classifying rotation"); the same pipeline as
//! `wingbeat classify`.

use super::marshal::{err, from_js, function_arg, progress_fn, to_js};
use crate::analysis::rotation_classify::{
    classify_with_progress, fe_case, mohren2018_classes, mohren2018_grid_every, ClassifyOptions,
    ClassifyReport, CLASSIFY_STAGES,
};
use crate::error::check_range;
use crate::WingbeatError;
use serde::{Deserialize, Serialize};
use wasm_bindgen::prelude::*;

/// What `classifyRotation` is asked: the plate, the classes, the sensor grid and the
/// classification options; every field optional (the published values).
#[derive(Debug, Clone, Deserialize)]
#[serde(default, deny_unknown_fields)]
struct ClassifyRequest {
    n_modes: usize,
    mesh_size_mm: Option<f64>,
    rotation_rad_s: f64,
    flap_disturbance_rad_s: f64,
    rotation_disturbance_rad_s: f64,
    seed: u64,
    grid_step_mm: usize,
    options: ClassifyOptions,
}

impl Default for ClassifyRequest {
    fn default() -> Self {
        ClassifyRequest {
            n_modes: 8,
            mesh_size_mm: None,
            rotation_rad_s: 10.0,
            flap_disturbance_rad_s: 0.312,
            rotation_disturbance_rad_s: 0.1,
            seed: 1,
            grid_step_mm: 2,
            options: ClassifyOptions::default(),
        }
    }
}

/// Most sensors the browser classifies: a 2 mm grid of the plate (338); the published 1 mm
/// grid (1326, about 30 s in wasm) is the CLI's (`wingbeat classify`).
pub const WEB_MAX_CLASSIFY_SENSORS: usize = 400;

#[derive(Serialize)]
struct ModeSummary {
    freq_hz: f64,
    zeta: f64,
    kind: String,
}

#[derive(Serialize)]
struct ClassifyRotationResult {
    modes: Vec<ModeSummary>,
    report: ClassifyReport,
}

/// Rotation or none, told from the plate's strain as the published study tells it: the FE
/// modes of the 50 × 25 mm plate (browser FE cap), two 4 s runs from rest under seeded
/// disturbances, the spanwise strain at a grid `grid_step_mm` apart (default 2: 26 × 13 points;
/// 1, the published 26 × 51, is over the browser's [`WEB_MAX_CLASSIFY_SENSORS`]),
/// encoded and raw, classified on all, SSPOC and random sensors. Every field is checked and
/// named (`request.rotation_rad_s`, `options.train_fraction`, …) before the FE solve;
/// `progress(done, total)` after the FE solve and each of the pipeline's stages.
#[wasm_bindgen(js_name = classifyRotation, unchecked_return_type = "ClassifyRotationResult")]
pub fn classify_rotation(
    #[wasm_bindgen(unchecked_param_type = "ClassifyRequest | undefined")] request: JsValue,
    #[wasm_bindgen(
        unchecked_param_type = "((done: number, total: number) => void) | null | undefined"
    )]
    progress: JsValue,
) -> Result<JsValue, JsError> {
    let progress = function_arg(progress, "progress")?;
    let r: ClassifyRequest = from_js(request, "request")?;
    let check = |f: &str, v: f64, lo: f64, hi: f64, unit: &str| {
        check_range(&format!("request.{f}"), v, lo, hi, unit).map_err(err)
    };
    check("rotation_rad_s", r.rotation_rad_s, -100.0, 100.0, "rad/s")?;
    check(
        "flap_disturbance_rad_s",
        r.flap_disturbance_rad_s,
        0.0,
        100.0,
        "rad/s",
    )?;
    check(
        "rotation_disturbance_rad_s",
        r.rotation_disturbance_rad_s,
        0.0,
        100.0,
        "rad/s",
    )?;
    if !(1..=25).contains(&r.grid_step_mm) {
        return Err(err(WingbeatError::invalid(
            "request.grid_step_mm",
            r.grid_step_mm,
            "1 to 25 mm",
        )));
    }
    let points = mohren2018_grid_every(r.grid_step_mm);
    if points.len() > WEB_MAX_CLASSIFY_SENSORS {
        return Err(err(WingbeatError::ResourceCap {
            field: "request.grid_step_mm".into(),
            requested: format!("{} sensors ({} mm grid)", points.len(), r.grid_step_mm),
            cap: format!("{WEB_MAX_CLASSIFY_SENSORS} sensors in the browser (a 2 mm grid or coarser)"),
            why: "the 1326-sensor published grid takes about 30 s in wasm; `wingbeat classify` runs it natively".into(),
        }));
    }
    r.options.validate(points.len()).map_err(err)?;
    let classes = mohren2018_classes(
        r.rotation_rad_s,
        r.flap_disturbance_rad_s,
        r.rotation_disturbance_rad_s,
        r.seed,
    );
    for c in &classes {
        c.validate().map_err(err)?;
    }
    let mut progress = progress_fn(progress);
    let total = CLASSIFY_STAGES + 1;
    progress(0, total);
    let fe = crate::fem::compute_modes_capped(
        &crate::presets::mohren2018_plate_input(r.mesh_size_mm, r.n_modes),
        crate::fem::EigenOptions::default(),
        crate::fem::BROWSER_FE_MAX_WORK,
    )
    .map_err(err)?;
    progress(1, total);
    let case = fe_case(&fe, classes, &points).map_err(err)?;
    let report = classify_with_progress(&case, &r.options, &mut |d, _| progress(d + 1, total))
        .map_err(err)?;
    to_js(&ClassifyRotationResult {
        modes: case
            .modes
            .iter()
            .zip(&fe.kinds)
            .map(|(m, k)| ModeSummary {
                freq_hz: m.freq_hz,
                zeta: m.zeta,
                kind: k.clone(),
            })
            .collect(),
        report,
    })
}
