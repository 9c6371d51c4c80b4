//! Planform input, validation and the camber surface.
//!
//! Units in this module are millimetres (the outline as the user gives it). The frame is the
//! paper's wing frame seen from above: x spanwise from the root, y chordwise (the chord runs
//! toward −y), origin at the root point (0, 0).

use crate::error::{Result, WingbeatError};

/// The built-in default outline: a SYNTHETIC Manduca-like forewing (mm), not digitised from a
/// specimen. Copied from the project's shared data with its provenance header.
pub const MANDUCA_CSV: &str = include_str!("../../data/planform_manduca.csv");

/// Provenance note shown wherever the default outline is used.
pub const MANDUCA_NOTE: &str =
    "synthetic Manduca-like forewing outline (span 49 mm, area 8.70 cm^2); \
plausible, NOT digitised from a specimen";

/// Largest number of outline points accepted (the self-intersection check is O(n²)).
pub const MAX_OUTLINE_POINTS: usize = 5000;

/// Largest coordinate magnitude accepted, mm (1 km: anything bigger is a unit error).
pub const MAX_COORD_MM: f64 = 1.0e6;

/// Smallest span (x extent) and chord (y extent) of an outline, mm: 10 µm, well below the
/// smallest insect wings (about 0.2 mm). Smaller outlines are refused by
/// [`validate_outline`] with a message naming the extent (a 1e-9 mm square used to fail
/// later with a puzzling clamp error).
pub const MIN_EXTENT_MM: f64 = 0.01;

/// Smallest area of an outline relative to its bounding box (span × chord): a sliver
/// thinner than this is refused by [`validate_outline`] as degenerate.
pub const MIN_AREA_FRACTION: f64 = 1e-4;

/// Smallest distance between two outline points, and between a point and an edge it is not
/// an end of, relative to the outline's size (the larger of span and chord): 1e-6 (49 nm on
/// the default 49 mm wing). Nearer points are not distinct to the triangulation's floating
/// point (an outline with two points 1e-300 mm apart made the mesher index out of bounds).
pub const MIN_SEPARATION_FRACTION: f64 = 1e-6;

/// Smallest angle between the two edges at an outline point, degrees: a sharper spike is a
/// zero-area sliver to the quality mesher (it refines toward it without end).
pub const MIN_VERTEX_ANGLE_DEG: f64 = 0.5;

fn parse_err(what: &str, msg: impl Into<String>) -> WingbeatError {
    WingbeatError::Parse {
        what: what.to_string(),
        message: msg.into(),
    }
}

/// Parses a planform outline from CSV text (mm).
///
/// Accepted: a header line `x_mm,y_mm` or `i,x_mm,y_mm` (optional), lines starting with `#`
/// are comments, blank lines are skipped. Returns the points in file order.
pub fn parse_planform_csv(text: &str) -> Result<Vec<[f64; 2]>> {
    let what = "planform CSV";
    let mut pts = Vec::new();
    let mut cols: Option<(usize, usize, usize)> = None; // (n columns, x col, y col)
    for (lineno, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if cols.is_none() && fields.iter().any(|f| f.parse::<f64>().is_err()) {
            // header line
            let lower: Vec<String> = fields.iter().map(|f| f.to_ascii_lowercase()).collect();
            let xi = lower.iter().position(|f| f == "x_mm" || f == "x");
            let yi = lower.iter().position(|f| f == "y_mm" || f == "y");
            match (xi, yi) {
                (Some(xi), Some(yi)) => {
                    cols = Some((fields.len(), xi, yi));
                    continue;
                }
                _ => {
                    return Err(parse_err(
                        what,
                        format!(
                            "line {}: expected a header `x_mm,y_mm` or `i,x_mm,y_mm`, got `{line}`",
                            lineno + 1
                        ),
                    ))
                }
            }
        }
        let (n, xi, yi) = *cols.get_or_insert(match fields.len() {
            2 => (2, 0, 1),
            3 => (3, 1, 2),
            k => {
                return Err(parse_err(
                    what,
                    format!("line {}: expected 2 or 3 columns, got {k}", lineno + 1),
                ))
            }
        });
        if fields.len() != n {
            return Err(parse_err(
                what,
                format!(
                    "line {}: expected {n} columns, got {}",
                    lineno + 1,
                    fields.len()
                ),
            ));
        }
        let num = |s: &str| -> Result<f64> {
            s.parse::<f64>().map_err(|e| {
                parse_err(
                    what,
                    format!("line {}: `{s}` is not a number ({e})", lineno + 1),
                )
            })
        };
        pts.push([num(fields[xi])?, num(fields[yi])?]);
        if pts.len() > MAX_OUTLINE_POINTS {
            return Err(WingbeatError::ResourceCap {
                field: "planform".into(),
                requested: format!("more than {MAX_OUTLINE_POINTS} points"),
                cap: MAX_OUTLINE_POINTS.to_string(),
                why: "the outline checks are quadratic in the point count".into(),
            });
        }
    }
    Ok(pts)
}

