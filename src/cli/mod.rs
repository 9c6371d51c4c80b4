//! Argument parsing and the subcommands of the `wingbeat` binary.

mod modes;
#[cfg(feature = "render")]
mod render;
mod sense;

use clap::{Args, Parser, Subcommand, ValueEnum};
use serde_json::json;
use wingbeat::analysis::ic_map::{ic_map, IcAttribution, IcMapOptions};
use wingbeat::analysis::psd::{welch, Detrend, WelchOptions};
use wingbeat::analysis::spectra::mode_spectra;
use wingbeat::analysis::sweep::{apply, sweep, SweepOptions, SweepParam};
use wingbeat::config::SimConfig;
use wingbeat::kinematics_table::{kinematics_from_csv, AngleUnits, CsvKinematicsOptions};
use wingbeat::modes_doc::read_modes_document;
use wingbeat::simulate::{force_series, simulate, SimResult};
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

/// Output of commands that produce tables.
#[derive(Copy, Clone, Debug, ValueEnum, PartialEq)]
enum Format {
    Json,
    Csv,
}

/// Output of the reproduce report.
#[derive(Copy, Clone, Debug, ValueEnum, PartialEq)]
enum ReportFormat {
    Text,
    Json,
}

/// Inputs shared by every command that runs a simulation.
#[derive(Args, Debug, Clone)]
struct SimInput {
    /// Start from a named preset: `paper` (Tables 3–6 as printed, forward flight) or `fe-wing`
    /// (the same kinematics with the first four shell-FE modes of the default synthetic wing,
    /// SI a_k, strain at P = (3, −6) mm; takes a second or two to compute).
    #[arg(long, default_value = "paper")]
    preset: String,
    /// JSON config file (SimConfig: kinematics, modes, duration_s, sample_rate_hz,
    /// initial_conditions); missing fields take the paper's values. Flags below override it.
    ///
    /// Each angle of `kinematics` (alpha, beta, gamma, rad) is either
    /// `{"kind": "fourier", "mean": m, "harmonics": [{"n": 1, "amplitude": A, "phase": φ}]}`,
    /// meaning m + Σ A sin(n ω_d t + φ), or measured samples
    /// `{"kind": "sampled", "values": [v_0, …, v_(N−1)], "max_harmonic": H}`: N equally spaced
    /// samples over exactly one flap period, v_j at t_j = j T / N (do not repeat the first
    /// sample at the end). The sampled angle is the trigonometric polynomial
    /// mean(v) + Σ_(h=1..K) [a_h cos(h ω_d t) + b_h sin(h ω_d t)] with a_h, b_h = (2/N) Σ_j v_j
    /// cos(2π h j/N), sin(2π h j/N), and K = min(⌊N/2⌋, H). For even N the Nyquist term
    /// h = N/2 gets weight 1/N instead of 2/N (it is shared by ±N/2), so with K = ⌊N/2⌋ the
    /// polynomial passes through every sample; a smaller H low-passes noisy data. Without
    /// `max_harmonic`, H = 24 (kinematics::DEFAULT_SAMPLED_MAX_HARMONIC, which bounds the
    /// run's cost): a table of more than 49 samples is then low-passed and does NOT pass
    /// through every sample; the output says so in `warnings` (and on stderr) with the
    /// largest deviation. Give `"max_harmonic": ⌊N/2⌋` to keep every harmonic.
    #[arg(long, value_name = "FILE")]
    config: Option<std::path::PathBuf>,
    /// Measured kinematics: a CSV table with a header naming `t` (s) and any of `alpha`,
    /// `beta`, `gamma` (a missing angle is 0; names may end in `_deg`/`_rad`, matching
    /// --kinematics-units), one row per sample, t strictly increasing over one or more whole
    /// flap periods (1 / --flap-hz, or the config's flap frequency). The samples are folded
    /// onto one period (t mod T). On a uniform grid aligned with t = 0 mod T they are averaged
    /// point by point over the periods into sampled angles (the same as a config with
    /// `{"kind": "sampled", "values": [...]}`); otherwise a least-squares Fourier series
    /// (--kinematics-max-harmonic harmonics, default up to 32) is fitted and sampled. Replaces
    /// the config's kinematics; the lab's "load kinematics" does exactly the same. On the grid
    /// without --kinematics-max-harmonic, at most 24 harmonics are kept as for a config's
    /// table (see --config), with a warning when that drops any.
    #[arg(long, value_name = "FILE")]
    kinematics_csv: Option<std::path::PathBuf>,
    /// Units of the angle columns of --kinematics-csv: deg or rad (required with it).
    #[arg(long, value_name = "deg|rad")]
    kinematics_units: Option<String>,
    /// Highest harmonic kept from --kinematics-csv (a low-pass for noisy measurements).
    #[arg(long, value_name = "H")]
    kinematics_max_harmonic: Option<u32>,
    /// Replace the modes by those in a JSON file: the output of `wingbeat modes` (FE) or
    /// `{"modes": [{"freq_hz":…, "a":[x,y], …}]}`.
    #[arg(long, value_name = "FILE")]
    modes: Option<std::path::PathBuf>,
    /// Roll amplitude α0 (first harmonic), rad.
    #[arg(long, allow_negative_numbers = true)]
    alpha0: Option<f64>,
    /// Pitch amplitude β0 (first harmonic), rad.
    #[arg(long, allow_negative_numbers = true)]
    beta0: Option<f64>,
    /// Yaw amplitude γ0 (first harmonic), rad. Above 0.3 rad: allowed, with a warning.
    #[arg(long, allow_negative_numbers = true)]
    gamma0: Option<f64>,
    /// Flap frequency f_d, Hz (ω_d = 2π f_d).
    #[arg(long, value_name = "HZ", allow_negative_numbers = true)]
    flap_hz: Option<f64>,
    /// Damping ratio ζ for every mode (the paper: 0; §4.3: 0.01).
    #[arg(long, allow_negative_numbers = true)]
    zeta: Option<f64>,
    /// Constant body angular velocity ω_b = X,Y,Z in body axes (I, J, K), rad/s, each within
    /// ±100 (default: none, the paper's fixed body). The wing frame then turns with
    /// Ω = Rᵀω_b + Ω_wing (docs/model.md, "Body rotation"). A periodic rate: the config's
    /// `kinematics.body_rate`.
    #[arg(
        long,
        value_name = "X,Y,Z",
        value_delimiter = ',',
        allow_negative_numbers = true
    )]
    body_rate: Vec<f64>,
    /// Simulated duration, s.
    #[arg(long, value_name = "S", allow_negative_numbers = true)]
    duration: Option<f64>,
    /// Output sample rate, Hz.
    #[arg(long, value_name = "HZ", allow_negative_numbers = true)]
    sample_rate: Option<f64>,
    /// Initial displacements q_k(0), comma-separated per mode.
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    q0: Vec<f64>,
    /// Initial velocities q̇_k(0), comma-separated per mode.
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    qdot0: Vec<f64>,
    /// Density of the fluid around the wing, kg/m³, 0 ..= 1000: 0 = vacuum (the paper's
    /// assumption and the default), 0.18 helium, 1.2 air. Overrides the config's
    /// `aero.air_density_kg_m3`. Air loads the wing point by point (quasi-steady strip theory
    /// with added mass, docs/model.md "The wing in air"), so it needs mode shapes over the
    /// wing: `--preset fe-wing`, or `--modes FILE` written by `wingbeat modes`. In air the
    /// modes are coupled; each mode gains an `aerodynamic` partial response and share and an
    /// `air` block (still-air frequency, aerodynamic damping ratio, decay time, the beat's fate).
    #[arg(long, value_name = "RHO", allow_negative_numbers = true)]
    air_density: Option<f64>,
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
        Command::Render(a) => cmd_render(a),
    }
}

