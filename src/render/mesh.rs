//! The renderer's mesh input: the interface between the shell FE and the GPU.
//!
//! A [`WingMesh`] is a triangulated wing in its undeformed, unrotated pose (the I″–J″ plane,
//! camber along K″) plus, per mode, the out-of-plane shape φ_k and the surface strains ε_k at
//! every node, both per unit modal coordinate q_k. The FE module writes the same data as JSON
//! ([`WingMesh::from_fe_json`]); [`WingMesh::synthetic`] builds an analytic stand-in.

use crate::error::{Result, WingbeatError};
use serde_json::Value;

/// Largest node count accepted (memory and upload cap; a 10k-triangle wing has ~5k nodes).
pub const MAX_NODES: usize = 1_000_000;
/// Largest triangle count accepted.
pub const MAX_TRIANGLES: usize = 2_000_000;

/// A triangulated wing with modal data, in metres.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WingMesh {
    /// Node positions, metres: x spanwise from the root, y chordwise (the chord runs toward −y),
    /// z the camber height along K″.
    pub nodes: Vec<[f32; 3]>,
    /// Triangles as node indices (either winding; the wing is lit two-sided).
    pub triangles: Vec<[u32; 3]>,
    /// Per mode, the out-of-plane displacement of each node per unit modal coordinate (m per unit q).
    pub shapes: Vec<Vec<f32>>,
    /// Per mode, per node, the surface strain `[ε_x, ε_y, γ_xy]` per unit modal coordinate.
    pub strains: Vec<Vec<[f32; 3]>>,
}

fn bad(field: impl Into<String>, value: impl std::fmt::Display, allowed: &str) -> WingbeatError {
    WingbeatError::invalid(field, value, allowed)
}

impl WingMesh {
    /// Number of modes carried by the mesh.
    pub fn n_modes(&self) -> usize {
        self.shapes.len()
    }

    /// Checks sizes, finiteness and index ranges. Every error names the offending field,
    /// e.g. `triangles[12][2]` or `strains[1][40][2]`.
    pub fn validate(&self) -> Result<()> {
        let n = self.nodes.len();
        if n < 3 {
            return Err(bad("nodes", format!("{n} nodes"), "at least 3 nodes"));
        }
        if n > MAX_NODES {
            return Err(bad(
                "nodes",
                format!("{n} nodes"),
                &format!("at most {MAX_NODES}"),
            ));
        }
        for (i, p) in self.nodes.iter().enumerate() {
            for (c, v) in p.iter().enumerate() {
                if !v.is_finite() {
                    return Err(bad(format!("nodes[{i}][{c}]"), v, "a finite number (m)"));
                }
            }
        }
        let nt = self.triangles.len();
        if nt == 0 || nt > MAX_TRIANGLES {
            return Err(bad(
                "triangles",
                format!("{nt} triangles"),
                &format!("1 to {MAX_TRIANGLES} triangles"),
            ));
        }
        for (i, t) in self.triangles.iter().enumerate() {
            for (c, &v) in t.iter().enumerate() {
                if v as usize >= n {
                    return Err(bad(
                        format!("triangles[{i}][{c}]"),
                        v,
                        &format!("a node index in [0, {n})"),
                    ));
                }
            }
        }
        if self.strains.len() != self.shapes.len() {
            return Err(bad(
                "strains",
                format!("{} modes", self.strains.len()),
                &format!("one entry per mode of `shapes` ({})", self.shapes.len()),
            ));
        }
        for (k, s) in self.shapes.iter().enumerate() {
            if s.len() != n {
                return Err(bad(
                    format!("shapes[{k}]"),
                    format!("{} values", s.len()),
                    &format!("one value per node ({n})"),
                ));
            }
            if let Some(i) = s.iter().position(|v| !v.is_finite()) {
                return Err(bad(format!("shapes[{k}][{i}]"), s[i], "a finite number"));
            }
        }
        for (k, s) in self.strains.iter().enumerate() {
            if s.len() != n {
                return Err(bad(
                    format!("strains[{k}]"),
                    format!("{} values", s.len()),
                    &format!("one [ε_x, ε_y, γ_xy] per node ({n})"),
                ));
            }
            for (i, e) in s.iter().enumerate() {
                for (c, v) in e.iter().enumerate() {
                    if !v.is_finite() {
                        return Err(bad(format!("strains[{k}][{i}][{c}]"), v, "a finite number"));
                    }
                }
            }
        }
        Ok(())
    }

    /// Span (largest x), metres.
    pub fn span(&self) -> f32 {
        self.nodes.iter().map(|p| p[0]).fold(0.0, f32::max)
    }

    /// Index of the wing-tip node: the node with the largest x (ties: the first).
    pub fn tip_node(&self) -> usize {
        let mut best = 0;
        for (i, p) in self.nodes.iter().enumerate() {
            if p[0] > self.nodes[best][0] {
                best = i;
            }
        }
        best
    }

