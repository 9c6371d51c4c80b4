// @ts-check
// Pure maths for the 3-D view (no DOM, no wasm), unit-tested in tests/js/scene3d.test.mjs:
//
// * a mirror of the renderer's orbit camera (src/render/scene.rs OrbitCamera: target, yaw,
//   pitch, distance, 45° field of view, K up) and of the wing rotation R_x(α)·R_y(β)·R_z(γ), so
//   the page can place every pose of the run on screen and fit the camera to the whole stroke
//   using only the WingView API (orbit / zoom);
// * the strain colour range of a run: per component, the robust (98th-percentile over nodes)
//   maximum over time of |Σ_k ε_k(node) q_k(t)|, fixed for the whole run so colours pulse with
//   the beat instead of being rescaled every frame;
// * the largest true deflection over the run.
// Extremes over time use the convex hull of the modal trajectory (q_1(t), q_2(t)): a linear
// function of q — or a norm of one — takes its maximum over the run at a hull vertex, so the
// result is exact and costs (hull vertices × nodes), not (samples × nodes).

export const ORBIT_RAD_PER_PX = 0.008;
const PITCH_LIMIT = Math.PI / 2 - 0.01;
const TAU = 2 * Math.PI;

/**
 * The mirror of the renderer's orbit camera: target (m), yaw and pitch (rad), distance (m),
 * vertical field of view (rad).
 * @typedef {{ target: number[], yaw: number, pitch: number, distance: number, fov: number }} Camera
 */

/**
 * The canvas backing store (device pixels) for a `cssW` × `cssH` CSS-pixel canvas: CSS size ×
 * devicePixelRatio, the ratio capped at `maxDpr` and the area at `maxPixels` (the scale shrinks
 * uniformly, keeping the aspect). Each side at least 1 px.
 * @param {number} cssW
 * @param {number} cssH
 * @param {number} dpr
 * @param {number} maxDpr
 * @param {number} maxPixels
 * @returns {{ width: number, height: number, scale: number }}
 */
export function backingSize(cssW, cssH, dpr, maxDpr, maxPixels) {
  let scale = Math.min(maxDpr, Number.isFinite(dpr) && dpr > 0 ? dpr : 1);
  const area = cssW * cssH * scale * scale;
  if (area > maxPixels) scale = Math.sqrt(maxPixels / (cssW * cssH));
  return { width: Math.max(1, Math.floor(cssW * scale)), height: Math.max(1, Math.floor(cssH * scale)), scale };
}

/**
 * The renderer's initial camera for a wing of span `span` (m): OrbitCamera::for_span.
 * @param {number} span
 * @returns {Camera}
 */
export function defaultCamera(span) {
  const s = Number.isFinite(span) && span > 0 ? span : 0.05;
  return { target: [0.5 * s, -0.25 * s, 0], yaw: -1.95, pitch: 0.8, distance: 2.1 * s, fov: (45 * Math.PI) / 180 };
}

/** The camera after WingView.orbit(dx, dy) (same arithmetic as the renderer). */
export function orbit(cam, dx, dy) {
  if (!Number.isFinite(dx) || !Number.isFinite(dy)) return cam;
  return { ...cam, yaw: (cam.yaw - dx * ORBIT_RAD_PER_PX) % TAU, pitch: Math.min(PITCH_LIMIT, Math.max(-PITCH_LIMIT, cam.pitch + dy * ORBIT_RAD_PER_PX)) };
}

/** The camera after WingView.zoom(factor). */
export function zoom(cam, f) {
  if (!(Number.isFinite(f) && f > 0)) return cam;
  return { ...cam, distance: Math.min(1e3, Math.max(1e-3, cam.distance * f)) };
}

/** The camera after WingView.key(k); null when the renderer ignores the key. */
export function key(cam, k) {
  switch (k) {
    case 'ArrowLeft': return orbit(cam, -12, 0);
    case 'ArrowRight': return orbit(cam, 12, 0);
    case 'ArrowUp': return orbit(cam, 0, 12);
    case 'ArrowDown': return orbit(cam, 0, -12);
    case '+': case '=': return zoom(cam, 1 / 1.1);
    case '-': case '_': return zoom(cam, 1.1);
    default: return null;
  }
}

/**
 * The orbit (dx, dy in "pixels") and zoom factor that take camera `from` to `to` (same target).
 * Applying them with WingView.orbit / zoom reproduces `to` up to float32 rounding.
 */
