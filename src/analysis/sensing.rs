//! Sensing body rotation through wing strain: the rotation signal, the per-node
//! detectability map and greedy sensor placement (docs/sensing.md).
//!
//! **The rotation signal.** The modal equation (paper Eq. 13) is linear in q with forcing
//! and stiffness set by the frame rate Ω. With a body angular velocity ω_b, two runs of the
//! same wing under the same kinematics, one with ω_b and one without, differ by
//! Δq_k(t) = q_k(t; ω_b) − q_k(t; 0): the part of the response that the body rotation causes.
//! The difference of two exact solutions is exact; it is linear in ω_b only to first order,
//! because Ω enters the stiffness term (Ω_x² + Ω_y²) and the centrifugal force quadratically.
//! With FE modes the strain follows (Eqs. 16–18): Δε(x, t) = Σ_k ε_k(x) Δq_k(t) for each of
//! ε_x, ε_y and γ_xy; the flapping strain ε_F(x, t) = Σ_k ε_k(x) q_k(t; 0) is what the wing
//! feels without rotation.
//!
//! **Detectability per point.** D(x) = E_Δ(x) / (ρ² E_F(x) + σ²): the mean square of Δε over
//! the run against the mean square of the flapping strain scaled by a relative stroke
//! variability ρ (a real stroke is never exactly periodic, and a change of the flapping strain
//! by a fraction ρ is what the rotation signal has to be told apart from) plus a sensor noise
//! floor σ² (σ an rms strain). Mean squares come from the modal covariances, so the map costs
//! nodes × modes² and no time loop (as [`crate::analysis::strain::strain_field`]'s RMS map).
//!
//! **Sparse placement.** A sensor is one strain component at one node. For a set S of sensors
//! stack their Δε series (decimated to M samples each) into Δ and their flapping-strain series
//! into F. The test "rotation vs none" sees y = s Δ + δ F + n with s ∈ {0, 1}, a stroke
//! variation δ ~ N(0, ρ²) common to all sensors (a rank-one nuisance) and white sensor noise
//! n ~ N(0, σ² I). The deflection d'² = Δᵀ C⁻¹ Δ with C = ρ² F Fᵀ + σ² I is, by
//! Sherman–Morrison,
//!
//! d'² = (A − ρ² B² / (σ² + ρ² G)) / σ²,  A = ΔᵀΔ, B = FᵀΔ, G = FᵀF,
//!
//! and A, B, G are sums over the sensors, so adding a candidate costs O(1). Sensors are chosen
//! by greedy forward selection (each step adds the candidate that raises d'² most): a greedy
//! approximation to the best subset, as in sparse sensor placement for classification
//! (Brunton et al., SIAM J. Appl. Math. 2016; Mohren et al., PNAS 2018), not the optimum. The
//! detection probability of a likelihood-ratio test at false-alarm rate P_fa is
//! P_d = Φ(d' − z_(1−P_fa)), reported for P_fa = 1 %.

use crate::analysis::strain::{modal_strains_at, StrainSeries};
use crate::config::SimConfig;
use crate::error::{Result, WingbeatError};
use crate::simulate::{check_run_cost, simulate, MAX_RUN_WORK};
use serde::{Deserialize, Serialize};

/// Default relative stroke variability ρ (1 %).
pub const DEFAULT_RHO: f64 = 0.01;
/// Default sensor noise floor σ, rms strain per decimated sample (1e-7). For FE modes the
/// strain is a true (dimensionless) strain; for the paper table's modes it is in the table's
/// units, which are not SI (docs/model.md), so σ has no absolute meaning there.
pub const DEFAULT_NOISE: f64 = 1e-7;
/// Smallest sensor noise σ accepted: 1e-12 strain, three orders of magnitude below the best
/// strain gauges. The detectability scales as 1/σ², and σ² must stay a normal f64: the former
/// floor, any σ > 0, let σ = 1e-300 through, whose square is 0, and the run then failed as
/// "too large to combine in f64".
pub const MIN_NOISE: f64 = 1e-12;
/// Default samples per sensor in the stacked detection vector.
pub const DEFAULT_SAMPLES_PER_SENSOR: usize = 256;
/// Most samples per sensor.
pub const MAX_SAMPLES_PER_SENSOR: usize = 4096;
/// Most sensors in the reported performance curve (K = 1 … k_max).
pub const MAX_K: usize = 30;
/// False-alarm rate of the reported detection probability.
pub const PFA: f64 = 0.01;
/// z_(1−P_fa) for [`PFA`] = 1 %: Φ⁻¹(0.99).
pub const Z_PFA: f64 = 2.326_347_874_040_841;
/// Most work of the per-node part (nodes × modes² × 3 components × 3 quadratic forms), about
/// one multiply–add each: 1e9 is a few seconds natively.
pub const MAX_SENSING_MAP_WORK: f64 = 1.0e9;
/// Most work of the Δε series at chosen points (points × samples × modes), checked before
/// anything is allocated: as [`crate::analysis::strain::MAX_STRAIN_FIELD_WORK`].
pub const MAX_SENSING_SERIES_WORK: f64 = 5.0e8;