    /// Axis-aligned bounds `(min, max)` of the undeformed nodes.
    pub fn bounds(&self) -> ([f32; 3], [f32; 3]) {
        let mut lo = [f32::INFINITY; 3];
        let mut hi = [f32::NEG_INFINITY; 3];
        for p in &self.nodes {
            for c in 0..3 {
                lo[c] = lo[c].min(p[c]);
                hi[c] = hi[c].max(p[c]);
            }
        }
        (lo, hi)
    }

    /// A Manduca-like forewing, generated procedurally, with two analytic modes.
    ///
    /// * Planform: span L = 49 mm, chord c(ξ) = (4 + 52 ξ^0.546)(1 − ξ)^0.764 mm with
    ///   ξ = x/L (a fit to the proportions of `data/planform_manduca.csv`: mean chord ≈ 18 mm,
    ///   area ≈ 8.8 cm²), leading edge y_le = −3.6 mm · ξ⁸, the chord running toward −y.
    /// * Camber: a parabolic arc, 13 % of the local chord at mid-chord, along +z.
    /// * Mode 0, spanwise bending: φ = A (x/L)². Mode 1, torsion: φ = B (x/L)(y − y_c)/L about
    ///   the line y = y_c = −9 mm. A and B make each mode mass-normalised (Σ φ² dm = 1) for a
    ///   membrane of 81 µm and 860 kg/m³ (≈ 61 mg), so q is in kg^½·m like FE modes.
    /// * Strains: Kirchhoff surface strains of a plate whose thickness tapers from 81 µm at the
    ///   root to 30 % of that at the tip: ε_x = −(h/2) ∂²φ/∂x², ε_y = −(h/2) ∂²φ/∂y²,
    ///   γ_xy = −h ∂²φ/∂x∂y (the taper only scales the strain; it is a visual stand-in).
    ///
    /// `n_span` and `n_chord` (each clamped to 1..=1000) set the grid; the tip column collapses
    /// onto one node, so there are `n_span·n_chord·2 − n_chord` triangles.
    pub fn synthetic(n_span: usize, n_chord: usize) -> WingMesh {
        let ns = n_span.clamp(1, 1000);
        let nc = n_chord.clamp(1, 1000);
        let span = 0.049_f64;
        let chord =
            |xi: f64| (4.0 + 52.0 * xi.powf(0.546)) * (1.0 - xi).max(0.0).powf(0.764) * 1e-3;
        let y_le = |xi: f64| -3.6e-3 * xi.powi(8);
        let mut nodes: Vec<[f64; 3]> = Vec::new();
        let mut index = vec![vec![0u32; nc + 1]; ns + 1];
        for i in 0..=ns {
            let xi = i as f64 / ns as f64;
            let c = chord(xi);
            for j in 0..=nc {
                if i == ns && j > 0 {
                    index[i][j] = index[i][0];
                    continue;
                }
                let eta = j as f64 / nc as f64;
                let y = y_le(xi) - eta * c;
                let z = 4.0 * 0.13 * c * eta * (1.0 - eta);
                index[i][j] = nodes.len() as u32;
                nodes.push([xi * span, y, z]);
            }
        }
        let mut triangles = Vec::new();
        for i in 0..ns {
            for j in 0..nc {
                let (a, b) = (index[i][j], index[i][j + 1]);
                let (c, d) = (index[i + 1][j], index[i + 1][j + 1]);
                triangles.push([a, c, b]);
                if c != d {
                    triangles.push([b, c, d]);
                }
            }
        }
        // Lumped node masses from the triangle areas (uniform areal density ρh).
        let rho_h = 860.0 * 81e-6;
        let mut mass = vec![0.0f64; nodes.len()];
        for t in &triangles {
            let [p, q, r] = t.map(|k| nodes[k as usize]);
            let area = 0.5 * ((q[0] - p[0]) * (r[1] - p[1]) - (r[0] - p[0]) * (q[1] - p[1])).abs();
            for &k in t {
                mass[k as usize] += rho_h * area / 3.0;
            }
        }
        let y_c = -9e-3;
        let bend: Vec<f64> = nodes.iter().map(|p| (p[0] / span).powi(2)).collect();
        let twist: Vec<f64> = nodes
            .iter()
            .map(|p| (p[0] / span) * (p[1] - y_c) / span)
            .collect();
        let norm = |phi: &[f64]| {
            let m2: f64 = phi.iter().zip(&mass).map(|(f, m)| f * f * m).sum();
            1.0 / m2.sqrt()
        };
        let (a, b) = (norm(&bend), norm(&twist));
        let h = |x: f64| 81e-6 * (1.0 - 0.7 * x / span);
        let shapes = vec![
            bend.iter().map(|v| (a * v) as f32).collect(),
            twist.iter().map(|v| (b * v) as f32).collect(),
        ];
        let strains = vec![
            nodes
                .iter()
                .map(|p| [(-h(p[0]) / 2.0 * 2.0 * a / (span * span)) as f32, 0.0, 0.0])
                .collect(),
            nodes
                .iter()
                .map(|p| [0.0, 0.0, (-h(p[0]) * b / (span * span)) as f32])
                .collect(),
        ];
        WingMesh {
            nodes: nodes
                .iter()
                .map(|p| [p[0] as f32, p[1] as f32, p[2] as f32])
                .collect(),
            triangles,
            shapes,
            strains,
        }
    }

