//! Wing kinematics: roll α(t), pitch β(t), yaw γ(t) and the frame's angular velocity
//! (paper §2.1, §3.2, Eq. 1).
//!
//! Each angle is periodic at the flap frequency f_d (ω_d = 2π f_d): a mean plus harmonics
//! `A_n sin(n ω_d t + φ_n)`. Sampled periodic tables (measured kinematics) are turned into the
//! same form by trigonometric interpolation (a discrete Fourier transform of the samples), which
//! is the smooth periodic interpolant through them, so derivatives stay analytic.
//!
//! Rotation order: roll α about I, then pitch β about the rolled J′ (both finite); yaw γ is small
//! and enters Eq. 13 only to first order. The rotating frame I″–J″–K″ turns with angular velocity
//! (Eq. 1, in frame components) Ω = (α̇ cos β, β̇, α̇ sin β).

use crate::error::{check_range, Result, WingbeatError};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// One harmonic `amplitude · sin(n ω_d t + phase)`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Harmonic {
    /// Harmonic number n ≥ 1 (multiple of the flap frequency).
    pub n: u32,
    /// Amplitude, rad.
    pub amplitude: f64,
    /// Phase, rad.
    #[serde(default)]
    pub phase: f64,
}

/// How one angle is specified. Read from `{"kind": "fourier" | "sampled", …}` by a
/// hand-written `Deserialize` (see there) so that an error inside an angle names the full
/// path (`kinematics.alpha.max_harmonic`), not only the angle.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum Angle {
    /// Mean plus harmonics (the paper's case is one sine: mean 0, n = 1, phase 0).
    Fourier {
        /// Mean value, rad.
        #[serde(default)]
        mean: f64,
        /// Harmonics of the flap frequency.
        #[serde(default)]
        harmonics: Vec<Harmonic>,
    },
    /// Equally spaced samples over exactly one period, t_j = j T / N, j = 0..N−1 (rad).
    /// Interpolated by the trigonometric polynomial through the samples, truncated at
    /// `max_harmonic` (a low-pass for noisy measurements; default
    /// [`DEFAULT_SAMPLED_MAX_HARMONIC`], so a long table does not cost N/2 harmonics).
    Sampled {
        /// The samples, rad.
        values: Vec<f64>,
        /// Keep harmonics up to this number (default: all that N samples resolve, at most
        /// [`DEFAULT_SAMPLED_MAX_HARMONIC`]).
        #[serde(default)]
        max_harmonic: Option<u32>,
    },
}

/// The fields of [`Angle::Fourier`] as read (the `kind` key removed).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FourierFields {
    #[serde(default)]
    mean: f64,
    #[serde(default)]
    harmonics: Vec<Harmonic>,
}

/// The fields of [`Angle::Sampled`] as read (the `kind` key removed).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SampledFields {
    values: Vec<f64>,
    #[serde(default)]
    max_harmonic: Option<u32>,
}

/// An angle is an internally tagged object. serde's derive for that buffers the object and
/// loses the path inside it (a type error in `max_harmonic` said ``at `kinematics.alpha`:
/// … expected u32``); here the fields are read with their own path, and the error message
/// starts with ``at `max_harmonic`: ``, which [`crate::error::parse_json`] joins to the outer
/// path. An array is refused (serde would read the fields by position).
impl<'de> Deserialize<'de> for Angle {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        use serde::de::Error;
        let v = serde_json::Value::deserialize(d)?;
        let serde_json::Value::Object(mut obj) = v else {
            return Err(D::Error::custom(format!(
                "expected an angle object {{\"kind\": \"fourier\" | \"sampled\", …}}, found {}",
                json_kind(&v)
            )));
        };
        let kind = match obj.remove("kind") {
            None => return Err(D::Error::missing_field("kind")),
            Some(serde_json::Value::String(k)) => k,
            Some(other) => {
                return Err(D::Error::custom(format!(
                    "at `kind`: expected \"fourier\" or \"sampled\", found {}",
                    json_kind(&other)
                )))
            }
        };
        let fields = serde_json::Value::Object(obj);
        let inner = |e: serde_path_to_error::Error<serde_json::Error>| {
            let path = e.path().to_string();
            if path == "." || path.is_empty() {
                D::Error::custom(e.into_inner())
            } else {
                D::Error::custom(format!("at `{path}`: {}", e.into_inner()))
            }
        };
        match kind.as_str() {
            "fourier" => {
                let f: FourierFields = serde_path_to_error::deserialize(fields).map_err(inner)?;
                Ok(Angle::Fourier {
                    mean: f.mean,
                    harmonics: f.harmonics,
                })
            }
            "sampled" => {
                let f: SampledFields = serde_path_to_error::deserialize(fields).map_err(inner)?;
                Ok(Angle::Sampled {
                    values: f.values,
                    max_harmonic: f.max_harmonic,
                })
            }
            other => Err(D::Error::custom(format!(
                "at `kind`: unknown variant `{other}`, expected `fourier` or `sampled`"
            ))),
        }
    }
}

