//! A seeded, non-periodic angular-velocity disturbance (Mohren et al. 2018; docs/sensing.md): per
//! axis a sum of sines with frequencies drawn uniformly in a band and uniform random phases,
//! normalised to zero mean and unit standard deviation on a sampling grid, then scaled.
//!
//! The published disturbance: 15 sines, 1–10 Hz, normalised on t = 0, 1 ms, …, 3.999 s (sample
//! standard deviation, n − 1), scaled to 0.312 rad/s on the flapping axis and 0.1 rad/s on the
//! rotation axis; each axis and each class its own draw. The published code drew without a seed;
//! here the seed is an input, so a run is reproducible.
//!
//! The angle is the integral of the rate from t = 0 (zero at t = 0). The published code used
//! the indefinite integral, which differs by a constant angle; `angle_offset` gives it.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::TAU;

use crate::{Result, WingbeatError};

/// How a disturbance is drawn.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DisturbanceSpec {
    /// Number of sines (published: 15).
    pub sines: usize,
    /// Lowest frequency, Hz (published: 1).
    pub f_min_hz: f64,
    /// Highest frequency, Hz (published: 10).
    pub f_max_hz: f64,
    /// The rate's standard deviation after scaling, rad/s (published: 0.312 flapping, 0.1 rotation).
    pub amplitude_rad_per_s: f64,
    /// The normalisation grid's length, s (published: 4).
    pub normalise_over_s: f64,
    /// The normalisation grid's spacing, s (published: 0.001).
    pub normalise_step_s: f64,
    /// The seed of the draw.
    pub seed: u64,
}

impl DisturbanceSpec {
    /// The published disturbance on one axis with the given amplitude (rad/s) and seed.
    pub fn published(amplitude_rad_per_s: f64, seed: u64) -> Self {
        DisturbanceSpec {
            sines: 15,
            f_min_hz: 1.0,
            f_max_hz: 10.0,
            amplitude_rad_per_s,
            normalise_over_s: 4.0,
            normalise_step_s: 1e-3,
            seed,
        }
    }
}

/// Most sines a disturbance may hold.
pub const MAX_SINES: usize = 1000;
/// Most normalisation samples.
pub const MAX_NORMALISE_SAMPLES: f64 = 1e7;

/// A drawn disturbance: rate(t) = a · (Σ_j sin(2π f_j t + p_j) − m) / s.
#[derive(Clone, Debug, PartialEq)]
pub struct Disturbance {
    /// The frequencies f_j, Hz.
    pub freqs_hz: Vec<f64>,
    /// The phases p_j, rad.
    pub phases_rad: Vec<f64>,
    /// m: the raw sum's mean on the normalisation grid.
    pub mean: f64,
    /// s: the raw sum's sample standard deviation (n − 1) on that grid.
    pub std: f64,
    /// a: the amplitude, rad/s.
    pub amplitude: f64,
    /// Σ_j cos(p_j) / (2π f_j), s: the raw sum's integral's value at t = 0 (kept for [`Disturbance::eval`]).
    angle_at_zero: f64,
}

/// Each component's (sin, cos) of 2π f_j t + p_j, moved on by one step h at a time by the
/// rotation (sin, cos) of 2π f_j h: four multiplications instead of a sine and a cosine. Each
/// step rounds, so a caller re-anchors ([`Disturbance::anchor`]) every few dozen steps: after k
/// steps the values are within about k·2ε of the exact ones.
#[derive(Clone, Debug, Default)]
pub struct Phasors {
    sc: Vec<[f64; 2]>,
    rot: Vec<[f64; 2]>,
}

impl Phasors {
    /// Moves every component on by one step.
    pub fn advance(&mut self) {
        for (z, r) in self.sc.iter_mut().zip(&self.rot) {
            let [s, c] = *z;
            *z = [s * r[1] + c * r[0], c * r[1] - s * r[0]];
        }
    }
}

fn check(field: &str, v: f64, lo: f64, hi: f64, unit: &str) -> Result<()> {
    if v.is_finite() && v >= lo && v <= hi {
        Ok(())
    } else {
        Err(WingbeatError::invalid(
            format!("disturbance.{field}"),
            v,
            format!("{lo} to {hi}{unit}"),
        ))
    }
}

