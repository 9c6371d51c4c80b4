//! Shell finite-element model of the wing: the natural frequencies ω_k, mass-normalised mode
//! shapes φ_k, the in-plane vectors a_k, b_k and the modal strains that the modal model of
//! Eq. 13 needs (paper §3.1, Eqs. 9–12 and 14–18).
//!
//! Pipeline: outline (mm) → [`geometry::validate_outline`] → quality constrained Delaunay mesh
//! with camber lifted onto z ([`mesh::mesh_planform`]) → flat DKT + membrane shell triangles
//! ([`element`]) → skyline assembly with RCM ordering ([`assembly`]) → shift-invert block
//! Krylov eigen-solve ([`eigen`]) → [`FemModes`].
//!
//! # Intended CLI (`wingbeat modes`, wired by the CLI module) → [`FemInput`] fields
//!
//! | flag | field |
//! |---|---|
//! | `--planform FILE` (`.csv` with `x_mm,y_mm` / `i,x_mm,y_mm`, or `.json` `[[x,y],...]`) | `planform_mm` via [`parse_planform_csv`] / [`parse_planform_json`]; `planform_note` = the file name |
//! | `--camber 0.13` | `camber` (rise / local chord) |
//! | `--clamp root` or `--clamp strip:X_MM` | `clamp` via [`Clamp::parse`] |
//! | `--thickness-um 81` | `material.thickness_m` = value × 1e-6 |
//! | `--e-pa 1.2e10` | `material.e_pa` |
//! | `--rho 860` | `material.rho_kg_m3` |
//! | `--nu 0.3` | `material.nu` |
//! | `--n-modes 6` | `n_modes` |
//! | `--mesh-size-mm 1.0` (default: automatic, [`default_mesh_size_mm`]) | `mesh_size_mm` (target triangle edge; `None` = automatic) |
//! | (none; the CLI keeps [`MAX_NODES`]) | `max_nodes` (node cap; `None` = [`MAX_NODES`]) |
//!
//! As JSON (`serde`), `clamp` is `"root"`, `"free"` or `{"strip": {"x_mm": 3.0}}`; every
//! field is optional and missing ones take their default (`mesh_size_mm` and `max_nodes`
//! missing or `null`: automatic size, CLI cap), e.g.
//! `{"n_modes": 4, "clamp": {"strip": {"x_mm": 3.0}}, "material": {"thickness_m": 8.1e-5,
//! "e_pa": 1.311e10, "rho_kg_m3": 860.0, "nu": 0.3}}`.
//!
//! Everything else defaults to [`FemInput::default`] (the synthetic Manduca-like wing, the
//! "paper-frequencies" material, root clamp, 6 modes). Output: `serde_json` of [`FemModes`].

// Element and assembly code indexes several parallel arrays per loop; ranges read clearer.
#![allow(clippy::needless_range_loop)]

pub mod assembly;
pub mod blocksparse;
pub mod eigen;
pub mod element;
pub mod geometry;
pub mod linalg;
pub mod locate;
pub mod mesh;
pub mod sparse;

pub use eigen::EigenOptions;
pub use element::ShellMaterial;
pub use geometry::{manduca_planform, parse_planform_csv, parse_planform_json, rectangle_planform};
pub use linalg::Backend;
pub use mesh::{Mesh, MeshOptions, MAX_NODES};

use crate::error::{Result, WingbeatError};
use crate::model::{ModalStrain, Mode};
use element::{corner_surface_strain, Vec18};
use serde::{Deserialize, Serialize};

/// Young's modulus of the "paper-frequencies" preset, Pa: chosen so that the default wing
/// (default mesh, 13 % camber, root clamp) has f1 ≈ 62.5 Hz, the paper's mode-1 frequency.
pub const PAPER_FREQUENCIES_E_PA: f64 = 1.311e10;

impl ShellMaterial {
    /// "paper-as-printed": t = 81 µm, E = 10 MPa, ρ = 860 kg/m³, ν = 0.3 exactly as the paper
    /// prints them (Table 2). E = 10 MPa is a unit slip: the default wing then has f1 ≈ 1.73 Hz,
    /// not the paper's 62.5 Hz.
    pub fn paper_as_printed() -> ShellMaterial {
        ShellMaterial {
            thickness_m: 81e-6,
            e_pa: 10e6,
            rho_kg_m3: 860.0,
            nu: 0.3,
        }
    }

    /// "paper-frequencies": the printed values with E = [`PAPER_FREQUENCIES_E_PA`] (GPa range),
    /// calibrated so that the default wing's f1 lands at the paper's 62.5 Hz.
    pub fn paper_frequencies() -> ShellMaterial {
        ShellMaterial {
            e_pa: PAPER_FREQUENCIES_E_PA,
            ..ShellMaterial::paper_as_printed()
        }
    }

    /// Checks every field against its physical range, [`crate::params::MATERIAL_RANGES`]
    /// (thickness 1e-7 ..= 1 m, E 1e3 ..= 1e13 Pa, ρ 1 ..= 1e5 kg/m³, −1 < ν < 0.5); the error
    /// names the field (`material.e_pa`) and its range.
    pub fn validate(&self) -> Result<()> {
        for (field, v) in [
            ("material.thickness_m", self.thickness_m),
            ("material.e_pa", self.e_pa),
            ("material.rho_kg_m3", self.rho_kg_m3),
            ("material.nu", self.nu),
        ] {
            // every field has a range (tests/clear_errors_and_url_ranges.rs checks the table)
            if let Some(r) = crate::ranges::material_range(field) {
                r.check(v)?;
            }
        }
        Ok(())
    }
}

