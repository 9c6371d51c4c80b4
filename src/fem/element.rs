//! The flat thin-shell triangle: DKT bending + an Allman-type membrane with drilling
//! rotations (stabilised by a small Hughes–Brezzi-type penalty tying the drilling rotation to
//! the membrane's in-plane rotation), 6 DOF per node, in a local element frame transformed to
//! the global frame. Lumped (diagonal) mass.
//!
//! DOF order per node: u, v, w (translations), θx, θy, θz (rotations about x, y, z), all in
//! the global frame. Kirchhoff sign convention: ∂w/∂x = −θy, ∂w/∂y = θx.

use nalgebra::{SMatrix, SVector};

/// 18 × 18 element matrix.
pub type Mat18 = SMatrix<f64, 18, 18>;
/// 18-vector of element DOFs.
pub type Vec18 = SVector<f64, 18>;

/// Drilling-penalty factor: the drilling energy is ½ k ∫ (θz − ω)² dA with
/// k = `DRILL_FACTOR` × (plate bending stiffness D) / (element area). Kept small so that the
/// term only removes the zero-energy drilling mode and does not stiffen curved shells (the
/// sensitivity is reported in docs/fem.md).
pub const DRILL_FACTOR: f64 = 1.0e-2;

/// Isotropic linear-elastic shell material (SI units).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShellMaterial {
    /// Shell thickness t, m.
    pub thickness_m: f64,
    /// Young's modulus E, Pa.
    pub e_pa: f64,
    /// Density ρ, kg/m³.
    pub rho_kg_m3: f64,
    /// Poisson's ratio ν, in (−1, 0.5).
    pub nu: f64,
}

impl ShellMaterial {
    /// Plane-stress elasticity matrix E/(1−ν²)[[1,ν,0],[ν,1,0],[0,0,(1−ν)/2]].
    fn plane_stress(&self) -> [[f64; 3]; 3] {
        let f = self.e_pa / (1.0 - self.nu * self.nu);
        [
            [f, f * self.nu, 0.0],
            [f * self.nu, f, 0.0],
            [0.0, 0.0, f * 0.5 * (1.0 - self.nu)],
        ]
    }

    /// Plate bending stiffness D = E t³ / (12 (1 − ν²)), N·m.
    pub fn bending_stiffness(&self) -> f64 {
        self.e_pa * self.thickness_m.powi(3) / (12.0 * (1.0 - self.nu * self.nu))
    }
}

/// Local frame of a flat triangle: rows of `r` are e1 (along edge 1→2), e2, and the unit
/// normal n; `x`, `y` are node coordinates in that frame (node 1 at the origin).
#[derive(Debug, Clone, Copy)]
pub struct Frame {
    /// Rotation matrix, rows e1, e2, n (global → local).
    pub r: [[f64; 3]; 3],
    /// Local x of the three nodes, m.
    pub x: [f64; 3],
    /// Local y of the three nodes, m.
    pub y: [f64; 3],
    /// Triangle area, m².
    pub area: f64,
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn unit(a: [f64; 3]) -> Option<[f64; 3]> {
    let n = dot(a, a).sqrt();
    (n > 0.0 && n.is_finite()).then(|| [a[0] / n, a[1] / n, a[2] / n])
}

impl Frame {
    /// Builds the frame of triangle `p`; `None` for a degenerate (zero-area) triangle.
    pub fn new(p: &[[f64; 3]; 3]) -> Option<Frame> {
        let d1 = sub(p[1], p[0]);
        let d2 = sub(p[2], p[0]);
        let e1 = unit(d1)?;
        let nn = cross(d1, d2);
        let area = 0.5 * dot(nn, nn).sqrt();
        let n = unit(nn)?;
        let e2 = cross(n, e1);
        let r = [e1, e2, n];
        let x = [0.0, dot(d1, e1), dot(d2, e1)];
        let y = [0.0, dot(d1, e2), dot(d2, e2)];
        (area > 0.0).then_some(Frame { r, x, y, area })
    }

