//! Floquet analysis of the coupled system in air: the 2N multipliers of the monodromy, and for
//! each structural mode the Floquet mode that continues it (the one whose motion lies most in
//! that mode), with its effective frequency and decay rate.
//!
//! As for one mode ([`crate::floquet`]), the effective frequency is |Im ν/2π + n f_p| with ν
//! the Floquet exponent over the homogeneous period T_p and n the harmonic of f_p = 1/T_p that
//! dominates the periodic factor of the Floquet solution, here read from the mode's own
//! coordinate. T_p is T/2 when the system's coefficients repeat twice per flap (checked
//! numerically), else T.

use super::ode::AirOde;
use crate::error::{Result, WingbeatError};
use crate::floquet::{FloquetResult, STABILITY_TOL, STABILITY_TOL_REAL};
use crate::solve::coupled::CoupledOde;
use nalgebra::{Complex, DMatrix, DVector};
use std::f64::consts::PI;

type C64 = Complex<f64>;

/// One structural mode's Floquet numbers in the coupled system.
#[derive(Debug, Clone)]
pub struct ModeFloquet {
    /// The single-mode-shaped summary (multipliers of its Floquet pair over T, its own 2×2
    /// block of the coupled monodromy, frequencies, beat).
    pub floquet: FloquetResult,
    /// −Re ν, 1/s: positive when the free vibration decays.
    pub decay_rate_per_s: f64,
    /// Share of the Floquet mode's motion in this structural mode.
    pub participation: f64,
}

/// The coupled Floquet analysis.
#[derive(Debug, Clone)]
pub struct CoupledFloquet {
    /// Per structural mode.
    pub modes: Vec<ModeFloquet>,
    /// All multipliers over T, [re, im].
    pub multipliers: Vec<[f64; 2]>,
    /// No multiplier outside the unit circle.
    pub stable: bool,
}

/// Whether the homogeneous coefficients repeat with period T/2.
fn half_period(ode: &AirOde<'_>) -> bool {
    let n = ode.n_modes();
    let t = ode.period();
    let (mut b0, mut c0, mut b1, mut c1) = (
        vec![0.0; n * n],
        vec![0.0; n * n],
        vec![0.0; n * n],
        vec![0.0; n * n],
    );
    let h = ode.homogeneous();
    for j in 0..8 {
        let tau = (j as f64 + 0.37) * t / 16.0;
        h.eval(tau, &mut b0, &mut c0, &mut []);
        h.eval(tau + 0.5 * t, &mut b1, &mut c1, &mut []);
        let scale = b0.iter().chain(&c0).fold(0.0f64, |m, v| m.max(v.abs()));
        let diff = b0
            .iter()
            .zip(&b1)
            .chain(c0.iter().zip(&c1))
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
        if diff > 1e-12 * scale.max(1e-300) {
            return false;
        }
    }
    true
}

/// An eigenvector of `m` for the eigenvalue `lam` by inverse iteration.
fn eigvec(m: &DMatrix<C64>, lam: C64) -> DVector<C64> {
    let d = m.nrows();
    let shift = lam + C64::new(1e-10, 1e-10) * lam.norm().max(1e-300);
    let a = m - DMatrix::<C64>::identity(d, d) * shift;
    let lu = a.lu();
    let mut v = DVector::<C64>::from_fn(d, |i, _| C64::new(1.0 + 0.1 * i as f64, 0.3));
    for _ in 0..3 {
        if let Some(x) = lu.solve(&v) {
            let nrm = x.norm();
            if nrm > 0.0 && nrm.is_finite() {
                v = x / C64::new(nrm, 0.0);
            }
        }
    }
    v
}

/// Greedy assignment of Floquet candidates to modes: the largest share first, each candidate
/// and each mode used once (`shares[c][k]`: candidate c's share in mode k). `None` for a mode
/// left without a candidate.
fn assign_by_share(shares: &[&[f64]], n: usize) -> Vec<Option<usize>> {
    let mut pairs: Vec<(f64, usize, usize)> = Vec::new();
    for (ci, share) in shares.iter().enumerate() {
        for k in 0..n {
            pairs.push((share[k], ci, k));
        }
    }
    pairs.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut of_mode: Vec<Option<usize>> = vec![None; n];
    let mut used = vec![false; shares.len()];
    for (_, ci, k) in pairs {
        if of_mode[k].is_none() && !used[ci] {
            of_mode[k] = Some(ci);
            used[ci] = true;
        }
    }
    of_mode
}