/// Root boundary condition (how the wing is held; f2/f1 depends strongly on it). Unknown
/// fields inside a variant (`{"strip": {"x_mm": 1, "extra": 2}}`) are errors.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Clamp {
    /// Clamp (all 6 DOFs) the nodes on the outline's root edge(s) lying on x = 0.
    Root,
    /// Clamp every node with x ≤ `x_mm` (a basal strip).
    Strip {
        /// Strip width from the root, mm.
        x_mm: f64,
    },
    /// No support (free structure; six rigid-body modes). Used by verification.
    Free,
}

impl Clamp {
    /// Parses the CLI form: `root`, `free`, or `strip:X_MM`.
    pub fn parse(s: &str) -> Result<Clamp> {
        let t = s.trim().to_ascii_lowercase();
        match t.as_str() {
            "root" => Ok(Clamp::Root),
            "free" => Ok(Clamp::Free),
            _ => {
                if let Some(v) = t.strip_prefix("strip:") {
                    let x: f64 = v.trim().parse().map_err(|_| {
                        WingbeatError::invalid("clamp", s, "root | free | strip:X_MM")
                    })?;
                    Ok(Clamp::Strip { x_mm: x })
                } else {
                    Err(WingbeatError::invalid(
                        "clamp",
                        s,
                        "root | free | strip:X_MM",
                    ))
                }
            }
        }
    }
}

/// Everything the shell FE step needs. `Default` is the paper's case: the synthetic
/// Manduca-like outline, 13 % camber, root clamp, "paper-frequencies" material, 6 modes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct FemInput {
    /// Outline, mm, x spanwise from the root, y chordwise (chord toward −y).
    pub planform_mm: Vec<[f64; 2]>,
    /// Where the outline came from (copied to the output).
    pub planform_note: String,
    /// Camber rise as a fraction of the local chord (circular arc), 0 ..= 0.5.
    pub camber: f64,
    /// Root boundary condition.
    pub clamp: Clamp,
    /// Shell material.
    pub material: ShellMaterial,
    /// Number of modes, 1 ..= 64.
    pub n_modes: usize,
    /// Target triangle edge length, mm; `None` (JSON: missing or `null`) = automatic from
    /// the planform's area ([`default_mesh_size_mm`]).
    pub mesh_size_mm: Option<f64>,
    /// Largest node count accepted, checked after meshing and before assembly; `None` =
    /// [`MAX_NODES`] (the CLI's cap). 1 ..= [`MAX_NODES`]. The browser lab passes
    /// [`BROWSER_MAX_NODES`].
    pub max_nodes: Option<usize>,
}

/// The default strain point P near the wing base, (x, y) in mm: the paper's Table 6 point is
/// not given in coordinates, so wingbeat picks one at mid-root-chord, 3 mm out from the root.
/// It applies to the default outline only; see [`default_strain_point_mm`].
pub const STRAIN_POINT_P_MM: (f64, f64) = (3.0, -6.0);

/// The element size the automatic rule gives the default wing, mm (the size its material
/// was calibrated at; `default_mesh_size_mm(&manduca_planform())` returns it).
pub const DEFAULT_MESH_SIZE_MM: f64 = 1.0;

/// Target node count of the automatic mesh size: [`default_mesh_size_mm`] picks the edge h
/// at which equilateral triangles would fill the planform's area with this many nodes.
pub const AUTO_MESH_NODES: f64 = 1000.0;

/// Node cap of the browser (wasm `feModes`), below the CLI's [`MAX_NODES`]: a wasm
/// instance that runs out of memory aborts, and the solve time grows like N^1.5–N^2.
/// See docs/fem.md ("Node caps") for the measured memory behind it.
pub const BROWSER_MAX_NODES: usize = 6000;

/// The automatic element size for an outline (mm): the edge h of equilateral triangles that
/// would cover the outline's area A with [`AUTO_MESH_NODES`] nodes, h = √(2A / (√3·N)),
/// rounded to two significant digits (so it prints cleanly and is reproducible). Scales
/// with the planform: 1.0 mm for the default wing (8.70 cm²), 0.68 mm for a 40 × 10 mm
/// strip, 340 mm for a 10 m square plate. The mesher grades finer toward a root edge, so the
/// actual node count is higher (1 653 nodes for the default wing). Returns NaN for an
/// outline without area (which [`compute_modes`] rejects first).
pub fn default_mesh_size_mm(outline: &[[f64; 2]]) -> f64 {
    let area = geometry::signed_area(outline).abs();
    if !(area.is_finite() && area > 0.0) {
        return f64::NAN;
    }
    round_2sig((2.0 * area / (3f64.sqrt() * AUTO_MESH_NODES)).sqrt())
}

/// Rounds a positive number to two significant digits.
fn round_2sig(h: f64) -> f64 {
    let k = 1 - h.log10().floor() as i32;
    if k >= 0 {
        let s = 10f64.powi(k);
        (h * s).round() / s
    } else {
        let s = 10f64.powi(-k);
        (h / s).round() * s
    }
}

/// The default strain point (x, y), mm, for an outline: the paper's P
/// ([`STRAIN_POINT_P_MM`]) for the default outline (exactly [`manduca_planform`]); for any
/// other outline the middle of the longest inside piece of the chordwise line one eighth of
/// the span out from the outline's innermost x. That point lies strictly inside the
/// outline, so it is inside the meshed planform whatever the mesh.
pub fn default_strain_point_mm(outline: &[[f64; 2]]) -> (f64, f64) {
    if outline == manduca_planform().as_slice() {
        return STRAIN_POINT_P_MM;
    }
    strain_point_beyond(outline, f64::NEG_INFINITY)
}

