//! Measured kinematics from a CSV table: the roll α, pitch β and yaw γ sampled at times t
//! over one or more flap periods, turned into the core's periodic kinematics
//! ([`Kinematics`] with [`Angle::Sampled`] angles on a uniform grid over one period).
//!
//! One function, [`kinematics_from_csv`], serves the CLI (`wingbeat simulate
//! --kinematics-csv FILE --kinematics-units deg`) and the lab (wasm `kinematicsFromCsv`), so
//! both turn a file into the same [`Kinematics`].
//!
//! # The file
//!
//! A header row naming the columns, then one row per sample, comma-separated (fields may be
//! quoted; a leading byte-order mark is ignored); `#` lines and blank lines are skipped. Columns: `t` (s; also `t_s`, `time`, `time_s`) and any of `alpha`, `beta`,
//! `gamma` (a missing angle is 0), each optionally suffixed `_deg` or `_rad`, which must agree
//! with the units given. t increases strictly; the samples cover one or more whole flap
//! periods T = 1 / f_d (the last sample either one step before a period boundary or on it).
//!
//! # From samples to one period
//!
//! Each sample's time is folded onto one period, τ = t mod T (so the file's time axis is kept:
//! the periodic function passes near the sample at t, not at t − t₀).
//!
//! * **Grid**: when every folded time lies on the grid τ_j = j T / N (within 1 % of a step;
//!   N = T / median step) and every grid point has a sample, the angle is the grid of the
//!   per-point means over the periods, `Angle::Sampled { values, max_harmonic }`, exactly what
//!   a JSON config with those values means (trigonometric interpolation, see
//!   [`Angle::series`]).
//! * **Least squares** otherwise: a Fourier series of H harmonics (`max_harmonic`, default
//!   the fewer of ⌊(distinct times − 1) / 2⌋ and [`DEFAULT_LS_HARMONICS`]) is fitted to the
//!   folded samples by least squares and sampled at M = 2H + 1 (at least 3) uniform points
//!   with `max_harmonic = H`, which reproduces the fitted series exactly.

use crate::error::{Result, WingbeatError};
use crate::kinematics::{
    Angle, Kinematics, MAX_FLAP_HZ, MAX_HARMONIC, MAX_SAMPLES_PER_PERIOD, MIN_FLAP_HZ,
};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Most data rows accepted.
pub const MAX_ROWS: usize = 1_000_000;
/// Default harmonic count of the least-squares fit.
pub const DEFAULT_LS_HARMONICS: u32 = 32;
/// Most work of the least-squares fit, rows × (2H + 1)².
pub const MAX_LS_WORK: f64 = 2.0e8;

/// Units of the angle columns.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum AngleUnits {
    /// Degrees.
    Deg,
    /// Radians.
    Rad,
}

impl AngleUnits {
    /// Parses `deg` or `rad`; `field` names the input in the error.
    pub fn parse(field: &str, s: &str) -> Result<AngleUnits> {
        match s.trim().to_ascii_lowercase().as_str() {
            "deg" => Ok(AngleUnits::Deg),
            "rad" => Ok(AngleUnits::Rad),
            _ => Err(WingbeatError::invalid(field, s, "deg or rad")),
        }
    }

    fn suffix(self) -> &'static str {
        match self {
            AngleUnits::Deg => "deg",
            AngleUnits::Rad => "rad",
        }
    }
}

/// How to read the table.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CsvKinematicsOptions {
    /// Units of the angle columns.
    pub units: AngleUnits,
    /// Flap frequency f_d, Hz (the period the samples are folded onto).
    pub flap_hz: f64,
    /// Keep harmonics up to this number (a low-pass); default: all the grid resolves, or
    /// [`DEFAULT_LS_HARMONICS`] for the least-squares fit.
    #[serde(default)]
    pub max_harmonic: Option<u32>,
}

