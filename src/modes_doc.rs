//! Reading a modes file: the JSON document `wingbeat modes` writes
//! ([`crate::fem::modes_document`]) or a plain `{"modes": [...]}`. One reader for the CLI
//! (`wingbeat simulate --modes FILE`, [`modes_from_json`]) and the lab (wasm `modesFromJson`,
//! [`read_modes_document`], which also returns the FE mesh and shapes when the file has them).
//!
//! Accepted, as the CLI always has: an object with a `modes` array of [`Mode`]s; or, without
//! `modes`, the FE arrays `freq_hz` and `a` (and optionally `kinds`), which become modes with
//! zero damping and no strains. The other top-level keys of a `wingbeat modes` document (the
//! mesh, shapes, `units`, …: [`DOCUMENT_KEYS`]) are accepted; any other key is an error, as is
//! an unknown key inside a mode or a strain.

use crate::error::{Result, WingbeatError};
use crate::fem::FemModes;
use crate::model::{Mode, MAX_MODES};
use serde_json::Value;

/// Largest modes document accepted, bytes (the CLI's file cap).
pub const MAX_DOCUMENT_BYTES: usize = 64 * 1024 * 1024;

/// A modes file as the lab reads it.
#[derive(Debug, Clone, PartialEq)]
pub struct ModesDocument {
    /// The modes for a `SimConfig`.
    pub modes: Vec<Mode>,
    /// The FE result, when the document is a `wingbeat modes` output (it has `nodes`).
    pub fe: Option<FemModes>,
}

fn parse_err(what: &str, message: impl Into<String>) -> WingbeatError {
    WingbeatError::Parse {
        what: what.into(),
        message: message.into(),
    }
}

fn parse_value(text: &str, what: &str) -> Result<Value> {
    if text.len() > MAX_DOCUMENT_BYTES {
        return Err(WingbeatError::ResourceCap {
            field: what.into(),
            requested: format!("{} bytes", text.len()),
            cap: "64 MiB".into(),
            why: "the document is read whole".into(),
        });
    }
    serde_json::from_str(text).map_err(|e| parse_err(what, e.to_string()))
}

/// The top-level keys a modes document may have: those of a `wingbeat modes` document
/// ([`crate::fem::modes_document`]: every field of [`FemModes`], `modes` and `units`).
pub const DOCUMENT_KEYS: &[&str] = &[
    "planform_note",
    "freq_hz",
    "a",
    "b",
    "mass_kg",
    "centre_of_mass_m",
    "nodes",
    "triangles",
    "clamped_nodes",
    "shapes",
    "strain_nodes",
    "residuals",
    "kinds",
    "mass_orthonormality_error",
    "n_dofs",
    "material",
    "mesh_size_mm",
    "modes",
    "units",
];

fn modes_of(v: &Value, what: &str) -> Result<Vec<Mode>> {
    let obj = v
        .as_object()
        .ok_or_else(|| parse_err(what, "expected a JSON object"))?;
    if !obj.contains_key("modes") && !obj.contains_key("freq_hz") {
        return Err(parse_err(
            what,
            "expected `modes` or `freq_hz` + `a` arrays",
        ));
    }
    if let Some(k) = obj.keys().find(|k| !DOCUMENT_KEYS.contains(&k.as_str())) {
        return Err(parse_err(
            what,
            format!(
                "unknown top-level key `{k}` (allowed: {})",
                DOCUMENT_KEYS.join(", ")
            ),
        ));
    }
    check_companions(obj, what)?;
    if let Some(m) = v.get("modes") {
        let modes: Vec<Mode> = crate::error::from_json_value_at(m.clone(), what, "modes")?;
        check_strain_names(&modes, "modes")?;
        return Ok(modes);
    }
    let freqs: Vec<f64> = v
        .get("freq_hz")
        .and_then(|f| serde_json::from_value(f.clone()).ok())
        .ok_or_else(|| parse_err(what, "expected `modes` or `freq_hz` + `a` arrays"))?;
    let a: Vec<[f64; 2]> = v
        .get("a")
        .and_then(|f| serde_json::from_value(f.clone()).ok())
        .ok_or_else(|| parse_err(what, "missing `a` array of [x, y]"))?;
    if a.len() != freqs.len() {
        return Err(parse_err(
            what,
            format!("{} frequencies but {} a-vectors", freqs.len(), a.len()),
        ));
    }
    let kinds: Vec<String> = v
        .get("kinds")
        .and_then(|k| serde_json::from_value(k.clone()).ok())
        .unwrap_or_default();
    Ok(freqs
        .iter()
        .zip(&a)
        .enumerate()
        .map(|(k, (f, a))| Mode {
            name: format!(
                "{}: {}",
                k + 1,
                kinds.get(k).map_or("FE mode", String::as_str)
            ),
            freq_hz: *f,
            a: *a,
            zeta: 0.0,
            strains: vec![],
        })
        .collect())
}