/// The DFT's twiddle factors e^(−2πi m/nh), m = 0..nh.
fn twiddles(nh: usize) -> Vec<C64> {
    (0..nh)
        .map(|m| {
            let th = -2.0 * PI * m as f64 / nh as f64;
            C64::new(th.cos(), th.sin())
        })
        .collect()
}

/// The harmonic h in (−nh/2, nh/2] with the largest DFT magnitude of the periodic samples `y`
/// (`tw[m]` = e^(−2πi m/nh)); ties within 1e-12 go to the first.
fn dominant_harmonic(y: &[C64], tw: &[C64]) -> i64 {
    let nh = tw.len();
    let half = nh as i64 / 2;
    let mut best = (0i64, -1.0f64);
    for h in (-half + 1)..=half {
        let mut s = C64::new(0.0, 0.0);
        for (j, yj) in y.iter().enumerate() {
            s += yj * tw[(h * j as i64).rem_euclid(nh as i64) as usize];
        }
        let mag = s.norm();
        if mag > best.1 * (1.0 + 1e-12) {
            best = (h, mag);
        }
    }
    best.0
}

/// The phases the Floquet analysis reads Φ at: nh equally spaced phases j·T_p/nh over the
/// homogeneous period T_p (T/2 when the coefficients repeat twice per flap, else T), enough for
/// the harmonics up to 4× the system's highest frequency, a power of two in [32, 16384].
#[derive(Debug, Clone)]
pub struct FloquetGrid {
    /// T_p, s.
    pub tp: f64,
    /// j·T_p/nh, j = 0..nh.
    pub phases: Vec<f64>,
}

impl FloquetGrid {
    /// The grid for `ode`. When the output samples fall on `per_period` equally spaced phases
    /// of the flap period (a commensurate grid), nh is the smallest whole fraction of them
    /// that is still enough, so the Floquet phases are output phases and cost the propagator
    /// no extra steps; otherwise nh is the next power of two.
    pub fn new(ode: &AirOde<'_>, per_period: Option<usize>) -> FloquetGrid {
        let t = ode.period();
        let half = half_period(ode);
        let tp = if half { 0.5 * t } else { t };
        let ratio = ode.homogeneous().freq_scale() * tp / (2.0 * PI);
        let need = ((4.0 * ratio + 16.0) as usize).max(32);
        let on_output = per_period
            .map(|l| if half { l / 2 } else { l })
            .filter(|&l| l >= need && (!half || per_period.is_some_and(|p| p % 2 == 0)))
            .and_then(|l| (1..=l / need).rev().find(|k| l % k == 0).map(|k| l / k))
            .filter(|&nh| nh <= 1 << 14);
        let nh = on_output.unwrap_or_else(|| need.next_power_of_two().clamp(32, 1 << 14));
        FloquetGrid {
            tp,
            phases: (0..nh).map(|j| j as f64 * tp / nh as f64).collect(),
        }
    }

    /// The phases to ask the propagator for: the grid and T_p itself (its last entry).
    pub fn checkpoints(&self) -> Vec<f64> {
        let mut v = self.phases.clone();
        v.push(self.tp);
        v
    }
}

/// The Φ values handed to [`analyse_coupled`]: one d × d matrix per checkpoint.
fn check_phi(phi: &[f64], checkpoints: usize, d: usize) -> Result<()> {
    if phi.len() != checkpoints * d * d {
        return Err(WingbeatError::NonFinite {
            what: "coupled Floquet analysis".into(),
            detail: format!("{} values of Φ for {checkpoints} phases", phi.len()),
        });
    }
    Ok(())
}

