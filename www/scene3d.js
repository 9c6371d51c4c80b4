// @ts-check
// Pure geometry of the 3-D view (no DOM, no wasm), unit-tested in tests/js/scene3d.test.mjs:
//
// * a mirror of the renderer's orbit camera (src/render/scene.rs OrbitCamera: target, yaw,
//   pitch, distance, 45° field of view, K up) and of the wing rotation R_x(α)·R_y(β)·R_z(γ), so
//   the page can place every pose of the run on screen and fit the camera to the whole stroke
//   using only the WingView API (orbit / zoom);
// * the drawn wing's nodes on screen and the triangle under a screen point (picking).
// The run-wide strain ranges, the largest deflection, the colour map and the whole-wing strain
// maps are in www/strainmap.js, the convex hull in www/hull.js; both are re-exported here, so
// the panels reach all of the 3-D maths as one namespace (`import * as S from '../scene3d.js'`).
import { hull2 } from './hull.js';

export * from './hull.js';
export * from './strainmap.js';

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
  return {
    ...cam,
    yaw: (cam.yaw - dx * ORBIT_RAD_PER_PX) % TAU,
    pitch: Math.min(PITCH_LIMIT, Math.max(-PITCH_LIMIT, cam.pitch + dy * ORBIT_RAD_PER_PX)),
  };
}

/** The camera after WingView.zoom(factor). */
export function zoom(cam, f) {
  if (!(Number.isFinite(f) && f > 0)) return cam;
  return { ...cam, distance: Math.min(1e3, Math.max(1e-3, cam.distance * f)) };
}

/** The camera after WingView.key(k); null when the renderer ignores the key. */
export function key(cam, k) {
  switch (k) {
    case 'ArrowLeft':
      return orbit(cam, -12, 0);
    case 'ArrowRight':
      return orbit(cam, 12, 0);
    case 'ArrowUp':
      return orbit(cam, 0, 12);
    case 'ArrowDown':
      return orbit(cam, 0, -12);
    case '+':
    case '=':
      return zoom(cam, 1 / 1.1);
    case '-':
    case '_':
      return zoom(cam, 1.1);
    default:
      return null;
  }
}

/**
 * The orbit (dx, dy in "pixels") and zoom factor that take camera `from` to `to` (same target).
 * Applying them with WingView.orbit / zoom reproduces `to` up to float32 rounding.
 */
export function moveTo(from, to) {
  return {
    dx: (from.yaw - to.yaw) / ORBIT_RAD_PER_PX,
    dy: (to.pitch - from.pitch) / ORBIT_RAD_PER_PX,
    zoom: to.distance / from.distance,
  };
}

export function eye(cam) {
  const cp = Math.cos(cam.pitch),
    sp = Math.sin(cam.pitch),
    cy = Math.cos(cam.yaw),
    sy = Math.sin(cam.yaw);
  const d = cam.distance,
    t = cam.target;
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
    const d0 = x - e[0],
      d1 = y - e[1],
      d2 = z - e[2];
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
  const cg = Math.cos(gamma),
    sg = Math.sin(gamma);
  const x1 = cg * x - sg * y,
    y1 = sg * x + cg * y,
    z1 = z;
  const cb = Math.cos(beta),
    sb = Math.sin(beta);
  const x2 = cb * x1 + sb * z1,
    y2 = y1,
    z2 = -sb * x1 + cb * z1;
  const ca = Math.cos(alpha),
    sa = Math.sin(alpha);
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
  const xs = new Float64Array(n),
    ys = new Float64Array(n);
  let zmax = 0;
  for (let i = 0; i < n; i++) {
    xs[i] = nodes[3 * i];
    ys[i] = nodes[3 * i + 1];
    zmax = Math.max(zmax, Math.abs(nodes[3 * i + 2]));
  }
  const h = hull2(xs, ys);
  const out = new Float64Array(3 * h.length);
  h.forEach((i, j) => {
    out[3 * j] = xs[i];
    out[3 * j + 1] = ys[i];
    out[3 * j + 2] = 0;
  });
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
  let x0 = Infinity,
    y0 = Infinity,
    x1 = -Infinity,
    y1 = -Infinity;
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
    return (
      b &&
      b[0] >= margin * width &&
      b[2] <= (1 - margin) * width &&
      b[1] >= margin * height &&
      b[3] <= (1 - margin) * height
    );
  };
  let lo = cam.distance * 0.05,
    hi = cam.distance;
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
    const a = triangles[t],
      b = triangles[t + 1],
      c = triangles[t + 2];
    const A =
      0.5 *
      Math.abs(
        (P[2 * b] - P[2 * a]) * (P[2 * c + 1] - P[2 * a + 1]) - (P[2 * c] - P[2 * a]) * (P[2 * b + 1] - P[2 * a + 1]),
      );
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
  const xy = new Float64Array(2 * n),
    depth = new Float64Array(n);
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
  let best = -1,
    bestDepth = Infinity,
    bw = [0, 0, 0];
  for (let t = 0; t + 2 < triangles.length; t += 3) {
    const a = triangles[t],
      b = triangles[t + 1],
      c = triangles[t + 2];
    const ax = xy[2 * a],
      ay = xy[2 * a + 1],
      bx = xy[2 * b],
      by = xy[2 * b + 1],
      cx = xy[2 * c],
      cy = xy[2 * c + 1];
    const det = (by - cy) * (ax - cx) + (cx - bx) * (ay - cy);
    if (!Number.isFinite(det) || Math.abs(det) < 1e-12) continue;
    const l0 = ((by - cy) * (px - cx) + (cx - bx) * (py - cy)) / det;
    const l1 = ((cy - ay) * (px - cx) + (ax - cx) * (py - cy)) / det;
    const l2 = 1 - l0 - l1;
    if (l0 < -1e-9 || l1 < -1e-9 || l2 < -1e-9) continue;
    const d = l0 * depth[a] + l1 * depth[b] + l2 * depth[c];
    if (d < bestDepth) {
      bestDepth = d;
      best = t;
      bw = [l0, l1, l2];
    }
  }
  if (best < 0) return null;
  const ids = [triangles[best], triangles[best + 1], triangles[best + 2]];
  let x = 0,
    y = 0;
  ids.forEach((i, j) => {
    x += bw[j] * nodes[3 * i];
    y += bw[j] * nodes[3 * i + 1];
  });
  return { tri: best / 3, x, y, ids, w: bw };
}