/// The keys of a `wingbeat modes` document's `units` object.
pub const UNIT_KEYS: &[&str] = &[
    "freq_hz",
    "a",
    "b",
    "mass_kg",
    "nodes",
    "mesh_size_mm",
    "shapes",
    "strain_nodes",
];

/// Checks the companions of the modes in a document without `nodes` (a `wingbeat modes`
/// document trimmed of its mesh): each of its other known keys must be what a `wingbeat modes`
/// document has there (the type of that field of [`FemModes`]; `material` with exactly the
/// material's keys), and `units` only the unit strings of [`UNIT_KEYS`]. Unknown keys inside
/// them used to be dropped silently. Errors name the path (`units.speed`, `material.e_pa`).
/// With `nodes` the whole FE result is read and checked instead ([`read_modes_document`]).
fn check_companions(obj: &serde_json::Map<String, Value>, what: &str) -> Result<()> {
    use crate::error::from_json_value_at as typed;
    let has_nodes = obj.contains_key("nodes");
    for (k, v) in obj {
        let v = v.clone();
        match k.as_str() {
            "modes" | "nodes" => {}
            "units" => {
                let Some(u) = v.as_object() else {
                    return Err(parse_err(
                        what,
                        "at `units`: expected an object of unit strings",
                    ));
                };
                for (uk, uv) in u {
                    if !UNIT_KEYS.contains(&uk.as_str()) {
                        return Err(parse_err(
                            what,
                            format!(
                                "at `units.{uk}`: unknown unit key (allowed: {})",
                                UNIT_KEYS.join(", ")
                            ),
                        ));
                    }
                    if !uv.is_string() {
                        return Err(parse_err(
                            what,
                            format!("at `units.{uk}`: expected a unit string"),
                        ));
                    }
                }
            }
            _ if has_nodes => {}
            "planform_note" => typed::<String>(v, what, k).map(drop)?,
            "freq_hz" | "residuals" => typed::<Vec<f64>>(v, what, k).map(drop)?,
            "a" | "b" => typed::<Vec<[f64; 2]>>(v, what, k).map(drop)?,
            "mass_kg" | "mass_orthonormality_error" | "mesh_size_mm" => {
                typed::<f64>(v, what, k).map(drop)?;
            }
            "centre_of_mass_m" => typed::<[f64; 3]>(v, what, k).map(drop)?,
            "triangles" => typed::<Vec<[usize; 3]>>(v, what, k).map(drop)?,
            "clamped_nodes" => typed::<Vec<usize>>(v, what, k).map(drop)?,
            "shapes" => typed::<Vec<Vec<f64>>>(v, what, k).map(drop)?,
            "strain_nodes" => typed::<Vec<Vec<[f64; 3]>>>(v, what, k).map(drop)?,
            "kinds" => typed::<Vec<String>>(v, what, k).map(drop)?,
            "n_dofs" => typed::<usize>(v, what, k).map(drop)?,
            "material" => typed::<crate::fem::ShellMaterial>(v, what, k).map(drop)?,
            _ => {}
        }
    }
    Ok(())
}

/// Refuses two strain points with the same name in one mode (the second was silently
/// dropped), naming both; `what` is the path of the modes list.
pub fn check_strain_names(modes: &[Mode], what: &str) -> Result<()> {
    for (i, m) in modes.iter().enumerate() {
        let mut seen: std::collections::HashMap<&str, usize> = std::collections::HashMap::new();
        for (j, s) in m.strains.iter().enumerate() {
            if let Some(k) = seen.insert(s.point.as_str(), j) {
                return Err(WingbeatError::invalid(
                    format!("{what}[{i}].strains[{j}].point"),
                    format!("\"{}\", the name of {what}[{i}].strains[{k}] too", s.point),
                    "a strain point name used once per mode",
                ));
            }
        }
    }
    Ok(())
}

