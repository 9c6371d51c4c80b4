// @ts-check
// Pure helpers of the sensing panel (www/views/sensing.js, issue 14): the body-rate slider's
// logarithmic scale, the detectability map's colour scale (decades below the largest D), the
// rotation-induced strain at any point from the modal series, and the performance-vs-K rows.
// No DOM; unit-tested in tests/js/sensemap.test.mjs.
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
  const v = Number(Math.pow(10, p).toPrecision(3));
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
    t: (v) => (Number.isFinite(v) && v > 0 && (!rel || max > 0) ? Math.min(1, Math.max(0, (Math.log10(v) - lo) / (hi - lo))) : 0),
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
    const e = modal[k], q = dq[k];
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
  const k = [], pd = [], share = [];
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
