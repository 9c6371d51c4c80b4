//! Quality triangulation of the planform (spade's constrained Delaunay refinement) and the
//! cambered node positions.

use super::geometry::{camber_height, signed_area};
use crate::error::{Result, WingbeatError};
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

/// Meshes a validated counter-clockwise outline (mm) with target edge length `h_mm`, and
/// lifts the nodes onto the camber surface ([`camber_height`]). Output in metres.
pub fn mesh_planform(outline: &[[f64; 2]], h_mm: f64, camber: f64) -> Result<Mesh> {
    let n = outline.len();
    let perim: f64 = (0..n)
        .map(|i| {
            let (a, b) = (outline[i], outline[(i + 1) % n]);
            ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt()
        })
        .sum();
    let area = signed_area(outline).abs();
    let est = estimate_nodes(area, perim, h_mm);
    if est.is_nan() || est > MAX_NODES as f64 {
        return Err(WingbeatError::ResourceCap {
            field: "mesh_size_mm".into(),
            requested: format!("{h_mm} mm (about {est:.0} nodes)"),
            cap: format!("{MAX_NODES} nodes"),
            why: "memory and solve time grow quickly with the node count".into(),
        });
    }
    // Split the outline edges so that the boundary is resolved at the target size, graded
    // finer toward the root (the clamp corners carry the stress concentration); the
    // quality refinement then grades the interior from these boundary sizes.
    let root = root_segment_length(outline);
    let local_h = |p: [f64; 2]| -> f64 {
        match root {
            Some(c0) => h_mm.min((h_mm / 4.0).max(0.1 * c0 + 0.3 * p[0].abs())),
            None => h_mm,
        }
    };
    let mut verts: Vec<Point2<f64>> = Vec::new();
    for i in 0..n {
        let (a, b) = (outline[i], outline[(i + 1) % n]);
        let mut s = 0.0;
        verts.push(Point2::new(a[0], a[1]));
        let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
        // march along the edge with the local size, then even out the last step
        let mut stations = vec![0.0];
        while s < len {
            let p = [
                a[0] + s / len * (b[0] - a[0]),
                a[1] + s / len * (b[1] - a[1]),
            ];
            s += local_h(p);
            stations.push(s);
            if stations.len() > 4 * MAX_NODES {
                break;
            }
        }
        let k = (stations.len() - 1).max(1);
        let scale = len / stations[k].max(1e-300);
        for st in stations.iter().take(k).skip(1) {
            let f = st * scale / len;
            verts.push(Point2::new(
                a[0] + f * (b[0] - a[0]),
                a[1] + f * (b[1] - a[1]),
            ));
        }
    }
    let m = verts.len();
    let edges: Vec<[usize; 2]> = (0..m).map(|i| [i, (i + 1) % m]).collect();
    let mut cdt = ConstrainedDelaunayTriangulation::<Point2<f64>>::bulk_load_cdt(verts, edges)
        .map_err(|e| WingbeatError::Geometry(format!("triangulation failed: {e:?}")))?;
    let max_area = 3f64.sqrt() / 4.0 * h_mm * h_mm;
    let result = cdt.refine(
        RefinementParameters::new()
            .with_max_allowed_area(max_area)
            .with_angle_limit(AngleLimit::from_deg(28.0))
            .with_max_additional_vertices(MAX_NODES)
            .exclude_outer_faces(true),
    );
    if !result.refinement_complete {
        return Err(WingbeatError::ResourceCap {
            field: "mesh_size_mm".into(),
            requested: format!("{h_mm} mm"),
            cap: format!("{MAX_NODES} nodes"),
            why: "mesh refinement stopped at the vertex cap".into(),
        });
    }
    let excluded: std::collections::HashSet<_> = result.excluded_faces.iter().copied().collect();
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
    if nodes.len() > MAX_NODES {
        return Err(WingbeatError::ResourceCap {
            field: "mesh_size_mm".into(),
            requested: format!("{h_mm} mm ({} nodes)", nodes.len()),
            cap: format!("{MAX_NODES} nodes"),
            why: "memory and solve time grow quickly with the node count".into(),
        });
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