/// The file's samples folded onto one period, in file order: t in [0, T) s, angles in rad.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FoldedSamples {
    /// Folded times, s.
    pub t: Vec<f64>,
    /// Roll, rad (0 when the file has no `alpha` column).
    pub alpha: Vec<f64>,
    /// Pitch, rad.
    pub beta: Vec<f64>,
    /// Yaw, rad.
    pub gamma: Vec<f64>,
}

/// How the samples became one period.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TableMethod {
    /// Per-grid-point means of samples on a uniform grid aligned with t = 0 mod T.
    Grid,
    /// A least-squares Fourier fit, sampled on a uniform grid.
    LeastSquares,
}

/// A table turned into kinematics.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct KinematicsTable {
    /// The periodic kinematics (sampled angles on a uniform grid over one period).
    pub kinematics: Kinematics,
    /// The file's samples, folded.
    pub samples: FoldedSamples,
    /// Periods the file covers (a whole number unless a warning says otherwise).
    pub n_periods: f64,
    /// Grid or least squares.
    pub method: TableMethod,
    /// Points of the uniform grid over one period.
    pub grid_points: usize,
    /// Highest harmonic kept.
    pub max_harmonic: u32,
    /// What the user should know (seams, averaged periods, fit residuals, yaw range).
    pub warnings: Vec<String>,
}

const WHAT: &str = "kinematics CSV";

fn parse_err(msg: impl Into<String>) -> WingbeatError {
    WingbeatError::Parse {
        what: WHAT.into(),
        message: msg.into(),
    }
}

/// The column a header name stands for: 0 = t, 1..=3 = α, β, γ.
fn column_of(name: &str, units: AngleUnits) -> Result<usize> {
    let lower = name.trim().to_ascii_lowercase();
    if matches!(lower.as_str(), "t" | "t_s" | "time" | "time_s") {
        return Ok(0);
    }
    let (base, suffix) = match lower.rsplit_once('_') {
        Some((b, s @ ("deg" | "rad"))) => (b.to_string(), Some(s)),
        _ => (lower.clone(), None),
    };
    let idx = match base.as_str() {
        "alpha" => 1,
        "beta" => 2,
        "gamma" => 3,
        _ => {
            return Err(WingbeatError::invalid(
                format!("{WHAT} column `{}`", name.trim()),
                "unknown column",
                "t (s) and any of alpha, beta, gamma (optionally _deg or _rad)",
            ))
        }
    };
    if let Some(s) = suffix {
        if s != units.suffix() {
            return Err(WingbeatError::invalid(
                format!("{WHAT} column `{}`", name.trim()),
                format!("{s} column with units {}", units.suffix()),
                format!("columns in the units given ({})", units.suffix()),
            ));
        }
    }
    Ok(idx)
}

/// Times (s) and the three angles (rad; `None` = no column) as read so far.
type Table = (Vec<f64>, [Option<Vec<f64>>; 3]);

/// Reads the table: times (s) and the three angles (rad; `None` = no column).
fn read_table(text: &str, units: AngleUnits) -> Result<Table> {
    let mut cols: Option<Vec<usize>> = None;
    let mut t = Vec::new();
    let mut ang: [Option<Vec<f64>>; 3] = [None, None, None];
    // A spreadsheet's byte-order mark and quoted fields are tolerated.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    for (lineno, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let fields: Vec<&str> = line
            .split(',')
            .map(|f| f.trim().trim_matches('"').trim())
            .collect();
        let Some(c) = &cols else {
            let c = read_header(&fields, line, lineno, units)?;
            for &k in &c {
                if k > 0 {
                    ang[k - 1] = Some(Vec::new());
                }
            }
            cols = Some(c);
            continue;
        };
        if fields.len() != c.len() {
            return Err(parse_err(format!(
                "line {}: expected {} columns, got {}",
                lineno + 1,
                c.len(),
                fields.len()
            )));
        }
        if t.len() >= MAX_ROWS {
            return Err(WingbeatError::ResourceCap {
                field: WHAT.into(),
                requested: format!("more than {MAX_ROWS} rows"),
                cap: MAX_ROWS.to_string(),
                why: "the table is read whole".into(),
            });
        }
        for (f, &k) in fields.iter().zip(c) {
            read_value(f, k, lineno, units, &mut t, &mut ang)?;
        }
    }
    if cols.is_none() {
        return Err(parse_err(
            "no header row (expected e.g. `t,alpha,beta,gamma`)",
        ));
    }
    if t.len() < 3 {
        return Err(WingbeatError::invalid(
            WHAT,
            format!("{} rows", t.len()),
            format!("3 to {MAX_ROWS} rows of samples"),
        ));
    }
    Ok((t, ang))
}

