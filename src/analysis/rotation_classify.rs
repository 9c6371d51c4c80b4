//! Telling body rotation from none through wing strain as the published sensing studies do
//! (Mohren et al. 2018, PNAS 115:10564; Weber et al. 2021, PLOS Comput. Biol. 17:e1009195;
//! docs/sensing.md, "Classifying rotation"): two non-periodic runs from rest, one without and
//! one with a body rotation, each under its own disturbance ([`crate::transient`]); the strain
//! at a grid of sensors; each sensor's strain encoded as a neuron would ([`super::neural`]); the
//! samples after a settling time split in time (the first part trains, the rest tests); a linear
//! discriminant ([`super::classify`]) on all sensors, on sparse sensors chosen by SSPOC
//! ([`super::sspoc`]), on random sensors and on greedy d′ sets; the same on the raw strain.

use nalgebra::DMatrix;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use super::classify::{Moments, ThresholdRule};
use super::neural::{self, Filter, Nonlinearity};
use super::sspoc::{sspoc_sweep_moments, SensorCount, SspocConfig};
use crate::disturbance::DisturbanceSpec;
use crate::kinematics::{Angle, Harmonic, Kinematics};
use crate::model::Mode;
use crate::transient::{self, BodyRateFrame, CompiledTransient, Disturbances, TransientKinematics};
use crate::{Result, WingbeatError};

/// One strain sensor: a point on the wing (mm, wingbeat's frame) and its strain per unit modal
/// coordinate of each mode (the strain component the sensor reads).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Sensor {
    /// Spanwise position x, mm.
    pub x_mm: f64,
    /// Chordwise position y, mm.
    pub y_mm: f64,
    /// Strain per unit q_k, one per mode.
    #[serde(skip)]
    pub per_mode: Vec<f64>,
}

/// What is classified: the wing's modes, the kinematics of the two classes, the sensors.
#[derive(Clone, Debug)]
pub struct ClassifyCase {
    /// The modes (with their damping).
    pub modes: Vec<Mode>,
    /// Class 0 (no rotation) and class 1 (rotation).
    pub classes: [TransientKinematics; 2],
    /// The sensors.
    pub sensors: Vec<Sensor>,
    /// A fluid the wing flaps in (its mesh and mode shapes for the loads, and the medium);
    /// `None`: a vacuum.
    pub air: Option<(crate::aero::WingGeometry, crate::aero::AeroConfig)>,
}

/// How the runs are sampled, encoded and classified.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ClassifyOptions {
    /// Length of each run from rest, s (published: 4).
    pub duration_s: f64,
    /// Sampling interval, s (published: 0.001).
    pub sample_step_s: f64,
    /// The settling time left out, s (published: 1).
    pub discard_s: f64,
    /// The encoder's temporal filter (published: the STA).
    pub filter: Filter,
    /// The encoder's nonlinearity (published: sigmoid, g = 10, θ = 0.5).
    pub nonlinearity: Nonlinearity,
    /// The strain normalisation s₀; `None`: the largest filtered strain over every sensor, sample
    /// and class (how the published constant was found).
    pub s0: Option<f64>,
    /// The fraction of each class's samples, from the start, that trains (published: 0.9).
    pub train_fraction: f64,
    /// Where the projected classes are split (published: the Gaussian crossing).
    pub threshold: ThresholdRule,
    /// SSPOC's r, the singular vectors kept (published: 30).
    pub rank: usize,
    /// SSPOC's α, the weight of ‖s‖₁ (published: 0.9).
    pub l1_weight: f64,
    /// The numbers of modes SSPOC's sensor weights are held to (published: 1 to 30); each gives
    /// its own sparse sensor set, its size set by the published cutoff.
    pub kept_modes: Vec<usize>,
    /// Sensor counts for random placement, and the sizes of the greedy d′ sets.
    pub random_counts: Vec<usize>,
    /// Random draws per count (published: 100).
    pub random_draws: usize,
    /// Seed of the random placements and the randomised SVD.
    pub seed: u64,
}