/// "an array", "a string", … for messages.
fn json_kind(v: &serde_json::Value) -> &'static str {
    match v {
        serde_json::Value::Null => "null",
        serde_json::Value::Bool(_) => "a boolean",
        serde_json::Value::Number(_) => "a number",
        serde_json::Value::String(_) => "a string",
        serde_json::Value::Array(_) => "an array (arrays are not read by position)",
        serde_json::Value::Object(_) => "an object",
    }
}

/// Largest harmonic number accepted.
pub const MAX_HARMONIC: u32 = 256;
/// Most samples accepted for one sampled angle.
pub const MAX_SAMPLES_PER_PERIOD: usize = 100_000;
/// Largest flap frequency accepted, Hz.
pub const MAX_FLAP_HZ: f64 = 10_000.0;
/// Lowest flap frequency accepted, Hz: one period (at most 1000 s) is integrated whole for
/// the Floquet analysis, so a slower flap means unbounded work (and 1e-320 Hz an infinite
/// period). Insects flap at 5 Hz and more; the run's work budget
/// ([`crate::simulate::MAX_RUN_WORK`]) may refuse a slow flap well above this floor when the
/// modes are stiff.
pub const MIN_FLAP_HZ: f64 = 1.0e-3;
/// Harmonics a sampled angle keeps when its `max_harmonic` is not given (the table's N/2 if
/// fewer). Every harmonic costs work at every solver step and shortens the step, so the run's
/// cost grows with its square; measured wing kinematics carry next to nothing above the
/// tenth harmonic. Ask for more (up to [`MAX_HARMONIC`]) with `max_harmonic`. This default
/// of 24 harmonics keeps a typical measured table (200 samples per period, the paper's two
/// modes at 25 Hz) at about 4e5 work units, inside the browser's budget (`WEB_MAX_RUN_WORK`,
/// 1e6); the same table with 64 harmonics costs 3.0e6 and is refused in the lab. The DFT of
/// [`Angle::series`], the CSV reader and the cap's warning all take it from here.
pub const DEFAULT_SAMPLED_MAX_HARMONIC: u32 = 24;

impl Angle {
    /// `amplitude · sin(ω_d t)`: the paper's profile.
    pub fn sine(amplitude: f64) -> Self {
        Angle::Fourier {
            mean: 0.0,
            harmonics: vec![Harmonic {
                n: 1,
                amplitude,
                phase: 0.0,
            }],
        }
    }

    /// The warning for a sampled table low-passed by the default cap: without `max_harmonic`
    /// a table of N samples keeps min(N/2, [`DEFAULT_SAMPLED_MAX_HARMONIC`]) harmonics, so a
    /// table of more than twice that many samples does not pass through its samples. Says by how much
    /// (the largest deviation at the sample times) and how to keep them all. `None` when the
    /// cap changes nothing.
    pub fn default_cap_warning(&self, field: &str, unit: &str) -> Option<String> {
        let Angle::Sampled {
            values,
            max_harmonic: None,
        } = self
        else {
            return None;
        };
        let n = values.len();
        let all = n / 2;
        if all <= DEFAULT_SAMPLED_MAX_HARMONIC as usize {
            return None;
        }
        let s = self.series();
        let mut dev: f64 = 0.0;
        for (j, v) in values.iter().enumerate() {
            let th = 2.0 * PI * j as f64 / n as f64;
            let y = s.mean
                + s.terms
                    .iter()
                    .map(|t| {
                        let (sn, cs) = (t.n * th).sin_cos();
                        t.s * sn + t.c * cs
                    })
                    .sum::<f64>();
            dev = dev.max((y - v).abs());
        }
        Some(format!(
            "{field}: the {n}-sample table resolves {all} harmonics, but without `max_harmonic` only \
             the first {DEFAULT_SAMPLED_MAX_HARMONIC} are kept (kinematics::DEFAULT_SAMPLED_MAX_HARMONIC, \
             which bounds the run's cost), so the angle does not pass through every sample \
             (largest deviation {} {unit}); set `{field}.max_harmonic` to {all} to keep them all",
            crate::error::num(dev)
        ))
    }