impl Disturbance {
    /// Draws a disturbance; every field of `spec` is checked and named in an error.
    pub fn new(spec: &DisturbanceSpec) -> Result<Disturbance> {
        if spec.sines == 0 || spec.sines > MAX_SINES {
            return Err(WingbeatError::invalid(
                "disturbance.sines",
                spec.sines,
                format!("1 to {MAX_SINES}"),
            ));
        }
        check("f_min_hz", spec.f_min_hz, 1e-6, 1e6, " Hz")?;
        check(
            "f_max_hz",
            spec.f_max_hz,
            spec.f_min_hz,
            1e6,
            " Hz (at least f_min_hz)",
        )?;
        check(
            "amplitude_rad_per_s",
            spec.amplitude_rad_per_s,
            0.0,
            1e3,
            " rad/s",
        )?;
        check("normalise_step_s", spec.normalise_step_s, 1e-9, 1.0, " s")?;
        check(
            "normalise_over_s",
            spec.normalise_over_s,
            spec.normalise_step_s,
            1e6,
            " s (at least one step)",
        )?;
        let n = (spec.normalise_over_s / spec.normalise_step_s).round();
        if !(2.0..=MAX_NORMALISE_SAMPLES).contains(&n) {
            return Err(WingbeatError::invalid(
                "disturbance.normalise_over_s / normalise_step_s",
                n,
                format!("2 to {MAX_NORMALISE_SAMPLES} samples"),
            ));
        }
        let mut rng = ChaCha8Rng::seed_from_u64(spec.seed);
        let (mut freqs_hz, mut phases_rad) = (
            Vec::with_capacity(spec.sines),
            Vec::with_capacity(spec.sines),
        );
        for _ in 0..spec.sines {
            freqs_hz.push(spec.f_min_hz + (spec.f_max_hz - spec.f_min_hz) * rng.random::<f64>());
            phases_rad.push(TAU * rng.random::<f64>());
        }
        let mut d = Disturbance {
            freqs_hz,
            phases_rad,
            mean: 0.0,
            std: 1.0,
            amplitude: spec.amplitude_rad_per_s,
            angle_at_zero: 0.0,
        };
        d.angle_at_zero = d
            .freqs_hz
            .iter()
            .zip(&d.phases_rad)
            .map(|(f, p)| p.cos() / (TAU * f))
            .sum();
        let n = n as usize;
        let raw: Vec<f64> = (0..n)
            .map(|i| d.raw(i as f64 * spec.normalise_step_s))
            .collect();
        let mean = raw.iter().sum::<f64>() / n as f64;
        let var = raw.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / (n - 1) as f64;
        if !(var > 0.0 && var.is_finite()) {
            return Err(WingbeatError::invalid(
                "disturbance",
                "a sum of sines without variation on the normalisation grid",
                "a grid finer than the highest frequency (normalise_step_s)",
            ));
        }
        d.mean = mean;
        d.std = var.sqrt();
        Ok(d)
    }

    fn raw(&self, t: f64) -> f64 {
        self.freqs_hz
            .iter()
            .zip(&self.phases_rad)
            .map(|(f, p)| (TAU * f * t + p).sin())
            .sum()
    }

    /// The rate at time t (s), rad/s.
    pub fn rate(&self, t: f64) -> f64 {
        self.amplitude * (self.raw(t) - self.mean) / self.std
    }

    /// The rate's time derivative at t, rad/s².
    pub fn rate_dot(&self, t: f64) -> f64 {
        let d: f64 = self
            .freqs_hz
            .iter()
            .zip(&self.phases_rad)
            .map(|(f, p)| TAU * f * (TAU * f * t + p).cos())
            .sum();
        self.amplitude * d / self.std
    }

    /// The angle ∫₀ᵗ rate, rad (zero at t = 0).
    pub fn angle(&self, t: f64) -> f64 {
        let s: f64 = self
            .freqs_hz
            .iter()
            .zip(&self.phases_rad)
            .map(|(f, p)| (p.cos() - (TAU * f * t + p).cos()) / (TAU * f))
            .sum();
        self.amplitude * (s - self.mean * t) / self.std
    }

    /// [`Disturbance::angle`], [`Disturbance::rate`] and [`Disturbance::rate_dot`] at t from one
    /// sine and cosine per component (rad, rad/s, rad/s²).
    pub fn eval(&self, t: f64) -> (f64, f64, f64) {
        self.combine(
            t,
            self.freqs_hz
                .iter()
                .zip(&self.phases_rad)
                .map(|(f, p)| (TAU * f * t + p).sin_cos()),
        )
    }

    /// [`Disturbance::eval`] from the components' sines and cosines already at hand (a
    /// [`Phasors`] kept up to date over equally spaced times): no sine or cosine computed.
    pub fn eval_phasors(&self, t: f64, ph: &Phasors) -> (f64, f64, f64) {
        self.combine(t, ph.sc.iter().map(|&[sn, cs]| (sn, cs)))
    }

    /// (angle, rate, rate_dot) at t from each component's (sin, cos) of 2π f_j t + p_j.
    fn combine(&self, t: f64, sc: impl Iterator<Item = (f64, f64)>) -> (f64, f64, f64) {
        let (mut s_angle, mut s_rate, mut s_dot) = (self.angle_at_zero, 0.0, 0.0);
        for (f, (sn, cs)) in self.freqs_hz.iter().zip(sc) {
            let w = TAU * f;
            s_angle -= cs / w;
            s_rate += sn;
            s_dot += w * cs;
        }
        let k = self.amplitude / self.std;
        (
            k * (s_angle - self.mean * t),
            k * (s_rate - self.mean),
            k * s_dot,
        )
    }

    /// The components' phasors at `t`, set to step by `h` (s) with [`Phasors::advance`].
    pub fn phasors(&self, t: f64, h: f64) -> Phasors {
        let mut ph = Phasors {
            sc: Vec::with_capacity(self.freqs_hz.len()),
            rot: self
                .freqs_hz
                .iter()
                .map(|f| {
                    let (s, c) = (TAU * f * h).sin_cos();
                    [s, c]
                })
                .collect(),
        };
        self.anchor(&mut ph, t);
        ph
    }

    /// Sets `ph` to the exact sines and cosines at `t` (its step kept).
    pub fn anchor(&self, ph: &mut Phasors, t: f64) {
        ph.sc.clear();
        ph.sc
            .extend(self.freqs_hz.iter().zip(&self.phases_rad).map(|(f, p)| {
                let (sn, cs) = (TAU * f * t + p).sin_cos();
                [sn, cs]
            }));
    }

    /// The constant by which the published indefinite integral differs from [`Disturbance::angle`]:
    /// their angle is `angle(t) + angle_offset()`, rad.
    pub fn angle_offset(&self) -> f64 {
        let s: f64 = self
            .freqs_hz
            .iter()
            .zip(&self.phases_rad)
            .map(|(f, p)| -p.cos() / (TAU * f))
            .sum();
        self.amplitude * s / self.std
    }
}
