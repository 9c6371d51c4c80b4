//! The wing side of the wasm API (the lab's own-wing panel): the built-in outlines, outline
//! files and live outline checks, the wing's parameter table and material presets, and the
//! `FemInput` built from them. Every function here is a thin wrapper over the core
//! ([`crate::fem::geometry`], [`crate::params`]), so the CLI and the lab parse and check the
//! same way.

use super::marshal::{
    err, f64_array_arg, from_js, int_arg, kind, parse_js_text, set, text_arg, to_js, u32_array_arg,
    MAX_TEXT_CHARS,
};
use crate::fem::geometry::{self, MAX_OUTLINE_POINTS};
use js_sys::Object;
use std::collections::BTreeMap;
use wasm_bindgen::prelude::*;

/// The built-in outlines: `[{ id, label, note, points_mm }]`, the synthetic Manduca-like
/// default (`manduca`) first, then `slender`, `broad` and `rect` (all synthetic, mm, root
/// edge on x = 0).
#[wasm_bindgen(unchecked_return_type = "BuiltinPlanform[]")]
pub fn planforms() -> Result<JsValue, JsError> {
    to_js(&geometry::builtin_planforms())
}

/// Parses an outline file's text, mm: `format` is `"csv"` (`x_mm,y_mm` or `i,x_mm,y_mm`
/// header optional, `#` comments) or `"json"` (`[[x, y], …]`), the formats of
/// `wingbeat modes --planform`. Returns the points in file order, unchecked (see
/// `checkPlanform`); throws naming the line or the JSON position.
#[wasm_bindgen(js_name = parsePlanform, unchecked_return_type = "[number, number][]")]
pub fn parse_planform(
    #[wasm_bindgen(unchecked_param_type = "string")] text: JsValue,
    #[wasm_bindgen(unchecked_param_type = "\"csv\" | \"json\"")] format: JsValue,
) -> Result<JsValue, JsError> {
    let format = text_arg(&format, "parsePlanform.format", 8, "\"csv\" or \"json\"")?;
    let text = text_arg(
        &text,
        "parsePlanform.text",
        MAX_TEXT_CHARS,
        "a string: the outline file's text",
    )?;
    let pts = match format.as_str() {
        "csv" => geometry::parse_planform_csv(&text),
        "json" => geometry::parse_planform_json(&text),
        other => Err(crate::WingbeatError::invalid(
            "parsePlanform.format",
            format!("{other:?}"),
            "\"csv\" or \"json\"",
        )),
    }
    .map_err(err)?;
    to_js(&pts)
}

use super::marshal::is_array;

/// Reads an outline `[[x, y], …]` (mm) from JS, its length checked before it is copied.
fn points_from(v: JsValue, what: &str) -> Result<Vec<[f64; 2]>, String> {
    let n = js_sys::Reflect::get(&v, &JsValue::from_str("length"))
        .ok()
        .and_then(|l| l.as_f64())
        .unwrap_or(f64::INFINITY);
    if n.is_nan() || n > MAX_OUTLINE_POINTS as f64 {
        return Err(crate::WingbeatError::ResourceCap {
            field: what.into(),
            requested: format!("{n} points"),
            cap: MAX_OUTLINE_POINTS.to_string(),
            why: "the outline checks are quadratic in the point count".into(),
        }
        .to_string());
    }
    parse_js_text(v, what)
}

/// Checks an outline while it is edited: `{ ok: true, area_mm2, span_mm, chord_mm, n_points,
/// root_edge, default_mesh_size_mm, default_strain_point_mm }` for a valid outline (at least
/// 3 distinct finite points, simple polygon, non-zero area; `root_edge`: an edge on x = 0, so
/// the root clamp applies; the automatic mesh size and strain point `feModes` would use), else
/// `{ ok: false, error }` naming what is wrong. Never throws for a bad outline; throws only
/// when `points` is not an array.
#[wasm_bindgen(js_name = checkPlanform, unchecked_return_type = "PlanformCheck")]
pub fn check_planform(
    #[wasm_bindgen(unchecked_param_type = "[number, number][]")] points: JsValue,
) -> Result<JsValue, JsError> {
    if !is_array(&points) {
        return Err(JsError::new(
            "invalid value for `points`: not an array (allowed: [[x_mm, y_mm], …])",
        ));
    }
    let o = Object::new();
    let checked = points_from(points, "points").and_then(|p| {
        let s = geometry::outline_summary(&p).map_err(|e| e.to_string())?;
        let outline = geometry::validate_outline(&p).map_err(|e| e.to_string())?;
        Ok((s, outline))
    });
    match checked {
        Ok((s, outline)) => {
            let (px, py) = crate::fem::default_strain_point_mm(&outline);
            #[derive(serde::Serialize)]
            struct Check<'a> {
                ok: bool,
                #[serde(flatten)]
                summary: &'a geometry::OutlineSummary,
                default_mesh_size_mm: f64,
                default_strain_point_mm: [f64; 2],
            }
            let h = crate::fem::default_mesh_size_mm(&outline);
            return to_js(&Check {
                ok: true,
                summary: &s,
                default_mesh_size_mm: h,
                default_strain_point_mm: [px, py],
            });
        }
        Err(m) => {
            set(&o, "ok", &JsValue::FALSE)?;
            set(&o, "error", &JsValue::from_str(&m))?;
        }
    }
    Ok(o.into())
}