    /// A constant angle.
    pub fn constant(value: f64) -> Self {
        Angle::Fourier {
            mean: value,
            harmonics: vec![],
        }
    }

    /// Validates the specification; `field` names it in errors.
    pub fn validate(&self, field: &str) -> Result<()> {
        self.validate_with(field, &|what, f, v| match what {
            "phase" => check_range(f, v, -1.0e3, 1.0e3, "rad"),
            // mean, amplitude and sampled values
            _ => check_range(f, v, -2.0 * PI, 2.0 * PI, "rad"),
        })
    }

    /// The structural checks every angle-like series shares (harmonic numbers and counts,
    /// sample counts, `max_harmonic`), with the numeric ranges left to `check(what, field,
    /// value)`, `what` being `"mean"`, `"amplitude"`, `"phase"` or `"value"`: the angles use
    /// ±2π rad, the body rate [`crate::params::BODY_RATE_RANGES`].
    pub(crate) fn validate_with(
        &self,
        field: &str,
        check: &dyn Fn(&str, &str, f64) -> Result<()>,
    ) -> Result<()> {
        match self {
            Angle::Fourier { mean, harmonics } => {
                check("mean", &format!("{field}.mean"), *mean)?;
                if harmonics.len() > MAX_HARMONIC as usize {
                    return Err(WingbeatError::invalid(
                        format!("{field}.harmonics"),
                        format!("{} entries", harmonics.len()),
                        format!("at most {MAX_HARMONIC} harmonics"),
                    ));
                }
                for (i, h) in harmonics.iter().enumerate() {
                    let f = format!("{field}.harmonics[{i}]");
                    if h.n == 0 || h.n > MAX_HARMONIC {
                        return Err(WingbeatError::invalid(
                            format!("{f}.n"),
                            h.n,
                            format!("an integer in [1, {MAX_HARMONIC}]"),
                        ));
                    }
                    check("amplitude", &format!("{f}.amplitude"), h.amplitude)?;
                    check("phase", &format!("{f}.phase"), h.phase)?;
                }
            }
            Angle::Sampled {
                values,
                max_harmonic,
            } => {
                if values.len() < 3 || values.len() > MAX_SAMPLES_PER_PERIOD {
                    return Err(WingbeatError::invalid(
                        format!("{field}.values"),
                        format!("{} samples", values.len()),
                        format!("3 to {MAX_SAMPLES_PER_PERIOD} samples over one period"),
                    ));
                }
                for (i, v) in values.iter().enumerate() {
                    check("value", &format!("{field}.values[{i}]"), *v)?;
                }
                if let Some(m) = max_harmonic {
                    if *m > MAX_HARMONIC {
                        return Err(WingbeatError::invalid(
                            format!("{field}.max_harmonic"),
                            m,
                            format!("an integer in [0, {MAX_HARMONIC}]"),
                        ));
                    }
                }
            }
        }
        Ok(())
    }

    /// The angle as a resolved Fourier series.
    pub fn series(&self) -> Series {
        match self {
            Angle::Fourier { mean, harmonics } => {
                let mut s = Series {
                    mean: *mean,
                    terms: Vec::new(),
                };
                for h in harmonics {
                    // A sin(nθ + φ) = A cos φ sin nθ + A sin φ cos nθ
                    s.terms.push(SeriesTerm {
                        n: h.n as f64,
                        s: h.amplitude * h.phase.cos(),
                        c: h.amplitude * h.phase.sin(),
                    });
                }
                s
            }
            Angle::Sampled {
                values,
                max_harmonic,
            } => {
                // Direct O(N·H) DFT, H = min(N/2, max_harmonic or DEFAULT_SAMPLED_MAX_HARMONIC):
                // tables are short and this runs once per model.
                let n = values.len();
                let nf = n as f64;
                let mean = values.iter().sum::<f64>() / nf;
                let hmax =
                    (n / 2).min(max_harmonic.unwrap_or(DEFAULT_SAMPLED_MAX_HARMONIC) as usize);
                let mut terms = Vec::with_capacity(hmax);
                for h in 1..=hmax {
                    let (mut cs, mut sn) = (0.0, 0.0);
                    for (j, v) in values.iter().enumerate() {
                        let th = 2.0 * PI * (h * j % n) as f64 / nf;
                        cs += v * th.cos();
                        sn += v * th.sin();
                    }
                    // Even N: the Nyquist term is shared by ±N/2, so it carries half weight.
                    let w = if n % 2 == 0 && h == n / 2 {
                        1.0 / nf
                    } else {
                        2.0 / nf
                    };
                    terms.push(SeriesTerm {
                        n: h as f64,
                        s: w * sn,
                        c: w * cs,
                    });
                }
                Series { mean, terms }
            }
        }
    }
}

