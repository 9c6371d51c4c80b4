// @ts-check
// Pure helpers of the sensing panel (www/views/sensing.js, rotation sensing): the body-rate
// slider's logarithmic scale, the detectability map's colour scale (decades below the largest D),
// the rotation-induced strain at any point from the modal series, the performance-vs-K rows, and
// the panel's words and data built from a result (spectrum window, summaries, the map published
// for the 3-D view, the CSV columns). No DOM; unit-tested in tests/js/sensemap.test.mjs.
import { BODY_RATE } from './state.js';

/** The rate slider moves log10 |ω_b| (rad/s) over [min, max] in steps of `step`. */
export const RATE_SLIDER = Object.freeze({ min: -4, max: 2, step: 0.05 });

/**
 * The slider position (log10 |ω_b|) of a rate; a zero rate sits at the slider's left end.
 * @param {number} rate rad/s
 */
export function sliderOfRate(rate) {
  const a = Math.abs(Number(rate));
  if (!(a > 0) || !Number.isFinite(a)) return RATE_SLIDER.min;
  return Math.min(RATE_SLIDER.max, Math.max(RATE_SLIDER.min, Math.log10(a)));
}

/**
 * The rate (rad/s) of a slider position with the sign of `sign` (a rate; 0 or positive = +),
 * rounded to 3 significant digits and kept within the core's range (BODY_RATE).
 * @param {number} pos log10 |ω_b|
 * @param {number} [sign]
 */
export function rateOfSlider(pos, sign = 1) {
  const p = Math.min(RATE_SLIDER.max, Math.max(RATE_SLIDER.min, Number(pos)));
  const v = Number((10 ** p).toPrecision(3));
  const r = (Number(sign) < 0 ? -1 : 1) * v;
  return Math.min(BODY_RATE.max, Math.max(BODY_RATE.min, r));
}

/**
 * The detectability map's fixed colour scale: log10 D from MAP_LO to MAP_HI (D ≤ 10^MAP_LO is
 * the lowest colour, D ≥ 10^MAP_HI the highest). Fixed, not scaled to each map's largest value,
 * so a faster rotation visibly lights the wing up (D grows as ω_b²) and D = 1 (the rotation's
 * strain as large as the flapping variation plus noise) sits at the same colour on every map.
 */
export const MAP_LO = -6;
export const MAP_HI = 2;

/** Decades below the map's largest D that the relative scale shows. */
export const REL_DECADES = 1;

/**
 * The colour scale of a detectability map: `t(v)` is the position in [0, 1] of a value on a log
 * scale (0 for D at or below the scale's bottom, zero or not finite); `max` is the largest D (0
 * when no node has a positive D: a zero body rate). `mode` 'relative' (the default: where on
 * this wing rotation shows up best) spans REL_DECADES decades below `max`; 'absolute' is the
 * fixed scale MAP_LO … MAP_HI (how strongly: the same colour means the same D on every map).
 * @param {ArrayLike<number>} d
 * @param {'relative' | 'absolute'} [mode]
 */
export function mapScale(d, mode = 'relative') {
  let max = 0;
  for (let i = 0; i < d.length; i++) if (Number.isFinite(d[i]) && d[i] > max) max = d[i];
  const rel = mode !== 'absolute';
  const hi = rel ? (max > 0 ? Math.log10(max) : 0) : MAP_HI;
  const lo = rel ? hi - REL_DECADES : MAP_LO;
  return {
    max,
    lo,
    hi,
    mode: rel ? 'relative' : 'absolute',
    /** @param {number} v */
    t: (v) =>
      Number.isFinite(v) && v > 0 && (!rel || max > 0) ? Math.min(1, Math.max(0, (Math.log10(v) - lo) / (hi - lo))) : 0,
  };
}

