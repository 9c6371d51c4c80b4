//! Crossing the wasm seam: JS values in (through JSON and serde, with the failing field's
//! path in the error), JS objects out (small metadata through serde, long series as
//! `Float64Array`s copied once out of wasm memory).

use super::helpers::check_web_caps;
use crate::analysis::psd::Spectrum;
use crate::config::SimConfig;
use crate::error::WingbeatError;
use crate::simulate::{SimResult, StrainSeries};
use js_sys::{Array, Float64Array, Object, Reflect};
use serde::de::DeserializeOwned;
use serde::Serialize;
use wasm_bindgen::prelude::*;

pub(crate) fn err(e: WingbeatError) -> JsError {
    JsError::new(&e.to_string())
}

/// Deserialises a JS value, naming the path of the first bad field in the error.
///
/// The value goes through `JSON.stringify` and serde_json — the same parser as the CLI's config
/// files — rather than straight through serde-wasm-bindgen, whose struct deserialiser skips
/// unknown keys and so would defeat `deny_unknown_fields`. NaN and ±Infinity become `null`
/// there and are reported as such.
pub(crate) fn from_js<T: DeserializeOwned + Default>(v: JsValue, what: &str) -> Result<T, JsError> {
    if v.is_undefined() || v.is_null() {
        return Ok(T::default());
    }
    parse_js(v, what)
}

pub(crate) fn parse_js<T: DeserializeOwned>(v: JsValue, what: &str) -> Result<T, JsError> {
    parse_js_text(v, what).map_err(|m| JsError::new(&m))
}

/// [`parse_js`] with the error as a plain message (for results that report rather than throw).
pub(crate) fn parse_js_text<T: DeserializeOwned>(v: JsValue, what: &str) -> Result<T, String> {
    if v.is_function() {
        return Err(format!(
            "invalid value for `{what}`: a function (expected a plain object, array or number)"
        ));
    }
    let text: String = js_sys::JSON::stringify(&v)
        .map_err(|_| {
            format!(
                "invalid value for `{what}`: not JSON-serialisable (cyclic, BigInt or a throwing getter)"
            )
        })?
        .as_string()
        .ok_or_else(|| {
            format!("invalid value for `{what}`: not JSON-serialisable (a symbol or undefined)")
        })?;
    let mut de = serde_json::Deserializer::from_str(&text);
    serde_path_to_error::deserialize(&mut de).map_err(|e| {
        let path = e.path().to_string();
        let place = if path == "." || path.is_empty() {
            what.to_string()
        } else {
            format!("{what}.{path}")
        };
        let inner = e.inner().to_string();
        let hint = if inner.contains("null") {
            " (NaN, ±Infinity and null are not numbers here)"
        } else {
            ""
        };
        format!("invalid value for `{place}`: {inner}{hint}")
    })
}

/// Reads a numeric series passed from JS (a `Float64Array` or an array of numbers), checking
/// its length against `cap` *before* anything is allocated (an object such as
/// `{ length: 2e9 }` is refused by name instead of aborting the instance), then that it is
/// non-empty and finite ([`super::helpers::check_series`]).
pub(crate) fn series_from_js(v: &JsValue, field: &str, cap: usize) -> Result<Vec<f64>, JsError> {
    let too_long = |n: f64| {
        err(WingbeatError::invalid(
            field,
            format!("{n} samples"),
            format!("1 to {cap} samples"),
        ))
    };
    let f = if v.is_instance_of::<Float64Array>() {
        v.clone().unchecked_into::<Float64Array>()
    } else if Array::is_array(v) {
        let n = Array::from(v).length();
        if n as usize > cap {
            return Err(too_long(f64::from(n)));
        }
        Float64Array::new(v)
    } else {
        return Err(JsError::new(&format!(
            "invalid value for `{field}`: not a Float64Array or an array of numbers"
        )));
    };
    if f.length() as usize > cap {
        return Err(too_long(f64::from(f.length())));
    }
    let x = f.to_vec();
    super::helpers::check_series(field, &x).map_err(err)?;
    Ok(x)
}