/// One term `s · sin(n θ) + c · cos(n θ)`, θ = ω_d t.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeriesTerm {
    /// Harmonic number.
    pub n: f64,
    /// Sine coefficient, rad.
    pub s: f64,
    /// Cosine coefficient, rad.
    pub c: f64,
}

/// A resolved Fourier series in θ = ω_d t.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Mean, rad.
    pub mean: f64,
    /// Harmonic terms.
    pub terms: Vec<SeriesTerm>,
}

impl Series {
    /// Value, first and second time derivative at time `t` for angular flap frequency `wd` (rad/s).
    pub fn eval(&self, t: f64, wd: f64) -> (f64, f64, f64) {
        self.eval_cached(t, wd, &mut [f64::NAN; 3])
    }

    /// [`Series::eval`] with a one-entry cache `[ω_n t, sin, cos]` of the last sine and cosine
    /// computed: series that share a harmonic (the paper's three sines all have n = 1) then
    /// evaluate it once. The same arithmetic, so the same bits.
    pub fn eval_cached(&self, t: f64, wd: f64, cache: &mut [f64; 3]) -> (f64, f64, f64) {
        let (mut v, mut d, mut dd) = (self.mean, 0.0, 0.0);
        for term in &self.terms {
            let w = term.n * wd;
            let arg = w * t;
            let (sn, cs) = if arg.to_bits() == cache[0].to_bits() {
                (cache[1], cache[2])
            } else {
                let sc = arg.sin_cos();
                *cache = [arg, sc.0, sc.1];
                sc
            };
            v += term.s * sn + term.c * cs;
            d += w * (term.s * cs - term.c * sn);
            dd -= w * w * (term.s * sn + term.c * cs);
        }
        (v, d, dd)
    }

    /// True if the series is odd about its mean under a half-period shift
    /// (only odd harmonics and zero mean), so that its square has period T/2.
    pub fn half_wave_antisymmetric(&self) -> bool {
        self.mean == 0.0
            && self
                .terms
                .iter()
                .all(|t| (t.n as u64) % 2 == 1 || (t.s == 0.0 && t.c == 0.0))
    }
}

/// Rotation kinematics of the wing.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Kinematics {
    /// Flap frequency f_d, Hz (ω_d = 2π f_d). The paper's forward flight: 25 Hz.
    pub flap_freq_hz: f64,
    /// Roll α about I (finite), rad.
    pub alpha: Angle,
    /// Pitch β about J′ (finite), rad.
    pub beta: Angle,
    /// Yaw γ (small; first order only), rad. Above 0.3 rad the small-angle model is stretched.
    pub gamma: Angle,
    /// Body angular velocity ω_b(t) in body axes (the fixed I, J, K frame of §2.1), rad/s.
    /// Omitted (and not written) when zero, which is the paper's case.
    #[serde(
        default,
        skip_serializing_if = "BodyRate::is_zero",
        deserialize_with = "crate::error::object_only"
    )]
    pub body_rate: BodyRate,
}

/// The body's angular velocity ω_b(t) in body axes (I, J, K: the frame the roll and pitch are
/// measured from), rad/s. Each component is periodic at the flap frequency and given like an
/// angle: `Angle::Fourier { mean, harmonics }` (a constant rate is the mean alone) or a
/// sampled table over one period; only the unit differs (rad/s instead of rad). The wing
/// frame then turns with Ω = Rᵀ ω_b + Ω_wing, R = R_x(α)·R_y(β) ([`RateState::omega`]).
/// Ranges: [`crate::params::BODY_RATE_RANGES`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct BodyRate {
    /// ω_b about I (rad/s).
    pub x: Angle,
    /// ω_b about J (rad/s).
    pub y: Angle,
    /// ω_b about K (rad/s).
    pub z: Angle,
}

impl Default for BodyRate {
    fn default() -> Self {
        BodyRate {
            x: Angle::constant(0.0),
            y: Angle::constant(0.0),
            z: Angle::constant(0.0),
        }
    }
}