/// Analyses the coupled system `ode` whose full-period monodromy is `mono` (2N × 2N
/// row-major), from Φ at the `grid`'s [`FloquetGrid::checkpoints`] (`phi`, concatenated, as
/// [`crate::solve::coupled::propagate_coupled`] returns them for those extra phases).
pub fn analyse_coupled(
    ode: &AirOde<'_>,
    mono: &[f64],
    flap_hz: f64,
    grid: &FloquetGrid,
    phi: &[f64],
) -> Result<CoupledFloquet> {
    let n = ode.n_modes();
    let d = 2 * n;
    let t = ode.period();
    let mt = DMatrix::from_row_slice(d, d, mono);
    let lt = mt.complex_eigenvalues();
    let modulus = |z: &C64| z.norm();
    let stable = lt.iter().all(|z| {
        if z.im != 0.0 {
            modulus(z) <= 1.0 + STABILITY_TOL
        } else {
            modulus(z) <= 1.0 + STABILITY_TOL_REAL
        }
    });
    let tp = grid.tp;
    let fp = 1.0 / tp;
    let phases = &grid.phases;
    let nh = phases.len();
    check_phi(phi, nh + 1, d)?;
    let mp = DMatrix::from_row_slice(d, d, &phi[nh * d * d..]);
    let lp = mp.complex_eigenvalues();
    let mpc = mp.map(|x| C64::new(x, 0.0));
    // Candidates: one of each conjugate pair (Im ≥ 0) and the real ones.
    let mut cands: Vec<C64> = lp.iter().copied().filter(|z| z.im >= 0.0).collect();
    cands.sort_by(|a, b| b.norm().total_cmp(&a.norm()));
    let w: Vec<f64> = ode.modes.iter().map(|m| m.omega().max(1e-300)).collect();
    // Per candidate: ν, the periodic factor of each coordinate, participation.
    struct Cand {
        nu: C64,
        y: Vec<Vec<C64>>,
        share: Vec<f64>,
    }
    let mut info = Vec::with_capacity(cands.len());
    for &lam in &cands {
        if lam.norm() == 0.0 || !lam.norm().is_finite() {
            return Err(WingbeatError::NonFinite {
                what: "coupled Floquet analysis".into(),
                detail: format!("a multiplier is {lam}"),
            });
        }
        let v = eigvec(&mpc, lam);
        let nu = lam.ln() / tp;
        let mut y = vec![Vec::with_capacity(nh); n];
        let mut energy = vec![0.0; n];
        for (c, &tau) in phases.iter().enumerate() {
            let ph = &phi[c * d * d..(c + 1) * d * d];
            let damp = (-nu * tau).exp();
            for k in 0..n {
                let mut qk = C64::new(0.0, 0.0);
                let mut vk = C64::new(0.0, 0.0);
                for j in 0..d {
                    qk += v[j] * ph[k * d + j];
                    vk += v[j] * ph[(n + k) * d + j];
                }
                energy[k] += (qk * w[k]).norm_sqr() + vk.norm_sqr();
                y[k].push(qk * damp);
            }
        }
        let tot: f64 = energy.iter().sum::<f64>().max(1e-300);
        info.push(Cand {
            nu,
            y,
            share: energy.iter().map(|e| e / tot).collect(),
        });
    }
    let shares: Vec<&[f64]> = info.iter().map(|c| c.share.as_slice()).collect();
    let of_mode = assign_by_share(&shares, n);
    let tw = twiddles(nh);
    let mut modes = Vec::with_capacity(n);
    for k in 0..n {
        let ci = of_mode[k].unwrap_or(0);
        let c = &info[ci];
        let h_dom = dominant_harmonic(&c.y[k], &tw);
        let mu = c.nu.im;
        let f_eff = (mu / (2.0 * PI) + h_dom as f64 * fp).abs();
        let nb = ((f_eff / flap_hz).round() as u32).max(1);
        let lam_t = (c.nu * t).exp();
        let pair = [lam_t, lam_t.conj()];
        let max_modulus = lam_t.norm();
        let beat = |f: f64| {
            let dd = (f_eff - f).abs();
            (stable && dd > 1e-9 * f_eff.max(1.0)).then(|| 1.0 / dd)
        };
        let block = [
            [mono[k * d + k], mono[k * d + n + k]],
            [mono[(n + k) * d + k], mono[(n + k) * d + n + k]],
        ];
        modes.push(ModeFloquet {
            floquet: FloquetResult {
                multipliers: pair.iter().map(|z| [z.re, z.im]).collect(),
                monodromy: block,
                stable,
                max_modulus,
                growth_rate_per_s: c.nu.re,
                homogeneous_period_s: tp,
                characteristic_freq_hz: (mu / (2.0 * PI)).abs(),
                dominant_harmonic: h_dom,
                effective_freq_hz: f_eff,
                averaged_freq_hz: f64::NAN,
                beat_harmonic: nb,
                beat_period_s: beat(nb as f64 * flap_hz),
                beat_period_vs_2fd_s: beat(2.0 * flap_hz),
            },
            decay_rate_per_s: -c.nu.re,
            participation: c.share[k],
        });
    }
    Ok(CoupledFloquet {
        modes,
        multipliers: lt.iter().map(|z| [z.re, z.im]).collect(),
        stable,
    })
}
