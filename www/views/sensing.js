// @ts-check
// Sensing body rotation (docs/sensing.md): the FE wing flaps while the body turns at a constant
// rate ω_b about one body axis. The worker job `sense` (wasm senseRotation) runs the model with
// and without ω_b; the difference Δε(x, t) is the strain the rotation causes. This panel shows
// the planform coloured by the detectability D = E_Δ / (ρ² E_F + σ²) per node (log scale), the K
// best sensors of the greedy placement as numbered markers, Δε(t) and its spectrum at a picked
// point (click, tap or the arrow keys on the map) and the detection probability against the
// number of sensors K. Reads the store (result, fe, body_rate, body_axis, modes); writes only
// body_rate / body_axis (and modes when asked to switch), and `sense_map` for the 3-D view.
// This file wires the panel and draws the map; its pieces: the analysis job (sensing-job.js),
// the controls (sensing-controls.js), the plots (sensing-plots.js), the map's markers and legend
// (sensing-map.js), and the pure words and data (www/sensemap.js).
import { WWW } from '../base.js';
import { el, rich, isTouch } from '../dom.js';
import { fmt } from '../format.js';
import { viridis } from '../plot.js';
import { toQuery } from '../state.js';
import { mapScale, deltaAt, senseFe, legendWords, senseMapOf, senseCsvColumns, COMP_LABEL } from '../sensemap.js';
import { fitPlanform, fillPlanform, pickOnMap, pointOnWing, drawRing, watchWidth } from '../planform.js';
import { experimentQuery } from '../experiments.js';
import { sensingControls } from './sensing-controls.js';
import { sensingPlots } from './sensing-plots.js';
import { sensingMapBox, drawSensorMarkers, drawViridisLegend } from './sensing-map.js';
import { senseJob } from './sensing-job.js';

export const title = 'Sensing body rotation';

/** @typedef {import('../sensemap.js').SenseMap} SenseMap */

/**
 * The panel's introduction and the link to its guided experiment (a shareable link; a plain
 * click applies it here — FE wing, exp=sensing — instead of leaving the page).
 * @param {import('../lab.js').ViewContext} ctx
 */
