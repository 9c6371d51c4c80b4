//! Quality triangulation of the planform (spade's constrained Delaunay refinement) and the
//! cambered node positions.

use super::geometry::{camber_height, check_meshable, point_segment_distance, signed_area};
use crate::error::{Result, WingbeatError};
use spade::handles::{FixedFaceHandle, InnerTag};
use spade::{
    AngleLimit, ConstrainedDelaunayTriangulation, Point2, RefinementParameters, Triangulation,
};

/// Documented cap on the node count of one mesh (memory and time stay bounded).
pub const MAX_NODES: usize = 20_000;

/// A triangle mesh of the wing surface.
#[derive(Debug, Clone)]
pub struct Mesh {
    /// Node positions in metres: planform (x, y) and camber height z.
    pub nodes: Vec<[f64; 3]>,
    /// Triangles as node-index triples, counter-clockwise seen from +z.
    pub triangles: Vec<[usize; 3]>,
}

/// Estimated node count for an outline of area `area_mm2`, perimeter `perim_mm`, target
/// element edge `h_mm` (equilateral triangles: about 2A/(√3 h²) nodes plus the boundary).
pub fn estimate_nodes(area_mm2: f64, perim_mm: f64, h_mm: f64) -> f64 {
    2.0 * area_mm2 / (3f64.sqrt() * h_mm * h_mm) + perim_mm / h_mm
}

/// Options of [`mesh_planform_with`].
#[derive(Debug, Clone, PartialEq)]
pub struct MeshOptions {
    /// Largest node count accepted (at most [`MAX_NODES`]); exceeding it is a
    /// `ResourceCap` error on `mesh_size_mm` that names a size that would fit.
    pub max_nodes: usize,
    /// Spanwise stations x (mm) that get a mesh line across the planform (a constraint
    /// segment wherever the line x = X lies inside the outline), e.g. the edge of a clamped
    /// basal strip, so that nodes lie exactly on it.
    pub lines_x_mm: Vec<f64>,
}

impl Default for MeshOptions {
    fn default() -> Self {
        MeshOptions {
            max_nodes: MAX_NODES,
            lines_x_mm: Vec::new(),
        }
    }
}

/// Meshes a validated counter-clockwise outline (mm) with target edge length `h_mm`, and
/// lifts the nodes onto the camber surface ([`camber_height`]). Output in metres.
pub fn mesh_planform(outline: &[[f64; 2]], h_mm: f64, camber: f64) -> Result<Mesh> {
    mesh_planform_with(outline, h_mm, camber, &MeshOptions::default())
}

/// A mesh size (mm) that should keep an outline of this area and perimeter under `cap`
/// nodes, from `h_mm` that gave `nodes`: node counts scale like 1/h², so scale by
/// √(nodes/cap) with a 10 % margin, rounded up to two significant digits.
pub fn size_that_fits(h_mm: f64, nodes: f64, cap: usize) -> f64 {
    let h = h_mm * (nodes / cap as f64).sqrt() * 1.1;
    round_up_2sig(h.max(h_mm * 1.1))
}

fn round_up_2sig(h: f64) -> f64 {
    if !(h.is_finite() && h > 0.0) {
        return h;
    }
    let k = 1 - h.log10().floor() as i32;
    if k >= 0 {
        let s = 10f64.powi(k);
        (h * s).ceil() / s
    } else {
        let s = 10f64.powi(-k);
        (h / s).ceil() * s
    }
}

/// The reason given with a node-cap error, naming a mesh size `fit_mm` that would fit.
pub fn cap_why(fit_mm: f64) -> String {
    format!(
        "memory and solve time grow quickly with the node count; a mesh size of about {fit_mm} mm \
         would fit"
    )
}