/// Deserialises options that have no defaults: `undefined`/`null` is an error that lists the
/// allowed shape (`allowed`, e.g. `"{ param, from, to, points }"`).
pub(crate) fn required_js<T: DeserializeOwned>(
    v: JsValue,
    what: &str,
    allowed: &str,
) -> Result<T, JsError> {
    if v.is_undefined() || v.is_null() {
        return Err(JsError::new(&format!(
            "invalid value for `{what}`: missing (allowed: {allowed})"
        )));
    }
    parse_js(v, what)
}

/// A `progress(done, total)` callback for the core's long loops: calls the JS function when
/// given and ignores an exception it throws (progress must never abort the computation).
pub(crate) fn progress_fn(progress: Option<js_sys::Function>) -> impl FnMut(usize, usize) {
    move |i, n| {
        if let Some(f) = &progress {
            let _ = f.call2(
                &JsValue::NULL,
                &JsValue::from_f64(i as f64),
                &JsValue::from_f64(n as f64),
            );
        }
    }
}

pub(crate) fn config_from(v: JsValue) -> Result<SimConfig, JsError> {
    let cfg: SimConfig = from_js(v, "config")?;
    cfg.validate().map_err(err)?;
    check_web_caps(&cfg).map_err(err)?;
    Ok(cfg)
}

pub(crate) fn to_js<T: Serialize + ?Sized>(v: &T) -> Result<JsValue, JsError> {
    v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| JsError::new(&format!("could not build the JS result: {e}")))
}

pub(crate) fn set(o: &Object, key: &str, v: &JsValue) -> Result<(), JsError> {
    Reflect::set(o, &JsValue::from_str(key), v)
        .map(|_| ())
        .map_err(|_| JsError::new(&format!("could not set `{key}` on the JS result")))
}

pub(crate) fn f64a(v: &[f64]) -> JsValue {
    Float64Array::from(v).into()
}

pub(crate) fn obj_with(pairs: &[(&str, &[f64])]) -> Result<Object, JsError> {
    let o = Object::new();
    for (k, v) in pairs {
        set(&o, k, &f64a(v))?;
    }
    Ok(o)
}

pub(crate) fn strain_js(s: &StrainSeries) -> Result<JsValue, JsError> {
    let o = obj_with(&[
        ("eps_x", &s.eps_x),
        ("eps_y", &s.eps_y),
        ("gamma_xy", &s.gamma_xy),
    ])?;
    set(&o, "point", &JsValue::from_str(&s.point))?;
    Ok(o.into())
}

#[derive(Serialize)]
struct ModeMeta<'a> {
    name: &'a str,
    freq_hz: f64,
    zeta: f64,
    contribution_percent: &'a crate::analysis::contribution::Contributions,
    floquet: &'a crate::floquet::FloquetResult,
    accuracy: &'a crate::simulate::Accuracy,
}

pub(crate) fn sim_js(r: &SimResult, sample_rate_hz: f64) -> Result<JsValue, JsError> {
    let o = Object::new();
    set(&o, "n", &JsValue::from_f64(r.t.len() as f64))?;
    set(&o, "sample_rate_hz", &JsValue::from_f64(sample_rate_hz))?;
    set(&o, "flap_freq_hz", &JsValue::from_f64(r.flap_freq_hz))?;
    set(&o, "t", &f64a(&r.t))?;
    let modes = Array::new();
    for m in &r.modes {
        let meta = to_js(&ModeMeta {
            name: &m.name,
            freq_hz: m.freq_hz,
            zeta: m.zeta,
            contribution_percent: &m.contribution_percent,
            floquet: &m.floquet,
            accuracy: &m.accuracy,
        })?;
        let mo: Object = meta.unchecked_into();
        let q = obj_with(&[
            ("euler", &m.q.euler),
            ("centrifugal", &m.q.centrifugal),
            ("coriolis", &m.q.coriolis),
            ("free", &m.q.free),
            ("total", &m.q.total),
        ])?;
        set(&mo, "q", &q)?;
        set(&mo, "qdot_total", &f64a(&m.qdot_total))?;
        modes.push(&mo);
    }
    set(&o, "modes", &modes)?;
    let strain = match &r.strain {
        Some(s) => strain_js(s)?,
        None => JsValue::NULL,
    };
    set(&o, "strain", &strain)?;
    let points = Array::new();
    for s in &r.strain_points {
        points.push(&strain_js(s)?);
    }
    set(&o, "strain_points", &points)?;
    set(&o, "warnings", &to_js(&r.warnings)?)?;
    Ok(o.into())
}

