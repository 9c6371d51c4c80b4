//! `wingbeat sense`: where body rotation shows up in wing strain, and how many sensors it
//! takes to detect it (docs/sensing.md).

use super::{build_config, read_file, to_json, Format, SimInput};
use clap::{Args, ValueEnum};
use serde_json::json;
use wingbeat::analysis::psd::{welch, WelchOptions};
use wingbeat::analysis::sensing::{
    body_rate_vector, check_sensing_cost, delta_strain_series, modal_rotation_signal,
    modal_strains_at_points, sense_fe, DetectabilityMap, ModalSignal, Placement, SensingOptions,
    SensingResult, COMPONENTS,
};
use wingbeat::analysis::strain::{strain_series, StrainSeries};
use wingbeat::config::SimConfig;
use wingbeat::fem::{compute_modes, FemInput, FemModes};
use wingbeat::modes_doc::read_modes_document;
use wingbeat::{Result, WingbeatError};

#[derive(Args, Debug)]
pub struct SenseArgs {
    #[command(flatten)]
    input: SimInput,
    /// Sensors in the performance curve, 1–30.
    #[arg(long, default_value_t = 30)]
    k_max: usize,
    /// Sensor noise σ, rms strain per decimated sample, [1e-12, 1] (FE modes: true strain;
    /// paper modes: the table's non-SI units).
    #[arg(long, default_value_t = wingbeat::analysis::sensing::DEFAULT_NOISE)]
    noise: f64,
    /// Relative stroke variability ρ (the flapping strain's nuisance), [0, 1].
    #[arg(long, default_value_t = wingbeat::analysis::sensing::DEFAULT_RHO)]
    rho: f64,
    /// Samples per sensor in the detection vector, 8–4096.
    #[arg(long, default_value_t = wingbeat::analysis::sensing::DEFAULT_SAMPLES_PER_SENSOR)]
    samples_per_sensor: usize,
    /// Points for the Δε series and spectrum, `X,Y;X,Y;…` in mm. Default: the 3 best sensors'
    /// nodes (FE), or the modes' named strain points (paper table).
    #[arg(long, value_name = "X,Y;…")]
    points: Option<String>,
    /// FE modes of the `fe-wing` preset when no --modes file is given: how many, 1–64.
    #[arg(long, default_value_t = wingbeat::presets::FE_WING_MODES)]
    fe_modes: usize,
    /// Element size of the `fe-wing` preset's mesh, mm (default: automatic, 1 mm).
    #[arg(long)]
    mesh_size_mm: Option<f64>,
    /// Output format: json (everything) or csv (one table, --table).
    #[arg(long, value_enum, default_value = "json")]
    format: Format,
    /// The CSV table: series (Δε at the points), map (per node), sensors, curve (d', P_d vs K).
    #[arg(long, value_enum, default_value = "series")]
    table: Table,
}

#[derive(Copy, Clone, Debug, ValueEnum, PartialEq)]
enum Table {
    Series,
    Map,
    Sensors,
    Curve,
}

/// The body rate of the sensing runs: the shared `--body-rate X,Y,Z` flag (rad/s, body
/// axes), default 0,0,1 (1 rad/s about the yaw axis K).
fn body_rate_of(v: &[f64]) -> Result<[f64; 3]> {
    if v.is_empty() {
        return Ok([0.0, 0.0, 1.0]);
    }
    body_rate_vector("--body-rate", v)
}

fn parse_points(s: &str) -> Result<Vec<(f64, f64)>> {
    let bad = |p: &str| {
        WingbeatError::invalid(
            "--points",
            p,
            "X,Y;X,Y;… in mm with finite numbers, e.g. 3,-6;20,-10 (1 to 256 points)",
        )
    };
    let pts: Vec<(f64, f64)> = s
        .split(';')
        .filter(|p| !p.trim().is_empty())
        .map(|p| {
            let (x, y) = p.split_once(',').ok_or_else(|| bad(p))?;
            let x: f64 = x.trim().parse().map_err(|_| bad(p))?;
            let y: f64 = y.trim().parse().map_err(|_| bad(p))?;
            if x.is_finite() && y.is_finite() {
                Ok((x, y))
            } else {
                Err(bad(p))
            }
        })
        .collect::<Result<_>>()?;
    if pts.is_empty() || pts.len() > wingbeat::model::MAX_STRAIN_POINTS {
        return Err(bad(s));
    }
    Ok(pts)
}