/// Parses a planform outline from a JSON array of `[x, y]` pairs (mm).
pub fn parse_planform_json(text: &str) -> Result<Vec<[f64; 2]>> {
    let pts: Vec<[f64; 2]> =
        serde_json::from_str(text).map_err(|e| parse_err("planform JSON", e.to_string()))?;
    if pts.len() > MAX_OUTLINE_POINTS {
        return Err(WingbeatError::ResourceCap {
            field: "planform".into(),
            requested: format!("{} points", pts.len()),
            cap: MAX_OUTLINE_POINTS.to_string(),
            why: "the outline checks are quadratic in the point count".into(),
        });
    }
    Ok(pts)
}

/// The default (synthetic) Manduca-like outline, mm.
pub fn manduca_planform() -> Vec<[f64; 2]> {
    parse_planform_csv(MANDUCA_CSV).expect("built-in planform parses")
}

/// A rectangle `span_mm` × `chord_mm` as a counter-clockwise outline with the root edge on
/// x = 0 from (0, −chord) to (0, 0), like the wing outlines (chord toward −y).
pub fn rectangle_planform(span_mm: f64, chord_mm: f64) -> Vec<[f64; 2]> {
    vec![
        [0.0, -chord_mm],
        [span_mm, -chord_mm],
        [span_mm, 0.0],
        [0.0, 0.0],
    ]
}

/// Signed area (mm²) of a closed polygon; positive when counter-clockwise.
pub fn signed_area(p: &[[f64; 2]]) -> f64 {
    let n = p.len();
    (0..n)
        .map(|i| {
            let a = p[i];
            let b = p[(i + 1) % n];
            a[0] * b[1] - b[0] * a[1]
        })
        .sum::<f64>()
        * 0.5
}

fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