/// The node-cap error: `how` qualifies the count ("about", "more than" or "").
fn cap_error(h_mm: f64, nodes: f64, cap: usize, how: &str) -> WingbeatError {
    let fit = size_that_fits(h_mm, nodes, cap);
    let how = if how.is_empty() {
        String::new()
    } else {
        format!("{how} ")
    };
    WingbeatError::ResourceCap {
        field: "mesh_size_mm".into(),
        requested: format!("{h_mm} mm ({how}{nodes:.0} nodes)"),
        cap: format!("{cap} nodes"),
        why: cap_why(fit),
    }
}

/// Points where the vertical line x = `x` meets the interior of outline edges (not at their
/// end points), per edge index, as the edge parameter s ∈ (0, 1).
fn line_crossings(outline: &[[f64; 2]], x: f64) -> Vec<(usize, f64)> {
    let n = outline.len();
    let mut out = Vec::new();
    for i in 0..n {
        let (a, b) = (outline[i], outline[(i + 1) % n]);
        if (a[0] < x && b[0] > x) || (a[0] > x && b[0] < x) {
            let s = (x - a[0]) / (b[0] - a[0]);
            if s > 0.0 && s < 1.0 {
                out.push((i, s));
            }
        }
    }
    out
}

/// True if `p` is strictly inside the polygon (even–odd rule) and farther than `tol` from
/// every edge.
fn strictly_inside(poly: &[[f64; 2]], p: [f64; 2], tol: f64) -> bool {
    let n = poly.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        if point_segment_distance(p, a, b) <= tol {
            return false;
        }
        if (a[1] > p[1]) != (b[1] > p[1]) {
            let xc = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if p[0] < xc {
                inside = !inside;
            }
        }
    }
    inside
}

/// The pieces (y_low, y_high), mm, of the vertical line x = `x` that lie inside the outline
/// (any orientation, not necessarily validated), bottom to top.
pub fn inside_intervals(outline: &[[f64; 2]], x: f64) -> Vec<(f64, f64)> {
    let (poly, segs) = outline_with_lines(outline, &[x]);
    let mut v: Vec<(f64, f64)> = segs
        .iter()
        .map(|&[i, j]| (poly[i][1], poly[j][1]))
        .collect();
    v.sort_by(|a, b| a.0.total_cmp(&b.0));
    v
}

/// Inserts the crossings of the lines x = X into the outline as vertices (exactly on x = X)
/// and returns the augmented outline with, per line, the pairs of outline-vertex indices
/// whose connecting vertical segment lies inside the planform.
fn outline_with_lines(outline: &[[f64; 2]], lines: &[f64]) -> (Vec<[f64; 2]>, Vec<[usize; 2]>) {
    let n = outline.len();
    let mut extra: Vec<Vec<(f64, [f64; 2])>> = vec![Vec::new(); n];
    for &x in lines {
        for (i, s) in line_crossings(outline, x) {
            let (a, b) = (outline[i], outline[(i + 1) % n]);
            extra[i].push((s, [x, a[1] + s * (b[1] - a[1])]));
        }
    }
    let mut poly = Vec::with_capacity(n + 4 * lines.len());
    for i in 0..n {
        poly.push(outline[i]);
        let mut e = extra[i].clone();
        e.sort_by(|p, q| p.0.total_cmp(&q.0));
        poly.extend(e.into_iter().map(|(_, p)| p));
    }
    let span = outline
        .iter()
        .map(|p| p[0].abs().max(p[1].abs()))
        .fold(0.0, f64::max);
    let tol = 1e-9 * span.max(1e-300);
    let mut segs = Vec::new();
    for &x in lines {
        let mut on: Vec<usize> = (0..poly.len()).filter(|&i| poly[i][0] == x).collect();
        on.sort_by(|&i, &j| poly[i][1].total_cmp(&poly[j][1]));
        for w in on.windows(2) {
            let (y0, y1) = (poly[w[0]][1], poly[w[1]][1]);
            if y1 - y0 > tol && strictly_inside(&poly, [x, 0.5 * (y0 + y1)], tol) {
                segs.push([w[0], w[1]]);
            }
        }
    }
    (poly, segs)
}