/// [`default_strain_point_mm`] for a whole input: with a basal strip clamp the station is
/// one eighth of the free span out from the strip's edge (a point in the clamped strip
/// would have no strain). The default outline keeps P whatever the clamp.
pub fn strain_point_for(input: &FemInput) -> (f64, f64) {
    if input.planform_mm == manduca_planform() {
        return STRAIN_POINT_P_MM;
    }
    match input.clamp {
        Clamp::Strip { x_mm } if x_mm.is_finite() => strain_point_beyond(&input.planform_mm, x_mm),
        _ => strain_point_beyond(&input.planform_mm, f64::NEG_INFINITY),
    }
}

fn strain_point_beyond(outline: &[[f64; 2]], x_from: f64) -> (f64, f64) {
    let (lo, hi) = outline
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
            (l.min(p[0]), h.max(p[0]))
        });
    let lo = lo.max(x_from);
    if !(lo.is_finite() && hi.is_finite()) || outline.is_empty() {
        return (0.0, 0.0);
    }
    // the line at 1/8 of the span, else (a thin or odd outline) the first station with an
    // inside piece
    for frac in [0.125, 0.25, 0.0625, 0.5, 0.375, 0.625, 0.75, 0.875] {
        let x = lo + frac * (hi - lo);
        let best = mesh::inside_intervals(outline, x)
            .into_iter()
            .max_by(|a, b| (a.1 - a.0).total_cmp(&(b.1 - b.0)));
        if let Some((y0, y1)) = best {
            return (x, 0.5 * (y0 + y1));
        }
    }
    let n = outline.len() as f64;
    let c = outline
        .iter()
        .fold([0.0, 0.0], |c, p| [c[0] + p[0] / n, c[1] + p[1] / n]);
    (c[0], c[1])
}

impl Default for FemInput {
    fn default() -> Self {
        FemInput {
            planform_mm: manduca_planform(),
            planform_note: geometry::MANDUCA_NOTE.to_string(),
            camber: 0.13,
            clamp: Clamp::Root,
            material: ShellMaterial::paper_frequencies(),
            n_modes: 6,
            mesh_size_mm: None,
            max_nodes: None,
        }
    }
}

/// Result of the shell FE step, JSON-serialisable. Frame: x spanwise, y chordwise, z up,
/// origin at the root point (0, 0); SI units unless a name says otherwise.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FemModes {
    /// Provenance of the outline.
    pub planform_note: String,
    /// Natural frequencies f_k = ω_k / 2π, Hz (ascending); ω_k² are the eigenvalues of
    /// K φ = ω² M φ (paper Eq. 10).
    pub freq_hz: Vec<f64>,
    /// a_k = Σ_i φ_k,z(node i) (x_i, y_i) dm_i over the nodes with the lumped nodal masses —
    /// the paper's discrete Eq. 14 (integral form Eq. 11) — kg^½·m, origin at the root point.
    pub a: Vec<[f64; 2]>,
    /// b_k = (−a_y, a_x), a_k turned 90° counter-clockwise (paper Eqs. 12 and 15), kg^½·m.
    pub b: Vec<[f64; 2]>,
    /// Wing mass, kg.
    pub mass_kg: f64,
    /// Centre of mass [x, y, z], m.
    pub centre_of_mass_m: [f64; 3],
    /// Node positions [x, y, z], m.
    pub nodes: Vec<[f64; 3]>,
    /// Triangles (node indices).
    pub triangles: Vec<[usize; 3]>,
    /// Indices of the clamped nodes.
    pub clamped_nodes: Vec<usize>,
    /// Per mode, the out-of-plane (global z) displacement of each node of the mode,
    /// mass-normalised as in paper Eq. 9 (Σ φ_k φ_e dm = δ_ke), kg^-½.
    pub shapes: Vec<Vec<f64>>,
    /// Per mode, per node: top-surface strain [ε_x, ε_y, γ_xy] per unit modal coordinate
    /// (paper Eqs. 16–18), averaged from the elements around the node, kg^-½.
    pub strain_nodes: Vec<Vec<[f64; 3]>>,
    /// Relative residual ‖Kφ − ω²Mφ‖ / ‖Kφ‖ per mode (see [`eigen::EigenResult::residuals`]).
    pub residuals: Vec<f64>,
    /// Mode classification: "spanwise bending", "torsion", "rigid body" or "other".
    pub kinds: Vec<String>,
    /// Largest |φᵀMφ − I| entry over the returned modes (how well Eq. 9 holds).
    pub mass_orthonormality_error: f64,
    /// Number of free (unclamped) DOFs.
    pub n_dofs: usize,
    /// Material used.
    pub material: ShellMaterial,
    /// Target element edge the mesh was made with, mm (the automatic size when the input
    /// left it out); 0 when the mesh did not come from the mesher ([`solve_mesh`]).
    #[serde(default)]
    pub mesh_size_mm: f64,
}

/// Most FE work one native run may take ([`fe_work`], about one multiply–add each): the
/// CLI's `wingbeat modes`, [`compute_modes`]. With the default block-sparse LDLᵀ the whole
/// solve takes 1.3–1.5 ns per unit on a loaded 2-core machine (load 6–9; default wing,
/// 6 modes: 1 mm 2.1e8 units 0.3 s, 0.4 mm / 9 963 nodes 2.8e9 units 4.3 s, 0.3 mm /
/// 17 658 nodes 7.1e9 units 9 s; docs/fem.md), so the cap keeps a run under about 10 s:
/// 10 000 nodes are admitted; 17 000-node meshes are refused. (The skyline
/// backend's units are counted on its RCM envelope, 1.2–2.5 ns each.) docs/limits.md
/// ("FE work").
pub const FE_MAX_WORK: f64 = 5.0e9;