/// Largest input file read, bytes.
const MAX_FILE_BYTES: u64 = 64 * 1024 * 1024;

/// Reads a whole input file, at most [`MAX_FILE_BYTES`]: the cap is checked while reading, so
/// it holds for devices and pipes (`/dev/zero`, `<(…)`) as for regular files.
fn read_file(path: &std::path::Path) -> Result<String> {
    use std::io::Read;
    let parse = |e: std::io::Error| WingbeatError::Parse {
        what: path.display().to_string(),
        message: e.to_string(),
    };
    let cap = |n: u64| WingbeatError::ResourceCap {
        field: path.display().to_string(),
        requested: if n > MAX_FILE_BYTES {
            format!("{n} bytes")
        } else {
            format!("more than {MAX_FILE_BYTES} bytes")
        },
        cap: "64 MiB".into(),
        why: "input files are read whole".into(),
    };
    let file = std::fs::File::open(path).map_err(parse)?;
    if let Ok(meta) = file.metadata() {
        if meta.is_file() && meta.len() > MAX_FILE_BYTES {
            return Err(cap(meta.len()));
        }
    }
    let mut bytes = Vec::new();
    file.take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(parse)?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(cap(0));
    }
    String::from_utf8(bytes).map_err(|e| WingbeatError::Parse {
        what: path.display().to_string(),
        message: format!("not UTF-8 text: {e}"),
    })
}