    /// Derivatives of the area coordinates: (∂L_i/∂x, ∂L_i/∂y) for i = 0..3.
    fn dl(&self) -> ([f64; 3], [f64; 3]) {
        let (x, y) = (self.x, self.y);
        let two_a = 2.0 * self.area;
        let mut b = [0.0; 3];
        let mut c = [0.0; 3];
        for i in 0..3 {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            b[i] = (y[j] - y[k]) / two_a;
            c[i] = (x[k] - x[j]) / two_a;
        }
        (b, c)
    }

    /// Global-to-local 18 × 18 transformation (block diagonal of `r`).
    pub fn transform(&self) -> Mat18 {
        let mut t = Mat18::zeros();
        for blk in 0..6 {
            for i in 0..3 {
                for j in 0..3 {
                    t[(3 * blk + i, 3 * blk + j)] = self.r[i][j];
                }
            }
        }
        t
    }
}

/// Quadratic (6-node) shape-function derivatives at area coordinates `l`; node order:
/// corners 0, 1, 2, then mid-sides of edges (1,2), (2,0), (0,1).
fn quad_derivs(f: &Frame, l: [f64; 3]) -> ([f64; 6], [f64; 6], [f64; 6]) {
    let (bx, by) = f.dl();
    let mut n = [0.0; 6];
    let mut nx = [0.0; 6];
    let mut ny = [0.0; 6];
    for i in 0..3 {
        n[i] = l[i] * (2.0 * l[i] - 1.0);
        nx[i] = (4.0 * l[i] - 1.0) * bx[i];
        ny[i] = (4.0 * l[i] - 1.0) * by[i];
    }
    for (k, (p, q)) in MIDSIDES {
        n[k] = 4.0 * l[p] * l[q];
        nx[k] = 4.0 * (l[p] * bx[q] + l[q] * bx[p]);
        ny[k] = 4.0 * (l[p] * by[q] + l[q] * by[p]);
    }
    (n, nx, ny)
}

/// Mid-side node k and the edge (i, j) it sits on.
const MIDSIDES: [(usize, (usize, usize)); 3] = [(3, (1, 2)), (4, (2, 0)), (5, (0, 1))];

/// Allman-type membrane: the in-plane displacement is quadratic (6-node), with the mid-side
/// values built from the corner translations and drilling rotations ω:
/// u_mid = ½(u_i + u_j) + (ω_j − ω_i)/8 · (y_j − y_i, −(x_j − x_i)) (outward edge normal × l/8).
/// Returns (B over u_i, v_i, ω_i ×3 giving [ε_x, ε_y, γ_xy]; in-plane rotation row
/// ½(∂v/∂x − ∂u/∂y) over the same DOFs) at area coordinates `l`.
fn membrane_b(f: &Frame, l: [f64; 3]) -> ([[f64; 9]; 3], [f64; 9]) {
    // a[k][c] = displacement component c of quadratic node k over (u, v, ω) × 3
    let mut a = [[[0.0f64; 9]; 2]; 6];
    for i in 0..3 {
        a[i][0][3 * i] = 1.0;
        a[i][1][3 * i + 1] = 1.0;
    }
    for (k, (i, j)) in MIDSIDES {
        let (dx, dy) = (f.x[j] - f.x[i], f.y[j] - f.y[i]);
        for c in 0..2 {
            a[k][c][3 * i + c] = 0.5;
            a[k][c][3 * j + c] = 0.5;
        }
        a[k][0][3 * j + 2] += dy / 8.0;
        a[k][0][3 * i + 2] -= dy / 8.0;
        a[k][1][3 * j + 2] -= dx / 8.0;
        a[k][1][3 * i + 2] += dx / 8.0;
    }
    let (_, nx, ny) = quad_derivs(f, l);
    let mut b = [[0.0; 9]; 3];
    let mut w = [0.0; 9];
    for k in 0..6 {
        for d in 0..9 {
            b[0][d] += nx[k] * a[k][0][d];
            b[1][d] += ny[k] * a[k][1][d];
            b[2][d] += ny[k] * a[k][0][d] + nx[k] * a[k][1][d];
            w[d] += 0.5 * (nx[k] * a[k][1][d] - ny[k] * a[k][0][d]);
        }
    }
    (b, w)
}

/// Local index of membrane DOF q (u, v, ω per node) in the 18-DOF element vector.
fn midx(q: usize) -> usize {
    let node = q / 3;
    6 * node + [0, 1, 5][q % 3]
}

/// DKT curvature matrix at area coordinates `l`: maps the 9 local bending DOFs
/// (w, θx, θy per node) to κ = [∂²w/∂x², ∂²w/∂y², 2∂²w/∂x∂y].
///
/// Built from its definition: the rotations (slopes) vary quadratically over the 6-node
/// triangle; at the corners they equal the nodal slopes, at mid-sides the tangential slope
/// comes from the cubic edge interpolation of w and the normal slope is the mean of the
/// corner values (discrete Kirchhoff constraints).
pub fn dkt_b(f: &Frame, l: [f64; 3]) -> [[f64; 9]; 3] {
    // a[k] = slope (βx, βy) at 6 nodes as a function of the slope DOFs (w, wx, wy) × 3.
    let mut a = [[[0.0f64; 9]; 2]; 6];
    for i in 0..3 {
        a[i][0][3 * i + 1] = 1.0;
        a[i][1][3 * i + 2] = 1.0;
    }
    // mid-side nodes 3, 4, 5 on edges (1,2), (2,0), (0,1)
    for (k, (i, j)) in [(3usize, (1usize, 2usize)), (4, (2, 0)), (5, (0, 1))] {
        let dx = f.x[j] - f.x[i];
        let dy = f.y[j] - f.y[i];
        let len = (dx * dx + dy * dy).sqrt();
        let (c, s) = (dx / len, dy / len);
        let kw = 1.5 / len;
        // βx = c βs + s βn, βy = s βs − c βn
        for (node, sign) in [(i, -1.0), (j, 1.0)] {
            a[k][0][3 * node] += c * sign * kw;
            a[k][1][3 * node] += s * sign * kw;
            a[k][0][3 * node + 1] += -0.25 * c * c + 0.5 * s * s;
            a[k][0][3 * node + 2] += -0.75 * c * s;
            a[k][1][3 * node + 1] += -0.75 * c * s;
            a[k][1][3 * node + 2] += -0.25 * s * s + 0.5 * c * c;
        }
    }
    let (_, nx, ny) = quad_derivs(f, l);
    let mut bs = [[0.0; 9]; 3];
    for k in 0..6 {
        for d in 0..9 {
            bs[0][d] += nx[k] * a[k][0][d];
            bs[1][d] += ny[k] * a[k][1][d];
            bs[2][d] += ny[k] * a[k][0][d] + nx[k] * a[k][1][d];
        }
    }
    // slope DOFs (w, wx, wy) → rotation DOFs (w, θx, θy): wx = −θy, wy = θx
    let mut br = [[0.0; 9]; 3];
    for r in 0..3 {
        for i in 0..3 {
            br[r][3 * i] = bs[r][3 * i];
            br[r][3 * i + 1] = bs[r][3 * i + 2];
            br[r][3 * i + 2] = -bs[r][3 * i + 1];
        }
    }
    br
}

const GAUSS3: [[f64; 3]; 3] = [
    [2.0 / 3.0, 1.0 / 6.0, 1.0 / 6.0],
    [1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0],
    [1.0 / 6.0, 1.0 / 6.0, 2.0 / 3.0],
];

/// Element stiffness in the LOCAL frame (18 × 18): membrane (CST) + drilling + DKT bending.
pub fn local_stiffness(f: &Frame, mat: &ShellMaterial) -> Mat18 {
    let c = mat.plane_stress();
    let t = mat.thickness_m;
    let a = f.area;
    let mut k = Mat18::zeros();
    // Allman-type membrane + drilling penalty ½ kd ∫ (Σ L_i ω_i − ½(∂v/∂x − ∂u/∂y))² dA; the
    // penalty removes Allman's spurious equal-rotation mode. 3-point rule: exact for both.
    let kd = DRILL_FACTOR * mat.bending_stiffness() / a;
    for l in GAUSS3 {
        let (bm, w) = membrane_b(f, l);
        let mut pen = w.map(|x| -x);
        for i in 0..3 {
            pen[3 * i + 2] += l[i];
        }
        for p in 0..9 {
            for q in 0..9 {
                let mut s = 0.0;
                for i in 0..3 {
                    for j in 0..3 {
                        s += bm[i][p] * c[i][j] * bm[j][q];
                    }
                }
                k[(midx(p), midx(q))] += a / 3.0 * (t * s + kd * pen[p] * pen[q]);
            }
        }
    }
    // DKT bending
    let db = mat.bending_stiffness() * (1.0 - mat.nu * mat.nu) / mat.e_pa;
    let bidx = |q: usize| 6 * (q / 3) + 2 + (q % 3);
    for l in GAUSS3 {
        let bb = dkt_b(f, l);
        for p in 0..9 {
            for q in 0..9 {
                let mut s = 0.0;
                for i in 0..3 {
                    for j in 0..3 {
                        s += bb[i][p] * c[i][j] * bb[j][q];
                    }
                }
                k[(bidx(p), bidx(q))] += a / 3.0 * db * s;
            }
        }
    }
    k
}

/// Element stiffness in the GLOBAL frame, Tᵀ K_local T; `None` for a degenerate triangle.
pub fn global_stiffness(p: &[[f64; 3]; 3], mat: &ShellMaterial) -> Option<Mat18> {
    let f = Frame::new(p)?;
    let kl = local_stiffness(&f, mat);
    // K_g = Tᵀ K_l T with T = diag(R, …, R): transform each 3 × 3 block as Rᵀ K_ab R
    let r = f.r;
    let mut kg = Mat18::zeros();
    for bi in 0..6 {
        for bj in 0..6 {
            let mut tmp = [[0.0; 3]; 3]; // K_ab R
            for i in 0..3 {
                for j in 0..3 {
                    let mut s = 0.0;
                    for k in 0..3 {
                        s += kl[(3 * bi + i, 3 * bj + k)] * r[k][j];
                    }
                    tmp[i][j] = s;
                }
            }
            for i in 0..3 {
                for j in 0..3 {
                    let mut s = 0.0;
                    for k in 0..3 {
                        s += r[k][i] * tmp[k][j];
                    }
                    kg[(3 * bi + i, 3 * bj + j)] = s;
                }
            }
        }
    }
    Some(kg)
}

/// Lumped (diagonal) mass per node of a triangle of area `area`: translational ρtA/3 and an
/// isotropic rotary inertia ρ(t³/12)A/3 for each rotation (isotropic, so frame-invariant).
pub fn lumped_mass(area: f64, mat: &ShellMaterial) -> (f64, f64) {
    let m = mat.rho_kg_m3 * mat.thickness_m * area / 3.0;
    (m, m * mat.thickness_m * mat.thickness_m / 12.0)
}

/// Top-surface (z = +t/2 along the element normal) strain of the element at its corner
/// `corner` for global element displacements `u`, expressed in the GLOBAL x–y directions:
/// [ε_x, ε_y, γ_xy] (membrane plus bending, ε = ε_m − (t/2) κ).
pub fn corner_surface_strain(
    p: &[[f64; 3]; 3],
    mat: &ShellMaterial,
    u: &Vec18,
    corner: usize,
) -> Option<[f64; 3]> {
    let f = Frame::new(p)?;
    let d = f.transform() * u;
    let mut l = [0.0; 3];
    l[corner] = 1.0;
    let (bm, _) = membrane_b(&f, l);
    let bb = dkt_b(&f, l);
    let mut e = [0.0; 3];
    for r in 0..3 {
        for q in 0..9 {
            e[r] += bm[r][q] * d[midx(q)];
        }
        let mut kap = 0.0;
        for q in 0..9 {
            kap += bb[r][q] * d[6 * (q / 3) + 2 + (q % 3)];
        }
        e[r] -= 0.5 * mat.thickness_m * kap;
    }
    let (e1, e2) = (f.r[0], f.r[1]);
    let ex = e1[0] * e1[0] * e[0] + e2[0] * e2[0] * e[1] + e1[0] * e2[0] * e[2];
    let ey = e1[1] * e1[1] * e[0] + e2[1] * e2[1] * e[1] + e1[1] * e2[1] * e[2];
    let gxy = 2.0 * e1[0] * e1[1] * e[0]
        + 2.0 * e2[0] * e2[1] * e[1]
        + (e1[0] * e2[1] + e2[0] * e1[1]) * e[2];
    Some([ex, ey, gxy])
}
