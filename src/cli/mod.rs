//! Argument parsing and the subcommands of the `wingbeat` binary.

mod args;
mod classify;
mod modes;
#[cfg(feature = "render")]
mod render;
mod sense;

// The shared flags and helpers, also for the subcommand modules (`super::build_config`, …).
pub(crate) use args::{apply_air_density, build_config, read_file, to_json, Format, SimInput};
use clap::{Args, Parser, Subcommand, ValueEnum};
use serde_json::json;
use wingbeat::analysis::ic_map::{ic_map, IcAttribution, IcMapOptions};
use wingbeat::analysis::psd::{welch, Detrend, WelchOptions};
use wingbeat::analysis::spectra::mode_spectra;
use wingbeat::analysis::sweep::{sweep, SweepOptions, SweepParam};
use wingbeat::config::SimConfig;
use wingbeat::simulate::{force_series, simulate, simulate_reusing, SimResult};
use wingbeat::{Result, WingbeatError};

#[derive(Parser, Debug)]
#[command(
    name = "wingbeat",
    version,
    about = "Inertial-elastic dynamics of a flapping insect wing (Jankauski & Shen, Eq. 13)",
    long_about = "wingbeat solves the modal equation of a flapping wing,\n\n  q̈ + 2ζω q̇ + [ω² − (α̇² cos²β + β̇²)] q = F_Euler + F_centrifugal + F_Coriolis,\n\nfor each mode, separately per force term, and analyses the result: Floquet effective\nfrequency and beat period, spectra, force contributions, sweeps, initial-condition maps and\nstrain. With no config, every command uses the paper's forward-flight case (α0 = 0.8,\nβ0 = 0.5, γ0 = 0.2 rad at 25 Hz; modes at 62.5 and 86.9 Hz from Tables 3–6).\n\nExamples:\n  wingbeat simulate --preset paper > paper.json\n  wingbeat simulate --gamma0 0.1 --zeta 0.01 --duration 5 --format csv > run.csv\n  wingbeat psd --detrend none\n  wingbeat sweep gamma0 --from 0 --to 0.3 --points 31\n  wingbeat sweep ic --mode 0 --n 101\n  wingbeat reproduce"
)]
struct Cli {
    #[command(subcommand)]
    cmd: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Solve Eq. 13: partial and total responses, contributions, Floquet summary, strain.
    ///
    /// Per mode, `q` holds the response to each force term alone from rest (`euler`,
    /// `centrifugal`, `coriolis`), the free vibration started by the initial conditions alone
    /// (`free`) and the `total` (the sum of all four, to rounding).
    ///
    /// Contributions (`contribution_percent`, paper §4.1): the share of a term is
    /// 100 · Σ_i q_term(t_i)² / Σ_i q_total(t_i)² over the output samples. The denominator is
    /// the total response, so it includes the free vibration from nonzero initial conditions
    /// (--q0/--qdot0), which belongs to no force term: it lowers all three shares. The shares
    /// need not add to 100 % (Σ q_total² has cross terms of either sign); all three are 0 when
    /// the total is identically zero.
    ///
    /// When a summary is null (JSON has no NaN, so NaN is written as null):
    /// `floquet.beat_period_s` is null when the effective frequency coincides with the
    /// nearest flap harmonic n_b·f_d (|f_eff − n_b f_d| ≤ 1e-9 · max(f_eff, 1 Hz): no beat),
    /// and for an unstable mode (`floquet.stable` false, a multiplier with |λ| > 1: the
    /// response grows instead of beating); `floquet.beat_period_vs_2fd_s` likewise against 2 f_d; `floquet.averaged_freq_hz` is
    /// null when ω² minus the mean stiffness coefficient is not positive (no real naive
    /// estimate). `strain` is absent when no mode carries modal strains, and `strain_points`
    /// unless more than one point is named.
    Simulate(SimulateArgs),
    /// Welch PSD, per mode, of each force term, the stiffness coefficient, the stiffness force
    /// and the total response.
    ///
    /// Keys per mode: `euler`, `centrifugal`, `coriolis` (the Eq. 13 force terms);
    /// `stiffness_coefficient`, the spectrum of S(t) = α̇² cos²β + β̇² (1/s², the same for
    /// every mode); `stiffness_force`, the spectrum of S(t)·q_k(t) (the stiffness term of
    /// Eq. 13 written as a force, same units as the force terms); `response_total`, q_k(t).
    Psd(PsdArgs),
    /// Parameter sweeps: `gamma0` (Fig. 6) or any of alpha0, beta0, flap_hz, zeta; `ic` (Fig. 7).
    ///
    /// Each point reports, per mode, the contributions (as in `simulate`: the denominator is
    /// the total response, including free vibration from nonzero initial conditions), the
    /// Floquet effective frequency, the beat period and the peak |q_total|. `beat_period_s` is
    /// null (empty in CSV) when the effective frequency coincides with the nearest flap
    /// harmonic or the mode is unstable (see `simulate --help`).
    Sweep(SweepArgs),
    /// Every claim of the paper's §3–4: what it says, what wingbeat computes, whether it holds.
    Reproduce(ReproduceArgs),
    /// Shell FE modes of a planform with camber: frequencies, a_k/b_k (SI), shapes, strains.
    Modes(modes::ModesArgs),
    /// Sensing body rotation through wing strain: the rotation-induced strain Δε, a
    /// detectability map over every FE node, greedy sparse sensor placement and detection
    /// performance vs the number of sensors (docs/sensing.md).
    ///
    /// Two runs, with and without a constant body rate --body-rate X,Y,Z (rad/s, body axes;
    /// default 0,0,1, i.e. 1 rad/s about the yaw axis; a config's `body_rate` is replaced):
    /// their difference is the rotation signal. Needs an FE wing for the map and the sensors
    /// (`--preset fe-wing`, or `--modes FILE` written by `wingbeat modes`); with the paper
    /// table's modes only Δq and Δε at the named points are reported. The per-node
    /// detectability is D = E_Δ / (ρ² E_flap + σ²) (mean squares over the run; ρ = --rho, the
    /// relative stroke variability; σ = --noise, the sensor noise); the sensors are chosen
    /// greedily to maximise d'² = Δᵀ(ρ²FFᵀ + σ²I)⁻¹Δ, and P_d is at a 1 % false-alarm rate.
    ///
    /// Examples:
    ///   wingbeat sense --preset fe-wing --body-rate 0,0,1 > sense.json
    ///   wingbeat sense --preset fe-wing --format csv --table curve
    Sense(sense::SenseArgs),
    /// Rotation or none, told from wing strain as the published sensing studies do (Mohren et
    /// al. 2018): two non-periodic runs from rest (with and without a body rotation about the
    /// plate's normal, each under its own seeded disturbance), the spanwise strain at a sensor
    /// grid, neuron-like encoding (an STA filter and a sigmoid), and a linear discriminant on
    /// all sensors, on sparse sensors chosen by SSPOC and on random sets; the same on raw
    /// strain (docs/sensing.md, "Classifying rotation").
    ///
    /// Examples:
    ///   wingbeat classify --preset mohren2018 > classify.json
    ///   wingbeat classify --kept-modes 5,10,20 --counts 1-30 --draws 100 --format csv
    Classify(classify::ClassifyArgs),
    /// Render the flexing wing offscreen to PNG (wgpu; needs a build with `--features render`
    /// and a Vulkan or GL driver, e.g. Mesa's lavapipe).
    Render(RenderArgs),
}

