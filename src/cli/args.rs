//! The flags every simulating subcommand shares ([`SimInput`]), the config they build
//! ([`build_config`]), input files ([`read_file`]) and the output format ([`Format`],
//! [`to_json`]). Used by `simulate`, `psd`, `sweep` (in `mod.rs`), `sense` and `render`; this
//! module uses none of them, so the binary's modules have no import cycle.

use clap::{Args, ValueEnum};
use wingbeat::config::SimConfig;
use wingbeat::kinematics_table::{kinematics_from_csv, AngleUnits, CsvKinematicsOptions};
use wingbeat::modes_doc::read_modes_document;
use wingbeat::{Result, WingbeatError};

/// Output of commands that produce tables.
#[derive(Copy, Clone, Debug, ValueEnum, PartialEq)]
pub(crate) enum Format {
    Json,
    Csv,
}

/// Inputs shared by every command that runs a simulation.
#[derive(Args, Debug, Clone)]
pub(crate) struct SimInput {
    /// Start from a named preset: `paper` (Tables 3–6 as printed, forward flight) or `fe-wing`
    /// (the same kinematics with the first four shell-FE modes of the default synthetic wing,
    /// SI a_k, strain at P = (3, −6) mm; takes a second or two to compute).
    #[arg(long, default_value = "paper")]
    pub(crate) preset: String,
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
    pub(crate) config: Option<std::path::PathBuf>,
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
    pub(crate) kinematics_csv: Option<std::path::PathBuf>,
    /// Units of the angle columns of --kinematics-csv: deg or rad (required with it).
    #[arg(long, value_name = "deg|rad")]
    pub(crate) kinematics_units: Option<String>,
    /// Highest harmonic kept from --kinematics-csv (a low-pass for noisy measurements).
    #[arg(long, value_name = "H")]
    pub(crate) kinematics_max_harmonic: Option<u32>,
    /// Replace the modes by those in a JSON file: the output of `wingbeat modes` (FE) or
    /// `{"modes": [{"freq_hz":…, "a":[x,y], …}]}`.
    #[arg(long, value_name = "FILE")]
    pub(crate) modes: Option<std::path::PathBuf>,
    /// Roll amplitude α0 (first harmonic), rad.
    #[arg(long, allow_negative_numbers = true)]
    pub(crate) alpha0: Option<f64>,
    /// Pitch amplitude β0 (first harmonic), rad.
    #[arg(long, allow_negative_numbers = true)]
    pub(crate) beta0: Option<f64>,
    /// Yaw amplitude γ0 (first harmonic), rad. Above 0.3 rad: allowed, with a warning.
    #[arg(long, allow_negative_numbers = true)]
    pub(crate) gamma0: Option<f64>,
    /// Flap frequency f_d, Hz (ω_d = 2π f_d).
    #[arg(long, value_name = "HZ", allow_negative_numbers = true)]
    pub(crate) flap_hz: Option<f64>,
    /// Damping ratio ζ for every mode (the paper: 0; §4.3: 0.01).
    #[arg(long, allow_negative_numbers = true)]
    pub(crate) zeta: Option<f64>,
    /// Phase φα of the roll angle's first harmonic, rad: α = α0 sin(ω_d t + φα) + …; the
    /// lab's `alpha_phase` slider, set the same way (params::set_param; a first harmonic of
    /// amplitude 0 is added when the angle has none). Any finite number the core accepts,
    /// [-1000, 1000] rad (kinematics.*.harmonics[].phase); not for a sampled angle.
    #[arg(long, value_name = "RAD", allow_negative_numbers = true)]
    pub(crate) alpha_phase: Option<f64>,
    /// Phase φβ of the pitch angle's first harmonic, rad (as --alpha-phase; the lab's
    /// `beta_phase`).
    #[arg(long, value_name = "RAD", allow_negative_numbers = true)]
    pub(crate) beta_phase: Option<f64>,
    /// Phase φγ of the yaw angle's first harmonic, rad (as --alpha-phase; the lab's
    /// `gamma_phase`).
    #[arg(long, value_name = "RAD", allow_negative_numbers = true)]
    pub(crate) gamma_phase: Option<f64>,
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
    pub(crate) body_rate: Vec<f64>,
    /// Simulated duration, s.
    #[arg(long, value_name = "S", allow_negative_numbers = true)]
    pub(crate) duration: Option<f64>,
    /// Output sample rate, Hz.
    #[arg(long, value_name = "HZ", allow_negative_numbers = true)]
    pub(crate) sample_rate: Option<f64>,
    /// Initial displacements q_k(0), comma-separated per mode.
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    pub(crate) q0: Vec<f64>,
    /// Initial velocities q̇_k(0), comma-separated per mode.
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    pub(crate) qdot0: Vec<f64>,
    /// Density of the fluid around the wing, kg/m³, 0 ..= 1000: 0 = vacuum (the paper's
    /// assumption and the default), 0.18 helium, 1.2 air. Overrides the config's
    /// `aero.air_density_kg_m3`. Air loads the wing point by point (quasi-steady strip theory
    /// with added mass, docs/model.md "The wing in air"), so it needs mode shapes over the
    /// wing: `--preset fe-wing`, or `--modes FILE` written by `wingbeat modes`. In air the
    /// modes are coupled; each mode gains an `aerodynamic` partial response and share and an
    /// `air` block (still-air frequency, aerodynamic damping ratio, decay time, the beat's fate).
    #[arg(long, value_name = "RHO", allow_negative_numbers = true)]
    pub(crate) air_density: Option<f64>,
}