/// Most candidate evaluations of the greedy continuation past k_max (steps × candidates):
/// about 0.5 s natively.
pub const MAX_GREEDY_WORK: f64 = 2.0e8;

/// Options of the sensing analysis.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SensingOptions {
    /// Sensors in the performance curve, 1 ..= [`MAX_K`].
    pub k_max: usize,
    /// Relative stroke variability ρ, [0, 1].
    pub rho: f64,
    /// Sensor noise σ, rms strain per decimated sample, [[`MIN_NOISE`], 1].
    pub noise: f64,
    /// Samples per sensor M in the detection vector, 8 ..= [`MAX_SAMPLES_PER_SENSOR`] (the
    /// run is decimated to every m-th sample, m = ⌈N / M⌉).
    pub samples_per_sensor: usize,
}

impl Default for SensingOptions {
    fn default() -> Self {
        SensingOptions {
            k_max: MAX_K,
            rho: DEFAULT_RHO,
            noise: DEFAULT_NOISE,
            samples_per_sensor: DEFAULT_SAMPLES_PER_SENSOR,
        }
    }
}

impl SensingOptions {
    /// Validates, naming each field `{prefix}k_max` etc. (the CLI passes its flag names
    /// through [`SensingOptions::validate_named`]).
    pub fn validate(&self) -> Result<()> {
        self.validate_named([
            "sensing.k_max",
            "sensing.rho",
            "sensing.noise",
            "sensing.samples_per_sensor",
        ])
    }

    /// Validates with the given names for k_max, rho, noise and samples_per_sensor.
    pub fn validate_named(&self, names: [&str; 4]) -> Result<()> {
        if self.k_max == 0 || self.k_max > MAX_K {
            return Err(WingbeatError::invalid(
                names[0],
                self.k_max,
                format!("an integer in [1, {MAX_K}]"),
            ));
        }
        crate::error::check_range(names[1], self.rho, 0.0, 1.0, "(relative)")?;
        crate::error::check_range(names[2], self.noise, MIN_NOISE, 1.0, "(rms strain)")?;
        if self.samples_per_sensor < 8 || self.samples_per_sensor > MAX_SAMPLES_PER_SENSOR {
            return Err(WingbeatError::invalid(
                names[3],
                self.samples_per_sensor,
                format!("an integer in [8, {MAX_SAMPLES_PER_SENSOR}]"),
            ));
        }
        Ok(())
    }
}

/// The modal rotation signal of one wing: per mode, the flapping response q_k(t; 0) and the
/// rotation-induced part Δq_k(t) = q_k(t; ω_b) − q_k(t; 0), on one time grid.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ModalSignal {
    /// Sample times, s.
    pub t: Vec<f64>,
    /// Sample rate, Hz.
    pub sample_rate_hz: f64,
    /// Flap frequency, Hz.
    pub flap_freq_hz: f64,
    /// Body rate ω_b (body axes), rad/s.
    pub body_rate: [f64; 3],
    /// Per mode, q_k(t; 0) (total response without body rotation).
    pub flap: Vec<Vec<f64>>,
    /// Per mode, Δq_k(t).
    pub delta: Vec<Vec<f64>>,
    /// Warnings of the runs.
    pub warnings: Vec<String>,
}

/// Sets a constant body rate on a config. The rotation signal is written against this so
/// that the core does not care how the body rate is stored in the kinematics.
pub type SetBodyRate<'a> = &'a dyn Fn(&mut SimConfig, [f64; 3]);

/// The body-rate setter of the kinematics (`Kinematics::body_rate`, constant in body axes).
pub fn set_constant_body_rate(cfg: &mut SimConfig, w: [f64; 3]) {
    cfg.kinematics.body_rate = crate::kinematics::BodyRate::constant(w);
}