impl Default for ClassifyOptions {
    fn default() -> Self {
        ClassifyOptions {
            duration_s: 4.0,
            sample_step_s: 1e-3,
            discard_s: 1.0,
            filter: Filter::PUBLISHED,
            nonlinearity: Nonlinearity::Sigmoid {
                gain: 10.0,
                threshold: 0.5,
            },
            s0: None,
            train_fraction: 0.9,
            threshold: ThresholdRule::GaussianCrossing,
            rank: 30,
            l1_weight: 0.9,
            kept_modes: (1..=30).collect(),
            random_counts: (1..=30).collect(),
            random_draws: 100,
            seed: 1,
        }
    }
}

/// Most sensors.
pub const MAX_SENSORS: usize = 5000;
/// Most sensor-samples per class and representation (sensors × classified samples).
pub const MAX_SENSOR_SAMPLES: f64 = 2e7;
/// Most random draws per count.
pub const MAX_DRAWS: usize = 10_000;

/// Accuracy on the test samples of the SSPOC sensors for one number of kept modes.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SparsePoint {
    /// Modes the sensor weights were held to.
    pub kept_modes: usize,
    /// The sensors chosen (indices into the sensor list), strongest first.
    pub sensors: Vec<usize>,
    /// Test accuracy of the discriminant refitted on them.
    pub accuracy: f64,
}

/// Accuracy of random sensor sets of one size.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RandomPoint {
    /// Sensors per set.
    pub sensors: usize,
    /// Mean test accuracy over the draws.
    pub mean: f64,
    /// Its sample standard deviation.
    pub sd: f64,
    /// Draws whose training data had no separating direction (counted at 0.5).
    pub failed_fits: usize,
}

/// Accuracy of the greedy d′ set of one size: the first `sensors.len()` sensors of a greedy
/// forward selection by the training data's separation d′² (the classification's counterpart
/// of `wingbeat sense`'s greedy placement).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GreedyPoint {
    /// The sensors, in the order chosen.
    pub sensors: Vec<usize>,
    /// Their training separation d′ (square root of d′²).
    pub d_prime: f64,
    /// Test accuracy of the discriminant fitted on them.
    pub accuracy: f64,
}

/// The curves for one representation of the strain.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Curves {
    /// Test accuracy with every sensor.
    pub all_sensors: f64,
    /// SSPOC's sparse sets.
    pub sparse: Vec<SparsePoint>,
    /// Random sets.
    pub random: Vec<RandomPoint>,
    /// Greedy d′ sets, one per size of `random_counts`.
    pub greedy: Vec<GreedyPoint>,
    /// The normalisation s₀ used.
    pub s0: f64,
}

/// The result of [`classify`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ClassifyReport {
    /// The options used.
    pub options: ClassifyOptions,
    /// Samples per class that trained and tested.
    pub train_samples: usize,
    /// Samples per class that tested.
    pub test_samples: usize,
    /// Encoded strain (the options' filter and nonlinearity).
    pub encoded: Curves,
    /// Raw strain (identity filter and nonlinearity).
    pub raw: Curves,
    /// The sensors' positions, mm.
    pub sensors: Vec<[f64; 2]>,
    /// Gauss steps per sample of the runs.
    pub steps_per_sample: usize,
}

fn check(field: &str, ok: bool, v: impl std::fmt::Display, allowed: &str) -> Result<()> {
    if ok {
        Ok(())
    } else {
        Err(WingbeatError::invalid(
            format!("options.{field}"),
            v,
            allowed,
        ))
    }
}

