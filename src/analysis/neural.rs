//! Neuron-like encoding of strain (Mohren et al. 2018, PNAS 115:10564; docs/sensing.md): each
//! sensor's strain is filtered by a spike-triggered-average (STA) kernel and passed through a
//! sigmoid that gives a firing probability. "Raw strain" is the same pipeline with the identity
//! filter and the identity nonlinearity.
//!
//! The STA kernel is f(t) = cos(ω_s (t + δ)) · exp(−(t + δ)² / w²), t in ms and t ≤ 0 (the strain
//! before the spike), sampled on the series' own grid over a window of `window_ms`. The firing
//! probability is P = 1 / (1 + exp(−g (ξ / s₀ − θ))), ξ the filtered strain.
//!
//! Orientation. A causal STA weights the strain τ before the output by f(−τ). The published code
//! convolved with the kernel's samples in the other order, which weights lag τ by f(τ − T_w + dt)
//! (T_w the window): the same shape, 29 ms later at the published parameters (a 34 ms latency
//! instead of 5 ms). Both are offered ([`Orientation`]); the causal one is the default and the
//! other reproduces the published numbers.

use crate::{Result, WingbeatError};

/// Which way the STA kernel is laid over the past strain (module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Orientation {
    /// The strain τ before the output is weighted by f(−τ) (the STA convention).
    Causal,
    /// The strain τ before the output is weighted by f(τ − T_w + dt), as the published code did.
    PublishedCode,
}

/// The temporal filter of a sensor.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Filter {
    /// No filtering: the strain itself ("raw strain").
    Identity,
    /// The STA kernel of the module docs.
    Sta {
        /// ω_s, rad/ms (published: 1).
        omega_rad_per_ms: f64,
        /// δ, ms (published: 5).
        delay_ms: f64,
        /// w, ms (published: 4).
        width_ms: f64,
        /// The kernel's length, ms (published: 40).
        window_ms: f64,
        /// How the kernel is laid over the past (module docs).
        orientation: Orientation,
    },
}

impl Filter {
    /// The published STA filter (ω_s = 1 rad/ms, δ = 5 ms, w = 4 ms, 40 ms window), causal.
    pub const PUBLISHED: Filter = Filter::published(Orientation::Causal);

    /// The published STA filter laid over the past as `orientation` says.
    pub const fn published(orientation: Orientation) -> Filter {
        Filter::Sta {
            omega_rad_per_ms: 1.0,
            delay_ms: 5.0,
            width_ms: 4.0,
            window_ms: 40.0,
            orientation,
        }
    }
}

/// The nonlinearity from filtered strain to output.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Nonlinearity {
    /// The filtered strain divided by s₀.
    Identity,
    /// P = 1 / (1 + exp(−g (ξ/s₀ − θ))).
    Sigmoid {
        /// g (published: 10).
        gain: f64,
        /// θ (published: 0.5).
        threshold: f64,
    },
}

/// Allowed range of the STA's ω_s, rad/ms.
pub const OMEGA_RANGE: (f64, f64) = (0.0, 100.0);
/// Allowed range of the STA's δ, ms.
pub const DELAY_RANGE_MS: (f64, f64) = (-1000.0, 1000.0);
/// Allowed range of the STA's w and window, ms.
pub const WIDTH_RANGE_MS: (f64, f64) = (1e-3, 1000.0);
/// Allowed range of the sigmoid's gain g.
pub const GAIN_RANGE: (f64, f64) = (1e-3, 1e3);
/// Allowed range of the sigmoid's threshold θ.
pub const THRESHOLD_RANGE: (f64, f64) = (-100.0, 100.0);

fn check(field: &str, v: f64, (lo, hi): (f64, f64), unit: &str) -> Result<()> {
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(())
    } else {
        Err(WingbeatError::invalid(
            field,
            v,
            format!("{lo} to {hi}{unit}"),
        ))
    }
}

/// The filter's taps on a grid of `dt_ms`: `taps[k]` weights the strain k·dt before the output.
/// Errors name the field (`filter.*`) and its range; the window must hold at least one sample.
pub fn taps(filter: &Filter, dt_ms: f64) -> Result<Vec<f64>> {
    check("sample interval (ms)", dt_ms, (1e-6, 1e3), " ms")?;
    match *filter {
        Filter::Identity => Ok(vec![1.0]),
        Filter::Sta {
            omega_rad_per_ms,
            delay_ms,
            width_ms,
            window_ms,
            orientation,
        } => {
            check(
                "filter.omega_rad_per_ms",
                omega_rad_per_ms,
                OMEGA_RANGE,
                " rad/ms",
            )?;
            check("filter.delay_ms", delay_ms, DELAY_RANGE_MS, " ms")?;
            check("filter.width_ms", width_ms, WIDTH_RANGE_MS, " ms")?;
            check("filter.window_ms", window_ms, WIDTH_RANGE_MS, " ms")?;
            let len = (window_ms / dt_ms).round();
            if len < 1.0 {
                return Err(WingbeatError::invalid(
                    "filter.window_ms",
                    window_ms,
                    format!("at least one sample interval ({dt_ms} ms)"),
                ));
            }
            let len = len as usize;
            let f = |t: f64| {
                let s = t + delay_ms;
                (omega_rad_per_ms * s).cos() * (-(s * s) / (width_ms * width_ms)).exp()
            };
            Ok((0..len)
                .map(|k| {
                    let lag = k as f64 * dt_ms;
                    match orientation {
                        Orientation::Causal => f(-lag),
                        Orientation::PublishedCode => f(lag - (len - 1) as f64 * dt_ms),
                    }
                })
                .collect())
        }
    }
}