/// The constant body rate ω_b (rad/s, body axes I, J, K) from a list of numbers, as the
/// front ends receive it: exactly three, each checked by [`check_body_rate`]. The one check
/// of the CLI's `--body-rate` (simulate, psd, sweep, sense) and of wasm `senseRotation`'s
/// `body_rate`; errors name `field` (`field[i]` for a component) and the range.
pub fn body_rate_vector(field: &str, v: &[f64]) -> Result<[f64; 3]> {
    let [x, y, z] = v else {
        return Err(WingbeatError::invalid(
            field,
            format!("{} numbers", v.len()),
            format!(
                "three numbers x, y, z in rad/s (body axes I, J, K), each a finite number in \
                 [{}, {MAX_BODY_RATE}]",
                -MAX_BODY_RATE
            ),
        ));
    };
    let w = [*x, *y, *z];
    check_body_rate(field, w)?;
    Ok(w)
}

/// Refuses a body rate that is not three finite numbers within ±[`MAX_BODY_RATE`] rad/s,
/// naming `field[i]` for component i.
pub fn check_body_rate(field: &str, w: [f64; 3]) -> Result<()> {
    for (i, v) in w.iter().enumerate() {
        crate::error::check_range(
            &format!("{field}[{i}]"),
            *v,
            -MAX_BODY_RATE,
            MAX_BODY_RATE,
            "rad/s",
        )?;
    }
    Ok(())
}

/// Largest body rate component accepted, rad/s: the kinematics' own range
/// ([`crate::params::MAX_BODY_RATE_RAD_S`]).
pub const MAX_BODY_RATE: f64 = crate::params::MAX_BODY_RATE_RAD_S;

/// The rotation signal of `cfg` (kinematics, modes, duration, initial conditions) under a
/// constant body rate ω_b = `body_rate` (rad/s, body axes): two runs of
/// [`crate::simulate::simulate`], one with ω_b and one with ω_b = 0 (both keep the config's
/// initial conditions, which therefore cancel in Δq). Both runs' work is checked against
/// [`MAX_RUN_WORK`] before either starts. Any body rate already in `cfg` is replaced.
pub fn modal_rotation_signal(cfg: &SimConfig, body_rate: [f64; 3]) -> Result<ModalSignal> {
    modal_rotation_signal_with(cfg, body_rate, &set_constant_body_rate)
}

/// [`modal_rotation_signal`] with the body rate applied by `set`.
pub fn modal_rotation_signal_with(
    cfg: &SimConfig,
    body_rate: [f64; 3],
    set: SetBodyRate<'_>,
) -> Result<ModalSignal> {
    check_body_rate("body_rate", body_rate)?;
    let mut base = cfg.clone();
    set(&mut base, [0.0; 3]);
    let mut rot = cfg.clone();
    set(&mut rot, body_rate);
    base.validate()?;
    rot.validate()?;
    check_run_cost(&base, MAX_RUN_WORK, "sense (run without rotation)")?;
    check_run_cost(&rot, MAX_RUN_WORK, "sense (run with rotation)")?;
    let r0 = simulate(&base)?;
    let r1 = if body_rate == [0.0; 3] {
        r0.clone()
    } else {
        simulate(&rot)?
    };
    let flap: Vec<Vec<f64>> = r0.modes.iter().map(|m| m.q.total.clone()).collect();
    let delta = r0
        .modes
        .iter()
        .zip(&r1.modes)
        .map(|(a, b)| {
            b.q.total
                .iter()
                .zip(&a.q.total)
                .map(|(x, y)| x - y)
                .collect()
        })
        .collect();
    let mut warnings = r0.warnings;
    for w in r1.warnings {
        if !warnings.contains(&w) {
            warnings.push(w);
        }
    }
    Ok(ModalSignal {
        t: r0.t,
        sample_rate_hz: cfg.sample_rate_hz,
        flap_freq_hz: r0.flap_freq_hz,
        body_rate,
        flap,
        delta,
        warnings,
    })
}

/// Most values of the Δε series at chosen points (points × samples): each point keeps six
/// series (Δε and the flapping strain, three components) and writes three, about 105 bytes per
/// point and sample in `wingbeat sense` (measured: 15 points over 2 000 000 samples of 4 FE
/// modes peaked at 3.5 GB, 60 points at 13.5 GB). 8e6 keeps a run at the sample cap (the two
/// runs' series, about 360 MB) under the documented 1.5 GB: 4 points over 2 000 000 samples,
/// all 256 over 31 250.
pub const MAX_SENSING_SERIES_VALUES: f64 = 8.0e6;