/// The FE wing, when there is one: a `wingbeat modes` document given with --modes, or the
/// `fe-wing` preset computed here.
fn fe_of(a: &SenseArgs) -> Result<Option<FemModes>> {
    if let Some(p) = &a.input.modes {
        let doc = read_modes_document(&read_file(p)?, &p.display().to_string())?;
        return Ok(doc.fe);
    }
    if a.input.preset == "fe-wing" {
        let input = FemInput {
            n_modes: a.fe_modes,
            mesh_size_mm: a.mesh_size_mm,
            ..Default::default()
        };
        if a.fe_modes == 0 || a.fe_modes > wingbeat::model::MAX_MODES {
            return Err(WingbeatError::invalid(
                "--fe-modes",
                a.fe_modes,
                format!("an integer in [1, {}]", wingbeat::model::MAX_MODES),
            ));
        }
        eprintln!("sense: computing the fe-wing preset's shell FE modes…");
        return Ok(Some(compute_modes(&input)?));
    }
    if a.mesh_size_mm.is_some() {
        return Err(WingbeatError::invalid(
            "--mesh-size-mm",
            "given without an FE wing",
            "only with --preset fe-wing",
        ));
    }
    Ok(None)
}

pub fn run(a: SenseArgs) -> Result<String> {
    let w = body_rate_of(&a.input.body_rate)?;
    let opts = SensingOptions {
        k_max: a.k_max,
        rho: a.rho,
        noise: a.noise,
        samples_per_sensor: a.samples_per_sensor,
    };
    opts.validate_named(["--k-max", "--rho", "--noise", "--samples-per-sensor"])?;
    let user_points = a.points.as_deref().map(parse_points).transpose()?;
    let fe = fe_of(&a)?;
    let cfg = sensing_config(&a, fe.as_ref())?;
    // points outside the wing are refused before any run
    if let (Some(fe), Some(pts)) = (&fe, &user_points) {
        for &(x, y) in pts {
            modal_strains_at_points(fe, &[(x, y)]).map_err(|e| {
                WingbeatError::invalid("--points", format!("{x},{y} mm"), e.to_string())
            })?;
        }
    }
    let n_nodes = fe.as_ref().map_or(0, |f| f.nodes.len());
    let n_points = user_points.as_ref().map_or(3, Vec::len);
    check_sensing_cost(&cfg, w, n_nodes, n_points, "sense")?;
    eprintln!(
        "sense: two runs of {} modes ({} samples), with and without ω_b = ({}, {}, {}) rad/s…",
        cfg.modes.len(),
        cfg.n_samples(),
        w[0],
        w[1],
        w[2]
    );
    let t0 = std::time::Instant::now();
    let sig = modal_rotation_signal(&cfg, w)?;
    for warning in &sig.warnings {
        eprintln!("warning: {warning}");
    }
    let Some(fe) = fe else {
        return modal_only(&a, &cfg, &sig);
    };
    eprintln!(
        "sense: detectability map and greedy placement over {} nodes × 3 components…",
        fe.nodes.len()
    );
    let res = sense_fe(&fe, &sig, &opts)?;
    let pts: Vec<(f64, f64)> = match user_points {
        Some(p) => p,
        None => res
            .placement
            .sensors
            .iter()
            .take(3)
            .map(|s| (s.x_mm, s.y_mm))
            .collect(),
    };
    let modal = modal_strains_at_points(&fe, &pts)?;
    let names: Vec<String> = pts.iter().map(|(x, y)| format!("({x},{y})")).collect();
    let series = delta_strain_series(&names, &modal, &sig)?;
    let elapsed = t0.elapsed().as_secs_f64();
    eprintln!("sense: done in {elapsed:.2} s");
    match (a.format, a.table) {
        (Format::Csv, Table::Series) => Ok(series_csv(&sig.t, &series)),
        (Format::Csv, Table::Map) => Ok(map_csv(&fe, &res.map)),
        (Format::Csv, Table::Sensors) => Ok(sensors_csv(&res.placement)),
        (Format::Csv, Table::Curve) => Ok(curve_csv(&res.placement)),
        (Format::Json, _) => fe_json(FeReport {
            body_rate: w,
            options: opts,
            cfg: &cfg,
            elapsed,
            fe: &fe,
            res: &res,
            pts: &pts,
            series: &series,
            sig: &sig,
        }),
    }
}