export function moveTo(from, to) {
  return { dx: (from.yaw - to.yaw) / ORBIT_RAD_PER_PX, dy: (to.pitch - from.pitch) / ORBIT_RAD_PER_PX, zoom: to.distance / from.distance };
}

export function eye(cam) {
  const cp = Math.cos(cam.pitch), sp = Math.sin(cam.pitch), cy = Math.cos(cam.yaw), sy = Math.sin(cam.yaw);
  const d = cam.distance, t = cam.target;
  return [t[0] + d * cp * cy, t[1] + d * cp * sy, t[2] + d * sp];
}

/** A projector for a width × height image: (x, y, z) → [px, py] (pixel units, y down), or null behind the eye. */
export function projector(cam, width, height) {
  const e = eye(cam);
  const t = cam.target;
  let f = [t[0] - e[0], t[1] - e[1], t[2] - e[2]];
  const fl = Math.hypot(...f);
  f = f.map((v) => v / fl);
  // s = normalize(f × up), up = K
  let s = [f[1], -f[0], 0];
  const sl = Math.hypot(...s) || 1;
  s = s.map((v) => v / sl);
  const u = [s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]];
  const F = 1 / Math.tan(0.5 * cam.fov);
  const aspect = width / Math.max(1, height);
  return (x, y, z) => {
    const d0 = x - e[0], d1 = y - e[1], d2 = z - e[2];
    const depth = f[0] * d0 + f[1] * d1 + f[2] * d2;
    if (depth <= 0) return null;
    const nx = ((F / aspect) * (s[0] * d0 + s[1] * d1 + s[2] * d2)) / depth;
    const ny = (F * (u[0] * d0 + u[1] * d1 + u[2] * d2)) / depth;
    return [(nx + 1) * 0.5 * width, (1 - ny) * 0.5 * height];
  };
}

/** R_x(α)·R_y(β)·R_z(γ) applied to p (the renderer's wing rotation). */
export function rotate(alpha, beta, gamma, p) {
  const [x, y, z] = p;
  const cg = Math.cos(gamma), sg = Math.sin(gamma);
  const x1 = cg * x - sg * y, y1 = sg * x + cg * y, z1 = z;
  const cb = Math.cos(beta), sb = Math.sin(beta);
  const x2 = cb * x1 + sb * z1, y2 = y1, z2 = -sb * x1 + cb * z1;
  const ca = Math.cos(alpha), sa = Math.sin(alpha);
  return [x2, ca * y2 - sa * z2, sa * y2 + ca * z2];
}

/**
 * The nodes that can be extreme on screen: the convex hull of the planform (x, y), as a flat
 * [x, y, z, …] array with z set to the largest |z| (camber) of the wing, so that with a lift
 * of ± that much every node lies inside their hull in 3-D. Fitting the camera to these few
 * points gives the same bounding box as all nodes, hundreds of times cheaper.
 */
export function outline(nodes) {
  const n = nodes.length / 3;
  const xs = new Float64Array(n), ys = new Float64Array(n);
  let zmax = 0;
  for (let i = 0; i < n; i++) {
    xs[i] = nodes[3 * i];
    ys[i] = nodes[3 * i + 1];
    zmax = Math.max(zmax, Math.abs(nodes[3 * i + 2]));
  }
  const h = hull2(xs, ys);
  const out = new Float64Array(3 * h.length);
  h.forEach((i, j) => { out[3 * j] = xs[i]; out[3 * j + 1] = ys[i]; out[3 * j + 2] = 0; });
  return { nodes: out, zmax };
}

/** Span (largest x) of flat node coordinates [x, y, z, …]. */
export function spanOf(nodes) {
  let s = 0;
  for (let i = 0; i < nodes.length; i += 3) s = Math.max(s, nodes[i]);
  return s;
}

/** Indices of `count` samples evenly spread over one flap period of a run at `rate` Hz. */
export function flapSamples(n, rate, flapHz, count = 48, start = 0) {
  const per = Math.max(1, Math.round(rate / flapHz));
  const out = [];
  for (let j = 0; j < count; j++) {
    const i = start + Math.round((j * per) / count);
    if (i < n) out.push(i);
  }
  return out;
}

/**
 * World positions of (a subset of) the wing's nodes at the given poses: Float64Array of
 * x, y, z triples. `lift` (m) moves every node ± along its normal to cover the drawn deflection.
 */