/// The Δε series' caps: work (points × samples × modes) and memory (points × samples).
fn check_series_size(n_points: usize, n: usize, m: usize) -> Result<()> {
    let work = n_points as f64 * n as f64 * m as f64;
    if work > MAX_SENSING_SERIES_WORK {
        return Err(WingbeatError::ResourceCap {
            field: "points × samples × modes (Δε series)".into(),
            requested: format!("{n_points} × {n} × {m} = {work:.3e}"),
            cap: format!("{MAX_SENSING_SERIES_WORK:e}"),
            why: "every point's series is written out; ask for fewer points or a shorter run"
                .into(),
        });
    }
    let values = n_points as f64 * n as f64;
    if values > MAX_SENSING_SERIES_VALUES {
        return Err(WingbeatError::ResourceCap {
            field: "points × samples (Δε series)".into(),
            requested: format!("{n_points} × {n} = {values:.3e}"),
            cap: format!("{MAX_SENSING_SERIES_VALUES:e}"),
            why: format!(
                "memory for the series (about 105 bytes per point and sample); at {n} samples at \
                 most {} points fit: ask for fewer points (--points) or a shorter run",
                (MAX_SENSING_SERIES_VALUES / n.max(1) as f64).floor()
            ),
        });
    }
    Ok(())
}

/// Checks, before any work, every budget of a sensing analysis of `cfg` under `body_rate`:
/// both runs against [`MAX_RUN_WORK`], the per-node map and placement against
/// [`MAX_SENSING_MAP_WORK`] (`n_nodes`, 0 without a mesh), and `n_points` Δε series against
/// [`MAX_SENSING_SERIES_WORK`] and [`MAX_SENSING_SERIES_VALUES`]. `who` names the caller in
/// errors.
pub fn check_sensing_cost(
    cfg: &SimConfig,
    body_rate: [f64; 3],
    n_nodes: usize,
    n_points: usize,
    who: &str,
) -> Result<()> {
    check_body_rate("body_rate", body_rate)?;
    let mut rot = cfg.clone();
    set_constant_body_rate(&mut rot, body_rate);
    rot.validate()?;
    check_run_cost(&rot, MAX_RUN_WORK, who)?;
    let m = cfg.modes.len();
    check_map_work(n_nodes, m)?;
    check_series_size(n_points, cfg.n_samples(), m)
}

/// The strain component names, in the order of the nodal strain triples.
pub const COMPONENTS: [&str; 3] = ["eps_x", "eps_y", "gamma_xy"];

/// Per-node detectability (one entry per node, each [ε_x, ε_y, γ_xy]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DetectabilityMap {
    /// E_Δ: mean square of Δε over the run.
    pub e_delta: Vec<[f64; 3]>,
    /// E_F: mean square of the flapping strain over the run.
    pub e_flap: Vec<[f64; 3]>,
    /// D = E_Δ / (ρ² E_F + σ²).
    pub d: Vec<[f64; 3]>,
    /// Per node, the largest D of the three components.
    pub d_best: Vec<f64>,
    /// Per node, the index (0 ε_x, 1 ε_y, 2 γ_xy) of that component.
    pub best_component: Vec<usize>,
}

/// Symmetric Gram matrix Σ_s u_k(s) v_l(s) over the samples `idx` (modes × modes, row-major).
fn gram(u: &[Vec<f64>], v: &[Vec<f64>], idx: &[usize]) -> Vec<f64> {
    let m = u.len();
    let mut g = vec![0.0; m * m];
    for k in 0..m {
        for l in 0..m {
            g[k * m + l] = idx.iter().map(|&s| u[k][s] * v[l][s]).sum();
        }
    }
    g
}

fn quad(g: &[f64], e: &[f64], f: &[f64]) -> f64 {
    let m = e.len();
    let mut s = 0.0;
    for k in 0..m {
        for l in 0..m {
            s += e[k] * g[k * m + l] * f[l];
        }
    }
    s
}