/// The config of the two runs: the input's, with the FE modes (when computed here) in place of
/// the preset's, keeping --zeta; the FE wing's shapes attached, then the medium; the body
/// rate left to the runs (they set it themselves, with and without it).
fn sensing_config(a: &SenseArgs, fe: Option<&FemModes>) -> Result<SimConfig> {
    let mut input = a.input.clone();
    input.body_rate.clear();
    if input.preset == "fe-wing" && input.modes.is_none() {
        input.preset = "paper".into();
    }
    // The medium is applied once the FE wing's shapes are attached (air needs them).
    let air = input.air_density.take();
    let mut cfg = build_config(&input)?;
    if let (Some(fe), None) = (fe, &a.input.modes) {
        cfg.modes = fe.to_modes(a.input.zeta.unwrap_or(0.0), &[]);
        cfg.initial_conditions.truncate(cfg.modes.len());
        cfg.validate()?;
    }
    if let Some(fe) = fe {
        cfg.wing = Some(std::sync::Arc::new(wingbeat::aero::WingGeometry::from_fem(
            fe,
        )));
    }
    if air.is_some() {
        super::apply_air_density(&mut cfg, air)?;
        cfg.validate()?;
    }
    if let Some(fe) = fe {
        if fe.strain_nodes.len() != cfg.modes.len() {
            return Err(WingbeatError::invalid(
                "--modes",
                format!("{} FE modes", fe.strain_nodes.len()),
                format!("the {} modes of the config", cfg.modes.len()),
            ));
        }
    }
    Ok(cfg)
}

/// `--table map`: one row per node with its detectability and energies per component.
fn map_csv(fe: &FemModes, m: &DetectabilityMap) -> String {
    let mut out = String::from("node,x_mm,y_mm,d_eps_x,d_eps_y,d_gamma_xy,e_delta_eps_x,e_delta_eps_y,e_delta_gamma_xy,e_flap_eps_x,e_flap_eps_y,e_flap_gamma_xy,best_component\n");
    for (i, p) in fe.nodes.iter().enumerate() {
        out.push_str(&format!(
            "{i},{:.6},{:.6},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{}\n",
            p[0] * 1e3,
            p[1] * 1e3,
            m.d[i][0],
            m.d[i][1],
            m.d[i][2],
            m.e_delta[i][0],
            m.e_delta[i][1],
            m.e_delta[i][2],
            m.e_flap[i][0],
            m.e_flap[i][1],
            m.e_flap[i][2],
            COMPONENTS[m.best_component[i]]
        ));
    }
    out
}

/// `--table sensors`: the greedy sensors in rank order.
fn sensors_csv(pl: &Placement) -> String {
    let mut out = String::from("rank,node,component,x_mm,y_mm,d\n");
    for s in &pl.sensors {
        out.push_str(&format!(
            "{},{},{},{:.6},{:.6},{:.9e}\n",
            s.rank, s.node, s.component, s.x_mm, s.y_mm, s.d
        ));
    }
    out
}

/// `--table curve`: d′ and the detection probability against the number of sensors K.
fn curve_csv(pl: &Placement) -> String {
    let mut out = String::from("k,d_prime,pd,d_prime_ranked\n");
    for (k, (d, p)) in pl.d_prime.iter().zip(&pl.pd).enumerate() {
        out.push_str(&format!(
            "{},{d:.9e},{p:.9},{:.9e}\n",
            k + 1,
            pl.d_prime_ranked[k]
        ));
    }
    out
}

/// What an FE wing's sensing run produced, for its JSON.
struct FeReport<'a> {
    body_rate: [f64; 3],
    options: SensingOptions,
    cfg: &'a SimConfig,
    elapsed: f64,
    fe: &'a FemModes,
    res: &'a SensingResult,
    pts: &'a [(f64, f64)],
    series: &'a [(StrainSeries, StrainSeries)],
    sig: &'a ModalSignal,
}

/// The JSON of an FE wing's run: everything, with Δε and its spectra at each point.
fn fe_json(r: FeReport<'_>) -> Result<String> {
    let sig = r.sig;
    let fd = sig.flap_freq_hz;
    let wopts = WelchOptions {
        segment_len: sig.t.len().clamp(8, 8192),
        ..Default::default()
    };
    let mut points = Vec::new();
    for ((x, y), (d, _)) in r.pts.iter().zip(r.series) {
        points.push(SensePoint {
            delta_strain: d,
            spectrum: Spectra {
                eps_x: welch(&d.eps_x, sig.sample_rate_hz, &wopts, Some(fd))?,
                eps_y: welch(&d.eps_y, sig.sample_rate_hz, &wopts, Some(fd))?,
                gamma_xy: welch(&d.gamma_xy, sig.sample_rate_hz, &wopts, Some(fd))?,
            },
            x_mm: *x,
            y_mm: *y,
        });
    }
    // Written straight from the results (a `serde_json::Value` of the series took several
    // times the memory of the text). Keys in alphabetical order, as before.
    #[derive(serde::Serialize)]
    struct Out<'a> {
        air_density_kg_m3: f64,
        body_rate: [f64; 3],
        elapsed_s: f64,
        flap_freq_hz: f64,
        map: &'a DetectabilityMap,
        n_nodes: usize,
        nodes_mm: Vec<[f64; 2]>,
        options: SensingOptions,
        placement: &'a Placement,
        points: Vec<SensePoint<'a>>,
        sample_rate_hz: f64,
        t: &'a [f64],
        units: serde_json::Value,
        warnings: &'a [String],
    }
    to_json(&Out {
        air_density_kg_m3: r.cfg.aero.air_density_kg_m3,
        body_rate: r.body_rate,
        elapsed_s: r.elapsed,
        flap_freq_hz: fd,
        map: &r.res.map,
        n_nodes: r.fe.nodes.len(),
        nodes_mm: r
            .fe
            .nodes
            .iter()
            .map(|p| [p[0] * 1e3, p[1] * 1e3])
            .collect(),
        options: r.options,
        placement: &r.res.placement,
        points,
        sample_rate_hz: sig.sample_rate_hz,
        t: &sig.t,
        units: json!({
            "air_density_kg_m3": "kg/m³ of the medium both runs are in (0 = vacuum)",
            "body_rate": "rad/s, body axes (I roll, J pitch, K yaw)",
            "strain": "dimensionless (FE modes, SI)",
            "x_mm": "mm, spanwise from the root", "y_mm": "mm, chordwise",
            "d": "E_delta / (rho^2 E_flap + noise^2), per node and component (eps_x, eps_y, gamma_xy)",
            "d_prime": "sqrt(Delta^T (rho^2 F F^T + noise^2 I)^-1 Delta), stacked decimated series",
            "pd": "detection probability at a 1 % false-alarm rate",
            "psd": "strain^2 / Hz, one-sided Welch",
        }),
        warnings: &sig.warnings,
    })
}