#[derive(Args, Debug)]
struct RenderArgs {
    /// Output PNG; with --frames N > 1 the files are numbered out_000.png, out_001.png, ...
    #[arg(long, default_value = "frame.png")]
    out: String,
    /// Number of frames, evenly spread over the simulated duration.
    #[arg(long, default_value_t = 1)]
    frames: usize,
    /// SimConfig JSON (default: the paper's case).
    #[arg(long, value_name = "FILE")]
    config: Option<String>,
    /// FE mesh JSON from `wingbeat modes` (default: a synthetic analytic wing).
    #[arg(long, value_name = "FILE")]
    mesh: Option<String>,
    /// Image width, px.
    #[arg(long, default_value_t = 960)]
    width: u32,
    /// Image height, px.
    #[arg(long, default_value_t = 640)]
    height: u32,
    /// Deflection exaggeration factor (default: automatic, largest drawn deflection 15 % of span).
    #[arg(long)]
    exaggeration: Option<f64>,
    /// Colouring: plain, ex, ey, gxy or mag (strain magnitude).
    #[arg(long, default_value = "mag")]
    colour: String,
}

/// Output of the reproduce report.
#[derive(Copy, Clone, Debug, ValueEnum, PartialEq)]
enum ReportFormat {
    Text,
    Json,
}