export function posePoints(nodes, poses, { stride = 1, lift = 0 } = {}) {
  const out = [];
  for (const [a, b, g] of poses) {
    for (let i = 0; i < nodes.length; i += 3 * stride) {
      for (const dz of lift > 0 ? [-lift, lift] : [0]) {
        const w = rotate(a, b, g, [nodes[i], nodes[i + 1], nodes[i + 2] + dz]);
        out.push(w[0], w[1], w[2]);
      }
    }
  }
  return Float64Array.from(out);
}

/** Pixel bounding box [x0, y0, x1, y1] of world points; null if any is behind the eye. */
export function bbox(cam, pts, width, height) {
  const pr = projector(cam, width, height);
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let i = 0; i < pts.length; i += 3) {
    const p = pr(pts[i], pts[i + 1], pts[i + 2]);
    if (!p) return null;
    if (p[0] < x0) x0 = p[0];
    if (p[0] > x1) x1 = p[0];
    if (p[1] < y0) y0 = p[1];
    if (p[1] > y1) y1 = p[1];
  }
  return [x0, y0, x1, y1];
}

/**
 * The smallest camera distance (same target and direction) at which every point projects
 * inside the image with `margin` (fraction of each side) to spare. Bisection on the distance.
 */
export function fitDistance(cam, pts, width, height, margin = 0.05) {
  const inside = (d) => {
    const b = bbox({ ...cam, distance: d }, pts, width, height);
    return b && b[0] >= margin * width && b[2] <= (1 - margin) * width && b[1] >= margin * height && b[3] <= (1 - margin) * height;
  };
  let lo = cam.distance * 0.05, hi = cam.distance;
  let guard = 0;
  while (!inside(hi) && guard++ < 40) hi *= 1.5;
  for (let it = 0; it < 26; it++) {
    const mid = 0.5 * (lo + hi);
    if (inside(mid)) hi = mid;
    else lo = mid;
  }
  return hi;
}

/** Projected area (pixels) of the wing's triangles at one pose, summed. */
export function projectedArea(cam, nodes, triangles, pose, width, height) {
  const pr = projector(cam, width, height);
  const n = nodes.length / 3;
  const P = new Float64Array(2 * n);
  for (let i = 0; i < n; i++) {
    const w = rotate(pose[0], pose[1], pose[2], [nodes[3 * i], nodes[3 * i + 1], nodes[3 * i + 2]]);
    const p = pr(w[0], w[1], w[2]) || [NaN, NaN];
    P[2 * i] = p[0];
    P[2 * i + 1] = p[1];
  }
  let area = 0;
  for (let t = 0; t < triangles.length; t += 3) {
    const a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
    const A = 0.5 * Math.abs((P[2 * b] - P[2 * a]) * (P[2 * c + 1] - P[2 * a + 1]) - (P[2 * c] - P[2 * a]) * (P[2 * b + 1] - P[2 * a + 1]));
    if (Number.isFinite(A)) area += A;
  }
  return area;
}

/**
 * The default view of a run: from the renderer's camera direction varied over a small grid of
 * yaw/pitch, the one whose stroke-fitting framing leaves the wing largest on screen (mean
 * projected area over the stroke) while keeping the stroke seen from above its plane. Returns
 * { camera, coverage } (coverage: mean wing area / image area).
 *
 * `fit(camera)` frames the stroke from that camera's direction; the lab passes the renderer's
 * own fit (WingView.fitPoints: target centred on the stroke, smallest distance). Without it the
 * target stays and only the distance is fitted here (fitDistance, `margin` of each side).
 * @param {number} span
 * @param {ArrayLike<number>} nodes
 * @param {ArrayLike<number>} triangles
 * @param {number[][]} poses [α, β, γ] each
 * @param {number} width
 * @param {number} height
 * @param {{ lift?: number, margin?: number, fit?: ((cam: Camera) => Camera) | null }} [o]
 */
