// @ts-check
// Strain panel (paper Fig. 9, and beyond it): ε_x, ε_y, γ_xy over time at the strain point,
// Σ_k ε_k q_k(t) over every mode; for an FE wing also a planform map of the whole wing coloured
// by the RMS or peak of a chosen strain component over the run (the store's `strain_map`), on
// which a click (or the arrow keys) chooses the strain point (the store's `strain_point`, mm;
// the engine then recomputes the modal strains there). The 3-D view can show the same map.
import { el, rich, isTouch } from '../dom.js';
import { fmt, PAPER_UNITS_NOTE, errorText } from '../format.js';
import { decimate } from '../decimate.js';
import { linePlot, color } from '../plot.js';
import { toQuery, describe } from '../state.js';
import * as S from '../scene3d.js';
import { context2d } from '../export.js';
import { fitPlanform, fillPlanform, pickOnMap } from '../planform.js';

export const title = 'Strain where you point (paper Fig. 9)';

/**
 * A peak map visits every sample of every node (~0.5 s for 1650 nodes × 20 000 samples × 6
 * modes): computed this long after the last change, so moving a slider stays smooth (the
 * previous map stays drawn meanwhile). RMS maps take milliseconds and are computed at once.
 */
export const PEAK_DELAY_MS = 300;

