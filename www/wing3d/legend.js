// @ts-check
// The 3-D panel's legends: the colour bar of the strain colours with its words (redrawn only
// when it changes), the words of the sensing panel's detectability colours (colour 6), and the
// list that names the renderer's scene lines. The words and the bar's gradient are pure
// functions (tests/js/wing3d_legend.test.mjs); createStrainLegend() draws them.
import { el, rich } from '../dom.js';
import { fmt } from '../format.js';
import { context2d } from '../export.js';
import { RANGE_QUANTILE } from '../strainmap.js';

// The renderer's scene decorations (src/render/gpu.rs scene_geometry), for the legend.
export const SCENE_LEGEND = [
  ['plane', 'Stroke plane (I–K plane through the root, ⟂ body axis)', 'rgba(115,140,217,0.35)', 'rgb(102,122,179)'],
  ['body', 'Body axis (along J)', 'rgb(217,217,217)'],
  ['fixed', 'Fixed frame I, J, K (dim red, green, blue)', 'rgb(140,64,64)', 'rgb(64,128,64)', 'rgb(64,77,153)'],
  [
    'wing',
    'Flapping frame I″, J″, K″ (bright red, green, blue)',
    'rgb(255,64,51)',
    'rgb(77,255,77)',
    'rgb(89,140,255)',
  ],
];

/** The list naming the stroke plane, the body axis and both frames, each with its colours. */
export function sceneLegendList() {
  const list = el('ul', { class: 'wl-w3-scene' });
  for (const [key, text, ...cols] of SCENE_LEGEND) {
    const sw = el('span', { class: 'wl-w3-sw', 'aria-hidden': 'true' });
    if (key === 'plane') sw.style.cssText = `background:${cols[0]};border:1px solid ${cols[1]}`;
    else
      sw.style.background =
        cols.length > 1 ? `linear-gradient(90deg, ${cols[0]} 33%, ${cols[1]} 33% 66%, ${cols[2]} 66%)` : cols[0];
    list.append(el('li', { 'data-scene': key }, sw, text));
  }
  return list;
}

/**
 * The colour bar's gradient from the renderer's stops [t, r, g, b, …] (WingView.legend_stops):
 * [offset 0…1, 'rgb(…)'] per stop, offsets scaled to the stops' own first … last t.
 * @param {ArrayLike<number>} stops
 * @returns {[number, string][]}
 */
export function gradientStops(stops) {
  const lo = stops[0],
    hi = stops[stops.length - 4];
  /** @type {[number, string][]} */
  const out = [];
  for (let j = 0; j < stops.length; j += 4) {
    const f = hi > lo ? (stops[j] - lo) / (hi - lo) : 0;
    const c = [1, 2, 3].map((k) => Math.round(255 * Math.min(1, Math.max(0, stops[j + k]))));
    out.push([Math.min(1, Math.max(0, f)), `rgb(${c[0]},${c[1]},${c[2]})`]);
  }
  return out;
}

/**
 * What the legend shows besides the frame's own range: the strain map's label and problem
 * (colour 5) and, for colour 6, the detectability map and why there is none.
 * @typedef {{ sensing: boolean, fieldProblem: string | null, fieldLabel: string, senseUp: any, senseProblem: string | null, senseStale: boolean }} LegendInfo
 */

/**
 * The words of the strain colours for the frame legend `lg` (WingView.set_frame's: component,
 * min, max), colours 1–5.
 * @param {{ component: string, min: number, max: number }} lg
 * @param {boolean} isFe
 * @param {string | null} fieldProblem
 * @param {string} fieldLabel
 */
export function strainLegendText(lg, isFe, fieldProblem, fieldLabel) {
  const units = isFe ? 'strain (–)' : '(FE strain × paper q: not physical)';
  return lg.component === 'field'
    ? fieldProblem
      ? `no strain map: ${fieldProblem}`
      : `${fieldLabel}: ${fmt(lg.min, 3)} … ${fmt(lg.max, 3)} strain (–), one map for the whole run (the hottest ${Math.round(100 * (1 - RANGE_QUANTILE))} % of the nodes saturate)`
    : `${lg.component}: ${fmt(lg.min, 3)} … ${fmt(lg.max, 3)} ${units}, fixed for the whole run`;
}