/// Most FE work one browser run may take (wasm `feModes`, about 2–3× slower than native):
/// should admit the default wing near 0.5 mm with 6 modes (about 1.4e9 units by N^1.5
/// scaling from 10 000 nodes; not measured), refuses 64 modes at
/// 0.75 mm (the Gram–Schmidt term of 216 basis vectors alone is 1.6e9).
pub const BROWSER_FE_MAX_WORK: f64 = 1.5e9;

/// Largest skyline envelope one FE run may allocate, entries (8 bytes each; K and its
/// factor hold one each): about 1.6 GB natively.
pub const FE_MAX_ENVELOPE: usize = 100_000_000;

/// Estimated work of the eigen-solve of a system of this size for `n_modes` modes, in
/// multiply–adds: one LDLᵀ factorisation, two sweeps over the factor per Krylov vector and the
/// Gram–Schmidt passes, with the basis the solver typically needs (3 vectors per mode plus
/// three blocks).
pub fn fe_work(size: &assembly::SystemSize, n_modes: usize, opt: &EigenOptions) -> f64 {
    let vectors = (3 * n_modes + 3 * opt.block).min(opt.max_basis) as f64;
    size.factor_work
        + vectors * 2.0 * size.envelope as f64
        + 2.0 * vectors * vectors * size.n_dofs as f64
}

/// Refuses a mesh whose eigen-solve would exceed `max_work` ([`fe_work`]) or
/// [`FE_MAX_ENVELOPE`], before anything is assembled; the error names the node count, the
/// cost and what to change.
pub fn check_fe_work(
    mesh: &Mesh,
    clamped: &[bool],
    n_modes: usize,
    opt: &EigenOptions,
    max_work: f64,
) -> Result<assembly::SystemSize> {
    let size = assembly::system_size_for(mesh, clamped, opt.backend);
    let work = fe_work(&size, n_modes, opt);
    let num = crate::error::num;
    let remedy = "a coarser mesh (`mesh_size_mm`), fewer outline points (a smoother outline), or fewer modes (`n_modes`)";
    if size.envelope > FE_MAX_ENVELOPE {
        return Err(WingbeatError::ResourceCap {
            field: "mesh_size_mm (FE memory)".into(),
            requested: format!(
                "a stiffness envelope of {} entries ({} nodes, {} free DOFs)",
                size.envelope,
                mesh.nodes.len(),
                size.n_dofs
            ),
            cap: format!("{FE_MAX_ENVELOPE} entries (about 1.6 GB)"),
            why: format!("memory of the factorisation; use {remedy}"),
        });
    }
    if work > max_work {
        return Err(WingbeatError::ResourceCap {
            field: "mesh_size_mm (FE work)".into(),
            requested: format!(
                "{} multiply-adds ({} nodes, {} free DOFs, {} modes)",
                num((work / 1e6).round() * 1e6),
                mesh.nodes.len(),
                size.n_dofs,
                n_modes
            ),
            cap: format!("{} multiply-adds", num(max_work)),
            why: format!("computing time of the eigen-solve; use {remedy}"),
        });
    }
    Ok(size)
}

/// Runs the whole FE step for `input`: validate, mesh, assemble, solve, post-process.
pub fn compute_modes(input: &FemInput) -> Result<FemModes> {
    compute_modes_with(input, EigenOptions::default())
}

/// [`compute_modes`] with explicit eigen-solver options (e.g. the factorisation
/// [`Backend`]).
pub fn compute_modes_with(input: &FemInput, opt: EigenOptions) -> Result<FemModes> {
    compute_modes_capped(input, opt, FE_MAX_WORK)
}

/// [`compute_modes_with`] under the work budget `max_work` ([`check_fe_work`], checked after
/// meshing and before assembly): [`FE_MAX_WORK`] natively, [`BROWSER_FE_MAX_WORK`] in wasm.
pub fn compute_modes_capped(
    input: &FemInput,
    opt: EigenOptions,
    max_work: f64,
) -> Result<FemModes> {
    input.material.validate()?;
    crate::error::check_range("camber", input.camber, 0.0, 0.5, "(rise / chord)")?;
    if input.n_modes == 0 || input.n_modes > crate::model::MAX_MODES {
        return Err(WingbeatError::invalid(
            "n_modes",
            input.n_modes,
            format!("1 ..= {}", crate::model::MAX_MODES),
        ));
    }
    let (outline, mesh, h) = mesh_input(input)?;
    let clamped = clamp_nodes(&outline, &mesh, input.clamp)?;
    check_fe_work(&mesh, &clamped, input.n_modes, &opt, max_work)?;
    let mut fe = solve_mesh_with(
        &mesh,
        &clamped,
        &input.material,
        input.n_modes,
        &input.planform_note,
        opt,
    )?;
    fe.mesh_size_mm = h;
    Ok(fe)
}

/// The node cap an input asks for ([`FemInput::max_nodes`], default [`MAX_NODES`]),
/// checked to be 1 ..= [`MAX_NODES`].
pub fn node_cap(input: &FemInput) -> Result<usize> {
    match input.max_nodes {
        None => Ok(MAX_NODES),
        Some(n) if (1..=MAX_NODES).contains(&n) => Ok(n),
        Some(n) => Err(WingbeatError::invalid(
            "max_nodes",
            n,
            format!("1 ..= {MAX_NODES} nodes"),
        )),
    }
}