/// The wing's parameters in panel order, from the core's table (`params::WING_PARAMS`):
/// `{ key, symbol, label, unit, min, max, step, default }` each — `camber` (rise / chord),
/// `clamp_mm` (0 = root clamp, else strip width, mm), `e_pa` (Pa), `rho` (kg/m³), `nu`,
/// `thickness_um` (µm), `mesh_mm` (0 = from the planform, mm), `n_modes` (1–8).
#[wasm_bindgen(js_name = wingParameters, unchecked_return_type = "WingParam[]")]
pub fn wing_parameters() -> Result<JsValue, JsError> {
    to_js(crate::params::wing_parameters())
}

/// The paper's two materials: `[{ id, label, e_pa, rho, nu, thickness_um }]`
/// (`paper-frequencies`, `paper-as-printed`), in the units of the wing parameters.
#[wasm_bindgen(js_name = materialPresets, unchecked_return_type = "MaterialPreset[]")]
pub fn material_presets() -> Result<JsValue, JsError> {
    to_js(&crate::params::material_presets())
}

/// The `FemInput` for `feModes` from the wing parameters by key (`WingOverrides`; missing
/// keys take their `wingParameters()` default) on the outline `points` (mm; default: the
/// synthetic Manduca-like outline), built by the core (`params::wing_input`). Throws naming
/// the key (`wing.KEY`) for an unknown key, a value that is not a number or lies outside its
/// range, and naming the outline for a bad outline.
#[wasm_bindgen(js_name = wingInput, unchecked_return_type = "FemInput")]
pub fn wing_input(
    #[wasm_bindgen(unchecked_param_type = "WingOverrides | undefined")] overrides: JsValue,
    #[wasm_bindgen(unchecked_param_type = "[number, number][] | undefined")] points: JsValue,
) -> Result<JsValue, JsError> {
    let o: BTreeMap<String, f64> = from_js(overrides, "wing")?;
    let pts = if points.is_undefined() || points.is_null() {
        None
    } else if is_array(&points) {
        Some(points_from(points, "points").map_err(|m| JsError::new(&m))?)
    } else {
        return Err(JsError::new(
            "invalid value for `points`: not an array (allowed: [[x_mm, y_mm], …] or undefined)",
        ));
    };
    let w = crate::params::wing_input(o.iter().map(|(k, v)| (k.as_str(), *v)), pts).map_err(err)?;
    to_js(&w)
}

/// `nodes`, `triangles` and `strain_nodes` as read by [`flat_mesh_args`].
pub(crate) type FlatMeshArgs = (Vec<f64>, Vec<u32>, Vec<f64>);

/// `feModes`' flat mesh arrays as given back by a caller: `nodes` (x, y, z per node),
/// `triangles` (three node indices each) and `strain_nodes` (3 values per node per mode), each
/// length checked against the browser's node cap before it is copied.
pub(crate) fn flat_mesh_args(
    nodes: &JsValue,
    triangles: &JsValue,
    strain_nodes: &JsValue,
    n_modes: usize,
) -> Result<FlatMeshArgs, JsError> {
    let (max_nodes, max_tris) = flat_mesh_caps();
    let nodes = f64_array_arg(nodes, "nodes", 3, 3 * max_nodes)?;
    let triangles = u32_array_arg(triangles, "triangles", 3, 3 * max_tris)?;
    let strain_nodes = strain_nodes_arg(strain_nodes, n_modes)?;
    Ok((nodes, triangles, strain_nodes))
}