/// One point of `wingbeat sense`'s JSON: Δε there and its spectra.
#[derive(serde::Serialize)]
struct SensePoint<'a> {
    delta_strain: &'a StrainSeries,
    spectrum: Spectra,
    x_mm: f64,
    y_mm: f64,
}

/// The spectra of the three strain components.
#[derive(serde::Serialize)]
struct Spectra {
    eps_x: wingbeat::analysis::psd::Spectrum,
    eps_y: wingbeat::analysis::psd::Spectrum,
    gamma_xy: wingbeat::analysis::psd::Spectrum,
}

fn series_csv(t: &[f64], series: &[(StrainSeries, StrainSeries)]) -> String {
    let mut out = String::from("t_s");
    for (d, _) in series {
        for c in COMPONENTS {
            out.push_str(&format!(",d_{c}_{}", d.point.replace(',', " ")));
        }
    }
    out.push('\n');
    for (i, ti) in t.iter().enumerate() {
        out.push_str(&format!("{ti:.9e}"));
        for (d, _) in series {
            out.push_str(&format!(
                ",{:.12e},{:.12e},{:.12e}",
                d.eps_x[i], d.eps_y[i], d.gamma_xy[i]
            ));
        }
        out.push('\n');
    }
    out
}

/// Paper-table modes (no strain field): the modal signal Δq and Δε at the modes' named
/// strain points; no map or placement.
fn modal_only(a: &SenseArgs, cfg: &SimConfig, sig: &ModalSignal) -> Result<String> {
    if a.points.is_some() {
        return Err(WingbeatError::invalid(
            "--points",
            "given without an FE wing",
            "only with an FE wing (--preset fe-wing or --modes FILE from `wingbeat modes`); the paper table has strains only at its named points",
        ));
    }
    let dq: Vec<&[f64]> = sig.delta.iter().map(Vec::as_slice).collect();
    let pts = strain_series(&cfg.modes, &dq);
    eprintln!("sense: no FE strain field (paper-table modes): modal signal and named points only");
    match a.format {
        Format::Csv => {
            let pairs: Vec<(StrainSeries, StrainSeries)> =
                pts.iter().map(|p| (p.clone(), p.clone())).collect();
            Ok(series_csv(&sig.t, &pairs))
        }
        Format::Json => {
            #[derive(serde::Serialize)]
            struct Out<'a> {
                body_rate: [f64; 3],
                delta_q: &'a [Vec<f64>],
                flap_freq_hz: f64,
                note: &'static str,
                points: &'a [StrainSeries],
                sample_rate_hz: f64,
                t: &'a [f64],
                units: serde_json::Value,
                warnings: &'a [String],
            }
            to_json(&Out {
                body_rate: sig.body_rate,
                delta_q: &sig.delta,
                flap_freq_hz: sig.flap_freq_hz,
                note: "paper-table modes carry strain only at named points: no detectability map or sensor placement (use --preset fe-wing or --modes FILE from `wingbeat modes`)",
                points: &pts,
                sample_rate_hz: sig.sample_rate_hz,
                t: &sig.t,
                units: json!({
                    "body_rate": "rad/s, body axes (I roll, J pitch, K yaw)",
                    "delta_q": "the modes' units (paper table: not SI)",
                    "strain": "the table's modal-strain units times q (not SI)",
                }),
                warnings: &sig.warnings,
            })
        }
    }
}
