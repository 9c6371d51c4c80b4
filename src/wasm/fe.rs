//! The shell finite-element side of the wasm API (paper §3.1): `feModes`.

use super::marshal::{err, fe_js, from_js};
use crate::fem::{FemInput, BROWSER_MAX_NODES};
use serde::{Deserialize, Serialize};
use wasm_bindgen::prelude::*;

/// The options of `feModes` (declared as `FeModesOptions`).
#[derive(Debug, Default, Deserialize)]
#[serde(default, deny_unknown_fields)]
struct FeModesOptions {
    /// The strain point [x, y], mm; default [`crate::fem::strain_point_for`] the input.
    strain_point_mm: Option<[f64; 2]>,
    /// Also return `modes_json`, the `wingbeat modes` JSON document.
    json: bool,
}

/// The input `feModes` solves: `input` with its node cap lowered to
/// [`BROWSER_MAX_NODES`] unless it asks for less.
pub(crate) fn browser_input(mut input: FemInput) -> FemInput {
    input.max_nodes = Some(
        input
            .max_nodes
            .map_or(BROWSER_MAX_NODES, |n| n.min(BROWSER_MAX_NODES)),
    );
    input
}

/// Shell FE modes of a wing (paper §3.1): mesh, assemble, solve `K φ = ω² M φ`, then the
/// modal model's inputs — frequencies, SI a_k and b_k, and `modes` ready for a `SimConfig`
/// (damping ratio `zeta`, modal strains at `strain_point_mm`: `opts.strain_point_mm`, else the
/// paper's P on the default outline and a point inside any other outline near its root).
/// The mesh size may be left out (automatic, reported as `mesh_size_mm`); the node cap is
/// `BROWSER_MAX_NODES` (or the input's `max_nodes` when lower, reported as `max_nodes`).
/// With `opts.json`, `modes_json` is the `wingbeat modes` JSON document of the same result.
/// The mesh, shapes and nodal strains come back as flat typed arrays (see `FeModesResult`).
/// Errors name the field (outline, material, camber, mesh size and its node cap, strain
/// point), and a mesh whose solve would exceed the browser's work budget
/// (`BROWSER_FE_MAX_WORK`) is refused before assembly. Seconds of work at fine meshes: call it
/// from a Web Worker.
#[wasm_bindgen(js_name = feModes, unchecked_return_type = "FeModesResult")]
pub fn fe_modes(
    #[wasm_bindgen(unchecked_param_type = "FemInput | undefined")] input: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number | null | undefined")] zeta: JsValue,
    #[wasm_bindgen(unchecked_param_type = "FeModesOptions | undefined")] opts: JsValue,
) -> Result<JsValue, JsError> {
    let zeta = super::marshal::opt_number_arg(&zeta, "zeta", "a number in [0, 10], or undefined")?
        .unwrap_or(0.0);
    let input = browser_input(from_js::<FemInput>(input, "fem")?);
    let opts: FeModesOptions = from_js(opts, "opts")?;
    crate::error::check_range("zeta", zeta, 0.0, 10.0, "").map_err(err)?;
    let (px, py) = match opts.strain_point_mm {
        Some([x, y]) => (x, y),
        None => crate::fem::strain_point_for(&input),
    };
    let fe = crate::fem::compute_modes_capped(
        &input,
        crate::fem::EigenOptions::default(),
        crate::fem::BROWSER_FE_MAX_WORK,
    )
    .map_err(err)?;
    let modes = fe
        .model_modes(zeta, &[("P".to_string(), px, py)], "opts.strain_point_mm")
        .map_err(err)?;
    #[derive(Serialize)]
    struct Extra<'a> {
        max_nodes: usize,
        strain_point_mm: [f64; 2],
        modes: &'a [crate::model::Mode],
        #[serde(skip_serializing_if = "Option::is_none")]
        modes_json: Option<String>,
    }
    let modes_json = if opts.json {
        Some(crate::fem::modes_document(&fe, &modes).map_err(err)?)
    } else {
        None
    };
    let o = fe_js(
        &fe,
        &Extra {
            max_nodes: input.max_nodes.unwrap_or(BROWSER_MAX_NODES),
            strain_point_mm: [px, py],
            modes: &modes,
            modes_json,
        },
    )?;
    Ok(o.into())
}