fn check_signal(n_modes: usize, sig: &ModalSignal) -> Result<usize> {
    if sig.flap.len() != n_modes || sig.delta.len() != n_modes {
        return Err(WingbeatError::invalid(
            "signal",
            format!("{} / {} mode series", sig.flap.len(), sig.delta.len()),
            format!("one series per mode ({n_modes})"),
        ));
    }
    let n = sig.t.len();
    if n == 0 {
        return Err(WingbeatError::invalid(
            "signal.t",
            "0 samples",
            "at least 1 sample",
        ));
    }
    super::check_series(
        sig.flap.iter().chain(&sig.delta).map(Vec::as_slice),
        n,
        "signal.t",
        |k| format!("signal series {k}"),
    )?;
    Ok(n)
}

fn check_map_work(n_nodes: usize, n_modes: usize) -> Result<()> {
    let work = n_nodes as f64 * (n_modes * n_modes) as f64 * 9.0;
    if work > MAX_SENSING_MAP_WORK {
        return Err(WingbeatError::ResourceCap {
            field: "nodes × modes² × 9 (sensing map)".into(),
            requested: format!("{n_nodes} × {n_modes}² × 9 = {work:.3e}"),
            cap: format!("{MAX_SENSING_MAP_WORK:e}"),
            why: "every node's quadratic forms in the modal covariances; use fewer modes or a coarser mesh".into(),
        });
    }
    Ok(())
}

/// The decimation indices: every m-th sample, m = ⌈N / M⌉.
pub fn decimation(n: usize, samples_per_sensor: usize) -> Vec<usize> {
    let m = n.div_ceil(samples_per_sensor.max(1)).max(1);
    (0..n).step_by(m).collect()
}

/// The per-node detectability map D(x) = E_Δ / (ρ² E_F + σ²) of every node and component,
/// where `strain(mode, node)` is the nodal modal strain (e.g. `FemModes::strain_nodes`).
/// Mean squares are over all samples of the run. Work capped by [`MAX_SENSING_MAP_WORK`]
/// (checked before allocating).
pub fn detectability_map(
    n_nodes: usize,
    strain: impl Fn(usize, usize) -> [f64; 3],
    sig: &ModalSignal,
    opts: &SensingOptions,
) -> Result<DetectabilityMap> {
    opts.validate()?;
    let m = sig.flap.len();
    let n = check_signal(m, sig)?;
    check_map_work(n_nodes, m)?;
    let all: Vec<usize> = (0..n).collect();
    let gdd = gram(&sig.delta, &sig.delta, &all);
    let gff = gram(&sig.flap, &sig.flap, &all);
    let nf = n as f64;
    let (r2, s2) = (opts.rho * opts.rho, opts.noise * opts.noise);
    let mut out = DetectabilityMap {
        e_delta: Vec::with_capacity(n_nodes),
        e_flap: Vec::with_capacity(n_nodes),
        d: Vec::with_capacity(n_nodes),
        d_best: Vec::with_capacity(n_nodes),
        best_component: Vec::with_capacity(n_nodes),
    };
    let mut e = vec![0.0; m];
    for i in 0..n_nodes {
        let (mut ed, mut ef, mut d) = ([0.0; 3], [0.0; 3], [0.0; 3]);
        for c in 0..3 {
            for (k, ek) in e.iter_mut().enumerate() {
                *ek = strain(k, i)[c];
            }
            ed[c] = (quad(&gdd, &e, &e) / nf).max(0.0);
            ef[c] = (quad(&gff, &e, &e) / nf).max(0.0);
            d[c] = ed[c] / (r2 * ef[c] + s2);
        }
        let best = (0..3).fold(0, |b, c| if d[c] > d[b] { c } else { b });
        out.e_delta.push(ed);
        out.e_flap.push(ef);
        out.d.push(d);
        out.d_best.push(d[best]);
        out.best_component.push(best);
    }
    if let Some(i) = out.d_best.iter().position(|v| !v.is_finite()) {
        return Err(WingbeatError::NonFinite {
            what: format!("detectability at node {i}"),
            detail: "the strains or responses are too large to combine in f64".into(),
        });
    }
    Ok(out)
}

/// The detection index of a set of sensors from its sums A = ΔᵀΔ, B = FᵀΔ, G = FᵀF:
/// d'² = (A − ρ² B² / (σ² + ρ² G)) / σ² (Sherman–Morrison on C = ρ² F Fᵀ + σ² I).
pub fn d_prime_sq(a: f64, b: f64, g: f64, rho: f64, noise: f64) -> f64 {
    let (r2, s2) = (rho * rho, noise * noise);
    ((a - r2 * b * b / (s2 + r2 * g)) / s2).max(0.0)
}

