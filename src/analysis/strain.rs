//! Strain at named points (paper Eqs. 16–18): ε(x, y, t) = Σ_k ε_k(x, y) q_k(t), for each of
//! ε_x, ε_y and γ_xy, using each mode's modal strain at the point and its total response.
//!
//! Also the modal strain anywhere on an FE mesh ([`modal_strains_at`]: the interpolation the
//! FE modes use for their strain points) and whole-wing strain maps ([`strain_field`]: RMS or
//! peak of a strain component at every node over a run).

use crate::error::{Result, WingbeatError};
use crate::model::{ModalStrain, Mode};
use crate::pool::SeriesPool;
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
    strain_series_in(modes, totals, &mut SeriesPool::new())
}

/// [`strain_series`] writing into series taken from `pool` (the same numbers).
pub fn strain_series_in(
    modes: &[Mode],
    totals: &[&[f64]],
    pool: &mut SeriesPool,
) -> Vec<StrainSeries> {
    // Names in order of first appearance; lookups through a map, so many points cost
    // points × modes, not points² (a quadratic version took 38 s for 100 000 points).
    let mut index: std::collections::HashMap<&str, usize> = std::collections::HashMap::new();
    let mut names: Vec<&str> = Vec::new();
    for m in modes {
        for s in &m.strains {
            index.entry(s.point.as_str()).or_insert_with(|| {
                names.push(s.point.as_str());
                names.len() - 1
            });
        }
    }
    let n = totals.first().map_or(0, |q| q.len());
    let mut out: Vec<StrainSeries> = names
        .iter()
        .map(|name| StrainSeries {
            point: (*name).to_string(),
            eps_x: pool.take(n),
            eps_y: pool.take(n),
            gamma_xy: pool.take(n),
        })
        .collect();
    // Per point, the (coefficient, response) of each mode naming it, in mode order (a mode
    // naming a point twice contributes its first entry).
    let mut terms: Vec<Vec<(&ModalStrain, &[f64])>> = vec![Vec::new(); names.len()];
    for (m, q_total) in modes.iter().zip(totals) {
        let mut seen = vec![false; names.len()];
        for s in &m.strains {
            let j = index[s.point.as_str()];
            if !std::mem::replace(&mut seen[j], true) {
                terms[j].push((s, q_total));
            }
        }
    }
    let parts: [fn(&ModalStrain) -> f64; 3] = [|s| s.eps_x, |s| s.eps_y, |s| s.gamma_xy];
    for (o, point) in out.iter_mut().zip(&terms) {
        for (series, part) in [&mut o.eps_x, &mut o.eps_y, &mut o.gamma_xy]
            .into_iter()
            .zip(parts)
        {
            // 0 + c₀q₀ + c₁q₁ + … summed in mode order, the first two modes in one pass.
            match point.as_slice() {
                [] => {}
                [(s0, q0)] => {
                    let c0 = part(s0);
                    series.extend(q0.iter().map(|q| 0.0 + c0 * q));
                }
                [(s0, q0), (s1, q1), rest @ ..] => {
                    let (c0, c1) = (part(s0), part(s1));
                    series.extend(
                        q0.iter()
                            .zip(q1.iter())
                            .map(|(a, b)| (0.0 + c0 * a) + c1 * b),
                    );
                    for (s, q) in rest {
                        let c = part(s);
                        for (v, q) in series.iter_mut().zip(q.iter()) {
                            *v += c * q;
                        }
                    }
                }
            }
        }
    }
    // A point named only by modes without a response here stays at zero strain.
    for o in &mut out {
        for series in [&mut o.eps_x, &mut o.eps_y, &mut o.gamma_xy] {
            series.resize(n, 0.0);
        }
    }
    out
}

/// Peak absolute value of a series: the largest |v|, 0 for an empty series. NaN samples are
/// skipped (`f64::max` returns the other operand), so a NaN never becomes the peak: the value
/// sets plot scales and shares in the lab (wasm `analyze`'s `peaks`), where a NaN would blank
/// the plot, and JSON outputs, where it would become `null`. A series of NaNs alone gives 0.
/// The one peak of the crate: sweeps, `reproduce` and the wasm API all call it.
pub fn peak_abs(x: &[f64]) -> f64 {
    x.iter().fold(0.0, |m, v| m.max(v.abs()))
}

/// The mesh lookup is owned by [`crate::fem`]; re-exported here for existing callers.
pub use crate::fem::locate::{interpolate_strain, locate_in_mesh};