#[derive(Args, Debug)]
struct SimulateArgs {
    #[command(flatten)]
    input: SimInput,
    /// Output format: json (everything) or csv (time series only).
    #[arg(long, value_enum, default_value = "json")]
    format: Format,
    /// Time the computation: run it N times and report the median in `timing_ms`.
    #[arg(long, default_value_t = 1)]
    repeat: usize,
}

#[derive(Copy, Clone, Debug, ValueEnum)]
enum DetrendArg {
    None,
    Mean,
    Linear,
}

#[derive(Args, Debug)]
struct PsdArgs {
    #[command(flatten)]
    input: SimInput,
    /// Welch segment length, samples (resolution = sample rate / this).
    #[arg(long, default_value_t = 8192)]
    segment_len: usize,
    /// Segment overlap fraction, [0, 0.95].
    ///
    /// With L = min(segment_len, series length), segments start every
    /// step = max(1, round(L · (1 − overlap))) samples, at 0, step, 2·step, …; only whole
    /// segments are used (samples after the last whole segment are dropped). Each segment is
    /// detrended (--detrend), multiplied by the periodic Hann window
    /// w_j = 0.5 − 0.5 cos(2π j / L) and transformed; the one-sided density is
    /// |X_k|² / (f_s Σ w_j²), doubled except at DC and Nyquist, averaged over segments.
    #[arg(long, default_value_t = 0.5)]
    overlap: f64,
    /// Detrending per segment. Default none: the Coriolis force's large mean stays visible.
    #[arg(long, value_enum, default_value = "none")]
    detrend: DetrendArg,
    /// Peaks to list per spectrum.
    #[arg(long, default_value_t = 8)]
    peaks: usize,
}

#[derive(Args, Debug)]
struct SweepArgs {
    /// What to sweep: gamma0, alpha0, beta0, flap_hz, zeta, or `ic` for the initial-condition map.
    what: String,
    #[command(flatten)]
    input: SimInput,
    /// First value (default 0 for gamma0).
    #[arg(long, allow_negative_numbers = true)]
    from: Option<f64>,
    /// Last value (default 0.3 for gamma0).
    #[arg(long, allow_negative_numbers = true)]
    to: Option<f64>,
    /// Number of points.
    #[arg(long, default_value_t = 31)]
    points: usize,
    /// IC map: mode index (0-based).
    #[arg(long, default_value_t = 0)]
    mode: usize,
    /// IC map: grid points per axis.
    #[arg(long, default_value_t = 101)]
    n: usize,
    /// IC map: who carries the free vibration: forced (default) or carried.
    ///
    /// forced: the Coriolis partial is the response to the Coriolis force from rest, and the
    /// free vibration from the initial conditions is only in the total (the share's
    /// denominator). carried: the Coriolis partial also carries the free vibration. The two
    /// agree at q0 = q̇0 = 0. The grid spans [min, max] of the zero-start total response and
    /// velocity (the paper's bounds).
    #[arg(long, default_value = "forced")]
    attribution: String,
    /// Output format: json or csv.
    #[arg(long, value_enum, default_value = "json")]
    format: Format,
}

#[derive(Args, Debug)]
struct ReproduceArgs {
    /// text (a readable report) or json.
    #[arg(long, value_enum, default_value = "text")]
    format: ReportFormat,
}

/// The command line: every option that takes a value takes the next word as its value even
/// when it starts with `-`, so that negative numbers in any float syntax (`-1e-3`, `-.5`,
/// `-1E+2`, lists `-1,2`) reach the value parser and the range check, not clap's "unexpected
/// argument" (clap's own negative-number test only knows `-1`, `-1.5`, `-1e5`). A flag given
/// where a value belongs (`--duration --format csv`) is then an invalid value of that option.
fn command() -> clap::Command {
    fn allow_hyphen_values(c: clap::Command) -> clap::Command {
        c.mut_args(|a| {
            if a.get_action().takes_values() && !a.is_positional() {
                a.allow_hyphen_values(true)
            } else {
                a
            }
        })
        .mut_subcommands(allow_hyphen_values)
    }
    allow_hyphen_values(<Cli as clap::CommandFactory>::command())
}