fn build_config(inp: &SimInput) -> Result<SimConfig> {
    let preset = match inp.preset.as_str() {
        "paper" => None,
        "fe-wing" => {
            eprintln!("simulate: computing the fe-wing preset's shell FE modes…");
            Some(wingbeat::presets::fe_wing_modes_and_wing()?)
        }
        other => {
            return Err(WingbeatError::invalid(
                "--preset",
                other,
                format!("one of: {}", wingbeat::presets::PRESETS.join(", ")),
            ))
        }
    };
    let mut cfg = match &inp.config {
        Some(p) => SimConfig::from_json(&read_file(p)?).map_err(|e| match e {
            WingbeatError::Parse { message, .. } => WingbeatError::Parse {
                what: p.display().to_string(),
                message,
            },
            other => other,
        })?,
        None => SimConfig::paper(),
    };
    if let Some((fe_modes, wing)) = preset {
        cfg.modes = fe_modes;
        cfg.wing = Some(std::sync::Arc::new(wing));
    }
    if let Some(p) = &inp.modes {
        let doc = read_modes_document(&read_file(p)?, &p.display().to_string())?;
        cfg.modes = doc.modes;
        // A `wingbeat modes` document carries the mesh and shapes the air needs.
        cfg.wing = doc
            .fe
            .as_ref()
            .map(|fe| std::sync::Arc::new(wingbeat::aero::WingGeometry::from_fem(fe)));
    }
    apply_air_density(&mut cfg, inp.air_density)?;
    if let Some(p) = &inp.kinematics_csv {
        let units = inp.kinematics_units.as_deref().ok_or_else(|| {
            WingbeatError::invalid(
                "--kinematics-units",
                "missing",
                "deg or rad (required with --kinematics-csv)",
            )
        })?;
        let opts = CsvKinematicsOptions {
            units: AngleUnits::parse("--kinematics-units", units)?,
            flap_hz: inp.flap_hz.unwrap_or(cfg.kinematics.flap_freq_hz),
            max_harmonic: inp.kinematics_max_harmonic,
        };
        let table = kinematics_from_csv(&read_file(p)?, &opts).map_err(|e| match e {
            WingbeatError::Parse { message, .. } => WingbeatError::Parse {
                what: p.display().to_string(),
                message,
            },
            other => other,
        })?;
        for w in &table.warnings {
            eprintln!("kinematics: {w}");
        }
        cfg.kinematics = table.kinematics;
    } else if inp.kinematics_units.is_some() || inp.kinematics_max_harmonic.is_some() {
        return Err(WingbeatError::invalid(
            "--kinematics-units/--kinematics-max-harmonic",
            "given without a table",
            "only together with --kinematics-csv FILE",
        ));
    }
    for (flag, param, v) in [
        ("--alpha0", SweepParam::Alpha0, inp.alpha0),
        ("--beta0", SweepParam::Beta0, inp.beta0),
        ("--gamma0", SweepParam::Gamma0, inp.gamma0),
        ("--flap-hz", SweepParam::FlapHz, inp.flap_hz),
        ("--zeta", SweepParam::Zeta, inp.zeta),
    ] {
        if let Some(v) = v {
            if !v.is_finite() {
                return Err(WingbeatError::invalid(flag, v, "a finite number"));
            }
            cfg = apply(&cfg, param, v)?;
        }
    }
    if !inp.body_rate.is_empty() {
        if inp.body_rate.len() != 3 {
            return Err(WingbeatError::invalid(
                "--body-rate",
                format!("{} values", inp.body_rate.len()),
                "three comma-separated rates X,Y,Z in rad/s (body axes)",
            ));
        }
        let range = wingbeat::params::body_rate_range("peak");
        for (i, v) in inp.body_rate.iter().enumerate() {
            let axis = ["X", "Y", "Z"][i];
            wingbeat::error::check_range(
                &format!("--body-rate {axis}"),
                *v,
                -range.max,
                range.max,
                range.unit,
            )?;
        }
        cfg.kinematics.body_rate = wingbeat::kinematics::BodyRate::constant([
            inp.body_rate[0],
            inp.body_rate[1],
            inp.body_rate[2],
        ]);
    }
    if let Some(d) = inp.duration {
        cfg.duration_s = d;
    }
    if let Some(r) = inp.sample_rate {
        cfg.sample_rate_hz = r;
    }
    if !inp.q0.is_empty() || !inp.qdot0.is_empty() {
        let n = cfg.modes.len();
        if inp.q0.len() > n || inp.qdot0.len() > n {
            return Err(WingbeatError::invalid(
                "--q0/--qdot0",
                format!("{}/{} values", inp.q0.len(), inp.qdot0.len()),
                format!("at most one value per mode ({n} modes)"),
            ));
        }
        cfg.initial_conditions = (0..n)
            .map(|k| {
                [
                    inp.q0.get(k).copied().unwrap_or(0.0),
                    inp.qdot0.get(k).copied().unwrap_or(0.0),
                ]
            })
            .collect();
    }
    cfg.validate()?;
    Ok(cfg)
}

