//! The one error type of the wingbeat core.
//!
//! Every fallible function in the library returns [`Result<T>`]. Front ends turn it into
//! what they need: the CLI prints it and exits non-zero, the wasm API wraps it in a `JsError`.
//! Messages always name the offending field and, where one exists, the allowed range.

use thiserror::Error;

/// Everything that can go wrong in wingbeat's core.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum WingbeatError {
    /// An input value is outside its allowed range (or not finite).
    #[error("invalid value for `{field}`: {value} (allowed: {allowed})")]
    InvalidInput {
        /// Dotted path of the offending field, e.g. `modes[1].freq_hz`.
        field: String,
        /// The value as given, formatted for a human.
        value: String,
        /// The allowed range or set, in words, with units.
        allowed: String,
    },
    /// The request would exceed a documented resource cap.
    #[error("`{field}` asks for {requested}, over the cap of {cap} ({why})")]
    ResourceCap {
        /// The field (or derived quantity) that is too large.
        field: String,
        /// What was asked for.
        requested: String,
        /// The documented cap.
        cap: String,
        /// Why the cap exists.
        why: String,
    },
    /// An input file or document could not be parsed.
    #[error("could not parse {what}: {message}")]
    Parse {
        /// What was being parsed (a file name, "config JSON", ...).
        what: String,
        /// The parser's explanation.
        message: String,
    },
    /// A geometric input (planform outline, mesh) is unusable.
    #[error("invalid geometry: {0}")]
    Geometry(String),
    /// An iterative numerical method stopped without meeting its tolerance.
    #[error("{method} did not converge: {detail}")]
    NoConvergence {
        /// The method, e.g. "shift-invert Lanczos".
        method: String,
        /// Iterations used, residual reached, and so on.
        detail: String,
    },
    /// Rendering failed (no GPU adapter, lost device, ...); see `render::RenderError`.
    #[error("rendering failed: {0}")]
    Render(String),
    /// A numerical result came out non-finite (overflow, parametric blow-up).
    #[error("non-finite result in {what}: {detail}")]
    NonFinite {
        /// Which computation.
        what: String,
        /// Context for the user.
        detail: String,
    },
}

/// Result alias used throughout the core.
pub type Result<T> = std::result::Result<T, WingbeatError>;

impl WingbeatError {
    /// An input error with its field renamed by `f` (to say where it happened: a sweep point,
    /// a disturbance's axis, an option's path); other errors unchanged.
    pub fn map_field(self, f: impl FnOnce(String) -> String) -> Self {
        match self {
            WingbeatError::InvalidInput {
                field,
                value,
                allowed,
            } => WingbeatError::InvalidInput {
                field: f(field),
                value,
                allowed,
            },
            other => other,
        }
    }

    /// Shorthand for [`WingbeatError::InvalidInput`].
    pub fn invalid(
        field: impl Into<String>,
        value: impl std::fmt::Display,
        allowed: impl Into<String>,
    ) -> Self {
        WingbeatError::InvalidInput {
            field: field.into(),
            value: compact_number(&value.to_string()),
            allowed: allowed.into(),
        }
    }
}

/// A number for a message: as given when short, else in exponent form (`1e308`, not a
/// 309-digit decimal; `5e-324`, not 324 zeros). Text that is not a number is returned as is.
pub fn compact_number(text: &str) -> String {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && text.len() > 17 => format!("{v:e}"),
        _ => text.to_string(),
    }
}

/// [`compact_number`] of an `f64`; magnitudes from 1e9 up and below 1e-5 always in exponent
/// form (`1e13`, `1e-9`), which reads better than 14 digits or 9 zeros.
pub fn num(v: f64) -> String {
    if v.is_finite() && v != 0.0 && (v.abs() >= 1e9 || v.abs() < 1e-5) {
        return format!("{v:e}");
    }
    compact_number(&v.to_string())
}

