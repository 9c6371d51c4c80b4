//! `wingbeat classify`: rotation or none, told from wing strain by neuron-like encoding and a
//! linear discriminant on sparse, random and all sensors (docs/sensing.md, "Classifying
//! rotation").

use super::{read_file, to_json, Format};
use clap::Args;
use serde_json::json;
use wingbeat::aero::AeroConfig;
use wingbeat::analysis::classify::ThresholdRule;
use wingbeat::analysis::neural::{Filter, Nonlinearity, Orientation};
use wingbeat::analysis::rotation_classify::{
    classify, fe_case, in_fluid, mohren2018_case, mohren2018_classes, mohren2018_grid_mm,
    spanwise_sensors, ClassifyCase, ClassifyOptions, ClassifyReport,
};
use wingbeat::modes_doc::read_modes_document;
use wingbeat::{Result, WingbeatError};

#[derive(Args, Debug)]
pub struct ClassifyArgs {
    /// The setup: `mohren2018`, the published plate, kinematics and sensor grid (Mohren et al.
    /// 2018) on wingbeat's shell FE.
    #[arg(long, default_value = "mohren2018")]
    preset: String,
    /// Instead of the preset's plate, the FE modes of any wing from `wingbeat modes` (JSON with
    /// the mesh); the sensors sit at the published grid's points that fall on it, else at every
    /// mesh node. The preset's kinematics and damping ratios ζ_k = 63/(2ω_k) apply.
    #[arg(long, value_name = "FILE")]
    modes: Option<std::path::PathBuf>,
    /// FE modes of the plate, 1–64.
    #[arg(long, default_value_t = 8)]
    n_modes: usize,
    /// Element size of the plate's mesh, mm (default: automatic).
    #[arg(long)]
    mesh_size_mm: Option<f64>,
    /// Body rate of the rotating class about the plate's normal, rad/s (published: 10).
    #[arg(long, default_value_t = 10.0, allow_negative_numbers = true)]
    rotation: f64,
    /// Disturbance on the flapping rate, rad/s rms (published: 0.312; 0 for none).
    #[arg(long, default_value_t = 0.312)]
    flap_disturbance: f64,
    /// Disturbance on the rotation rate, rad/s rms (published: 0.1; 0 for none).
    #[arg(long, default_value_t = 0.1)]
    rotation_disturbance: f64,
    /// Seed of the disturbances, the random sensor sets and the randomised SVD.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Length of each run, s.
    #[arg(long, default_value_t = 4.0)]
    duration: f64,
    /// Settling time left out, s.
    #[arg(long, default_value_t = 1.0)]
    discard: f64,
    /// Random draws per sensor count, 1–10000.
    #[arg(long, default_value_t = 100)]
    draws: usize,
    /// SSPOC's kept modes, a list or ranges: `1-30`, `2,5,10`.
    #[arg(long, default_value = "1-30")]
    kept_modes: String,
    /// Sensor counts for random placement and for the greedy d′ sets, a list or ranges.
    #[arg(long, default_value = "1-30")]
    counts: String,
    /// Where the STA kernel is laid: causal (the STA convention) or published-code (as the
    /// authors' code did, 29 ms later).
    #[arg(long, default_value = "causal")]
    orientation: String,
    /// Sigmoid gain g.
    #[arg(long, default_value_t = 10.0)]
    gain: f64,
    /// Sigmoid threshold θ.
    #[arg(long, default_value_t = 0.5, allow_negative_numbers = true)]
    threshold: f64,
    /// Strain normalisation s₀ (default: the largest filtered strain of the run).
    #[arg(long)]
    s0: Option<f64>,
    /// Split of the projected classes: gaussian (published) or midpoint.
    #[arg(long, default_value = "gaussian")]
    split: String,
    /// Density of the fluid the wing flaps in, kg/m³, 0 ..= 1000: 0 = vacuum (the published
    /// setup and the default), 1.2 air. Both runs then carry the air's loads (quasi-steady
    /// strip theory with added mass, docs/model.md "The wing in air") from the wing's mesh and
    /// mode shapes; each run costs far more than in a vacuum (capped before the first step).
    #[arg(
        long,
        value_name = "RHO",
        default_value_t = 0.0,
        allow_negative_numbers = true
    )]
    air_density: f64,
    /// Output: json (everything) or csv (accuracy against the number of sensors).
    #[arg(long, value_enum, default_value = "json")]
    format: Format,
}

