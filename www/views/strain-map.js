// @ts-check
// The strain panel's whole-wing map (views/strain.js): for an FE wing, the planform coloured by
// the RMS or peak of a chosen strain component over the run (the store's `strain_map`), on which
// a click (or the arrow keys) chooses the strain point (the store's `strain_point`, mm; the engine
// then recomputes the modal strains there). Its box (component and statistic, canvas, legend,
// words), the drawing, the picking and the map's export. The 3-D view shows the same map
// (www/wing3d/fields.js uses strainFieldOf and PEAK_DELAY_MS from here).
import { el, rich } from '../dom.js';
import { fmt, errorText } from '../format.js';
import { toQuery } from '../state.js';
import {
  MAP_COMPONENTS,
  MAP_STATS,
  MAP_LABELS,
  DEFAULT_MAP,
  RANGE_QUANTILE,
  cachedStrainMap,
  strainMap,
  mapLimit,
  colourAt,
} from '../strainmap.js';
import { context2d } from '../export.js';
import { senseFe } from '../sensemap.js';
import { fitPlanform, fillPlanform, pickOnMap, pointOnWing, drawRing, watchWidth } from '../planform.js';

/**
 * A peak map visits every sample of every node (~0.5 s for 1650 nodes × 20 000 samples × 6
 * modes): computed this long after the last change, so moving a slider stays smooth (the
 * previous map stays drawn meanwhile). RMS maps take milliseconds and are computed at once.
 */
export const PEAK_DELAY_MS = 300;

/**
 * The engine's strainField (the core's, wasm, for the engine's current wing) when it has one,
 * as strainMap wants it; else null (the JS fallback is used). A map whose length is not the
 * wing's node count (the engine moved on to another wing) is discarded by strainMap.
 * @param {any} engine
 */
export function strainFieldOf(engine) {
  if (!engine || typeof engine.strainField !== 'function') return null;
  return (
    /** @type {Float64Array} */ _sn,
    /** @type {number} */ _n,
    /** @type {Float64Array[]} */ qs,
    /** @type {{ component: string, stat: string }} */ opts,
  ) => engine.strainField(qs, opts);
}

/**
 * The strain point in use, mm: the store's, else the FE wing's default (the one feModes used),
 * else (3, −6).
 * @param {any} s the store's state
 * @returns {number[]}
 */
export const strainPointOf = (s) => s.strain_point || (s.fe && s.fe.strain_point_mm) || [3, -6];

/**
 * The map's box: heading with the export buttons, component and statistic, canvas, legend row,
 * the strain point's words and the note.
 * @param {import('../lab.js').ViewContext} ctx
 * @param {boolean} touch
 */
function strainMapBox(ctx, touch) {
  const { uid } = ctx;
  const mapId = `${uid}-smap`;
  const comp = el('select', { id: `${uid}-smap-comp` });
  for (const c of MAP_COMPONENTS) comp.append(el('option', { value: c, text: MAP_LABELS[c] }));
  const stat = el('select', { id: `${uid}-smap-stat` });
  for (const c of MAP_STATS) stat.append(el('option', { value: c, text: MAP_LABELS[c] }));
  const canvas = el('canvas', {
    class: 'wl-smap-canvas',
    id: mapId,
    tabindex: '0',
    role: 'img',
    width: 600,
    height: 300,
    'aria-label': `Planform map of the wing coloured by the whole-run strain; ${touch ? 'tap' : 'click'} a point, or use the arrow keys here, to choose where the strain is plotted.`,
    'aria-describedby': `${mapId}-text`,
  });
  const legend = el('canvas', { class: 'wl-smap-legend', width: 240, height: 12, 'aria-hidden': 'true' });
  const legendText = el('span', { class: 'wl-smap-legend-text' });
  const pointText = el('p', { class: 'wl-smap-point', id: `${mapId}-text`, 'aria-live': 'polite' });
  const mapNote = el('p', { class: 'wl-note' });
  const row = (label, id, input) =>
    el('span', { class: 'wl-smap-field' }, el('label', { for: id, text: label }), input);
  const controls = el(
    'div',
    { class: 'wl-smap-controls' },
    row('component', comp.id, comp),
    row('statistic', stat.id, stat),
  );
  const box = el(
    'div',
    { class: 'wl-smap', 'data-smap': '' },
    el(
      'div',
      { class: 'wl-smap-head' },
      el('h3', { class: 'wl-smap-title', text: 'Whole-wing strain map' }),
      ctx.exportButtons('strainmap', 'Whole-wing strain map', ['csv', 'png']),
    ),
    controls,
    canvas,
    el('div', { class: 'wl-smap-legendrow' }, legend, legendText),
    pointText,
    mapNote,
  );
  return { box, comp, stat, controls, canvas, legend, legendText, pointText, mapNote };
}