impl ClassifyOptions {
    /// Checks every field against the case's sensor count; errors name `options.<field>`.
    pub fn validate(&self, sensors: usize) -> Result<()> {
        let d = self.duration_s;
        check(
            "duration_s",
            d.is_finite() && d > 0.0 && d <= 1e4,
            d,
            "above 0 s, at most 10000 s",
        )?;
        check(
            "sample_step_s",
            self.sample_step_s.is_finite() && self.sample_step_s > 0.0 && self.sample_step_s < d,
            self.sample_step_s,
            "above 0 s, below duration_s",
        )?;
        check(
            "rank",
            (1..=1000).contains(&self.rank),
            self.rank,
            "1 to 1000",
        )?;
        check(
            "l1_weight",
            self.l1_weight > 0.0 && self.l1_weight <= 1.0,
            self.l1_weight,
            "above 0, at most 1",
        )?;
        for (i, &k) in self.kept_modes.iter().enumerate() {
            check(
                &format!("kept_modes[{i}]"),
                (1..=self.rank).contains(&k),
                k,
                &format!("1 to rank ({})", self.rank),
            )?;
        }
        check(
            "discard_s",
            self.discard_s.is_finite() && self.discard_s >= 0.0 && self.discard_s < d,
            self.discard_s,
            "0 s or more, below duration_s",
        )?;
        check(
            "train_fraction",
            self.train_fraction > 0.0 && self.train_fraction < 1.0,
            self.train_fraction,
            "above 0 and below 1",
        )?;
        check(
            "random_draws",
            (1..=MAX_DRAWS).contains(&self.random_draws),
            self.random_draws,
            &format!("1 to {MAX_DRAWS}"),
        )?;
        for (i, &c) in self.random_counts.iter().enumerate() {
            check(
                &format!("random_counts[{i}]"),
                (1..=sensors).contains(&c),
                c,
                &format!("1 to {sensors} (the sensors there are)"),
            )?;
        }
        if let Some(s0) = self.s0 {
            check("s0", s0.is_finite() && s0 > 0.0, s0, "a positive strain")?;
        }
        neural::check_nonlinearity(&self.nonlinearity)
            .map_err(|e| rename(e, "nonlinearity", "options.nonlinearity"))?;
        neural::taps(&self.filter, self.sample_step_s * 1e3)
            .map_err(|e| rename(e, "filter", "options.filter"))?;
        Ok(())
    }
}

fn rename(e: WingbeatError, from: &str, to: &str) -> WingbeatError {
    e.map_field(|field| {
        if field.starts_with(from) {
            field.replacen(from, to, 1)
        } else {
            format!("{to} ({field})")
        }
    })
}

/// The two classes' sensor readings after encoding: rows are samples, columns sensors.
struct Encoded {
    classes: [DMatrix<f64>; 2],
    s0: f64,
}

/// Encodes each sensor's strain. The filter is linear, so it is applied to the modal
/// responses (a handful of series) and the filtered strain of every sensor is then their
/// combination, `filtered (samples × modes) · per_mode (modes × sensors)`: the same numbers as
/// filtering every sensor's strain, up to rounding, at a fraction of the work.
fn encode(
    modal: &[Vec<Vec<f64>>; 2],
    per_mode: &DMatrix<f64>,
    first: usize,
    taps: &[f64],
    nl: &Nonlinearity,
    s0: Option<f64>,
) -> Result<Encoded> {
    let l = taps.len();
    let start = first + 1 - l.min(first + 1);
    let filtered: Vec<DMatrix<f64>> = modal
        .iter()
        .map(|class| {
            let series: Vec<Vec<f64>> = class
                .iter()
                .map(|x| {
                    let mut f = neural::filter_valid(&x[start..], taps);
                    // Outputs stand for samples start + l − 1, …; keep those from `first` on.
                    let skip = (first + 1).saturating_sub(start + l);
                    f.drain(..skip.min(f.len()));
                    f
                })
                .collect();
            let rows = series.first().map_or(0, Vec::len);
            DMatrix::from_fn(rows, series.len(), |i, k| series[k][i]) * per_mode
        })
        .collect();
    let s0 = match s0 {
        Some(v) => v,
        None => neural::max_filtered(filtered.iter().map(DMatrix::as_slice))?,
    };
    let mut classes = filtered
        .into_iter()
        .map(|m| m.map(|v| neural::fire(v, s0, nl)));
    Ok(Encoded {
        classes: [classes.next().unwrap(), classes.next().unwrap()],
        s0,
    })
}