/// The header row (`line`, its `fields`): the quantity of each column (0 = t, 1–3 = α, β, γ),
/// each named once, `t` and at least one angle among them.
fn read_header(
    fields: &[&str],
    line: &str,
    lineno: usize,
    units: AngleUnits,
) -> Result<Vec<usize>> {
    let mut c = Vec::with_capacity(fields.len());
    for f in fields {
        let k = column_of(f, units)?;
        if c.contains(&k) {
            return Err(parse_err(format!(
                "line {}: column `{f}` repeats a quantity already named",
                lineno + 1
            )));
        }
        c.push(k);
    }
    if !c.contains(&0) {
        return Err(WingbeatError::invalid(
            format!("{WHAT} header"),
            line,
            "a header naming `t` (s) and any of alpha, beta, gamma",
        ));
    }
    if c.len() < 2 {
        return Err(WingbeatError::invalid(
            format!("{WHAT} header"),
            line,
            "at least one angle column: alpha, beta or gamma",
        ));
    }
    Ok(c)
}

/// Parses one field `f` of quantity `k` on line `lineno` (0-based) and appends it: a time
/// after the previous one to `t`, or an angle within ±2π rad (converted from `units`) to its
/// column of `ang`.
fn read_value(
    f: &str,
    k: usize,
    lineno: usize,
    units: AngleUnits,
    t: &mut Vec<f64>,
    ang: &mut [Option<Vec<f64>>; 3],
) -> Result<()> {
    let scale = match units {
        AngleUnits::Deg => PI / 180.0,
        AngleUnits::Rad => 1.0,
    };
    let v: f64 = f
        .parse()
        .map_err(|e| parse_err(format!("line {}: `{f}` is not a number ({e})", lineno + 1)))?;
    if !v.is_finite() {
        return Err(parse_err(format!(
            "line {}: `{f}` is not a finite number",
            lineno + 1
        )));
    }
    if k == 0 {
        if let Some(&prev) = t.last() {
            if v <= prev {
                return Err(WingbeatError::invalid(
                    format!("{WHAT} line {} t", lineno + 1),
                    v,
                    format!("a time after the previous one ({prev} s): t increases strictly"),
                ));
            }
        }
        t.push(v);
    } else {
        let r = v * scale;
        if r.abs() > 2.0 * PI {
            return Err(WingbeatError::invalid(
                format!(
                    "{WHAT} line {} {}",
                    lineno + 1,
                    ["alpha", "beta", "gamma"][k - 1]
                ),
                format!("{v} {}", units.suffix()),
                "an angle within ±2π rad (±360°)",
            ));
        }
        if let Some(a) = ang[k - 1].as_mut() {
            a.push(r);
        }
    }
    Ok(())
}

fn median_step(t: &[f64]) -> f64 {
    let mut d: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
    d.sort_by(f64::total_cmp);
    d[d.len() / 2]
}

