//! `wingbeat modes`: shell FE modes of a planform (paper §3.1), JSON out.

use clap::Args;
use wingbeat::fem::{
    compute_modes, modes_document, parse_planform_csv, parse_planform_json, strain_point_for,
    Clamp, FemInput, FemModes, ShellMaterial,
};
use wingbeat::model::Mode;
use wingbeat::{Result, WingbeatError};

#[derive(Args, Debug, Clone)]
pub struct ModesArgs {
    /// Built-in plate instead of the wing: `mohren2018`, the sensing plate of Mohren et al.
    /// 2018 / Weber et al. 2021 (Eberle et al. 2015): flat 50 × 25 mm, the 25 mm root edge
    /// clamped, acrylic E = 3 GPa, ν = 0.35, 0.127 mm, 1180 kg/m³, each mode damped at
    /// ζ_k = 63/(2ω_k) (their C = 63 s⁻¹·M). Not with --planform, --camber, --clamp or
    /// --material; --thickness-um, --e-pa, --rho and --nu still override its material.
    #[arg(long, conflicts_with_all = ["planform", "camber", "clamp", "material"])]
    pub preset: Option<String>,
    /// Planform outline: CSV (`x_mm,y_mm` or `i,x_mm,y_mm`, `#` comments) or JSON `[[x,y],…]`, mm.
    /// Default: the built-in SYNTHETIC Manduca-like outline (not digitised from a specimen).
    #[arg(long, value_name = "FILE")]
    pub planform: Option<std::path::PathBuf>,
    /// Camber rise as a fraction of the local chord (circular arc), [0, 0.5].
    #[arg(long, default_value_t = 0.13)]
    pub camber: f64,
    /// Root boundary condition: `root` (clamp the root edge on x = 0) or `strip:X_MM`
    /// (clamp every node with x ≤ X_MM). f2/f1 depends strongly on it.
    #[arg(long, default_value = "root")]
    pub clamp: String,
    /// Material preset: `paper-frequencies` (E = 13.11 GPa, reproduces f1 ≈ 62.5 Hz) or
    /// `paper-as-printed` (E = 10 MPa as in Table 2 — a unit slip, f1 ≈ 1.7 Hz).
    #[arg(long, default_value = "paper-frequencies")]
    pub material: String,
    /// Thickness, µm (overrides the preset).
    #[arg(long, allow_negative_numbers = true)]
    pub thickness_um: Option<f64>,
    /// Young's modulus, Pa (overrides the preset).
    #[arg(long, allow_negative_numbers = true)]
    pub e_pa: Option<f64>,
    /// Density, kg/m³ (overrides the preset).
    #[arg(long, allow_negative_numbers = true)]
    pub rho: Option<f64>,
    /// Poisson's ratio, (−1, 0.5) (overrides the preset).
    #[arg(long, allow_negative_numbers = true)]
    pub nu: Option<f64>,
    /// Number of modes, 1–64.
    #[arg(long, default_value_t = 6)]
    pub n_modes: usize,
    /// Target element edge, mm. Default: automatic from the planform's area (about 1 000
    /// nodes' worth; 1.0 mm for the default wing), printed on stderr. The mesh is refused
    /// above 20 000 nodes (the error names a size that fits).
    #[arg(long, allow_negative_numbers = true)]
    pub mesh_size_mm: Option<f64>,
    /// Strain point(s) `NAME:X_MM,Y_MM` carried into the `modes` array for `simulate --modes`.
    /// Default: `P:3,-6` on the default outline; on any other outline a point P inside the
    /// wing, 1/8 of the span out from the root (or from a strip clamp's edge), mid-chord.
    #[arg(long = "point", value_name = "NAME:X,Y")]
    pub points: Vec<String>,
}

fn parse_point(s: &str) -> Result<(String, f64, f64)> {
    let bad = || {
        WingbeatError::invalid(
            "--point",
            s,
            "NAME:X_MM,Y_MM with finite numbers, e.g. P:3,-6",
        )
    };
    let (name, xy) = s.split_once(':').ok_or_else(bad)?;
    let (x, y) = xy.split_once(',').ok_or_else(bad)?;
    let x: f64 = x.trim().parse().map_err(|_| bad())?;
    let y: f64 = y.trim().parse().map_err(|_| bad())?;
    if name.is_empty() || !x.is_finite() || !y.is_finite() {
        return Err(bad());
    }
    Ok((name.to_string(), x, y))
}

