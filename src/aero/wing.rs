//! The wing as the air sees it: a strip quadrature over the planform built from an FE mesh and
//! its mode shapes, and the modal loads (aerodynamic force, damping and added-mass matrices)
//! evaluated on it.
//!
//! The planform is the mesh projected on the I″–J″ plane (camber is ignored by the air). The
//! span [x_min, x_max] is cut into equal strips with two Gauss–Legendre stations each; at a
//! station x the chord is where the line x = const crosses the mesh's triangles (several
//! intervals where a planform is notched), and each interval carries Gauss–Legendre points
//! across the chord. The mode shapes are interpolated linearly inside the triangles crossed,
//! which is how the FE result is defined between nodes for the out-of-plane displacement.
//! The quadrature converges with the number of strips and chord points
//! (`tests/aero_loads.rs`); it is exact for a rectangular plate in face-on flapping, whose
//! |v|v load is a polynomial in x.

use super::{damping_density, normal_pressure, AeroConfig, FrameState};
use crate::error::{Result, WingbeatError};
use serde::{Deserialize, Serialize};

/// What the aerodynamic model needs from an FE wing: the mesh in the wing frame and the
/// mass-normalised out-of-plane mode shapes at its nodes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WingGeometry {
    /// Node positions [x, y] (m), x spanwise from the root, y chordwise.
    pub nodes: Vec<[f64; 2]>,
    /// Triangles (node indices).
    pub triangles: Vec<[usize; 3]>,
    /// Per mode, the out-of-plane displacement at each node, kg^-½ (Σ φ_k φ_l dm = δ_kl).
    pub shapes: Vec<Vec<f64>>,
}

impl WingGeometry {
    /// From an FE result (`nodes` [x, y, z] in m; camber z dropped).
    pub fn from_fem(fe: &crate::fem::FemModes) -> Self {
        WingGeometry {
            nodes: fe.nodes.iter().map(|p| [p[0], p[1]]).collect(),
            triangles: fe.triangles.clone(),
            shapes: fe.shapes.clone(),
        }
    }

    /// Checks sizes, indices and finiteness; `n_modes` is the run's mode count.
    pub fn validate(&self, n_modes: usize) -> Result<()> {
        let n = self.nodes.len();
        if n < 3 || self.triangles.is_empty() {
            return Err(WingbeatError::invalid(
                "wing.nodes",
                format!("{n} nodes, {} triangles", self.triangles.len()),
                "an FE mesh with at least 3 nodes and one triangle",
            ));
        }
        if self.shapes.len() != n_modes {
            return Err(WingbeatError::invalid(
                "wing.shapes",
                format!("{} mode shapes", self.shapes.len()),
                format!("one shape per mode of the run ({n_modes})"),
            ));
        }
        for (i, p) in self.nodes.iter().enumerate() {
            if !(p[0].is_finite() && p[1].is_finite()) {
                return Err(WingbeatError::invalid(
                    format!("wing.nodes[{i}]"),
                    format!("{p:?}"),
                    "finite coordinates in m",
                ));
            }
        }
        for (i, t) in self.triangles.iter().enumerate() {
            if t.iter().any(|&v| v >= n) {
                return Err(WingbeatError::invalid(
                    format!("wing.triangles[{i}]"),
                    format!("{t:?}"),
                    format!("node indices below {n}"),
                ));
            }
        }
        for (k, s) in self.shapes.iter().enumerate() {
            if s.len() != n || s.iter().any(|v| !v.is_finite()) {
                return Err(WingbeatError::invalid(
                    format!("wing.shapes[{k}]"),
                    format!("{} values", s.len()),
                    format!("{n} finite values (one per node), kg^-0.5"),
                ));
            }
        }
        Ok(())
    }
}

/// One chord interval at one span station: its added-mass data.
#[derive(Debug, Clone, PartialEq)]
pub struct StripPiece {
    /// Span station x, m.
    pub x: f64,
    /// Mid-chord y, m.
    pub y_mid: f64,
    /// Half chord b, m.
    pub half_chord: f64,
    /// Spanwise quadrature weight, m.
    pub dx: f64,
    /// Per mode: the heave of the fitted chordwise shape at mid-chord (kg^-½).
    pub heave: Vec<f64>,
    /// Per mode: its pitch ∂φ/∂y (kg^-½ per m).
    pub pitch: Vec<f64>,
}