fn angle_is_zero(a: &Angle) -> bool {
    match a {
        Angle::Fourier { mean, harmonics } => {
            *mean == 0.0 && harmonics.iter().all(|h| h.amplitude == 0.0)
        }
        Angle::Sampled { values, .. } => values.iter().all(|v| *v == 0.0),
    }
}

impl BodyRate {
    /// A constant body rate [ω_x, ω_y, ω_z], rad/s, in body axes.
    pub fn constant(w: [f64; 3]) -> Self {
        BodyRate {
            x: Angle::constant(w[0]),
            y: Angle::constant(w[1]),
            z: Angle::constant(w[2]),
        }
    }

    /// True when every component is identically zero (the default: no body rotation).
    pub fn is_zero(&self) -> bool {
        angle_is_zero(&self.x) && angle_is_zero(&self.y) && angle_is_zero(&self.z)
    }

    /// The three components as Fourier series (rad/s).
    pub fn series(&self) -> [Series; 3] {
        [self.x.series(), self.y.series(), self.z.series()]
    }

    /// Validates every component against [`crate::params::BODY_RATE_RANGES`]; errors name
    /// the field (`kinematics.body_rate.x.mean`, …).
    pub fn validate(&self) -> Result<()> {
        use crate::ranges::body_rate_range as r;
        for (name, a) in [("x", &self.x), ("y", &self.y), ("z", &self.z)] {
            let field = format!("kinematics.body_rate.{name}");
            a.validate_with(&field, &|what, f, v| r(what).check(f, v))?;
            if let Angle::Fourier { mean, harmonics } = a {
                let peak = mean.abs() + harmonics.iter().map(|h| h.amplitude.abs()).sum::<f64>();
                r("peak").check(&format!("{field} (|mean| + Σ|amplitude|)"), peak)?;
            }
        }
        Ok(())
    }
}

/// Yaw amplitudes above this (rad) are outside the paper's small-angle range: allowed, with a warning.
pub const SMALL_ANGLE_LIMIT: f64 = 0.3;

/// Angles and their first two derivatives at one instant (rad, rad/s, rad/s²).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RateState {
    /// α, α̇, α̈.
    pub alpha: f64,
    /// α̇.
    pub alpha_dot: f64,
    /// α̈.
    pub alpha_ddot: f64,
    /// β.
    pub beta: f64,
    /// β̇.
    pub beta_dot: f64,
    /// β̈.
    pub beta_ddot: f64,
    /// γ.
    pub gamma: f64,
    /// γ̇.
    pub gamma_dot: f64,
    /// γ̈.
    pub gamma_ddot: f64,
    /// Body angular velocity ω_b in body axes, rad/s (zero without body rotation).
    pub body_rate: [f64; 3],
    /// Its time derivative ω̇_b, rad/s².
    pub body_rate_dot: [f64; 3],
}

impl RateState {
    /// Angular velocity of the I″–J″–K″ frame in its own components, rad/s:
    /// Ω = Rᵀ ω_b + Ω_wing with Ω_wing = (α̇ cos β, β̇, α̇ sin β) (Eq. 1) and R = R_x(α)·R_y(β)
    /// the wing frame's orientation in body axes. Without body rotation (ω_b = 0) this is
    /// Eq. 1 exactly, computed with the same arithmetic as before the body rate existed.
    pub fn omega(&self) -> [f64; 3] {
        let (sb, cb) = self.beta.sin_cos();
        let w = [self.alpha_dot * cb, self.beta_dot, self.alpha_dot * sb];
        if self.body_rate == [0.0; 3] {
            return w;
        }
        let v = self.to_wing_frame(self.body_rate);
        [w[0] + v[0], w[1] + v[1], w[2] + v[2]]
    }

