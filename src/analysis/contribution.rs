//! Force-term contributions (paper §4.1): the share of term j is
//! 100 · Σ_i q_j(t_i)² / Σ_i q_total(t_i)², in percent. The three shares need not add to 100 %:
//! Σ q_total² = Σ (Σ_j q_j)² contains cross terms 2 Σ q_j q_l, which can be either sign.

use serde::{Deserialize, Serialize};

/// Contribution of each force term, percent.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Contributions {
    /// Euler share, %.
    pub euler: f64,
    /// Centrifugal share, %.
    pub centrifugal: f64,
    /// Coriolis share, %.
    pub coriolis: f64,
    /// Aerodynamic share, % (in air; absent in a vacuum).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub aerodynamic: Option<f64>,
}

impl Contributions {
    /// The term with the largest share and its name.
    pub fn dominant(&self) -> (&'static str, f64) {
        let mut best = ("euler", self.euler);
        for (n, v) in [
            ("centrifugal", self.centrifugal),
            ("coriolis", self.coriolis),
            ("aerodynamic", self.aerodynamic.unwrap_or(f64::NEG_INFINITY)),
        ] {
            if v > best.1 {
                best = (n, v);
            }
        }
        best
    }
}

/// Σ x², summed in eight interleaved partial sums (x_0 + x_8 + …, x_1 + x_9 + …, …, then
/// added together), so the sum is not one long chain of dependent additions; the result differs
/// from the left-to-right sum only in rounding (≤ n ε relative either way).
pub fn sum_sq(x: &[f64]) -> f64 {
    max_abs_and_sum_sq(x).1
}

/// (max |x_i|, Σ x_i²) in one pass with eight interleaved lanes each
/// ([`crate::solve::stats::SeriesStats`]). NaNs are skipped by the maximum (as `f64::max`
/// does) and propagate into the sum.
pub fn max_abs_and_sum_sq(x: &[f64]) -> (f64, f64) {
    let s = crate::solve::stats::SeriesStats::of(x);
    (s.max_abs(), s.sum_sq())
}

/// Shares of the three partial responses in the total (paper's definition), percent.
/// Returns zeros when the total is identically zero.
pub fn contributions(
    euler: &[f64],
    centrifugal: &[f64],
    coriolis: &[f64],
    total: &[f64],
) -> Contributions {
    let all = [euler, centrifugal, coriolis, total].map(max_abs_and_sum_sq);
    contributions_with(euler, centrifugal, coriolis, total, all)
}

/// [`contributions`] from each series' (max |x|, Σ x²) already taken (the run's writer takes
/// them while the values are in cache: `propagate_responses`'s statistics).
pub fn contributions_with(
    euler: &[f64],
    centrifugal: &[f64],
    coriolis: &[f64],
    total: &[f64],
    all: [(f64, f64); 4],
) -> Contributions {
    // A growing (unstable) response can reach 1e200 and more: its squares would overflow, so
    // every series is scaled by one power of two (exact) chosen from the largest magnitude.
    // One pass per series gives its largest magnitude and its unscaled Σx²; only when a scale is
    // needed (magnitudes beyond 1e±100) are the sums taken again on the scaled values.
    let m = all.iter().fold(0.0_f64, |m, v| m.max(v.0));
    let s = crate::analysis::beat::safe_scale(&[m]);
    let series = [euler, centrifugal, coriolis, total];
    let ss = |i: usize| {
        if s == 1.0 {
            all[i].1
        } else {
            series[i].iter().map(|v| (v * s) * (v * s)).sum()
        }
    };
    let den = ss(3);
    if den <= 0.0 || !den.is_finite() {
        return Contributions {
            euler: 0.0,
            centrifugal: 0.0,
            coriolis: 0.0,
            aerodynamic: None,
        };
    }
    Contributions {
        euler: 100.0 * ss(0) / den,
        centrifugal: 100.0 * ss(1) / den,
        coriolis: 100.0 * ss(2) / den,
        aerodynamic: None,
    }
}

/// [`contributions`] with a fourth, aerodynamic partial response (the wing in air).
pub fn contributions_with_aero(
    euler: &[f64],
    centrifugal: &[f64],
    coriolis: &[f64],
    aerodynamic: &[f64],
    total: &[f64],
) -> Contributions {
    // The aerodynamic share with the same scaling and denominator: computed as the Euler
    // share of (aerodynamic, –, –, total).
    let base = contributions(euler, centrifugal, coriolis, total);
    let aero = contributions(aerodynamic, &[], &[], total).euler;
    let zero = base.euler == 0.0 && base.centrifugal == 0.0 && base.coriolis == 0.0 && aero == 0.0;
    Contributions {
        aerodynamic: Some(if zero { 0.0 } else { aero }),
        ..base
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The lane sums against the plain left-to-right sum and maximum, for every remainder length.
    #[test]
    fn lanes_agree_with_the_plain_sum_and_maximum() {
        for n in 0..40 {
            let x: Vec<f64> = (0..n)
                .map(|i| ((i * 37 % 11) as f64 - 5.0) * 0.37)
                .collect();
            let plain: f64 = x.iter().map(|v| v * v).sum();
            let max = x.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            let (m, s) = max_abs_and_sum_sq(&x);
            assert_eq!(m, max, "n = {n}");
            assert!(
                (s - plain).abs() <= 1e-14 * plain.max(1e-300),
                "n = {n}: {s} vs {plain}"
            );
        }
        // The maximum skips a NaN (as f64::max does); the sum carries it.
        let (m, s) = max_abs_and_sum_sq(&[1.0, f64::NAN, -3.0]);
        assert_eq!(m, 3.0);
        assert!(s.is_nan());
    }

    /// Shares do not depend on the units: the same responses at 1e150 and 1e-150 (scaled out by
    /// a power of two) give the same percentages as at 1.
    #[test]
    fn shares_are_scale_free_and_match_the_definition() {
        let t: Vec<f64> = (0..1001).map(|i| i as f64 * 1e-3).collect();
        let e: Vec<f64> = t.iter().map(|t| (7.0 * t).sin()).collect();
        let c: Vec<f64> = t.iter().map(|t| 0.3 * (3.0 * t).cos()).collect();
        let k: Vec<f64> = t.iter().map(|t| 0.1 * t).collect();
        let tot: Vec<f64> = (0..t.len()).map(|i| e[i] + c[i] + k[i]).collect();
        let r = contributions(&e, &c, &k, &tot);
        let sq = |x: &[f64]| x.iter().map(|v| v * v).sum::<f64>();
        let den = sq(&tot);
        assert!((r.euler - 100.0 * sq(&e) / den).abs() < 1e-12);
        assert!((r.centrifugal - 100.0 * sq(&c) / den).abs() < 1e-12);
        assert!((r.coriolis - 100.0 * sq(&k) / den).abs() < 1e-12);
        for f in [1e150, 1e-150] {
            let sc = |x: &[f64]| x.iter().map(|v| v * f).collect::<Vec<_>>();
            let q = contributions(&sc(&e), &sc(&c), &sc(&k), &sc(&tot));
            assert!((q.euler - r.euler).abs() < 1e-12 * r.euler, "{f}");
            assert!((q.coriolis - r.coriolis).abs() < 1e-12 * r.coriolis, "{f}");
        }
    }
}
