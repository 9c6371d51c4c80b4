//! Power spectral density by Welch's method (paper §3.3, Fig. 4's spectra).
//!
//! The series is cut into segments of `segment_len` samples overlapping by `overlap`, each is
//! optionally detrended, multiplied by a periodic Hann window and transformed; the one-sided
//! density is (|X|² / (f_s Σ w²)), doubled for bins other than DC and Nyquist, averaged over
//! segments. Units: (unit of x)² / Hz. The default keeps the mean (no detrending) because the
//! Coriolis force of the paper's case has a large DC part that detrending would hide.
//! Integrating the density over frequency returns the mean square of the (detrended) series.

use crate::error::{Result, WingbeatError};
use realfft::RealFftPlanner;
use serde::{Deserialize, Serialize};

/// What to remove from each segment before windowing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum Detrend {
    /// Keep everything (DC visible).
    #[default]
    None,
    /// Subtract the segment mean.
    Mean,
    /// Subtract the least-squares line.
    Linear,
}

/// Welch options.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct WelchOptions {
    /// Samples per segment (clipped to the series length). Resolution = f_s / segment_len.
    pub segment_len: usize,
    /// Overlap fraction between segments, [0, 0.95].
    pub overlap: f64,
    /// Detrending per segment.
    pub detrend: Detrend,
    /// How many peaks to list.
    pub max_peaks: usize,
}

impl Default for WelchOptions {
    fn default() -> Self {
        WelchOptions {
            segment_len: 8192,
            overlap: 0.5,
            detrend: Detrend::None,
            max_peaks: 8,
        }
    }
}

/// Lowest sample rate accepted, Hz (below it the bin frequencies and the density lose their
/// meaning in f64; a run's own rate is at least 1 / 3600 s).
pub const MIN_SAMPLE_RATE_HZ: f64 = 1e-6;

/// Largest segment accepted.
pub const MAX_SEGMENT: usize = 1 << 22;

/// Most spectrum bins one `wingbeat psd` run writes (six spectra per mode, each
/// min(segment, samples)/2 + 1 bins, every bin a frequency and a density): 6e6 bins keep the
/// JSON text near 250 MB, so that the run, its series and the text stay under the documented
/// 1.5 GB (docs/limits.md, "Memory"). One mode may still use a segment of 2 000 000 samples
/// (the whole run at the sample cap, 6 000 006 bins); four modes up to about 508 000.
pub const MAX_RUN_SPECTRUM_BINS: f64 = 6.1e6;

impl WelchOptions {
    /// Validates the options.
    pub fn validate(&self) -> Result<()> {
        self.validate_named("psd.segment_len", "psd.overlap", "psd.max_peaks")
    }

    /// [`WelchOptions::validate`] with the names the caller uses for the segment length, the
    /// overlap and the peak count (the CLI's flags).
    pub fn validate_named(&self, segment: &str, overlap: &str, peaks: &str) -> Result<()> {
        if self.segment_len < 8 || self.segment_len > MAX_SEGMENT {
            return Err(WingbeatError::invalid(
                segment,
                self.segment_len,
                format!("an integer in [8, {MAX_SEGMENT}] samples"),
            ));
        }
        crate::error::check_range(overlap, self.overlap, 0.0, 0.95, "(fraction)")?;
        if self.max_peaks > 1000 {
            return Err(WingbeatError::invalid(
                peaks,
                self.max_peaks,
                "an integer in [0, 1000]",
            ));
        }
        Ok(())
    }
}

/// A spectral peak.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Peak {
    /// Frequency of the peak bin, Hz.
    pub freq_hz: f64,
    /// Density at the peak, (unit)²/Hz.
    pub psd: f64,
    /// Frequency as a multiple of the flap frequency (when given; else NaN → null).
    pub flap_multiple: Option<f64>,
}

/// A one-sided PSD.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Spectrum {
    /// Bin frequencies, Hz.
    pub freq_hz: Vec<f64>,
    /// Density, (unit)²/Hz.
    pub psd: Vec<f64>,
    /// The largest local maxima, strongest first.
    pub peaks: Vec<Peak>,
}

fn detrend(seg: &mut [f64], how: Detrend) {
    let n = seg.len() as f64;
    match how {
        Detrend::None => {}
        Detrend::Mean => {
            let m = seg.iter().sum::<f64>() / n;
            seg.iter_mut().for_each(|v| *v -= m);
        }
        Detrend::Linear => {
            let xm = (n - 1.0) / 2.0;
            let ym = seg.iter().sum::<f64>() / n;
            let (mut sxy, mut sxx) = (0.0, 0.0);
            for (i, v) in seg.iter().enumerate() {
                let dx = i as f64 - xm;
                sxy += dx * (v - ym);
                sxx += dx * dx;
            }
            let slope = if sxx > 0.0 { sxy / sxx } else { 0.0 };
            for (i, v) in seg.iter_mut().enumerate() {
                *v -= ym + slope * (i as f64 - xm);
            }
        }
    }
}