/// The aerodynamic quadrature of one wing and its modes.
#[derive(Debug, Clone, PartialEq)]
pub struct AeroWing {
    /// Number of modes.
    pub n_modes: usize,
    /// Quadrature points [x, y] (m).
    pub points: Vec<[f64; 2]>,
    /// Quadrature weights (m²); they sum to the planform area.
    pub weights: Vec<f64>,
    /// Mode values at the points, point-major: `phi[p * n_modes + k]`, kg^-½.
    pub phi: Vec<f64>,
    /// The chord pieces for the added mass.
    pub pieces: Vec<StripPiece>,
    /// Per point the products the loads sum, point-major: φ_k (N values), then φ_a φ_b for
    /// a ≤ b (C_a's upper triangle, row by row).
    packed: Vec<f64>,
}

/// Gauss–Legendre nodes and weights on [−1, 1] (Newton on the Legendre recurrence).
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut x = vec![0.0; n];
    let mut w = vec![0.0; n];
    let nf = n as f64;
    for i in 0..n.div_ceil(2) {
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (nf + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, z);
            if n == 1 {
                p1 = z;
                p0 = 1.0;
            } else {
                for j in 2..=n {
                    let jf = j as f64;
                    let p2 = ((2.0 * jf - 1.0) * z * p1 - (jf - 1.0) * p0) / jf;
                    p0 = p1;
                    p1 = p2;
                }
            }
            // p1 = P_n(z), p0 = P_{n−1}(z)
            dp = nf * (z * p1 - p0) / (z * z - 1.0);
            let dz = p1 / dp;
            z -= dz;
            if dz.abs() <= 1e-16 {
                break;
            }
        }
        x[i] = -z;
        x[n - 1 - i] = z;
        let wi = 2.0 / ((1.0 - z * z) * dp * dp);
        w[i] = wi;
        w[n - 1 - i] = wi;
    }
    if n == 1 {
        x[0] = 0.0;
        w[0] = 2.0;
    }
    (x, w)
}

/// A piece of the line x = const inside one triangle: its end points and the mode values there.
struct Segment {
    y0: f64,
    y1: f64,
    w0: Vec<f64>,
    w1: Vec<f64>,
}

/// The crossings of the line x = `xs` with the mesh.
fn crossings(g: &WingGeometry, xs: f64) -> Vec<Segment> {
    let nm = g.shapes.len();
    let mut out = Vec::new();
    for t in &g.triangles {
        let p = t.map(|i| g.nodes[i]);
        let (xmin, xmax) = p
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), q| {
                (a.min(q[0]), b.max(q[0]))
            });
        if xs < xmin || xs > xmax || xmax <= xmin {
            continue;
        }
        let mut hits: Vec<(f64, usize, usize, f64)> = Vec::with_capacity(3);
        for (a, b) in [(0, 1), (1, 2), (2, 0)] {
            let (xa, xb) = (p[a][0], p[b][0]);
            if xa == xb {
                continue;
            }
            let s = (xs - xa) / (xb - xa);
            if (0.0..=1.0).contains(&s) {
                hits.push((p[a][1] + s * (p[b][1] - p[a][1]), t[a], t[b], s));
            }
        }
        if hits.len() < 2 {
            continue;
        }
        let lo = hits
            .iter()
            .min_by(|u, v| u.0.total_cmp(&v.0))
            .copied()
            .expect("two hits");
        let hi = hits
            .iter()
            .max_by(|u, v| u.0.total_cmp(&v.0))
            .copied()
            .expect("two hits");
        if hi.0 <= lo.0 {
            continue;
        }
        let val = |h: (f64, usize, usize, f64)| -> Vec<f64> {
            (0..nm)
                .map(|k| g.shapes[k][h.1] + h.3 * (g.shapes[k][h.2] - g.shapes[k][h.1]))
                .collect()
        };
        out.push(Segment {
            y0: lo.0,
            y1: hi.0,
            w0: val(lo),
            w1: val(hi),
        });
    }
    out.sort_by(|a, b| a.y0.total_cmp(&b.y0));
    out
}

/// Mode values at `y` from the crossing segments (the segment containing y, else the nearest).
fn values_at(segs: &[Segment], y: f64, out: &mut [f64]) {
    let mut best = (f64::INFINITY, 0usize);
    for (i, s) in segs.iter().enumerate() {
        let d = if y < s.y0 {
            s.y0 - y
        } else if y > s.y1 {
            y - s.y1
        } else {
            0.0
        };
        if d < best.0 {
            best = (d, i);
            if d == 0.0 {
                break;
            }
        }
    }
    let s = &segs[best.1];
    let u = ((y - s.y0) / (s.y1 - s.y0)).clamp(0.0, 1.0);
    for (k, o) in out.iter_mut().enumerate() {
        *o = s.w0[k] + u * (s.w1[k] - s.w0[k]);
    }
}