/// `1-30`, `2,5,10`, `1-5,10`: positive integers, at most 10 000 of them.
pub fn parse_list(field: &str, s: &str) -> Result<Vec<usize>> {
    let bad = || {
        WingbeatError::invalid(
            field,
            s,
            "positive integers and ranges separated by commas, e.g. 1-30 or 2,5,10",
        )
    };
    let mut out = Vec::new();
    for part in s.split(',') {
        let part = part.trim();
        let (a, b) = match part.split_once('-') {
            Some((a, b)) => (a.trim(), b.trim()),
            None => (part, part),
        };
        let a: usize = a.parse().map_err(|_| bad())?;
        let b: usize = b.parse().map_err(|_| bad())?;
        if a == 0 || b < a || out.len() + (b - a + 1) > 10_000 {
            return Err(bad());
        }
        out.extend(a..=b);
    }
    Ok(out)
}

fn options(a: &ClassifyArgs) -> Result<ClassifyOptions> {
    let orientation = match a.orientation.as_str() {
        "causal" => Orientation::Causal,
        "published-code" => Orientation::PublishedCode,
        other => {
            return Err(WingbeatError::invalid(
                "--orientation",
                other,
                "causal or published-code",
            ))
        }
    };
    let threshold = match a.split.as_str() {
        "gaussian" => ThresholdRule::GaussianCrossing,
        "midpoint" => ThresholdRule::Midpoint,
        other => {
            return Err(WingbeatError::invalid(
                "--split",
                other,
                "gaussian or midpoint",
            ))
        }
    };
    Ok(ClassifyOptions {
        duration_s: a.duration,
        discard_s: a.discard,
        filter: Filter::published(orientation),
        nonlinearity: Nonlinearity::Sigmoid {
            gain: a.gain,
            threshold: a.threshold,
        },
        s0: a.s0,
        threshold,
        kept_modes: parse_list("--kept-modes", &a.kept_modes)?,
        random_counts: parse_list("--counts", &a.counts)?,
        random_draws: a.draws,
        seed: a.seed,
        ..ClassifyOptions::default()
    })
}

fn check_rate(field: &str, v: f64, lo: f64) -> Result<()> {
    if v.is_finite() && v >= lo && v.abs() <= 100.0 {
        Ok(())
    } else {
        Err(WingbeatError::invalid(
            field,
            v,
            format!("{lo} to 100 rad/s"),
        ))
    }
}

