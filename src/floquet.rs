//! Floquet analysis of one modal equation (Eq. 13 is Hill-type: periodic stiffness).
//!
//! * The monodromy matrix M = Φ(T) maps the state over one flap period; its eigenvalues are the
//!   Floquet multipliers λ. Undamped and stable: |λ| = 1; det M = exp(−c T) always (Liouville).
//!   max |λ| > 1 means parametric resonance: the free response grows like |λ|^(t/T).
//! * The free response is a sum of Floquet solutions e^(νt) P(t), P periodic. Its *effective
//!   natural frequency* is |Im ν + n·2π/T_p| for the harmonic n that dominates P — the branch
//!   choice is not arbitrary (for the paper's mode 1, 62.5 Hz = 2.5 × 25 Hz sits exactly between
//!   two branches of the period-T multiplier). We use the homogeneous period T_p (T/2 for
//!   symmetric sinusoidal kinematics, where the softening repeats twice per flap) and pick the
//!   dominant harmonic of P from a DFT of the computed Floquet solution.
//! * The beat: the forced response at harmonic n_b·f_d beats against the effective frequency
//!   with period 1 / |f_eff − n_b f_d|. The paper's mode-1 Coriolis beat uses n_b = 2.

pub use crate::solve::propagator::multipliers;
use crate::solve::propagator::{period_map_with, HomogeneousSamples};
use crate::solve::LinearOde;
use nalgebra::{Complex, Matrix2, Vector2};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

type C64 = Complex<f64>;

/// Modulus above which a complex multiplier pair counts as unstable.
pub const STABILITY_TOL: f64 = 1e-9;
/// The same for real multipliers: near a double real multiplier (±1, the edge of a
/// parametric-resonance tongue) rounding of order ε in M moves the eigenvalues by √ε, so the
/// tolerance there is √ε-sized.
pub const STABILITY_TOL_REAL: f64 = 1e-7;

/// Stability from the multipliers over one period.
pub fn is_stable(l: &[C64; 2]) -> bool {
    let m = l[0].norm().max(l[1].norm());
    if l[0].im != 0.0 {
        m <= 1.0 + STABILITY_TOL
    } else {
        m <= 1.0 + STABILITY_TOL_REAL
    }
}

/// What Floquet analysis says about one mode.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FloquetResult {
    /// Floquet multipliers over one flap period T, as [re, im].
    pub multipliers: Vec<[f64; 2]>,
    /// The monodromy matrix over T, row-major [[m00, m01], [m10, m11]].
    pub monodromy: [[f64; 2]; 2],
    /// True when no multiplier lies outside the unit circle (see [`is_stable`] for tolerances).
    pub stable: bool,
    /// Largest multiplier modulus.
    pub max_modulus: f64,
    /// Growth rate of the free response, ln(max |λ|) / T, 1/s (negative when damped).
    pub growth_rate_per_s: f64,
    /// Period of the homogeneous coefficients used for the branch choice, s (T or T/2).
    pub homogeneous_period_s: f64,
    /// Characteristic frequency Im ν / 2π, Hz, in [0, f_p / 2] (f_p = 1 / T_p).
    pub characteristic_freq_hz: f64,
    /// Harmonic n (of f_p) that dominates the Floquet solution.
    pub dominant_harmonic: i64,
    /// Effective natural frequency |Im ν/2π + n f_p|, Hz: the frequency of the free vibration
    /// of the flapping wing (lowered by centrifugal softening).
    pub effective_freq_hz: f64,
    /// A naive estimate for comparison: sqrt(ω² − mean softening) / 2π, Hz (NaN if negative).
    pub averaged_freq_hz: f64,
    /// Harmonic of the flap frequency nearest the effective frequency (≥ 1).
    pub beat_harmonic: u32,
    /// Beat period against that harmonic, 1/|f_eff − n_b f_d|, s. None when they coincide,
    /// and None for an unstable mode (a multiplier with |λ| > 1, `stable` false): its response
    /// grows flap after flap instead of beating, so no beat period describes it.
    pub beat_period_s: Option<f64>,
    /// Beat period against 2 f_d specifically (the paper's mode-1 Coriolis beat), s; None as
    /// for `beat_period_s`.
    pub beat_period_vs_2fd_s: Option<f64>,
}

fn eigvec(m: &Matrix2<C64>, lam: C64) -> Vector2<C64> {
    let v1 = Vector2::new(m[(0, 1)], lam - m[(0, 0)]);
    let v2 = Vector2::new(lam - m[(1, 1)], m[(1, 0)]);
    let (n1, n2) = (v1.norm(), v2.norm());
    let scale = m.norm().max(1e-300);
    if n1.max(n2) <= 1e-10 * scale {
        // M ≈ λ I: every vector is an eigenvector.
        return Vector2::new(C64::new(1.0, 0.0), C64::new(0.0, 0.0));
    }
    if n1 >= n2 {
        v1
    } else {
        v2
    }
}