/// Merges the segments into the chord intervals [y_lo, y_hi] at one station.
fn intervals(segs: &[Segment], tol: f64) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::new();
    for s in segs {
        match out.last_mut() {
            Some(last) if s.y0 <= last.1 + tol => last.1 = last.1.max(s.y1),
            _ => out.push((s.y0, s.y1)),
        }
    }
    out
}

impl AeroWing {
    /// Builds the quadrature of `geom` with the strip counts of `cfg`.
    pub fn build(geom: &WingGeometry, cfg: &AeroConfig) -> Result<AeroWing> {
        let nm = geom.shapes.len();
        let (x0, x1) = geom
            .nodes
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p[0]), b.max(p[0]))
            });
        let (y0, y1) = geom
            .nodes
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p[1]), b.max(p[1]))
            });
        let span = x1 - x0;
        if span.is_nan() || span <= 0.0 {
            return Err(WingbeatError::Geometry(
                "the wing mesh has no spanwise extent".into(),
            ));
        }
        let tol = 1e-9 * span.max(y1 - y0);
        let (gx, wx) = gauss_legendre(2);
        let (gc, wc) = gauss_legendre(cfg.chord_points);
        let strip = span / cfg.strips as f64;
        let mut wing = AeroWing {
            n_modes: nm,
            points: Vec::new(),
            weights: Vec::new(),
            phi: Vec::new(),
            pieces: Vec::new(),
            packed: Vec::new(),
        };
        let mut vals = vec![0.0; nm];
        for s in 0..cfg.strips {
            for (gxi, wxi) in gx.iter().zip(&wx) {
                let xs = x0 + strip * (s as f64 + 0.5 * (1.0 + gxi));
                let dx = 0.5 * strip * wxi;
                let segs = crossings(geom, xs);
                if segs.is_empty() {
                    continue;
                }
                for (lo, hi) in intervals(&segs, tol) {
                    let b = 0.5 * (hi - lo);
                    let ym = 0.5 * (hi + lo);
                    // Heave and pitch fit weighted by the heave pressure √(1 − s²).
                    let (mut sw, mut sws2) = (0.0, 0.0);
                    let mut heave = vec![0.0; nm];
                    let mut pitch = vec![0.0; nm];
                    for (sc, wci) in gc.iter().zip(&wc) {
                        let y = ym + b * sc;
                        values_at(&segs, y, &mut vals);
                        wing.points.push([xs, y]);
                        wing.weights.push(dx * b * wci);
                        wing.phi.extend_from_slice(&vals);
                        let ww = wci * (1.0 - sc * sc).sqrt();
                        sw += ww;
                        sws2 += ww * sc * sc;
                        for k in 0..nm {
                            heave[k] += ww * vals[k];
                            pitch[k] += ww * sc * vals[k];
                        }
                    }
                    for k in 0..nm {
                        heave[k] /= sw;
                        pitch[k] = if sws2 > 0.0 {
                            pitch[k] / (sws2 * b)
                        } else {
                            0.0
                        };
                    }
                    wing.pieces.push(StripPiece {
                        x: xs,
                        y_mid: ym,
                        half_chord: b,
                        dx,
                        heave,
                        pitch,
                    });
                }
            }
        }
        if wing.points.is_empty() {
            return Err(WingbeatError::Geometry(
                "no aerodynamic quadrature point fell on the wing mesh".into(),
            ));
        }
        let width = nm + nm * (nm + 1) / 2;
        wing.packed = Vec::with_capacity(wing.points.len() * width);
        for phi in wing.phi.chunks_exact(nm.max(1)).take(wing.points.len()) {
            wing.packed.extend_from_slice(phi);
            for a in 0..nm {
                for b in a..nm {
                    wing.packed.push(phi[a] * phi[b]);
                }
            }
        }
        Ok(wing)
    }

    /// Planform area covered by the quadrature, m².
    pub fn area(&self) -> f64 {
        self.weights.iter().sum()
    }

    /// The added-mass matrix M_a (N × N, row-major, dimensionless for mass-normalised modes)
    /// of a fluid of density `rho` (kg/m³): ρ Σ dx [π b² h_k h_l + π b⁴/8 θ_k θ_l].
    pub fn added_mass(&self, rho: f64) -> Vec<f64> {
        let n = self.n_modes;
        let mut m = vec![0.0; n * n];
        for p in &self.pieces {
            let b2 = p.half_chord * p.half_chord;
            let heave = rho * std::f64::consts::PI * b2 * p.dx;
            let rot = heave * b2 / 8.0;
            for k in 0..n {
                for l in 0..n {
                    m[k * n + l] += heave * p.heave[k] * p.heave[l] + rot * p.pitch[k] * p.pitch[l];
                }
            }
        }
        m
    }

    /// The aerodynamic loads at one instant for the rigid motion `fs`: adds the aerodynamic
    /// generalised force F_A,k (kg^½·m/s²) into `force` (length N) and the damping matrix
    /// C_a (1/s, N × N row-major) into `damping`. `k` = ½ ρ C_N,max; the added-mass force
    /// uses `rho` (0 to leave it out).
    pub fn loads(&self, fs: &FrameState, k: f64, rho: f64, force: &mut [f64], damping: &mut [f64]) {
        let n = self.n_modes;
        let width = n + n * (n + 1) / 2;
        // Σ_p w_p f_p φ_k and Σ_p w_p c_p φ_a φ_b, from the packed products.
        let mut acc = vec![0.0; width];
        for ((xy, w), row) in self
            .points
            .iter()
            .zip(&self.weights)
            .zip(self.packed.chunks_exact(width))
        {
            let fl = fs.flow(xy[0], xy[1]);
            let f = normal_pressure(k, fl.vn, fl.speed) * w;
            let c = damping_density(k, fl.vn, fl.speed) * w;
            let (rf, rc) = row.split_at(n);
            let (af, ac) = acc.split_at_mut(n);
            for (a, v) in af.iter_mut().zip(rf) {
                *a += v * f;
            }
            for (a, v) in ac.iter_mut().zip(rc) {
                *a += v * c;
            }
        }
        for a in 0..n {
            force[a] += acc[a];
        }
        let mut slot = n;
        for a in 0..n {
            for b in a..n {
                damping[a * n + b] += acc[slot];
                slot += 1;
            }
        }
        for a in 0..n {
            for b in 0..a {
                damping[a * n + b] = damping[b * n + a];
            }
        }
        if rho > 0.0 {
            self.added_mass_force(fs, rho, force);
        }
    }

    /// Adds the added-mass force of the rigid motion: − ρ Σ dx [π b² h_k a_heave + π b⁴/8 θ_k a_pitch]
    /// with a_heave, a_pitch the rigid normal acceleration at mid-chord and its chordwise slope.
    pub fn added_mass_force(&self, fs: &FrameState, rho: f64, force: &mut [f64]) {
        let n = self.n_modes;
        for p in &self.pieces {
            let b2 = p.half_chord * p.half_chord;
            let heave = rho * std::f64::consts::PI * b2 * p.dx;
            let rot = heave * b2 / 8.0;
            let a_h = fs.normal_acceleration(p.x, p.y_mid);
            let a_p = fs.normal_acceleration_slope(p.x, p.y_mid);
            for k in 0..n {
                force[k] -= heave * p.heave[k] * a_h + rot * p.pitch[k] * a_p;
            }
        }
    }

    /// The unlinearised aerodynamic force for the rigid motion `fs` plus the elastic velocity
    /// q̇ (kg^½·m/s): Σ_p w_p φ_k(p) f_n(v₀ₙ + Σ φ_l q̇_l), added into `force`; the added-mass
    /// force of the rigid motion is added as in [`AeroWing::loads`]. The nonlinear reference
    /// path ([`super::nonlinear`]) calls it at every stage.
    pub fn loads_nonlinear(
        &self,
        fs: &FrameState,
        k: f64,
        rho: f64,
        qdot: &[f64],
        force: &mut [f64],
    ) {
        let n = self.n_modes;
        for (p, (xy, w)) in self.points.iter().zip(&self.weights).enumerate() {
            let phi = &self.phi[p * n..(p + 1) * n];
            let wdot: f64 = phi.iter().zip(qdot).map(|(a, b)| a * b).sum();
            let fl = fs.flow(xy[0], xy[1]);
            let vn = fl.vn + wdot;
            let speed = (fl.speed * fl.speed - fl.vn * fl.vn + vn * vn)
                .max(0.0)
                .sqrt();
            let f = normal_pressure(k, vn, speed) * w;
            for a in 0..n {
                force[a] += phi[a] * f;
            }
        }
        if rho > 0.0 {
            self.added_mass_force(fs, rho, force);
        }
    }
}