/// Parses the command line and runs; returns what to print.
pub fn run() -> Result<String> {
    let parsed = command()
        .try_get_matches()
        .and_then(|m| <Cli as clap::FromArgMatches>::from_arg_matches(&m));
    let cli = match parsed {
        Ok(c) => c,
        Err(e) => {
            use clap::error::ErrorKind;
            if matches!(
                e.kind(),
                ErrorKind::DisplayHelp
                    | ErrorKind::DisplayVersion
                    | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
            ) {
                let _ = e.print();
                std::process::exit(0);
            }
            let _ = e.print();
            std::process::exit(2);
        }
    };
    match cli.cmd {
        Command::Simulate(a) => cmd_simulate(a),
        Command::Psd(a) => cmd_psd(a),
        Command::Sweep(a) => cmd_sweep(a),
        Command::Reproduce(a) => cmd_reproduce(a),
        Command::Modes(a) => modes::run(&a, read_file),
        Command::Sense(a) => sense::run(a),
        Command::Classify(a) => classify::run(a),
        Command::Render(a) => cmd_render(a),
    }
}

fn csv_of(r: &SimResult) -> String {
    let mut out = String::from("t_s");
    let air = r.air.is_some();
    let terms: &[&str] = if air {
        &[
            "euler",
            "centrifugal",
            "coriolis",
            "aerodynamic",
            "free",
            "total",
        ]
    } else {
        &["euler", "centrifugal", "coriolis", "free", "total"]
    };
    for (k, _) in r.modes.iter().enumerate() {
        for term in terms {
            out.push_str(&format!(",q{}_{}", k + 1, term));
        }
        out.push_str(&format!(",qdot{}_total", k + 1));
    }
    if let Some(s) = &r.strain {
        out.push_str(&format!(",eps_x_{0},eps_y_{0},gamma_xy_{0}", s.point));
    }
    out.push('\n');
    for (i, t) in r.t.iter().enumerate() {
        out.push_str(&format!("{t:.9e}"));
        for m in &r.modes {
            let mut vals = vec![m.q.euler[i], m.q.centrifugal[i], m.q.coriolis[i]];
            if air {
                vals.push(m.q.aerodynamic[i]);
            }
            vals.extend([m.q.free[i], m.q.total[i], m.qdot_total[i]]);
            for v in vals {
                out.push_str(&format!(",{v:.12e}"));
            }
        }
        if let Some(s) = &r.strain {
            out.push_str(&format!(
                ",{:.12e},{:.12e},{:.12e}",
                s.eps_x[i], s.eps_y[i], s.gamma_xy[i]
            ));
        }
        out.push('\n');
    }
    out
}

fn cmd_simulate(a: SimulateArgs) -> Result<String> {
    let cfg = build_config(&a.input)?;
    if a.repeat == 0 || a.repeat > 1000 {
        return Err(WingbeatError::invalid(
            "--repeat",
            a.repeat,
            "an integer in [1, 1000]",
        ));
    }
    let mut times = Vec::with_capacity(a.repeat);
    let mut r: Option<SimResult> = None;
    // Each run writes into the previous result's memory (handed back outside the timing).
    let mut pool = wingbeat::pool::SeriesPool::new();
    for _ in 0..a.repeat {
        if let Some(old) = r.take() {
            old.recycle(&mut pool);
        }
        let t0 = std::time::Instant::now();
        r = Some(simulate_reusing(&cfg, &mut pool)?);
        times.push(t0.elapsed().as_secs_f64() * 1e3);
    }
    let r = r.expect("repeat ≥ 1");
    for w in &r.warnings {
        eprintln!("warning: {w}");
    }
    match a.format {
        Format::Csv => Ok(csv_of(&r)),
        Format::Json => {
            // Written straight from the result (no intermediate `serde_json::Value`, which
            // took about 3× the memory of the text).
            #[derive(serde::Serialize)]
            struct Out<'a> {
                #[serde(flatten)]
                r: &'a SimResult,
                #[serde(skip_serializing_if = "Option::is_none")]
                timing_ms: Option<serde_json::Value>,
            }
            let timing_ms = (a.repeat > 1).then(|| {
                times.sort_by(f64::total_cmp);
                json!({"median": times[times.len() / 2], "min": times[0], "runs": times.len()})
            });
            to_json(&Out { r: &r, timing_ms })
        }
    }
}