/// Floquet analysis of `ode` with flap frequency `flap_hz` (Hz). `averaged_freq_hz` is a
/// caller-supplied naive estimate carried into the result for comparison (NaN if none).
pub fn analyse<O: LinearOde + ?Sized>(
    ode: &O,
    flap_hz: f64,
    averaged_freq_hz: f64,
) -> FloquetResult {
    analyse_with(ode, flap_hz, averaged_freq_hz, None)
}

/// As [`analyse`], reusing a full-period monodromy matrix already computed by the caller
/// (the propagator has it), which saves one period's integration.
pub fn analyse_with<O: LinearOde + ?Sized>(
    ode: &O,
    flap_hz: f64,
    averaged_freq_hz: f64,
    monodromy: Option<Matrix2<f64>>,
) -> FloquetResult {
    let tp = ode.homogeneous_period();
    // Full-period monodromy.
    let hom = crate::solve::Homogeneous(ode);
    let mt = monodromy.unwrap_or_else(|| period_map_with(&hom, ode.period(), &[], false).monodromy);
    // Floquet solution over the homogeneous period, sampled finely enough to resolve the
    // harmonic that carries the natural frequency.
    let nh = standalone_samples(ode);
    let phases: Vec<f64> = (0..nh).map(|j| j as f64 * tp / nh as f64).collect();
    let pm = period_map_with(&hom, tp, &phases, false);
    from_samples(ode, flap_hz, averaged_freq_hz, mt, &pm.monodromy, &pm.phi)
}

/// Fewest equally spaced samples of the Floquet solution over the homogeneous period that
/// resolve the harmonic carrying the natural frequency: 4·ω/ω_p + 16 (ω the equation's
/// [`LinearOde::freq_scale`], ω_p = 2π/T_p), at least 32.
fn min_samples<O: LinearOde + ?Sized>(ode: &O) -> f64 {
    let ratio = ode.freq_scale() * ode.homogeneous_period() / (2.0 * PI);
    (4.0 * ratio + 16.0).max(32.0)
}

/// The samples [`analyse`] takes over the homogeneous period: [`min_samples`] rounded up to a
/// power of two, at most 2¹⁶ (also what [`analysis_cost`] counts).
fn standalone_samples<O: LinearOde + ?Sized>(ode: &O) -> usize {
    (min_samples(ode).min(1.0e9) as usize)
        .next_power_of_two()
        .clamp(32, 1 << 16)
}

/// As [`analyse_with`] with the full-period monodromy `monodromy`, reading the Floquet solution
/// from Φ already sampled over the homogeneous period by the caller's own integration (a
/// simulation's output grid holds it: [`HomogeneousSamples`]) instead of integrating that span
/// again. It takes every d-th sample, d the largest divisor of their number that leaves at
/// least the samples [`analyse`] would take; with too few samples, or none, it integrates
/// the span as [`analyse_with`] does.
pub fn analyse_sampled<O: LinearOde + ?Sized>(
    ode: &O,
    flap_hz: f64,
    averaged_freq_hz: f64,
    monodromy: Matrix2<f64>,
    samples: Option<&HomogeneousSamples>,
) -> FloquetResult {
    let tp = ode.homogeneous_period();
    if let Some(s) = samples {
        let m = s.phi.len();
        let need = min_samples(ode);
        if m as f64 >= need && (s.span - tp).abs() <= 1e-12 * tp {
            let most = (m as f64 / need).floor() as usize;
            let d = (1..=most).rev().find(|d| m % d == 0).unwrap_or(1);
            let phi: Vec<Matrix2<f64>> = s.phi.iter().step_by(d).copied().collect();
            return from_samples(ode, flap_hz, averaged_freq_hz, monodromy, &s.end, &phi);
        }
    }
    analyse_with(ode, flap_hz, averaged_freq_hz, Some(monodromy))
}