/**
 * The rotation-induced strain at a point: Δε_c(t) = Σ_k ε_k,c Δq_k(t) for c = ε_x, ε_y, γ_xy,
 * from the point's modal strains (one { eps_x, eps_y, gamma_xy } per mode, e.g. wasm
 * modalStrainAt) and the modal series (senseRotation's `dq`). Exactly 0 where every Δq_k is 0.
 * @param {{ eps_x: number, eps_y: number, gamma_xy: number }[]} modal
 * @param {ArrayLike<number>[]} dq
 */
export function deltaAt(modal, dq) {
  const n = dq.length ? dq[0].length : 0;
  const out = { eps_x: new Float64Array(n), eps_y: new Float64Array(n), gamma_xy: new Float64Array(n) };
  const m = Math.min(modal.length, dq.length);
  for (let k = 0; k < m; k++) {
    const e = modal[k],
      q = dq[k];
    for (let i = 0; i < n; i++) {
      out.eps_x[i] += e.eps_x * q[i];
      out.eps_y[i] += e.eps_y * q[i];
      out.gamma_xy[i] += e.gamma_xy * q[i];
    }
  }
  return out;
}

/**
 * The performance-vs-K plot's data: K = 1 … n, the detection probability P_d and d′ as a share
 * of the all-sensor d′ (both in [0, 1]; the share is null when d′_all is 0).
 * @param {{ pd: ArrayLike<number>, d_prime: ArrayLike<number>, d_prime_all: number }} r
 * @returns {[number[], number[], (number | null)[]]}
 */
export function curveData(r) {
  const n = Math.min(r.pd.length, r.d_prime.length);
  const k = [],
    pd = [],
    share = [];
  for (let i = 0; i < n; i++) {
    k.push(i + 1);
    pd.push(r.pd[i]);
    share.push(r.d_prime_all > 0 ? Math.min(1, r.d_prime[i] / r.d_prime_all) : null);
  }
  return [k, pd, share];
}

/**
 * The smallest K (1-based) whose P_d reaches `p` (default 0.9), or null.
 * @param {ArrayLike<number>} pd
 * @param {number} [p]
 */
export function sensorsFor(pd, p = 0.9) {
  for (let i = 0; i < pd.length; i++) if (pd[i] >= p) return i + 1;
  return null;
}

/**
 * Groups sensor markers that would overlap on screen: each marker (screen px, in rank order)
 * joins the first group whose first marker lies within `radius` px, else starts a new group.
 * Returns the groups with their first marker's position and their ranks in order, so a label
 * such as "1,2,4" can stand for sensors that sit a fraction of a millimetre apart.
 * @param {{ x: number, y: number, rank: number }[]} markers
 * @param {number} radius
 * @returns {{ x: number, y: number, ranks: number[] }[]}
 */
export function clusterMarkers(markers, radius) {
  /** @type {{ x: number, y: number, ranks: number[] }[]} */
  const groups = [];
  for (const m of markers) {
    const g = groups.find((q) => Math.hypot(q.x - m.x, q.y - m.y) < radius);
    if (g) g.ranks.push(m.rank);
    else groups.push({ x: m.x, y: m.y, ranks: [m.rank] });
  }
  return groups;
}

/**
 * A group's label: the ranks joined by commas, at most `max` of them, then "+n".
 * @param {number[]} ranks
 * @param {number} [max]
 */
export function groupLabel(ranks, max = 4) {
  const shown = ranks.slice(0, max).join(',');
  return ranks.length > max ? `${shown} +${ranks.length - max}` : shown;
}

/** How the panel names a strain component. */
export const COMP_LABEL = Object.freeze({ eps_x: 'ε_x', eps_y: 'ε_y', gamma_xy: 'γ_xy' });

/**
 * The rate field's complaint about a typed value, or null when it is a rate the core accepts.
 * @param {string} text
 */
export function rateError(text) {
  const v = Number(text);
  if (text.trim() === '' || !Number.isFinite(v) || v < BODY_RATE.min || v > BODY_RATE.max)
    return `ω_b must be a number in [${BODY_RATE.min}, ${BODY_RATE.max}] rad/s.`;
  return null;
}