fn cmd_psd(a: PsdArgs) -> Result<String> {
    let cfg = build_config(&a.input)?;
    let air = !cfg.aero.is_vacuum();
    let opts = WelchOptions {
        segment_len: a.segment_len,
        overlap: a.overlap,
        detrend: match a.detrend {
            DetrendArg::None => Detrend::None,
            DetrendArg::Mean => Detrend::Mean,
            DetrendArg::Linear => Detrend::Linear,
        },
        max_peaks: a.peaks,
    };
    opts.validate_named("--segment-len", "--overlap", "--peaks")?;
    // the output's size, before anything is computed
    check_run_spectra(
        cfg.modes.len(),
        if air { 7 } else { 6 },
        cfg.n_samples(),
        a.segment_len,
        "--segment-len",
    )?;
    let fs = cfg.sample_rate_hz;
    let fd = Some(cfg.kinematics.flap_freq_hz);
    // The run first, keeping only each mode's total response (the other series of the run
    // are not needed here), then the forces: the peak memory is the larger of the two, not
    // their sum (the sum was 4.3 GB with four modes at the sample cap).
    let sim = simulate(&cfg)?;
    for w in &sim.warnings {
        eprintln!("warning: {w}");
    }
    let warnings = sim.warnings;
    // Per mode: name, natural and effective frequency, total response and, in air, the
    // response to the aerodynamic force alone (empty in a vacuum).
    type Run = (String, f64, f64, Vec<f64>, Vec<f64>);
    let runs: Vec<Run> = sim
        .modes
        .into_iter()
        .map(|m| {
            let f = m.floquet.effective_freq_hz;
            (m.name, m.freq_hz, f, m.q.total, m.q.aerodynamic)
        })
        .collect();
    let forces = force_series(&cfg)?;
    let mut modes = Vec::with_capacity(runs.len());
    for ((name, freq_hz_natural, effective_freq_hz, total, aerodynamic), f) in
        runs.into_iter().zip(forces)
    {
        let s = mode_spectra(&f, &total, fs, &opts, fd)?;
        let stiffness_coefficient = welch(&f.stiffness_coefficient, fs, &opts, fd)?;
        let response_aerodynamic = if air {
            Some(welch(&aerodynamic, fs, &opts, fd)?)
        } else {
            None
        };
        drop((f, total, aerodynamic));
        modes.push(PsdMode {
            centrifugal: s.centrifugal,
            coriolis: s.coriolis,
            effective_freq_hz,
            euler: s.euler,
            freq_hz_natural,
            name,
            response_aerodynamic,
            response_total: s.total,
            stiffness_coefficient,
            stiffness_force: s.stiffness_force,
        });
    }
    // Written straight from the spectra (a `serde_json::Value` of them took several times
    // the memory of the text). Keys in alphabetical order, as before; the medium and the
    // aerodynamic response's unit only in air, so a vacuum's output is as it always was.
    #[derive(serde::Serialize)]
    struct Out<'a> {
        #[serde(skip_serializing_if = "Option::is_none")]
        air_density_kg_m3: Option<f64>,
        flap_freq_hz: f64,
        modes: Vec<PsdMode>,
        options: &'a WelchOptions,
        sample_rate_hz: f64,
        units: serde_json::Value,
        warnings: Vec<String>,
    }
    let mut units = json!({"freq_hz": "Hz", "psd": "(unit of the series)^2 / Hz, one-sided, Hann window, Welch average"});
    if air {
        units["air_density_kg_m3"] = json!("kg/m^3");
        units["response_aerodynamic"] = json!("(unit of q)^2 / Hz: the response to the aerodynamic force alone, from rest, in the coupled system (simulate's q.aerodynamic)");
    }
    to_json(&Out {
        air_density_kg_m3: air.then_some(cfg.aero.air_density_kg_m3),
        flap_freq_hz: cfg.kinematics.flap_freq_hz,
        modes,
        options: &opts,
        sample_rate_hz: fs,
        units,
        warnings,
    })
}

