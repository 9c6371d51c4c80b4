//! Non-periodic runs of Eq. 13: the flapping may start from rest through a start-up ramp, and
//! the body rate and the flapping angles may carry a non-periodic disturbance
//! ([`crate::disturbance`]). Nothing repeats, so there is no period map and no Floquet
//! analysis: each mode's equation is stepped directly from its initial state with the same
//! order-8 Gauss–Legendre step the periodic propagator uses ([`crate::solve::gauss`]), at the
//! same ω·h accuracy rule, and sampled on an output grid (docs/sensing.md, "Time-varying
//! rotation").
//!
//! The published sensing setup (Mohren et al. 2018, PNAS 115:10564; Weber et al. 2021) is one
//! such run: flapping φ = 15°·[sin(2π·25 t) + 0.2 sin(2π·50 t)]·σ(t) about the plate's
//! chordwise axis, a body rotation about the plate's normal whose angle is ω t σ(t), the ramp
//! σ(t) = (ω_d t)³ / (10 + (ω_d t)³), disturbances on both axes, 4 s from rest.
//!
//! The body rate is given either in body axes (turned into the wing frame by Rᵀ, as the
//! periodic runs do) or directly in wing-frame components, as the published model adds it.

use crate::disturbance::{Disturbance, DisturbanceSpec, Phasors};
use crate::kinematics::{Compiled, Kinematics, RateState};
use crate::model::{coefficients_of, Mode, Rotation};
use crate::solve::gauss::{step_map_from, Tableau, STAGES};
use crate::solve::propagator::omega_h_for;
use crate::solve::MAX_FORCES;
use crate::{Result, WingbeatError};
use serde::{Deserialize, Serialize};

/// In which components the body rate is given.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BodyRateFrame {
    /// Body axes I, J, K (the frame the roll and pitch are measured from); the wing feels Rᵀ ω_b.
    Body,
    /// The wing frame I″, J″, K″ itself: the rate is added to the wing's own angular velocity
    /// unchanged, as the published sensing model does.
    Wing,
}

/// Disturbances, each optional: on the three angles (their rates are disturbed, the angle is the
/// rate's integral from t = 0) and on the three body-rate components.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Disturbances {
    /// On the roll α.
    pub alpha: Option<DisturbanceSpec>,
    /// On the pitch β.
    pub beta: Option<DisturbanceSpec>,
    /// On the yaw γ.
    pub gamma: Option<DisturbanceSpec>,
    /// On the body rate's first component.
    pub body_x: Option<DisturbanceSpec>,
    /// On the body rate's second component.
    pub body_y: Option<DisturbanceSpec>,
    /// On the body rate's third component.
    pub body_z: Option<DisturbanceSpec>,
}

/// A non-periodic run's kinematics.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TransientKinematics {
    /// The periodic flapping α, β, γ (its `body_rate` must be zero; the body rate is below).
    pub flapping: Kinematics,
    /// Start from rest through σ(t) = (ω_d t)³ / (10 + (ω_d t)³) on the flapping angles and the
    /// body rotation angle (published; σ > 0.997 after 4 wingbeats).
    pub startup_ramp: bool,
    /// A constant body rate (rad/s), reached through the ramp when there is one.
    pub body_rate_rad_s: [f64; 3],
    /// The components the body rate (and its disturbances) are given in.
    pub body_rate_frame: BodyRateFrame,
    /// Non-periodic disturbances.
    #[serde(default)]
    pub disturbances: Disturbances,
}

/// Largest body rate, rad/s.
pub const MAX_BODY_RATE: f64 = 1e3;

impl TransientKinematics {
    /// Periodic flapping alone (no ramp, no body rate, no disturbance).
    pub fn periodic(flapping: Kinematics) -> Self {
        TransientKinematics {
            flapping,
            startup_ramp: false,
            body_rate_rad_s: [0.0; 3],
            body_rate_frame: BodyRateFrame::Body,
            disturbances: Disturbances::default(),
        }
    }