fn split(x: &DMatrix<f64>, n_train: usize) -> (DMatrix<f64>, DMatrix<f64>) {
    let n = x.nrows();
    (
        x.rows(0, n_train).into_owned(),
        x.rows(n_train, n - n_train).into_owned(),
    )
}

fn columns(x: &DMatrix<f64>, idx: &[usize]) -> DMatrix<f64> {
    DMatrix::from_fn(x.nrows(), idx.len(), |i, j| x[(i, idx[j])])
}

/// q distinct indices below p, uniformly: the first q steps of a Fisher–Yates shuffle.
fn draw(rng: &mut ChaCha8Rng, p: usize, q: usize) -> Vec<usize> {
    let mut all: Vec<usize> = (0..p).collect();
    for i in 0..q.min(p) {
        let j = rng.random_range(i..p);
        all.swap(i, j);
    }
    all.truncate(q);
    all
}

/// Test accuracy of a discriminant fitted, from the training moments, on the sensors `idx`
/// (all when `None`); `None` when no direction separates the training classes.
fn accuracy(
    moments: &Moments,
    test: &[DMatrix<f64>; 2],
    idx: Option<&[usize]>,
    rule: ThresholdRule,
) -> Option<f64> {
    let lda = moments.fit(idx, rule).ok()?;
    Some(match idx {
        Some(i) => lda.accuracy(&columns(&test[0], i), &columns(&test[1], i)),
        None => lda.accuracy(&test[0], &test[1]),
    })
}

fn curves(enc: Encoded, n_train: usize, opts: &ClassifyOptions) -> Result<Curves> {
    let (tr0, te0) = split(&enc.classes[0], n_train);
    let (tr1, te1) = split(&enc.classes[1], n_train);
    let train = [tr0, tr1];
    let test = [te0, te1];
    let rule = opts.threshold;
    // Every discriminant below (all sensors, SSPOC's sets, the random sets) is fitted from these.
    let moments = Moments::new(&train[0], &train[1])?;
    let all_sensors = accuracy(&moments, &test, None, rule).unwrap_or(0.5);
    let cfg = SspocConfig {
        rank: opts.rank,
        kept_modes: 1,
        l1_weight: opts.l1_weight,
        sensors: SensorCount::Cutoff,
        seed: opts.seed,
    };
    let sparse = sspoc_sweep_moments(&moments, &cfg, &opts.kept_modes)
        .map_err(|e| rename(e, "sspoc", "options"))?
        .into_iter()
        .zip(&opts.kept_modes)
        .map(|(s, &kept)| SparsePoint {
            kept_modes: kept,
            accuracy: accuracy(&moments, &test, Some(&s.sensors), rule).unwrap_or(0.5),
            sensors: s.sensors,
        })
        .collect();
    let p = train[0].ncols();
    let mut rng = ChaCha8Rng::seed_from_u64(opts.seed ^ 0x5eed_5e75);
    let random = opts
        .random_counts
        .iter()
        .map(|&q| {
            let mut failed = 0;
            let acc: Vec<f64> = (0..opts.random_draws)
                .map(|_| {
                    let idx = draw(&mut rng, p, q);
                    accuracy(&moments, &test, Some(&idx), rule).unwrap_or_else(|| {
                        failed += 1;
                        0.5
                    })
                })
                .collect();
            let n = acc.len() as f64;
            let mean = acc.iter().sum::<f64>() / n;
            let var = if acc.len() > 1 {
                acc.iter().map(|a| (a - mean) * (a - mean)).sum::<f64>() / (n - 1.0)
            } else {
                0.0
            };
            RandomPoint {
                sensors: q,
                mean,
                sd: var.sqrt(),
                failed_fits: failed,
            }
        })
        .collect();
    // Greedy d′: one forward selection up to the largest size, each size its prefix.
    let kmax = opts.random_counts.iter().copied().max().unwrap_or(0);
    let (order, gains) = moments.greedy(kmax);
    let greedy = opts
        .random_counts
        .iter()
        .filter(|&&k| k >= 1 && k <= order.len())
        .map(|&k| GreedyPoint {
            sensors: order[..k].to_vec(),
            d_prime: gains[k - 1].sqrt(),
            accuracy: accuracy(&moments, &test, Some(&order[..k]), rule).unwrap_or(0.5),
        })
        .collect();
    Ok(Curves {
        all_sensors,
        sparse,
        random,
        greedy,
        s0: enc.s0,
    })
}