/// Parses JSON text into `T`; a failure names the path of the offending field
/// (``at `modes[0]`: unknown field `damping`…``) as well as the line and column, so the CLI's
/// messages say where, as the wasm API's do. `what` names the document.
///
/// Objects only where objects are meant: serde's derived structs also accept a JSON array and
/// read it by position (`[25, …]` for a config), so after a successful parse the document's
/// shape is compared with the parsed value's ([`check_objects`]) and an array where the value
/// has an object is refused, naming the path.
pub fn parse_json<T: serde::de::DeserializeOwned + serde::Serialize + Default>(
    text: &str,
    what: &str,
) -> Result<T> {
    match parse_json_at::<T>(text) {
        Ok(v) => Ok(v),
        Err(e) => Err(WingbeatError::Parse {
            what: what.into(),
            message: e.to_string(),
        }),
    }
}

/// A JSON document's error with the path of the offending field (`.` or empty at the top).
#[derive(Debug, Clone, PartialEq)]
pub struct JsonPathError {
    /// Dotted path, e.g. `kinematics.alpha.max_harmonic`; empty for the document itself.
    pub path: String,
    /// What is wrong there.
    pub message: String,
}

impl std::fmt::Display for JsonPathError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.path.is_empty() || self.path == "." {
            write!(f, "{}", self.message)
        } else {
            write!(f, "at `{}`: {}", self.path, self.message)
        }
    }
}

/// [`parse_json`] with the error as a path and a message (the wasm API formats them its own
/// way): a typed parse that names the full path (also inside an angle), then
/// [`check_objects`]. When the typed parse fails where the document has an array in the
/// place of an object (of `T::default()`'s shape: a config read by position fails at its
/// first field), that is the error reported.
pub fn parse_json_at<T: serde::de::DeserializeOwned + serde::Serialize + Default>(
    text: &str,
) -> std::result::Result<T, JsonPathError> {
    let shape = || -> std::result::Result<Shape, JsonPathError> {
        serde_json::from_str(text).map_err(|e| JsonPathError {
            path: String::new(),
            message: e.to_string(),
        })
    };
    let mut de = serde_json::Deserializer::from_str(text);
    let v: T = match serde_path_to_error::deserialize(&mut de) {
        Ok(v) => v,
        Err(e) => {
            let err = split_path(&e);
            if let (Ok(shape), Ok(template)) = (shape(), serde_json::to_value(T::default())) {
                check_shape(&shape, &template, String::new())?;
            }
            return Err(err);
        }
    };
    de.end().map_err(|e| JsonPathError {
        path: String::new(),
        message: e.to_string(),
    })?;
    let shape = shape()?;
    let parsed = serde_json::to_value(&v).map_err(|e| JsonPathError {
        path: String::new(),
        message: e.to_string(),
    })?;
    check_shape(&shape, &parsed, String::new())?;
    Ok(v)
}

/// [`parse_json`] for an already parsed `serde_json::Value`; `what` names the part (its
/// path is appended to it).
pub fn from_json_value<T: serde::de::DeserializeOwned + serde::Serialize>(
    v: serde_json::Value,
    what: &str,
) -> Result<T> {
    from_json_value_at(v, what, "")
}

/// [`from_json_value`] for the part of a document at `prefix` (`modes`): the paths in errors
/// start with it (``at `modes[0].freq_hz` ``).
pub fn from_json_value_at<T: serde::de::DeserializeOwned + serde::Serialize>(
    v: serde_json::Value,
    what: &str,
    prefix: &str,
) -> Result<T> {
    let shape = Shape::of(&v);
    let join = |mut e: JsonPathError| {
        if !prefix.is_empty() {
            e.path = if e.path.is_empty() || e.path == "." {
                prefix.to_string()
            } else if e.path.starts_with('[') {
                format!("{prefix}{}", e.path)
            } else {
                format!("{prefix}.{}", e.path)
            };
        }
        WingbeatError::Parse {
            what: what.into(),
            message: e.to_string(),
        }
    };
    let t: T = serde_path_to_error::deserialize(v).map_err(|e| join(split_path(&e)))?;
    let parsed = serde_json::to_value(&t).map_err(|e| WingbeatError::Parse {
        what: what.into(),
        message: e.to_string(),
    })?;
    check_shape(&shape, &parsed, String::new()).map_err(join)?;
    Ok(t)
}