/// The modes of a modes document (what `wingbeat simulate --modes FILE` uses); `what` names
/// the document in errors. The modes are checked later, with the config they go into; the
/// FE result of a complete `wingbeat modes` document is read and checked as the lab reads it
/// ([`read_modes_document`]), so nothing in the file is ignored.
pub fn modes_from_json(text: &str, what: &str) -> Result<Vec<Mode>> {
    let v = parse_value(text, what)?;
    let modes = modes_of(&v, what)?;
    if v.get("nodes").is_some() {
        fe_of(v, what)?;
    }
    Ok(modes)
}

/// The FE result of a complete `wingbeat modes` document, checked.
fn fe_of(v: Value, what: &str) -> Result<FemModes> {
    let fe: FemModes = crate::error::from_json_value(v, &format!("{what}: fe"))?;
    check_fem_modes(&fe, what)?;
    Ok(fe)
}

/// Checks that an FE result's arrays fit together (every per-mode array has one entry per
/// mode, every per-node array one per node, triangle indices name nodes).
pub fn check_fem_modes(fe: &FemModes, what: &str) -> Result<()> {
    let w = format!("{what}: fe");
    let k = fe.freq_hz.len();
    let nn = fe.nodes.len();
    if k == 0 || k > MAX_MODES {
        return Err(parse_err(
            &w,
            format!("{k} frequencies; expected 1 to {MAX_MODES} modes"),
        ));
    }
    for (name, len) in [
        ("a", fe.a.len()),
        ("shapes", fe.shapes.len()),
        ("strain_nodes", fe.strain_nodes.len()),
    ] {
        if len != k {
            return Err(parse_err(
                &w,
                format!("`{name}` has {len} entries, expected one per mode ({k})"),
            ));
        }
    }
    if !fe.kinds.is_empty() && fe.kinds.len() != k {
        return Err(parse_err(
            &w,
            format!("`kinds` has {} entries, expected {k}", fe.kinds.len()),
        ));
    }
    if nn < 3 || fe.triangles.is_empty() {
        return Err(parse_err(&w, "no mesh: `nodes` and `triangles` are needed"));
    }
    for m in 0..k {
        if fe.shapes[m].len() != nn || fe.strain_nodes[m].len() != nn {
            return Err(parse_err(
                &w,
                format!(
                    "mode {}: `shapes` has {} and `strain_nodes` {} values, expected one per node ({nn})",
                    m + 1,
                    fe.shapes[m].len(),
                    fe.strain_nodes[m].len()
                ),
            ));
        }
    }
    if let Some((i, t)) = fe
        .triangles
        .iter()
        .enumerate()
        .find(|(_, t)| t.iter().any(|&n| n >= nn))
    {
        return Err(parse_err(
            &w,
            format!("triangle {i} {t:?} names a node beyond the {nn} nodes"),
        ));
    }
    if let Some(&c) = fe.clamped_nodes.iter().find(|&&c| c >= nn) {
        return Err(parse_err(
            &w,
            format!("clamped node {c} is beyond the {nn} nodes"),
        ));
    }
    Ok(())
}

/// A modes document for the lab: its modes (each checked as a config would check it, at most
/// [`MAX_MODES`]) and, when the document has `nodes` (a `wingbeat modes` output), the whole
/// FE result, checked with [`check_fem_modes`]; `what` names the document in errors.
pub fn read_modes_document(text: &str, what: &str) -> Result<ModesDocument> {
    let v = parse_value(text, what)?;
    let modes = modes_of(&v, what)?;
    if modes.is_empty() || modes.len() > MAX_MODES {
        return Err(WingbeatError::invalid(
            format!("{what}: modes"),
            format!("{} modes", modes.len()),
            format!("1 to {MAX_MODES} modes"),
        ));
    }
    for (i, m) in modes.iter().enumerate() {
        m.validate(i)?;
    }
    let fe = if v.get("nodes").is_some() {
        Some(fe_of(v, what)?)
    } else {
        None
    };
    Ok(ModesDocument { modes, fe })
}