/**
 * The FE wing the sensing analysis can use, and the one the strain panel's map is drawn for
 * (views/strain-map.js): the store's `fe` when the FE mode set is chosen and the live result was
 * computed with that wing's modes; else null.
 * @param {any} s store state
 */
export const senseFe = (s) =>
  s.modes === 'fe' && s.fe && s.result && s.result.analysis.sim.modes.length === s.fe.n_modes ? s.fe : null;

/**
 * Largest |v| of a series (0 for an empty one).
 * @param {ArrayLike<number>} y
 */
export function peakAbs(y) {
  let m = 0;
  for (let i = 0; i < y.length; i++) m = Math.max(m, Math.abs(y[i]));
  return m;
}

/**
 * The spectrum plot's window: the bins up to min(Nyquist, 10 f_d) and a marker at every multiple
 * of the flap frequency f_d inside it.
 * @param {{ flap_freq_hz: number, sample_rate_hz: number }} r
 * @param {ArrayLike<number>} freq bin frequencies, Hz, ascending
 */
export function spectrumWindow(r, freq) {
  const fd = r.flap_freq_hz;
  const fmax = Math.min(r.sample_rate_hz / 2, 10 * fd);
  let n = 0;
  while (n < freq.length && freq[n] <= fmax) n++;
  const marks = [];
  for (let j = 1; j * fd <= fmax; j++) marks.push({ x: j * fd, label: `${j}f_d`, color: '#8a8a8a' });
  return { fmax, n, marks };
}

/**
 * The detection curve's summary at K sensors.
 * @param {{ pd: ArrayLike<number>, d_prime: ArrayLike<number>, d_prime_all: number, pd_all: number, n_nodes: number, k_for_90_percent?: number | null }} r
 * @param {number} K
 * @param {(v: number, digits: number) => string} fmt number formatter
 */
export function curveSummary(r, K, fmt) {
  if (!(r.d_prime_all > 0))
    return 'With no body rotation there is nothing to detect: P_d is the false-alarm rate (1 %) at every K.';
  const k90 = sensorsFor(r.pd);
  const atK = K ? r.pd[K - 1] : 0;
  return `With K = ${K} sensors, P_d = ${fmt(atK, 3)} (d′ = ${fmt(r.d_prime[K - 1], 3)}); all ${3 * r.n_nodes} candidates together: d′ = ${fmt(r.d_prime_all, 3)}, P_d = ${fmt(r.pd_all, 3)}. ${k90 ? `P_d ≥ 0.9 from K = ${k90}.` : 'P_d stays below 0.9 up to K = ' + r.pd.length + '.'} ${r.k_for_90_percent ? `90 % of the all-sensor d′ needs K = ${r.k_for_90_percent}.` : ''} A lower rate (or more noise) makes detection harder: try 0.001 rad/s.`;
}

/**
 * The legend's words for a map scale (rich text: 10^{n} is a power).
 * @param {ReturnType<typeof mapScale>} scale
 * @param {(v: number, digits: number) => string} fmt
 * @returns {string[]} the scale's sentence, then (for a non-zero map) the note on the sensors
 */
export function legendWords(scale, fmt) {
  if (!(scale.max > 0)) return ['D = 0 everywhere: no rotation, so nothing to detect'];
  return [
    scale.mode === 'absolute'
      ? `detectability D, log scale from 10^{${MAP_LO}} (and below) to 10^{${MAP_HI}} (and above); largest on this wing ${fmt(scale.max, 3)}. D = 1: the rotation’s strain as large as the flapping variation plus noise.`
      : `detectability D, log scale from ${fmt(10 ** scale.lo, 3)} (and below) to ${fmt(scale.max, 3)}, the largest on this wing (brightest: where rotation shows up best). D = 1: the rotation’s strain as large as the flapping variation plus noise.`,
    ' The colours rate each point alone, by energy; the numbered sensors are chosen by how well their time series tell a rotation from a slightly different stroke, which favours points whose Δε has a different time course from the flapping strain, not only the brightest ones.',
  ];
}