fn case(a: &ClassifyArgs) -> Result<ClassifyCase> {
    if a.preset != "mohren2018" {
        return Err(WingbeatError::invalid("--preset", &a.preset, "mohren2018"));
    }
    check_rate("--rotation", a.rotation, -100.0)?;
    check_rate("--flap-disturbance", a.flap_disturbance, 0.0)?;
    check_rate("--rotation-disturbance", a.rotation_disturbance, 0.0)?;
    wingbeat::error::check_range(
        "--air-density",
        a.air_density,
        0.0,
        wingbeat::aero::MAX_DENSITY,
        "kg/m³ (0 = vacuum, 1.2 air)",
    )?;
    let classes = mohren2018_classes(
        a.rotation,
        a.flap_disturbance,
        a.rotation_disturbance,
        a.seed,
    );
    if let Some(path) = &a.modes {
        let text = read_file(path)?;
        let doc = read_modes_document(&text, &path.display().to_string())?;
        let fe = doc.fe.ok_or_else(|| {
            WingbeatError::invalid(
                "--modes",
                path.display(),
                "a file written by `wingbeat modes` (it carries the mesh the sensors need)",
            )
        })?;
        let grid: Vec<(f64, f64)> = mohren2018_grid_mm()
            .into_iter()
            .filter(|&p| spanwise_sensors(&fe, &[p]).is_ok())
            .collect();
        let points: Vec<(f64, f64)> = if grid.len() >= 2 {
            grid
        } else {
            fe.nodes.iter().map(|p| (p[0] * 1e3, p[1] * 1e3)).collect()
        };
        return Ok(fluid(fe_case(&fe, classes, &points)?, &fe, a.air_density));
    }
    let (mut c, fe) = mohren2018_case(a.n_modes, a.mesh_size_mm, a.seed)?;
    c.classes = classes;
    Ok(fluid(c, &fe, a.air_density))
}

/// The case in the fluid of `--air-density` (checked in `case` before the FE solve), or as
/// it is in a vacuum.
fn fluid(c: ClassifyCase, fe: &wingbeat::fem::FemModes, rho: f64) -> ClassifyCase {
    if rho > 0.0 {
        in_fluid(c, fe, AeroConfig::with_density(rho))
    } else {
        c
    }
}

fn csv(r: &ClassifyReport) -> String {
    let mut out = String::from("strain,placement,kept_modes,sensors,accuracy,sd\n");
    for (name, c) in [("encoded", &r.encoded), ("raw", &r.raw)] {
        out.push_str(&format!(
            "{name},all,,{},{:.6},\n",
            r.sensors.len(),
            c.all_sensors
        ));
        for p in &c.sparse {
            out.push_str(&format!(
                "{name},sspoc,{},{},{:.6},\n",
                p.kept_modes,
                p.sensors.len(),
                p.accuracy
            ));
        }
        for p in &c.random {
            out.push_str(&format!(
                "{name},random,,{},{:.6},{:.6}\n",
                p.sensors, p.mean, p.sd
            ));
        }
        for p in &c.greedy {
            out.push_str(&format!(
                "{name},greedy,,{},{:.6},\n",
                p.sensors.len(),
                p.accuracy
            ));
        }
    }
    out
}

/// Runs the command; the JSON carries the report, the modes' frequencies and damping, and
/// the chosen sensors' positions.
pub fn run(a: ClassifyArgs) -> Result<String> {
    let opts = options(&a)?;
    let c = case(&a)?;
    let report = classify(&c, &opts)?;
    Ok(match a.format {
        Format::Csv => csv(&report),
        Format::Json => {
            let where_ =
                |s: &[usize]| -> Vec<[f64; 2]> { s.iter().map(|&i| report.sensors[i]).collect() };
            let sparse_positions: Vec<_> = report
                .encoded
                .sparse
                .iter()
                .map(|p| json!({"kept_modes": p.kept_modes, "positions_mm": where_(&p.sensors)}))
                .collect();
            to_json(&json!({
                "preset": a.preset,
                "modes": c.modes.iter().map(|m| json!({
                    "freq_hz": m.freq_hz, "zeta": m.zeta, "name": m.name,
                })).collect::<Vec<_>>(),
                "units": {"positions": "mm (x spanwise from the root, y chordwise)",
                          "air_density_kg_m3": "kg/m^3 (0 = vacuum)",
                          "accuracy": "fraction of test samples classed right (chance 0.5)",
                          "rates": "rad/s"},
                "rotation_rad_s": a.rotation,
                "flap_disturbance_rad_s": a.flap_disturbance,
                "rotation_disturbance_rad_s": a.rotation_disturbance,
                "air_density_kg_m3": a.air_density,
                "report": report,
                "encoded_sparse_positions": sparse_positions,
            }))?
        }
    })
}