/**
 * The engine's strainField (the core's, wasm, for the engine's current wing) when it has one,
 * as S.strainMap wants it; else null (the JS fallback is used). A map whose length is not the
 * wing's node count (the engine moved on to another wing) is discarded by S.strainMap.
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

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, section, uid } = ctx;
  const touch = isTouch();
  const plot = linePlot(section, {
    name: 'strain',
    title: 'Strain at the strain point',
    ariaLabel: 'Strain plot: normal strains ε_x, ε_y and shear strain γ_xy at the strain point over time',
    xLabel: 't',
    xUnit: 's',
    yLabel: 'strain',
    series: [
      { label: 'ε_x', color: color('eps_x') },
      { label: 'ε_y', color: color('eps_y') },
      { label: 'γ_{xy}', color: color('gamma_xy') },
    ],
    height: 200,
  });
  const note = el('p', { class: 'wl-note' });
  section.append(note);

  // ---- the planform map ----
  const mapId = `${uid}-smap`;
  const comp = el('select', { id: `${uid}-smap-comp` });
  for (const c of S.MAP_COMPONENTS) comp.append(el('option', { value: c, text: S.MAP_LABELS[c] }));
  const stat = el('select', { id: `${uid}-smap-stat` });
  for (const c of S.MAP_STATS) stat.append(el('option', { value: c, text: S.MAP_LABELS[c] }));
  const setMap = () => store.set({ strain_map: /** @type {any} */ ({ component: comp.value, stat: stat.value }) });
  comp.addEventListener('change', setMap);
  stat.addEventListener('change', setMap);
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
  const mapControls = el(
    'div',
    { class: 'wl-smap-controls' },
    row('component', comp.id, comp),
    row('statistic', stat.id, stat),
  );
  const mapBox = el(
    'div',
    { class: 'wl-smap', 'data-smap': '' },
    el(
      'div',
      { class: 'wl-smap-head' },
      el('h3', { class: 'wl-smap-title', text: 'Whole-wing strain map' }),
      ctx.exportButtons('strainmap', 'Whole-wing strain map', ['csv', 'png']),
    ),
    mapControls,
    canvas,
    el('div', { class: 'wl-smap-legendrow' }, legend, legendText),
    pointText,
    mapNote,
  );
  section.append(mapBox);

  /** @type {{ x0: number, y1: number, k: number } | null} mm → CSS px of the last drawing */
  let frame = null;
  /** @type {Float64Array | null} */
  let field = null;
  let limit = 0;

  const unit = (s) => (s.modes === 'fe' ? 'strain (–)' : 'paper units');
  const mapOf = (s) => s.strain_map || S.DEFAULT_MAP;
  const feOf = (s) =>
    s.modes === 'fe' && s.fe && s.result && s.result.analysis.sim.modes.length === s.fe.n_modes ? s.fe : null;
  /** The point in use, mm: the store's, else the FE wing's default (the one feModes used). */
  const pointOf = (s) => s.strain_point || (s.fe && s.fe.strain_point_mm) || [3, -6];

  /** The planform's nodes in mm as { xy, depth } for S.pick (a flat top view). */
  const topView = (fe) => {
    const n = fe.nodes.length / 3;
    const xy = new Float64Array(2 * n);
    for (let i = 0; i < n; i++) {
      xy[2 * i] = fe.nodes[3 * i] * 1e3;
      xy[2 * i + 1] = fe.nodes[3 * i + 1] * 1e3;
    }
    return { xy, depth: new Float64Array(n) };
  };
  /** Whether (x, y) mm lies on the meshed wing. */
  const inside = (fe, x, y) => !!S.pick(fe.nodes, fe.triangles, topView(fe), x, y);

  function stops() {
    const R = ctx.engine.renderer;
    const m = R ? R.colourMap() : null;
    return m && m.length ? m : null;
  }

  /** @type {ReturnType<typeof setTimeout> | undefined} */
  let peakTimer;
  /** Draws the planform map; `force`: compute a peak map now (else it waits PEAK_DELAY_MS). */
  function drawMap(force = false) {
    const s = store.get();
    const fe = feOf(s);
    const c2 = context2d(canvas);
    mapBox.dataset.state = fe ? 'ready' : 'none';
    const map = mapOf(s);
    comp.value = map.component;
    stat.value = map.stat;
    mapControls.hidden = !fe;
    if (!fe) {
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
      return;
    }
    canvas.hidden = false;
    legend.hidden = false;
    let err = '';
    const cached = S.cachedStrainMap(fe, s.result, map);
    if (cached) field = cached;
    else if (map.stat === 'peak' && !force) {
      // keep the last map (if it is this wing's) and compute once the changes stop
      if (!field || field.length !== fe.nodes.length / 3) field = null;
      clearTimeout(peakTimer);
      peakTimer = setTimeout(() => drawMap(true), PEAK_DELAY_MS);
      mapBox.dataset.pending = '1';
    } else {
      try {
        field = S.strainMap(fe, s.result, map, strainFieldOf(ctx.engine));
      } catch (e) {
        field = null;
        err = errorText(e);
      }
    }
    if (cached || force || map.stat !== 'peak') delete mapBox.dataset.pending;
    // Size: the planform's aspect, the panel's width (device pixels for sharpness).
    const fit = fitPlanform(canvas, fe.nodes, 10);
    frame = fit.frame;
    const kk = fit.frame.k;
    const fr = fit.frame;
    const px = (x) => (x - fr.x0) * kk;
    const py = (y) => (fr.y1 - y) * kk;
    const st = stops();
    limit = field ? S.mapLimit(field) : 0;
    const signed = !!field && field.some((v) => v < 0);
    const tOf = (v) => (limit > 0 ? 0.5 + 0.5 * Math.max(-1, Math.min(1, v / limit)) : 0.5);
    fillPlanform(c2, fe.nodes, fe.triangles, fit.frame, (a, b, c) => {
      const v = field ? (field[a] + field[b] + field[c]) / 3 : 0;
      return st ? S.colourAt(st, tOf(v)) : [200, 200, 200];
    });
    // The strain point: a ring with a dark and a light edge (visible on every colour).
    const [sx, sy] = pointOf(s);
    const cx = px(sx),
      cy = py(sy);
    c2.lineWidth = 3;
    c2.strokeStyle = '#111';
    c2.beginPath();
    c2.arc(cx, cy, 6, 0, 2 * Math.PI);
    c2.stroke();
    c2.lineWidth = 1.5;
    c2.strokeStyle = '#fff';
    c2.beginPath();
    c2.arc(cx, cy, 6, 0, 2 * Math.PI);
    c2.stroke();
    canvas.dataset.point = `${sx},${sy}`;
    // Legend bar: the part of the map in use (0…M: the upper half; ±M: all of it).
    const lc = context2d(legend);
    lc.clearRect(0, 0, legend.width, legend.height);
    if (st) {
      for (let i = 0; i < legend.width; i++) {
        const f = i / (legend.width - 1);
        const rgb = S.colourAt(st, signed ? f : 0.5 + 0.5 * f);
        lc.fillStyle = `rgb(${rgb[0]},${rgb[1]},${rgb[2]})`;
        lc.fillRect(i, 0, 1, legend.height);
      }
    }
    const what = `${S.MAP_LABELS[map.stat]} of ${S.MAP_LABELS[map.component]}`;
    legendText.textContent = field
      ? `${signed ? fmt(-limit, 3) : '0'} … ${fmt(limit, 3)} strain (–): ${what}; the hottest ${Math.round(100 * (1 - S.RANGE_QUANTILE))} % of the nodes saturate (largest ${fmt(Math.max(...field), 3)})`
      : mapBox.dataset.pending
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
    const s = store.get();
    const fe = feOf(s);
    if (!fe) return false;
    if (!inside(fe, x, y)) {
      pointText.textContent = `(${fmt(x, 3)}, ${fmt(y, 3)}) mm is outside the wing: choose a point on the wing.`;
      return false;
    }
    const r = (v) => Math.round(v * 1000) / 1000;
    store.set({ strain_point: [r(x), r(y)] });
    return true;
  }

  pickOnMap(
    canvas,
    () => frame,
    () => pointOf(store.get()),
    choose,
  );

  const draw = (s) => {
    const r = s.result;
    if (!r) return;
    const a = r.analysis;
    const st = a.sim.strain;
    const [px, py] = pointOf(s);
    note.replaceChildren(
      rich(
        s.modes === 'fe'
          ? `Σ_k ε_k q_k(t) over all ${a.sim.modes.length} modes at the strain point (${fmt(px, 3)}, ${fmt(py, 3)}) mm, from the FE modal strain fields (top surface, dimensionless, SI).`
          : `Σ_k ε_k q_k(t) with the Table 6 modal strains at P (both modes). ${PAPER_UNITS_NOTE}`,
      ),
    );
    plot.setYLabel(s.modes === 'fe' ? 'strain (–)' : 'strain (paper units)');
    if (!st) {
      plot.setData([[0], [null], [null], [null]]);
      plot.setSummary('No strain at this point for this mode set.');
    } else {
      const w = plot.u.bbox ? plot.u.bbox.width / (globalThis.devicePixelRatio || 1) : 600;
      plot.setData(decimate(a.sim.t, [st.eps_x, st.eps_y, st.gamma_xy], Math.min(1500, Math.max(200, Math.round(w)))));
      // The core's run-wide peaks (Analysis.peaks.strain); a scan only for an analysis without them.
      const sp = a.peaks && a.peaks.strain;
      const pk = (/** @type {'eps_x' | 'eps_y' | 'gamma_xy'} */ c) => {
        if (sp) return sp[c];
        let p = 0;
        for (const v of st[c]) p = Math.max(p, Math.abs(v));
        return p;
      };
      plot.setSummary(
        `Peak |strain| at the strain point over the run (${unit(s)}): ε_x ${fmt(pk('eps_x'), 3)}, ε_y ${fmt(pk('eps_y'), 3)}, γ_xy ${fmt(pk('gamma_xy'), 3)}.`,
      );
    }
    drawMap();
  };
  const unsubs = [
    store.subscribe(['result'], draw),
    store.subscribe(['fe', 'strain_map', 'strain_point', 'modes'], () => drawMap()),
  ];
  /** @type {ResizeObserver | null} */
  let ro = null;
  if (typeof ResizeObserver === 'function') {
    let lastW = 0;
    ro = new ResizeObserver(() => {
      const w = mapBox.clientWidth;
      if (w && Math.abs(w - lastW) > 4) {
        lastW = w;
        drawMap();
      }
    });
    ro.observe(mapBox);
  }
  drawMap();
  ctx.registerPlot('strain', plot);
  ctx.registerExport('strain', {
    csv: () => {
      const s = store.get();
      const st = s.result && s.result.analysis.sim.strain;
      if (!st) return null;
      const a = s.result.analysis;
      return ctx.toCSV(
        [
          { name: 't', unit: 's', values: a.sim.t },
          { name: 'eps_x', unit: unit(s), values: st.eps_x },
          { name: 'eps_y', unit: unit(s), values: st.eps_y },
          { name: 'gamma_xy', unit: unit(s), values: st.gamma_xy },
        ],
        [
          `wingbeat lab; ${toQuery(s)}`,
          s.modes === 'fe'
            ? `strain at the strain point (x, y) = (${pointOf(s).join(', ')}) mm`
            : `strain at point ${st.point}`,
        ],
      );
    },
    figure: () => {
      const s = store.get();
      const st = s.result && s.result.analysis.sim.strain;
      if (!st) return null;
      return {
        title: 'Strain at the strain point (paper Fig. 9)',
        params: describe(s),
        x: s.result.analysis.sim.t,
        xRange: plot.xWindow(),
        xLabel: 't (s)',
        yLabel: s.modes === 'fe' ? 'strain (–)' : 'strain (paper units)',
        series: [
          { label: 'ε_x', color: color('eps_x'), y: st.eps_x, show: plot.u.series[1].show },
          { label: 'ε_y', color: color('eps_y'), y: st.eps_y, show: plot.u.series[2].show },
          { label: 'γ_{xy}', color: color('gamma_xy'), y: st.gamma_xy, show: plot.u.series[3].show },
        ],
        note: s.modes === 'paper' ? 'Paper units: Table 4/6 data are not SI.' : 'Dimensionless (SI).',
      };
    },
  });
  // The map itself: one row per node (planform position, mm, and the value), and the canvas.
  ctx.registerExport('strainmap', {
    csv: () => {
      const s = store.get();
      const fe = feOf(s);
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
          `whole-wing strain map: ${S.MAP_LABELS[map.stat]} of ${S.MAP_LABELS[map.component]}, per FE node (${n} nodes, all ${fe.n_modes} modes)`,
        ],
      );
    },
    canvas: () => (feOf(store.get()) && field ? canvas : null),
  });
  return {
    plot,
    get field() {
      return field;
    },
    choose,
    destroy: () => {
      for (const f of unsubs) f();
      clearTimeout(peakTimer);
      if (ro) ro.disconnect();
      plot.destroy();
    },
  };
}
