// @ts-check
// Pointer ↔ wing for the 3-D panel (pure, no DOM): which sample of the run is drawn at time t,
// the drawn wing's nodes on screen (the renderer's vertex transform through the camera mirror of
// www/scene3d.js), the planform point under a click (the strain point, mm), where a planform
// point is drawn now, and where the sensing panel's sensors are drawn. Unit-tested in
// tests/js/wing3d_picking.test.mjs.
import * as S from '../scene3d.js';

/**
 * The sample of a simulation drawn at time t (s): the nearest, clamped to the run.
 * @param {{ t: ArrayLike<number>, sample_rate_hz: number }} sim
 * @param {number} t
 */
export function sampleIndex(sim, t) {
  return Math.min(sim.t.length - 1, Math.max(0, Math.round(t * sim.sample_rate_hz)));
}

/**
 * The pose [α, β, γ] and the modal coordinates q_k at sample i of a run.
 * @param {any} result LiveResult with angles
 * @param {number} i
 */
export function poseAt(result, i) {
  const ang = [result.angles.alpha[i], result.angles.beta[i], result.angles.gamma[i]];
  const q = result.analysis.sim.modes.map((/** @type {any} */ m) => m.q.total[i]);
  return { ang, q };
}

/**
 * The drawn wing's nodes on screen at time t (CSS pixels of a w × h canvas): the pose, q and
 * S.projectNodes' { xy, depth }. Null before a run with angles or without a camera.
 * @param {any} fe FeModesResult (nodes, shapes)
 * @param {any} result LiveResult
 * @param {S.Camera | null} cam
 * @param {number} t
 * @param {number} exaggeration
 * @param {number} w
 * @param {number} h
 */
export function screenNodes(fe, result, cam, t, exaggeration, w, h) {
  if (!fe || !cam || !result || !result.angles) return null;
  const { ang, q } = poseAt(result, sampleIndex(result.analysis.sim, t));
  return { ang, q, proj: S.projectNodes(fe.nodes, fe.shapes, q, exaggeration, ang, cam, w, h) };
}

/**
 * The strain point (mm, rounded to µm) under the screen point (x, y): the undeformed planform
 * coordinates at the front-most drawn triangle there. Null off the wing.
 * @param {any} fe
 * @param {{ xy: ArrayLike<number>, depth: ArrayLike<number> }} proj
 * @param {number} x
 * @param {number} y
 * @returns {[number, number] | null}
 */
export function strainPointAt(fe, proj, x, y) {
  const hit = S.pick(fe.nodes, fe.triangles, proj, x, y);
  if (!hit) return null;
  return [Math.round(hit.x * 1e6) / 1e3, Math.round(hit.y * 1e6) / 1e3];
}

/**
 * The flat planform's triangle and barycentric weights at (x, y) mm, or null off the wing.
 * The returned function remembers its last answer (fixed per wing and point).
 */
export function planformHits() {
  /** @type {{ fe: any, key: string, hit: ReturnType<typeof S.pick> } | null} */
  let cache = null;
  return (/** @type {any} */ fe, /** @type {number} */ xmm, /** @type {number} */ ymm) => {
    const key = `${xmm}/${ymm}`;
    if (cache && cache.fe === fe && cache.key === key) return cache.hit;
    const n = fe.nodes.length / 3;
    const top = { xy: new Float64Array(2 * n), depth: new Float64Array(n) };
    for (let i = 0; i < n; i++) {
      top.xy[2 * i] = fe.nodes[3 * i];
      top.xy[2 * i + 1] = fe.nodes[3 * i + 1];
    }
    const hit = S.pick(fe.nodes, fe.triangles, top, xmm * 1e-3, ymm * 1e-3);
    cache = { fe, key, hit };
    return hit;
  };
}

/**
 * Where a planform hit is drawn: its barycentric weights applied to the drawn nodes' screen
 * positions. Null when not finite (behind the eye).
 * @param {{ ids: number[], w: number[] }} hit
 * @param {{ xy: ArrayLike<number> }} proj
 * @returns {number[] | null}
 */
export function drawnAt(hit, proj) {
  let px = 0,
    py = 0;
  hit.ids.forEach((i, j) => {
    px += hit.w[j] * proj.xy[2 * i];
    py += hit.w[j] * proj.xy[2 * i + 1];
  });
  return Number.isFinite(px) && Number.isFinite(py) ? [px, py] : null;
}

/**
 * The sensors' screen positions: each sensor is an FE node, deflected by ex · Σ_k φ_k q_k,
 * rotated to pose `ang` and projected with the camera mirror (NaN behind the eye).
 * @param {any} fe
 * @param {{ node: number, rank: number }[]} sensors
 * @param {number[]} ang
 * @param {ArrayLike<number>} q
 * @param {number} ex
 * @param {S.Camera} cam
 * @param {number} w
 * @param {number} h
 */
export function sensorPoints(fe, sensors, ang, q, ex, cam, w, h) {
  const pr = S.projector(cam, w, h);
  const { nodes, shapes } = fe;
  const n = nodes.length / 3;
  const nm = shapes ? Math.min(q.length, Math.floor(shapes.length / n)) : 0;
  return sensors.map((sn) => {
    const i = sn.node;
    let dz = 0;
    for (let k = 0; k < nm; k++) dz += shapes[k * n + i] * q[k];
    const p = S.rotate(ang[0], ang[1], ang[2], [nodes[3 * i], nodes[3 * i + 1], nodes[3 * i + 2] + ex * dz]);
    const sp = pr(p[0], p[1], p[2]);
    return { x: sp ? sp[0] : NaN, y: sp ? sp[1] : NaN, rank: sn.rank };
  });
}