/// One mode of `wingbeat psd`'s output.
#[derive(serde::Serialize)]
struct PsdMode {
    centrifugal: wingbeat::analysis::psd::Spectrum,
    coriolis: wingbeat::analysis::psd::Spectrum,
    effective_freq_hz: f64,
    euler: wingbeat::analysis::psd::Spectrum,
    freq_hz_natural: f64,
    name: String,
    /// In air: the response to the aerodynamic force alone (absent in a vacuum).
    #[serde(skip_serializing_if = "Option::is_none")]
    response_aerodynamic: Option<wingbeat::analysis::psd::Spectrum>,
    response_total: wingbeat::analysis::psd::Spectrum,
    stiffness_coefficient: wingbeat::analysis::psd::Spectrum,
    stiffness_force: wingbeat::analysis::psd::Spectrum,
}

/// Refuses a `wingbeat psd` whose output would exceed
/// [`wingbeat::analysis::psd::MAX_RUN_SPECTRUM_BINS`] (`spectra` per mode: six in a vacuum,
/// seven in air; each min(segment, samples)/2 + 1 bins), naming the segment flag.
fn check_run_spectra(
    modes: usize,
    spectra: usize,
    samples: usize,
    segment_len: usize,
    flag: &str,
) -> Result<()> {
    use wingbeat::analysis::psd::MAX_RUN_SPECTRUM_BINS;
    let seg = segment_len.min(samples);
    let per_mode = spectra as f64;
    let bins = modes as f64 * per_mode * (seg / 2 + 1) as f64;
    if bins > MAX_RUN_SPECTRUM_BINS {
        let fit = 2.0 * (MAX_RUN_SPECTRUM_BINS / (per_mode * modes.max(1) as f64) - 1.0);
        return Err(WingbeatError::ResourceCap {
            field: flag.into(),
            requested: format!(
                "{seg} samples per segment: {bins:.0} spectrum bins ({modes} modes × {spectra} spectra × {} bins)",
                seg / 2 + 1
            ),
            cap: format!("{MAX_RUN_SPECTRUM_BINS:.0} bins"),
            why: format!(
                "memory for the output; with {modes} modes a segment of at most {} samples fits",
                fit.floor()
            ),
        });
    }
    Ok(())
}

/// Refuses air for a subcommand that does not handle it (rather than ignore it).
fn vacuum_only(cfg: &SimConfig, what: &str) -> Result<()> {
    if cfg.aero.is_vacuum() {
        return Ok(());
    }
    Err(WingbeatError::invalid(
        "--air-density",
        cfg.aero.air_density_kg_m3,
        format!("0 for `{what}` (not in air: the initial-condition map superposes one mode's vacuum responses); `simulate`, `psd`, `sweep` over a parameter and `sense` run in air"),
    ))
}