/// Standard normal CDF Φ(x), from the complementary error function (relative error below
/// 1.2e-7, Numerical Recipes' Chebyshev fit of erfc).
pub fn normal_cdf(x: f64) -> f64 {
    0.5 * erfc(-x / std::f64::consts::SQRT_2)
}

fn erfc(x: f64) -> f64 {
    let z = x.abs();
    let t = 1.0 / (1.0 + 0.5 * z);
    let p = -z * z - 1.265_512_23
        + t * (1.000_023_68
            + t * (0.374_091_96
                + t * (0.096_784_18
                    + t * (-0.186_288_06
                        + t * (0.278_868_07
                            + t * (-1.135_203_98
                                + t * (1.488_515_87 + t * (-0.822_152_23 + t * 0.170_872_77))))))));
    let r = t * p.exp();
    if x >= 0.0 {
        r
    } else {
        2.0 - r
    }
}

/// Detection probability at false-alarm rate [`PFA`]: P_d = Φ(d' − z_(1−P_fa)).
pub fn detection_probability(d_prime: f64) -> f64 {
    normal_cdf(d_prime - Z_PFA)
}

/// One chosen sensor.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Sensor {
    /// Its rank (1 = chosen first).
    pub rank: usize,
    /// Node index.
    pub node: usize,
    /// Strain component: "eps_x", "eps_y" or "gamma_xy".
    pub component: String,
    /// Node position x (spanwise), mm.
    pub x_mm: f64,
    /// Node position y (chordwise), mm.
    pub y_mm: f64,
    /// The single-sensor detectability D of this node and component.
    pub d: f64,
}

/// Detection performance versus the number of sensors.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Placement {
    /// The chosen sensors, in order (k_max of them, or fewer when there are fewer candidates).
    pub sensors: Vec<Sensor>,
    /// d' with the first K sensors, K = 1 … (one per sensor).
    pub d_prime: Vec<f64>,
    /// P_d at P_fa = 1 % with the first K sensors.
    pub pd: Vec<f64>,
    /// Baseline for comparison: d' of the K candidates with the largest single-sensor d'
    /// (ranked alone, no greedy interaction), K = 1 … (as `d_prime`).
    pub d_prime_ranked: Vec<f64>,
    /// d' with every candidate (all nodes, all three components).
    pub d_prime_all: f64,
    /// P_d with every candidate.
    pub pd_all: f64,
    /// The smallest K whose d' reaches 90 % of `d_prime_all` (greedy order; may exceed
    /// k_max); `None` when the greedy continuation stopped at [`MAX_GREEDY_WORK`] first.
    pub k_for_90_percent: Option<usize>,
    /// Method text.
    pub method: String,
}

/// The decimated series of one sensor (node modal strains `e` per mode of one component):
/// (Δε(t_s), ε_F(t_s)) at the samples `idx`. The time-domain twin of the Gram sums the
/// placement uses (tests build the dense covariance from it).
pub fn sensor_series(e: &[f64], sig: &ModalSignal, idx: &[usize]) -> (Vec<f64>, Vec<f64>) {
    let comb = |qs: &[Vec<f64>]| {
        idx.iter()
            .map(|&s| e.iter().zip(qs).map(|(ek, q)| ek * q[s]).sum())
            .collect()
    };
    (comb(&sig.delta), comb(&sig.flap))
}