/// The filtered series where the whole kernel lies inside the data: output j uses samples
/// j … j + L − 1 (L = taps.len()) and stands for the time of sample j + L − 1. Empty when the
/// series is shorter than the kernel.
pub fn filter_valid(x: &[f64], taps: &[f64]) -> Vec<f64> {
    let l = taps.len();
    if l == 0 || x.len() < l {
        return Vec::new();
    }
    (0..=x.len() - l)
        .map(|j| {
            let last = j + l - 1;
            taps.iter().enumerate().map(|(k, h)| h * x[last - k]).sum()
        })
        .collect()
}

/// The output of the nonlinearity for a filtered value `xi` and normalisation `s0`.
pub fn fire(xi: f64, s0: f64, nl: &Nonlinearity) -> f64 {
    match *nl {
        Nonlinearity::Identity => xi / s0,
        Nonlinearity::Sigmoid { gain, threshold } => {
            1.0 / (1.0 + (-gain * (xi / s0 - threshold)).exp())
        }
    }
}

/// Checks a nonlinearity's parameters (errors name `nonlinearity.*` and the range).
pub fn check_nonlinearity(nl: &Nonlinearity) -> Result<()> {
    if let Nonlinearity::Sigmoid { gain, threshold } = *nl {
        check("nonlinearity.gain", gain, GAIN_RANGE, "")?;
        check("nonlinearity.threshold", threshold, THRESHOLD_RANGE, "")?;
    }
    Ok(())
}

/// The published normalisation: the largest filtered value over every sensor, sample and class
/// (not its absolute value). Errors when it is not a positive finite number.
pub fn max_filtered<'a>(filtered: impl IntoIterator<Item = &'a [f64]>) -> Result<f64> {
    let m = filtered
        .into_iter()
        .flatten()
        .fold(f64::NEG_INFINITY, |a, &b| a.max(b));
    if m.is_finite() && m > 0.0 {
        Ok(m)
    } else {
        Err(WingbeatError::invalid(
            "s0 (the largest filtered strain)",
            m,
            "a positive finite number: the strain is zero or negative everywhere; give s0 explicitly",
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn causal_taps_peak_at_the_delay_and_published_ones_are_mirrored() {
        let t = taps(&Filter::PUBLISHED, 1.0).unwrap();
        assert_eq!(t.len(), 40);
        let peak = (0..40).max_by(|&a, &b| t[a].total_cmp(&t[b])).unwrap();
        assert_eq!(peak, 5, "f(−τ) peaks at τ = δ = 5 ms");
        let Filter::Sta {
            omega_rad_per_ms,
            delay_ms,
            width_ms,
            window_ms,
            ..
        } = Filter::PUBLISHED
        else {
            unreachable!()
        };
        let p = taps(
            &Filter::Sta {
                omega_rad_per_ms,
                delay_ms,
                width_ms,
                window_ms,
                orientation: Orientation::PublishedCode,
            },
            1.0,
        )
        .unwrap();
        for k in 0..40 {
            assert_eq!(p[k], t[39 - k]);
        }
        let ppeak = (0..40).max_by(|&a, &b| p[a].total_cmp(&p[b])).unwrap();
        assert_eq!(ppeak, 34, "the published code's latency: 34 ms");
    }

    #[test]
    fn filter_valid_is_the_direct_convolution() {
        let x: Vec<f64> = (0..50)
            .map(|i| ((i * 7919) % 101) as f64 / 101.0 - 0.5)
            .collect();
        let h = [0.5, -1.0, 2.0];
        let y = filter_valid(&x, &h);
        assert_eq!(y.len(), 48);
        for (j, yj) in y.iter().enumerate() {
            let direct = 0.5 * x[j + 2] - x[j + 1] + 2.0 * x[j];
            assert!((yj - direct).abs() < 1e-15);
        }
        assert!(filter_valid(&x[..2], &h).is_empty());
    }

    #[test]
    fn bad_parameters_are_named() {
        let e = taps(
            &Filter::Sta {
                omega_rad_per_ms: f64::NAN,
                delay_ms: 5.0,
                width_ms: 4.0,
                window_ms: 40.0,
                orientation: Orientation::Causal,
            },
            1.0,
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("filter.omega_rad_per_ms"), "{e}");
        let e = check_nonlinearity(&Nonlinearity::Sigmoid {
            gain: 0.0,
            threshold: 0.5,
        })
        .unwrap_err()
        .to_string();
        assert!(e.contains("nonlinearity.gain"), "{e}");
        assert!(max_filtered([&[0.0, -1.0][..]]).is_err());
    }
}