fn on_segment(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> bool {
    p[0] >= a[0].min(b[0])
        && p[0] <= a[0].max(b[0])
        && p[1] >= a[1].min(b[1])
        && p[1] <= a[1].max(b[1])
}

fn segments_intersect(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    let d1 = orient(c, d, a);
    let d2 = orient(c, d, b);
    let d3 = orient(a, b, c);
    let d4 = orient(a, b, d);
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
        && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
    {
        return true;
    }
    (d1 == 0.0 && on_segment(c, d, a))
        || (d2 == 0.0 && on_segment(c, d, b))
        || (d3 == 0.0 && on_segment(a, b, c))
        || (d4 == 0.0 && on_segment(a, b, d))
}

/// Validates and normalises an outline (mm): at least 3 distinct points, finite coordinates,
/// no repeated consecutive points (a closing copy of the first point is dropped), not
/// self-intersecting, non-zero area. Returns it counter-clockwise.
pub fn validate_outline(points: &[[f64; 2]]) -> Result<Vec<[f64; 2]>> {
    if points.len() > MAX_OUTLINE_POINTS {
        return Err(WingbeatError::ResourceCap {
            field: "planform".into(),
            requested: format!("{} points", points.len()),
            cap: MAX_OUTLINE_POINTS.to_string(),
            why: "the outline checks are quadratic in the point count".into(),
        });
    }
    for (i, p) in points.iter().enumerate() {
        for (k, c) in p.iter().enumerate() {
            if !c.is_finite() || c.abs() > MAX_COORD_MM {
                return Err(WingbeatError::invalid(
                    format!("planform[{i}][{k}]"),
                    c,
                    format!("a finite coordinate within ±{MAX_COORD_MM} mm"),
                ));
            }
        }
    }
    // the points without exact repeats, with their index in `points` (for messages)
    let mut p: Vec<[f64; 2]> = Vec::with_capacity(points.len());
    let mut orig: Vec<usize> = Vec::with_capacity(points.len());
    for (i, q) in points.iter().enumerate() {
        if p.last() != Some(q) {
            p.push(*q);
            orig.push(i);
        }
    }
    while p.len() > 1 && p.first() == p.last() {
        p.pop();
        orig.pop();
    }
    if p.len() < 3 {
        return Err(WingbeatError::invalid(
            "planform",
            format!("{} distinct points", p.len()),
            "at least 3 distinct points forming a simple polygon",
        ));
    }
    let (lo, hi) = bounds(&p);
    let (span, chord) = (hi[0] - lo[0], hi[1] - lo[1]);
    for (what, v) in [("span (x extent)", span), ("chord (y extent)", chord)] {
        if v < MIN_EXTENT_MM {
            return Err(WingbeatError::invalid(
                "planform",
                format!("a {what} of {} mm", crate::error::num(v)),
                format!(
                    "an outline at least {MIN_EXTENT_MM} mm in span and chord (coordinates are in mm)"
                ),
            ));
        }
    }
    check_meshable(&p, &|i| format!("planform[{}]", orig[i]), "planform")?;
    let area = signed_area(&p);
    if area.abs() < MIN_AREA_FRACTION * span * chord {
        return Err(WingbeatError::invalid(
            "planform",
            format!(
                "an area of {} mm^2 in a {} × {} mm box",
                crate::error::num(area.abs()),
                crate::error::num(span),
                crate::error::num(chord)
            ),
            format!(
                "an outline that covers at least {MIN_AREA_FRACTION} of its bounding box (not a sliver or a line)"
            ),
        ));
    }
    if area < 0.0 {
        p.reverse();
    }
    Ok(p)
}

fn bounds(p: &[[f64; 2]]) -> ([f64; 2], [f64; 2]) {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for q in p {
        for k in 0..2 {
            lo[k] = lo[k].min(q[k]);
            hi[k] = hi[k].max(q[k]);
        }
    }
    (lo, hi)
}

/// Distance from `p` to the segment a–b.
pub(crate) fn point_segment_distance(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a[0] + t * dx - p[0]).hypot(a[1] + t * dy - p[1])
}

/// Three significant digits, compactly (`3e-5`, not `2.9999999999999997e-5`).
fn sig3(v: f64) -> String {
    crate::error::num(format!("{v:.2e}").parse().unwrap_or(v))
}

fn pt(p: [f64; 2]) -> String {
    format!("({}, {})", crate::error::num(p[0]), crate::error::num(p[1]))
}

/// Refuses a closed polygon (mm, no exact repeats) that floating point cannot mesh: two points
/// nearer than [`MIN_SEPARATION_FRACTION`] × its size (a zero-length edge when they are
/// neighbours), a point that nearly touches an edge it is not an end of (the outline touches
/// itself), edges that cross, and a spike sharper than [`MIN_VERTEX_ANGLE_DEG`]. `label(i)` names point `i`
/// as the user gave it (`planform[4]`); `field` names the outline. O(n²) in the point count (at
/// most [`MAX_OUTLINE_POINTS`]). The mesher runs it again on the outline it is given (with
/// the mesh lines' crossings inserted), so no input reaches the triangulation unchecked.
pub fn check_meshable(p: &[[f64; 2]], label: &dyn Fn(usize) -> String, field: &str) -> Result<()> {
    let n = p.len();
    if n < 3 {
        return Err(WingbeatError::invalid(
            field,
            format!("{n} points"),
            "at least 3 distinct points forming a simple polygon",
        ));
    }
    let (lo, hi) = bounds(p);
    let size = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    let tol = MIN_SEPARATION_FRACTION * size;
    if !(size.is_finite() && tol > 0.0 && tol.is_normal()) {
        return Err(WingbeatError::invalid(
            field,
            format!("an outline of size {} mm", crate::error::num(size)),
            format!(
                "a finite outline at least {MIN_EXTENT_MM} mm in span and chord, coordinates within ±{MAX_COORD_MM} mm"
            ),
        ));
    }
    let allowed = format!(
        "points at least {} mm apart and from every edge they are not an end of \
         ({} of the outline's size, {} mm): floating point cannot mesh nearly coincident or \
         touching geometry",
        sig3(tol),
        crate::error::num(MIN_SEPARATION_FRACTION),
        sig3(size)
    );
    check_separation(p, label, tol, &allowed)?;
    check_touching(p, label, tol, &allowed)?;
    check_crossings(p, label, field)?;
    check_spikes(p, label)
}