/// Greedy sparse sensor placement over every node and component of a mesh (`nodes` in m,
/// `strain(mode, node)` the nodal modal strains): the stacked detection vector of the run
/// decimated to `opts.samples_per_sensor` samples per sensor, the nuisance and noise model of
/// the module docs, greedy forward selection on d'². The greedy order is continued past
/// k_max (O(candidates) per step) until 90 % of the all-candidate d' is reached, to report
/// [`Placement::k_for_90_percent`]. Work capped as [`detectability_map`].
pub fn place_sensors(
    nodes: &[[f64; 3]],
    strain: impl Fn(usize, usize) -> [f64; 3],
    sig: &ModalSignal,
    opts: &SensingOptions,
) -> Result<Placement> {
    opts.validate()?;
    let m = sig.flap.len();
    let n = check_signal(m, sig)?;
    check_map_work(nodes.len(), m)?;
    let idx = decimation(n, opts.samples_per_sensor);
    let cand = candidates(nodes.len(), strain, sig, opts, &idx);
    let nc = cand.len();
    let dps = |a: f64, b: f64, g: f64| d_prime_sq(a, b, g, opts.rho, opts.noise);
    let (ta, tb, tg) = cand
        .iter()
        .fold((0.0, 0.0, 0.0), |s, c| (s.0 + c.0, s.1 + c.1, s.2 + c.2));
    let d_all = dps(ta, tb, tg).sqrt();
    if !d_all.is_finite() {
        return Err(WingbeatError::NonFinite {
            what: "all-sensor detection index".into(),
            detail: "the strains or responses are too large to combine in f64".into(),
        });
    }
    let mut used = vec![false; nc];
    let (mut sa, mut sb, mut sg) = (0.0, 0.0, 0.0);
    let mut sensors = Vec::new();
    let (mut d_prime, mut pd) = (Vec::new(), Vec::new());
    let mut k90 = None;
    let max_steps = ((MAX_GREEDY_WORK / nc.max(1) as f64) as usize).max(opts.k_max);
    for step in 0..nc.min(max_steps) {
        let mut best: Option<(usize, f64)> = None;
        for (j, c) in cand.iter().enumerate() {
            if used[j] {
                continue;
            }
            let v = dps(sa + c.0, sb + c.1, sg + c.2);
            if best.is_none_or(|(_, bv)| v > bv) {
                best = Some((j, v));
            }
        }
        let Some((j, v)) = best else { break };
        used[j] = true;
        sa += cand[j].0;
        sb += cand[j].1;
        sg += cand[j].2;
        let d = v.sqrt();
        if step < opts.k_max {
            let node = j / 3;
            sensors.push(Sensor {
                rank: step + 1,
                node,
                component: COMPONENTS[j % 3].into(),
                x_mm: nodes[node][0] * 1e3,
                y_mm: nodes[node][1] * 1e3,
                d: cand[j].3,
            });
            d_prime.push(d);
            pd.push(detection_probability(d));
        }
        if k90.is_none() && d >= 0.9 * d_all {
            k90 = Some(step + 1);
        }
        if step + 1 >= opts.k_max && k90.is_some() {
            break;
        }
    }
    let d_prime_ranked = ranked_baseline(&cand, sensors.len(), dps);
    Ok(Placement {
        sensors,
        d_prime,
        d_prime_ranked,
        pd,
        d_prime_all: d_all,
        pd_all: detection_probability(d_all),
        k_for_90_percent: k90,
        method: format!(
            "greedy forward selection on d'² = Δᵀ(ρ²FFᵀ + σ²I)⁻¹Δ (Sherman–Morrison), ρ = {}, σ = {}, {} samples per sensor (every {}th of {}), candidates: every node × ε_x, ε_y, γ_xy",
            opts.rho,
            opts.noise,
            idx.len(),
            n.div_ceil(opts.samples_per_sensor),
            n
        ),
    })
}

/// One candidate sensor's sums: Δᵀ Δ, Fᵀ Δ, Fᵀ F over the decimated samples (the terms of
/// d'²) and its single-sensor detectability D over the whole run.
type Candidate = (f64, f64, f64, f64);

/// The candidates of [`place_sensors`], node by node and component by component (index
/// 3 × node + component), from the Gram matrices of the modal series on the decimated
/// samples `idx` and on every sample.
fn candidates(
    n_nodes: usize,
    strain: impl Fn(usize, usize) -> [f64; 3],
    sig: &ModalSignal,
    opts: &SensingOptions,
    idx: &[usize],
) -> Vec<Candidate> {
    let m = sig.flap.len();
    let n = sig.t.len();
    let gdd = gram(&sig.delta, &sig.delta, idx);
    let gfd = gram(&sig.flap, &sig.delta, idx);
    let gff = gram(&sig.flap, &sig.flap, idx);
    let all: Vec<usize> = (0..n).collect();
    let mdd = gram(&sig.delta, &sig.delta, &all);
    let mff = gram(&sig.flap, &sig.flap, &all);
    let (r2, s2) = (opts.rho * opts.rho, opts.noise * opts.noise);
    let mut cand = Vec::with_capacity(n_nodes * 3);
    let mut e = vec![0.0; m];
    for i in 0..n_nodes {
        for c in 0..3 {
            for (k, ek) in e.iter_mut().enumerate() {
                *ek = strain(k, i)[c];
            }
            let a = quad(&gdd, &e, &e);
            let b = quad(&gfd, &e, &e);
            let g = quad(&gff, &e, &e);
            let d = (quad(&mdd, &e, &e) / n as f64) / (r2 * quad(&mff, &e, &e) / n as f64 + s2);
            cand.push((a, b, g, d));
        }
    }
    cand
}

