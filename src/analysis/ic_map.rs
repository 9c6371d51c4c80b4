//! The initial-condition map (paper §4.2, Fig. 7): the Coriolis contribution of one mode over a
//! grid of initial conditions (q(0), q̇(0)).
//!
//! Linearity makes the whole map cost one propagation: with h₁, h₂ the free responses to
//! (1, 0) and (0, 1) and q_F the zero-start forced total, q(t; q₀, v₀) = q_F + q₀ h₁ + v₀ h₂,
//! so Σ q² is a quadratic form in (1, q₀, v₀) whose 3×3 Gram matrix is summed once.
//!
//! Which response is "the Coriolis response" when the initial conditions are not zero is a
//! choice the paper leaves open. [`IcAttribution::Forced`] (the default) keeps the Coriolis
//! partial as the response to the Coriolis force alone from rest — the free vibration started
//! by the initial conditions belongs to no force term and only enlarges the total. This is the
//! reading under which the paper's Fig. 6 and Fig. 7 measure the same thing (at q₀ = v₀ = 0 they
//! coincide). [`IcAttribution::Carried`] lets the Coriolis partial carry the initial conditions
//! (Coriolis + free), for comparison.

use crate::config::SimConfig;
use crate::error::{Result, WingbeatError};
use crate::solve::ModalOde;
use serde::{Deserialize, Serialize};

/// How the free vibration is attributed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum IcAttribution {
    /// Coriolis partial from rest; free vibration only in the total.
    #[default]
    Forced,
    /// Coriolis partial carries the initial conditions.
    Carried,
}

/// Options of the map.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct IcMapOptions {
    /// Mode index (0-based).
    pub mode: usize,
    /// Grid points along q(0).
    pub n_q: usize,
    /// Grid points along q̇(0).
    pub n_qdot: usize,
    /// q(0) range; default: [min, max] of the zero-start total response (the paper's bounds).
    pub q_range: Option<[f64; 2]>,
    /// q̇(0) range; default: [min, max] of the zero-start total velocity.
    pub qdot_range: Option<[f64; 2]>,
    /// Attribution of the free vibration.
    pub attribution: IcAttribution,
}

impl Default for IcMapOptions {
    fn default() -> Self {
        IcMapOptions {
            mode: 0,
            n_q: 101,
            n_qdot: 101,
            q_range: None,
            qdot_range: None,
            attribution: IcAttribution::Forced,
        }
    }
}

/// Most grid cells in one map.
pub const MAX_CELLS: usize = 4_000_000;

/// The map.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct IcMap {
    /// Mode index.
    pub mode: usize,
    /// q(0) grid values (columns).
    pub q0: Vec<f64>,
    /// q̇(0) grid values (rows).
    pub qdot0: Vec<f64>,
    /// Coriolis contribution, percent, row-major: `coriolis_percent[r * n_q + c]` at `(q0[c], qdot0[r])`.
    pub coriolis_percent: Vec<f64>,
    /// Smallest value on the map, percent.
    pub min_percent: f64,
    /// Largest value on the map, percent.
    pub max_percent: f64,
    /// Fraction of cells above 60 %.
    pub fraction_above_60: f64,
    /// Attribution used.
    pub attribution: IcAttribution,
}

fn gram(vs: &[&[f64]]) -> Vec<Vec<f64>> {
    let m = vs.len();
    let mut g = vec![vec![0.0; m]; m];
    for i in 0..m {
        for j in i..m {
            let s: f64 = vs[i].iter().zip(vs[j]).map(|(a, b)| a * b).sum();
            g[i][j] = s;
            g[j][i] = s;
        }
    }
    g
}

fn quad(g: &[Vec<f64>], x: [f64; 3]) -> f64 {
    let mut s = 0.0;
    for i in 0..3 {
        for j in 0..3 {
            s += x[i] * g[i][j] * x[j];
        }
    }
    s
}

fn grid(r: [f64; 2], n: usize) -> Vec<f64> {
    if n == 1 {
        return vec![0.5 * (r[0] + r[1])];
    }
    (0..n)
        .map(|i| r[0] + (r[1] - r[0]) * i as f64 / (n - 1) as f64)
        .collect()
}

