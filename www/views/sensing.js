// @ts-check
// Sensing body rotation (issue 14; docs/sensing.md): the FE wing flaps while the body turns at
// a constant rate ω_b about one body axis. The worker job `sense` (wasm senseRotation) runs the
// model with and without ω_b; the difference Δε(x, t) is the strain the rotation causes. This
// panel shows the planform coloured by the detectability D = E_Δ / (ρ² E_F + σ²) per node (log
// scale), the K best sensors of the greedy placement as numbered markers, Δε(t) and its
// spectrum at a picked point (click, tap or the arrow keys on the map) and the detection
// probability against the number of sensors K. Reads the store (result, fe, body_rate,
// body_axis, modes); writes only body_rate / body_axis (and modes when asked to switch).
import { el, rich, isTouch } from '../dom.js';
import { fmt, errorText } from '../format.js';
import { decimate } from '../decimate.js';
import { linePlot, color, log10OrNull, viridis } from '../plot.js';
import { BODY_RATE, BODY_AXIS, BODY_AXIS_LABELS, bodyRateVector, toQuery } from '../state.js';
import { RATE_SLIDER, MAP_LO, MAP_HI, REL_DECADES, sliderOfRate, rateOfSlider, mapScale, deltaAt, curveData, sensorsFor, clusterMarkers, groupLabel } from '../sensemap.js';
import * as S from '../scene3d.js';
import { context2d } from '../export.js';
import { fitPlanform, fillPlanform, pickOnMap } from '../planform.js';
import { experimentQuery } from '../experiments.js';

export const title = 'Sensing body rotation';

/**
 * What this panel publishes in the store (`sense_map`) for the 3-D view's colour "rotation
 * detectability": the map's colour position per node (`field`, 0…1: log10 D on the panel's
 * colour scale, `mode` relative | absolute, from 10^lo to 10^hi; `max` the largest D), the first
 * K sensors (`label` their rank as text), the FE wing it was computed for, the body rate (rad/s,
 * body axes), the run configuration as JSON (`cfg_json`: kinematics and modes of the two runs) and
 * `show`, a count the button "Show on the 3-D wing" raises.
 * @typedef {{ fe: import('../engine.js').FeModesResult, n_nodes: number, field: Float64Array,
 *   mode: 'relative' | 'absolute', lo: number, hi: number, max: number, body_rate: number[], cfg_json: string,
 *   sensors: { rank: number, node: number, component: string, x_mm: number, y_mm: number, label: string }[],
 *   show: number }} SenseMap
 */