/// Least-squares Fourier fit of degree `h` to (τ, y) for several series at once; returns
/// per series [mean, s_1, c_1, …, s_h, c_h] (y ≈ mean + Σ s_n sin nθ + c_n cos nθ, θ = 2π τ / T).
fn ls_fit(tau: &[f64], period: f64, ys: &[&[f64]], h: usize) -> Result<Vec<Vec<f64>>> {
    let m = 2 * h + 1;
    let mut ata = nalgebra::DMatrix::<f64>::zeros(m, m);
    let mut aty = nalgebra::DMatrix::<f64>::zeros(m, ys.len());
    let mut row = vec![0.0; m];
    for (i, &tt) in tau.iter().enumerate() {
        let th = 2.0 * PI * tt / period;
        row[0] = 1.0;
        for n in 1..=h {
            let (s, c) = (n as f64 * th).sin_cos();
            row[2 * n - 1] = s;
            row[2 * n] = c;
        }
        for a in 0..m {
            for b in 0..=a {
                ata[(a, b)] += row[a] * row[b];
            }
            for (j, y) in ys.iter().enumerate() {
                aty[(a, j)] += row[a] * y[i];
            }
        }
    }
    for a in 0..m {
        for b in 0..a {
            ata[(b, a)] = ata[(a, b)];
        }
    }
    let ch = ata.cholesky().ok_or_else(|| {
        WingbeatError::invalid(
            "max_harmonic",
            h,
            "fewer harmonics: the folded samples leave gaps that do not determine this many",
        )
    })?;
    let x = ch.solve(&aty);
    Ok((0..ys.len())
        .map(|j| (0..m).map(|a| x[(a, j)]).collect())
        .collect())
}

fn eval_fit(coef: &[f64], th: f64) -> f64 {
    let h = (coef.len() - 1) / 2;
    let mut v = coef[0];
    for n in 1..=h {
        let (s, c) = (n as f64 * th).sin_cos();
        v += coef[2 * n - 1] * s + coef[2 * n] * c;
    }
    v
}

/// Turns a CSV table of measured angles into periodic kinematics at `opts.flap_hz` (see the
/// module documentation for the file and the method).
///
/// Errors name the field: `flap_hz`, `max_harmonic`, the units, an unknown or repeated column,
/// a bad number (with its line), a time that does not increase, an angle beyond ±2π rad,
/// fewer than 3 rows or less than one period, and the caps ([`MAX_ROWS`], the grid's
/// [`MAX_SAMPLES_PER_PERIOD`], [`MAX_LS_WORK`]).
pub fn kinematics_from_csv(text: &str, opts: &CsvKinematicsOptions) -> Result<KinematicsTable> {
    crate::error::check_range("flap_hz", opts.flap_hz, MIN_FLAP_HZ, MAX_FLAP_HZ, "Hz")?;
    if let Some(h) = opts.max_harmonic {
        if h > MAX_HARMONIC {
            return Err(WingbeatError::invalid(
                "max_harmonic",
                h,
                format!("an integer in [0, {MAX_HARMONIC}]"),
            ));
        }
    }
    let (t, ang) = read_table(text, opts.units)?;
    let n = t.len();
    let period = 1.0 / opts.flap_hz;
    let dt = median_step(&t);
    let mut warnings = Vec::new();
    let n_periods = whole_periods(&t, dt, opts.flap_hz, &mut warnings)?;
    let tau: Vec<f64> = t.iter().map(|x| x.rem_euclid(period)).collect();
    let zero = vec![0.0; n];
    let ys: Vec<&[f64]> = ang
        .iter()
        .map(|a| a.as_deref().unwrap_or(&zero[..]))
        .collect();
    let (method, grid_points, max_h, values) = match uniform_grid(&tau, period, dt) {
        Some(grid) => {
            let (h, values) = grid_means(&ys, &grid, n_periods, opts, &mut warnings);
            (TableMethod::Grid, grid.points, h, values)
        }
        None => {
            let (gn, h, values) = least_squares(&tau, period, &ys, opts, &mut warnings)?;
            (TableMethod::LeastSquares, gn, h, values)
        }
    };
    // On the grid without a requested cap the angle keeps `max_harmonic: None`, so the
    // default cap applies as for a config's table and the run's output warns about it
    // (`Kinematics::warnings`).
    let stored_h = match (method, opts.max_harmonic) {
        (TableMethod::Grid, None) => None,
        _ => Some(max_h),
    };
    let angle = |a: usize, values: &[f64]| -> Angle {
        if ang[a].is_some() {
            Angle::Sampled {
                values: values.to_vec(),
                max_harmonic: stored_h,
            }
        } else {
            Angle::constant(0.0)
        }
    };
    let kinematics = Kinematics {
        flap_freq_hz: opts.flap_hz,
        alpha: angle(0, &values[0]),
        beta: angle(1, &values[1]),
        gamma: angle(2, &values[2]),
        body_rate: Default::default(),
    };
    kinematics.validate()?;
    warnings.extend(kinematics.warnings());
    Ok(KinematicsTable {
        kinematics,
        samples: FoldedSamples {
            t: tau,
            alpha: ys[0].to_vec(),
            beta: ys[1].to_vec(),
            gamma: ys[2].to_vec(),
        },
        n_periods,
        method,
        grid_points,
        max_harmonic: max_h,
        warnings,
    })
}