/// Two points of `p` nearer than `tol` (a zero-length edge when they are neighbours).
fn check_separation(
    p: &[[f64; 2]],
    label: &dyn Fn(usize) -> String,
    tol: f64,
    allowed: &str,
) -> Result<()> {
    let n = p.len();
    for i in 0..n {
        for j in (i + 1)..n {
            let d = (p[i][0] - p[j][0]).hypot(p[i][1] - p[j][1]);
            if d < tol {
                let what = if j == i + 1 || (i == 0 && j == n - 1) {
                    "a zero-length edge: "
                } else {
                    ""
                };
                return Err(WingbeatError::invalid(
                    label(j),
                    format!(
                        "{what}{} is {} mm from {} {}",
                        pt(p[j]),
                        crate::error::num(d),
                        label(i),
                        pt(p[i])
                    ),
                    allowed,
                ));
            }
        }
    }
    Ok(())
}

/// A point nearer than `tol` to an edge it is not an end of: the outline touches itself.
fn check_touching(
    p: &[[f64; 2]],
    label: &dyn Fn(usize) -> String,
    tol: f64,
    allowed: &str,
) -> Result<()> {
    let n = p.len();
    for i in 0..n {
        for j in 0..n {
            let k = (j + 1) % n;
            if i == j || i == k {
                continue;
            }
            let d = point_segment_distance(p[i], p[j], p[k]);
            if d < tol {
                return Err(WingbeatError::invalid(
                    label(i),
                    format!(
                        "{} is {} mm from the edge {}–{} ({}–{}): the outline touches itself",
                        pt(p[i]),
                        crate::error::num(d),
                        label(j),
                        label(k),
                        pt(p[j]),
                        pt(p[k])
                    ),
                    allowed,
                ));
            }
        }
    }
    Ok(())
}

/// Edges that cross (the near misses are caught by [`check_touching`]).
fn check_crossings(p: &[[f64; 2]], label: &dyn Fn(usize) -> String, field: &str) -> Result<()> {
    let n = p.len();
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        for j in (i + 2)..n {
            if i == 0 && j == n - 1 {
                continue;
            }
            let (c, d) = (p[j], p[(j + 1) % n]);
            if segments_intersect(a, b, c, d) {
                return Err(WingbeatError::Geometry(format!(
                    "{field} outline is self-intersecting: edge {}–{} ({}–{}) crosses edge {}–{} ({}–{})",
                    label(i),
                    label((i + 1) % n),
                    pt(a),
                    pt(b),
                    label(j),
                    label((j + 1) % n),
                    pt(c),
                    pt(d)
                )));
            }
        }
    }
    Ok(())
}

/// A spike: an angle sharper than [`MIN_VERTEX_ANGLE_DEG`] between the two edges at a point.
fn check_spikes(p: &[[f64; 2]], label: &dyn Fn(usize) -> String) -> Result<()> {
    let n = p.len();
    let min_angle = MIN_VERTEX_ANGLE_DEG.to_radians();
    for i in 0..n {
        let (a, b, c) = (p[(i + n - 1) % n], p[i], p[(i + 1) % n]);
        let (u, v) = ([a[0] - b[0], a[1] - b[1]], [c[0] - b[0], c[1] - b[1]]);
        let angle = (u[0] * v[1] - u[1] * v[0])
            .abs()
            .atan2(u[0] * v[0] + u[1] * v[1]);
        if angle < min_angle {
            return Err(WingbeatError::invalid(
                label(i),
                format!(
                    "a spike of {}° at {} between {} and {}",
                    crate::error::num((angle.to_degrees() * 1e6).round() / 1e6),
                    pt(b),
                    label((i + n - 1) % n),
                    label((i + 1) % n)
                ),
                format!(
                    "an angle of at least {MIN_VERTEX_ANGLE_DEG}° between the two edges at every point (a sharper spike is a zero-area sliver to the mesher)"
                ),
            ));
        }
    }
    Ok(())
}