fn cmd_sweep(a: SweepArgs) -> Result<String> {
    let cfg = build_config(&a.input)?;
    if a.what == "ic" {
        vacuum_only(&cfg, "sweep ic")?;
    }
    for w in cfg.warnings() {
        eprintln!("warning: {w}");
    }
    if a.what == "ic" {
        let attribution = match a.attribution.as_str() {
            "forced" => IcAttribution::Forced,
            "carried" => IcAttribution::Carried,
            other => {
                return Err(WingbeatError::invalid(
                    "--attribution",
                    other,
                    "forced or carried",
                ))
            }
        };
        let opts = IcMapOptions {
            mode: a.mode,
            n_q: a.n,
            n_qdot: a.n,
            attribution,
            ..Default::default()
        };
        let m = ic_map(&cfg, &opts)?;
        if a.format == Format::Csv {
            let mut out = String::from("q0,qdot0,coriolis_percent\n");
            for (r, v) in m.qdot0.iter().enumerate() {
                for (c, q) in m.q0.iter().enumerate() {
                    out.push_str(&format!(
                        "{q:.9e},{v:.9e},{:.6}\n",
                        m.coriolis_percent[r * m.q0.len() + c]
                    ));
                }
            }
            return Ok(out);
        }
        return to_json(&WithWarnings {
            body: &m,
            warnings: cfg.warnings(),
        });
    }
    let param = SweepParam::parse(&a.what)?;
    let (from, to) = match param {
        SweepParam::Gamma0 => (a.from.unwrap_or(0.0), a.to.unwrap_or(0.3)),
        _ => (
            a.from.ok_or_else(|| {
                WingbeatError::invalid("--from", "missing", "a value (required for this parameter)")
            })?,
            a.to.ok_or_else(|| {
                WingbeatError::invalid("--to", "missing", "a value (required for this parameter)")
            })?,
        ),
    };
    let opts = SweepOptions {
        param,
        from,
        to,
        points: a.points,
    };
    let s = sweep(&cfg, &opts, |done, total| {
        if total >= 50 && done % (total / 10).max(1) == 0 {
            eprintln!("sweep: {done}/{total}");
        }
    })?;
    let air = !cfg.aero.is_vacuum();
    if a.format == Format::Csv {
        // In air the aerodynamic share gets its column after the Coriolis share.
        let mut out = String::from(if air {
            "value,mode,euler_percent,centrifugal_percent,coriolis_percent,aerodynamic_percent,effective_freq_hz,beat_period_s,stable\n"
        } else {
            "value,mode,euler_percent,centrifugal_percent,coriolis_percent,effective_freq_hz,beat_period_s,stable\n"
        });
        for p in &s.points {
            for (k, m) in p.modes.iter().enumerate() {
                let c = m.contribution_percent;
                let aero = match (air, c.aerodynamic) {
                    (true, Some(v)) => format!("{v:.6},"),
                    (true, None) => ",".to_string(),
                    (false, _) => String::new(),
                };
                out.push_str(&format!(
                    "{},{},{:.6},{:.6},{:.6},{aero}{:.9},{},{}\n",
                    p.value,
                    k,
                    c.euler,
                    c.centrifugal,
                    c.coriolis,
                    m.effective_freq_hz,
                    m.beat_period_s.map_or(String::new(), |b| format!("{b:.9}")),
                    m.stable
                ));
            }
        }
        return Ok(out);
    }
    // The medium is named only in air, so a vacuum sweep's output is as it always was.
    #[derive(serde::Serialize)]
    struct Out<'a> {
        #[serde(skip_serializing_if = "Option::is_none")]
        air_density_kg_m3: Option<f64>,
        #[serde(flatten)]
        body: &'a wingbeat::analysis::sweep::Sweep,
        warnings: Vec<String>,
    }
    to_json(&Out {
        air_density_kg_m3: air.then_some(cfg.aero.air_density_kg_m3),
        body: &s,
        warnings: cfg.warnings(),
    })
}

/// A JSON result with the run's warnings beside its own keys (`warnings`: always present,
/// an empty list when there is nothing to say).
#[derive(serde::Serialize)]
struct WithWarnings<'a, T: serde::Serialize> {
    #[serde(flatten)]
    body: &'a T,
    warnings: Vec<String>,
}

fn cmd_reproduce(a: ReproduceArgs) -> Result<String> {
    let rep = wingbeat::reproduce::reproduce()?;
    match a.format {
        ReportFormat::Json => to_json(&rep),
        ReportFormat::Text => Ok(rep.to_text()),
    }
}

#[cfg(feature = "render")]
fn cmd_render(a: RenderArgs) -> Result<String> {
    if a.frames == 0 || a.frames > 10_000 {
        return Err(WingbeatError::invalid(
            "--frames",
            a.frames,
            "an integer in [1, 10000]",
        ));
    }
    render::run_render(
        a.config.as_deref(),
        a.mesh.as_deref(),
        &a.out,
        a.frames,
        a.width,
        a.height,
        a.exaggeration,
        &a.colour,
    )
    .map_err(WingbeatError::Render)
}

#[cfg(not(feature = "render"))]
fn cmd_render(_: RenderArgs) -> Result<String> {
    Err(WingbeatError::Render(
        "this wingbeat was built without the renderer; rebuild with `cargo build --release --features render`".into(),
    ))
}
