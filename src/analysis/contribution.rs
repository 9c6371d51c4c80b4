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

/// Σ x².
pub fn sum_sq(x: &[f64]) -> f64 {
    x.iter().map(|v| v * v).sum()
}

/// Shares of the three partial responses in the total (paper's definition), percent.
/// Returns zeros when the total is identically zero.
pub fn contributions(
    euler: &[f64],
    centrifugal: &[f64],
    coriolis: &[f64],
    total: &[f64],
) -> Contributions {
    // A growing (unstable) response can reach 1e200 and more: its squares would overflow, so
    // every series is scaled by one power of two (exact) chosen from the largest magnitude.
    let all = [euler, centrifugal, coriolis, total];
    let m = all
        .iter()
        .flat_map(|x| x.iter())
        .fold(0.0_f64, |m, v| m.max(v.abs()));
    let s = crate::analysis::beat::safe_scale(&[m]);
    let ss = |x: &[f64]| {
        if s == 1.0 {
            sum_sq(x)
        } else {
            x.iter().map(|v| (v * s) * (v * s)).sum()
        }
    };
    let den = ss(total);
    if den <= 0.0 || !den.is_finite() {
        return Contributions {
            euler: 0.0,
            centrifugal: 0.0,
            coriolis: 0.0,
            aerodynamic: None,
        };
    }
    Contributions {
        euler: 100.0 * ss(euler) / den,
        centrifugal: 100.0 * ss(centrifugal) / den,
        coriolis: 100.0 * ss(coriolis) / den,
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
