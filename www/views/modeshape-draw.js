// @ts-check
// The mode-shape viewer's drawing (views/modeshape.js): one mode of the FE wing on a 2-D canvas,
// seen obliquely with the renderer's camera mirror (www/scene3d.js), triangles painted back to
// front with two-sided diffuse shading, coloured by the out-of-plane displacement with the
// renderer's colour map, the flat outline dashed. The geometry (camera fitted to both extremes of
// the oscillation, drawing scale), the paint order and the shading are pure and unit-tested in
// tests/js/modeshape_draw.test.mjs.
import { fmt } from '../format.js';
import * as S from '../scene3d.js';
import { colourAt } from '../strainmap.js';

/** The largest drawn deflection, as a fraction of the span. */
export const DRAWN_FRACTION = 0.15;

/**
 * Pure: for mode k of `fe` drawn on a w × h (CSS px) canvas, the camera (the renderer's default
 * view turned to an oblique one, fitted so the wing at both extremes of the oscillation fits with
 * a margin, looking at the middle of their bounding box), the drawing scale (the largest |φ_k|
 * becomes DRAWN_FRACTION of the span) and that largest |φ_k|.
 * @param {{ nodes: ArrayLike<number>, shapes: ArrayLike<number> }} fe
 * @param {number} k
 * @param {number} w
 * @param {number} h
 * @returns {{ cam: S.Camera, scale: number, max: number }}
 */
export function modeGeometry(fe, k, w, h) {
  const n = fe.nodes.length / 3;
  const span = S.spanOf(fe.nodes);
  let max = 0;
  for (let i = 0; i < n; i++) max = Math.max(max, Math.abs(fe.shapes[k * n + i]));
  const scale = max > 0 ? (DRAWN_FRACTION * span) / max : 0;
  const base = S.defaultCamera(span);
  const cam = { ...base, yaw: -1.45, pitch: 0.62 };
  const pts = [];
  const stride = Math.max(1, Math.floor(n / 400));
  for (const sgn of [-1, 1]) {
    for (let i = 0; i < n; i += stride) {
      pts.push(fe.nodes[3 * i], fe.nodes[3 * i + 1], fe.nodes[3 * i + 2] + sgn * scale * fe.shapes[k * n + i]);
    }
  }
  const lo = [Infinity, Infinity, Infinity],
    hi = [-Infinity, -Infinity, -Infinity];
  for (let j = 0; j < pts.length; j += 3) {
    for (let c = 0; c < 3; c++) {
      lo[c] = Math.min(lo[c], pts[j + c]);
      hi[c] = Math.max(hi[c], pts[j + c]);
    }
  }
  cam.target = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])];
  cam.distance = S.fitDistance(cam, pts, w, h, 0.04);
  return { cam, scale, max };
}

/**
 * Pure: the triangles in painting order, farthest first (by the sum of their nodes' depths).
 * @param {ArrayLike<number>} tri node indices, three per triangle
 * @param {ArrayLike<number>} depth per node, larger = farther
 * @returns {Uint32Array}
 */
export function backToFront(tri, depth) {
  const nt = Math.floor(tri.length / 3);
  const order = new Uint32Array(nt);
  const d = new Float64Array(nt);
  for (let t = 0; t < nt; t++) {
    order[t] = t;
    d[t] = depth[tri[3 * t]] + depth[tri[3 * t + 1]] + depth[tri[3 * t + 2]];
  }
  order.sort((a, b) => d[b] - d[a]);
  return order;
}

/**
 * Pure: two-sided diffuse shading of the triangle (pa, pb, pc) lit from direction L (|L| = ll):
 * 0.6 + 0.4·|cos| of the angle between its normal and L, so 0.6 (edge-on) … 1 (facing).
 * @param {number[]} pa
 * @param {number[]} pb
 * @param {number[]} pc
 * @param {number[]} L
 * @param {number} ll
 */
export function shadeOf(pa, pb, pc, L, ll) {
  const u = [pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]],
    v = [pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]];
  const nn = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
  return 0.6 + 0.4 * Math.abs((nn[0] * L[0] + nn[1] * L[1] + nn[2] * L[2]) / ((Math.hypot(...nn) || 1) * ll));
}