/// The mesh size an input resolves to, mm: its `mesh_size_mm` (checked > 0) or the
/// automatic [`default_mesh_size_mm`] of its (validated) outline.
pub fn resolved_mesh_size_mm(input: &FemInput) -> Result<f64> {
    match input.mesh_size_mm {
        Some(h) => {
            crate::error::check_positive("mesh_size_mm", h, 1e6, "mm")?;
            Ok(h)
        }
        None => Ok(default_mesh_size_mm(&geometry::validate_outline(
            &input.planform_mm,
        )?)),
    }
}

/// Validates the outline and meshes it: the mesh size resolved ([`resolved_mesh_size_mm`]),
/// a mesh line on a strip clamp's edge (so the clamped edge is exact), and the node cap
/// ([`node_cap`]) checked after meshing, before any assembly. An automatic size that would
/// exceed the cap is coarsened until it fits (a default never makes a valid outline fail);
/// an explicit size over the cap is an error naming `mesh_size_mm`, the node count, the cap
/// and a size that would fit. Returns (validated outline, mesh, mesh size in mm).
pub fn mesh_input(input: &FemInput) -> Result<(Vec<[f64; 2]>, Mesh, f64)> {
    let cap = node_cap(input)?;
    let mut h = resolved_mesh_size_mm(input)?;
    let outline = geometry::validate_outline(&input.planform_mm)?;
    let lines_x_mm = match input.clamp {
        Clamp::Strip { x_mm } if x_mm.is_finite() => vec![x_mm],
        _ => Vec::new(),
    };
    let opts = MeshOptions {
        max_nodes: cap,
        lines_x_mm,
    };
    let mut tries = 0;
    loop {
        match mesh::mesh_planform_with(&outline, h, input.camber, &opts) {
            Ok(m) => return Ok((outline, m, h)),
            Err(WingbeatError::ResourceCap { .. }) if input.mesh_size_mm.is_none() && tries < 8 => {
                tries += 1;
                h = round_2sig(h * 1.25);
            }
            Err(WingbeatError::ResourceCap {
                field,
                requested,
                cap,
                why,
            }) => {
                // name a size that was checked to fit (the estimate behind the first
                // suggestion does not see the grading toward the root)
                let fit = (1..=8)
                    .scan(why_size(&why).unwrap_or(h * 1.25), |next, _| {
                        let try_h = *next;
                        *next = round_2sig(try_h * 1.2);
                        Some(try_h)
                    })
                    .find(|&try_h| {
                        mesh::mesh_planform_with(&outline, try_h, input.camber, &opts).is_ok()
                    });
                return Err(WingbeatError::ResourceCap {
                    field,
                    requested,
                    cap,
                    why: fit.map_or(why, mesh::cap_why),
                });
            }
            Err(e) => return Err(e),
        }
    }
}

/// The size named in a [`mesh::cap_why`] text.
fn why_size(why: &str) -> Option<f64> {
    why.split("about ").nth(1)?.split(' ').next()?.parse().ok()
}

/// The `wingbeat modes` JSON document: every field of [`FemModes`], plus `modes` (the
/// modal model's [`Mode`]s, e.g. from [`FemModes::model_modes`], which `wingbeat simulate
/// --modes FILE` reads) and `units`. The CLI and wasm `feModes` (`json: true`) both build it
/// here, so a file exported from the lab is the CLI's file.
pub fn modes_document(fe: &FemModes, modes: &[Mode]) -> Result<String> {
    let json_err = |e: serde_json::Error| WingbeatError::NonFinite {
        what: "JSON output".into(),
        detail: e.to_string(),
    };
    let mut v = serde_json::to_value(fe).map_err(json_err)?;
    v["modes"] = serde_json::to_value(modes).map_err(json_err)?;
    v["units"] = serde_json::json!({
        "freq_hz": "Hz", "a": "kg^0.5 m", "b": "kg^0.5 m", "mass_kg": "kg", "nodes": "m",
        "mesh_size_mm": "mm",
        "shapes": "kg^-0.5 (mass-normalised out-of-plane displacement)",
        "strain_nodes": "strain per unit modal coordinate [eps_x, eps_y, gamma_xy], top surface"
    });
    serde_json::to_string(&v).map_err(json_err)
}

/// Flags the nodes held by `clamp` (outline and clamp in mm, mesh in m).
pub fn clamp_nodes(outline: &[[f64; 2]], mesh: &Mesh, clamp: Clamp) -> Result<Vec<bool>> {
    let span = outline
        .iter()
        .map(|p| p[0].abs().max(p[1].abs()))
        .fold(0.0, f64::max);
    let tol = 1e-9 * span.max(1e-300);
    let flags: Vec<bool> = match clamp {
        Clamp::Free => return Ok(vec![false; mesh.nodes.len()]),
        Clamp::Root => {
            let n = outline.len();
            let segs: Vec<(f64, f64)> = (0..n)
                .filter_map(|i| {
                    let (a, b) = (outline[i], outline[(i + 1) % n]);
                    (a[0].abs() <= tol && b[0].abs() <= tol)
                        .then(|| (a[1].min(b[1]), a[1].max(b[1])))
                })
                .collect();
            if segs.is_empty() {
                return Err(WingbeatError::invalid(
                    "clamp",
                    "root",
                    "an outline with an edge on x = 0 (the root segment); use strip:X_MM otherwise",
                ));
            }
            mesh.nodes
                .iter()
                .map(|p| {
                    let (x, y) = (p[0] * 1e3, p[1] * 1e3);
                    x.abs() <= 1e-6 * span.max(1.0)
                        && segs
                            .iter()
                            .any(|&(lo, hi)| y >= lo - 1e-6 && y <= hi + 1e-6)
                })
                .collect()
        }
        Clamp::Strip { x_mm } => {
            if !x_mm.is_finite() {
                return Err(WingbeatError::invalid(
                    "clamp.x_mm",
                    x_mm,
                    "a finite strip width, mm",
                ));
            }
            mesh.nodes
                .iter()
                .map(|p| p[0] * 1e3 <= x_mm + 1e-9 * span)
                .collect()
        }
    };
    let count = flags.iter().filter(|&&f| f).count();
    let (field, shown) = match clamp {
        Clamp::Strip { x_mm } => ("clamp.x_mm", format!("{} mm", crate::error::num(x_mm))),
        _ => ("clamp", "root".to_string()),
    };
    if count == 0 {
        return Err(WingbeatError::invalid(
            field,
            shown,
            "a clamp that holds at least one mesh node",
        ));
    }
    if count == flags.len() {
        return Err(WingbeatError::invalid(
            field,
            format!("{shown}, which holds every one of the {count} mesh nodes"),
            "a clamp that leaves some of the wing free (a narrower strip, or a larger outline)",
        ));
    }
    Ok(flags)
}