/// The analysis from the full-period monodromy `mt`, the homogeneous-period one `mp_real` and
/// Φ at the equally spaced phases j·T_p/`phi.len()` of the homogeneous period.
fn from_samples<O: LinearOde + ?Sized>(
    ode: &O,
    flap_hz: f64,
    averaged_freq_hz: f64,
    mt: Matrix2<f64>,
    mp_real: &Matrix2<f64>,
    phi: &[Matrix2<f64>],
) -> FloquetResult {
    let t = ode.period();
    let tp = ode.homogeneous_period();
    let fp = 1.0 / tp;
    let lt = multipliers(&mt);
    let max_modulus = lt[0].norm().max(lt[1].norm());
    let nh = phi.len();
    let phases: Vec<f64> = (0..nh).map(|j| j as f64 * tp / nh as f64).collect();
    let mp = mp_real.map(|x| C64::new(x, 0.0));
    let lp = multipliers(mp_real);
    let lam = if lp[0].im.abs() > 0.0 {
        if lp[0].im > 0.0 {
            lp[0]
        } else {
            lp[1]
        }
    } else if lp[0].norm() >= lp[1].norm() {
        lp[0]
    } else {
        lp[1]
    };
    let v = eigvec(&mp, lam);
    let nu = lam.ln() / tp; // Floquet exponent, 1/s; Im in (−π/Tp, π/Tp]
    let mu = nu.im;
    // y_j = e^(−ν τ_j) (Φ(τ_j) v)_q is the periodic factor P(τ_j).
    let y: Vec<C64> = phi
        .iter()
        .zip(&phases)
        .map(|(ph, &tau)| {
            let q = C64::new(ph[(0, 0)], 0.0) * v[0] + C64::new(ph[(0, 1)], 0.0) * v[1];
            q * (-nu * tau).exp()
        })
        .collect();
    // Harmonics −⌊(nh−1)/2⌋ ..= ⌊nh/2⌋: each alias class once, for odd nh too.
    let (lo, hi) = (-((nh as i64 - 1) / 2), nh as i64 / 2);
    let mut best = (0i64, -1.0f64);
    // Twiddles e^(−2πi m / nh), m = 0..nh (exact index arithmetic, one table).
    let tw: Vec<C64> = (0..nh)
        .map(|m| {
            let th = -2.0 * PI * m as f64 / nh as f64;
            C64::new(th.cos(), th.sin())
        })
        .collect();
    for n in lo..=hi {
        let mut c = C64::new(0.0, 0.0);
        for (j, yj) in y.iter().enumerate() {
            c += yj * tw[(n * j as i64).rem_euclid(nh as i64) as usize];
        }
        let mag = c.norm();
        // Ties (degenerate multipliers) resolve to the smaller |frequency|... either is valid.
        if mag > best.1 * (1.0 + 1e-12) {
            best = (n, mag);
        }
    }
    let n_dom = best.0;
    let f_eff = (mu / (2.0 * PI) + n_dom as f64 * fp).abs();
    let f_char = (mu / (2.0 * PI)).abs();
    let nb = ((f_eff / flap_hz).round() as u32).max(1);
    let beat = |f: f64| {
        let d = (f_eff - f).abs();
        if d > 1e-9 * f_eff.max(1.0) {
            Some(1.0 / d)
        } else {
            None
        }
    };
    let stable = is_stable(&lt);
    let beat = |f: f64| if stable { beat(f) } else { None };
    FloquetResult {
        multipliers: lt.iter().map(|z| [z.re, z.im]).collect(),
        monodromy: [[mt[(0, 0)], mt[(0, 1)]], [mt[(1, 0)], mt[(1, 1)]]],
        stable,
        max_modulus,
        growth_rate_per_s: max_modulus.ln() / t,
        homogeneous_period_s: tp,
        characteristic_freq_hz: f_char,
        dominant_harmonic: n_dom,
        effective_freq_hz: f_eff,
        averaged_freq_hz,
        beat_harmonic: nb,
        beat_period_s: beat(nb as f64 * flap_hz),
        beat_period_vs_2fd_s: beat(2.0 * flap_hz),
    }
}

/// Estimated cost of the Floquet analysis ([`analyse`], as `resonance::floquet_for` runs it)
/// for `mode` under the kinematics `kin`, in Gauss–Legendre step equivalents: the full period
/// (plus, in a simulation, its error-estimate rerun at twice the step), the homogeneous period
/// sampled at the checkpoints the Floquet solution needs, and the DFT over those checkpoints
/// (a table lookup and a complex multiply per term, counted as 1/250 step). It follows the
/// step-size rule of [`crate::solve::propagator::steps_per_span`] and the sampling rule of
/// [`analyse`].
pub fn analysis_cost(kin: &crate::kinematics::Compiled, mode: &crate::model::Mode) -> f64 {
    use crate::solve::propagator::steps_per_span;
    let ode = crate::solve::ModalOde::new(kin, mode);
    let s = ode.freq_scale().max(1e-300);
    let t = ode.period();
    let tp = ode.homogeneous_period();
    let steps = |span: f64| steps_per_span(s, span);
    let nh = standalone_samples(&ode) as f64;
    1.5 * steps(t) + nh + steps(tp) + nh * nh / 250.0
}