/// [`mesh_planform`] with a node cap and interior mesh lines ([`MeshOptions`]). The node
/// count is estimated before meshing and counted after it; both are checked against
/// `opts.max_nodes`.
pub fn mesh_planform_with(
    outline: &[[f64; 2]],
    h_mm: f64,
    camber: f64,
    opts: &MeshOptions,
) -> Result<Mesh> {
    let cap = opts.max_nodes.min(MAX_NODES);
    check_mesh_inputs(h_mm, camber, opts)?;
    let n = outline.len();
    let perim: f64 = (0..n)
        .map(|i| {
            let (a, b) = (outline[i], outline[(i + 1) % n]);
            ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt()
        })
        .sum();
    let area = signed_area(outline).abs();
    let est = estimate_nodes(area, perim, h_mm);
    if est.is_nan() || est > cap as f64 {
        return Err(cap_error(h_mm, est, cap, "about"));
    }
    let size = SizeField {
        h_mm,
        root: root_segment_length(outline),
    };
    let (poly, lines) = outline_with_lines(outline, &opts.lines_x_mm);
    check_polygon(outline, &poly)?;
    let (mut verts, edges) = boundary_vertices(&poly, &size);
    let line_pts = line_stations(&poly, &lines, &size, &mut verts);
    let (cdt, excluded) = triangulate(verts, edges, &line_pts, h_mm, cap, outline, &poly)?;
    let (nodes, mut triangles) = lifted_mesh(&cdt, &excluded, outline, camber);
    if nodes.len() > cap {
        return Err(cap_error(h_mm, nodes.len() as f64, cap, ""));
    }
    if triangles.is_empty() {
        return Err(WingbeatError::Geometry(
            "the outline produced no triangles".into(),
        ));
    }
    // make every triangle counter-clockwise in the x–y plane
    for t in &mut triangles {
        let (a, b, c) = (nodes[t[0]], nodes[t[1]], nodes[t[2]]);
        let o = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        if o < 0.0 {
            t.swap(1, 2);
        }
    }
    Ok(Mesh { nodes, triangles })
}

/// The element size, the camber and the mesh lines' stations must be finite (the size
/// also > 0); each error names its field.
fn check_mesh_inputs(h_mm: f64, camber: f64, opts: &MeshOptions) -> Result<()> {
    if !(h_mm.is_finite() && h_mm > 0.0) {
        return Err(WingbeatError::invalid(
            "mesh_size_mm",
            h_mm,
            "a finite element size > 0 mm",
        ));
    }
    if !camber.is_finite() {
        return Err(WingbeatError::invalid("camber", camber, "a finite number"));
    }
    if let Some(x) = opts.lines_x_mm.iter().find(|x| !x.is_finite()) {
        return Err(WingbeatError::invalid(
            "mesh line x (mm)",
            x,
            "a finite station",
        ));
    }
    Ok(())
}

/// The target element size over the planform: `h_mm`, graded finer toward the root when
/// the outline has one (the clamp corners carry the stress concentration); the quality
/// refinement then grades the interior from the boundary sizes.
struct SizeField {
    h_mm: f64,
    /// [`root_segment_length`] of the outline.
    root: Option<f64>,
}

impl SizeField {
    fn at(&self, p: [f64; 2]) -> f64 {
        match self.root {
            Some(c0) => self
                .h_mm
                .min((self.h_mm / 4.0).max(0.1 * c0 + 0.3 * p[0].abs())),
            None => self.h_mm,
        }
    }

    /// Stations along a segment a → b at the local size (end points excluded), evened out.
    fn stations(&self, a: [f64; 2], b: [f64; 2]) -> Vec<[f64; 2]> {
        let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
        let mut s = 0.0;
        let mut st = vec![0.0];
        while s < len {
            let p = [
                a[0] + s / len * (b[0] - a[0]),
                a[1] + s / len * (b[1] - a[1]),
            ];
            s += self.at(p);
            st.push(s);
            if st.len() > 4 * MAX_NODES {
                break;
            }
        }
        let k = (st.len() - 1).max(1);
        let scale = len / st[k].max(1e-300);
        st.iter()
            .take(k)
            .skip(1)
            .map(|v| {
                let f = v * scale / len;
                [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])]
            })
            .collect()
    }
}

