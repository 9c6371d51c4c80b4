// @ts-check
// Pure maths of strain over a run (no DOM, no wasm), unit-tested in tests/js/scene3d.test.mjs:
//
// * the strain colour range of a run: per component, the robust (98th-percentile over nodes)
//   maximum over time of |Σ_k ε_k(node) q_k(t)|, fixed for the whole run so colours pulse with
//   the beat instead of being rescaled every frame;
// * the largest true deflection over the run;
// * the renderer's colour map sampled for 2-D drawings, and whole-wing strain maps (RMS or peak
//   over the run, the strain panel and the 3-D view's colour 5).
// Extremes over time use the convex hull of the modal trajectory (q_1(t), q_2(t)): a linear
// function of q — or a norm of one — takes its maximum over the run at a hull vertex, so the
// result is exact and costs (hull vertices × nodes), not (samples × nodes).
import { hull2 } from './hull.js';

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
    let lo = 0,
      hi = 0;
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
    let lo = 0,
      hi = 0;
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
  let ex = 0,
    ey = 0,
    g = 0;
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

/**
 * The states as one flat array, state-major (Q[s·m + k] = q_k of state s), first m modes.
 * @param {ArrayLike<number>[]} states @param {number} m
 */
function flatStates(states, m) {
  const Q = new Float64Array(states.length * m);
  states.forEach((q, s) => {
    for (let k = 0; k < m; k++) Q[s * m + k] = q[k];
  });
  return Q;
}

/**
 * strainRanges over given modal states (see extremeStates / statesAt). Per node its 3 × m
 * strain coefficients are read once and every state's strain follows from them (the states flat
 * in one typed array): the same sums as strainAt's, in the same order, so the same numbers, about
 * ten times faster than a strainAt call per node and state (which made this the page's longest
 * task for a 6-mode wing: ≈ 250 ms per run).
 */
export function strainRangesAt(strainNodes, nNodes, states, q = RANGE_QUANTILE) {
  const m0 = states.length ? states[0].length : 0;
  const m = Math.min(m0, Math.floor(strainNodes.length / (3 * nNodes)));
  const S = states.length;
  const Q = flatStates(states, m);
  const mx = [new Float64Array(nNodes), new Float64Array(nNodes), new Float64Array(nNodes), new Float64Array(nNodes)];
  const c = new Float64Array(3 * m);
  for (let i = 0; i < nNodes; i++) {
    for (let k = 0; k < m; k++) {
      const o = (k * nNodes + i) * 3;
      c[3 * k] = strainNodes[o];
      c[3 * k + 1] = strainNodes[o + 1];
      c[3 * k + 2] = strainNodes[o + 2];
    }
    let ax = 0,
      ay = 0,
      ag = 0,
      am2 = 0;
    for (let s = 0; s < S; s++) {
      let ex = 0,
        ey = 0,
        g = 0;
      const o = s * m;
      for (let k = 0; k < m; k++) {
        const qk = Q[o + k];
        ex += c[3 * k] * qk;
        ey += c[3 * k + 1] * qk;
        g += c[3 * k + 2] * qk;
      }
      const m2 = ex * ex + ey * ey + 0.5 * g * g;
      if (Math.abs(ex) > ax) ax = Math.abs(ex);
      if (Math.abs(ey) > ay) ay = Math.abs(ey);
      if (Math.abs(g) > ag) ag = Math.abs(g);
      if (m2 > am2) am2 = m2;
    }
    mx[0][i] = ax;
    mx[1][i] = ay;
    mx[2][i] = ag;
    mx[3][i] = Math.sqrt(am2);
  }
  return { 1: robust(mx[0], q), 2: robust(mx[1], q), 3: robust(mx[2], q), 4: robust(mx[3], q) };
}

/** The largest |Σ_k φ_k(node) q_k(t)| over nodes and the whole run (m, true scale). */
export function maxDeflection(shapes, nNodes, qs, maxSamples = 4000) {
  return maxDeflectionAt(shapes, nNodes, extremeStates(qs, maxSamples));
}