fn to_json(v: &impl serde::Serialize) -> Result<String> {
    serde_json::to_string(v).map_err(|e| WingbeatError::NonFinite {
        what: "JSON output".into(),
        detail: e.to_string(),
    })
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
    let mut r = None;
    for _ in 0..a.repeat {
        let t0 = std::time::Instant::now();
        r = Some(simulate(&cfg)?);
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
            // took about 3× the memory of the text: issue 13).
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
    vacuum_only(&cfg, "psd")?;
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
        cfg.n_samples(),
        a.segment_len,
        "--segment-len",
    )?;
    let fs = cfg.sample_rate_hz;
    let fd = Some(cfg.kinematics.flap_freq_hz);
    // The run first, keeping only each mode's total response (the other series of the run
    // are not needed here), then the forces: the peak memory is the larger of the two, not
    // their sum (issue 20: 4.3 GB with four modes at the sample cap).
    let sim = simulate(&cfg)?;
    for w in &sim.warnings {
        eprintln!("warning: {w}");
    }
    let warnings = sim.warnings;
    let runs: Vec<(String, f64, f64, Vec<f64>)> = sim
        .modes
        .into_iter()
        .map(|m| (m.name, m.freq_hz, m.floquet.effective_freq_hz, m.q.total))
        .collect();
    let forces = force_series(&cfg)?;
    let mut modes = Vec::with_capacity(runs.len());
    for ((name, freq_hz_natural, effective_freq_hz, total), f) in runs.into_iter().zip(forces) {
        let s = mode_spectra(&f, &total, fs, &opts, fd)?;
        let stiffness_coefficient = welch(&f.stiffness_coefficient, fs, &opts, fd)?;
        drop((f, total));
        modes.push(PsdMode {
            centrifugal: s.centrifugal,
            coriolis: s.coriolis,
            effective_freq_hz,
            euler: s.euler,
            freq_hz_natural,
            name,
            response_total: s.total,
            stiffness_coefficient,
            stiffness_force: s.stiffness_force,
        });
    }
    // Written straight from the spectra (a `serde_json::Value` of them took several times
    // the memory of the text). Keys in alphabetical order, as before.
    #[derive(serde::Serialize)]
    struct Out<'a> {
        flap_freq_hz: f64,
        modes: Vec<PsdMode>,
        options: &'a WelchOptions,
        sample_rate_hz: f64,
        units: serde_json::Value,
        warnings: Vec<String>,
    }
    to_json(&Out {
        flap_freq_hz: cfg.kinematics.flap_freq_hz,
        modes,
        options: &opts,
        sample_rate_hz: fs,
        units: json!({"freq_hz": "Hz", "psd": "(unit of the series)^2 / Hz, one-sided, Hann window, Welch average"}),
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
    response_total: wingbeat::analysis::psd::Spectrum,
    stiffness_coefficient: wingbeat::analysis::psd::Spectrum,
    stiffness_force: wingbeat::analysis::psd::Spectrum,
}

/// Refuses a `wingbeat psd` whose output would exceed
/// [`wingbeat::analysis::psd::MAX_RUN_SPECTRUM_BINS`] (six spectra per mode, each
/// min(segment, samples)/2 + 1 bins), naming the segment flag.
fn check_run_spectra(modes: usize, samples: usize, segment_len: usize, flag: &str) -> Result<()> {
    use wingbeat::analysis::psd::MAX_RUN_SPECTRUM_BINS;
    let seg = segment_len.min(samples);
    let bins = modes as f64 * 6.0 * (seg / 2 + 1) as f64;
    if bins > MAX_RUN_SPECTRUM_BINS {
        let fit = 2.0 * (MAX_RUN_SPECTRUM_BINS / (6.0 * modes.max(1) as f64) - 1.0);
        return Err(WingbeatError::ResourceCap {
            field: flag.into(),
            requested: format!(
                "{seg} samples per segment: {bins:.0} spectrum bins ({modes} modes × 6 spectra × {} bins)",
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

/// Applies `--air-density` (when given) to `cfg` and refuses air without the wing's mode
/// shapes; the one place the flag is read (simulate, psd, sweep, sense).
pub(crate) fn apply_air_density(cfg: &mut SimConfig, rho: Option<f64>) -> Result<()> {
    if let Some(rho) = rho {
        wingbeat::error::check_range(
            "--air-density",
            rho,
            0.0,
            wingbeat::aero::MAX_DENSITY,
            "kg/m³ (0 = vacuum, 0.18 helium, 1.2 air)",
        )?;
        cfg.aero.air_density_kg_m3 = rho;
    }
    if !cfg.aero.is_vacuum() && cfg.wing.is_none() {
        return Err(WingbeatError::invalid(
            "--air-density",
            cfg.aero.air_density_kg_m3,
            "0 (vacuum) with these modes: air needs mode shapes over the wing, from `--preset fe-wing` or `--modes FILE` written by `wingbeat modes` (the paper's table modes and modes without a mesh have none)",
        ));
    }
    Ok(())
}

/// Refuses air for a subcommand that does not handle it yet (rather than ignore it).
fn vacuum_only(cfg: &SimConfig, what: &str) -> Result<()> {
    if cfg.aero.is_vacuum() {
        return Ok(());
    }
    Err(WingbeatError::invalid(
        "--air-density",
        cfg.aero.air_density_kg_m3,
        format!("0 for `{what}` (not yet in air: {what} prices and spectra its runs for a vacuum); `simulate` and `sense` run in air"),
    ))
}

fn cmd_sweep(a: SweepArgs) -> Result<String> {
    let cfg = build_config(&a.input)?;
    vacuum_only(&cfg, "sweep")?;
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
    if a.format == Format::Csv {
        let mut out = String::from("value,mode,euler_percent,centrifugal_percent,coriolis_percent,effective_freq_hz,beat_period_s,stable\n");
        for p in &s.points {
            for (k, m) in p.modes.iter().enumerate() {
                let c = m.contribution_percent;
                out.push_str(&format!(
                    "{},{},{:.6},{:.6},{:.6},{:.9},{},{}\n",
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
    to_json(&WithWarnings {
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