    /// Checks every field; errors name it (`kinematics.*`, `body_rate_rad_s[i]`,
    /// `disturbances.<axis>.*`).
    pub fn validate(&self) -> Result<()> {
        self.flapping.validate()?;
        if !self.flapping.body_rate.is_zero() {
            return Err(WingbeatError::invalid(
                "kinematics.body_rate",
                "a periodic body rate",
                "zero in a non-periodic run (give body_rate_rad_s and disturbances instead)",
            ));
        }
        for (i, w) in self.body_rate_rad_s.iter().enumerate() {
            if !(w.is_finite() && w.abs() <= MAX_BODY_RATE) {
                return Err(WingbeatError::invalid(
                    format!("body_rate_rad_s[{i}]"),
                    w,
                    format!("-{MAX_BODY_RATE} to {MAX_BODY_RATE} rad/s"),
                ));
            }
        }
        self.compile().map(|_| ())
    }

    /// Draws the disturbances and resolves the series (errors name the disturbance's axis).
    pub fn compile(&self) -> Result<CompiledTransient> {
        let d = &self.disturbances;
        let draw = |name: &str, s: &Option<DisturbanceSpec>| -> Result<Option<Disturbance>> {
            s.as_ref()
                .map(|spec| Disturbance::new(spec).map_err(|e| on_axis(e, name)))
                .transpose()
        };
        Ok(CompiledTransient {
            flapping: self.flapping.compile(),
            ramp: self.startup_ramp,
            body_rate: self.body_rate_rad_s,
            frame: self.body_rate_frame,
            angles: [
                draw("alpha", &d.alpha)?,
                draw("beta", &d.beta)?,
                draw("gamma", &d.gamma)?,
            ],
            body: [
                draw("body_x", &d.body_x)?,
                draw("body_y", &d.body_y)?,
                draw("body_z", &d.body_z)?,
            ],
        })
    }
}

/// A disturbance's error, its field (`disturbance.x`) renamed to the axis it is on
/// (`disturbances.beta.x`).
fn on_axis(e: WingbeatError, axis: &str) -> WingbeatError {
    e.map_field(|field| field.replacen("disturbance", &format!("disturbances.{axis}"), 1))
}

/// [`TransientKinematics`] resolved for evaluation.
#[derive(Clone, Debug)]
pub struct CompiledTransient {
    /// The periodic flapping.
    pub flapping: Compiled,
    /// Whether the start-up ramp applies.
    pub ramp: bool,
    /// The constant body rate, rad/s.
    pub body_rate: [f64; 3],
    /// Its frame.
    pub frame: BodyRateFrame,
    /// Drawn disturbances on α, β, γ.
    pub angles: [Option<Disturbance>; 3],
    /// Drawn disturbances on the body rate's components.
    pub body: [Option<Disturbance>; 3],
}

/// The disturbances' phasors at each Gauss stage time of a run's steps t0 + c_l h, stepped by h
/// from one step to the next ([`crate::disturbance::Phasors`]) and re-anchored to exact sines
/// every [`StageClock::ANCHOR_EVERY`] steps at most: the 15 sines a disturbance sums cost four
/// multiplications each per stage instead of a sine and a cosine.
#[derive(Clone, Debug)]
pub struct StageClock {
    /// Per stage, per axis (α, β, γ, body x, y, z): the phasors of that axis's disturbance.
    stages: Vec<[Option<Phasors>; 6]>,
}

impl StageClock {
    /// Most steps between exact re-anchorings (each step rounds the phasors by about 2ε).
    pub const ANCHOR_EVERY: usize = 64;

    /// The clock at the stage times `t0 + c_l h` of `kin`'s disturbances, stepping by `h`.
    pub fn new(kin: &CompiledTransient, c: &[f64], t0: f64, h: f64) -> Self {
        StageClock {
            stages: c
                .iter()
                .map(|cl| {
                    let mut it = kin.disturbances();
                    std::array::from_fn(|_| {
                        it.next()
                            .and_then(|d| d.as_ref())
                            .map(|d| d.phasors(t0 + cl * h, h))
                    })
                })
                .collect(),
        }
    }

    /// Moves every stage on by one step.
    pub fn advance(&mut self) {
        self.stages
            .iter_mut()
            .flatten()
            .flatten()
            .for_each(Phasors::advance);
    }

    /// Sets every stage to the exact values at `t0 + c_l h`.
    pub fn anchor(&mut self, kin: &CompiledTransient, c: &[f64], t0: f64, h: f64) {
        for (stage, cl) in self.stages.iter_mut().zip(c) {
            for (ph, d) in stage.iter_mut().zip(kin.disturbances()) {
                if let (Some(ph), Some(d)) = (ph, d) {
                    d.anchor(ph, t0 + cl * h);
                }
            }
        }
    }
}