export function bestView(span, nodes, triangles, poses, width, height, { lift = 0, margin = 0.03, fit = null } = {}) {
  const base = defaultCamera(span);
  const ol = outline(nodes);
  const pts = posePoints(ol.nodes, poses, { lift: lift + ol.zmax });
  const few = poses.filter((_, j) => j % Math.max(1, Math.floor(poses.length / 8)) === 0);
  /** @type {{ camera: Camera, coverage: number } | null} */
  let best = null;
  for (const dyaw of [-0.9, -0.6, -0.3, 0, 0.3, 0.6, 0.9]) {
    for (const pitch of [0.7, 0.9, 1.1]) {
      const cam0 = { ...base, yaw: base.yaw + dyaw, pitch };
      const cam = fit ? fit(cam0) : { ...cam0, distance: fitDistance(cam0, pts, width, height, margin) };
      let area = 0;
      for (const p of few) area += projectedArea(cam, nodes, triangles, p, width, height);
      const coverage = area / few.length / (width * height);
      if (!best || coverage > best.coverage) best = { camera: cam, coverage };
    }
  }
  return best;
}

/**
 * Convex hull (monotone chain) of 2-D points given as two arrays; returns vertex indices.
 * Points strictly inside the polygon of the 16 directional extremes are dropped first
 * (Akl–Toussaint), so long trajectories sort only their outer points.
 */
export function hull2(xs, ys) {
  const n = xs.length;
  /** @type {number[] | null} */
  let cand = null;
  if (n > 64) {
    /** @type {number[]} */
    const ext = [];
    for (let d = 0; d < 16; d++) {
      const c = Math.cos((Math.PI * d) / 8), sn = Math.sin((Math.PI * d) / 8);
      let best = 0, bv = -Infinity;
      for (let i = 0; i < n; i++) {
        const v = c * xs[i] + sn * ys[i];
        if (v > bv) { bv = v; best = i; }
      }
      if (ext[ext.length - 1] !== best && ext[0] !== best) ext.push(best);
    }
    // ext is in angular order (counter-clockwise); keep points not strictly inside it
    if (ext.length >= 3) {
      /** @type {number[]} */
      const kept = [];
      cand = kept;
      const m = ext.length;
      for (let i = 0; i < n; i++) {
        let inside = true;
        for (let j = 0; j < m; j++) {
          const a = ext[j], b = ext[(j + 1) % m];
          if ((xs[b] - xs[a]) * (ys[i] - ys[a]) - (ys[b] - ys[a]) * (xs[i] - xs[a]) <= 0) { inside = false; break; }
        }
        if (!inside) kept.push(i);
      }
    }
  }
  const idx = (cand || Array.from({ length: n }, (_, i) => i)).sort((a, b) => xs[a] - xs[b] || ys[a] - ys[b]);
  const cross = (o, a, b) => (xs[a] - xs[o]) * (ys[b] - ys[o]) - (ys[a] - ys[o]) * (xs[b] - xs[o]);
  const lower = [], upper = [];
  for (const i of idx) {
    while (lower.length >= 2 && cross(lower[lower.length - 2], lower[lower.length - 1], i) <= 0) lower.pop();
    lower.push(i);
  }
  for (let j = idx.length - 1; j >= 0; j--) {
    const i = idx[j];
    while (upper.length >= 2 && cross(upper[upper.length - 2], upper[upper.length - 1], i) <= 0) upper.pop();
    upper.push(i);
  }
  upper.pop();
  lower.pop();
  const h = lower.concat(upper);
  return h.length ? h : idx.length ? [idx[0]] : n ? [0] : [];
}

/**
 * Modal states q (one array per mode, length n_modes) at which every extreme over the run is
 * reached: hull vertices for one or two modes (exact), else every `stride`-th sample plus each
 * mode's extremes.
 */
export function extremeStates(qs, maxSamples = 4000) {
  const m = qs.length;
  const n = m ? qs[0].length : 0;
  if (!n) return [];
  if (m === 1) {
    let lo = 0, hi = 0;
    for (let i = 1; i < n; i++) {
      if (qs[0][i] < qs[0][lo]) lo = i;
      if (qs[0][i] > qs[0][hi]) hi = i;
    }
    return [[qs[0][lo]], [qs[0][hi]]];
  }
  if (m === 2) return hull2(qs[0], qs[1]).map((i) => [qs[0][i], qs[1][i]]);
  const stride = Math.max(1, Math.ceil(n / maxSamples));
  const pick = new Set();
  for (let i = 0; i < n; i += stride) pick.add(i);
  for (const q of qs) {
    let lo = 0, hi = 0;
    for (let i = 1; i < n; i++) {
      if (q[i] < q[lo]) lo = i;
      if (q[i] > q[hi]) hi = i;
    }
    pick.add(lo);
    pick.add(hi);
  }
  return [...pick].map((i) => qs.map((q) => q[i]));
}

