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
pub fn parse_json<T: serde::de::DeserializeOwned>(text: &str, what: &str) -> Result<T> {
    let mut de = serde_json::Deserializer::from_str(text);
    let v = serde_path_to_error::deserialize(&mut de).map_err(|e| path_error(&e, what))?;
    de.end().map_err(|e| WingbeatError::Parse {
        what: what.into(),
        message: e.to_string(),
    })?;
    Ok(v)
}

/// [`parse_json`] for an already parsed `serde_json::Value`; `what` names the part (its
/// path is appended to it).
pub fn from_json_value<T: serde::de::DeserializeOwned>(
    v: serde_json::Value,
    what: &str,
) -> Result<T> {
    serde_path_to_error::deserialize(v).map_err(|e| path_error(&e, what))
}

fn path_error(e: &serde_path_to_error::Error<serde_json::Error>, what: &str) -> WingbeatError {
    let path = e.path().to_string();
    let message = if path == "." || path.is_empty() {
        e.inner().to_string()
    } else {
        format!("at `{path}`: {}", e.inner())
    };
    WingbeatError::Parse {
        what: what.into(),
        message,
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