    /// Its exact time derivative, rad/s²:
    /// Ω̇ = Ω̇_wing + Rᵀ ω̇_b + Ṙᵀ ω_b, with Ṙᵀ ω_b = −Ω_wing × (Rᵀ ω_b) (since RᵀṘ = \[Ω_wing\]×)
    /// and Ω̇_wing = (α̈ cos β − α̇ β̇ sin β, β̈, α̈ sin β + α̇ β̇ cos β).
    pub fn omega_dot(&self) -> [f64; 3] {
        let (sb, cb) = self.beta.sin_cos();
        let wd = [
            self.alpha_ddot * cb - self.alpha_dot * self.beta_dot * sb,
            self.beta_ddot,
            self.alpha_ddot * sb + self.alpha_dot * self.beta_dot * cb,
        ];
        if self.body_rate == [0.0; 3] && self.body_rate_dot == [0.0; 3] {
            return wd;
        }
        let w = [self.alpha_dot * cb, self.beta_dot, self.alpha_dot * sb];
        let v = self.to_wing_frame(self.body_rate);
        let u = self.to_wing_frame(self.body_rate_dot);
        // −Ω_wing × v
        let c = [
            w[1] * v[2] - w[2] * v[1],
            w[2] * v[0] - w[0] * v[2],
            w[0] * v[1] - w[1] * v[0],
        ];
        [
            wd[0] + u[0] - c[0],
            wd[1] + u[1] - c[1],
            wd[2] + u[2] - c[2],
        ]
    }

    /// [`RateState::omega`] and [`RateState::omega_dot`] together (one sine and cosine of β
    /// shared; the same arithmetic, so the same bits).
    pub fn omega_and_dot(&self) -> ([f64; 3], [f64; 3]) {
        if self.body_rate != [0.0; 3] || self.body_rate_dot != [0.0; 3] {
            return (self.omega(), self.omega_dot());
        }
        let (sb, cb) = self.beta.sin_cos();
        let w = [self.alpha_dot * cb, self.beta_dot, self.alpha_dot * sb];
        let wd = [
            self.alpha_ddot * cb - self.alpha_dot * self.beta_dot * sb,
            self.beta_ddot,
            self.alpha_ddot * sb + self.alpha_dot * self.beta_dot * cb,
        ];
        (w, wd)
    }

    /// Rᵀ v: a body-axes vector in wing-frame (I″, J″, K″) components, R = R_x(α)·R_y(β).
    pub fn to_wing_frame(&self, v: [f64; 3]) -> [f64; 3] {
        let (sa, ca) = self.alpha.sin_cos();
        let (sb, cb) = self.beta.sin_cos();
        // R_x(α)ᵀ v, then R_y(β)ᵀ.
        let u = [v[0], ca * v[1] + sa * v[2], -sa * v[1] + ca * v[2]];
        [cb * u[0] - sb * u[2], u[1], sb * u[0] + cb * u[2]]
    }
}

impl Kinematics {
    /// The paper's example: α = α0 sin ω_d t, β = β0 sin ω_d t, γ = γ0 sin ω_d t.
    pub fn sinusoidal(flap_freq_hz: f64, alpha0: f64, beta0: f64, gamma0: f64) -> Self {
        Kinematics {
            flap_freq_hz,
            alpha: Angle::sine(alpha0),
            beta: Angle::sine(beta0),
            gamma: Angle::sine(gamma0),
            body_rate: BodyRate::default(),
        }
    }

    /// Forward flight of Manduca sexta (paper Table 5): α0 = 0.8, β0 = 0.5, γ0 = 0.2 rad at 25 Hz.
    pub fn paper_forward_flight() -> Self {
        Self::sinusoidal(25.0, 0.8, 0.5, 0.2)
    }

    /// Flap period T = 1 / f_d, s.
    pub fn period(&self) -> f64 {
        1.0 / self.flap_freq_hz
    }

    /// ω_d = 2π f_d, rad/s.
    pub fn omega_d(&self) -> f64 {
        2.0 * PI * self.flap_freq_hz
    }

    /// Validates frequency and every angle.
    pub fn validate(&self) -> Result<()> {
        check_range(
            "kinematics.flap_freq_hz",
            self.flap_freq_hz,
            MIN_FLAP_HZ,
            MAX_FLAP_HZ,
            "Hz",
        )?;
        self.alpha.validate("kinematics.alpha")?;
        self.beta.validate("kinematics.beta")?;
        self.gamma.validate("kinematics.gamma")?;
        self.body_rate.validate()?;
        Ok(())
    }