/**
 * The legend bar: the part of the colour map in use (0…M: the upper half; ±M: all of it).
 * @param {HTMLCanvasElement} legend
 * @param {ArrayLike<number> | null} st the colour stops (WingView.colourMap)
 * @param {boolean} signed
 */
function drawLegendBar(legend, st, signed) {
  const lc = context2d(legend);
  lc.clearRect(0, 0, legend.width, legend.height);
  if (!st) return;
  for (let i = 0; i < legend.width; i++) {
    const f = i / (legend.width - 1);
    const rgb = colourAt(st, signed ? f : 0.5 + 0.5 * f);
    lc.fillStyle = `rgb(${rgb[0]},${rgb[1]},${rgb[2]})`;
    lc.fillRect(i, 0, 1, legend.height);
  }
}

/**
 * Builds the whole-wing map and registers its export ('strainmap'); `draw(force)` redraws it
 * (force: compute a peak map now, else it waits PEAK_DELAY_MS), `choose(x, y)` sets the strain
 * point (mm) if it lies on the wing.
 * @param {import('../lab.js').ViewContext} ctx
 * @param {boolean} touch
 */
export function strainMapView(ctx, touch) {
  const { store } = ctx;
  const ui = strainMapBox(ctx, touch);
  const { box, comp, stat, canvas, legend, legendText, pointText, mapNote } = ui;
  const setMap = () => store.set({ strain_map: /** @type {any} */ ({ component: comp.value, stat: stat.value }) });
  comp.addEventListener('change', setMap);
  stat.addEventListener('change', setMap);

  /** @type {{ x0: number, y1: number, k: number } | null} mm → CSS px of the last drawing */
  let frame = null;
  /** @type {Float64Array | null} */
  let field = null;
  let limit = 0;
  const mapOf = (s) => s.strain_map || DEFAULT_MAP;

  function stops() {
    const R = ctx.engine.renderer;
    const m = R ? R.colourMap() : null;
    return m && m.length ? m : null;
  }

  /** Shows why there is no map (the paper's mode set, or the FE wing's modes still to come). */
  function showNone(s) {
    canvas.hidden = true;
    legend.hidden = true;
    legendText.textContent = '';
    field = null;
    mapNote.replaceChildren(
      rich(
        s.modes === 'fe'
          ? 'The map appears once the FE wing’s modes are computed.'
          : 'The paper’s mode set gives strains only at the paper’s point P (Table 6), so there is no whole-wing map and the point is fixed: choose the FE wing mode set (or your own wing) to map the strain and to choose the point.',
      ),
    );
    pointText.textContent = s.modes === 'fe' ? '' : 'Strain point: the paper’s P (Table 6).';
  }

  /** @type {ReturnType<typeof setTimeout> | undefined} */
  let peakTimer;
  /** Draws the planform map; `force`: compute a peak map now (else it waits PEAK_DELAY_MS). */
  function draw(force = false) {
    const s = store.get();
    const fe = senseFe(s);
    const c2 = context2d(canvas);
    box.dataset.state = fe ? 'ready' : 'none';
    const map = mapOf(s);
    comp.value = map.component;
    stat.value = map.stat;
    ui.controls.hidden = !fe;
    if (!fe) return showNone(s);
    canvas.hidden = false;
    legend.hidden = false;
    let err = '';
    const cached = cachedStrainMap(fe, s.result, map);
    if (cached) field = cached;
    else if (map.stat === 'peak' && !force) {
      // keep the last map (if it is this wing's) and compute once the changes stop
      if (!field || field.length !== fe.nodes.length / 3) field = null;
      clearTimeout(peakTimer);
      peakTimer = setTimeout(() => draw(true), PEAK_DELAY_MS);
      box.dataset.pending = '1';
    } else {
      try {
        field = strainMap(fe, s.result, map, strainFieldOf(ctx.engine));
      } catch (e) {
        field = null;
        err = errorText(e);
      }
    }
    if (cached || force || map.stat !== 'peak') delete box.dataset.pending;
    // Size: the planform's aspect, the panel's width (device pixels for sharpness).
    const fit = fitPlanform(canvas, fe.nodes, 10);
    frame = fit.frame;
    const fr = fit.frame;
    const st = stops();
    limit = field ? mapLimit(field) : 0;
    const signed = !!field && field.some((v) => v < 0);
    const tOf = (v) => (limit > 0 ? 0.5 + 0.5 * Math.max(-1, Math.min(1, v / limit)) : 0.5);
    fillPlanform(c2, fe.nodes, fe.triangles, fit.frame, (a, b, c) => {
      const v = field ? (field[a] + field[b] + field[c]) / 3 : 0;
      return st ? colourAt(st, tOf(v)) : [200, 200, 200];
    });
    const [sx, sy] = strainPointOf(s);
    drawRing(c2, (sx - fr.x0) * fr.k, (fr.y1 - sy) * fr.k, 6, '#fff');
    canvas.dataset.point = `${sx},${sy}`;
    drawLegendBar(legend, st, signed);
    const what = `${MAP_LABELS[map.stat]} of ${MAP_LABELS[map.component]}`;
    legendText.textContent = field
      ? `${signed ? fmt(-limit, 3) : '0'} … ${fmt(limit, 3)} strain (–): ${what}; the hottest ${Math.round(100 * (1 - RANGE_QUANTILE))} % of the nodes saturate (largest ${fmt(Math.max(...field), 3)})`
      : box.dataset.pending
        ? 'computing the peak map…'
        : `no map: ${err || 'the wing and the run do not match'}`;
    canvas.dataset.limit = String(limit);
    mapNote.replaceChildren(
      rich(
        `Colours: ${what}, per node of the FE mesh (${fe.nodes.length / 3} nodes), from the modal strain fields and q_k(t) of all ${fe.n_modes} modes; the same colour map as the 3-D view (choose “whole-run strain map” there to see it on the flapping wing). Top view: span to the right, leading edge up.`,
      ),
    );
    pointText.textContent = `Strain point (x, y) = (${fmt(sx, 3)}, ${fmt(sy, 3)}) mm. ${touch ? 'Tap the map or the 3-D wing to move it.' : 'Click the map or the 3-D wing, or focus the map and use the arrow keys (Shift: bigger steps), to move it.'}`;
  }

  /** Sets the strain point if (x, y) mm lies on the wing; says so otherwise. */
  function choose(x, y) {
    const fe = senseFe(store.get());
    if (!fe) return false;
    const p = pointOnWing(fe, x, y, pointText);
    if (!p) return false;
    store.set({ strain_point: p });
    return true;
  }

  pickOnMap(
    canvas,
    () => frame,
    () => strainPointOf(store.get()),
    choose,
  );
  // The map itself: one row per node (planform position, mm, and the value), and the canvas.
  ctx.registerExport('strainmap', {
    csv: () => {
      const s = store.get();
      const fe = senseFe(s);
      if (!fe || !field || field.length !== fe.nodes.length / 3) return null;
      const n = field.length;
      const map = mapOf(s);
      return ctx.toCSV(
        [
          { name: 'x', unit: 'mm', values: Float64Array.from({ length: n }, (_, i) => fe.nodes[3 * i] * 1e3) },
          { name: 'y', unit: 'mm', values: Float64Array.from({ length: n }, (_, i) => fe.nodes[3 * i + 1] * 1e3) },
          { name: `${map.stat}_${map.component}`, unit: 'strain (-)', values: field },
        ],
        [
          `wingbeat lab; ${toQuery(s)}`,
          `whole-wing strain map: ${MAP_LABELS[map.stat]} of ${MAP_LABELS[map.component]}, per FE node (${n} nodes, all ${fe.n_modes} modes)`,
        ],
      );
    },
    canvas: () => (senseFe(store.get()) && field ? canvas : null),
  });
  const width = watchWidth(box, draw);
  return {
    box,
    draw,
    choose,
    get field() {
      return field;
    },
    destroy: () => {
      clearTimeout(peakTimer);
      width.disconnect();
    },
  };
}