/** The p-quantile of |values| (rank round((n−1)·p); p = 0.98 is the renderer's own robust range). */
export function robust(values, p = 0.98) {
  // A typed array sorts numerically without a comparator call per comparison (several times faster).
  const a = Float64Array.from(values, Math.abs).filter(Number.isFinite).sort();
  if (!a.length) return 0;
  return a[Math.round((a.length - 1) * p)];
}

/**
 * Quantile over nodes used for the run-wide colour range. Strain is singular at the clamped
 * root, and a run's extremes there are far above the rest of the wing: the 90th percentile
 * keeps the colours readable over the wing (the hot root saturates) while still being one
 * fixed range for the whole run.
 */
export const RANGE_QUANTILE = 0.9;

/**
 * The strain [ε_x, ε_y, γ_xy] at node i for the modal state q (first m modes):
 * Σ_k strainNodes[(k·n + i)·3 + c] q_k, written into `out` (a reused 3-array) and returned.
 * @param {ArrayLike<number>} strainNodes @param {number} nNodes @param {number} m
 * @param {number} i @param {ArrayLike<number>} q @param {Float64Array} out
 */
function strainAt(strainNodes, nNodes, m, i, q, out) {
  let ex = 0, ey = 0, g = 0;
  for (let k = 0; k < m; k++) {
    const o = (k * nNodes + i) * 3;
    ex += strainNodes[o] * q[k];
    ey += strainNodes[o + 1] * q[k];
    g += strainNodes[o + 2] * q[k];
  }
  out[0] = ex;
  out[1] = ey;
  out[2] = g;
  return out;
}

/**
 * The colour range of a run per component: { 1: ε_x, 2: ε_y, 3: γ_xy, 4: |ε| } (limits for
 * WingView.set_strain_range), each the robust (q-quantile over nodes, RANGE_QUANTILE by
 * default) maximum over time of the nodal |strain|. With more than two modes the maximum is over
 * at most `maxSamples` evenly spaced samples plus each mode's extremes (extremeStates). strainNodes[(k·n + i)·3 + c] per unit q_k; qs: q_k(t) per mode.
 */
export function strainRanges(strainNodes, nNodes, qs, q = RANGE_QUANTILE, maxSamples = 4000) {
  return strainRangesAt(strainNodes, nNodes, extremeStates(qs, maxSamples), q);
}

/**
 * The modal states q (one array per mode) at the given sample indices, e.g. an analysis's
 * `extreme_samples` (the core's hull vertices / extremes, so the page need not scan the run).
 * Indices past the end are skipped.
 * @param {ArrayLike<number>[]} qs @param {ArrayLike<number>} idx
 */
export function statesAt(qs, idx) {
  const n = qs.length ? qs[0].length : 0;
  /** @type {number[][]} */
  const out = [];
  for (const i of Array.from(idx)) if (i < n) out.push(qs.map((q) => q[i]));
  return out;
}

/** strainRanges over given modal states (see extremeStates / statesAt). */
export function strainRangesAt(strainNodes, nNodes, states, q = RANGE_QUANTILE) {
  const m0 = states.length ? states[0].length : 0;
  const m = Math.min(m0, Math.floor(strainNodes.length / (3 * nNodes)));
  const mx = [new Float64Array(nNodes), new Float64Array(nNodes), new Float64Array(nNodes), new Float64Array(nNodes)];
  const e = new Float64Array(3);
  for (let i = 0; i < nNodes; i++) {
    for (const q of states) {
      strainAt(strainNodes, nNodes, m, i, q, e);
      const ex = e[0], ey = e[1], g = e[2];
      const mag = Math.sqrt(ex * ex + ey * ey + 0.5 * g * g);
      if (Math.abs(ex) > mx[0][i]) mx[0][i] = Math.abs(ex);
      if (Math.abs(ey) > mx[1][i]) mx[1][i] = Math.abs(ey);
      if (Math.abs(g) > mx[2][i]) mx[2][i] = Math.abs(g);
      if (mag > mx[3][i]) mx[3][i] = mag;
    }
  }
  return { 1: robust(mx[0], q), 2: robust(mx[1], q), 3: robust(mx[2], q), 4: robust(mx[3], q) };
}

/** The largest |Σ_k φ_k(node) q_k(t)| over nodes and the whole run (m, true scale). */
export function maxDeflection(shapes, nNodes, qs, maxSamples = 4000) {
  return maxDeflectionAt(shapes, nNodes, extremeStates(qs, maxSamples));
}