    /// Human-readable warnings (not errors), e.g. yaw beyond the small-angle range.
    pub fn warnings(&self) -> Vec<String> {
        let mut w = Vec::new();
        let g = self.gamma.series();
        let peak = g.mean.abs() + g.terms.iter().map(|t| t.s.hypot(t.c)).sum::<f64>();
        if peak > SMALL_ANGLE_LIMIT {
            w.push(format!(
                "yaw γ reaches up to {peak:.3} rad, beyond the small-angle range (≤ {SMALL_ANGLE_LIMIT} rad) assumed by Eq. 13; results are extrapolations"
            ));
        }
        let angles = [
            ("kinematics.alpha", &self.alpha, "rad"),
            ("kinematics.beta", &self.beta, "rad"),
            ("kinematics.gamma", &self.gamma, "rad"),
            ("kinematics.body_rate.x", &self.body_rate.x, "rad/s"),
            ("kinematics.body_rate.y", &self.body_rate.y, "rad/s"),
            ("kinematics.body_rate.z", &self.body_rate.z, "rad/s"),
        ];
        for (field, a, unit) in angles {
            if let Some(msg) = a.default_cap_warning(field, unit) {
                w.push(msg);
            }
        }
        w
    }

    /// The paper's kinematics plus a constant body rate (body axes, rad/s).
    pub fn with_body_rate(mut self, w: [f64; 3]) -> Self {
        self.body_rate = BodyRate::constant(w);
        self
    }

    /// Resolve into evaluable series (do this once, then call [`Compiled::state`] many times).
    pub fn compile(&self) -> Compiled {
        Compiled {
            wd: self.omega_d(),
            alpha: self.alpha.series(),
            beta: self.beta.series(),
            gamma: self.gamma.series(),
            body_rate: if self.body_rate.is_zero() {
                None
            } else {
                Some(self.body_rate.series())
            },
        }
    }

    /// Angles and rates at time `t` (s). Convenience; compiles on every call.
    pub fn rate_state(&self, t: f64) -> RateState {
        self.compile().state(t)
    }
}

/// Kinematics resolved into Fourier series, ready for fast evaluation.
#[derive(Debug, Clone, PartialEq)]
pub struct Compiled {
    /// ω_d, rad/s.
    pub wd: f64,
    /// Roll series.
    pub alpha: Series,
    /// Pitch series.
    pub beta: Series,
    /// Yaw series.
    pub gamma: Series,
    /// Body-rate series (x, y, z in body axes, rad/s); `None` without body rotation.
    pub body_rate: Option<[Series; 3]>,
}

/// The four stage times t0 + c_i h of one Gauss–Legendre step share their harmonics' sines:
/// sin and cos of n ω_d t0 once per step, turned to each stage by the angle-addition formulas
/// with sin and cos of n ω_d c_i h, which depend only on the step length and are kept here
/// between steps ([`Compiled::stage_states`]).
#[derive(Debug, Clone, Default)]
pub struct StageTurns {
    /// The step length and nodes (bits) the turns are for (none yet when empty).
    key: Option<(f64, [u64; 4])>,
    /// The distinct harmonic numbers of α, β and γ, in order of first appearance.
    harmonics: Vec<f64>,
    /// Per distinct harmonic: (sin, cos) of n ω_d c_i h for each stage.
    turns: Vec<[(f64, f64); 4]>,
    /// Per distinct harmonic: (sin, cos) of n ω_d (t0 + c_i h) for the current step.
    stage: Vec<[(f64, f64); 4]>,
    /// Per series (α, β, γ) and term: its harmonic's index in `harmonics`.
    index: [Vec<usize>; 3],
}