/// Top-surface modal strain [ε_x, ε_y, γ_xy] per unit q of each of `n_modes` modes at
/// (x, y) in mm, linearly interpolated from the nodal strains `strain(mode, node)` of a
/// triangle mesh (nodes in m): the modal strains of Eqs. 16–18 at any point of the wing.
///
/// Errors (naming `point`): a non-finite coordinate, or a point outside the meshed planform
/// (the allowed text gives the mesh's extent in mm). The caller checks that the triangles'
/// node indices are in range.
pub fn modal_strains_at(
    nodes: &[[f64; 3]],
    triangles: &[[usize; 3]],
    n_modes: usize,
    strain: impl Fn(usize, usize) -> [f64; 3],
    x_mm: f64,
    y_mm: f64,
) -> Result<Vec<[f64; 3]>> {
    let big = crate::fem::geometry::MAX_COORD_MM;
    if !(x_mm.is_finite() && y_mm.is_finite() && x_mm.abs() <= big && y_mm.abs() <= big) {
        return Err(WingbeatError::invalid(
            "point",
            format!("({x_mm}, {y_mm})"),
            format!("finite coordinates within ±{big} mm"),
        ));
    }
    match locate_in_mesh(nodes, triangles, x_mm, y_mm) {
        Some((ti, l, true)) if l.iter().all(|v| v.is_finite()) => Ok((0..n_modes)
            .map(|k| interpolate_strain(triangles[ti], l, k, &strain))
            .collect()),
        _ => {
            let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
            for p in nodes {
                for k in 0..2 {
                    lo[k] = lo[k].min(p[k] * 1e3);
                    hi[k] = hi[k].max(p[k] * 1e3);
                }
            }
            Err(WingbeatError::invalid(
                "point",
                format!("({x_mm}, {y_mm}) mm"),
                format!(
                    "a point inside the meshed planform (x in [{:.3}, {:.3}] mm, y in [{:.3}, {:.3}] mm)",
                    lo[0], hi[0], lo[1], hi[1]
                ),
            ))
        }
    }
}

/// Which strain a whole-wing map shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum StrainComponent {
    /// ε_x (spanwise).
    EpsX,
    /// ε_y (chordwise).
    EpsY,
    /// γ_xy (engineering shear strain).
    GammaXy,
    /// The von Mises equivalent of the in-plane strain, the plane-stress von Mises formula
    /// applied to the strain components: ε_vm = √(ε_x² − ε_x ε_y + ε_y² + 3 (γ_xy / 2)²).
    #[default]
    VonMises,
}

/// Which statistic over the run a whole-wing map shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StrainStat {
    /// Root mean square over the samples, exact from the modal covariance.
    Rms,
    /// Largest absolute value (for von Mises: largest value) over the samples.
    Peak,
}

/// Options of [`strain_field`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StrainFieldOptions {
    /// The strain shown (default: von Mises).
    #[serde(default)]
    pub component: StrainComponent,
    /// RMS or peak.
    pub stat: StrainStat,
}

/// Most work a peak map may take: nodes × samples × modes (about 1.3 s in the browser at the
/// cap, from the lab's 0.5 s for 1653 nodes × 20001 samples × 6 modes; the default 2 s run of
/// an 8-mode wing at the automatic mesh size stays under it). RMS maps cost
/// samples × modes² + nodes × modes² and are not capped.
pub const MAX_STRAIN_FIELD_WORK: f64 = 5.0e8;

/// ε_vm² as a quadratic form in (ε_x, ε_y, γ_xy): ε_x² − ε_x ε_y + ε_y² + ¾ γ_xy².
fn von_mises_sq(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] - 0.5 * (a[0] * b[1] + a[1] * b[0]) + a[1] * b[1] + 0.75 * a[2] * b[2]
}

/// A whole-wing strain map: per node, the RMS or peak over the samples of a strain
/// component of ε(t) = Σ_k ε_k q_k(t), where `strain(mode, node)` is the nodal modal strain
/// [ε_x, ε_y, γ_xy] per unit q and `qs[k]` the modal response q_k on one time grid.
///
/// RMS: with the modal covariance C_kl = (1/N) Σ_t q_k(t) q_l(t), the mean square of a
/// linear component e = Σ_k e_k q_k is Σ_kl e_k C_kl e_l, and that of ε_vm² (a quadratic
/// form Q in the strain) is Σ_kl C_kl ε_kᵀ Q ε_l: the same number as averaging over the
/// samples, without the per-node time loop. Peak: max over every sample, capped by
/// [`MAX_STRAIN_FIELD_WORK`] (an error names the cap; pass every m-th sample to stay
/// under it).
///
/// Errors: `qs` not one series per mode, series of different or zero length, more than
/// [`crate::config::MAX_SAMPLES`] samples, a non-finite sample (named `qs[k][i]`), and a map
/// that overflows (never a NaN or infinite value).
pub fn strain_field(
    n_nodes: usize,
    n_modes: usize,
    strain: impl Fn(usize, usize) -> [f64; 3],
    qs: &[&[f64]],
    opts: &StrainFieldOptions,
) -> Result<Vec<f64>> {
    let v = strain_field_values(n_nodes, n_modes, strain, qs, opts)?;
    if let Some(i) = v.iter().position(|x| !x.is_finite()) {
        return Err(WingbeatError::NonFinite {
            what: format!("strain map at node {i}"),
            detail: "the strains or responses are too large to combine in f64".into(),
        });
    }
    Ok(v)
}