/// Refuses an array in `original` (the document as given) where `parsed` (the value read from
/// it) has an object: serde's derived structs read an array by position, so
/// `{"modes": [["m", 62.5, [1, 2], 0, []]]}` would otherwise be a mode. `what` names the
/// document in the error, which names the path.
pub fn check_objects<T: serde::Serialize>(
    original: &serde_json::Value,
    parsed: &T,
    what: &str,
) -> Result<()> {
    check_objects_shape(&Shape::of(original), parsed, what)
}

fn check_objects_shape<T: serde::Serialize>(shape: &Shape, parsed: &T, what: &str) -> Result<()> {
    let parsed = serde_json::to_value(parsed).map_err(|e| WingbeatError::Parse {
        what: what.into(),
        message: e.to_string(),
    })?;
    check_shape(shape, &parsed, String::new()).map_err(|e| WingbeatError::Parse {
        what: what.into(),
        message: e.to_string(),
    })
}

/// A `deserialize_with` for struct fields that serialization may skip
/// (`skip_serializing_if`), where the shape check of [`parse_json`] cannot see them: refuses
/// anything but an object, reads the struct from it with its own path (the message starts with
/// ``at `inner.path`: ``, which [`parse_json`] joins to the field's path) and refuses arrays
/// inside it the same way.
pub fn object_only<'de, D, T>(d: D) -> std::result::Result<T, D::Error>
where
    D: serde::Deserializer<'de>,
    T: serde::de::DeserializeOwned + serde::Serialize,
{
    use serde::de::Error;
    let v = <serde_json::Value as serde::Deserialize>::deserialize(d)?;
    if !v.is_object() {
        return Err(D::Error::custom(format!(
            "expected an object with named keys, found {}",
            match v {
                serde_json::Value::Array(_) => "an array (arrays are not read by position)",
                serde_json::Value::Null => "null",
                serde_json::Value::Bool(_) => "a boolean",
                serde_json::Value::Number(_) => "a number",
                serde_json::Value::String(_) => "a string",
                serde_json::Value::Object(_) => "an object",
            }
        )));
    }
    let shape = Shape::of(&v);
    let t: T = serde_path_to_error::deserialize(v)
        .map_err(|e| D::Error::custom(split_path(&e).to_string()))?;
    let parsed = serde_json::to_value(&t).map_err(D::Error::custom)?;
    check_shape(&shape, &parsed, String::new()).map_err(|e| D::Error::custom(e.to_string()))?;
    Ok(t)
}

/// The error of serde_path_to_error as a path and a message. A message that itself starts
/// with ``at `inner`: `` (the error of a part read separately, e.g. the fields of an angle,
/// which serde buffers so that the outer path stops at the angle) continues the path.
fn split_path(e: &serde_path_to_error::Error<serde_json::Error>) -> JsonPathError {
    let mut path = e.path().to_string();
    if path == "." {
        path.clear();
    }
    let mut message = e.inner().to_string();
    while let Some(rest) = message.strip_prefix("at `") {
        let Some((inner, tail)) = rest.split_once("`: ") else {
            break;
        };
        path = if path.is_empty() {
            inner.to_string()
        } else if inner.starts_with('[') {
            format!("{path}{inner}")
        } else {
            format!("{path}.{inner}")
        };
        message = tail.to_string();
    }
    if message.contains(", expected struct ") && message.contains(" element") {
        // serde's words for an array read by position with the wrong length
        message = format!(
            "{message}; an object with named keys is expected here (arrays are not read by position)"
        );
    }
    JsonPathError { path, message }
}

/// The structure of a JSON document without its values: which places hold arrays and which
/// objects (array elements that are plain values take no memory, so a long table stays cheap).
#[derive(Debug)]
enum Shape {
    Leaf,
    /// The elements that are themselves arrays or objects, with their index.
    Array(Vec<(usize, Shape)>),
    Object(Vec<(String, Shape)>),
}

impl Shape {
    fn of(v: &serde_json::Value) -> Shape {
        match v {
            serde_json::Value::Array(a) => Shape::Array(
                a.iter()
                    .enumerate()
                    .map(|(i, e)| (i, Shape::of(e)))
                    .filter(|(_, s)| !matches!(s, Shape::Leaf))
                    .collect(),
            ),
            serde_json::Value::Object(o) => {
                Shape::Object(o.iter().map(|(k, e)| (k.clone(), Shape::of(e))).collect())
            }
            _ => Shape::Leaf,
        }
    }
}