/// Local leading-edge and trailing-edge y (mm) of the outline at spanwise station `x`:
/// the largest and smallest y where the vertical line through `x` meets the outline.
/// Returns `None` if the line misses the outline.
pub fn chord_extent(outline: &[[f64; 2]], x: f64) -> Option<(f64, f64)> {
    let n = outline.len();
    let (mut ymax, mut ymin) = (f64::NEG_INFINITY, f64::INFINITY);
    for i in 0..n {
        let (a, b) = (outline[i], outline[(i + 1) % n]);
        let (x0, x1) = (a[0].min(b[0]), a[0].max(b[0]));
        if x < x0 || x > x1 {
            continue;
        }
        let ys: [f64; 2] = if (b[0] - a[0]).abs() < 1e-300 {
            [a[1], b[1]]
        } else {
            let s = (x - a[0]) / (b[0] - a[0]);
            let y = a[1] + s * (b[1] - a[1]);
            [y, y]
        };
        for y in ys {
            ymax = ymax.max(y);
            ymin = ymin.min(y);
        }
    }
    (ymax >= ymin).then_some((ymax, ymin))
}

/// Camber height (mm) at (x, y): a circular arc across the local chord at station x whose
/// rise at mid-chord is `camber` × local chord (so the camber tapers with the chord), zero at
/// the leading and trailing edges. Points outside the local chord get zero.
pub fn camber_height(outline: &[[f64; 2]], camber: f64, x: f64, y: f64) -> f64 {
    if camber == 0.0 {
        return 0.0;
    }
    let Some((yle, yte)) = chord_extent(outline, x) else {
        return 0.0;
    };
    let c = yle - yte;
    if c <= 0.0 {
        return 0.0;
    }
    let h = camber * c;
    let half = 0.5 * c;
    let r = (half * half + h * h) / (2.0 * h);
    let d = (y.clamp(yte, yle) - 0.5 * (yle + yte)).abs();
    let s = (r * r - d * d).max(0.0).sqrt() - (r - h);
    s.max(0.0)
}

// ---- Built-in outlines (the lab's planform picker) ----

/// A built-in planform: an identifier, a label that says it is synthetic, a provenance note
/// and the outline in mm (counter-clockwise, root edge on x = 0, chord toward −y).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct BuiltinPlanform {
    /// Identifier (`manduca`, `slender`, `broad`, `rect`).
    pub id: &'static str,
    /// Human label, including the word "synthetic".
    pub label: &'static str,
    /// Provenance note (copied into `FemInput.planform_note` when used).
    pub note: &'static str,
    /// Outline, mm.
    pub points_mm: Vec<[f64; 2]>,
}

/// An outline with a straight leading edge on y = 0 from the root (0, 0) to the tip
/// (`span`, 0) and a trailing edge y = −c(x) given by the superellipse
/// (x / span)^p + (c / root_chord)^p = 1, sampled at `n` points from the root to the tip
/// (denser near the tip), coordinates rounded to 0.1 µm. The root edge is x = 0 from
/// (0, −root_chord) to (0, 0).
fn superellipse_wing(span: f64, root_chord: f64, p: f64, n: usize, n_le: usize) -> Vec<[f64; 2]> {
    let round = |v: f64| (v * 1e4).round() / 1e4;
    let mut pts = Vec::with_capacity(n + n_le + 1);
    for i in 0..n {
        let th = std::f64::consts::FRAC_PI_2 * i as f64 / (n - 1) as f64;
        let (s, c) = th.sin_cos();
        let x = span * s.powf(2.0 / p);
        let y = -root_chord * c.powf(2.0 / p);
        pts.push([round(x), round(y)]);
    }
    // Back along the leading edge, from just inside the tip to the root.
    for j in 1..=n_le {
        let x = span * (1.0 - j as f64 / n_le as f64);
        pts.push([round(x), 0.0]);
    }
    pts
}

