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
/// there and are reported as such. Before that, [`check_js_value`] walks the value: its size
/// and depth are bounded and a function, symbol, BigInt or typed array inside it is refused
/// by path (`JSON.stringify` would drop the first two silently and throw on a BigInt).
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
    check_js_value(&v, what)?;
    let text: String = js_sys::JSON::stringify(&v)
        .map_err(|_| {
            format!(
                "invalid value for `{what}`: not JSON-serialisable (cyclic, or a getter or toJSON that throws)"
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

// ---------------------------------------------------------------------------------------------
// Argument checks. Every export takes its arguments as `JsValue`s and reads them through these
// helpers, which check the type (never coercing: "3" is not a number, 1 is not `true`), the
// length before anything is allocated, and finiteness, and name the argument in the error.
// Typed wasm-bindgen parameters (`&str`, `&[f64]`, `Vec<f64>`, `u32`) would instead copy
// whatever they are given into wasm memory first — a number where text is expected, or
// `{ length: 2e9 }` where a slice is, trapped the instance or leaked the allocation. Every JS
// call made here is a `catch` binding, so a throwing getter or a revoked proxy becomes an error
// instead of an exception unwinding through Rust frames.
// ---------------------------------------------------------------------------------------------

#[wasm_bindgen]
extern "C" {
    /// `Array.isArray` (throws for a revoked proxy).
    #[wasm_bindgen(catch, js_namespace = Array, js_name = isArray)]
    fn js_is_array(v: &JsValue) -> Result<bool, JsValue>;
    /// `Object.keys` (throws for some proxies).
    #[wasm_bindgen(catch, js_namespace = Object, js_name = keys)]
    fn js_object_keys(v: &JsValue) -> Result<Array, JsValue>;
}

/// `Array.isArray`, false for a value it throws on (a revoked proxy).
pub(crate) fn is_array(v: &JsValue) -> bool {
    js_is_array(v).unwrap_or(false)
}

/// `ArrayBuffer.isView`: a real typed array or DataView (a prototype trick cannot fake it).
fn js_is_view(v: &JsValue) -> bool {
    js_sys::ArrayBuffer::is_view(v)
}

/// `new Float64Array(typedArray)`: the values from the source's internal slots, no user code;
/// an error for BigInt arrays.
fn js_f64_copy(v: &JsValue) -> Result<Float64Array, JsValue> {
    let ctor = Float64Array::new_with_length(0).constructor();
    Reflect::construct(&ctor, &Array::of1(v)).map(JsCast::unchecked_into)
}

/// Most characters a text argument may have (file contents: outlines, kinematics CSV, modes
/// JSON): 32 Mi UTF-16 code units. The copy into wasm memory is at most 3 bytes per unit.
pub const MAX_TEXT_CHARS: usize = 32 * 1024 * 1024;

/// Most values (numbers, strings, array elements, object entries) an object argument (a
/// config, an options object, an FE input) may hold, and how deeply it may nest; checked
/// before it is serialised.
pub const MAX_JS_VALUES: usize = 1_000_000;
/// See [`MAX_JS_VALUES`].
pub const MAX_JS_DEPTH: usize = 32;

fn bad(field: &str, got: impl std::fmt::Display, allowed: impl Into<String>) -> JsError {
    err(WingbeatError::invalid(field, got, allowed))
}

/// A JS number as it would print in JS (`NaN`, `Infinity`, `1e+300` as `1e300`).
fn js_number(x: f64) -> String {
    if x.is_nan() {
        "NaN".into()
    } else if x.is_infinite() {
        if x > 0.0 { "Infinity" } else { "-Infinity" }.into()
    } else {
        crate::error::num(x)
    }
}

/// The length property of an array-like, when it is a number (a `catch` read).
fn length_of(v: &JsValue) -> Option<f64> {
    Reflect::get(v, &JsValue::from_str("length"))
        .ok()
        .and_then(|l| l.as_f64())
}

/// What a JS value is, for error messages (never its whole text).
pub(crate) fn kind(v: &JsValue) -> String {
    if v.is_undefined() {
        return "undefined".into();
    }
    if v.is_null() {
        return "null".into();
    }
    if let Some(x) = v.as_f64() {
        return format!("the number {}", js_number(x));
    }
    if let Some(b) = v.as_bool() {
        return format!("the boolean {b}");
    }
    if v.is_string() {
        let n = v.unchecked_ref::<js_sys::JsString>().length();
        return format!("a string of {n} characters");
    }
    match v.js_typeof().as_string().as_deref() {
        Some("function") => return "a function".into(),
        Some("symbol") => return "a symbol".into(),
        Some("bigint") => return "a BigInt".into(),
        _ => {}
    }
    if js_is_view(v) {
        let name = Reflect::get(v, &JsValue::from_str("constructor"))
            .ok()
            .and_then(|c| Reflect::get(&c, &JsValue::from_str("name")).ok())
            .and_then(|n| n.as_string())
            .filter(|n| n.len() <= 40)
            .unwrap_or_else(|| "typed array".into());
        return format!("a {name}");
    }
    if js_is_array(v).unwrap_or(false) {
        return match length_of(v) {
            Some(n) => format!("an array of {} elements", js_number(n)),
            None => "an array".into(),
        };
    }
    match length_of(v) {
        Some(n) => format!("an object with length {}", js_number(n)),
        None => "an object".into(),
    }
}

/// Walks an object argument before it is serialised: at most [`MAX_JS_VALUES`] values and
/// [`MAX_JS_DEPTH`] levels; a function, symbol, BigInt or typed array anywhere in it is
/// refused, naming its path (`what.key[i]`).
pub(crate) fn check_js_value(v: &JsValue, what: &str) -> Result<(), String> {
    let mut budget = MAX_JS_VALUES;
    walk_js(v, what, 0, &mut budget)
}

fn walk_js(v: &JsValue, path: &str, depth: usize, budget: &mut usize) -> Result<(), String> {
    let too_big = |path: &str| {
        WingbeatError::ResourceCap {
            field: path.to_string(),
            requested: format!("more than {MAX_JS_VALUES} values"),
            cap: format!("{MAX_JS_VALUES} values in one argument"),
            why: "the argument is copied into wasm memory as JSON".into(),
        }
        .to_string()
    };
    if *budget == 0 {
        return Err(too_big(path));
    }
    *budget -= 1;
    if v.is_undefined() || v.is_null() || v.as_f64().is_some() || v.as_bool().is_some() {
        return Ok(());
    }
    if v.is_string() {
        let n = v.unchecked_ref::<js_sys::JsString>().length() as usize;
        if n > MAX_TEXT_CHARS {
            return Err(WingbeatError::invalid(
                path,
                kind(v),
                format!("a string of at most {MAX_TEXT_CHARS} characters"),
            )
            .to_string());
        }
        return Ok(());
    }
    if !v.is_object() || js_is_view(v) {
        // a function, symbol, BigInt, typed array or DataView
        return Err(WingbeatError::invalid(
            path,
            kind(v),
            "plain JSON values: numbers, strings, booleans, arrays and objects",
        )
        .to_string());
    }
    if depth >= MAX_JS_DEPTH {
        return Err(WingbeatError::invalid(
            path,
            "nested too deeply",
            format!("at most {MAX_JS_DEPTH} levels of arrays and objects"),
        )
        .to_string());
    }
    let unreadable = |path: &str| {
        WingbeatError::invalid(path, "unreadable (a getter or proxy threw)", "plain data")
            .to_string()
    };
    if js_is_array(v).map_err(|_| unreadable(path))? {
        let n = length_of(v).ok_or_else(|| unreadable(path))?;
        if !(n >= 0.0 && n <= *budget as f64) {
            return Err(too_big(path));
        }
        for i in 0..n as u32 {
            let e = Reflect::get_u32(v, i).map_err(|_| unreadable(path))?;
            if e.is_undefined() || e.is_null() || e.as_f64().is_some() || e.as_bool().is_some() {
                // the common case (a list of numbers): no path string built
                if *budget == 0 {
                    return Err(too_big(path));
                }
                *budget -= 1;
            } else {
                walk_js(&e, &format!("{path}[{i}]"), depth + 1, budget)?;
            }
        }
        return Ok(());
    }
    let keys = js_object_keys(v).map_err(|_| unreadable(path))?;
    let n = keys.length() as usize;
    if n > *budget {
        return Err(too_big(path));
    }
    for k in keys.iter() {
        let e = Reflect::get(v, &k).map_err(|_| unreadable(path))?;
        let key = k.as_string().unwrap_or_default();
        walk_js(&e, &format!("{path}.{key}"), depth + 1, budget)?;
    }
    Ok(())
}

/// A text argument (a file's contents, a name): a JS string of at most `max_chars` UTF-16
/// units, checked before it is copied into wasm memory. `allowed` describes it for the error.
pub(crate) fn text_arg(
    v: &JsValue,
    field: &str,
    max_chars: usize,
    allowed: &str,
) -> Result<String, JsError> {
    if !v.is_string() {
        return Err(bad(field, kind(v), allowed));
    }
    let n = v.unchecked_ref::<js_sys::JsString>().length() as usize;
    if n > max_chars {
        return Err(bad(
            field,
            kind(v),
            format!("{allowed}, at most {max_chars} characters"),
        ));
    }
    Ok(v.as_string().unwrap_or_default())
}

/// A number argument: a JS number (no coercion from strings, booleans or objects); NaN and
/// ±Infinity are passed on for the caller's own range check.
pub(crate) fn number_arg(v: &JsValue, field: &str, allowed: &str) -> Result<f64, JsError> {
    v.as_f64().ok_or_else(|| bad(field, kind(v), allowed))
}

/// A finite number argument within `[lo, hi]` (used by the 3-D view only).
#[cfg_attr(not(all(feature = "render", target_arch = "wasm32")), allow(dead_code))]
pub(crate) fn finite_arg(v: &JsValue, field: &str, lo: f64, hi: f64) -> Result<f64, JsError> {
    let allowed = format!("a finite number in [{}, {}]", js_number(lo), js_number(hi));
    let x = number_arg(v, field, &allowed)?;
    if !(x.is_finite() && x >= lo && x <= hi) {
        return Err(bad(field, js_number(x), allowed));
    }
    Ok(x)
}

/// An optional number argument: `undefined`/`null` is `None`.
pub(crate) fn opt_number_arg(
    v: &JsValue,
    field: &str,
    allowed: &str,
) -> Result<Option<f64>, JsError> {
    if v.is_undefined() || v.is_null() {
        return Ok(None);
    }
    number_arg(v, field, allowed).map(Some)
}

/// An integer argument in `[lo, hi]` (a JS number; 1.5, NaN, "3" are refused).
pub(crate) fn int_arg(v: &JsValue, field: &str, lo: usize, hi: usize) -> Result<usize, JsError> {
    let x = number_arg(v, field, &format!("an integer in [{lo}, {hi}]"))?;
    super::helpers::check_int(field, x, lo, hi).map_err(err)
}

/// A boolean argument (`true`/`false` only; used by the 3-D view only).
#[cfg_attr(not(all(feature = "render", target_arch = "wasm32")), allow(dead_code))]
pub(crate) fn bool_arg(v: &JsValue, field: &str) -> Result<bool, JsError> {
    v.as_bool()
        .ok_or_else(|| bad(field, kind(v), "true or false"))
}

/// An optional callback: `undefined`/`null` is `None`; anything but a function is refused.
pub(crate) fn function_arg(v: JsValue, field: &str) -> Result<Option<js_sys::Function>, JsError> {
    if v.is_undefined() || v.is_null() {
        return Ok(None);
    }
    if !v.is_function() {
        return Err(bad(field, kind(&v), "a function or undefined"));
    }
    Ok(Some(v.unchecked_into()))
}

/// A list of numbers: a typed array of numbers (not BigInt; copied from its internal slots) or
/// an array whose every element is a JS number. Its length is checked against `[min, max]`
/// before anything is copied into wasm memory; the values are not checked.
pub(crate) fn f64_array_arg(
    v: &JsValue,
    field: &str,
    min: usize,
    max: usize,
) -> Result<Vec<f64>, JsError> {
    let allowed = || {
        if min == max {
            format!("a Float64Array or an array of exactly {min} numbers")
        } else {
            format!("a Float64Array or an array of {min} to {max} numbers")
        }
    };
    let count = |n: f64| -> Result<usize, JsError> {
        if !(n >= min as f64 && n <= max as f64) {
            return Err(bad(field, format!("{} values", js_number(n)), allowed()));
        }
        Ok(n as usize)
    };
    if js_is_view(v) {
        let f = js_f64_copy(v).map_err(|_| bad(field, kind(v), allowed()))?;
        // `f` is ours: its length is its own (the source's `length` could be shadowed).
        count(f64::from(f.length()))?;
        return Ok(f.to_vec());
    }
    if js_is_array(v).unwrap_or(false) {
        let n = count(length_of(v).unwrap_or(f64::NAN))?;
        let mut out = Vec::with_capacity(n);
        for i in 0..n {
            let e = Reflect::get_u32(v, i as u32)
                .map_err(|_| bad(&format!("{field}[{i}]"), "unreadable", "a number"))?;
            match e.as_f64() {
                Some(x) => out.push(x),
                None => return Err(bad(&format!("{field}[{i}]"), kind(&e), "a number")),
            }
        }
        return Ok(out);
    }
    Err(bad(field, kind(v), allowed()))
}

/// A list of indices: a typed array or array of integers in `[0, 2³² − 1]` (no wrapping or
/// truncation: −1 and 1.5 are refused), length checked as [`f64_array_arg`].
pub(crate) fn u32_array_arg(
    v: &JsValue,
    field: &str,
    min: usize,
    max: usize,
) -> Result<Vec<u32>, JsError> {
    let x = f64_array_arg(v, field, min, max)?;
    x.iter()
        .enumerate()
        .map(|(i, &t)| {
            if t.is_finite() && t.fract() == 0.0 && (0.0..=f64::from(u32::MAX)).contains(&t) {
                Ok(t as u32)
            } else {
                Err(bad(
                    &format!("{field}[{i}]"),
                    js_number(t),
                    "an integer index in [0, 4294967295]",
                ))
            }
        })
        .collect()
}

/// Reads a numeric series passed from JS (a typed array or an array of numbers), checking
/// its length against `cap` *before* anything is allocated (an object such as
/// `{ length: 2e9 }` is refused by name instead of aborting the instance), then that it is
/// non-empty and finite ([`super::helpers::check_series`]).
pub(crate) fn series_from_js(v: &JsValue, field: &str, cap: usize) -> Result<Vec<f64>, JsError> {
    let x = f64_array_arg(v, field, 0, cap)?;
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

/// A config from JS: the JSON fields through [`from_js`], and the optional `wing` (the mesh
/// and mode shapes that air needs, in `feModes`' layout) through [`wing_from_js`].
pub(crate) fn config_from(v: JsValue) -> Result<SimConfig, JsError> {
    let (v, wing) = split_wing(v)?;
    let mut cfg: SimConfig = from_js(v, "config")?;
    if let Some(w) = wing {
        cfg.wing = Some(std::sync::Arc::new(wing_from_js(&w, cfg.modes.len())?));
    }
    cfg.validate().map_err(err)?;
    check_web_caps(&cfg).map_err(err)?;
    Ok(cfg)
}

/// Separates a config object's `wing` (typed arrays, which the JSON path refuses) from its
/// JSON fields: the config without it (a shallow copy; the caller's object is not changed)
/// and the wing when present (not `undefined` or `null`).
fn split_wing(v: JsValue) -> Result<(JsValue, Option<JsValue>), JsError> {
    if !v.is_object() || is_array(&v) || js_is_view(&v) {
        return Ok((v, None));
    }
    let unreadable = || {
        bad(
            "config",
            "unreadable (a getter or proxy threw)",
            "plain data",
        )
    };
    let wing = Reflect::get(&v, &JsValue::from_str("wing")).map_err(|_| unreadable())?;
    if wing.is_undefined() {
        return Ok((v, None));
    }
    let keys = js_object_keys(&v).map_err(|_| unreadable())?;
    if keys.length() as usize > MAX_JS_VALUES {
        return Err(bad(
            "config",
            format!("{} keys", keys.length()),
            format!("at most {MAX_JS_VALUES} keys"),
        ));
    }
    let rest = Object::new();
    for k in keys.iter() {
        if k.as_string().as_deref() == Some("wing") {
            continue;
        }
        let e = Reflect::get(&v, &k).map_err(|_| unreadable())?;
        Reflect::set(&rest, &k, &e).map_err(|_| unreadable())?;
    }
    Ok((rest.into(), (!wing.is_null()).then_some(wing)))
}

/// Reads `config.wing`: `nodes` (x, y, z per node, m; z, the camber, is not used by the air),
/// `triangles` (node indices, three per triangle) and `shapes` (mode-major, one value per node
/// and mode of the config, kg^-½): the arrays `feModes` returns, so `cfg.wing = fe` works.
/// Lengths are checked before anything is copied; the values by [`crate::aero::WingGeometry::validate`].
pub(crate) fn wing_from_js(
    w: &JsValue,
    n_modes: usize,
) -> Result<crate::aero::WingGeometry, JsError> {
    if !w.is_object() || is_array(w) || js_is_view(w) {
        return Err(bad(
            "config.wing",
            kind(w),
            "an object { nodes, triangles, shapes } (an feModes result)",
        ));
    }
    let get = |key: &str| {
        Reflect::get(w, &JsValue::from_str(key)).map_err(|_| {
            bad(
                &format!("config.wing.{key}"),
                "unreadable (a getter or proxy threw)",
                "a typed array",
            )
        })
    };
    let max_nodes = crate::fem::mesh::MAX_NODES;
    let nodes = f64_array_arg(&get("nodes")?, "config.wing.nodes", 9, 3 * max_nodes)?;
    if nodes.len() % 3 != 0 {
        return Err(bad(
            "config.wing.nodes",
            format!("{} values", nodes.len()),
            "x, y, z per node (a multiple of 3 values), m",
        ));
    }
    let n = nodes.len() / 3;
    let tris = u32_array_arg(
        &get("triangles")?,
        "config.wing.triangles",
        3,
        6 * max_nodes,
    )?;
    if tris.len() % 3 != 0 {
        return Err(bad(
            "config.wing.triangles",
            format!("{} values", tris.len()),
            "three node indices per triangle (a multiple of 3 values)",
        ));
    }
    let want = n * n_modes;
    let shapes = f64_array_arg(&get("shapes")?, "config.wing.shapes", want, want)?;
    let geom = crate::aero::WingGeometry {
        nodes: nodes.chunks_exact(3).map(|p| [p[0], p[1]]).collect(),
        triangles: tris
            .chunks_exact(3)
            .map(|t| [t[0] as usize, t[1] as usize, t[2] as usize])
            .collect(),
        shapes: if n == 0 {
            Vec::new()
        } else {
            shapes.chunks_exact(n).map(<[f64]>::to_vec).collect()
        },
    };
    geom.validate(n_modes).map_err(err)?;
    Ok(geom)
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
    #[serde(skip_serializing_if = "Option::is_none")]
    air: Option<&'a crate::run::ModeAir>,
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
            air: m.air.as_ref(),
        })?;
        let mo: Object = meta.unchecked_into();
        let q = obj_with(&[
            ("euler", &m.q.euler),
            ("centrifugal", &m.q.centrifugal),
            ("coriolis", &m.q.coriolis),
            ("free", &m.q.free),
            ("total", &m.q.total),
        ])?;
        if !m.q.aerodynamic.is_empty() {
            set(&q, "aerodynamic", &f64a(&m.q.aerodynamic))?;
        }
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
    if let Some(a) = &r.air {
        set(&o, "air", &to_js(a)?)?;
    }
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