/** maxDeflection over given modal states (see extremeStates / statesAt). */
export function maxDeflectionAt(shapes, nNodes, states) {
  const m = Math.min(states.length ? states[0].length : 0, Math.floor(shapes.length / nNodes));
  let best = 0;
  for (let i = 0; i < nNodes; i++) {
    for (const q of states) {
      let w = 0;
      for (let k = 0; k < m; k++) w += shapes[k * nNodes + i] * q[k];
      if (Math.abs(w) > best) best = Math.abs(w);
    }
  }
  return best;
}

// ---------- colour map, picking and whole-wing strain maps (mode viewer, strain panel) ----------

/**
 * The colour at `t` ∈ [0, 1] of a flat stop list [t0, r, g, b, t1, r, g, b, …] (sRGB 0–1, t
 * increasing), as [r, g, b] in 0–255. The stops come from the renderer (WingView.colourMap(),
 * the one definition of the map), so the 2-D drawings use the 3-D view's colours.
 * @param {ArrayLike<number>} stops
 * @param {number} t
 * @returns {number[]}
 */
export function colourAt(stops, t) {
  const n = Math.floor(stops.length / 4);
  if (!n) return [128, 128, 128];
  const x = Number.isFinite(t) ? Math.min(1, Math.max(0, t)) : 0.5;
  const rgb = (j) => [stops[4 * j + 1], stops[4 * j + 2], stops[4 * j + 3]];
  let out = rgb(n - 1);
  if (x <= stops[0]) out = rgb(0);
  else {
    for (let j = 0; j + 1 < n; j++) {
      const t0 = stops[4 * j], t1 = stops[4 * j + 4];
      if (x <= t1) {
        const f = t1 > t0 ? (x - t0) / (t1 - t0) : 0;
        const a = rgb(j), b = rgb(j + 1);
        out = [0, 1, 2].map((c) => a[c] + f * (b[c] - a[c]));
        break;
      }
    }
  }
  return out.map((v) => Math.round(255 * Math.min(1, Math.max(0, v))));
}

/**
 * Screen positions of every node of the wing at one pose: the renderer's vertex transform
 * (wing frame (x, y, z + ex·Σ φ_k q_k) rotated by R_x(α)·R_y(β)·R_z(γ)) then the camera
 * mirror's projection. Returns { xy: Float64Array [px, py, …] (NaN behind the eye), depth }.
 * @param {ArrayLike<number>} nodes flat x, y, z (m)
 * @param {ArrayLike<number> | null} shapes mode-major φ_k per node
 * @param {ArrayLike<number>} q modal coordinates (true scale)
 * @param {number} exaggeration
 * @param {number[]} ang [α, β, γ] rad
 * @param {Camera} cam
 * @param {number} width CSS pixels
 * @param {number} height
 */
export function projectNodes(nodes, shapes, q, exaggeration, ang, cam, width, height) {
  const n = Math.floor(nodes.length / 3);
  const m = shapes ? Math.min(q.length, Math.floor(shapes.length / Math.max(1, n))) : 0;
  const pr = projector(cam, width, height);
  const e = eye(cam);
  const xy = new Float64Array(2 * n), depth = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    let w = 0;
    for (let k = 0; k < m; k++) w += /** @type {ArrayLike<number>} */ (shapes)[k * n + i] * q[k];
    const p = rotate(ang[0], ang[1], ang[2], [nodes[3 * i], nodes[3 * i + 1], nodes[3 * i + 2] + exaggeration * w]);
    const s = pr(p[0], p[1], p[2]);
    xy[2 * i] = s ? s[0] : NaN;
    xy[2 * i + 1] = s ? s[1] : NaN;
    depth[i] = Math.hypot(p[0] - e[0], p[1] - e[1], p[2] - e[2]);
  }
  return { xy, depth };
}

/**
 * The wing point under a screen position: the front-most triangle (smallest mean depth) whose
 * projection contains (px, py), and the undeformed planform coordinates there (barycentric
 * interpolation of the nodes' x, y, m) with the barycentric weights `w` of the triangle's three
 * nodes `ids`. Null when no triangle is hit.
 * @param {ArrayLike<number>} nodes flat x, y, z (m)
 * @param {ArrayLike<number>} triangles
 * @param {{ xy: ArrayLike<number>, depth: ArrayLike<number> }} proj from projectNodes
 * @param {number} px
 * @param {number} py
 * @returns {{ tri: number, x: number, y: number, ids: number[], w: number[] } | null}
 */