/// The number of flap periods (1 / `flap_hz`) the times `t` (median step `dt`) cover: whole
/// when the file ends one step before a period boundary, or on it, to a quarter step;
/// otherwise fractional, with a warning about the seam. Fewer than one period, or a range or
/// step not finite in f64, is an error.
fn whole_periods(t: &[f64], dt: f64, flap_hz: f64, warnings: &mut Vec<String>) -> Result<f64> {
    let n = t.len();
    let period = 1.0 / flap_hz;
    let span = t[n - 1] - t[0];
    if !(span + dt).is_finite() || !(period / dt).is_finite() {
        return Err(WingbeatError::invalid(
            format!("{WHAT} t"),
            format!("from {} s to {} s", t[0], t[n - 1]),
            "times whose range and steps are finite in f64",
        ));
    }
    let k_open = ((span + dt) / period).round();
    let k_closed = (span / period).round();
    if k_open >= 1.0 && (span + dt - k_open * period).abs() <= 0.25 * dt {
        return Ok(k_open);
    }
    if k_closed >= 1.0 && (span - k_closed * period).abs() <= 0.25 * dt {
        return Ok(k_closed);
    }
    let p = (span + dt) / period;
    if p < 1.0 {
        return Err(WingbeatError::invalid(
            WHAT,
            format!("samples over {:.6} s ({p:.3} periods)", span + dt),
            format!("one or more whole flap periods (1 / f_d = {period:.6} s at {flap_hz} Hz)"),
        ));
    }
    warnings.push(format!(
        "the samples cover {p:.3} flap periods of {period:.6} s, not a whole number: \
         folding them onto one period leaves a seam (check the flap frequency, {flap_hz} Hz)"
    ));
    Ok(p)
}

/// Folded samples on a uniform grid of the period: each sample's grid point and the count of
/// samples at each point.
struct Grid {
    points: usize,
    index: Vec<usize>,
    count: Vec<usize>,
}

/// The uniform grid j T / N (N = T / `dt` rounded, 3 ..= [`MAX_SAMPLES_PER_PERIOD`]) when
/// every folded time `tau` lies on it (to 1 % of a step) and every grid point is sampled.
fn uniform_grid(tau: &[f64], period: f64, dt: f64) -> Option<Grid> {
    let grid_n = (period / dt).round();
    if !(grid_n >= 3.0 && grid_n <= MAX_SAMPLES_PER_PERIOD as f64) {
        return None;
    }
    let gn = grid_n as usize;
    let mut index = Vec::with_capacity(tau.len());
    for &x in tau {
        let f = x / period * grid_n;
        let j = f.round();
        if (f - j).abs() > 0.01 {
            return None;
        }
        index.push(j as usize % gn);
    }
    let mut count = vec![0usize; gn];
    index.iter().for_each(|&j| count[j] += 1);
    count.iter().all(|&c| c > 0).then_some(Grid {
        points: gn,
        index,
        count,
    })
}