impl<'de> serde::Deserialize<'de> for Shape {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        struct V;
        impl<'de> serde::de::Visitor<'de> for V {
            type Value = Shape;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("any JSON value")
            }
            fn visit_bool<E>(self, _: bool) -> std::result::Result<Shape, E> {
                Ok(Shape::Leaf)
            }
            fn visit_i64<E>(self, _: i64) -> std::result::Result<Shape, E> {
                Ok(Shape::Leaf)
            }
            fn visit_u64<E>(self, _: u64) -> std::result::Result<Shape, E> {
                Ok(Shape::Leaf)
            }
            fn visit_f64<E>(self, _: f64) -> std::result::Result<Shape, E> {
                Ok(Shape::Leaf)
            }
            fn visit_str<E>(self, _: &str) -> std::result::Result<Shape, E> {
                Ok(Shape::Leaf)
            }
            fn visit_unit<E>(self) -> std::result::Result<Shape, E> {
                Ok(Shape::Leaf)
            }
            fn visit_none<E>(self) -> std::result::Result<Shape, E> {
                Ok(Shape::Leaf)
            }
            fn visit_some<D: serde::Deserializer<'de>>(
                self,
                d: D,
            ) -> std::result::Result<Shape, D::Error> {
                <Shape as serde::Deserialize<'de>>::deserialize(d)
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> std::result::Result<Shape, A::Error> {
                let mut items = Vec::new();
                let mut i = 0;
                while let Some(s) = seq.next_element::<Shape>()? {
                    if !matches!(s, Shape::Leaf) {
                        items.push((i, s));
                    }
                    i += 1;
                }
                Ok(Shape::Array(items))
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(
                self,
                mut map: A,
            ) -> std::result::Result<Shape, A::Error> {
                let mut items = Vec::new();
                while let Some((k, s)) = map.next_entry::<String, Shape>()? {
                    items.push((k, s));
                }
                Ok(Shape::Object(items))
            }
        }
        d.deserialize_any(V)
    }
}

fn check_shape(
    shape: &Shape,
    parsed: &serde_json::Value,
    path: String,
) -> std::result::Result<(), JsonPathError> {
    match (shape, parsed) {
        (Shape::Array(_), serde_json::Value::Object(_)) => Err(JsonPathError {
            message: format!(
                "expected an object with named keys, found an array{} (arrays are not read by \
                 position)",
                if path.is_empty() {
                    " as the whole document"
                } else {
                    ""
                }
            ),
            path,
        }),
        (Shape::Object(items), serde_json::Value::Object(m)) => {
            for (k, s) in items {
                if let Some(v) = m.get(k) {
                    let p = if path.is_empty() {
                        k.clone()
                    } else {
                        format!("{path}.{k}")
                    };
                    check_shape(s, v, p)?;
                }
            }
            Ok(())
        }
        (Shape::Array(items), serde_json::Value::Array(vs)) => {
            for (i, s) in items {
                if let Some(v) = vs.get(*i) {
                    check_shape(s, v, format!("{path}[{i}]"))?;
                }
            }
            Ok(())
        }
        _ => Ok(()),
    }
}

/// Checks that `v` is finite and within `[lo, hi]`; the error names `field` and the range with `unit`.
pub fn check_range(field: &str, v: f64, lo: f64, hi: f64, unit: &str) -> Result<()> {
    check(
        field,
        v,
        v.is_finite() && v >= lo && v <= hi,
        &format!("[{}, {}]", num(lo), num(hi)),
        unit,
    )
}

/// Checks that `v` is finite and strictly positive and at most `hi`.
pub fn check_positive(field: &str, v: f64, hi: f64, unit: &str) -> Result<()> {
    check(
        field,
        v,
        v.is_finite() && v > 0.0 && v <= hi,
        &format!("(0, {}]", num(hi)),
        unit,
    )
}

fn check(field: &str, v: f64, ok: bool, interval: &str, unit: &str) -> Result<()> {
    if ok {
        return Ok(());
    }
    let u = if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    };
    Err(WingbeatError::invalid(
        field,
        v,
        format!("a finite number in {interval}{u}"),
    ))
}