/// Builds the FE input from the flags (file reading happens here, not in the core).
pub fn fem_input(
    a: &ModesArgs,
    read: impl Fn(&std::path::Path) -> Result<String>,
) -> Result<FemInput> {
    let mut input = match a.preset.as_deref() {
        None => FemInput::default(),
        Some(MOHREN2018) => wingbeat::presets::mohren2018_plate_input(None, a.n_modes),
        Some(other) => return Err(WingbeatError::invalid("--preset", other, MOHREN2018)),
    };
    if let Some(p) = &a.planform {
        let text = read(p)?;
        let is_json = p
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("json"))
            || text.trim_start().starts_with('[');
        input.planform_mm = if is_json {
            parse_planform_json(&text)?
        } else {
            parse_planform_csv(&text)?
        };
        input.planform_note = format!("user outline from {}", p.display());
    }
    if a.preset.is_none() {
        input.camber = a.camber;
        input.clamp = Clamp::parse(&a.clamp)
            .map_err(|_| WingbeatError::invalid("--clamp", &a.clamp, "root | strip:X_MM"))?;
        input.material = match a.material.as_str() {
            "paper-frequencies" => ShellMaterial::paper_frequencies(),
            "paper-as-printed" => ShellMaterial::paper_as_printed(),
            other => {
                return Err(WingbeatError::invalid(
                    "--material",
                    other,
                    "paper-frequencies | paper-as-printed",
                ))
            }
        };
    }
    if let Some(t) = a.thickness_um {
        input.material.thickness_m = t * 1e-6;
    }
    if let Some(e) = a.e_pa {
        input.material.e_pa = e;
    }
    if let Some(r) = a.rho {
        input.material.rho_kg_m3 = r;
    }
    if let Some(n) = a.nu {
        input.material.nu = n;
    }
    input.n_modes = a.n_modes;
    input.mesh_size_mm = a.mesh_size_mm;
    Ok(input)
}

/// The strain points requested (default: P = [`strain_point_for`] the input).
pub fn points(a: &ModesArgs, input: &FemInput) -> Result<Vec<(String, f64, f64)>> {
    if a.points.is_empty() {
        let (x, y) = strain_point_for(input);
        return Ok(vec![("P".into(), x, y)]);
    }
    a.points.iter().map(|s| parse_point(s)).collect()
}

/// The `--preset` value of the published sensing plate.
const MOHREN2018: &str = "mohren2018";

/// Model modes with strains at the points; a point outside the wing is an error naming it.
/// Undamped, except with `--preset mohren2018`: ζ_k = 63/(2ω_k), the published damping.
pub fn model_modes(a: &ModesArgs, fe: &FemModes, pts: &[(String, f64, f64)]) -> Result<Vec<Mode>> {
    let mut modes = fe.model_modes(0.0, pts, "--point")?;
    if a.preset.as_deref() == Some(MOHREN2018) {
        let zetas = wingbeat::presets::mohren2018_damping_ratios(&fe.freq_hz)?;
        for (m, z) in modes.iter_mut().zip(zetas) {
            m.zeta = z;
        }
    }
    Ok(modes)
}

/// Runs `wingbeat modes`.
pub fn run(a: &ModesArgs, read: impl Fn(&std::path::Path) -> Result<String>) -> Result<String> {
    let input = fem_input(a, read)?;
    let pts = points(a, &input)?;
    let size = match input.mesh_size_mm {
        Some(h) => format!("{h} mm elements"),
        None => "automatic element size".to_string(),
    };
    eprintln!(
        "modes: meshing and solving ({} modes, {size})…",
        input.n_modes
    );
    let t0 = std::time::Instant::now();
    let fe = compute_modes(&input)?;
    eprintln!(
        "modes: mesh size {} mm{}, {} nodes, {} DOFs, done in {:.2} s",
        fe.mesh_size_mm,
        if input.mesh_size_mm.is_none() {
            " (automatic)"
        } else {
            ""
        },
        fe.nodes.len(),
        fe.n_dofs,
        t0.elapsed().as_secs_f64()
    );
    let modes = model_modes(a, &fe, &pts)?;
    modes_document(&fe, &modes)
}