/// Solves the modes of an existing mesh (m) with the nodes flagged in `clamped` held in all
/// 6 DOFs, and post-processes them into [`FemModes`].
pub fn solve_mesh(
    mesh: &Mesh,
    clamped: &[bool],
    material: &ShellMaterial,
    n_modes: usize,
    planform_note: &str,
) -> Result<FemModes> {
    solve_mesh_with(
        mesh,
        clamped,
        material,
        n_modes,
        planform_note,
        EigenOptions::default(),
    )
}

/// [`solve_mesh`] with explicit eigen-solver options.
pub fn solve_mesh_with(
    mesh: &Mesh,
    clamped: &[bool],
    material: &ShellMaterial,
    n_modes: usize,
    planform_note: &str,
    opt: EigenOptions,
) -> Result<FemModes> {
    material.validate()?;
    if opt.backend == Backend::Sparse {
        let asm = assembly::assemble_blocks(mesh, material, clamped)?;
        let eig = eigen::lowest_modes_with::<linalg::SparseLdlt>(&asm.k, &asm.m, n_modes, opt)?;
        return Ok(postprocess(
            mesh,
            clamped,
            material,
            &asm,
            &eig,
            planform_note,
        ));
    }
    let asm = assembly::assemble(mesh, material, clamped)?;
    let eig = eigen::lowest_modes(&asm.k, &asm.m, n_modes, opt)?;
    Ok(postprocess(
        mesh,
        clamped,
        material,
        &asm,
        &eig,
        planform_note,
    ))
}

fn postprocess<K>(
    mesh: &Mesh,
    clamped: &[bool],
    material: &ShellMaterial,
    asm: &assembly::Assembled<K>,
    eig: &eigen::EigenResult,
    note: &str,
) -> FemModes {
    let nn = mesh.nodes.len();
    let mass: f64 = asm.node_mass.iter().sum();
    let mut com = [0.0; 3];
    for (p, m) in mesh.nodes.iter().zip(&asm.node_mass) {
        for k in 0..3 {
            com[k] += p[k] * m / mass;
        }
    }
    // mass orthonormality check
    let mut ortho: f64 = 0.0;
    for i in 0..eig.vectors.len() {
        for j in 0..=i {
            let s: f64 = (0..asm.m.len())
                .map(|q| eig.vectors[i][q] * asm.m[q] * eig.vectors[j][q])
                .sum();
            ortho = ortho.max((s - if i == j { 1.0 } else { 0.0 }).abs());
        }
    }
    let dof = |v: &[f64], node: usize, d: usize| -> f64 {
        let e = asm.eq[node][d];
        if e == assembly::CLAMPED {
            0.0
        } else {
            v[e]
        }
    };
    let mut freq_hz = Vec::new();
    let mut a_vecs = Vec::new();
    let mut b_vecs = Vec::new();
    let mut shapes = Vec::new();
    let mut strain_nodes = Vec::new();
    let mut kinds = Vec::new();
    let lam_max = eig.values.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for (lam, v) in eig.values.iter().zip(&eig.vectors) {
        let mut w: Vec<f64> = (0..nn).map(|n| dof(v, n, 2)).collect();
        let sgn = sign_of_shape(mesh, &asm.node_mass, &w);
        w.iter_mut().for_each(|x| *x *= sgn);
        let mut a = [0.0; 2];
        for n in 0..nn {
            a[0] += asm.node_mass[n] * w[n] * mesh.nodes[n][0];
            a[1] += asm.node_mass[n] * w[n] * mesh.nodes[n][1];
        }
        // nodal strains: area-weighted average of the element corner values
        let mut acc = vec![[0.0; 3]; nn];
        let mut wsum = vec![0.0; nn];
        for t in &mesh.triangles {
            let p = [mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]]];
            let mut u = Vec18::zeros();
            for c in 0..3 {
                for d in 0..6 {
                    u[6 * c + d] = sgn * dof(v, t[c], d);
                }
            }
            let area = element::Frame::new(&p).map(|f| f.area).unwrap_or(0.0);
            for c in 0..3 {
                if let Some(e) = corner_surface_strain(&p, material, &u, c) {
                    for k in 0..3 {
                        acc[t[c]][k] += area * e[k];
                    }
                    wsum[t[c]] += area;
                }
            }
        }
        for (s, wgt) in acc.iter_mut().zip(&wsum) {
            if *wgt > 0.0 {
                s.iter_mut().for_each(|x| *x /= wgt);
            }
        }
        let f = lam.max(0.0).sqrt() / (2.0 * std::f64::consts::PI);
        let rigid = *lam < 1e-6 * lam_max.max(1e-300) || *lam <= 0.0;
        kinds.push(if rigid {
            "rigid body".to_string()
        } else {
            classify(mesh, &asm.node_mass, &w).to_string()
        });
        freq_hz.push(f);
        a_vecs.push(a);
        b_vecs.push([-a[1], a[0]]);
        shapes.push(w);
        strain_nodes.push(acc);
    }
    FemModes {
        planform_note: note.to_string(),
        freq_hz,
        a: a_vecs,
        b: b_vecs,
        mass_kg: mass,
        centre_of_mass_m: com,
        nodes: mesh.nodes.clone(),
        triangles: mesh.triangles.clone(),
        clamped_nodes: (0..nn).filter(|&i| clamped[i]).collect(),
        shapes,
        strain_nodes,
        residuals: eig.residuals.clone(),
        kinds,
        mass_orthonormality_error: ortho,
        n_dofs: asm.m.len(),
        material: *material,
        mesh_size_mm: 0.0,
    }
}