/// Second line of defence (callers validate the outline first): nothing that floating point
/// cannot triangulate reaches spade, including a mesh line's crossing that falls on top of an
/// outline point. Points of `poly` are named by their index in `outline`, or as a crossing.
fn check_polygon(outline: &[[f64; 2]], poly: &[[f64; 2]]) -> Result<()> {
    let names: std::collections::HashMap<(u64, u64), usize> = outline
        .iter()
        .enumerate()
        .map(|(i, p)| ((p[0].to_bits(), p[1].to_bits()), i))
        .collect();
    check_meshable(
        poly,
        &|i| {
            let p = poly[i];
            names.get(&(p[0].to_bits(), p[1].to_bits())).map_or_else(
                || format!("the crossing {p:?} of the mesh line x = {} mm", p[0]),
                |k| format!("planform[{k}]"),
            )
        },
        "planform",
    )
}

/// The outline's points and the stations that split its edges at the local size, in order,
/// and the closed chain of boundary edges through them.
fn boundary_vertices(poly: &[[f64; 2]], size: &SizeField) -> (Vec<Point2<f64>>, Vec<[usize; 2]>) {
    let np = poly.len();
    let mut verts: Vec<Point2<f64>> = Vec::new();
    for i in 0..np {
        let (a, b) = (poly[i], poly[(i + 1) % np]);
        verts.push(Point2::new(a[0], a[1]));
        for p in size.stations(a, b) {
            verts.push(Point2::new(p[0], p[1]));
        }
    }
    let m = verts.len();
    let edges = (0..m).map(|i| [i, (i + 1) % m]).collect();
    (verts, edges)
}

/// The stations of each mesh line (`lines`: pairs of indices into `poly`), end points
/// included; the interior ones are also appended to `verts`.
///
/// They go in as plain vertices now and become constraint edges after the refinement
/// (spade finds the outer faces by counting constraint crossings from the convex hull, which
/// an interior line would confuse: it separates two inner regions). Station sizes grow from
/// each end of a line from the outline segments met there (an outline point may lie close to
/// the crossing) by at most 1.5× per station.
fn line_stations(
    poly: &[[f64; 2]],
    lines: &[[usize; 2]],
    size: &SizeField,
    verts: &mut Vec<Point2<f64>>,
) -> Vec<Vec<[f64; 2]>> {
    let np = poly.len();
    let seg = |i: usize, k: usize| -> f64 {
        let (a, b) = (poly[i], poly[k]);
        ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt()
    };
    let mut line_pts: Vec<Vec<[f64; 2]>> = Vec::new();
    for &[i, j] in lines {
        let (a, b) = (poly[i], poly[j]);
        let end_size = |k: usize| {
            seg(k, (k + np - 1) % np)
                .min(seg(k, (k + 1) % np))
                .min(size.at(poly[k]))
        };
        let (ea, eb) = (end_size(i), end_size(j));
        let len = (b[1] - a[1]).abs();
        let at = |s: f64| [a[0], a[1] + (b[1] - a[1]) * s / len];
        let mut st = vec![0.0];
        let mut s = 0.0;
        while s < len && st.len() < 4 * MAX_NODES {
            s += size
                .at(at(s))
                .min(ea + 0.5 * s)
                .min(eb + 0.5 * (len - s).max(0.0));
            st.push(s);
        }
        let k = (st.len() - 1).max(1);
        let scale = len / st[k];
        let mut pts = vec![a];
        for v in st.iter().take(k).skip(1) {
            let p = at(v * scale);
            verts.push(Point2::new(p[0], p[1]));
            pts.push(p);
        }
        pts.push(b);
        line_pts.push(pts);
    }
    line_pts
}