/// The most nodes and triangles a flat mesh from JS may have: the FE node cap
/// ([`crate::fem::MAX_NODES`]) and twice as many triangles.
pub(crate) fn flat_mesh_caps() -> (usize, usize) {
    (crate::fem::MAX_NODES, 2 * crate::fem::MAX_NODES)
}

/// `strain_nodes` (3 values per node per mode) with its length checked against the node cap.
pub(crate) fn strain_nodes_arg(v: &JsValue, n_modes: usize) -> Result<Vec<f64>, JsError> {
    let (max_nodes, _) = flat_mesh_caps();
    f64_array_arg(v, "strain_nodes", 3, 3 * max_nodes * n_modes)
}

/// The nodal strain accessor over the flat `strain_nodes[(k·n_nodes + i)·3 + c]`.
fn flat_strain(s: &[f64], n_nodes: usize) -> impl Fn(usize, usize) -> [f64; 3] + '_ {
    move |k, i| {
        let o = (k * n_nodes + i) * 3;
        [s[o], s[o + 1], s[o + 2]]
    }
}

/// The modal strain of every mode at a point `[x_mm, y_mm]` of an FE wing, from `feModes`'
/// flat arrays (`nodes`, `triangles`, `strain_nodes`, `n_modes`): `[{ eps_x, eps_y, gamma_xy }]`
/// per mode, per unit q (top surface, Eqs. 16–18), interpolated in the triangle that holds the
/// point by the core function the FE modes use for their strain point
/// (`analysis::strain::modal_strains_at`). Throws naming `point` (with the mesh's extent) for
/// a point outside the meshed planform, and naming the array for inconsistent arrays.
#[cfg(feature = "web")]
#[wasm_bindgen(js_name = modalStrainAt, unchecked_return_type = "ModalStrainValues[]")]
pub fn modal_strain_at(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] nodes: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Uint32Array | number[]")] triangles: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] strain_nodes: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] n_modes: JsValue,
    #[wasm_bindgen(unchecked_param_type = "[number, number]")] point: JsValue,
) -> Result<JsValue, JsError> {
    use super::helpers::{check_mode_count, check_strain_nodes, mesh_from_flat};
    let max = crate::model::MAX_MODES;
    let n_modes = int_arg(&n_modes, "n_modes", 1, max)?;
    check_mode_count("n_modes", n_modes as f64).map_err(err)?;
    let (nodes, triangles, strain_nodes) =
        flat_mesh_args(&nodes, &triangles, &strain_nodes, n_modes)?;
    let point = f64_array_arg(&point, "point", 2, 2)?;
    let nn = check_strain_nodes(&strain_nodes, n_modes).map_err(err)?;
    let (p, t) = mesh_from_flat(&nodes, &triangles, nn).map_err(err)?;
    let e = crate::analysis::strain::modal_strains_at(
        &p,
        &t,
        n_modes,
        flat_strain(&strain_nodes, nn),
        point[0],
        point[1],
    )
    .map_err(err)?;
    #[derive(serde::Serialize)]
    struct Values {
        eps_x: f64,
        eps_y: f64,
        gamma_xy: f64,
    }
    let v: Vec<Values> = e
        .iter()
        .map(|e| Values {
            eps_x: e[0],
            eps_y: e[1],
            gamma_xy: e[2],
        })
        .collect();
    to_js(&v)
}

/// Reads `qs`, one series per mode (`Float64Array`s or arrays), each length checked against
/// the core's sample cap before it is copied.
fn series_list(qs: &JsValue, n_modes: usize) -> Result<Vec<Vec<f64>>, JsError> {
    if !is_array(qs) {
        return Err(err(crate::WingbeatError::invalid(
            "qs",
            kind(qs),
            "an array with one Float64Array (or array of numbers) per mode",
        )));
    }
    let n = js_sys::Reflect::get(qs, &JsValue::from_str("length"))
        .ok()
        .and_then(|l| l.as_f64())
        .unwrap_or(f64::NAN);
    if n != n_modes as f64 {
        return Err(err(crate::WingbeatError::invalid(
            "qs",
            format!("{n} series"),
            format!("one series per mode ({n_modes})"),
        )));
    }
    let cap = crate::config::MAX_SAMPLES;
    (0..n_modes)
        .map(|k| {
            let field = format!("qs[{k}]");
            let v = js_sys::Reflect::get_u32(qs, k as u32).map_err(|_| {
                err(crate::WingbeatError::invalid(
                    &field,
                    "unreadable",
                    "a Float64Array",
                ))
            })?;
            f64_array_arg(&v, &field, 1, cap)
        })
        .collect()
}

