//! Points on a triangle mesh: which triangle holds (x, y), with what barycentric weights, and
//! the linear interpolation of nodal values there. Used by [`super::FemModes::strain_at`] and by
//! [`crate::analysis::strain::modal_strains_at`] (strain at a clicked point, the strain maps).

/// Locates (x, y) in mm on a triangle mesh whose node coordinates are in m: the triangle,
/// its barycentric weights and whether the point is inside (within 1e-9 in the weights).
/// A point outside maps to the nearest triangle (in the weights' sense) with clamped,
/// renormalised weights. `None` for a mesh without a non-degenerate triangle.
pub fn locate_in_mesh(
    nodes: &[[f64; 3]],
    triangles: &[[usize; 3]],
    x_mm: f64,
    y_mm: f64,
) -> Option<(usize, [f64; 3], bool)> {
    let (x, y) = (x_mm * 1e-3, y_mm * 1e-3);
    let mut best: Option<(usize, [f64; 3], f64)> = None;
    for (ti, t) in triangles.iter().enumerate() {
        let (a, b, c) = (nodes[t[0]], nodes[t[1]], nodes[t[2]]);
        let det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
        if det == 0.0 {
            continue;
        }
        let l1 = ((b[0] - x) * (c[1] - y) - (c[0] - x) * (b[1] - y)) / det;
        let l2 = ((c[0] - x) * (a[1] - y) - (a[0] - x) * (c[1] - y)) / det;
        let l3 = 1.0 - l1 - l2;
        let out = (-l1).max(-l2).max(-l3).max(0.0);
        if best.is_none_or(|bst| out < bst.2) {
            best = Some((ti, [l1, l2, l3], out));
        }
        if out == 0.0 {
            break;
        }
    }
    best.map(|(ti, l, out)| {
        let mut lc = l.map(|v| v.max(0.0));
        let s: f64 = lc.iter().sum();
        lc.iter_mut().for_each(|v| *v /= s);
        (ti, lc, out <= 1e-9)
    })
}

/// The linear interpolation of nodal strains `strain(mode, node)` in triangle `t` with
/// barycentric weights `l`.
pub fn interpolate_strain(
    t: [usize; 3],
    l: [f64; 3],
    mode: usize,
    strain: impl Fn(usize, usize) -> [f64; 3],
) -> [f64; 3] {
    let mut e = [0.0; 3];
    for c in 0..3 {
        let s = strain(mode, t[c]);
        for (k, ek) in e.iter_mut().enumerate() {
            *ek += l[c] * s[k];
        }
    }
    e
}