/// The low-order polynomial probes of the sign convention, in ξ (spanwise, 0 at the root,
/// 1 at the tip) and η (chordwise from the mass centre toward the trailing edge, −y, over
/// the span).
const SIGN_PROBES: [fn(f64, f64) -> f64; 7] = [
    |_, _| 1.0,
    |x, _| x,
    |_, y| y,
    |x, y| x * y,
    |x, _| x * x,
    |x, y| x * x * y,
    |x, _| x * x * x,
];

/// The sign convention of the mode shapes (+1 or −1 to multiply `w` by): with c_j the
/// mass-weighted correlation of w with the probe g_j (Σ m w g_j / √(Σ m w² · Σ m g_j²),
/// probes 1, ξ, η, ξη, ξ², ξ²η, ξ³ with ξ spanwise from the root over the span and η
/// chordwise from the mass centre toward the trailing edge over the span), the sign makes
/// Σ_j c_j |c_j| positive: a bending mode lifts its tip, a torsion mode lifts its trailing
/// edge.
/// The c_j converge with the mesh like the shape itself, so the sign is the same on any
/// mesh fine enough to resolve the mode, except for a mode whose vote is tied; in
/// particular an antisymmetric mode of a symmetric planform (whose largest displacement
/// occurs twice with opposite signs) gets a definite sign. Repeated eigenvalues have no
/// unique shapes (any rotation within their pair is a mode), so no convention fixes them.
pub fn sign_of_shape(mesh: &Mesh, node_mass: &[f64], w: &[f64]) -> f64 {
    let (x0, x1) = mesh
        .nodes
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p[0]), b.max(p[0]))
        });
    let span = (x1 - x0).max(1e-300);
    let mass: f64 = node_mass.iter().sum();
    let yc = mesh
        .nodes
        .iter()
        .zip(node_mass)
        .map(|(p, m)| p[1] * m)
        .sum::<f64>()
        / mass.max(1e-300);
    let ww: f64 = w.iter().zip(node_mass).map(|(v, m)| m * v * v).sum();
    let mut vote = 0.0;
    for g in SIGN_PROBES {
        let (mut gw, mut gg) = (0.0, 0.0);
        for ((p, m), v) in mesh.nodes.iter().zip(node_mass).zip(w) {
            let gv = g((p[0] - x0) / span, (yc - p[1]) / span);
            gw += m * gv * v;
            gg += m * gv * gv;
        }
        if gg > 0.0 && ww > 0.0 {
            let c = gw / (gg * ww).sqrt();
            vote += c * c.abs();
        }
    }
    if vote < 0.0 {
        -1.0
    } else {
        1.0
    }
}

/// Mass-weighted R² of a least-squares fit of `w` on the columns of `basis`.
fn r_squared(w: &[f64], m: &[f64], basis: &[Vec<f64>]) -> f64 {
    let k = basis.len();
    let mut g = nalgebra::DMatrix::<f64>::zeros(k, k);
    let mut r = nalgebra::DVector::<f64>::zeros(k);
    for i in 0..k {
        for j in 0..k {
            g[(i, j)] = (0..w.len()).map(|n| m[n] * basis[i][n] * basis[j][n]).sum();
        }
        r[i] = (0..w.len()).map(|n| m[n] * basis[i][n] * w[n]).sum();
    }
    let total: f64 = (0..w.len()).map(|n| m[n] * w[n] * w[n]).sum();
    if total <= 0.0 {
        return 0.0;
    }
    match g.clone().cholesky() {
        Some(ch) => {
            let c = ch.solve(&r);
            (c.dot(&r) / total).clamp(0.0, 1.0)
        }
        None => 0.0,
    }
}