/// Largest input file read, bytes.
const MAX_FILE_BYTES: u64 = 64 * 1024 * 1024;

/// Reads a whole input file, at most [`MAX_FILE_BYTES`]: the cap is checked while reading, so
/// it holds for devices and pipes (`/dev/zero`, `<(…)`) as for regular files.
pub(crate) fn read_file(path: &std::path::Path) -> Result<String> {
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

/// The config of a run from the shared flags: preset or config file, modes file, medium,
/// measured kinematics, then the parameter flags through the lab's interpretation
/// ([`wingbeat::params::apply_values`], the core's ranges), body rate, duration, sample rate and
/// initial conditions; validated.
pub(crate) fn build_config(inp: &SimInput) -> Result<SimConfig> {
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
    // The parameter flags, in this order, each named by its flag in errors.
    use wingbeat::params as p;
    let values = [
        (p::ALPHA0, inp.alpha0),
        (p::BETA0, inp.beta0),
        (p::GAMMA0, inp.gamma0),
        (p::FLAP_HZ, inp.flap_hz),
        (p::ZETA, inp.zeta),
        (p::ALPHA_PHASE, inp.alpha_phase),
        (p::BETA_PHASE, inp.beta_phase),
        (p::GAMMA_PHASE, inp.gamma_phase),
    ];
    cfg = p::apply_values(
        &cfg,
        values.into_iter().filter_map(|(k, v)| Some((k, v?))),
        flag_of,
        p::Limits::Core,
    )?;
    if !inp.body_rate.is_empty() {
        let w = wingbeat::analysis::sensing::body_rate_vector("--body-rate", &inp.body_rate)?;
        cfg.kinematics.body_rate = wingbeat::kinematics::BodyRate::constant(w);
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

pub(crate) fn to_json(v: &impl serde::Serialize) -> Result<String> {
    serde_json::to_string(v).map_err(|e| WingbeatError::NonFinite {
        what: "JSON output".into(),
        detail: e.to_string(),
    })
}

/// The CLI flag of a parameter key: `gamma0` -> `--gamma0`, `flap_hz` -> `--flap-hz`.
fn flag_of(key: &str) -> String {
    format!("--{}", key.replace('_', "-"))
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