export function pick(nodes, triangles, proj, px, py) {
  const { xy, depth } = proj;
  let best = -1, bestDepth = Infinity, bw = [0, 0, 0];
  for (let t = 0; t + 2 < triangles.length; t += 3) {
    const a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
    const ax = xy[2 * a], ay = xy[2 * a + 1], bx = xy[2 * b], by = xy[2 * b + 1], cx = xy[2 * c], cy = xy[2 * c + 1];
    const det = (by - cy) * (ax - cx) + (cx - bx) * (ay - cy);
    if (!Number.isFinite(det) || Math.abs(det) < 1e-12) continue;
    const l0 = ((by - cy) * (px - cx) + (cx - bx) * (py - cy)) / det;
    const l1 = ((cy - ay) * (px - cx) + (ax - cx) * (py - cy)) / det;
    const l2 = 1 - l0 - l1;
    if (l0 < -1e-9 || l1 < -1e-9 || l2 < -1e-9) continue;
    const d = l0 * depth[a] + l1 * depth[b] + l2 * depth[c];
    if (d < bestDepth) { bestDepth = d; best = t; bw = [l0, l1, l2]; }
  }
  if (best < 0) return null;
  const ids = [triangles[best], triangles[best + 1], triangles[best + 2]];
  let x = 0, y = 0;
  ids.forEach((i, j) => { x += bw[j] * nodes[3 * i]; y += bw[j] * nodes[3 * i + 1]; });
  return { tri: best / 3, x, y, ids, w: bw };
}

/** Strain components a whole-wing map can show, and the statistics over the run. */
export const MAP_COMPONENTS = ['eps_x', 'eps_y', 'gamma_xy', 'von_mises'];
export const MAP_STATS = ['rms', 'peak'];

/**
 * The von Mises equivalent of an in-plane strain state, the plane-stress von Mises formula
 * applied to the strain components (as the core's strainField):
 * ε_vm = √(ε_x² − ε_x ε_y + ε_y² + ¾ γ_xy²).
 */
export function vonMisesStrain(ex, ey, g) {
  return Math.sqrt(Math.max(0, ex * ex - ex * ey + ey * ey + 0.75 * g * g));
}

/**
 * A whole-wing strain map in JS (used only when the engine does not offer the core's
 * strainField): per node, the RMS or the peak |value| over the run of a component of
 * Σ_k ε_k(node) q_k(t). RMS is exact from the modal second-moment matrix C_kl = mean_t q_k q_l:
 * √(Σ_kl C_kl B(ε_k, ε_l)) per node, B the component's bilinear form (as the core's); a peak
 * uses at most `maxSamples` evenly spaced samples plus each mode's extremes (extremeStates), so
 * it may fall slightly below the core's, which visits every sample.
 * @param {ArrayLike<number>} strainNodes [(k·n + i)·3 + c]
 * @param {number} nNodes
 * @param {ArrayLike<number>[]} qs q_k(t) per mode
 * @param {{ component: string, stat: string }} opts
 * @returns {Float64Array}
 */
