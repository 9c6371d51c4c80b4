//! Strain at named points (paper Eqs. 16–18): ε(x, y, t) = Σ_k ε_k(x, y) q_k(t), for each of
//! ε_x, ε_y and γ_xy, using each mode's modal strain at the point and its total response.

use crate::model::Mode;
use serde::{Deserialize, Serialize};

/// Strain time series at one point (Eqs. 16–18): Σ_k ε_k q_k(t).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StrainSeries {
    /// Point label.
    pub point: String,
    /// ε_x(t).
    pub eps_x: Vec<f64>,
    /// ε_y(t).
    pub eps_y: Vec<f64>,
    /// γ_xy(t).
    pub gamma_xy: Vec<f64>,
}

/// Strain series at every point named by any mode (a mode without strain at a point adds 0).
/// `totals[k]` is mode k's total response q_k(t); all on one time grid.
pub fn strain_series(modes: &[Mode], totals: &[&[f64]]) -> Vec<StrainSeries> {
    let mut names: Vec<String> = Vec::new();
    for m in modes {
        for s in &m.strains {
            if !names.contains(&s.point) {
                names.push(s.point.clone());
            }
        }
    }
    let n = totals.first().map_or(0, |q| q.len());
    names
        .into_iter()
        .map(|name| {
            let mut out = StrainSeries {
                point: name.clone(),
                eps_x: vec![0.0; n],
                eps_y: vec![0.0; n],
                gamma_xy: vec![0.0; n],
            };
            for (m, q_total) in modes.iter().zip(totals) {
                if let Some(s) = m.strains.iter().find(|s| s.point == name) {
                    for (i, q) in q_total.iter().enumerate() {
                        out.eps_x[i] += s.eps_x * q;
                        out.eps_y[i] += s.eps_y * q;
                        out.gamma_xy[i] += s.gamma_xy * q;
                    }
                }
            }
            out
        })
        .collect()
}

/// Peak absolute value of a series.
pub fn peak_abs(x: &[f64]) -> f64 {
    x.iter().fold(0.0, |m, v| m.max(v.abs()))
}