/// The start-up ramp σ(t) = u³ / (10 + u³), u = ω_d t, and its first two time derivatives.
pub fn startup_ramp(t: f64, wd: f64) -> (f64, f64, f64) {
    if t <= 0.0 {
        return (0.0, 0.0, 0.0);
    }
    let u = wd * t;
    let u3 = u * u * u;
    let den = 10.0 + u3;
    let s = u3 / den;
    // dσ/du = 30 u² / den², d²σ/du² = 60 u (10 − 2 u³) / den³.
    let ds = 30.0 * u * u / (den * den);
    let dds = 60.0 * u * (10.0 - 2.0 * u3) / (den * den * den);
    (s, ds * wd, dds * wd * wd)
}

/// R v: a wing-frame vector in body axes, R = R_x(α)·R_y(β) (the inverse of
/// [`RateState::to_wing_frame`]).
pub fn to_body_frame(alpha: f64, beta: f64, v: [f64; 3]) -> [f64; 3] {
    let (sa, ca) = alpha.sin_cos();
    let (sb, cb) = beta.sin_cos();
    let u = [cb * v[0] + sb * v[2], v[1], -sb * v[0] + cb * v[2]];
    [u[0], ca * u[1] - sa * u[2], sa * u[1] + ca * u[2]]
}

impl CompiledTransient {
    /// Angles, rates and body rate at time t (s). The body rate in the returned state is always
    /// in body axes; a wing-frame rate v is stored as R v with derivative R (Ω_wing × v + v̇), so
    /// that the wing frame turns with exactly Ω_wing + v.
    pub fn state(&self, t: f64) -> RateState {
        self.state_from(t, |_, d| d.eval(t))
    }

    /// [`CompiledTransient::state`] reading the stage `stage` of `clock` for the disturbances
    /// (their sines stepped, not computed); within a few ε of `state(t)` when the clock is at t.
    pub fn state_clocked(&self, t: f64, clock: &StageClock, stage: usize) -> RateState {
        self.state_from(t, |axis, d| match &clock.stages[stage][axis] {
            Some(ph) => d.eval_phasors(t, ph),
            None => d.eval(t),
        })
    }

    /// The disturbances in axis order (α, β, γ, then the body rate's x, y, z).
    fn disturbances(&self) -> impl Iterator<Item = &Option<Disturbance>> {
        self.angles.iter().chain(&self.body)
    }

    /// The state at t with each disturbance's (angle, rate, rate_dot) from `dist(axis, d)`.
    fn state_from(
        &self,
        t: f64,
        dist: impl Fn(usize, &Disturbance) -> (f64, f64, f64),
    ) -> RateState {
        let mut s = self.flapping.state(t);
        let (sig, dsig, ddsig) = if self.ramp {
            startup_ramp(t, self.flapping.wd)
        } else {
            (1.0, 0.0, 0.0)
        };
        let angles = [
            (&mut s.alpha, &mut s.alpha_dot, &mut s.alpha_ddot),
            (&mut s.beta, &mut s.beta_dot, &mut s.beta_ddot),
            (&mut s.gamma, &mut s.gamma_dot, &mut s.gamma_ddot),
        ];
        for (axis, ((a, ad, add), disturbance)) in angles.into_iter().zip(&self.angles).enumerate()
        {
            let (v, d, dd) = (*a, *ad, *add);
            *a = v * sig;
            *ad = d * sig + v * dsig;
            *add = dd * sig + 2.0 * d * dsig + v * ddsig;
            if let Some(x) = disturbance {
                let (angle, rate, rate_dot) = dist(axis, x);
                *a += angle;
                *ad += rate;
                *add += rate_dot;
            }
        }
        // The body rotation angle is w t σ(t): its rate w (σ + t σ′), and that rate's derivative
        // w (2 σ′ + t σ″).
        let (f, fd) = if self.ramp {
            (sig + t * dsig, 2.0 * dsig + t * ddsig)
        } else {
            (1.0, 0.0)
        };
        let mut v = [0.0; 3];
        let mut vd = [0.0; 3];
        for i in 0..3 {
            v[i] = self.body_rate[i] * f;
            vd[i] = self.body_rate[i] * fd;
            if let Some(x) = &self.body[i] {
                let (_, rate, rate_dot) = dist(3 + i, x);
                v[i] += rate;
                vd[i] += rate_dot;
            }
        }
        match self.frame {
            BodyRateFrame::Body => {
                s.body_rate = v;
                s.body_rate_dot = vd;
            }
            BodyRateFrame::Wing => {
                let (sb, cb) = s.beta.sin_cos();
                let w = [s.alpha_dot * cb, s.beta_dot, s.alpha_dot * sb];
                let wxv = [
                    w[1] * v[2] - w[2] * v[1],
                    w[2] * v[0] - w[0] * v[2],
                    w[0] * v[1] - w[1] * v[0],
                ];
                let rhs = [wxv[0] + vd[0], wxv[1] + vd[1], wxv[2] + vd[2]];
                s.body_rate = to_body_frame(s.alpha, s.beta, v);
                s.body_rate_dot = to_body_frame(s.alpha, s.beta, rhs);
            }
        }
        s
    }