/// Welch PSD of `x` sampled at `fs` Hz. `flap_hz`, if given, labels peaks as multiples of it.
pub fn welch(x: &[f64], fs: f64, opts: &WelchOptions, flap_hz: Option<f64>) -> Result<Spectrum> {
    opts.validate()?;
    crate::error::check_range("psd.sample_rate_hz", fs, MIN_SAMPLE_RATE_HZ, 1e9, "Hz")?;
    if x.len() < 8 {
        return Err(WingbeatError::invalid(
            "psd.series",
            format!("{} samples", x.len()),
            "at least 8 samples",
        ));
    }
    if let Some(i) = x.iter().position(|v| !v.is_finite()) {
        return Err(WingbeatError::invalid(
            format!("psd.series[{i}]"),
            x[i],
            "finite values",
        ));
    }
    // Extreme magnitudes are scaled out exactly (a power of two) and back in at the end, so the
    // squares cannot overflow on the way; a density that itself exceeds f64 is refused below.
    let sx = crate::analysis::beat::safe_scale(x);
    let nseg = opts.segment_len.min(x.len());
    let step = ((nseg as f64 * (1.0 - opts.overlap)).round() as usize).max(1);
    let win: Vec<f64> = (0..nseg)
        .map(|j| 0.5 - 0.5 * (2.0 * std::f64::consts::PI * j as f64 / nseg as f64).cos())
        .collect();
    let wss: f64 = win.iter().map(|w| w * w).sum();
    let mut planner = RealFftPlanner::<f64>::new();
    let fft = planner.plan_fft_forward(nseg);
    let mut buf = fft.make_input_vec();
    let mut spec = fft.make_output_vec();
    let nb = nseg / 2 + 1;
    let mut acc = vec![0.0; nb];
    let mut count = 0usize;
    let mut start = 0;
    while start + nseg <= x.len() {
        buf.copy_from_slice(&x[start..start + nseg]);
        if sx != 1.0 {
            for b in &mut buf {
                *b *= sx;
            }
        }
        detrend(&mut buf, opts.detrend);
        for (b, w) in buf.iter_mut().zip(&win) {
            *b *= w;
        }
        fft.process(&mut buf, &mut spec)
            .map_err(|e| WingbeatError::NonFinite {
                what: "FFT".into(),
                detail: e.to_string(),
            })?;
        for (a, c) in acc.iter_mut().zip(&spec) {
            *a += c.norm_sqr();
        }
        count += 1;
        start += step;
    }
    let scale = 1.0 / (fs * wss * count as f64);
    let psd: Vec<f64> = acc
        .iter()
        .enumerate()
        .map(|(k, a)| {
            let one_sided = if k == 0 || (nseg % 2 == 0 && k == nb - 1) {
                1.0
            } else {
                2.0
            };
            let p = a * scale * one_sided;
            if sx == 1.0 {
                p
            } else {
                p / sx / sx
            }
        })
        .collect();
    if psd.iter().any(|p| !p.is_finite()) {
        return Err(WingbeatError::NonFinite {
            what: "psd".into(),
            detail: format!(
                "the density of `psd.series` (|x| up to about {}, sample rate {} Hz) exceeds the largest f64; scale the series down",
                crate::error::num(if sx == 1.0 { 1e100 } else { 0.5 / sx }),
                crate::error::num(fs)
            ),
        });
    }
    let freq_hz: Vec<f64> = (0..nb).map(|k| k as f64 * fs / nseg as f64).collect();
    let peaks = find_peaks(&freq_hz, &psd, opts.max_peaks, flap_hz);
    Ok(Spectrum {
        freq_hz,
        psd,
        peaks,
    })
}

/// Local maxima (DC counts when it exceeds its neighbour) at least 1e-8 of the global maximum,
/// strongest first, at most `max` of them.
pub fn find_peaks(freq: &[f64], psd: &[f64], max: usize, flap_hz: Option<f64>) -> Vec<Peak> {
    let top = psd.iter().cloned().fold(0.0, f64::max);
    let n = psd.len();
    let mut idx: Vec<usize> = (0..n)
        .filter(|&i| {
            let left = if i == 0 {
                f64::NEG_INFINITY
            } else {
                psd[i - 1]
            };
            let right = if i + 1 == n {
                f64::NEG_INFINITY
            } else {
                psd[i + 1]
            };
            psd[i] > left && psd[i] >= right && psd[i] >= 1e-8 * top && psd[i] > 0.0
        })
        .collect();
    idx.sort_by(|&a, &b| psd[b].total_cmp(&psd[a]));
    idx.truncate(max);
    idx.into_iter()
        .map(|i| Peak {
            freq_hz: freq[i],
            psd: psd[i],
            flap_multiple: flap_hz.filter(|f| *f > 0.0).map(|f| freq[i] / f),
        })
        .collect()
}

/// Density integrated over [f_lo, f_hi] (trapezoid-free bin sum × Δf): the mean square carried
/// by that band.
pub fn band_power(s: &Spectrum, f_lo: f64, f_hi: f64) -> f64 {
    let df = if s.freq_hz.len() > 1 {
        s.freq_hz[1] - s.freq_hz[0]
    } else {
        0.0
    };
    s.freq_hz
        .iter()
        .zip(&s.psd)
        .filter(|(f, _)| **f >= f_lo && **f <= f_hi)
        .map(|(_, p)| p * df)
        .sum()
}