/// The mass-weighted R² of a mode shape `w` against the two model families behind
/// [`classify`]: (spanwise bending: a cubic in x; torsion: (y − local mid-chord) × (1, x, x²)).
pub fn kind_scores(mesh: &Mesh, node_mass: &[f64], w: &[f64]) -> (f64, f64) {
    let xs: Vec<f64> = mesh.nodes.iter().map(|p| p[0]).collect();
    let xmax = xs.iter().copied().fold(f64::MIN, f64::max).max(1e-300);
    // local mid-chord from the node cloud, in 20 spanwise bins
    let nb = 20;
    let mut lo = vec![f64::INFINITY; nb];
    let mut hi = vec![f64::NEG_INFINITY; nb];
    let bin = |x: f64| (((x / xmax) * nb as f64) as usize).min(nb - 1);
    for p in &mesh.nodes {
        let b = bin(p[0].max(0.0));
        lo[b] = lo[b].min(p[1]);
        hi[b] = hi[b].max(p[1]);
    }
    let s: Vec<f64> = mesh
        .nodes
        .iter()
        .map(|p| {
            let b = bin(p[0].max(0.0));
            (p[1] - 0.5 * (lo[b] + hi[b])) / xmax
        })
        .collect();
    let xn: Vec<f64> = xs.iter().map(|x| x / xmax).collect();
    let one = vec![1.0; xs.len()];
    let bend = vec![
        one,
        xn.clone(),
        xn.iter().map(|x| x * x).collect(),
        xn.iter().map(|x| x * x * x).collect(),
    ];
    let tors = vec![
        s.clone(),
        s.iter().zip(&xn).map(|(a, x)| a * x).collect(),
        s.iter().zip(&xn).map(|(a, x)| a * x * x).collect(),
    ];
    (
        r_squared(w, node_mass, &bend),
        r_squared(w, node_mass, &tors),
    )
}

/// Classifies an out-of-plane mode shape: "spanwise bending" if w is explained by a cubic in
/// the spanwise coordinate x alone (mass-weighted R² ≥ 0.8, see [`kind_scores`]), "torsion"
/// if it is explained by a chordwise-linear twist (y − local mid-chord) × (1, x, x²)
/// (R² ≥ 0.6), else "other". The R² are smooth functionals of the shape, so the label only
/// changes with the mesh when a score sits at a threshold (the default wing's six modes keep
/// their labels from 2 mm to 0.75 mm; `tests/fem_signs.rs`).
pub fn classify(mesh: &Mesh, node_mass: &[f64], w: &[f64]) -> &'static str {
    let (rb, rt) = kind_scores(mesh, node_mass, w);
    if rb >= 0.8 && rb >= rt {
        "spanwise bending"
    } else if rt >= 0.6 && rt > rb {
        "torsion"
    } else {
        "other"
    }
}

impl FemModes {
    /// Locates (x, y) in mm: (triangle, barycentric weights, inside?). Outside points map to
    /// the nearest triangle with clamped weights.
    fn locate(&self, x_mm: f64, y_mm: f64) -> Option<(usize, [f64; 3], bool)> {
        locate::locate_in_mesh(&self.nodes, &self.triangles, x_mm, y_mm)
    }

    /// Top-surface modal strain [ε_x, ε_y, γ_xy] of mode `mode` (0-based) at (x, y) in mm,
    /// linearly interpolated from the nodal averages (paper Eqs. 16–18). Errors if the mode
    /// index is out of range or the point is outside the meshed planform.
    pub fn strain_at(&self, mode: usize, x_mm: f64, y_mm: f64) -> Result<[f64; 3]> {
        if mode >= self.strain_nodes.len() {
            return Err(WingbeatError::invalid(
                "mode",
                mode,
                format!("0 ..= {}", self.strain_nodes.len().saturating_sub(1)),
            ));
        }
        if !(x_mm.is_finite() && y_mm.is_finite()) {
            return Err(WingbeatError::invalid(
                "point",
                format!("({x_mm}, {y_mm})"),
                "finite coordinates, mm",
            ));
        }
        match self.locate(x_mm, y_mm) {
            Some((ti, l, true)) => Ok(self.interp(mode, ti, l)),
            _ => Err(WingbeatError::invalid(
                "point",
                format!("({x_mm}, {y_mm}) mm"),
                "a point inside the meshed planform",
            )),
        }
    }

    fn interp(&self, mode: usize, ti: usize, l: [f64; 3]) -> [f64; 3] {
        locate::interpolate_strain(self.triangles[ti], l, mode, |k, i| self.strain_nodes[k][i])
    }

    /// [`FemModes::to_modes`], strict: every point must lie inside the meshed planform, else
    /// an error naming `{field} {name}` (e.g. `--point P`), so no NaN strain reaches a plot.
    pub fn model_modes(
        &self,
        zeta: f64,
        points: &[(String, f64, f64)],
        field: &str,
    ) -> Result<Vec<Mode>> {
        for (name, x, y) in points {
            self.strain_at(0, *x, *y).map_err(|_| {
                WingbeatError::invalid(
                    format!("{field} {name}"),
                    format!("({x}, {y}) mm"),
                    "a point inside the meshed planform",
                )
            })?;
        }
        Ok(self.to_modes(zeta, points))
    }

    /// Converts to the modal model's [`Mode`]s (Eq. 13 inputs) with damping ratio `zeta` and
    /// modal strains at the named points `(name, x_mm, y_mm)`. Points outside the mesh take
    /// the value at the nearest point of the mesh (use [`FemModes::strain_at`] to be strict).
    pub fn to_modes(&self, zeta: f64, points: &[(String, f64, f64)]) -> Vec<Mode> {
        (0..self.freq_hz.len())
            .map(|k| Mode {
                name: format!("{}: {}", k + 1, self.kinds[k]),
                freq_hz: self.freq_hz[k],
                a: self.a[k],
                zeta,
                strains: points
                    .iter()
                    .map(|(name, x, y)| {
                        let e = self
                            .locate(*x, *y)
                            .map(|(ti, l, _)| self.interp(k, ti, l))
                            .unwrap_or([f64::NAN; 3]);
                        ModalStrain {
                            point: name.clone(),
                            eps_x: e[0],
                            eps_y: e[1],
                            gamma_xy: e[2],
                        }
                    })
                    .collect(),
            })
            .collect()
    }
}