fn strain_field_values(
    n_nodes: usize,
    n_modes: usize,
    strain: impl Fn(usize, usize) -> [f64; 3],
    qs: &[&[f64]],
    opts: &StrainFieldOptions,
) -> Result<Vec<f64>> {
    if qs.len() != n_modes {
        return Err(WingbeatError::invalid(
            "qs",
            format!("{} series", qs.len()),
            format!("one series per mode ({n_modes})"),
        ));
    }
    let n = qs.first().map_or(0, |q| q.len());
    if n == 0 || n > crate::config::MAX_SAMPLES {
        return Err(WingbeatError::invalid(
            "qs[0]",
            format!("{n} samples"),
            format!("1 to {} samples", crate::config::MAX_SAMPLES),
        ));
    }
    super::check_series(qs.iter().copied(), n, "qs[0]", |k| format!("qs[{k}]"))?;
    // The index of a linear component (unused for von Mises).
    let ci = match opts.component {
        StrainComponent::EpsX | StrainComponent::VonMises => 0,
        StrainComponent::EpsY => 1,
        StrainComponent::GammaXy => 2,
    };
    let vm = opts.component == StrainComponent::VonMises;
    match opts.stat {
        StrainStat::Rms => {
            let nf = n as f64;
            let mut c = vec![0.0; n_modes * n_modes];
            for k in 0..n_modes {
                for l in 0..=k {
                    let s: f64 = qs[k].iter().zip(qs[l]).map(|(a, b)| a * b).sum::<f64>() / nf;
                    c[k * n_modes + l] = s;
                    c[l * n_modes + k] = s;
                }
            }
            Ok((0..n_nodes)
                .map(|i| {
                    let e: Vec<[f64; 3]> = (0..n_modes).map(|k| strain(k, i)).collect();
                    let mut ms = 0.0;
                    for k in 0..n_modes {
                        for l in 0..n_modes {
                            let w = if vm {
                                von_mises_sq(e[k], e[l])
                            } else {
                                e[k][ci] * e[l][ci]
                            };
                            ms += c[k * n_modes + l] * w;
                        }
                    }
                    ms.max(0.0).sqrt()
                })
                .collect())
        }
        StrainStat::Peak => {
            let work = n_nodes as f64 * n as f64 * n_modes as f64;
            if work > MAX_STRAIN_FIELD_WORK {
                return Err(WingbeatError::ResourceCap {
                    field: "nodes × samples × modes (strain peak map)".into(),
                    requested: format!("{n_nodes} × {n} × {n_modes} = {work:.3e}"),
                    cap: format!("{MAX_STRAIN_FIELD_WORK:e}"),
                    why: "the peak visits every sample at every node; pass every m-th sample"
                        .into(),
                });
            }
            let mut out = vec![0.0; n_nodes];
            let mut e = vec![[0.0; 3]; n_modes];
            for (i, o) in out.iter_mut().enumerate() {
                for (k, ek) in e.iter_mut().enumerate() {
                    *ek = strain(k, i);
                }
                let mut peak: f64 = 0.0;
                if vm {
                    for t in 0..n {
                        let mut s = [0.0; 3];
                        for k in 0..n_modes {
                            let q = qs[k][t];
                            for c in 0..3 {
                                s[c] += e[k][c] * q;
                            }
                        }
                        peak = peak.max(von_mises_sq(s, s).max(0.0).sqrt());
                    }
                } else {
                    for t in 0..n {
                        let s: f64 = (0..n_modes).map(|k| e[k][ci] * qs[k][t]).sum();
                        peak = peak.max(s.abs());
                    }
                }
                *o = peak;
            }
            Ok(out)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::peak_abs;

    #[test]
    fn peak_abs_is_the_largest_magnitude_and_never_nan() {
        assert_eq!(peak_abs(&[1.0, -3.0, 2.0]), 3.0);
        assert_eq!(peak_abs(&[]), 0.0);
        // a NaN sample is skipped wherever it falls, so it cannot reach a plot's scale
        assert_eq!(peak_abs(&[f64::NAN, 1.0, -3.0]), 3.0);
        assert_eq!(peak_abs(&[1.0, f64::NAN, -0.5]), 1.0);
        assert_eq!(peak_abs(&[-2.0, f64::NAN]), 2.0);
        assert_eq!(peak_abs(&[f64::NAN, f64::NAN]), 0.0);
    }
}