/// Per-point means of the three series on the grid, with a warning giving the largest
/// deviation from them, and the harmonic cap: `opts.max_harmonic` or the sampled default,
/// never above N / 2.
fn grid_means(
    ys: &[&[f64]],
    grid: &Grid,
    n_periods: f64,
    opts: &CsvKinematicsOptions,
    warnings: &mut Vec<String>,
) -> (u32, Vec<Vec<f64>>) {
    let (gn, idx, count) = (grid.points, &grid.index, &grid.count);
    let mut values = vec![vec![0.0; gn]; 3];
    let mut dev: f64 = 0.0;
    for (a, y) in ys.iter().enumerate() {
        for (i, &j) in idx.iter().enumerate() {
            values[a][j] += y[i] / count[j] as f64;
        }
        for (i, &j) in idx.iter().enumerate() {
            dev = dev.max((y[i] - values[a][j]).abs());
        }
    }
    if dev > 0.0 {
        warnings.push(format!(
            "{n_periods} periods averaged point by point: a sample differs from its \
             period mean by up to {dev:.3e} rad ({:.3}°)",
            dev.to_degrees()
        ));
    }
    let all = (gn / 2) as u32;
    let h = opts.max_harmonic.map_or(
        all.min(crate::kinematics::DEFAULT_SAMPLED_MAX_HARMONIC),
        |m| m.min(all),
    );
    (h, values)
}

/// A least-squares Fourier fit of the three series at the folded times `tau`, evaluated on a
/// grid of 2h + 1 points (at least 3), with a warning giving the worst RMS residual. The
/// number of harmonics h is `opts.max_harmonic` (an error above what the distinct folded
/// times determine) or at most [`DEFAULT_LS_HARMONICS`]; the work is capped by
/// [`MAX_LS_WORK`]. Returns (grid points, h, values).
fn least_squares(
    tau: &[f64],
    period: f64,
    ys: &[&[f64]],
    opts: &CsvKinematicsOptions,
    warnings: &mut Vec<String>,
) -> Result<(usize, u32, Vec<Vec<f64>>)> {
    let n = tau.len();
    let mut sorted = tau.to_vec();
    sorted.sort_by(f64::total_cmp);
    let distinct = 1 + sorted
        .windows(2)
        .filter(|w| w[1] - w[0] > 1e-9 * period)
        .count();
    let most = ((distinct.saturating_sub(1)) / 2) as u32;
    let h = match opts.max_harmonic {
        Some(m) if m > most => {
            return Err(WingbeatError::invalid(
                "max_harmonic",
                m,
                format!(
                    "at most {most}: {distinct} distinct folded times determine at most \
                     (distinct − 1) / 2 harmonics"
                ),
            ))
        }
        Some(m) => m,
        None => most.min(DEFAULT_LS_HARMONICS),
    };
    let m = (2 * h + 1) as f64;
    if n as f64 * m * m > MAX_LS_WORK {
        return Err(WingbeatError::ResourceCap {
            field: "kinematics CSV rows × (2 max_harmonic + 1)²".into(),
            requested: format!("{n} × {m}²"),
            cap: format!("{MAX_LS_WORK:e}"),
            why: "the least-squares fit of samples off a uniform grid; use fewer \
                  harmonics, fewer rows or a grid with a whole number of samples per \
                  period"
                .into(),
        });
    }
    let coef = ls_fit(tau, period, ys, h as usize)?;
    let gn = (2 * h as usize + 1).max(3);
    let values: Vec<Vec<f64>> = coef
        .iter()
        .map(|c| {
            (0..gn)
                .map(|j| eval_fit(c, 2.0 * PI * j as f64 / gn as f64))
                .collect()
        })
        .collect();
    let mut worst: f64 = 0.0;
    for (c, y) in coef.iter().zip(ys) {
        let ss: f64 = tau
            .iter()
            .zip(y.iter())
            .map(|(x, v)| (v - eval_fit(c, 2.0 * PI * x / period)).powi(2))
            .sum();
        worst = worst.max((ss / n as f64).sqrt());
    }
    warnings.push(format!(
        "samples off a uniform grid aligned with t = 0 mod T: fitted by least squares \
         with {h} harmonics (RMS residual up to {worst:.3e} rad, {:.3}°)",
        worst.to_degrees()
    ));
    Ok((gn, h, values))
}