impl Compiled {
    /// Angles and rates at the stage times t0 + c_i h of one Gauss–Legendre step: the same as
    /// [`Compiled::state`] at each time to within a few units in the last place (each harmonic's
    /// sine is turned from t0 to the stage instead of taken at the stage), with one sine and
    /// cosine per harmonic and step instead of four. `turns` keeps the turns between steps of
    /// one length (a fresh [`StageTurns`] works). With a body rate, [`Compiled::state`] at
    /// each time.
    pub fn stage_states(
        &self,
        t0: f64,
        h: f64,
        c: &[f64; 4],
        turns: &mut StageTurns,
    ) -> [RateState; 4] {
        if self.body_rate.is_some() {
            return std::array::from_fn(|i| self.state(t0 + c[i] * h));
        }
        let series = [&self.alpha, &self.beta, &self.gamma];
        // Steps between checkpoints differ in length by a few units in the last place (each
        // interval's length over its step count, ≈ 1e-13 relative): turns kept for a length
        // h_ref within 1e-9 of h are corrected by the small angle δ = n ω_d c_i (h − h_ref)
        // below (to first order; δ²/2 < 1e-20 is far below a unit in the last place).
        let near =
            |k: &(f64, [u64; 4])| k.1 == c.map(f64::to_bits) && (k.0 - h).abs() <= 1e-9 * h.abs();
        if !turns.key.as_ref().is_some_and(near) {
            turns.harmonics.clear();
            for (k, s) in series.iter().enumerate() {
                turns.index[k] = s
                    .terms
                    .iter()
                    .map(
                        |term| match turns.harmonics.iter().position(|&n| n == term.n) {
                            Some(i) => i,
                            None => {
                                turns.harmonics.push(term.n);
                                turns.harmonics.len() - 1
                            }
                        },
                    )
                    .collect();
            }
            turns.turns = turns
                .harmonics
                .iter()
                .map(|&n| std::array::from_fn(|i| (n * self.wd * (c[i] * h)).sin_cos()))
                .collect();
            turns.key = Some((h, c.map(f64::to_bits)));
        }
        let dh = h - turns.key.map_or(h, |k| k.0);
        turns.stage.clear();
        for (&n, tn) in turns.harmonics.iter().zip(&turns.turns) {
            let (s0, c0) = (n * self.wd * t0).sin_cos();
            let mut st = [(0.0, 0.0); 4];
            for i in 0..4 {
                let (sn, cn) = tn[i];
                let (s1, c1) = (s0 * cn + c0 * sn, c0 * cn - s0 * sn);
                let d = n * self.wd * (c[i] * dh);
                st[i] = (s1 + d * c1, c1 - d * s1);
            }
            turns.stage.push(st);
        }
        // Value, rate and acceleration of series k at the four stages.
        let eval = |k: usize| {
            let s = series[k];
            let (mut v, mut d, mut dd) = ([s.mean; 4], [0.0; 4], [0.0; 4]);
            for (term, &j) in s.terms.iter().zip(&turns.index[k]) {
                let w = term.n * self.wd;
                let st = &turns.stage[j];
                for i in 0..4 {
                    let (sn, cs) = st[i];
                    v[i] += term.s * sn + term.c * cs;
                    d[i] += w * (term.s * cs - term.c * sn);
                    dd[i] -= w * w * (term.s * sn + term.c * cs);
                }
            }
            (v, d, dd)
        };
        let (a, b, g) = (eval(0), eval(1), eval(2));
        std::array::from_fn(|i| RateState {
            alpha: a.0[i],
            alpha_dot: a.1[i],
            alpha_ddot: a.2[i],
            beta: b.0[i],
            beta_dot: b.1[i],
            beta_ddot: b.2[i],
            gamma: g.0[i],
            gamma_dot: g.1[i],
            gamma_ddot: g.2[i],
            body_rate: [0.0; 3],
            body_rate_dot: [0.0; 3],
        })
    }

    /// Angles and rates at time `t` (s).
    pub fn state(&self, t: f64) -> RateState {
        let mut cache = [f64::NAN; 3];
        let (alpha, alpha_dot, alpha_ddot) = self.alpha.eval_cached(t, self.wd, &mut cache);
        let (beta, beta_dot, beta_ddot) = self.beta.eval_cached(t, self.wd, &mut cache);
        let (gamma, gamma_dot, gamma_ddot) = self.gamma.eval_cached(t, self.wd, &mut cache);
        let (mut body_rate, mut body_rate_dot) = ([0.0; 3], [0.0; 3]);
        if let Some(b) = &self.body_rate {
            for i in 0..3 {
                let (v, d, _) = b[i].eval(t, self.wd);
                body_rate[i] = v;
                body_rate_dot[i] = d;
            }
        }
        RateState {
            alpha,
            alpha_dot,
            alpha_ddot,
            beta,
            beta_dot,
            beta_ddot,
            gamma,
            gamma_dot,
            gamma_ddot,
            body_rate,
            body_rate_dot,
        }
    }

    /// Whether the stiffness coefficient α̇² cos²β + β̇² (the centrifugal softening) has period T/2 (true when α and β
    /// contain only odd harmonics and β has zero mean — the paper's symmetric sinusoids).
    /// Then Floquet analysis can use the half period.
    /// A body rate breaks that symmetry (R_x(−α)R_y(−β) ≠ R_x(α)R_y(β)), so then it is false.
    pub fn stiffness_coefficient_has_half_period(&self) -> bool {
        if self.body_rate.is_some() {
            return false;
        }
        // α̇ only needs odd harmonics (its mean does not enter α̇); β must flip sign.
        let alpha_odd = self
            .alpha
            .terms
            .iter()
            .all(|t| (t.n as u64) % 2 == 1 || (t.s == 0.0 && t.c == 0.0));
        alpha_odd && self.beta.half_wave_antisymmetric()
    }
}