    /// The highest angular frequency (rad/s) the kinematics' forcing carries to relevant accuracy:
    /// products of up to three series, so 4× the highest flapping harmonic or disturbance.
    pub fn freq_scale(&self) -> f64 {
        let f = &self.flapping;
        let harmonic = [&f.alpha, &f.beta, &f.gamma]
            .into_iter()
            .flat_map(|s| s.terms.iter().map(|t| t.n))
            .fold(1.0_f64, f64::max)
            * f.wd;
        let dist = self
            .angles
            .iter()
            .chain(&self.body)
            .flatten()
            .flat_map(|d| d.freqs_hz.iter())
            .fold(0.0_f64, |m, &x| m.max(std::f64::consts::TAU * x));
        4.0 * harmonic.max(dist)
    }
}

/// The output of a non-periodic run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TransientRun {
    /// Output times, s (0, dt, 2 dt, …).
    pub t: Vec<f64>,
    /// Per mode, per forcing column `[euler, centrifugal, coriolis, total]`, the response q (kg^½·m).
    pub q: Vec<[Vec<f64>; MAX_FORCES]>,
    /// Gauss steps per output interval.
    pub steps_per_sample: usize,
    /// In a fluid ([`crate::aero::transient::run_in_air`]): per mode, the response to the
    /// aerodynamic force alone (kg^½·m); empty in a vacuum.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub aerodynamic: Vec<Vec<f64>>,
}

impl TransientRun {
    /// The total response of mode k.
    pub fn total(&self, k: usize) -> &[f64] {
        &self.q[k][3]
    }
}

/// Most output samples of one run.
pub const MAX_SAMPLES: usize = 10_000_000;
/// Most Gauss steps of one run, summed over modes.
pub const MAX_STEPS: f64 = 5e8;

/// Gauss steps per output interval `dt` for the largest angular frequency `w`, the error target
/// of [`omega_h_for`] holding over each `span` (the runs use one flap period, as the periodic
/// path does).
pub fn steps_per_sample(w: f64, dt: f64, span: f64) -> usize {
    let w = w.max(1e-300);
    let h = omega_h_for(w, span) / w;
    ((dt / h).ceil() as usize).max(1)
}

/// Checks a run's size before it starts: samples ≤ [`MAX_SAMPLES`], Gauss steps ≤ [`MAX_STEPS`].
pub fn check_run_cost(
    kin: &CompiledTransient,
    modes: &[Mode],
    duration_s: f64,
    dt_s: f64,
) -> Result<(usize, usize)> {
    if !(duration_s.is_finite() && duration_s > 0.0 && duration_s <= 1e4) {
        return Err(WingbeatError::invalid(
            "duration_s",
            duration_s,
            "above 0 and at most 10000 s",
        ));
    }
    if !(dt_s.is_finite() && dt_s > 0.0 && dt_s <= duration_s) {
        return Err(WingbeatError::invalid(
            "sample_step_s",
            dt_s,
            "above 0 and at most the duration",
        ));
    }
    let n = (duration_s / dt_s).round() as usize + 1;
    if n > MAX_SAMPLES {
        return Err(WingbeatError::ResourceCap {
            field: "duration_s / sample_step_s".into(),
            requested: format!("{n} samples"),
            cap: format!("{MAX_SAMPLES} samples"),
            why: "memory for the sampled responses".into(),
        });
    }
    let w = modes
        .iter()
        .map(|m| m.omega().max(2.0 * m.zeta * m.omega()))
        .fold(kin.freq_scale(), f64::max);
    // The periodic path's accuracy rule: its error target holds per flap period.
    let period = std::f64::consts::TAU / kin.flapping.wd;
    let m = steps_per_sample(w, dt_s, period.min(duration_s));
    let steps = (n - 1) as f64 * m as f64 * modes.len() as f64;
    if steps > MAX_STEPS {
        return Err(WingbeatError::ResourceCap {
            field: "duration_s".into(),
            requested: format!("{steps:.3e} Gauss steps over all modes"),
            cap: format!("{MAX_STEPS:e} steps"),
            why: "run time; shorten the run or use fewer, lower modes".into(),
        });
    }
    Ok((n, m))
}