/// Computes the map for `cfg` (its own initial conditions are ignored).
pub fn ic_map(cfg: &SimConfig, opts: &IcMapOptions) -> Result<IcMap> {
    cfg.validate()?;
    if !cfg.aero.is_vacuum() {
        // One mode's initial conditions, superposed per mode: air couples the modes.
        return Err(WingbeatError::invalid(
            "aero.air_density_kg_m3",
            cfg.aero.air_density_kg_m3,
            "0 for the initial-condition map (it superposes one mode's free responses, and a fluid couples the modes)",
        ));
    }
    if opts.mode >= cfg.modes.len() {
        return Err(WingbeatError::invalid(
            "ic_map.mode",
            opts.mode,
            format!("a mode index in [0, {}]", cfg.modes.len() - 1),
        ));
    }
    if opts.n_q == 0 || opts.n_qdot == 0 || opts.n_q.saturating_mul(opts.n_qdot) > MAX_CELLS {
        return Err(WingbeatError::invalid(
            "ic_map.n_q × ic_map.n_qdot",
            format!("{} × {}", opts.n_q, opts.n_qdot),
            format!("1 to {MAX_CELLS} cells"),
        ));
    }
    // The same bounds as a config's initial conditions (`SimConfig::validate`), so the
    // quadratic forms below stay finite.
    for (name, r, lim, unit) in [
        ("ic_map.q_range", opts.q_range, 1.0e6, "q units"),
        ("ic_map.qdot_range", opts.qdot_range, 1.0e9, "q units per s"),
    ] {
        if let Some([a, b]) = r {
            if !a.is_finite() || !b.is_finite() || a > b || a < -lim || b > lim {
                return Err(WingbeatError::invalid(
                    name,
                    format!("[{}, {}]", crate::error::num(a), crate::error::num(b)),
                    format!(
                        "finite [lo, hi] with lo ≤ hi inside [{}, {}] {unit}",
                        crate::error::num(-lim),
                        crate::error::num(lim)
                    ),
                ));
            }
        }
    }
    let kin = cfg.kinematics.compile();
    let mode = &cfg.modes[opts.mode];
    let p = crate::solve::propagator::propagate(
        &ModalOde::new(&kin, mode),
        1.0 / cfg.sample_rate_hz,
        cfg.n_samples(),
    )?;
    let tot = &p.q[ModalOde::TOTAL];
    let cor = &p.q[ModalOde::CORIOLIS];
    let minmax = |v: &[f64]| {
        v.iter()
            .fold([f64::MAX, f64::MIN], |[lo, hi], &x| [lo.min(x), hi.max(x)])
    };
    let qr = opts.q_range.unwrap_or_else(|| minmax(tot));
    let vr = opts
        .qdot_range
        .unwrap_or_else(|| minmax(&p.qdot[ModalOde::TOTAL]));
    let g_tot = gram(&[tot, &p.h_q[0], &p.h_q[1]]);
    let g_cor = gram(&[cor, &p.h_q[0], &p.h_q[1]]);
    let cor_forced = g_cor[0][0];
    let q0 = grid(qr, opts.n_q);
    let qdot0 = grid(vr, opts.n_qdot);
    let mut out = Vec::with_capacity(q0.len() * qdot0.len());
    for &v in &qdot0 {
        for &q in &q0 {
            let x = [1.0, q, v];
            let den = quad(&g_tot, x);
            let num = match opts.attribution {
                IcAttribution::Forced => cor_forced,
                IcAttribution::Carried => quad(&g_cor, x),
            };
            out.push(if den > 0.0 { 100.0 * num / den } else { 0.0 });
        }
    }
    if out.iter().any(|v| !v.is_finite()) {
        return Err(WingbeatError::NonFinite {
            what: "ic_map".into(),
            detail: "a Coriolis share overflowed: the response (or the ranges) are too large; \
                     shorten the run or narrow `q_range`/`qdot_range`"
                .into(),
        });
    }
    let min_percent = out.iter().cloned().fold(f64::MAX, f64::min);
    let max_percent = out.iter().cloned().fold(f64::MIN, f64::max);
    let fraction_above_60 = out.iter().filter(|v| **v > 60.0).count() as f64 / out.len() as f64;
    Ok(IcMap {
        mode: opts.mode,
        q0,
        qdot0,
        coriolis_percent: out,
        min_percent,
        max_percent,
        fraction_above_60,
        attribution: opts.attribution,
    })
}