pub(crate) fn spectrum_js(s: &Spectrum) -> Result<JsValue, JsError> {
    let o = Object::new();
    set(&o, "freq_hz", &f64a(&s.freq_hz))?;
    set(&o, "psd", &f64a(&s.psd))?;
    set(&o, "peaks", &to_js(&s.peaks)?)?;
    Ok(o.into())
}

/// The small fields every FE result carries (`feModes` and `modesFromJson`'s `fe`), one
/// list for both; `extra` adds the caller's own fields (flattened into the same object).
#[derive(Serialize)]
struct FeMeta<'a, E: Serialize> {
    planform_note: &'a str,
    a: &'a [[f64; 2]],
    b: &'a [[f64; 2]],
    mass_kg: f64,
    centre_of_mass_m: [f64; 3],
    kinds: &'a [String],
    mass_orthonormality_error: f64,
    n_dofs: usize,
    n_nodes: usize,
    n_triangles: usize,
    n_modes: usize,
    mesh_size_mm: f64,
    #[serde(flatten)]
    extra: &'a E,
}

/// `fe` as a JS object: its metadata plus `extra`'s fields, then the long arrays
/// ([`fe_arrays_js`]).
pub(crate) fn fe_js<E: Serialize>(fe: &crate::fem::FemModes, extra: &E) -> Result<Object, JsError> {
    let o: Object = to_js(&FeMeta {
        planform_note: &fe.planform_note,
        a: &fe.a,
        b: &fe.b,
        mass_kg: fe.mass_kg,
        centre_of_mass_m: fe.centre_of_mass_m,
        kinds: &fe.kinds,
        mass_orthonormality_error: fe.mass_orthonormality_error,
        n_dofs: fe.n_dofs,
        n_nodes: fe.nodes.len(),
        n_triangles: fe.triangles.len(),
        n_modes: fe.freq_hz.len(),
        mesh_size_mm: fe.mesh_size_mm,
        extra,
    })?
    .unchecked_into();
    fe_arrays_js(&o, fe)?;
    Ok(o)
}

/// Sets the long arrays of an FE result on `o`, in `feModes`' layout: `freq_hz`, `residuals`,
/// `nodes` (x, y, z per node, m), `triangles` (`Uint32Array`), `shapes` (mode-major) and
/// `strain_nodes` (`[(k·n_nodes + i)·3 + c]`).
pub(crate) fn fe_arrays_js(o: &Object, fe: &crate::fem::FemModes) -> Result<(), JsError> {
    set(o, "freq_hz", &f64a(&fe.freq_hz))?;
    set(o, "residuals", &f64a(&fe.residuals))?;
    let nodes: Vec<f64> = fe.nodes.iter().flatten().copied().collect();
    set(o, "nodes", &f64a(&nodes))?;
    let tris: Vec<u32> = fe
        .triangles
        .iter()
        .flatten()
        .map(|&i| u32::try_from(i).unwrap_or(u32::MAX))
        .collect();
    set(o, "triangles", &js_sys::Uint32Array::from(&tris[..]).into())?;
    let shapes: Vec<f64> = fe.shapes.iter().flatten().copied().collect();
    set(o, "shapes", &f64a(&shapes))?;
    let strains: Vec<f64> = fe
        .strain_nodes
        .iter()
        .flatten()
        .flatten()
        .copied()
        .collect();
    set(o, "strain_nodes", &f64a(&strains))?;
    Ok(())
}