export function strainMapJs(strainNodes, nNodes, qs, { component, stat }, maxSamples = 2000) {
  const m = Math.min(qs.length, Math.floor(strainNodes.length / (3 * Math.max(1, nNodes))));
  const out = new Float64Array(nNodes);
  const c = { eps_x: 0, eps_y: 1, gamma_xy: 2 }[component];
  const nT = m ? qs[0].length : 0;
  if (!m || !nT) return out;
  if (stat === 'rms') {
    // mean square = Σ_kl C_kl B(ε_k, ε_l), B the component's bilinear form
    const C = new Float64Array(m * m);
    for (let k = 0; k < m; k++) {
      for (let l = k; l < m; l++) {
        let s = 0;
        const a = qs[k], b = qs[l];
        for (let t = 0; t < nT; t++) s += a[t] * b[t];
        C[k * m + l] = C[l * m + k] = s / nT;
      }
    }
    const B = c != null
      ? (/** @type {number} */ i, /** @type {number} */ j) => strainNodes[i + c] * strainNodes[j + c]
      : (/** @type {number} */ i, /** @type {number} */ j) => {
        const ax = strainNodes[i], ay = strainNodes[i + 1], ag = strainNodes[i + 2];
        const bx = strainNodes[j], by = strainNodes[j + 1], bg = strainNodes[j + 2];
        return ax * bx - 0.5 * (ax * by + ay * bx) + ay * by + 0.75 * ag * bg;
      };
    for (let i = 0; i < nNodes; i++) {
      let s = 0;
      for (let k = 0; k < m; k++) {
        for (let l = 0; l < m; l++) s += C[k * m + l] * B((k * nNodes + i) * 3, (l * nNodes + i) * 3);
      }
      out[i] = Math.sqrt(Math.max(0, s));
    }
    return out;
  }
  const states = extremeStates(qs, maxSamples);
  const e = new Float64Array(3);
  for (let i = 0; i < nNodes; i++) {
    let acc = 0;
    for (const q of states) {
      strainAt(strainNodes, nNodes, m, i, q, e);
      const ex = e[0], ey = e[1], g = e[2];
      const v = c === 0 ? ex : c === 1 ? ey : c === 2 ? g : vonMisesStrain(ex, ey, g);
      acc = Math.max(acc, Math.abs(v));
    }
    out[i] = acc;
  }
  return out;
}

/**
 * The colour limit of a whole-wing strain map: the RANGE_QUANTILE (90 %) quantile of |value|
 * over the nodes, as for the 3-D view's run-wide ranges (the clamped root's singular strains
 * would otherwise leave the rest of the wing in the map's neutral colour). The planform map and
 * the 3-D wing (WingView.setNodeField's limit) both use it, so their colours agree.
 * @param {ArrayLike<number>} field
 */
export function mapLimit(field) {
  return robust(field, RANGE_QUANTILE);
}

/** Labels of the strain-map choices (store `strain_map`), for selects and legends. */
export const MAP_LABELS = {
  eps_x: 'ε_x, spanwise strain',
  eps_y: 'ε_y, chordwise strain',
  gamma_xy: 'γ_xy, shear strain',
  von_mises: 'von Mises equivalent strain',
  rms: 'RMS over the run',
  peak: 'peak |value| over the run',
};
/** The strain map shown when the store has no choice yet. */
export const DEFAULT_MAP = Object.freeze({ component: 'von_mises', stat: 'rms' });

/** @type {{ fe: any, result: any, key: string, field: Float64Array } | null} */
let mapCache = null;

/** The cached strain map for exactly this wing, run and choice, else undefined (see strainMap). */
export function cachedStrainMap(fe, result, map) {
  const c = mapCache;
  return c && c.fe === fe && c.result === result && c.key === `${map.component}/${map.stat}` ? c.field : undefined;
}

/**
 * The whole-wing strain map of a run: per node of the FE wing `fe`, the RMS or peak of a strain
 * component of Σ_k ε_k q_k(t) over the run of `result`. Uses `strainField` (the core's, through
 * the engine) when given, else strainMapJs; the last map is cached (two views draw it).
 * Null when the wing and the run do not match (e.g. the paper mode set: its q are not the FE
 * wing's, so no physical map exists).
 * @param {any} fe FeModesResult (nodes, strain_nodes, n_modes)
 * @param {any} result LiveResult
 * @param {{ component: string, stat: string }} map
 * @param {((strainNodes: Float64Array, nModes: number, qs: Float64Array[], opts: { component: string, stat: string }) => Float64Array) | null} [strainField]
 * @returns {Float64Array | null}
 */
export function strainMap(fe, result, map, strainField = null) {
  if (!fe || !result || !fe.strain_nodes || !fe.strain_nodes.length) return null;
  const n = fe.nodes.length / 3;
  const qs = result.analysis.sim.modes.map((m) => m.q.total);
  const nModes = fe.strain_nodes.length / (3 * n);
  if (qs.length !== nModes) return null;
  const key = `${map.component}/${map.stat}`;
  if (mapCache && mapCache.fe === fe && mapCache.result === result && mapCache.key === key) return mapCache.field;
  /** @type {ArrayLike<number> | null} */
  let field = null;
  if (strainField) {
    try { field = strainField(fe.strain_nodes, nModes, qs, { component: map.component, stat: map.stat }); } catch { field = null; }
  }
  if (!field || field.length !== n) field = strainMapJs(fe.strain_nodes, n, qs, map);
  mapCache = { fe, result, key, field: Float64Array.from(field) };
  return mapCache.field;
}