/// At least one mode, each valid (errors name `modes` or the mode).
pub fn check_modes(modes: &[Mode]) -> Result<()> {
    if modes.is_empty() {
        return Err(WingbeatError::invalid("modes", 0, "at least one mode"));
    }
    for (i, m) in modes.iter().enumerate() {
        m.validate(i)?;
    }
    Ok(())
}

/// Steps every mode of Eq. 13 from rest (q = q̇ = 0 at t = 0) over `duration_s`, sampling every
/// `dt_s`. The kinematics are evaluated once per stage time and shared by all modes.
pub fn run(
    kin: &CompiledTransient,
    modes: &[Mode],
    duration_s: f64,
    dt_s: f64,
) -> Result<TransientRun> {
    check_modes(modes)?;
    let (n, m) = check_run_cost(kin, modes, duration_s, dt_s)?;
    let h = dt_s / m as f64;
    let tab = Tableau::new();
    let nm = modes.len();
    let mut x = vec![[[0.0_f64; 2]; MAX_FORCES]; nm];
    let mut q: Vec<[Vec<f64>; MAX_FORCES]> = (0..nm)
        .map(|_| std::array::from_fn(|_| Vec::with_capacity(n)))
        .collect();
    let damping: Vec<f64> = modes.iter().map(|md| 2.0 * md.zeta * md.omega()).collect();
    // The rotation at each stage time, worked out once for all modes (the same bits as per mode).
    let mut rotations = [Rotation::default(); STAGES];
    let mut clock = StageClock::new(kin, &tab.c, 0.0, h);
    let mut since_anchor = 0;
    for i in 0..n {
        for k in 0..nm {
            for j in 0..MAX_FORCES {
                q[k][j].push(x[k][j][0]);
            }
        }
        if i + 1 == n {
            break;
        }
        for s in 0..m {
            let t0 = i as f64 * dt_s + s as f64 * h;
            // Exact at each sample's first step (and at least every ANCHOR_EVERY steps), stepped
            // in between.
            if s == 0 || since_anchor >= StageClock::ANCHOR_EVERY {
                clock.anchor(kin, &tab.c, t0, h);
                since_anchor = 0;
            }
            for (l, (rot, c)) in rotations.iter_mut().zip(tab.c).enumerate() {
                *rot = Rotation::of(&kin.state_clocked(t0 + c * h, &clock, l));
            }
            clock.advance();
            since_anchor += 1;
            for k in 0..nm {
                let mut ks = [0.0; STAGES];
                let mut fs = [[0.0; MAX_FORCES]; STAGES];
                for (l, rot) in rotations.iter().enumerate() {
                    let c = coefficients_of(&modes[k], rot);
                    ks[l] = c.stiffness;
                    fs[l] = [c.euler, c.centrifugal, c.coriolis, c.total_force()];
                }
                let map = step_map_from(&tab, damping[k], h, &ks, &fs, MAX_FORCES);
                for j in 0..MAX_FORCES {
                    let [q0, v0] = x[k][j];
                    let r = map.r;
                    x[k][j] = [
                        r[(0, 0)] * q0 + r[(0, 1)] * v0 + map.p[j][0],
                        r[(1, 0)] * q0 + r[(1, 1)] * v0 + map.p[j][1],
                    ];
                }
            }
        }
    }
    Ok(TransientRun {
        t: (0..n).map(|i| i as f64 * dt_s).collect(),
        q,
        steps_per_sample: m,
        aerodynamic: Vec::new(),
    })
}