/**
 * What the sensing panel publishes in the store (`sense_map`) for the 3-D view's colour "rotation
 * detectability": the map's colour position per node (`field`, 0…1: log10 D on the panel's
 * colour scale, `mode` relative | absolute, from 10^lo to 10^hi; `max` the largest D), the first
 * K sensors (`label` their rank as text), the FE wing it was computed for, the body rate (rad/s,
 * body axes), the run configuration as JSON (`cfg_json`: kinematics and modes of the two runs) and
 * `show`, a count the button "Show on the 3-D wing" raises.
 * @typedef {{ fe: import('./engine.js').FeModesResult, n_nodes: number, field: Float64Array,
 *   mode: 'relative' | 'absolute', lo: number, hi: number, max: number, body_rate: number[], cfg_json: string,
 *   sensors: { rank: number, node: number, component: string, x_mm: number, y_mm: number, label: string }[],
 *   show: number }} SenseMap
 */

/**
 * The SenseMap of a result on its wing with the first K sensors.
 * @param {any} fe the FE wing (n_nodes)
 * @param {{ d_best: ArrayLike<number>, body_rate: ArrayLike<number>, sensors: { rank: number, node: number, component: string, x_mm: number, y_mm: number }[] }} result
 * @param {ReturnType<typeof mapScale>} scale
 * @param {number} K
 * @param {string} cfgJson
 * @param {number} show
 * @returns {SenseMap}
 */
export function senseMapOf(fe, result, scale, K, cfgJson, show) {
  const n = fe.n_nodes;
  const field = new Float64Array(n);
  for (let i = 0; i < n && i < result.d_best.length; i++) field[i] = scale.t(result.d_best[i]);
  return {
    fe,
    n_nodes: n,
    field,
    mode: /** @type {'relative' | 'absolute'} */ (scale.mode),
    lo: scale.lo,
    hi: scale.hi,
    max: scale.max,
    body_rate: Array.from(result.body_rate),
    cfg_json: cfgJson,
    sensors: result.sensors.slice(0, K).map((sn) => ({
      rank: sn.rank,
      node: sn.node,
      component: sn.component,
      x_mm: sn.x_mm,
      y_mm: sn.y_mm,
      label: String(sn.rank),
    })),
    show,
  };
}

/**
 * The sensing map's CSV columns: node position (mm), D per component and the best, and the rank
 * at which the greedy placement first chose the node (0 = not chosen).
 * @param {{ nodes: ArrayLike<number> }} fe
 * @param {{ n_nodes: number, d: ArrayLike<number>, d_best: ArrayLike<number>, sensors: { node: number, rank: number }[] }} result
 */
export function senseCsvColumns(fe, result) {
  const n = result.n_nodes;
  const col = (c) => Float64Array.from({ length: n }, (_, i) => result.d[3 * i + c]);
  const rank = new Float64Array(n);
  result.sensors.forEach((sn) => {
    if (!rank[sn.node]) rank[sn.node] = sn.rank;
  });
  return [
    { name: 'x', unit: 'mm', values: Float64Array.from({ length: n }, (_, i) => fe.nodes[3 * i] * 1e3) },
    { name: 'y', unit: 'mm', values: Float64Array.from({ length: n }, (_, i) => fe.nodes[3 * i + 1] * 1e3) },
    { name: 'D_eps_x', unit: '-', values: col(0) },
    { name: 'D_eps_y', unit: '-', values: col(1) },
    { name: 'D_gamma_xy', unit: '-', values: col(2) },
    { name: 'D_best', unit: '-', values: result.d_best },
    { name: 'sensor_rank', unit: '0 = not chosen', values: rank },
  ];
}