/**
 * The legend of colour 6 (rich text): what the colours and the numbered tags mean, and on which
 * scale, for the sensing panel's map `m` (store `sense_map`).
 * @param {any} m
 * @param {string | null} problem why there is no map
 * @param {boolean} stale the map is for other settings than the run drawn
 */
export function senseLegendText(m, problem, stale) {
  if (problem || !m) return `No detectability map: ${problem || 'no sensing result yet: open the Sensing panel'}.`;
  const axis = m.body_rate.findIndex((/** @type {number} */ v) => v !== 0);
  const rate = axis >= 0 ? `ω_b = ${fmt(m.body_rate[axis], 3)} rad/s about body axis ${'xyz'[axis]}` : 'ω_b = 0';
  if (!(m.max > 0))
    return `Rotation detectability D (Sensing panel, ${rate}): D = 0 everywhere, no rotation, nothing to detect.`;
  const scale =
    m.mode === 'absolute'
      ? `fixed log scale: grey = D ≤ 10^{${m.lo}}, dark red = D ≥ 10^{${m.hi}}; largest on this wing ${fmt(m.max, 3)}`
      : `log scale relative to this wing: grey = D ≤ ${fmt(10 ** m.lo, 3)} (${fmt(m.hi - m.lo, 2)} decade below the largest), dark red = the largest, ${fmt(m.max, 3)}`;
  return `Rotation detectability D per node from the Sensing panel (${rate}), ${scale}: the panel’s scale in this view’s colours (D = 1: the rotation’s strain as large as the 1 % stroke variation plus noise). Numbered tags: the ${m.sensors.length} best sensors (1 = chosen first) on the deflected wing, drawn on top even where the wing hides them.${stale ? ' This map is for earlier settings (kinematics or modes): the Sensing panel recomputes it when it is on screen.' : ''}`;
}

/**
 * The key that changes whenever the legend's drawing or words would.
 * @param {{ component: string, min: number, max: number }} lg
 * @param {boolean} isFe
 * @param {LegendInfo} info
 */
export function legendKey(lg, isFe, info) {
  const { sensing, senseUp: m } = info;
  return `${lg.component}/${lg.min}/${lg.max}/${isFe}/${info.fieldProblem}/${info.fieldLabel}/${sensing ? `${info.senseProblem}/${info.senseStale}/${m ? m.max : ''}/${m ? m.mode : ''}/${m ? m.sensors.length : ''}` : ''}`;
}

/**
 * The colour bar `bar` and its words `text`: draw(lg, isFe, stops, info) redraws only when
 * legendKey changes (it is fixed for a run while the wing plays); `stops` is called only then.
 * @param {HTMLCanvasElement} bar
 * @param {HTMLElement} text
 */
export function createStrainLegend(bar, text) {
  let shown = '';
  return (
    /** @type {any} */ lg,
    /** @type {boolean} */ isFe,
    /** @type {() => ArrayLike<number>} */ stops,
    /** @type {LegendInfo} */ info,
  ) => {
    const key = legendKey(lg, isFe, info);
    if (key === shown) return;
    shown = key;
    const c2 = context2d(bar);
    const { width: w, height: h } = bar;
    c2.clearRect(0, 0, w, h);
    const st = stops();
    if (!st.length || lg.component === 'none') {
      bar.hidden = true;
      text.textContent = 'plain shading';
      return;
    }
    bar.hidden = false;
    const g = c2.createLinearGradient(0, 0, w, 0);
    for (const [at, css] of gradientStops(st)) g.addColorStop(at, css);
    c2.fillStyle = g;
    c2.fillRect(0, 0, w, h);
    text.dataset.min = String(lg.min);
    text.dataset.max = String(lg.max);
    if (info.sensing) {
      text.replaceChildren(rich(senseLegendText(info.senseUp, info.senseProblem, info.senseStale)));
      return;
    }
    text.textContent = strainLegendText(lg, isFe, info.fieldProblem, info.fieldLabel);
  };
}