/// The ranked baseline: d' of the best `count` single sensors taken together, best first
/// (ties by index), for K = 1 … `count`.
fn ranked_baseline(
    cand: &[Candidate],
    count: usize,
    dps: impl Fn(f64, f64, f64) -> f64,
) -> Vec<f64> {
    let mut order: Vec<usize> = (0..cand.len()).collect();
    let single: Vec<f64> = cand.iter().map(|c| dps(c.0, c.1, c.2)).collect();
    order.sort_by(|&i, &j| single[j].total_cmp(&single[i]).then(i.cmp(&j)));
    let (mut ra, mut rb, mut rg) = (0.0, 0.0, 0.0);
    order
        .iter()
        .take(count)
        .map(|&j| {
            ra += cand[j].0;
            rb += cand[j].1;
            rg += cand[j].2;
            dps(ra, rb, rg).sqrt()
        })
        .collect()
}

/// Δε(t) and the flapping strain at points given by their modal strains (`modal[p][k]` =
/// [ε_x, ε_y, γ_xy] of mode k at point p; e.g. from [`modal_strains_at`]), each labelled by
/// `names[p]`. Work (points × samples × modes) capped by [`MAX_SENSING_SERIES_WORK`], checked
/// before allocating.
pub fn delta_strain_series(
    names: &[String],
    modal: &[Vec<[f64; 3]>],
    sig: &ModalSignal,
) -> Result<Vec<(StrainSeries, StrainSeries)>> {
    let m = sig.flap.len();
    let n = check_signal(m, sig)?;
    check_series_size(modal.len(), n, m)?;
    let series = |name: &str, e: &[[f64; 3]], qs: &[Vec<f64>]| {
        let mut s = StrainSeries {
            point: name.to_string(),
            eps_x: vec![0.0; n],
            eps_y: vec![0.0; n],
            gamma_xy: vec![0.0; n],
        };
        for (ek, q) in e.iter().zip(qs) {
            for (i, qi) in q.iter().enumerate() {
                s.eps_x[i] += ek[0] * qi;
                s.eps_y[i] += ek[1] * qi;
                s.gamma_xy[i] += ek[2] * qi;
            }
        }
        s
    };
    Ok(names
        .iter()
        .zip(modal)
        .map(|(name, e)| (series(name, e, &sig.delta), series(name, e, &sig.flap)))
        .collect())
}

/// Modal strains at points (x, y) in mm on an FE mesh, through
/// [`modal_strains_at`] (the one strain lookup), naming the point `field` in errors.
pub fn modal_strains_at_points(
    fe: &crate::fem::FemModes,
    points_mm: &[(f64, f64)],
) -> Result<Vec<Vec<[f64; 3]>>> {
    let n_modes = fe.strain_nodes.len();
    points_mm
        .iter()
        .map(|&(x, y)| {
            modal_strains_at(
                &fe.nodes,
                &fe.triangles,
                n_modes,
                |k, i| fe.strain_nodes[k][i],
                x,
                y,
            )
        })
        .collect()
}

/// Everything the sensing analysis reports for an FE wing.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SensingResult {
    /// Body rate, rad/s (body axes).
    pub body_rate: [f64; 3],
    /// Options used.
    pub options: SensingOptions,
    /// The per-node detectability.
    pub map: DetectabilityMap,
    /// The chosen sensors and the performance curve.
    pub placement: Placement,
}

/// The whole sensing analysis of an FE wing under a modal signal whose modes are `fe`'s
/// (the detectability map and the sensor placement).
pub fn sense_fe(
    fe: &crate::fem::FemModes,
    sig: &ModalSignal,
    opts: &SensingOptions,
) -> Result<SensingResult> {
    if fe.strain_nodes.len() != sig.flap.len() {
        return Err(WingbeatError::invalid(
            "modes",
            format!("{} FE modes", fe.strain_nodes.len()),
            format!("the {} modes of the signal", sig.flap.len()),
        ));
    }
    let strain = |k: usize, i: usize| fe.strain_nodes[k][i];
    let map = detectability_map(fe.nodes.len(), strain, sig, opts)?;
    let placement = place_sensors(&fe.nodes, strain, sig, opts)?;
    Ok(SensingResult {
        body_rate: sig.body_rate,
        options: *opts,
        map,
        placement,
    })
}