/** Wait after the last change before a new analysis is asked for, ms. */
export const SENSE_DELAY_MS = 250;
const COMP_LABEL = { eps_x: 'ε_x', eps_y: 'ε_y', gamma_xy: 'γ_xy' };

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, section, uid, engine } = ctx;
  const touch = isTouch();
  section.append(el('p', {
    class: 'wl-note',
    rich: 'When the body turns while the wings flap, the Coriolis and centrifugal forces change and the wing bends and twists a little differently. Here the FE wing is simulated twice, with and without a constant body rotation; the difference Δε is the strain the rotation causes. The map shows where Δε stands out best against the flapping strain (1 % stroke-to-stroke variation) and sensor noise (σ = 10^{-7}), and where K strain sensors detect the rotation best.',
  }));

  // the guided experiment (www/experiments.js `sensing`): a shareable link; a plain click applies
  // it here (FE wing, exp=sensing) instead of leaving the page
  const expLink = el('a', { class: 'wl-sense-exp', href: new URL(`../index.html?${experimentQuery('sensing', { panels: 'controls,experiments,sensing' })}`, import.meta.url).href, text: 'Guided experiment: how many sensors does it take?' });
  expLink.addEventListener('click', (ev) => {
    if (ev.button !== 0 || ev.ctrlKey || ev.metaKey || ev.shiftKey || ev.altKey) return;
    ev.preventDefault();
    ctx.setParams({ exp: 'sensing', modes: 'fe' });
  });
  section.append(el('p', { class: 'wl-note' }, expLink));

  // ---- controls ----
  const axis = el('select', { id: `${uid}-sense-axis` });
  for (const a of BODY_AXIS.choices) axis.append(el('option', { value: a, text: /** @type {any} */ (BODY_AXIS_LABELS)[a] }));
  const rateNum = el('input', { type: 'number', id: `${uid}-sense-rate`, min: BODY_RATE.min, max: BODY_RATE.max, step: 'any', 'aria-describedby': `${uid}-sense-rate-help` });
  const rateRange = el('input', { type: 'range', id: `${uid}-sense-log`, min: RATE_SLIDER.min, max: RATE_SLIDER.max, step: RATE_SLIDER.step, 'aria-label': 'Body rotation rate, logarithmic slider (|ω_b| from 0.0001 to 100 rad/s)' });
  const kRange = el('input', { type: 'range', id: `${uid}-sense-k`, min: 1, max: 30, step: 1, value: 5 });
  const kOut = el('output', { for: kRange.id, text: '5' });
  const scaleSel = el('select', { id: `${uid}-sense-scale` },
    el('option', { value: 'relative', text: `relative: ${REL_DECADES} decade${REL_DECADES === 1 ? '' : 's'} below this map’s largest D` }),
    el('option', { value: 'absolute', text: `absolute: D from 10⁻⁶ to 10² on every map` }));
  const field = (label, id, ...inputs) => el('span', { class: 'wl-sense-field' }, el('label', { for: id, rich: label }), ...inputs);
  const controls = el('div', { class: 'wl-sense-controls' },
    field('rotation axis', axis.id, axis),
    field('ω_b (rad/s)', rateNum.id, rateNum),
    el('span', { class: 'wl-sense-field wl-sense-log' }, rateRange),
    field('sensors K', kRange.id, kRange, kOut),
    field('colour scale', scaleSel.id, scaleSel));
  const rateHelp = el('p', { class: 'wl-note', id: `${uid}-sense-rate-help`, text: `Rate from ${BODY_RATE.min} to ${BODY_RATE.max} rad/s (the sign turns the rotation around); the slider moves |ω_b| on a log scale. Hawkmoths turn at a few rad/s.` });
  const status = el('p', { class: 'wl-sense-status', 'aria-live': 'polite' });
  const prog = el('progress', { class: 'wl-progress', max: 1, value: 0, hidden: true, 'aria-label': 'sensing analysis progress' });
  const cancel = el('button', { type: 'button', class: 'wl-cancel', text: 'Cancel', hidden: true });
  const statusRow = el('div', { class: 'wl-study-controls' }, status, prog, cancel);
  const needFe = el('div', { class: 'wl-sense-needfe' });
  const useFe = el('button', { type: 'button', text: 'Use the FE wing' });
  useFe.addEventListener('click', () => ctx.setParams({ modes: 'fe' }));
  needFe.append(el('p', { rich: 'Sensing needs strain over the whole wing, which only the FE wing has: the paper’s modes (Table 6) give strain at one point P only. Switch the mode set to the FE wing (or your own wing) to see where rotation shows up.' }), useFe);

  // ---- map ----
  const mapId = `${uid}-sensemap`;
  const canvas = el('canvas', {
    class: 'wl-smap-canvas wl-sense-canvas',
    id: mapId,
    tabindex: '0',
    role: 'img',
    width: 600,
    height: 300,
    'aria-label': `Planform map of the wing coloured by how detectable the body rotation is in strain, with the best sensors numbered; ${touch ? 'tap' : 'click'} a point, or use the arrow keys here, to plot the rotation-induced strain there.`,
    'aria-describedby': `${mapId}-text`,
  });
  const legend = el('canvas', { class: 'wl-smap-legend', width: 240, height: 12, 'aria-hidden': 'true' });
  const legendText = el('span', { class: 'wl-smap-legend-text' });
  const pointText = el('p', { class: 'wl-smap-point', id: `${mapId}-text`, 'aria-live': 'polite' });
  // the map and the sensors on the 3-D wing (store `sense_map`; views/wing3d.js colour 6)
  const show3d = el('button', { type: 'button', class: 'wl-small', text: 'Show on the 3-D wing', 'data-show3d': '' });
  show3d.disabled = true;
  let showCount = 0;
  show3d.addEventListener('click', () => {
    const s = store.get();
    if (!s.panels.includes('wing3d')) ctx.setParams({ panels: [...s.panels, 'wing3d'] });
    showCount += 1;
    drawMap();
  });
  const sensorList = el('ol', { class: 'wl-sense-list', 'aria-label': 'The best sensors, in the order the greedy placement chose them' });
  const mapBox = el('div', { class: 'wl-smap wl-sense-map', 'data-sensemap': '' },
    el('div', { class: 'wl-smap-head' },
      el('h3', { class: 'wl-smap-title', text: 'Where rotation shows up: detectability per point' }),
      ctx.exportButtons('sensing', 'Sensing map and sensors', ['csv', 'png'])),
    canvas,
    el('div', { class: 'wl-smap-legendrow' }, legend, legendText),
    pointText,
    el('p', { class: 'wl-note wl-sense-3d' }, show3d, ' this map (the same log-D scale) and the K sensors on the flapping 3-D wing.'),
    el('details', { class: 'wl-sense-details' }, el('summary', { text: 'The chosen sensors' }), sensorList));
  const body = el('div', { class: 'wl-sense-body' }, controls, rateHelp, statusRow, mapBox);
  section.append(needFe, body);

  const heading = (text) => body.append(el('h3', { class: 'wl-smap-title wl-sense-h', rich: text }));
  heading('Rotation-induced strain Δε at the picked point');
  const seriesPlot = linePlot(body, {
    name: 'sensing-series',
    title: 'Rotation-induced strain at the picked point',
    ariaLabel: 'Plot of the rotation-induced strain Δε_x, Δε_y and Δγ_xy at the picked point over time',
    xLabel: 't',
    xUnit: 's',
    yLabel: 'Δε (–)',
    series: [
      { label: 'Δε_x', color: color('eps_x') },
      { label: 'Δε_y', color: color('eps_y') },
      { label: 'Δγ_{xy}', color: color('gamma_xy') },
    ],
    height: 180,
  });
  let specMarkers = [];
  heading('Its spectrum: where in frequency the rotation shows up');
  const specPlot = linePlot(body, {
    name: 'sensing-spectrum',
    title: 'Spectrum of the rotation-induced strain',
    ariaLabel: 'Power spectral density of the rotation-induced strain components at the picked point, log scale',
    xLabel: 'f',
    xUnit: 'Hz',
    yLabel: 'PSD of Δε (1/Hz)',
    log: { y: true },
    series: [
      { label: 'Δε_x', color: color('eps_x') },
      { label: 'Δε_y', color: color('eps_y') },
      { label: 'Δγ_{xy}', color: color('gamma_xy') },
    ],
    markers: () => specMarkers,
    height: 180,
  });
  let kMarkers = [];
  heading('How many sensors does it take? Detection against K');
  const curvePlot = linePlot(body, {
    name: 'sensing-curve',
    title: 'Detection against the number of sensors',
    ariaLabel: 'Plot of the detection probability and of the share of the all-sensor detection index against the number of sensors K',
    xLabel: 'sensors K',
    xUnit: 'count',
    yLabel: 'P_d, share of d′_{all}',
    series: [
      { label: 'P_d (1 % false alarms)', color: '#1f5fbf', width: 2 },
      { label: 'd′ / d′_{all}', color: '#d62728', dash: [4, 3] },
    ],
    markers: () => kMarkers,
    keys: false,
    height: 180,
  });
  const curveNote = el('p', { class: 'wl-note' });
  body.append(curveNote);

  /** @type {any} the last wasm result (SensingResult) */
  let result = null;
  /** @type {{ fe: any, key: string } | null} what `result` was computed for */
  let resultFor = null;
  /** the run configuration (JSON) the result is for (published with sense_map, so the 3-D view can tell an outdated map) */
  let resultCfg = '';
  /** @type {[number, number] | null} the picked point (mm); null = the best sensor */
  let point = null;
  /** @type {{ id: number, key: string } | null} */
  let running = null;
  let dirty = false;
  let visible = typeof IntersectionObserver !== 'function';
  /** @type {ReturnType<typeof setTimeout> | undefined} */
  let timer;
  /** @type {{ x0: number, y1: number, k: number } | null} */
  let frame = null;
  let drawn = 0;
  /** The wing and mode set the map was last drawn for. */
  let lastFe = null, lastModes = '';

  const feOf = (s) => (s.modes === 'fe' && s.fe && s.result && s.result.analysis.sim.modes.length === s.fe.n_modes ? s.fe : null);
  /** What an analysis depends on: the body rate, the point and the config (kinematics, modes, run). */
  const keyOf = (s) => JSON.stringify({ w: bodyRateVector(s), p: point, c: s.result ? s.result.cfg : null });

  function syncControls() {
    const s = store.get();
    axis.value = s.body_axis;
    const root = /** @type {any} */ (section.getRootNode());
    if (!root || root.activeElement !== rateNum) rateNum.value = String(s.body_rate);
    rateRange.value = String(sliderOfRate(s.body_rate));
    rateRange.setAttribute('aria-valuetext', `${fmt(Math.abs(s.body_rate), 3)} rad/s`);
  }

  axis.addEventListener('change', () => store.set({ body_axis: /** @type {any} */ (axis.value) }));
  rateNum.addEventListener('change', () => {
    const v = Number(rateNum.value);
    if (rateNum.value.trim() === '' || !Number.isFinite(v) || v < BODY_RATE.min || v > BODY_RATE.max) {
      rateNum.setAttribute('aria-invalid', 'true');
      status.textContent = `ω_b must be a number in [${BODY_RATE.min}, ${BODY_RATE.max}] rad/s.`;
      return;
    }
    rateNum.removeAttribute('aria-invalid');
    store.set({ body_rate: v });
  });
  rateRange.addEventListener('input', () => {
    const s = store.get();
    store.set({ body_rate: rateOfSlider(Number(rateRange.value), s.body_rate < 0 ? -1 : 1) });
  });
  kRange.addEventListener('input', () => { kOut.textContent = kRange.value; drawMap(); drawCurve(); });
  scaleSel.addEventListener('change', () => drawMap());
  cancel.addEventListener('click', () => { if (running) engine.cancel(running.id); });

  /** Asks for a new analysis SENSE_DELAY_MS after the last change (one at a time). */
  function schedule() {
    clearTimeout(timer);
    timer = setTimeout(request, SENSE_DELAY_MS);
  }

  function request() {
    const s = store.get();
    const fe = feOf(s);
    if (!fe || !visible || !s.result) return;
    const cfg = s.result.cfg;
    const key = keyOf(s);
    if (result && resultFor && resultFor.fe === fe && resultFor.key === key) return;
    if (running) { dirty = true; return; }
    const w = bodyRateVector(s);
    const t0 = performance.now();
    /** @type {Record<string, unknown>} */
    const opts = {};
    if (point) opts.point_mm = point;
    const job = engine.run('sense', { cfg, fe: { nodes: fe.nodes, triangles: fe.triangles, strain_nodes: fe.strain_nodes }, body_rate: w, opts }, (done, total) => {
      prog.max = total;
      prog.value = done;
    });
    running = { id: job.id, key };
    dirty = false;
    mapBox.dataset.state = 'computing';
    status.textContent = `Computing: two runs of the FE wing (with and without ω_b), then ${fe.n_nodes} nodes × 3 strain components…`;
    prog.hidden = false;
    cancel.hidden = false;
    job.promise.then(({ result: r, ms }) => {
      running = null;
      result = r;
      resultFor = { fe, key };
      resultCfg = JSON.stringify(cfg);
      const t1 = performance.now();
      drawAll();
      const t2 = performance.now();
      mapBox.dataset.ms = String(Math.round(t2 - t0));
      mapBox.dataset.workerMs = String(Math.round(ms));
      status.textContent = `Done in ${fmt((t2 - t0) / 1000, 2)} s (analysis ${fmt(ms / 1000, 2)} s in the worker, drawing ${fmt(t2 - t1, 2)} ms).${r.warnings.length ? ' Warnings: ' + r.warnings.join('; ') : ''}`;
    }, (e) => {
      const why = errorText(e);
      mapBox.dataset.state = why === 'cancelled' ? 'cancelled' : 'error';
      status.textContent = why === 'cancelled' ? 'Cancelled; change a setting to compute again.' : `Error: ${why}`;
    }).finally(() => {
      running = null;
      prog.hidden = true;
      cancel.hidden = true;
      if (dirty) schedule();
    });
  }

  function stale() {
    const s = store.get();
    const fe = feOf(s);
    return !result || !resultFor || resultFor.fe !== fe || fe === null;
  }

  function drawAll() {
    drawMap();
    drawSeries();
    drawCurve();
  }

  /** The K shown (the slider, at most the sensors there are). */
  const kNow = () => Math.min(Number(kRange.value), result ? result.sensors.length : 0);

  function drawMap() {
    const s = store.get();
    const fe = feOf(s);
    needFe.hidden = !!(s.modes === 'fe');
    body.hidden = s.modes !== 'fe';
    if (s.modes !== 'fe') { mapBox.dataset.state = 'none'; return; }
    if (!fe) {
      mapBox.dataset.state = 'none';
      status.textContent = 'Waiting for the FE wing’s modes…';
      canvas.hidden = true;
      return;
    }
    canvas.hidden = false;
    const have = result && !stale() && result.n_nodes === fe.n_nodes;
    if (have && !running) mapBox.dataset.state = 'ready';
    const fit = fitPlanform(canvas, fe.nodes, 14);
    const { c2, cssW, cssH } = fit;
    frame = fit.frame;
    const f = fit.frame;
    const kk = f.k;
    const px = (x) => (x - f.x0) * kk;
    const py = (y) => (f.y1 - y) * kk;
    const scale = have ? mapScale(result.d_best, /** @type {any} */ (scaleSel.value)) : null;
    fillPlanform(c2, fe.nodes, fe.triangles, f, (a, b, c) => {
      if (scale && scale.max > 0) return viridis(scale.t((result.d_best[a] + result.d_best[b] + result.d_best[c]) / 3));
      return scale ? viridis(0) : [215, 215, 215];
    });
    // the K best sensors: numbered discs (last drawn on top: the best)
    const K = have ? kNow() : 0;
    c2.font = 'bold 10px system-ui, sans-serif';
    c2.textAlign = 'center';
    c2.textBaseline = 'middle';
    // sensors closer than a marker's size share one label ("1,2,4"), drawn at the first one;
    // each sensor's exact place is a small dark dot
    const marks = result && have ? result.sensors.slice(0, K).map((sn) => ({ x: px(sn.x_mm), y: py(sn.y_mm), rank: sn.rank })) : [];
    for (const m of marks) {
      c2.fillStyle = '#111';
      c2.beginPath(); c2.arc(m.x, m.y, 2, 0, 2 * Math.PI); c2.fill();
    }
    const groups = clusterMarkers(marks, 16);
    for (let j = groups.length - 1; j >= 0; j--) {
      const g = groups[j];
      const label = groupLabel(g.ranks);
      const w = Math.max(16, c2.measureText(label).width + 8);
      // the label sits up and to the right of the first sensor of its group, joined by a line
      const lx = g.x + 6 + w / 2, ly = g.y - 12;
      c2.strokeStyle = '#111';
      c2.lineWidth = 1;
      c2.beginPath(); c2.moveTo(g.x, g.y); c2.lineTo(lx - w / 2, ly); c2.stroke();
      c2.fillStyle = '#fff';
      c2.lineWidth = 1.5;
      c2.beginPath();
      c2.roundRect(lx - w / 2, ly - 8, w, 16, 8);
      c2.fill();
      c2.stroke();
      c2.fillStyle = '#111';
      c2.fillText(label, lx, ly + 0.5);
    }
    canvas.dataset.markers = JSON.stringify(groups.map((g) => g.ranks));
    // the picked point: a ring with a dark and a light edge
    const p = point || (have ? result.point_mm : null);
    if (p) {
      c2.lineWidth = 3;
      c2.strokeStyle = '#111';
      c2.beginPath(); c2.arc(px(p[0]), py(p[1]), 11, 0, 2 * Math.PI); c2.stroke();
      c2.lineWidth = 1.5;
      c2.strokeStyle = '#ff3d7f';
      c2.beginPath(); c2.arc(px(p[0]), py(p[1]), 11, 0, 2 * Math.PI); c2.stroke();
      canvas.dataset.point = `${p[0]},${p[1]}`;
    }
    // legend: viridis over the fixed log scale
    const lc = context2d(legend);
    for (let i = 0; i < legend.width; i++) {
      const rgb = viridis(i / (legend.width - 1));
      lc.fillStyle = `rgb(${rgb[0]},${rgb[1]},${rgb[2]})`;
      lc.fillRect(i, 0, 1, legend.height);
    }
    if (!have) {
      legendText.textContent = running ? 'computing…' : '';
    } else if (scale && scale.max > 0) {
      legendText.replaceChildren(rich(scale.mode === 'absolute'
        ? `detectability D, log scale from 10^{${MAP_LO}} (and below) to 10^{${MAP_HI}} (and above); largest on this wing ${fmt(scale.max, 3)}. D = 1: the rotation’s strain as large as the flapping variation plus noise.`
        : `detectability D, log scale from ${fmt(10 ** scale.lo, 3)} (and below) to ${fmt(scale.max, 3)}, the largest on this wing (brightest: where rotation shows up best). D = 1: the rotation’s strain as large as the flapping variation plus noise.`));
      legendText.append(rich(' The colours rate each point alone, by energy; the numbered sensors are chosen by how well their time series tell a rotation from a slightly different stroke, which favours points whose Δε has a different time course from the flapping strain, not only the brightest ones.'));
    } else {
      legendText.textContent = 'D = 0 everywhere: no rotation, so nothing to detect';
    }
    canvas.dataset.maxD = scale ? String(scale.max) : '';
    show3d.disabled = !(have && scale);
    if (have && scale) publish(fe, scale, K);
    canvas.dataset.drawn = String(++drawn);
    // the sensors as text
    sensorList.replaceChildren(...(have ? result.sensors.slice(0, K).map((sn) => el('li', {
      text: `node ${sn.node}, ${COMP_LABEL[sn.component] || sn.component} at (${fmt(sn.x_mm, 3)}, ${fmt(sn.y_mm, 3)}) mm, D = ${fmt(sn.d, 3)}`,
    })) : []));
    if (p) {
      const src = point ? 'the picked point' : 'the best sensor (default)';
      pointText.textContent = `Δε is plotted at ${src}, (x, y) = (${fmt(p[0], 3)}, ${fmt(p[1], 3)}) mm. ${touch ? 'Tap the map to move it.' : 'Click the map, or focus it and use the arrow keys (Shift: bigger steps), to move it.'}`;
    }
  }

  /** @type {{ result: any, k: number, mode: string, show: number } | null} what was last published */
  let published = null;
  /** Puts the map (colour positions per node) and the first K sensors in the store for the 3-D view. */
  function publish(/** @type {any} */ fe, /** @type {ReturnType<typeof mapScale>} */ scale, /** @type {number} */ K) {
    if (published && published.result === result && published.k === K && published.mode === scale.mode && published.show === showCount) return;
    published = { result, k: K, mode: scale.mode, show: showCount };
    const n = fe.n_nodes;
    const field = new Float64Array(n);
    for (let i = 0; i < n && i < result.d_best.length; i++) field[i] = scale.t(result.d_best[i]);
    store.set({
      sense_map: {
        fe,
        n_nodes: n,
        field,
        mode: /** @type {'relative' | 'absolute'} */ (scale.mode),
        lo: scale.lo,
        hi: scale.hi,
        max: scale.max,
        body_rate: Array.from(result.body_rate),
        cfg_json: resultCfg,
        sensors: result.sensors.slice(0, K).map((sn) => ({ rank: sn.rank, node: sn.node, component: sn.component, x_mm: sn.x_mm, y_mm: sn.y_mm, label: String(sn.rank) })),
        show: showCount,
      },
    });
  }

  /** The series at the point in use: the wasm result's, or (picked since) formed from dq. */
  function seriesNow() {
    if (!result) return null;
    if (!point) return { delta: result.delta, spectrum: result.spectrum };
    const same = (result.point_source === 'opts' && result.point_mm[0] === point[0] && result.point_mm[1] === point[1]);
    if (same) return { delta: result.delta, spectrum: result.spectrum };
    try {
      return { delta: deltaAt(engine.modalStrainAt(point), result.dq), spectrum: null };
    } catch {
      return null;
    }
  }

  function drawSeries() {
    if (!result || stale()) return;
    const sr = seriesNow();
    if (!sr) return;
    const d = sr.delta;
    const w = seriesPlot.u.bbox ? seriesPlot.u.bbox.width / (globalThis.devicePixelRatio || 1) : 600;
    seriesPlot.setData(decimate(result.t, [d.eps_x, d.eps_y, d.gamma_xy], Math.min(1500, Math.max(200, Math.round(w)))));
    const pk = (y) => { let m = 0; for (const v of y) m = Math.max(m, Math.abs(v)); return m; };
    const peak = Math.max(pk(d.eps_x), pk(d.eps_y), pk(d.gamma_xy));
    mapBox.dataset.deltaPeak = String(peak);
    seriesPlot.setSummary(`Peak |Δε| at the point: ε_x ${fmt(pk(d.eps_x), 3)}, ε_y ${fmt(pk(d.eps_y), 3)}, γ_xy ${fmt(pk(d.gamma_xy), 3)} (dimensionless).`);
    if (sr.spectrum) {
      const sp = sr.spectrum;
      const fd = result.flap_freq_hz;
      const fmax = Math.min(result.sample_rate_hz / 2, 10 * fd);
      const freq = sp.eps_x.freq_hz;
      let n = 0;
      while (n < freq.length && freq[n] <= fmax) n++;
      const pos = (arr) => Array.from(arr.subarray(0, n), (v) => log10OrNull(v));
      specPlot.setData([Array.from(freq.subarray(0, n)), pos(sp.eps_x.psd), pos(sp.eps_y.psd), pos(sp.gamma_xy.psd)]);
      const marks = [];
      for (let j = 1; j * fd <= fmax; j++) marks.push({ x: j * fd, label: `${j}f_d`, color: '#8a8a8a' });
      specMarkers = marks;
      specPlot.redraw();
      const top = sp.eps_x.peaks && sp.eps_x.peaks[0];
      specPlot.setSummary(peak > 0
        ? `Welch PSD of Δε at the point up to ${fmt(fmax, 3)} Hz; grey lines: multiples of the flap frequency ${fmt(fd, 3)} Hz.${top ? ` Strongest Δε_x peak at ${fmt(top.freq_hz, 4)} Hz.` : ''}`
        : 'Δε is zero: no body rotation, no spectrum.');
    } else {
      specPlot.setSummary('Spectrum: updating for the picked point…');
    }
  }

  function drawCurve() {
    if (!result || stale()) return;
    const [k, pd, share] = curveData(result);
    curvePlot.setData([k, pd, share]);
    const K = kNow();
    kMarkers = K ? [{ x: K, label: `K = ${K}`, color: '#555', dash: [3, 3] }] : [];
    curvePlot.redraw();
    const k90 = sensorsFor(result.pd);
    const atK = K ? result.pd[K - 1] : 0;
    const text = result.d_prime_all > 0
      ? `With K = ${K} sensors, P_d = ${fmt(atK, 3)} (d′ = ${fmt(result.d_prime[K - 1], 3)}); all ${3 * result.n_nodes} candidates together: d′ = ${fmt(result.d_prime_all, 3)}, P_d = ${fmt(result.pd_all, 3)}. ${k90 ? `P_d ≥ 0.9 from K = ${k90}.` : 'P_d stays below 0.9 up to K = ' + result.pd.length + '.'} ${result.k_for_90_percent ? `90 % of the all-sensor d′ needs K = ${result.k_for_90_percent}.` : ''} A lower rate (or more noise) makes detection harder: try 0.001 rad/s.`
      : 'With no body rotation there is nothing to detect: P_d is the false-alarm rate (1 %) at every K.';
    curvePlot.setSummary(text);
    curveNote.replaceChildren(rich(text));
  }

  /** Picks (x, y) mm if it lies on the wing. */
  function choose(x, y) {
    const s = store.get();
    const fe = feOf(s);
    if (!fe) return false;
    const n = fe.nodes.length / 3;
    const xy = new Float64Array(2 * n);
    for (let i = 0; i < n; i++) { xy[2 * i] = fe.nodes[3 * i] * 1e3; xy[2 * i + 1] = fe.nodes[3 * i + 1] * 1e3; }
    if (!S.pick(fe.nodes, fe.triangles, { xy, depth: new Float64Array(n) }, x, y)) {
      pointText.textContent = `(${fmt(x, 3)}, ${fmt(y, 3)}) mm is outside the wing: choose a point on the wing.`;
      return false;
    }
    const r = (v) => Math.round(v * 1000) / 1000;
    point = [r(x), r(y)];
    drawMap();
    drawSeries();
    schedule();
    return true;
  }
  pickOnMap(canvas, () => frame, () => point || (result ? result.point_mm : null), choose);

  const unsubs = [
    store.subscribe(['body_rate', 'body_axis'], () => { syncControls(); schedule(); }),
    store.subscribe(['result', 'fe', 'modes'], () => {
      // a new live result alone (a slider moved) only asks for a new analysis; the map is
      // redrawn when that arrives, or now when the wing or the mode set changed
      const s = store.get();
      const fe = feOf(s);
      if (result && resultFor && resultFor.fe !== fe) point = null;
      if (fe !== lastFe || s.modes !== lastModes) { lastFe = fe; lastModes = s.modes; drawMap(); }
      schedule();
    }),
  ];
  /** @type {IntersectionObserver | null} */
  let io = null;
  if (typeof IntersectionObserver === 'function') {
    io = new IntersectionObserver((entries) => {
      const was = visible;
      visible = entries.some((e) => e.isIntersecting);
      if (visible && !was) schedule();
    });
    io.observe(section);
  }
  /** @type {ResizeObserver | null} */
  let ro = null;
  if (typeof ResizeObserver === 'function') {
    let lastW = 0;
    ro = new ResizeObserver(() => {
      const w = mapBox.clientWidth;
      if (w && Math.abs(w - lastW) > 4) { lastW = w; drawMap(); }
    });
    ro.observe(mapBox);
  }
  syncControls();
  drawMap();
  schedule();

  ctx.registerPlot('sensing-series', seriesPlot);
  ctx.registerPlot('sensing-spectrum', specPlot);
  ctx.registerPlot('sensing-curve', curvePlot);
  ctx.registerExport('sensing', {
    csv: () => {
      const s = store.get();
      const fe = feOf(s);
      if (!fe || !result || stale()) return null;
      const n = result.n_nodes;
      const col = (c) => Float64Array.from({ length: n }, (_, i) => result.d[3 * i + c]);
      const rank = new Float64Array(n);
      result.sensors.forEach((sn) => { if (!rank[sn.node]) rank[sn.node] = sn.rank; });
      return ctx.toCSV(
        [
          { name: 'x', unit: 'mm', values: Float64Array.from({ length: n }, (_, i) => fe.nodes[3 * i] * 1e3) },
          { name: 'y', unit: 'mm', values: Float64Array.from({ length: n }, (_, i) => fe.nodes[3 * i + 1] * 1e3) },
          { name: 'D_eps_x', unit: '-', values: col(0) },
          { name: 'D_eps_y', unit: '-', values: col(1) },
          { name: 'D_gamma_xy', unit: '-', values: col(2) },
          { name: 'D_best', unit: '-', values: result.d_best },
          { name: 'sensor_rank', unit: '0 = not chosen', values: rank },
        ],
        [`wingbeat lab; ${toQuery(s)}`, `detectability per FE node, body rate [${result.body_rate.join(', ')}] rad/s (body axes); ${result.method}`],
      );
    },
    canvas: () => (result && !stale() ? canvas : null),
  });
  return {
    get result() { return result; },
    get point() { return point; },
    choose,
    destroy: () => {
      unsubs.forEach((f) => f());
      clearTimeout(timer);
      if (io) io.disconnect();
      if (ro) ro.disconnect();
      seriesPlot.destroy();
      specPlot.destroy();
      curvePlot.destroy();
    },
  };
}
