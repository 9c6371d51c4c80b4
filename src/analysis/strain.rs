//! Strain at named points (paper Eqs. 16–18): ε(x, y, t) = Σ_k ε_k(x, y) q_k(t), for each of
//! ε_x, ε_y and γ_xy, using each mode's modal strain at the point and its total response.

use crate::model::Mode;
use crate::simulate::{ModeResult, StrainSeries};

/// Strain series at every point named by any mode (a mode without strain at a point adds 0).
pub fn strain_series(modes: &[Mode], results: &[ModeResult]) -> Vec<StrainSeries> {
    let mut names: Vec<String> = Vec::new();
    for m in modes {
        for s in &m.strains {
            if !names.contains(&s.point) {
                names.push(s.point.clone());
            }
        }
    }
    let n = results.first().map_or(0, |r| r.q.total.len());
    names
        .into_iter()
        .map(|name| {
            let mut out = StrainSeries {
                point: name.clone(),
                eps_x: vec![0.0; n],
                eps_y: vec![0.0; n],
                gamma_xy: vec![0.0; n],
            };
            for (m, r) in modes.iter().zip(results) {
                if let Some(s) = m.strains.iter().find(|s| s.point == name) {
                    for (i, q) in r.q.total.iter().enumerate() {
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