    /// Reads the FE module's JSON: `nodes` ([x, y, z] in m), `triangles` ([i, j, k]), `shapes`
    /// (per mode, one out-of-plane value per node; a `[ux, uy, uz]` triple is accepted and its
    /// `uz` used) and optional `strain_nodes` (per mode, per node `[ε_x, ε_y, γ_xy]`; zeros when
    /// absent). The result is validated; errors name the JSON field.
    pub fn from_fe_json(v: &Value) -> Result<WingMesh> {
        let arr = |v: &'_ Value, field: &str| -> Result<Vec<Value>> {
            v.as_array()
                .cloned()
                .ok_or_else(|| bad(field, short(v), "an array"))
        };
        let num = |v: &Value, field: &str| -> Result<f32> {
            v.as_f64()
                .map(|x| x as f32)
                .ok_or_else(|| bad(field, short(v), "a number"))
        };
        let nodes_v = arr(v.get("nodes").unwrap_or(&Value::Null), "nodes")?;
        let mut nodes = Vec::with_capacity(nodes_v.len());
        for (i, p) in nodes_v.iter().enumerate() {
            let f = format!("nodes[{i}]");
            let a = arr(p, &f)?;
            if a.len() != 3 {
                return Err(bad(f, short(p), "[x, y, z] in metres"));
            }
            nodes.push([
                num(&a[0], &format!("{f}[0]"))?,
                num(&a[1], &format!("{f}[1]"))?,
                num(&a[2], &format!("{f}[2]"))?,
            ]);
        }
        let tri_v = arr(v.get("triangles").unwrap_or(&Value::Null), "triangles")?;
        let mut triangles = Vec::with_capacity(tri_v.len());
        for (i, t) in tri_v.iter().enumerate() {
            let f = format!("triangles[{i}]");
            let a = arr(t, &f)?;
            if a.len() != 3 {
                return Err(bad(f, short(t), "[i, j, k] node indices"));
            }
            let mut tri = [0u32; 3];
            for c in 0..3 {
                tri[c] = a[c]
                    .as_u64()
                    .and_then(|x| u32::try_from(x).ok())
                    .ok_or_else(|| bad(format!("{f}[{c}]"), short(&a[c]), "a node index"))?;
            }
            triangles.push(tri);
        }
        let shapes_v = arr(v.get("shapes").unwrap_or(&Value::Null), "shapes")?;
        let mut shapes = Vec::with_capacity(shapes_v.len());
        for (k, s) in shapes_v.iter().enumerate() {
            let f = format!("shapes[{k}]");
            let a = arr(s, &f)?;
            let mut out = Vec::with_capacity(a.len());
            for (i, e) in a.iter().enumerate() {
                let fi = format!("{f}[{i}]");
                let val = match e {
                    Value::Array(t) if t.len() == 3 => num(&t[2], &format!("{fi}[2]"))?,
                    _ => num(e, &fi)?,
                };
                out.push(val);
            }
            shapes.push(out);
        }
        let strains = match v.get("strain_nodes") {
            None | Some(Value::Null) => shapes.iter().map(|s| vec![[0.0; 3]; s.len()]).collect(),
            Some(sv) => {
                let modes = arr(sv, "strain_nodes")?;
                let mut strains = Vec::with_capacity(modes.len());
                for (k, m) in modes.iter().enumerate() {
                    let f = format!("strain_nodes[{k}]");
                    let a = arr(m, &f)?;
                    let mut out = Vec::with_capacity(a.len());
                    for (i, e) in a.iter().enumerate() {
                        let fi = format!("{f}[{i}]");
                        let t = arr(e, &fi)?;
                        if t.len() != 3 {
                            return Err(bad(fi, short(e), "[ε_x, ε_y, γ_xy]"));
                        }
                        out.push([
                            num(&t[0], &format!("{fi}[0]"))?,
                            num(&t[1], &format!("{fi}[1]"))?,
                            num(&t[2], &format!("{fi}[2]"))?,
                        ]);
                    }
                    strains.push(out);
                }
                strains
            }
        };
        let mesh = WingMesh {
            nodes,
            triangles,
            shapes,
            strains,
        };
        mesh.validate_fe()?;
        Ok(mesh)
    }

    /// [`WingMesh::validate`] with the FE output's field names (`strain_nodes[…]`).
    fn validate_fe(&self) -> Result<()> {
        self.validate().map_err(|e| match e {
            WingbeatError::InvalidInput {
                field,
                value,
                allowed,
            } if field.starts_with("strains") => WingbeatError::InvalidInput {
                field: field.replacen("strains", "strain_nodes", 1),
                value,
                allowed,
            },
            other => other,
        })
    }

    /// Builds a mesh from the flat arrays of the wasm API's `feModes` (the shell FE's output):
    /// `nodes` = x, y, z per node (m); `triangles` = three node indices each; `shapes` =
    /// mode-major φ_k per node (`shapes[k·n + i]`); `strain_nodes` =
    /// `[(k·n + i)·3 + c]` for c = ε_x, ε_y, γ_xy per unit q, or empty for no strain colouring.
    /// Lengths are checked against each other and every error names the array (and, through
    /// [`WingMesh::validate`], the entry).
    pub fn from_flat(
        nodes: &[f64],
        triangles: &[u32],
        shapes: &[f64],
        strain_nodes: &[f64],
    ) -> Result<WingMesh> {
        if nodes.len() % 3 != 0 || nodes.is_empty() {
            return Err(bad(
                "nodes",
                format!("{} values", nodes.len()),
                "x, y, z per node (a non-empty multiple of 3)",
            ));
        }
        let n = nodes.len() / 3;
        if n > MAX_NODES {
            return Err(bad(
                "nodes",
                format!("{n} nodes"),
                &format!("at most {MAX_NODES}"),
            ));
        }
        if triangles.len() % 3 != 0 {
            return Err(bad(
                "triangles",
                format!("{} values", triangles.len()),
                "three node indices per triangle (a multiple of 3)",
            ));
        }
        if shapes.len() % n != 0 {
            return Err(bad(
                "shapes",
                format!("{} values", shapes.len()),
                &format!("one value per node ({n}) for each mode"),
            ));
        }
        let n_modes = shapes.len() / n;
        if !strain_nodes.is_empty() && strain_nodes.len() != 3 * n * n_modes {
            return Err(bad(
                "strain_nodes",
                format!("{} values", strain_nodes.len()),
                &format!("3 per node per mode ({}), or none", 3 * n * n_modes),
            ));
        }
        let mesh = WingMesh {
            nodes: nodes
                .chunks_exact(3)
                .map(|p| [p[0] as f32, p[1] as f32, p[2] as f32])
                .collect(),
            triangles: triangles
                .chunks_exact(3)
                .map(|t| [t[0], t[1], t[2]])
                .collect(),
            shapes: shapes
                .chunks_exact(n)
                .map(|s| s.iter().map(|&v| v as f32).collect())
                .collect(),
            strains: if strain_nodes.is_empty() {
                vec![vec![[0.0; 3]; n]; n_modes]
            } else {
                strain_nodes
                    .chunks_exact(3 * n)
                    .map(|m| {
                        m.chunks_exact(3)
                            .map(|e| [e[0] as f32, e[1] as f32, e[2] as f32])
                            .collect()
                    })
                    .collect()
            },
        };
        mesh.validate_fe()?;
        Ok(mesh)
    }

    /// The strain field `Σ_k ε_k q_k` at every node, for the given modal coordinates
    /// (modes beyond `q.len()` count as zero).
    pub fn strain_field(&self, q: &[f32]) -> Vec<[f32; 3]> {
        let mut out = vec![[0.0f32; 3]; self.nodes.len()];
        for (k, s) in self.strains.iter().enumerate() {
            let qk = q.get(k).copied().unwrap_or(0.0);
            if qk == 0.0 {
                continue;
            }
            for (o, e) in out.iter_mut().zip(s) {
                for c in 0..3 {
                    o[c] += e[c] * qk;
                }
            }
        }
        out
    }

    /// The largest |Σ_k φ_k q_k| over the nodes, metres (the true deflection scale).
    pub fn max_deflection(&self, q: &[f32]) -> f32 {
        let mut best = 0.0f32;
        for i in 0..self.nodes.len() {
            let w: f32 = self.shapes.iter().zip(q).map(|(s, qk)| s[i] * qk).sum();
            best = best.max(w.abs());
        }
        best
    }
}

/// A JSON value, shortened for an error message.
fn short(v: &Value) -> String {
    let s = v.to_string();
    if s.len() > 40 {
        format!(
            "{}…",
            &s[..s.char_indices().nth(40).map_or(s.len(), |c| c.0)]
        )
    } else {
        s
    }
}