type Cdt = ConstrainedDelaunayTriangulation<Point2<f64>>;
type FaceSet = std::collections::HashSet<FixedFaceHandle<InnerTag>>;

/// The constrained Delaunay triangulation of the boundary, refined to equilateral-size
/// triangles of edge `h_mm` with angles ≥ 28° and at most `cap` added vertices, with the mesh
/// lines then forced in ([`insert_lines`]); and the set of its faces outside the planform.
fn triangulate(
    verts: Vec<Point2<f64>>,
    edges: Vec<[usize; 2]>,
    line_pts: &[Vec<[f64; 2]>],
    h_mm: f64,
    cap: usize,
    outline: &[[f64; 2]],
    poly: &[[f64; 2]],
) -> Result<(Cdt, FaceSet)> {
    let mut conflicts = 0usize;
    let mut cdt = Cdt::try_bulk_load_cdt(verts, edges, |_| {
        conflicts += 1;
    })
    .map_err(|e| WingbeatError::Geometry(format!("triangulation failed: {e:?}")))?;
    if conflicts > 0 {
        return Err(WingbeatError::Geometry(format!(
            "triangulation failed: {conflicts} outline segment(s) at the mesh size {h_mm} mm overlap \
             or cross another (the outline nearly touches itself)"
        )));
    }
    let max_area = 3f64.sqrt() / 4.0 * h_mm * h_mm;
    let result = cdt.refine(
        RefinementParameters::new()
            .with_max_allowed_area(max_area)
            .with_angle_limit(AngleLimit::from_deg(28.0))
            .with_max_additional_vertices(cap)
            .exclude_outer_faces(true),
    );
    if !result.refinement_complete {
        return Err(cap_error(h_mm, cdt.num_vertices() as f64, cap, "more than"));
    }
    if line_pts.is_empty() {
        let excluded = result.excluded_faces.iter().copied().collect();
        return Ok((cdt, excluded));
    }
    insert_lines(&mut cdt, line_pts)?;
    // with lines the face handles changed: tell inside from outside by the centroid
    // (faces of three collinear outline points, which spade may leave outside, have their
    // centroid on the outline and are dropped too)
    let span = outline
        .iter()
        .map(|p| p[0].abs().max(p[1].abs()))
        .fold(0.0, f64::max);
    let excluded = cdt
        .inner_faces()
        .filter(|f| {
            let c = f.center();
            !strictly_inside(poly, [c.x, c.y], 1e-9 * span)
        })
        .map(|f| f.fix())
        .collect();
    Ok((cdt, excluded))
}

/// The nodes (metres, lifted onto the camber surface) and triangles of the faces of `cdt`
/// not in `excluded`, nodes numbered in the order the faces first use them.
fn lifted_mesh(
    cdt: &Cdt,
    excluded: &FaceSet,
    outline: &[[f64; 2]],
    camber: f64,
) -> (Vec<[f64; 3]>, Vec<[usize; 3]>) {
    let mut used = vec![usize::MAX; cdt.num_vertices()];
    let mut nodes: Vec<[f64; 3]> = Vec::new();
    let mut triangles = Vec::new();
    for face in cdt.inner_faces() {
        if excluded.contains(&face.fix()) {
            continue;
        }
        let vs = face.vertices();
        let mut tri = [0usize; 3];
        for (k, v) in vs.iter().enumerate() {
            let idx = v.fix().index();
            if used[idx] == usize::MAX {
                used[idx] = nodes.len();
                let p = v.position();
                let z = camber_height(outline, camber, p.x, p.y);
                nodes.push([p.x * 1e-3, p.y * 1e-3, z * 1e-3]);
            }
            tri[k] = used[idx];
        }
        triangles.push(tri);
    }
    (nodes, triangles)
}