/**
 * Paints mode k of `fe` at phase `deg` (degrees) on `c2` (CSS pixels, cssW × cssH): the shaded
 * triangles, the flat outline dashed, and the mode's name.
 * @param {CanvasRenderingContext2D} c2
 * @param {any} fe FeModesResult
 * @param {number} k
 * @param {{ cam: S.Camera, scale: number, max: number }} geom from modeGeometry
 * @param {number} deg
 * @param {ArrayLike<number> | null} stops the renderer's colour map (null: one sand colour)
 * @param {number} cssW
 * @param {number} cssH
 */
export function paintMode(c2, fe, k, geom, deg, stops, cssW, cssH) {
  c2.fillStyle = '#fafbfd';
  c2.fillRect(0, 0, cssW, cssH);
  const n = fe.nodes.length / 3;
  const amp = Math.sin((deg * Math.PI) / 180);
  const q = new Float64Array(fe.n_modes);
  q[k] = amp * geom.scale;
  const proj = S.projectNodes(fe.nodes, fe.shapes, q, 1, [0, 0, 0], geom.cam, cssW, cssH);
  const tri = fe.triangles;
  const max = geom.max || 1;
  // Two-sided diffuse shading from a light above and behind the viewer's right shoulder, so
  // bending and twist read as shape, not only as colour.
  const e = S.eye(geom.cam);
  const L = [
    e[0] - geom.cam.target[0] + 0.3 * S.spanOf(fe.nodes),
    e[1] - geom.cam.target[1],
    e[2] - geom.cam.target[2] + 0.5 * S.spanOf(fe.nodes),
  ];
  const ll = Math.hypot(...L);
  const P = (i) => [fe.nodes[3 * i], fe.nodes[3 * i + 1], fe.nodes[3 * i + 2] + q[k] * fe.shapes[k * n + i]];
  for (const t of backToFront(tri, proj.depth)) {
    const a = tri[3 * t],
      b = tri[3 * t + 1],
      c = tri[3 * t + 2];
    const w = (fe.shapes[k * n + a] + fe.shapes[k * n + b] + fe.shapes[k * n + c]) / 3;
    const rgb = stops ? colourAt(stops, 0.5 + (0.5 * (amp * w)) / max) : [200, 190, 160];
    const shade = shadeOf(P(a), P(b), P(c), L, ll);
    for (let j = 0; j < 3; j++) rgb[j] = Math.round(rgb[j] * shade);
    c2.fillStyle = `rgb(${rgb[0]},${rgb[1]},${rgb[2]})`;
    c2.strokeStyle = c2.fillStyle;
    c2.lineWidth = 0.7;
    c2.beginPath();
    c2.moveTo(proj.xy[2 * a], proj.xy[2 * a + 1]);
    c2.lineTo(proj.xy[2 * b], proj.xy[2 * b + 1]);
    c2.lineTo(proj.xy[2 * c], proj.xy[2 * c + 1]);
    c2.closePath();
    c2.fill();
    c2.stroke();
  }
  // The undeformed outline (root to tip), thin and dark, for reference.
  const ol = S.outline(fe.nodes);
  const pr = S.projector(geom.cam, cssW, cssH);
  c2.strokeStyle = 'rgba(40,40,40,0.55)';
  c2.setLineDash([3, 3]);
  c2.lineWidth = 1;
  c2.beginPath();
  const m = ol.nodes.length / 3;
  for (let j = 0; j <= m; j++) {
    const i = j % m;
    const p = pr(ol.nodes[3 * i], ol.nodes[3 * i + 1], 0);
    if (!p) continue;
    if (j === 0) c2.moveTo(p[0], p[1]);
    else c2.lineTo(p[0], p[1]);
  }
  c2.stroke();
  c2.setLineDash([]);
  c2.fillStyle = '#222';
  c2.font = '12px system-ui, sans-serif';
  c2.fillText(`mode ${k + 1}: ${fe.kinds[k] || ''}, ${fmt(fe.freq_hz[k], 4)} Hz`, 8, 16);
}