/// Provenance note of the `slender` outline.
pub const SLENDER_NOTE: &str = "synthetic slender wing: straight leading edge, elliptic \
trailing edge, span 45 mm, root chord 9 mm (aspect ratio 6.4); not a measured wing";
/// Provenance note of the `broad` outline.
pub const BROAD_NOTE: &str = "synthetic broad wing: straight leading edge, superellipse \
(power 3) trailing edge, span 30 mm, root chord 20 mm (aspect ratio 1.7); not a measured wing";
/// Provenance note of the `rect` outline.
pub const RECT_NOTE: &str = "synthetic rectangular plate 40 mm × 10 mm, root edge on x = 0";

/// The built-in outlines, the default first: `manduca` (the synthetic Manduca-like forewing,
/// [`manduca_planform`]), `slender`, `broad` and `rect`. All are synthetic, have a root edge
/// on x = 0 (so [`crate::fem::Clamp::Root`] applies) and contain the paper's strain point
/// P = (3, −6) mm; `tests/lab_api.rs` meshes and solves each one.
pub fn builtin_planforms() -> Vec<BuiltinPlanform> {
    vec![
        BuiltinPlanform {
            id: "manduca",
            label: "Manduca-like forewing (synthetic)",
            note: MANDUCA_NOTE,
            points_mm: manduca_planform(),
        },
        BuiltinPlanform {
            id: "slender",
            label: "Slender elliptic wing (synthetic)",
            note: SLENDER_NOTE,
            points_mm: superellipse_wing(45.0, 9.0, 2.0, 17, 6),
        },
        BuiltinPlanform {
            id: "broad",
            label: "Broad wing (synthetic)",
            note: BROAD_NOTE,
            points_mm: superellipse_wing(30.0, 20.0, 3.0, 17, 5),
        },
        BuiltinPlanform {
            id: "rect",
            label: "Rectangular plate 40 × 10 mm (synthetic)",
            note: RECT_NOTE,
            points_mm: rectangle_planform(40.0, 10.0),
        },
    ]
}

/// What the lab shows about an outline while it is edited.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct OutlineSummary {
    /// Area, mm².
    pub area_mm2: f64,
    /// Spanwise extent max x − min x, mm.
    pub span_mm: f64,
    /// Chordwise extent max y − min y, mm.
    pub chord_mm: f64,
    /// Number of distinct points (after dropping repeats and a closing copy).
    pub n_points: usize,
    /// Whether an edge lies on x = 0 (the root edge that the root clamp holds).
    pub root_edge: bool,
}

/// Validates `points` ([`validate_outline`]) and summarises the outline.
pub fn outline_summary(points: &[[f64; 2]]) -> Result<OutlineSummary> {
    let p = validate_outline(points)?;
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for q in &p {
        for k in 0..2 {
            lo[k] = lo[k].min(q[k]);
            hi[k] = hi[k].max(q[k]);
        }
    }
    let scale = p
        .iter()
        .map(|q| q[0].abs().max(q[1].abs()))
        .fold(0.0, f64::max);
    let tol = 1e-9 * scale.max(1e-300);
    let n = p.len();
    let root_edge = (0..n).any(|i| p[i][0].abs() <= tol && p[(i + 1) % n][0].abs() <= tol);
    Ok(OutlineSummary {
        area_mm2: signed_area(&p),
        span_mm: hi[0] - lo[0],
        chord_mm: hi[1] - lo[1],
        n_points: n,
        root_edge,
    })
}

/// The provenance note for an outline: a built-in's note when `points` are exactly that
/// built-in's outline, else `user outline (N points)`.
pub fn planform_note_for(points: &[[f64; 2]]) -> String {
    builtin_planforms()
        .into_iter()
        .find(|b| b.points_mm == points)
        .map_or_else(
            || format!("user outline ({} points)", points.len()),
            |b| b.note.to_string(),
        )
}