/** maxDeflection over given modal states (see extremeStates / statesAt); flat as strainRangesAt. */
export function maxDeflectionAt(shapes, nNodes, states) {
  const m = Math.min(states.length ? states[0].length : 0, Math.floor(shapes.length / nNodes));
  const S = states.length;
  const Q = flatStates(states, m);
  const phi = new Float64Array(m);
  let best = 0;
  for (let i = 0; i < nNodes; i++) {
    for (let k = 0; k < m; k++) phi[k] = shapes[k * nNodes + i];
    for (let s = 0; s < S; s++) {
      let w = 0;
      const o = s * m;
      for (let k = 0; k < m; k++) w += phi[k] * Q[o + k];
      if (Math.abs(w) > best) best = Math.abs(w);
    }
  }
  return best;
}

/**
 * The display numbers of a run on an FE wing: the colour limit per strain component
 * (strainRangesAt at RANGE_QUANTILE: { 1: ε_x, 2: ε_y, 3: γ_xy, 4: |ε| }) and the largest
 * deflection (maxDeflectionAt, m). Taken over the analysis's `extreme_samples` when the core
 * listed them (its hull vertices / extremes), else over extremeStates(qs, maxSamples).
 * @param {{ nodes: ArrayLike<number>, strain_nodes: ArrayLike<number>, shapes: ArrayLike<number> }} fe
 * @param {any} analysis the run's Analysis (sim.modes[k].q.total, optional extreme_samples)
 * @param {number} maxSamples
 */
export function runRanges(fe, analysis, maxSamples) {
  return rangesOfStates(fe, runStates(analysis, maxSamples));
}

/**
 * The modal states runRanges takes its numbers over, flat (Q[s·m + k]; S states of m modes): a
 * small message for the render worker, which holds the wing (www/render-worker.js).
 * @param {any} analysis
 * @param {number} maxSamples
 * @returns {{ Q: Float64Array, S: number, m: number }}
 */
export function runStates(analysis, maxSamples) {
  const qs = analysis.sim.modes.map((/** @type {any} */ m) => m.q.total);
  const states = analysis.extreme_samples ? statesAt(qs, analysis.extreme_samples) : extremeStates(qs, maxSamples);
  const m = qs.length;
  return { Q: flatStates(states, m), S: states.length, m };
}

/**
 * runRanges's numbers over flat states (runStates).
 * @param {{ nodes: ArrayLike<number>, strain_nodes: ArrayLike<number>, shapes: ArrayLike<number> }} fe
 * @param {{ Q: Float64Array, S: number, m: number }} st
 */
export function rangesOfStates(fe, st) {
  const n = fe.nodes.length / 3;
  const states = Array.from({ length: st.S }, (_, s) => st.Q.subarray(s * st.m, (s + 1) * st.m));
  return {
    ranges: strainRangesAt(fe.strain_nodes, n, states, RANGE_QUANTILE),
    deflection: maxDeflectionAt(fe.shapes, n, states),
  };
}

// ---------- colour map and whole-wing strain maps (mode viewer, strain panel, 3-D view) ----------

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
      const t0 = stops[4 * j],
        t1 = stops[4 * j + 4];
      if (x <= t1) {
        const f = t1 > t0 ? (x - t0) / (t1 - t0) : 0;
        const a = rgb(j),
          b = rgb(j + 1);
        out = [0, 1, 2].map((c) => a[c] + f * (b[c] - a[c]));
        break;
      }
    }
  }
  return out.map((v) => Math.round(255 * Math.min(1, Math.max(0, v))));
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
        const a = qs[k],
          b = qs[l];
        for (let t = 0; t < nT; t++) s += a[t] * b[t];
        C[k * m + l] = C[l * m + k] = s / nT;
      }
    }
    const B =
      c != null
        ? (/** @type {number} */ i, /** @type {number} */ j) => strainNodes[i + c] * strainNodes[j + c]
        : (/** @type {number} */ i, /** @type {number} */ j) => {
            const ax = strainNodes[i],
              ay = strainNodes[i + 1],
              ag = strainNodes[i + 2];
            const bx = strainNodes[j],
              by = strainNodes[j + 1],
              bg = strainNodes[j + 2];
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
      const ex = e[0],
        ey = e[1],
        g = e[2];
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
    try {
      field = strainField(fe.strain_nodes, nModes, qs, { component: map.component, stat: map.stat });
    } catch {
      field = null;
    }
  }
  if (!field || field.length !== n) field = strainMapJs(fe.strain_nodes, n, qs, map);
  mapCache = { fe, result, key, field: Float64Array.from(field) };
  return mapCache.field;
}