/// Runs both classes, encodes the strain and classifies it (module docs). Every input is
/// checked, and the runs' and the data's sizes against their caps, before any work.
pub fn classify(case: &ClassifyCase, opts: &ClassifyOptions) -> Result<ClassifyReport> {
    classify_with_progress(case, opts, &mut |_, _| {})
}

/// Stages [`classify_with_progress`] reports: the two runs (reported together, `done` = 2, as
/// they run at once on a native target), the encoding, the encoded and the raw curves.
pub const CLASSIFY_STAGES: usize = 5;

/// [`classify`], calling `progress(done, CLASSIFY_STAGES)` after each stage.
pub fn classify_with_progress(
    case: &ClassifyCase,
    opts: &ClassifyOptions,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<ClassifyReport> {
    let ns = case.sensors.len();
    if ns == 0 || ns > MAX_SENSORS {
        return Err(WingbeatError::invalid(
            "sensors",
            ns,
            format!("1 to {MAX_SENSORS} sensors"),
        ));
    }
    for (i, s) in case.sensors.iter().enumerate() {
        if s.per_mode.len() != case.modes.len() || s.per_mode.iter().any(|v| !v.is_finite()) {
            return Err(WingbeatError::invalid(
                format!("sensors[{i}].per_mode"),
                format!("{} values", s.per_mode.len()),
                format!("{} finite strains, one per mode", case.modes.len()),
            ));
        }
    }
    opts.validate(ns)?;
    let compiled = [case.classes[0].compile()?, case.classes[1].compile()?];
    for k in &case.classes {
        k.validate()?;
    }
    let (n, steps) = transient::check_run_cost(
        &compiled[1],
        &case.modes,
        opts.duration_s,
        opts.sample_step_s,
    )?;
    // Samples at t < duration_s (published: 4000), of which those from discard_s on classify.
    let n = n - 1;
    let first = (opts.discard_s / opts.sample_step_s).round() as usize;
    let kept = n.saturating_sub(first);
    if (kept * ns) as f64 > MAX_SENSOR_SAMPLES {
        return Err(WingbeatError::ResourceCap {
            field: "sensors × classified samples".into(),
            requested: format!("{ns} × {kept}"),
            cap: format!("{MAX_SENSOR_SAMPLES:e}"),
            why: "memory for the encoded readings of both classes".into(),
        });
    }
    let n_train = ((kept as f64) * opts.train_fraction).round() as usize;
    if n_train < 2 || kept - n_train < 1 {
        return Err(WingbeatError::invalid(
            "options.train_fraction",
            opts.train_fraction,
            format!("a split leaving at least 2 training and 1 test samples of {kept}"),
        ));
    }
    // The two classes' runs share nothing: on a native target they run at once. Each keeps
    // every mode's total response, the first `n` samples.
    let class_run = |kin: &CompiledTransient| -> Result<Vec<Vec<f64>>> {
        let run = match &case.air {
            None => transient::run(kin, &case.modes, opts.duration_s, opts.sample_step_s)?,
            Some((geom, aero)) => crate::aero::transient::run_in_air(
                kin,
                &case.modes,
                geom,
                aero,
                opts.duration_s,
                opts.sample_step_s,
            )?,
        };
        Ok((0..case.modes.len())
            .map(|k| run.total(k)[..n].to_vec())
            .collect())
    };
    let (q0, q1) = crate::parallel::join(|| class_run(&compiled[0]), || class_run(&compiled[1]));
    let modal = [q0?, q1?];
    progress(2, CLASSIFY_STAGES);
    let per_mode = DMatrix::from_fn(case.modes.len(), ns, |k, s| case.sensors[s].per_mode[k]);
    let taps = neural::taps(&opts.filter, opts.sample_step_s * 1e3)?;
    let encoded = encode(&modal, &per_mode, first, &taps, &opts.nonlinearity, opts.s0)?;
    let identity = |s0| {
        encode(
            &modal,
            &per_mode,
            first,
            &[1.0],
            &Nonlinearity::Identity,
            s0,
        )
    };
    let raw = identity(None).or_else(|_| identity(Some(1.0)))?;
    progress(3, CLASSIFY_STAGES);
    let n_rows = encoded.classes[0].nrows();
    let n_train = n_train.min(n_rows - 1);
    // Encoded and raw curves are independent too.
    let (encoded, raw) = crate::parallel::join(
        || curves(encoded, n_train, opts),
        || curves(raw, n_train, opts),
    );
    let encoded = encoded?;
    progress(4, CLASSIFY_STAGES);
    let raw = raw?;
    progress(5, CLASSIFY_STAGES);
    Ok(ClassifyReport {
        options: opts.clone(),
        train_samples: n_train,
        test_samples: n_rows - n_train,
        encoded,
        raw,
        sensors: case.sensors.iter().map(|s| [s.x_mm, s.y_mm]).collect(),
        steps_per_sample: steps,
    })
}

/// Flapping of the published setup in wingbeat's angles: their flap φ about the plate's
/// chordwise axis is −β here, φ = 15°·[sin(2π·25 t) + 0.2 sin(2π·50 t)].
pub fn mohren2018_flapping() -> Kinematics {
    let deg = std::f64::consts::PI / 180.0;
    let h = |n, a: f64| Harmonic {
        n,
        amplitude: -a * deg,
        phase: 0.0,
    };
    Kinematics {
        flap_freq_hz: 25.0,
        alpha: Angle::constant(0.0),
        beta: Angle::Fourier {
            mean: 0.0,
            harmonics: vec![h(1, 15.0), h(2, 3.0)],
        },
        gamma: Angle::constant(0.0),
        body_rate: Default::default(),
    }
}

/// The published classes: from rest through the start-up ramp, class 0 without rotation,
/// class 1 at `rotation_rad_s` (published: 10) about the plate's normal, added in the plate's
/// frame; each class its own disturbances, `flap_dist` rad/s on the flapping (published 0.312)
/// and `rot_dist` rad/s on the rotation (published 0.1), seeded from `seed`.
pub fn mohren2018_classes(
    rotation_rad_s: f64,
    flap_dist: f64,
    rot_dist: f64,
    seed: u64,
) -> [TransientKinematics; 2] {
    let class = |c: u64, w: f64| TransientKinematics {
        flapping: mohren2018_flapping(),
        startup_ramp: true,
        body_rate_rad_s: [0.0, 0.0, w],
        body_rate_frame: BodyRateFrame::Wing,
        disturbances: Disturbances {
            beta: (flap_dist > 0.0)
                .then(|| DisturbanceSpec::published(flap_dist, seed.wrapping_mul(4) + 2 * c)),
            body_z: (rot_dist > 0.0)
                .then(|| DisturbanceSpec::published(rot_dist, seed.wrapping_mul(4) + 2 * c + 1)),
            ..Default::default()
        },
    };
    [class(0, 0.0), class(1, rotation_rad_s)]
}

/// The published sensor grid on the 50 × 25 mm plate: 26 chordwise × 51 spanwise points 1 mm
/// apart, edges included, ordered as published (chord index fastest, from the root row to the
/// tip). In wingbeat's frame x = 0 … 50 mm spanwise, y = 0 … −25 mm chordwise.
pub fn mohren2018_grid_mm() -> Vec<(f64, f64)> {
    mohren2018_grid_every(1)
}

/// Every `step`-th point of [`mohren2018_grid_mm`] along both axes (from the root and the
/// leading edge): 1 is the published grid, 2 a 2 mm grid of 26 × 13 points.
pub fn mohren2018_grid_every(step: usize) -> Vec<(f64, f64)> {
    let step = step.max(1);
    (0..51)
        .step_by(step)
        .flat_map(|s| (0..26).step_by(step).map(move |c| (s as f64, -(c as f64))))
        .collect()
}

/// Sensors at `points_mm` on an FE wing, each reading the spanwise normal strain ε_x of the top
/// surface (the published sensors' strain), from the modes' nodal strains.
pub fn spanwise_sensors(
    fe: &crate::fem::FemModes,
    points_mm: &[(f64, f64)],
) -> Result<Vec<Sensor>> {
    let strains = super::sensing::modal_strains_at_points(fe, points_mm)?;
    Ok(points_mm
        .iter()
        .zip(strains)
        .map(|(&(x, y), e)| Sensor {
            x_mm: x,
            y_mm: y,
            per_mode: e.iter().map(|v| v[0]).collect(),
        })
        .collect())
}

/// A case on an FE wing: its modes with the published damping ζ_k = 63/(2ω_k), the two classes,
/// and spanwise-strain sensors at `points_mm` (each must lie on the wing; errors name it).
pub fn fe_case(
    fe: &crate::fem::FemModes,
    classes: [TransientKinematics; 2],
    points_mm: &[(f64, f64)],
) -> Result<ClassifyCase> {
    let zetas = crate::presets::mohren2018_damping_ratios(&fe.freq_hz)?;
    let mut modes = fe.to_modes(0.0, &[]);
    for (m, z) in modes.iter_mut().zip(zetas) {
        m.zeta = z;
    }
    Ok(ClassifyCase {
        modes,
        classes,
        sensors: spanwise_sensors(fe, points_mm)?,
        air: None,
    })
}

/// `case` flapping in the fluid `aero` (density > 0; checked with the run) on the FE wing
/// `fe` it was built from: the loads of [`crate::aero`] from the wing's mesh and mode shapes.
pub fn in_fluid(
    mut case: ClassifyCase,
    fe: &crate::fem::FemModes,
    aero: crate::aero::AeroConfig,
) -> ClassifyCase {
    case.air = Some((crate::aero::WingGeometry::from_fem(fe), aero));
    case
}

/// The published setup on wingbeat's shell FE: the plate of [`crate::presets::mohren2018_plate_input`]
/// (`n_modes` modes, `mesh_size_mm` or automatic), its published damping ζ_k = 63/(2ω_k), the
/// classes of [`mohren2018_classes`] (10 rad/s; disturbances 0.312 and 0.1 rad/s) and the
/// sensors of [`mohren2018_grid_mm`]. Returns the case and the FE modes.
pub fn mohren2018_case(
    n_modes: usize,
    mesh_size_mm: Option<f64>,
    seed: u64,
) -> Result<(ClassifyCase, crate::fem::FemModes)> {
    let fe = crate::fem::compute_modes(&crate::presets::mohren2018_plate_input(
        mesh_size_mm,
        n_modes,
    ))?;
    let case = fe_case(
        &fe,
        mohren2018_classes(10.0, 0.312, 0.1, seed),
        &mohren2018_grid_mm(),
    )?;
    Ok((case, fe))
}