function intro(ctx) {
  ctx.section.append(
    el('p', {
      class: 'wl-note',
      rich: 'When the body turns while the wings flap, the Coriolis and centrifugal forces change and the wing bends and twists a little differently. Here the FE wing is simulated twice, with and without a constant body rotation; the difference Δε is the strain the rotation causes. The map shows where Δε stands out best against the flapping strain (1 % stroke-to-stroke variation) and sensor noise (σ = 10^{-7}), and where K strain sensors detect the rotation best.',
    }),
  );
  const expLink = el('a', {
    class: 'wl-sense-exp',
    href: new URL(`index.html?${experimentQuery('sensing', { panels: 'controls,experiments,sensing' })}`, WWW).href,
    text: 'Guided experiment: how many sensors does it take?',
  });
  expLink.addEventListener('click', (ev) => {
    if (ev.button !== 0 || ev.ctrlKey || ev.metaKey || ev.shiftKey || ev.altKey) return;
    ev.preventDefault();
    ctx.setParams({ exp: 'sensing', modes: 'fe' });
  });
  ctx.section.append(el('p', { class: 'wl-note' }, expLink));
}

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, section, engine } = ctx;
  const touch = isTouch();
  intro(ctx);
  const ui = sensingControls(ctx, {
    onK: () => {
      drawMap();
      drawCurve();
    },
    onScale: () => drawMap(),
    onCancel: () => job.cancel(),
  });
  const { status, needFe } = ui;
  const map = sensingMapBox(ctx, touch);
  const { canvas, legend, legendText, pointText, show3d, sensorList } = map;
  const mapBox = map.box;
  let showCount = 0;
  show3d.addEventListener('click', () => {
    const s = store.get();
    if (!s.panels.includes('wing3d')) ctx.setParams({ panels: [...s.panels, 'wing3d'] });
    showCount += 1;
    drawMap();
  });
  const body = el('div', { class: 'wl-sense-body' }, ui.controls, ui.rateHelp, ui.statusRow, mapBox);
  section.append(needFe, body);
  const plots = sensingPlots(body);

  /** @type {[number, number] | null} the picked point (mm); null = the best sensor */
  let point = null;
  let visible = typeof IntersectionObserver !== 'function';
  /** @type {{ x0: number, y1: number, k: number } | null} */
  let frame = null;
  let drawn = 0;
  /** The wing and mode set the map was last drawn for. */
  let lastFe = null,
    lastModes = '';
  const job = senseJob(ctx, ui, mapBox, { point: () => point, visible: () => visible, onResult: () => drawAll() });
  const schedule = job.schedule;
  const stale = job.stale;

  function drawAll() {
    drawMap();
    drawSeries();
    drawCurve();
  }

  /** The K shown (the slider, at most the sensors there are). */
  const kNow = () => Math.min(ui.k(), job.result ? job.result.sensors.length : 0);

  function drawMap() {
    const s = store.get();
    const result = job.result;
    const fe = senseFe(s);
    needFe.hidden = !!(s.modes === 'fe');
    body.hidden = s.modes !== 'fe';
    if (s.modes !== 'fe') {
      mapBox.dataset.state = 'none';
      return;
    }
    if (!fe) {
      mapBox.dataset.state = 'none';
      status.textContent = 'Waiting for the FE wing’s modes…';
      canvas.hidden = true;
      return;
    }
    canvas.hidden = false;
    const have = result && !stale() && result.n_nodes === fe.n_nodes;
    if (have && !job.running) mapBox.dataset.state = 'ready';
    const fit = fitPlanform(canvas, fe.nodes, 14);
    const { c2 } = fit;
    frame = fit.frame;
    const f = fit.frame;
    const px = (x) => (x - f.x0) * f.k;
    const py = (y) => (f.y1 - y) * f.k;
    const scale = have ? mapScale(result.d_best, ui.scaleMode()) : null;
    fillPlanform(c2, fe.nodes, fe.triangles, f, (a, b, c) => {
      if (scale && scale.max > 0) return viridis(scale.t((result.d_best[a] + result.d_best[b] + result.d_best[c]) / 3));
      return scale ? viridis(0) : [215, 215, 215];
    });
    const K = have ? kNow() : 0;
    const marks =
      result && have ? result.sensors.slice(0, K).map((sn) => ({ x: px(sn.x_mm), y: py(sn.y_mm), rank: sn.rank })) : [];
    const groups = drawSensorMarkers(c2, marks);
    canvas.dataset.markers = JSON.stringify(groups.map((g) => g.ranks));
    const p = point || (have ? result.point_mm : null);
    if (p) {
      drawRing(c2, px(p[0]), py(p[1]), 11, '#ff3d7f');
      canvas.dataset.point = `${p[0]},${p[1]}`;
    }
    drawViridisLegend(legend);
    if (!have) {
      legendText.textContent = job.running ? 'computing…' : '';
    } else if (scale && scale.max > 0) {
      const [words, note] = legendWords(scale, fmt);
      legendText.replaceChildren(rich(words));
      legendText.append(rich(note));
    } else {
      legendText.textContent = legendWords(mapScale([]), fmt)[0];
    }
    canvas.dataset.maxD = scale ? String(scale.max) : '';
    show3d.disabled = !(have && scale);
    if (have && scale) publish(fe, scale, K);
    canvas.dataset.drawn = String(++drawn);
    // the sensors as text
    sensorList.replaceChildren(
      ...(have
        ? result.sensors.slice(0, K).map((sn) =>
            el('li', {
              text: `node ${sn.node}, ${COMP_LABEL[sn.component] || sn.component} at (${fmt(sn.x_mm, 3)}, ${fmt(sn.y_mm, 3)}) mm, D = ${fmt(sn.d, 3)}`,
            }),
          )
        : []),
    );
    if (p) {
      const src = point ? 'the picked point' : 'the best sensor (default)';
      pointText.textContent = `Δε is plotted at ${src}, (x, y) = (${fmt(p[0], 3)}, ${fmt(p[1], 3)}) mm. ${touch ? 'Tap the map to move it.' : 'Click the map, or focus it and use the arrow keys (Shift: bigger steps), to move it.'}`;
    }
  }

  /** @type {{ result: any, k: number, mode: string, show: number } | null} what was last published */
  let published = null;
  /** Puts the map (colour positions per node) and the first K sensors in the store for the 3-D view. */
  function publish(/** @type {any} */ fe, /** @type {ReturnType<typeof mapScale>} */ scale, /** @type {number} */ K) {
    if (
      published &&
      published.result === job.result &&
      published.k === K &&
      published.mode === scale.mode &&
      published.show === showCount
    )
      return;
    const result = job.result;
    published = { result, k: K, mode: scale.mode, show: showCount };
    store.set({ sense_map: senseMapOf(fe, result, scale, K, job.cfg, showCount) });
  }

  /** The series at the point in use: the wasm result's, or (picked since) formed from dq. */
  function seriesNow() {
    const result = job.result;
    if (!result) return null;
    if (!point) return { delta: result.delta, spectrum: result.spectrum };
    const same = result.point_source === 'opts' && result.point_mm[0] === point[0] && result.point_mm[1] === point[1];
    if (same) return { delta: result.delta, spectrum: result.spectrum };
    try {
      return { delta: deltaAt(engine.modalStrainAt(point), result.dq), spectrum: null };
    } catch {
      return null;
    }
  }

  function drawSeries() {
    if (!job.result || stale()) return;
    const sr = seriesNow();
    if (!sr) return;
    mapBox.dataset.deltaPeak = String(plots.showSeries(job.result, sr));
  }

  function drawCurve() {
    if (!job.result || stale()) return;
    plots.showCurve(job.result, kNow());
  }

  /** Picks (x, y) mm if it lies on the wing. */
  function choose(x, y) {
    const fe = senseFe(store.get());
    if (!fe) return false;
    const p = pointOnWing(fe, x, y, pointText);
    if (!p) return false;
    point = p;
    drawMap();
    drawSeries();
    schedule();
    return true;
  }
  pickOnMap(
    canvas,
    () => frame,
    () => point || (job.result ? job.result.point_mm : null),
    choose,
  );

  const unsubs = [
    store.subscribe(['body_rate', 'body_axis'], () => {
      ui.sync();
      schedule();
    }),
    store.subscribe(['result', 'fe', 'modes'], () => {
      // a new live result alone (a slider moved) only asks for a new analysis; the map is
      // redrawn when that arrives, or now when the wing or the mode set changed
      const s = store.get();
      const fe = senseFe(s);
      if (job.forOtherWing(fe)) point = null;
      if (fe !== lastFe || s.modes !== lastModes) {
        lastFe = fe;
        lastModes = s.modes;
        drawMap();
      }
      schedule();
    }),
  ];
  const observers = watchVisibleAndSize(
    section,
    mapBox,
    (v) => {
      const was = visible;
      visible = v;
      if (visible && !was) schedule();
    },
    drawMap,
  );
  ui.sync();
  drawMap();
  schedule();

  ctx.registerPlot('sensing-series', plots.seriesPlot);
  ctx.registerPlot('sensing-spectrum', plots.specPlot);
  ctx.registerPlot('sensing-curve', plots.curvePlot);
  ctx.registerExport('sensing', {
    csv: () => {
      const s = store.get();
      const fe = senseFe(s);
      const result = job.result;
      if (!fe || !result || stale()) return null;
      return ctx.toCSV(senseCsvColumns(fe, result), [
        `wingbeat lab; ${toQuery(s)}`,
        `detectability per FE node, body rate [${result.body_rate.join(', ')}] rad/s (body axes); ${result.method}`,
      ]);
    },
    canvas: () => (job.result && !stale() ? canvas : null),
  });
  return {
    get result() {
      return job.result;
    },
    get point() {
      return point;
    },
    choose,
    destroy: () => {
      for (const f of unsubs) f();
      job.destroy();
      observers.disconnect();
      plots.destroy();
    },
  };
}

/**
 * Calls `onVisible(visible)` when the section scrolls in or out of view and `onResize()` when the
 * map's box changes width by more than 4 px (where the browser has the observers).
 * @param {Element} section
 * @param {HTMLElement} box
 * @param {(visible: boolean) => void} onVisible
 * @param {() => void} onResize
 */
function watchVisibleAndSize(section, box, onVisible, onResize) {
  /** @type {IntersectionObserver | null} */
  let io = null;
  if (typeof IntersectionObserver === 'function') {
    io = new IntersectionObserver((entries) => onVisible(entries.some((e) => e.isIntersecting)));
    io.observe(section);
  }
  const width = watchWidth(box, onResize);
  return {
    disconnect() {
      if (io) io.disconnect();
      width.disconnect();
    },
  };
}
