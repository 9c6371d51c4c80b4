//! CPU-side scene maths shared by the GPU path and the tests: the wing rotation, the orbit
//! camera, per-frame parameters and their sanitising, the strain colour map and its legend.
//!
//! Matrices are column-major `[[f32; 4]; 4]` (an array of columns), exactly as uploaded.

use super::MAX_MODES;

/// A column-major 4×4 matrix (`m[column][row]`).
pub type Mat4 = [[f32; 4]; 4];

/// The identity matrix.
pub const IDENTITY: Mat4 = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

/// `a · b`.
pub fn mat_mul(a: &Mat4, b: &Mat4) -> Mat4 {
    let mut out = [[0.0f32; 4]; 4];
    for c in 0..4 {
        for r in 0..4 {
            out[c][r] = (0..4).map(|k| a[k][r] * b[c][k]).sum();
        }
    }
    out
}

/// `m · (p, 1)`, returning all four homogeneous components.
pub fn transform(m: &Mat4, p: [f32; 3]) -> [f32; 4] {
    let mut out = [0.0f32; 4];
    for r in 0..4 {
        out[r] = m[0][r] * p[0] + m[1][r] * p[1] + m[2][r] * p[2] + m[3][r];
    }
    out
}

fn rot_x(a: f32) -> Mat4 {
    let (s, c) = a.sin_cos();
    [
        [1.0, 0.0, 0.0, 0.0],
        [0.0, c, s, 0.0],
        [0.0, -s, c, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

fn rot_y(a: f32) -> Mat4 {
    let (s, c) = a.sin_cos();
    [
        [c, 0.0, -s, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [s, 0.0, c, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

fn rot_z(a: f32) -> Mat4 {
    let (s, c) = a.sin_cos();
    [
        [c, s, 0.0, 0.0],
        [-s, c, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

/// The rotating frame I″–J″–K″ in the fixed frame: roll α about the fixed I axis, then pitch β
/// about the rolled axis J′, i.e. `R_x(α) · R_y(β)` (paper §2.1; its body-frame angular velocity
/// is Eq. 1's Ω = (α̇ cos β, β̇, α̇ sin β)). Columns are I″, J″, K″.
pub fn frame_rotation(alpha: f32, beta: f32) -> Mat4 {
    mat_mul(&rot_x(alpha), &rot_y(beta))
}

/// The wing's rotation: the frame rotation followed by the yaw γ about K″,
/// `R = R_x(α) · R_y(β) · R_z(γ)`. The paper keeps γ to first order (r₂ = γ(−y, x, 0) in the
/// I″–J″ plane); rendering uses the exact R_z(γ), which agrees with it to O(γ²).
///
/// A wing point p = (x, y, z + w) in the wing frame is drawn at R·p in the fixed frame; the
/// vertex shader does exactly `u.wing_rot * vec4(p, 1)` with this matrix.
pub fn wing_rotation(alpha: f32, beta: f32, gamma: f32) -> Mat4 {
    mat_mul(&frame_rotation(alpha, beta), &rot_z(gamma))
}

/// Where a wing-frame point lands in the fixed frame (the CPU mirror of the vertex shader).
pub fn wing_point_to_world(alpha: f32, beta: f32, gamma: f32, p: [f32; 3]) -> [f32; 3] {
    let v = transform(&wing_rotation(alpha, beta, gamma), p);
    [v[0], v[1], v[2]]
}

/// A right-handed perspective projection with WebGPU's depth range [0, 1].
pub fn perspective(fov_y: f32, aspect: f32, near: f32, far: f32) -> Mat4 {
    let f = 1.0 / (0.5 * fov_y).tan();
    let r = far / (near - far);
    [
        [f / aspect, 0.0, 0.0, 0.0],
        [0.0, f, 0.0, 0.0],
        [0.0, 0.0, r, -1.0],
        [0.0, 0.0, r * near, 0.0],
    ]
}

fn sub(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn dot(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn normalize(a: [f32; 3]) -> [f32; 3] {
    let n = dot(a, a).sqrt();
    if n > 0.0 {
        [a[0] / n, a[1] / n, a[2] / n]
    } else {
        [0.0, 0.0, 1.0]
    }
}

/// A right-handed view matrix looking from `eye` at `target` with `up`.
pub fn look_at(eye: [f32; 3], target: [f32; 3], up: [f32; 3]) -> Mat4 {
    let f = normalize(sub(target, eye));
    let s = normalize(cross(f, up));
    let u = cross(s, f);
    [
        [s[0], u[0], -f[0], 0.0],
        [s[1], u[1], -f[1], 0.0],
        [s[2], u[2], -f[2], 0.0],
        [-dot(s, eye), -dot(u, eye), dot(f, eye), 1.0],
    ]
}

/// Keys the orbit camera understands (the page maps arrow keys, +/− to these).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OrbitKey {
    /// Orbit left (yaw −).
    Left,
    /// Orbit right (yaw +).
    Right,
    /// Orbit up (pitch +).
    Up,
    /// Orbit down (pitch −).
    Down,
    /// Move closer.
    ZoomIn,
    /// Move away.
    ZoomOut,
}

/// An orbit camera around `target`, with K (z) up. The eye sits at
/// `target + distance·(cos p cos y, cos p sin y, sin p)` for yaw y and pitch p.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OrbitCamera {
    /// Point looked at, metres.
    pub target: [f32; 3],
    /// Azimuth about K, radians.
    pub yaw: f32,
    /// Elevation, radians, kept within ±(π/2 − 0.01).
    pub pitch: f32,
    /// Eye–target distance, metres.
    pub distance: f32,
    /// Vertical field of view, radians.
    pub fov_y: f32,
}

/// Radians of orbit per pixel dragged.
pub const ORBIT_RAD_PER_PX: f32 = 0.008;
const PITCH_LIMIT: f32 = std::f32::consts::FRAC_PI_2 - 0.01;

impl OrbitCamera {
    /// A camera framing a wing of span `span` (metres) from above the trailing edge.
    pub fn for_span(span: f32) -> Self {
        let span = if span.is_finite() && span > 0.0 {
            span
        } else {
            0.05
        };
        OrbitCamera {
            target: [0.5 * span, -0.25 * span, 0.0],
            yaw: -1.95,
            pitch: 0.8,
            distance: 2.1 * span,
            fov_y: 45f32.to_radians(),
        }
    }

    /// Eye position, metres.
    pub fn eye(&self) -> [f32; 3] {
        let (sy, cy) = self.yaw.sin_cos();
        let (sp, cp) = self.pitch.sin_cos();
        let d = self.distance;
        [
            self.target[0] + d * cp * cy,
            self.target[1] + d * cp * sy,
            self.target[2] + d * sp,
        ]
    }

    /// Orbit by a mouse drag of (dx, dy) pixels. Non-finite input is ignored.
    pub fn drag(&mut self, dx: f32, dy: f32) {
        if !(dx.is_finite() && dy.is_finite()) {
            return;
        }
        self.yaw = (self.yaw - dx * ORBIT_RAD_PER_PX) % std::f32::consts::TAU;
        self.pitch = (self.pitch + dy * ORBIT_RAD_PER_PX).clamp(-PITCH_LIMIT, PITCH_LIMIT);
    }

    /// Multiply the distance by `factor` (> 1 moves away), kept within [0.01, 100] of the
    /// initial-scale distance limits. Non-finite or non-positive factors are ignored.
    pub fn zoom(&mut self, factor: f32) {
        if factor.is_finite() && factor > 0.0 {
            self.distance = (self.distance * factor).clamp(1e-3, 1e3);
        }
    }

    /// One keyboard step.
    pub fn key(&mut self, key: OrbitKey) {
        match key {
            OrbitKey::Left => self.drag(-12.0, 0.0),
            OrbitKey::Right => self.drag(12.0, 0.0),
            OrbitKey::Up => self.drag(0.0, 12.0),
            OrbitKey::Down => self.drag(0.0, -12.0),
            OrbitKey::ZoomIn => self.zoom(1.0 / 1.1),
            OrbitKey::ZoomOut => self.zoom(1.1),
        }
    }

    /// Sets target (m), yaw, pitch (rad; pitch kept within ±(π/2 − 0.01)) and distance (m).
    /// Returns false, changing nothing, when a value is not finite or the distance is not
    /// positive.
    pub fn set(&mut self, target: [f32; 3], yaw: f32, pitch: f32, distance: f32) -> bool {
        let finite = target.iter().all(|v| v.is_finite())
            && yaw.is_finite()
            && pitch.is_finite()
            && distance.is_finite();
        if !finite || distance <= 0.0 {
            return false;
        }
        self.target = target;
        self.yaw = yaw % std::f32::consts::TAU;
        self.pitch = pitch.clamp(-PITCH_LIMIT, PITCH_LIMIT);
        self.distance = distance;
        true
    }

    /// The camera's unit basis: right `s`, up `u` and forward `f` (eye towards target), the
    /// same as [`look_at`]'s with K up.
    fn basis(&self) -> ([f64; 3], [f64; 3], [f64; 3]) {
        let (sy, cy) = (self.yaw as f64).sin_cos();
        let (sp, cp) = (self.pitch as f64).sin_cos();
        let f = [-cp * cy, -cp * sy, -sp];
        // s = normalize(f × K); |f × K| = cos(pitch) > 0 within the pitch limit.
        let n = (f[1] * f[1] + f[0] * f[0]).sqrt().max(1e-12);
        let s = [f[1] / n, -f[0] / n, 0.0];
        let u = [
            s[1] * f[2] - s[2] * f[1],
            s[2] * f[0] - s[0] * f[2],
            s[0] * f[1] - s[1] * f[0],
        ];
        (s, u, f)
    }

    /// Aims the camera at `points` (fixed-frame metres) and sets its distance so that every
    /// point projects inside the normalised device square shrunk by `margin` on each side
    /// (|x|, |y| ≤ 1 − `margin`) of a viewport of `aspect` = width / height, with their
    /// projected bounding box centred. Yaw, pitch and field of view are kept: the view
    /// direction is the caller's, the framing is computed. Non-finite points are skipped;
    /// `margin` is clamped to [0, 0.45]. Returns false (camera unchanged) when no point is
    /// finite or `aspect` is not a positive number.
    ///
    /// The distance is exact for the target: a point at offset (x, y, z) along (right, up,
    /// forward) from the target projects to x·F/aspect/(d + z) with F = 1/tan(fov/2), so the
    /// smallest d that keeps it inside is max(F·|x|/(aspect·L), F·|y|/L) − z with L = 1 − margin.
    /// The target is then moved sideways by the box's off-centre amount and the distance
    /// refitted, a few times (perspective makes the centring converge, not jump, to the middle).
    pub fn fit_points(&mut self, points: &[[f32; 3]], aspect: f32, margin: f32) -> bool {
        if !(aspect.is_finite() && aspect > 0.0) {
            return false;
        }
        let pts: Vec<[f64; 3]> = points
            .iter()
            .filter(|p| p.iter().all(|v| v.is_finite()))
            .map(|p| [p[0] as f64, p[1] as f64, p[2] as f64])
            .collect();
        if pts.is_empty() {
            return false;
        }
        let margin = f64::from(if margin.is_finite() {
            margin.clamp(0.0, 0.45)
        } else {
            0.0
        });
        let lim = 1.0 - margin;
        let big_f = 1.0 / (0.5 * self.fov_y as f64).tan();
        let (kx, ky) = (big_f / aspect as f64, big_f);
        let (s, u, f) = self.basis();
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        // Start from the centre of the points' bounding box.
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for p in &pts {
            for ((l, h), v) in lo.iter_mut().zip(hi.iter_mut()).zip(p) {
                *l = l.min(*v);
                *h = h.max(*v);
            }
        }
        let mut t = [
            0.5 * (lo[0] + hi[0]),
            0.5 * (lo[1] + hi[1]),
            0.5 * (lo[2] + hi[2]),
        ];
        // Smallest distance for target t (points also kept in front of the near plane,
        // which sits at 0.02·d).
        let fit = |t: [f64; 3]| -> f64 {
            let mut d: f64 = 1e-3;
            for p in &pts {
                let v = [p[0] - t[0], p[1] - t[1], p[2] - t[2]];
                let (x, y, z) = (dot(v, s), dot(v, u), dot(v, f));
                d = d
                    .max(kx * x.abs() / lim - z)
                    .max(ky * y.abs() / lim - z)
                    .max(-z / 0.9);
            }
            d
        };
        let mut d = fit(t);
        for _ in 0..12 {
            // Projected box (normalised device coordinates) at this target and distance.
            let (mut x0, mut x1, mut y0, mut y1) = (
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::INFINITY,
                f64::NEG_INFINITY,
            );
            for p in &pts {
                let v = [p[0] - t[0], p[1] - t[1], p[2] - t[2]];
                let depth = d + dot(v, f);
                let (nx, ny) = (kx * dot(v, s) / depth, ky * dot(v, u) / depth);
                x0 = x0.min(nx);
                x1 = x1.max(nx);
                y0 = y0.min(ny);
                y1 = y1.max(ny);
            }
            let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
            if cx.abs() < 1e-4 && cy.abs() < 1e-4 {
                break;
            }
            // A sideways shift δ of the target moves a point at depth ≈ d by −k·δ/d on screen.
            let (dx, dy) = (cx * d / kx, cy * d / ky);
            for ((tk, sk), uk) in t.iter_mut().zip(s).zip(u) {
                *tk += dx * sk + dy * uk;
            }
            d = fit(t);
        }
        self.target = [t[0] as f32, t[1] as f32, t[2] as f32];
        // A hair more than exact, so f32 rounding never puts a point outside.
        self.distance = (d * (1.0 + 1e-5)) as f32;
        true
    }

    /// Projection × view for a viewport of the given aspect ratio (width / height).
    pub fn view_proj(&self, aspect: f32) -> Mat4 {
        let aspect = if aspect.is_finite() && aspect > 0.0 {
            aspect
        } else {
            1.0
        };
        let near = self.distance * 0.02;
        let far = self.distance * 20.0;
        let view = look_at(self.eye(), self.target, [0.0, 0.0, 1.0]);
        mat_mul(&perspective(self.fov_y, aspect, near, far), &view)
    }

    /// Pixel position (x right, y down, pixel centres at +0.5) of a fixed-frame point in a
    /// `width × height` image, or `None` behind the eye.
    pub fn project(&self, p: [f32; 3], width: u32, height: u32) -> Option<[f32; 2]> {
        let vp = self.view_proj(width as f32 / height.max(1) as f32);
        let c = transform(&vp, p);
        if c[3] <= 0.0 {
            return None;
        }
        let (nx, ny) = (c[0] / c[3], c[1] / c[3]);
        Some([
            (nx + 1.0) * 0.5 * width as f32,
            (1.0 - ny) * 0.5 * height as f32,
        ])
    }
}

/// Which quantity colours the wing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ColourMode {
    /// A plain membrane colour, no strain.
    #[default]
    Plain,
    /// ε_x, spanwise normal strain.
    StrainX,
    /// ε_y, chordwise normal strain.
    StrainY,
    /// γ_xy, engineering shear strain.
    ShearXY,
    /// √(ε_x² + ε_y² + γ_xy²/2), the Frobenius norm of the strain tensor (≥ 0).
    Magnitude,
    /// A scalar per node set by the page ([`super::Renderer::set_node_field`]), e.g. the RMS
    /// or the peak of a strain component over a whole run; it does not change with q.
    Field,
}

impl ColourMode {
    /// All modes, in index order.
    pub const ALL: [ColourMode; 6] = [
        ColourMode::Plain,
        ColourMode::StrainX,
        ColourMode::StrainY,
        ColourMode::ShearXY,
        ColourMode::Magnitude,
        ColourMode::Field,
    ];

    /// The index used by the shader and the JS API (0 plain, 1 ε_x, 2 ε_y, 3 γ_xy, 4 magnitude,
    /// 5 node field).
    pub fn index(self) -> u32 {
        match self {
            ColourMode::Plain => 0,
            ColourMode::StrainX => 1,
            ColourMode::StrainY => 2,
            ColourMode::ShearXY => 3,
            ColourMode::Magnitude => 4,
            ColourMode::Field => 5,
        }
    }

    /// From the index; unknown indices give `None`.
    pub fn from_index(i: u32) -> Option<Self> {
        Self::ALL.get(i as usize).copied()
    }

    /// From a name: `plain`, `ex`, `ey`, `gxy`, `mag` (and a few spelled-out aliases).
    pub fn from_name(s: &str) -> Option<Self> {
        match s.trim().to_ascii_lowercase().as_str() {
            "plain" | "none" => Some(ColourMode::Plain),
            "ex" | "eps_x" | "strain_x" => Some(ColourMode::StrainX),
            "ey" | "eps_y" | "strain_y" => Some(ColourMode::StrainY),
            "gxy" | "gamma_xy" | "shear" => Some(ColourMode::ShearXY),
            "mag" | "magnitude" => Some(ColourMode::Magnitude),
            "field" => Some(ColourMode::Field),
            _ => None,
        }
    }

    /// A label for the legend.
    pub fn label(self) -> &'static str {
        match self {
            ColourMode::Plain => "none",
            ColourMode::StrainX => "ε_x",
            ColourMode::StrainY => "ε_y",
            ColourMode::ShearXY => "γ_xy",
            ColourMode::Magnitude => "|ε|",
            ColourMode::Field => "field",
        }
    }

    /// The coloured value at one node from its strain `[ε_x, ε_y, γ_xy]` (0 for the plain
    /// colouring and for the node field, which does not come from the strain).
    pub fn value(self, e: [f32; 3]) -> f32 {
        match self {
            ColourMode::Plain | ColourMode::Field => 0.0,
            ColourMode::StrainX => e[0],
            ColourMode::StrainY => e[1],
            ColourMode::ShearXY => e[2],
            ColourMode::Magnitude => (e[0] * e[0] + e[1] * e[1] + 0.5 * e[2] * e[2]).sqrt(),
        }
    }
}

/// The diverging colour map (Moreland's cool–warm, sRGB), as `(t, rgb)` stops for t ∈ [0, 1].
/// Signed components map −M…0…+M onto 0…0.5…1; the magnitude maps 0…M onto 0.5…1.
/// The one definition of the map: the shaders get these stops as constants written by
/// [`super::gpu::colour_map_wgsl`] (they assume the stops at t = 0, ¼, ½, ¾, 1).
pub const DIVERGING_STOPS: [(f32, [f32; 3]); 5] = [
    (0.0, [0.230, 0.299, 0.754]),
    (0.25, [0.552, 0.690, 0.996]),
    (0.5, [0.865, 0.865, 0.865]),
    (0.75, [0.956, 0.604, 0.486]),
    (1.0, [0.706, 0.016, 0.150]),
];

/// The colour map at `t` (clamped to [0, 1]), sRGB; the shader's `diverging` evaluates the
/// same stops.
pub fn diverging(t: f32) -> [f32; 3] {
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.5
    };
    for w in DIVERGING_STOPS.windows(2) {
        let ((t0, c0), (t1, c1)) = (w[0], w[1]);
        if t <= t1 {
            let f = (t - t0) / (t1 - t0);
            return [0, 1, 2].map(|i| c0[i] + f * (c1[i] - c0[i]));
        }
    }
    DIVERGING_STOPS[4].1
}

/// What the page needs to draw a legend for the current colouring.
#[derive(Debug, Clone, PartialEq)]
pub struct Legend {
    /// The component shown (`ε_x`, `ε_y`, `γ_xy`, `|ε|`).
    pub component: &'static str,
    /// Value at the low end of the colour bar.
    pub min: f32,
    /// Value at the high end of the colour bar.
    pub max: f32,
    /// Always `"strain"` (dimensionless).
    pub units: &'static str,
    /// The extreme values actually present on the wing this frame.
    pub data_min: f32,
    /// See `data_min`.
    pub data_max: f32,
}

impl Legend {
    /// Colour-map stops for the bar from `min` to `max`: `(value, sRGB)` pairs.
    pub fn stops(&self) -> Vec<(f32, [f32; 3])> {
        let (t0, t1) = if self.min >= 0.0 {
            (0.5, 1.0)
        } else {
            (0.0, 1.0)
        };
        (0..=8)
            .map(|i| {
                let f = i as f32 / 8.0;
                (
                    self.min + f * (self.max - self.min),
                    diverging(t0 + f * (t1 - t0)),
                )
            })
            .collect()
    }
}

/// Everything that changes per frame. Angles in radians; `q` the modal coordinates (true
/// scale); the drawn deflection is `exaggeration · Σ φ_k q_k`, the strain colour always uses
/// the true q.
#[derive(Debug, Clone, PartialEq)]
pub struct FrameParams {
    /// Roll α, rad.
    pub alpha: f64,
    /// Pitch β, rad.
    pub beta: f64,
    /// Yaw γ, rad.
    pub gamma: f64,
    /// Modal coordinates q_k (only the first [`MAX_MODES`] are drawn).
    pub q: Vec<f64>,
    /// Deflection exaggeration (1 = true scale).
    pub exaggeration: f64,
    /// Colouring.
    pub colour: ColourMode,
    /// Fixed legend limit M (colours span ±M, or 0…M for the magnitude); `None`: this frame's
    /// largest |value|.
    pub strain_range: Option<f64>,
    /// Draw the fixed frame and the I″–J″–K″ triad.
    pub show_axes: bool,
    /// Draw the stroke plane (fill and outline).
    pub show_stroke_plane: bool,
    /// Draw the body axis.
    pub show_body_axis: bool,
}

impl Default for FrameParams {
    fn default() -> Self {
        FrameParams {
            alpha: 0.0,
            beta: 0.0,
            gamma: 0.0,
            q: Vec::new(),
            exaggeration: 1.0,
            colour: ColourMode::Plain,
            strain_range: None,
            show_axes: true,
            show_stroke_plane: true,
            show_body_axis: true,
        }
    }
}

/// A frame's values after sanitising: all finite, in `f32`, q padded to [`MAX_MODES`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CleanFrame {
    /// Roll α, rad.
    pub alpha: f32,
    /// Pitch β, rad.
    pub beta: f32,
    /// Yaw γ, rad.
    pub gamma: f32,
    /// True modal coordinates.
    pub q: [f32; MAX_MODES],
    /// Exaggeration.
    pub exaggeration: f32,
    /// Colouring.
    pub colour: ColourMode,
    /// Fixed legend limit, if any (finite, > 0).
    pub strain_range: Option<f32>,
    /// See [`FrameParams::show_axes`].
    pub show_axes: bool,
    /// See [`FrameParams::show_stroke_plane`].
    pub show_stroke_plane: bool,
    /// See [`FrameParams::show_body_axis`].
    pub show_body_axis: bool,
}

/// Largest |angle| (rad) and |q·exaggeration| passed on; beyond this f32 maths loses meaning.
pub const MAX_ABS_VALUE: f64 = 1.0e6;

fn clean(name: &str, v: f64, warnings: &mut Vec<String>) -> f32 {
    if !v.is_finite() {
        warnings.push(format!("{name} was {v}; drawn as 0"));
        0.0
    } else if v.abs() > MAX_ABS_VALUE {
        warnings.push(format!("{name} = {v} clamped to ±{MAX_ABS_VALUE}"));
        v.clamp(-MAX_ABS_VALUE, MAX_ABS_VALUE) as f32
    } else {
        v as f32
    }
}

impl FrameParams {
    /// The pose at time `t` (s) from compiled kinematics, with modal coordinates `q`; the other
    /// fields take their defaults. (Time control lives in the caller: it picks `t` and `q`.)
    pub fn at_time(kin: &crate::kinematics::Compiled, t: f64, q: Vec<f64>) -> Self {
        let s = kin.state(t);
        FrameParams {
            alpha: s.alpha,
            beta: s.beta,
            gamma: s.gamma,
            q,
            ..FrameParams::default()
        }
    }

    /// Replaces every non-finite value by 0 (and clamps absurd magnitudes), returning the clean
    /// frame and one warning per value changed. Modes beyond [`MAX_MODES`] are dropped with a
    /// warning. Nothing non-finite ever reaches the GPU.
    pub fn sanitise(&self) -> (CleanFrame, Vec<String>) {
        let mut w = Vec::new();
        let mut q = [0.0f32; MAX_MODES];
        for (k, v) in self.q.iter().enumerate() {
            if k < MAX_MODES {
                q[k] = clean(&format!("q[{k}]"), *v, &mut w);
            }
        }
        if self.q.len() > MAX_MODES {
            w.push(format!(
                "{} modal coordinates given; only the first {MAX_MODES} are drawn",
                self.q.len()
            ));
        }
        let strain_range = match self.strain_range {
            Some(r) if r.is_finite() && r > 0.0 => Some(r.min(MAX_ABS_VALUE) as f32),
            Some(r) => {
                w.push(format!("strain_range was {r}; using this frame's range"));
                None
            }
            None => None,
        };
        let clean_frame = CleanFrame {
            alpha: clean("alpha", self.alpha, &mut w),
            beta: clean("beta", self.beta, &mut w),
            gamma: clean("gamma", self.gamma, &mut w),
            q,
            exaggeration: clean("exaggeration", self.exaggeration, &mut w),
            colour: self.colour,
            strain_range,
            show_axes: self.show_axes,
            show_stroke_plane: self.show_stroke_plane,
            show_body_axis: self.show_body_axis,
        };
        (clean_frame, w)
    }
}

/// The automatic colour-scale limit: the 98th percentile of |value|. Strain is singular at
/// the corners of a clamped root, so the plain maximum would leave the rest of the wing in the
/// middle colour; values beyond the limit saturate, and the legend still reports the true
/// extremes (`data_min`, `data_max`). Non-finite values are ignored; 0 if nothing is left.
pub fn robust_range(values: impl Iterator<Item = f32>) -> f32 {
    let mut a: Vec<f32> = values.filter(|v| v.is_finite()).map(f32::abs).collect();
    if a.is_empty() {
        return 0.0;
    }
    let k = ((a.len() - 1) as f64 * 0.98).round() as usize;
    let (_, v, _) = a.select_nth_unstable_by(k, f32::total_cmp);
    *v
}

/// The legend of a node field ([`ColourMode::Field`]): colours span 0…M when no value is
/// negative (the upper half of the map, as for the magnitude), else −M…M; M is `fixed_range`
/// or [`robust_range`] of the values (at least 1e-12). Non-finite values are ignored.
pub fn legend_for_field(values: &[f32], fixed_range: Option<f32>) -> Legend {
    legend_of(
        ColourMode::Field.label(),
        values.iter().copied(),
        fixed_range,
        |lo| lo >= 0.0,
    )
}

/// The legend for `mode` given the nodal strain field; `None` for [`ColourMode::Plain`].
/// With no fixed range the limit is [`robust_range`] of the field (at least 1e-12); colours
/// span 0…M for the magnitude, −M…M for a component.
pub fn legend_for(
    mode: ColourMode,
    field: &[[f32; 3]],
    fixed_range: Option<f32>,
) -> Option<Legend> {
    if mode == ColourMode::Plain {
        return None;
    }
    Some(legend_of(
        mode.label(),
        field.iter().map(|e| mode.value(*e)),
        fixed_range,
        |_| mode == ColourMode::Magnitude,
    ))
}

/// The one legend builder behind [`legend_for`] and [`legend_for_field`]: the finite
/// extremes of `values` (0 and 0 when there are none) and the limit M = `fixed_range` or
/// [`robust_range`] of the values, at least 1e-12; colours span 0…M when
/// `one_sided(data_min)`, else −M…M.
fn legend_of(
    component: &'static str,
    values: impl Iterator<Item = f32> + Clone,
    fixed_range: Option<f32>,
    one_sided: impl FnOnce(f32) -> bool,
) -> Legend {
    let mut lo = f32::INFINITY;
    let mut hi = f32::NEG_INFINITY;
    for v in values.clone().filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() {
        lo = 0.0;
        hi = 0.0;
    }
    let m = fixed_range
        .unwrap_or_else(|| robust_range(values))
        .max(1e-12);
    Legend {
        component,
        min: if one_sided(lo) { 0.0 } else { -m },
        max: m,
        units: "strain",
        data_min: lo,
        data_max: hi,
    }
}