/// Makes each mesh line (its stations, in order) a chain of constraint edges of the refined
/// triangulation. Refinement vertices closer to a line than 0.3 × the local station spacing are removed
/// first (unless they lie on a constraint edge), so that forcing the line in leaves no
/// slivers; the Delaunay fill of the small gap they leave is well shaped.
fn insert_lines(cdt: &mut Cdt, lines: &[Vec<[f64; 2]>]) -> Result<()> {
    let on_line: std::collections::HashSet<(u64, u64)> = lines
        .iter()
        .flatten()
        .map(|p| (p[0].to_bits(), p[1].to_bits()))
        .collect();
    let near: Vec<Point2<f64>> = cdt
        .vertices()
        .filter(|v| {
            let p = v.position();
            if on_line.contains(&(p.x.to_bits(), p.y.to_bits()))
                || v.out_edges()
                    .any(|e| cdt.is_constraint_edge(e.as_undirected().fix()))
            {
                return false;
            }
            lines.iter().any(|l| {
                // the stations bracketing p.y and their spacing
                let k = l.windows(2).position(|w| {
                    let (lo, hi) = (w[0][1].min(w[1][1]), w[0][1].max(w[1][1]));
                    p.y > lo && p.y <= hi
                });
                k.is_some_and(|k| (p.x - l[0][0]).abs() < 0.5 * (l[k + 1][1] - l[k][1]).abs())
            })
        })
        .map(|v| v.position())
        .collect();
    for p in near {
        if let Some(v) = cdt.locate_vertex(p).map(|v| v.fix()) {
            cdt.remove(v);
        }
    }
    let handle = |cdt: &ConstrainedDelaunayTriangulation<Point2<f64>>, p: [f64; 2]| {
        cdt.locate_vertex(Point2::new(p[0], p[1]))
            .map(|v| v.fix())
            .ok_or_else(|| WingbeatError::Geometry(format!("mesh line vertex {p:?} was lost")))
    };
    for l in lines {
        for w in l.windows(2) {
            let (a, b) = (handle(cdt, w[0])?, handle(cdt, w[1])?);
            if !cdt.can_add_constraint(a, b) {
                return Err(WingbeatError::Geometry(format!(
                    "mesh line {:?}–{:?} crosses the outline",
                    w[0], w[1]
                )));
            }
            cdt.add_constraint(a, b);
        }
    }
    Ok(())
}

/// Total length (mm) of the outline edges lying on x = 0 (the root), if any.
pub fn root_segment_length(outline: &[[f64; 2]]) -> Option<f64> {
    let n = outline.len();
    let span = outline
        .iter()
        .map(|p| p[0].abs().max(p[1].abs()))
        .fold(0.0, f64::max);
    let tol = 1e-9 * span;
    let len: f64 = (0..n)
        .map(|i| {
            let (a, b) = (outline[i], outline[(i + 1) % n]);
            if a[0].abs() <= tol && b[0].abs() <= tol {
                (b[1] - a[1]).abs()
            } else {
                0.0
            }
        })
        .sum();
    (len > 0.0).then_some(len)
}

/// A structured mesh of a rectangle `[0, lx] × [−ly, 0]` (metres), `nx` × `ny` cells, each
/// split into two triangles along alternating diagonals (used by verification tests).
pub fn structured_rectangle(lx: f64, ly: f64, nx: usize, ny: usize) -> Mesh {
    let mut nodes = Vec::with_capacity((nx + 1) * (ny + 1));
    for j in 0..=ny {
        for i in 0..=nx {
            nodes.push([
                lx * i as f64 / nx as f64,
                -ly + ly * j as f64 / ny as f64,
                0.0,
            ]);
        }
    }
    let id = |i: usize, j: usize| j * (nx + 1) + i;
    let mut triangles = Vec::with_capacity(2 * nx * ny);
    for j in 0..ny {
        for i in 0..nx {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            if (i + j) % 2 == 0 {
                triangles.push([a, b, c]);
                triangles.push([a, c, d]);
            } else {
                triangles.push([a, b, d]);
                triangles.push([b, c, d]);
            }
        }
    }
    Mesh { nodes, triangles }
}
