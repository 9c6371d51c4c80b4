//! Measuring a beat in a computed response, independently of the Floquet prediction.
//!
//! The envelope is the modulus of the analytic signal (Hilbert transform by FFT). A beat
//! between two tones A cos ω₁t + B cos ω₂t has envelope √(A² + B² + 2AB cos (ω₁−ω₂)t), so the
//! strongest slow component of the envelope is the beat frequency. Ripple inside one flap
//! (harmonics of the forcing) is removed by a moving average over one flap period before the
//! modulation depth is taken.

use realfft::num_complex::Complex;
use rustfft::FftPlanner;
use serde::{Deserialize, Serialize};

/// Envelope `|x + i H(x)|` of a real series (H the Hilbert transform).
pub fn envelope(x: &[f64]) -> Vec<f64> {
    let n = x.len();
    if n == 0 {
        return vec![];
    }
    let mut planner = FftPlanner::<f64>::new();
    let mut buf: Vec<Complex<f64>> = x.iter().map(|&v| Complex::new(v, 0.0)).collect();
    planner.plan_fft_forward(n).process(&mut buf);
    // Analytic signal: keep DC (and Nyquist) once, double positive frequencies, zero negative.
    for (k, c) in buf.iter_mut().enumerate() {
        let pos = k > 0 && 2 * k < n;
        let neg = 2 * k > n;
        if pos {
            *c *= 2.0;
        } else if neg {
            *c = Complex::new(0.0, 0.0);
        }
    }
    planner.plan_fft_inverse(n).process(&mut buf);
    buf.iter().map(|c| c.norm() / n as f64).collect()
}

/// A power of two `s` with `max |x| · s` in [0.5, 1) when `max |x|` is outside
/// [1e-100, 1e100], else 1: scaling by it is exact, so the linear transforms below give the
/// same digits on ordinary inputs and no overflow (or underflow) on extreme ones.
pub fn safe_scale(x: &[f64]) -> f64 {
    let m = x.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    if m == 0.0 || !m.is_finite() || (1e-100..=1e100).contains(&m) {
        return 1.0;
    }
    let e = m.log2().floor() as i32 + 1;
    2f64.powi(-e)
}

/// [`envelope`] with extreme magnitudes scaled out first (exactly, by a power of two) and the
/// result checked: finite, or an error naming `field`.
pub fn checked_envelope(x: &[f64], field: &str) -> crate::Result<Vec<f64>> {
    let s = safe_scale(x);
    let e = if s == 1.0 {
        envelope(x)
    } else {
        let scaled: Vec<f64> = x.iter().map(|v| v * s).collect();
        envelope(&scaled).into_iter().map(|v| v / s).collect()
    };
    if e.iter().any(|v| !v.is_finite()) {
        return Err(crate::WingbeatError::NonFinite {
            what: "envelope".into(),
            detail: format!(
                "the envelope of `{field}` (|x| up to {}) exceeds the largest f64; scale the series down",
                crate::error::num(x.iter().fold(0.0_f64, |m, v| m.max(v.abs())))
            ),
        });
    }
    Ok(e)
}

/// Moving average over `w` samples (centred; shrinks at the ends).
pub fn moving_average(x: &[f64], w: usize) -> Vec<f64> {
    let n = x.len();
    let w = w.max(1);
    let mut pre = vec![0.0; n + 1];
    for i in 0..n {
        pre[i + 1] = pre[i] + x[i];
    }
    (0..n)
        .map(|i| {
            let lo = i.saturating_sub(w / 2);
            let hi = (i + w - w / 2).min(n);
            (pre[hi] - pre[lo]) / (hi - lo) as f64
        })
        .collect()
}

/// A measured beat.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct BeatMeasure {
    /// (max − min) / (max + min) of the flap-averaged envelope over the analysed window
    /// (0: steady amplitude, 1: amplitude touching zero).
    pub modulation_index: f64,
    /// Strongest envelope frequency below the flap frequency, Hz (None if the envelope is flat).
    pub beat_freq_hz: Option<f64>,
}

/// Measures the beat in `x` (sampled at `fs` Hz) between fractions `from`..`to` of its length;
/// `flap_hz` sets the averaging window and the upper search limit.
pub fn measure(x: &[f64], fs: f64, flap_hz: f64, from: f64, to: f64) -> BeatMeasure {
    let n = x.len();
    let env = envelope(x);
    let per = ((fs / flap_hz).round() as usize).max(1);
    let avg = moving_average(&env, per);
    let (a, b) = (
        ((from * n as f64) as usize).min(n),
        ((to * n as f64) as usize).min(n),
    );
    // Keep clear of the ends, where the Hilbert transform and the average are distorted.
    let a = a.max(per);
    let b = b.min(n.saturating_sub(per));
    if b <= a + 2 {
        return BeatMeasure {
            modulation_index: 0.0,
            beat_freq_hz: None,
        };
    }
    let w = &avg[a..b];
    let (mx, mn) = w
        .iter()
        .fold((f64::MIN, f64::MAX), |(mx, mn), &v| (mx.max(v), mn.min(v)));
    let modulation_index = if mx + mn > 0.0 {
        (mx - mn) / (mx + mn)
    } else {
        0.0
    };
    // Envelope spectrum (mean removed, Hann, zero-padded ×8), peak below the flap frequency.
    let seg = &env[a..b];
    let m = seg.len();
    let mean = seg.iter().sum::<f64>() / m as f64;
    let nfft = (8 * m).next_power_of_two();
    let mut buf = vec![Complex::new(0.0, 0.0); nfft];
    for (j, v) in seg.iter().enumerate() {
        let wj = 0.5 - 0.5 * (2.0 * std::f64::consts::PI * j as f64 / m as f64).cos();
        buf[j] = Complex::new((v - mean) * wj, 0.0);
    }
    FftPlanner::<f64>::new()
        .plan_fft_forward(nfft)
        .process(&mut buf);
    let df = fs / nfft as f64;
    let kmin = ((0.5 * fs / m as f64) / df).ceil() as usize; // skip below half a window's resolution
    let kmax = ((flap_hz / df) as usize).min(nfft / 2);
    let mut best = (0usize, 0.0f64);
    for (k, c) in buf.iter().enumerate().take(kmax).skip(kmin.max(1)) {
        let p = c.norm_sqr();
        if p > best.1 {
            best = (k, p);
        }
    }
    let beat_freq_hz = if best.0 > 0 && modulation_index > 1e-6 {
        // Parabolic refinement on the log spectrum.
        let k = best.0;
        let (l, c, r) = (
            buf[k - 1].norm_sqr().ln(),
            best.1.ln(),
            buf[(k + 1).min(nfft - 1)].norm_sqr().ln(),
        );
        let den = l - 2.0 * c + r;
        let d = if den.abs() > 0.0 {
            0.5 * (l - r) / den
        } else {
            0.0
        };
        Some((k as f64 + d.clamp(-0.5, 0.5)) * df)
    } else {
        None
    };
    BeatMeasure {
        modulation_index,
        beat_freq_hz,
    }
}