/// A whole-wing strain map: per node, the RMS or peak over a run of a strain component of
/// ε(t) = Σ_k ε_k q_k(t), from `feModes`' `strain_nodes`, `n_modes` and the modal responses
/// `qs` (one series per mode on one time grid, e.g. `sim.modes[k].q.total`). `opts`:
/// `{ component?: "eps_x" | "eps_y" | "gamma_xy" | "von_mises" (default), stat: "rms" |
/// "peak" }`. RMS is exact from the modal covariance; the peak visits every sample and is
/// capped (`limits().max_strain_field_work` = nodes × samples × modes; over it, throws: pass
/// every m-th sample). Returns a `Float64Array` of one value per node (strain, dimensionless).
#[cfg(feature = "web")]
#[wasm_bindgen(js_name = strainField)]
pub fn strain_field(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] strain_nodes: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] n_modes: JsValue,
    #[wasm_bindgen(unchecked_param_type = "(Float64Array | number[])[]")] qs: JsValue,
    #[wasm_bindgen(unchecked_param_type = "StrainFieldOptions")] opts: JsValue,
) -> Result<js_sys::Float64Array, JsError> {
    use super::helpers::{check_mode_count, check_strain_nodes};
    use super::marshal::required_js;
    let n_modes = int_arg(&n_modes, "n_modes", 1, crate::model::MAX_MODES)?;
    check_mode_count("n_modes", n_modes as f64).map_err(err)?;
    let strain_nodes = strain_nodes_arg(&strain_nodes, n_modes)?;
    let nn = check_strain_nodes(&strain_nodes, n_modes).map_err(err)?;
    let opts: crate::analysis::strain::StrainFieldOptions = required_js(
        opts,
        "strainField",
        "{ component?: eps_x | eps_y | gamma_xy | von_mises, stat: rms | peak }",
    )?;
    let qs = series_list(&qs, n_modes)?;
    let refs: Vec<&[f64]> = qs.iter().map(Vec::as_slice).collect();
    let v = crate::analysis::strain::strain_field(
        nn,
        n_modes,
        flat_strain(&strain_nodes, nn),
        &refs,
        &opts,
    )
    .map_err(err)?;
    Ok(js_sys::Float64Array::from(&v[..]))
}

/// Reads a modes file (core `modes_doc::read_modes_document`, the reader behind `wingbeat
/// simulate --modes`): the `wingbeat modes` JSON document (e.g. `feModes`' `modes_json`) or a
/// plain `{ "modes": [...] }`. Returns `{ modes, fe? }`: `modes` ready for a `SimConfig`
/// (checked, at most 64), and, when the document carries the FE mesh, `fe` with the same
/// layout as `feModes`' result (`freq_hz`, `a`, `b`, `kinds`, `mesh_size_mm`, `nodes`,
/// `triangles`, `shapes`, `strain_nodes` as flat typed arrays, …) but no `modes`. Throws
/// naming the document's part for malformed or inconsistent content.
#[cfg(feature = "web")]
#[wasm_bindgen(js_name = modesFromJson, unchecked_return_type = "ModesDocument")]
pub fn modes_from_json(
    #[wasm_bindgen(unchecked_param_type = "string")] text: JsValue,
) -> Result<JsValue, JsError> {
    let text = text_arg(
        &text,
        "modesFromJson.text",
        MAX_TEXT_CHARS,
        "a string: the modes file's JSON text",
    )?;
    let doc = crate::modes_doc::read_modes_document(&text, "modes JSON").map_err(err)?;
    let o = Object::new();
    set(&o, "modes", &to_js(&doc.modes)?)?;
    if let Some(fe) = &doc.fe {
        #[derive(serde::Serialize)]
        struct Extra<'a> {
            clamped_nodes: &'a [usize],
            material: &'a crate::fem::ShellMaterial,
        }
        let f = super::marshal::fe_js(
            fe,
            &Extra {
                clamped_nodes: &fe.clamped_nodes,
                material: &fe.material,
            },
        )?;
        set(&o, "fe", &f)?;
    }
    Ok(o.into())
}
