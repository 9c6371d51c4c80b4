// @ts-check
// 3-D wing panel: the shell-FE wing flapping (roll α, pitch β, yaw γ about the root), bending
// and twisting as the simulated q_k(t) say, coloured by strain — drawn by the wasm WingView
// (WebGPU where the browser has it, WebGL2 otherwise; a plain explanation where neither works).
//
// What makes it show the physics:
// * the camera fits the whole stroke (every pose of the run stays in frame; www/scene3d.js
//   mirrors the renderer's camera, so the fit is done here with orbit/zoom only);
// * one strain colour range per component for the whole run (robust maximum over time), fixed
//   while playing, so the beat shows as pulsing colour;
// * speeds "one flap per second" and "one beat in 4 s" besides fixed slow-motion factors;
// * the largest deflection over the run in mm for the FE wing (the paper table is not SI);
// * a legend for the stroke plane, the body axis and both frames, each hideable.
// The instant shown is the store's `t3d`; the angles come with the analysis (no wasm call per
// frame). Test hooks on the box: data-state (loading | ready | unavailable), data-backend,
// data-frames, data-coverage (estimated wing share of the canvas at the fitted view).
import { el, rich, isTouch } from '../dom.js';
import { fmt, errorText } from '../format.js';
import { beatInfo } from '../beat.js';
import * as S from '../scene3d.js';
import { context2d } from '../export.js';
import { strainFieldOf, PEAK_DELAY_MS } from './strain.js';
import { clusterMarkers, groupLabel } from '../sensemap.js';

export const title = '3-D wing';

/**
 * States of the run (evenly spaced samples plus each mode's extremes) over which the colour
 * ranges and the largest deflection are taken when there are 3+ modes: 1000 keeps the per-run
 * work near 100 ms for 1653 nodes × 6 modes (4000 took 0.5 s), and the ranges are for display.
 */
const RANGE_SAMPLES = 1000;

/** Margin of the camera fit, as a fraction of the half-width and half-height (2 % of each side). */
const FIT_MARGIN = 0.04;

/**
 * The canvas's backing store: CSS size × devicePixelRatio, the ratio capped at MAX_DPR and the
 * area at MAX_BACKING_PX device pixels (a software rasteriser pays per pixel, every frame).
 */
export const MAX_DPR = 2;
export const MAX_BACKING_PX = 2_000_000;
/** While playing, the time goes to the store (responses plot cursor, time slider) at most this often (ms). */
const PUSH_MS = 100;
/** While playing, the status, summary, legend and deflection texts change at most this often (ms). */
const TEXT_MS = 250;
/**
 * When the frames delivered while playing come slower than SLOW_FRAME_MS apart on average (a
 * software rasteriser, a busy machine), the wing is drawn at most every CAPPED_FRAME_MS (≈ 30 fps),
 * leaving the rest of each 60 Hz period to the sliders and the compositor.
 */
const SLOW_FRAME_MS = 24;
const CAPPED_FRAME_MS = 30;

/**
 * WebGL2 context attributes for the 3-D canvas when the browser offers no WebGPU adapter (wgpu
 * then takes this context as it is): no alpha channel, depth or stencil buffer on the canvas
 * (wgpu draws into its own targets and blits), no MSAA, no preserved drawing buffer (so the
 * browser never has to keep or read back a copy).
 */
export const WEBGL_ATTRIBUTES = { alpha: false, depth: false, stencil: false, antialias: false, preserveDrawingBuffer: false, powerPreference: 'high-performance' };

const COLOURS = [
  ['0', 'none (shading only)'],
  ['1', 'ε_x, spanwise strain'],
  ['2', 'ε_y, chordwise strain'],
  ['3', 'γ_xy, shear strain'],
  ['4', '|ε|, strain magnitude'],
  ['5', 'whole-run strain map (strain panel’s choice)'],
  ['6', 'rotation detectability (sensing panel)'],
];
/** The colour option that shows the sensing panel's detectability map (drawn as the renderer's node field, mode 5). */
const SENSE_COLOUR = 6;
const SPEEDS = [
  ['beat4', 'one beat in 4 s'],
  ['flap1', 'one flap per second'],
  ['0.002', '1/500 of real time'],
  ['0.005', '1/200 of real time'],
  ['0.01', '1/100 of real time'],
  ['0.02', '1/50 of real time'],
  ['0.05', '1/20 of real time'],
];
// The renderer's scene decorations (src/render/gpu.rs scene_geometry), for the legend.
const SCENE_LEGEND = [
  ['plane', 'Stroke plane (I–K plane through the root, ⟂ body axis)', 'rgba(115,140,217,0.35)', 'rgb(102,122,179)'],
  ['body', 'Body axis (along J)', 'rgb(217,217,217)'],
  ['fixed', 'Fixed frame I, J, K (dim red, green, blue)', 'rgb(140,64,64)', 'rgb(64,128,64)', 'rgb(64,77,153)'],
  ['wing', 'Flapping frame I″, J″, K″ (bright red, green, blue)', 'rgb(255,64,51)', 'rgb(77,255,77)', 'rgb(89,140,255)'],
];

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, section, engine, uid } = ctx;
  const touch = isTouch();
  /** @type {import('../pkg/wingbeat.js').WingView | null} */
  let view = null;
  /** @type {import('../pkg/wingbeat.js').FeModesResult | null} */
  let fe = null;
  let started = false;
  let frames = 0;
  /** @type {S.Camera | null} mirror of the renderer's camera */
  let cam = null;
  let userCamera = false;
  let fitKey = '';
  /** @type {Record<number, number> | null} colour limit per colour mode (1 ε_x … 4 |ε|) */
  let ranges = null;
  /** @type {number | null} largest true deflection over the run (m) */
  let runDeflection = null;
  let raf = 0;
  let pending = 0;
  let dirty = false;
  /** @type {number | null} the instant drawn while playing (s); reaches the store every PUSH_MS */
  let playT = null;
  let pushing = false;
  let lastPush = 0;
  let lastText = -Infinity;
  /** sample index of the last frame the play loop drew (-1: something else drew since) */
  let lastLoopI = -1;
  /** on screen (IntersectionObserver); the play loop pauses while off screen or the tab is hidden */
  let onScreen = true;
  /** @type {IntersectionObserver | null} */
  let vis = null;
  /** reused for the per-frame modal coordinates */
  let qBuf = new Float64Array(0);
  let legendKey = '';
  /** @type {IntersectionObserver | null} */
  let io = null;
  /** @type {ResizeObserver | null} */
  let ro = null;
  const box = el('div', { class: 'wl-wing3d-box', 'data-wing3d': '', 'data-state': 'loading', 'data-loop': 'stopped' });
  // One 3-D view per lab and every lab renders into its own shadow root, so the id is unique
  // in its tree (tests and host scripts reach it as lab.shadowRoot.getElementById('wing3d')).
  box.id = 'wing3d';
  const summaryId = `${uid}-w3-sum`;
  const makeCanvas = () => el('canvas', {
    class: 'wl-w3-canvas',
    tabindex: '0',
    role: 'img',
    'aria-label': `3-D view of the flexing wing. ${touch ? 'Drag to orbit, pinch or use the buttons to zoom; tap the wing to choose the strain point.' : 'Drag, or use the arrow keys, to orbit; wheel or + and − to zoom; Space plays or pauses; click the wing to choose the strain point.'}`,
    'aria-describedby': summaryId,
    width: 640,
    height: 480,
  });
  let canvas = makeCanvas();
  // Labels drawn over the canvas at the projected tips of the axes and a corner of the stroke
  // plane (positions from the camera mirror; the legend below says the same in words).
  const LABELS = [
    ['I', 'fixed', 'rgb(200,110,110)'], ['J', 'fixed', 'rgb(110,190,110)'], ['K', 'fixed', 'rgb(130,150,230)'],
    ['I″', 'wing', 'rgb(255,90,80)'], ['J″', 'wing', 'rgb(100,255,100)'], ['K″', 'wing', 'rgb(120,165,255)'],
    ['body axis', 'body', 'rgb(220,220,220)'], ['stroke plane', 'plane', 'rgb(150,170,235)'],
  ];
  const overlay = el('div', { class: 'wl-w3-overlay', 'aria-hidden': 'true' });
  // The strain point (FE wings): a ring at its projected position on the drawn wing.
  const pointMark = el('span', { class: 'wl-w3-point', hidden: true });
  pointMark.style.willChange = 'transform';
  overlay.append(pointMark);
  // The sensing panel's K best sensors (colour 6): a dot per sensor, a numbered tag per group of
  // sensors that sit closer on screen than a tag (see placeSensors).
  const sensorLayer = el('div', { class: 'wl-w3-sensors', 'data-sensors': '0', hidden: true });
  overlay.append(sensorLayer);
  const labelEls = LABELS.map(([t, kind, c]) => {
    // Hidden until the first frame places it (else every label sits at the canvas's corner).
    const e = el('span', { class: `wl-w3-label wl-w3-label-${kind}`, text: t, hidden: true });
    e.style.color = c;
    // moved every frame while playing: its own compositor layer, so a move repaints nothing
    e.style.willChange = 'transform';
    overlay.append(e);
    return e;
  });
  const stage = el('div', { class: 'wl-w3-stage' }, canvas, overlay);
  box.append(stage);
  const summary = el('p', { class: 'wl-sr', id: summaryId, text: 'The 3-D view of the wing is starting: it shows the wing flapping and bending at the instant chosen with the time slider.' });
  const status = el('p', { class: 'wl-w3-status', role: 'status', text: 'Starting the 3-D view…' });

  const playBtn = el('button', { type: 'button', class: 'wl-w3-play', text: 'Play', 'aria-pressed': 'false', onclick: () => store.set({ playing: !store.get().playing }) });
  const speed = el('select', { id: `${uid}-w3-speed`, 'aria-label': 'Playback speed' });
  for (const [v, t] of SPEEDS) speed.append(el('option', { value: v, text: t }));
  speed.value = 'beat4';
  speed.addEventListener('change', () => describeTime());
  const time = el('input', { type: 'range', id: `${uid}-w3-time`, min: 0, max: 2, step: 0.0001, value: 0.505, 'aria-label': 'Simulated time t, in s' });
  time.addEventListener('input', () => store.set({ playing: false, t3d: Number(time.value) }));
  const timeText = el('span', { class: 'wl-w3-time', 'aria-live': 'off' });
  const exag = el('input', { type: 'range', id: `${uid}-w3-exag`, min: 0, max: 3, step: 0.05, value: 1, 'aria-label': 'Deflection exaggeration, as a power of ten' });
  let exagTouched = false;
  exag.addEventListener('input', () => { exagTouched = true; dirty = true; draw(); });
  const exagText = el('span', { class: 'wl-w3-exag' });
  const colour = el('select', { id: `${uid}-w3-colour`, 'aria-label': 'Colour the wing by' });
  for (const [v, t] of COLOURS) colour.append(el('option', { value: v, text: t }));
  colour.value = '3';
  colour.addEventListener('change', () => { fieldKey = ''; sensorGroups = null; applyRange(); draw(); });
  const legend = el('canvas', { class: 'wl-w3-legend', width: 240, height: 14, 'aria-hidden': 'true' });
  const legendText = el('span', { class: 'wl-w3-legend-text' });
  const showAxes = el('input', { type: 'checkbox', id: `${uid}-w3-axes`, checked: true });
  const showBody = el('input', { type: 'checkbox', id: `${uid}-w3-body`, checked: true });
  const showPlane = el('input', { type: 'checkbox', id: `${uid}-w3-plane`, checked: true });
  const onScene = () => { if (view) { view.set_scene(showAxes.checked, showPlane.checked, showBody.checked); draw(); } };
  showAxes.addEventListener('change', onScene);
  showBody.addEventListener('change', onScene);
  showPlane.addEventListener('change', onScene);
  const resetBtn = el('button', { type: 'button', class: 'wl-small', text: 'Fit view', title: 'Camera back to the view that fits the whole stroke', onclick: () => { userCamera = false; fitKey = ''; fit(true); draw(); } });

  const sceneLegend = el('ul', { class: 'wl-w3-scene' });
  for (const [key, text, ...cols] of SCENE_LEGEND) {
    const sw = el('span', { class: 'wl-w3-sw', 'aria-hidden': 'true' });
    if (key === 'plane') sw.style.cssText = `background:${cols[0]};border:1px solid ${cols[1]}`;
    else sw.style.background = cols.length > 1 ? `linear-gradient(90deg, ${cols[0]} 33%, ${cols[1]} 33% 66%, ${cols[2]} 66%)` : cols[0];
    sceneLegend.append(el('li', { 'data-scene': key }, sw, text));
  }
  const row = (label, id, ...inputs) => el('div', { class: 'wl-w3-row' }, el('label', { for: id, text: label }), ...inputs);
  const options = el('details', { class: 'wl-w3-options', open: true },
    el('summary', { text: 'View options: exaggeration, colour, what the lines are' }),
    el('div', { class: 'wl-w3-optrows' },
      row('exaggeration', exag.id, exag, exagText),
      row('colour', colour.id, colour),
      el('div', { class: 'wl-w3-row wl-w3-legendrow' }, legend, legendText)),
    el('div', { class: 'wl-w3-row' },
      el('label', { class: 'wl-check' }, showPlane, ' stroke plane'),
      el('label', { class: 'wl-check' }, showBody, ' body axis'),
      el('label', { class: 'wl-check' }, showAxes, ' frames I, J, K and I″, J″, K″'),
      resetBtn),
    sceneLegend);
  const controls = el('div', { class: 'wl-w3-controls' },
    el('div', { class: 'wl-w3-row' }, playBtn, el('label', { for: speed.id, text: 'speed' }), speed),
    row('time', time.id, time, timeText),
    options,
  );
  const sceneBox = options;
  let narrowNow = false;
  /** @type {boolean | null} on a focused screen (null: not told yet) */
  let focusedNow = null;
  const defl = el('p', { class: 'wl-w3-defl' });
  const note = el('p', { class: 'wl-note' });
  options.append(note);
  section.append(box, summary, status, controls, defl);
  bindCamera();
  describeTime();

  function unavailable(why) {
    box.dataset.state = 'unavailable';
    box.replaceChildren(el('p', { class: 'wl-w3-fallback', text: `3-D view unavailable: ${why}. Everything else in the lab works without it.` }));
    summary.textContent = `3-D view unavailable: ${why}.`;
    status.textContent = '';
    controls.hidden = true;
    sceneBox.hidden = true;
  }

  async function start() {
    if (started) return;
    started = true;
    if (!engine.hasRenderer) {
      unavailable('this build of the lab has no renderer (built without the `render` feature)');
      return;
    }
    try {
      status.textContent = 'Computing the shell FE wing (mesh + modes) in a worker, a few seconds…';
      fe = await engine.ensureFe();
      store.set({ fe });
    } catch (e) {
      unavailable(`the FE wing could not be computed: ${errorText(e)}`);
      return;
    }
    if (!(await makeView(fe))) return;
    if (typeof ResizeObserver === 'function') {
      ro = new ResizeObserver(() => { if (fitCanvas()) { fit(false); draw(); } });
      ro.observe(stage);
    }
    onResult();
  }

  /** (Re)creates the WingView for the FE wing `w` (a new wing gets a fresh canvas). */
  async function makeView(w) {
    const renderer = engine.renderer;
    if (!renderer) return false;
    if (view) {
      view.free();
      view = null;
      const fresh = makeCanvas();
      canvas.replaceWith(fresh);
      canvas = fresh;
      bindCamera();
    }
    fitCanvas();
    await prepareContext(canvas);
    try {
      view = await renderer.createFromArrays(canvas, w.nodes, w.triangles, w.shapes, w.strain_nodes);
    } catch (e) {
      unavailable(errorText(e));
      return false;
    }
    fe = w;
    cam = S.defaultCamera(S.spanOf(w.nodes));
    userCamera = false;
    fitKey = '';
    fieldKey = '';
    dirty = true;
    box.dataset.state = 'ready';
    box.dataset.backend = view.backend();
    box.dataset.nodes = String(w.nodes.length / 3);
    onScene();
    return true;
  }

  /** A new FE wing in the store (the user's own wing, or another mode count): redraw with it. */
  /** @type {Promise<void> | null} */
  let remaking = null;
  function onFe() {
    const w = store.get().fe;
    if (!started || !w || w === fe || remaking) return;
    remaking = makeView(w).then(() => { remaking = null; if (store.get().fe !== fe) onFe(); else onResult(); });
  }

  /** Starts now if the panel is on screen, else when it first scrolls into sight. */
  function startWhenVisible() {
    if (started || io) return;
    if (typeof IntersectionObserver !== 'function') { start(); return; }
    status.textContent = 'The 3-D view starts when this panel is on screen.';
    const obs = new IntersectionObserver((entries) => {
      if (entries.some((e) => e.isIntersecting)) {
        obs.disconnect();
        start();
      }
    });
    io = obs;
    obs.observe(box);
  }

  /**
   * Without a WebGPU adapter wgpu draws with WebGL2 into the canvas's "webgl2" context; made
   * here first, that context has WEBGL_ATTRIBUTES instead of the defaults (an alpha channel and
   * a depth buffer nobody uses, each paid per pixel per frame by a software rasteriser).
   * @param {HTMLCanvasElement} c
   */
  async function prepareContext(c) {
    try {
      const gpu = /** @type {any} */ (navigator).gpu;
      if (gpu && (await gpu.requestAdapter())) return;
    } catch { /* no WebGPU: WebGL2 */ }
    try { c.getContext('webgl2', WEBGL_ATTRIBUTES); } catch { /* wgpu reports it */ }
  }

  /**
   * The canvas's CSS size, measured once per resize (fitCanvas clears it): the play loop places
   * labels every frame, and reading clientWidth after the previous frame's style writes forced
   * a style/layout pass each time.
   */
  let cssW = 0, cssH = 0;
  function canvasCss() {
    if (!cssW || !cssH) { cssW = canvas.clientWidth; cssH = canvas.clientHeight; }
    return [cssW, cssH];
  }

  /** Drawing-buffer size from the stage (device pixels). Returns true when it changed. */
  function fitCanvas() {
    cssW = 0;
    const w = Math.max(160, Math.round(stage.clientWidth || 640));
    const aspect = w < 520 ? 0.72 : 0.78;
    const h = Math.max(140, Math.round(Math.min(w * aspect, 520)));
    const { width: W, height: H } = S.backingSize(w, h, globalThis.devicePixelRatio || 1, MAX_DPR, MAX_BACKING_PX);
    box.dataset.backing = `${W}x${H}`;
    canvas.style.height = `${h}px`;
    if (canvas.width === W && canvas.height === H) return false;
    canvas.width = W;
    canvas.height = H;
    if (view) {
      try { view.resize(W, H); } catch (e) { status.textContent = `resize: ${errorText(e)}`; }
    }
    return true;
  }

  /** Sets the renderer's camera to `to` (and the mirror used for the labels). */
  function moveCamera(to) {
    if (!view) return;
    view.setCamera(to.target[0], to.target[1], to.target[2], to.yaw, to.pitch, to.distance);
    cam = to;
  }

  /** The mirror of a camera returned by the renderer ([tx, ty, tz, yaw, pitch, distance]). */
  function cameraOf(/** @type {Float64Array} */ c) {
    return { target: [c[0], c[1], c[2]], yaw: c[3], pitch: c[4], distance: c[5], fov: cam ? cam.fov : S.defaultCamera(0.05).fov };
  }

  function poses() {
    const r = store.get().result;
    if (!r || !r.angles) return null;
    const { alpha, beta, gamma } = r.angles;
    const a = r.analysis;
    return S.flapSamples(alpha.length, a.sim.sample_rate_hz, a.sim.flap_freq_hz, 32).map((i) => [alpha[i], beta[i], gamma[i]]);
  }

  /**
   * Fits the camera to the whole stroke with the renderer's own fit (WingView.fitPoints: the
   * target centres the stroke, the distance is the smallest that keeps every pose inside):
   * from each of a few view directions when `search`, keeping the most wing on screen; else
   * from the current direction.
   */
  function fit(search) {
    const v = view;
    if (!v || !fe || userCamera) return;
    const ps = poses();
    if (!ps) return;
    // The drawn deflection can be astronomically large (in a parametric instability the
    // response grows every flap: ~1e42 m after 2 s at f_d = 54.5 Hz); frame at most two spans of it.
    const span = S.spanOf(fe.nodes);
    const drawn = (runDeflection || 0) * exaggeration();
    const lift = Number.isFinite(drawn) ? Math.min(drawn, 2 * span) : 2 * span;
    const ol = S.outline(fe.nodes);
    const pts = Float32Array.from(S.posePoints(ol.nodes, ps, { lift: lift + ol.zmax }));
    if (search || !fitKey) {
      const fitFrom = (/** @type {S.Camera} */ c) => { moveCamera(c); return cameraOf(v.fitPoints(pts, FIT_MARGIN)); };
      const best = S.bestView(span, fe.nodes, fe.triangles, ps, canvas.width, canvas.height, { lift, fit: fitFrom });
      if (!best) return;
      moveCamera(best.camera);
      box.dataset.coverage = best.coverage.toFixed(3);
    } else {
      cam = cameraOf(v.fitPoints(pts, FIT_MARGIN));
    }
    fitKey = 'fitted';
  }

  function exaggeration() {
    return 10 ** Number(exag.value);
  }

  function applyRange() {
    if (!view) return;
    const c = Number(colour.value);
    if (c === 5) applyField();
    if (c === SENSE_COLOUR) applySense();
    view.set_strain_range(c === 5 ? fieldLimit : c === SENSE_COLOUR ? 1 : c > 0 && ranges && ranges[c] > 0 ? ranges[c] : null);
  }

  /**
   * Colour 6: the sensing panel's detectability map (store `sense_map`: per node the position
   * 0…1 on that panel's log-D colour scale), uploaded once per map as the renderer's node field
   * with the limit 1 (0 → the colour map's grey middle, 1 → its dark red end). Sets
   * senseProblem when there is no map for this wing.
   */
  /** @type {any} the sense_map uploaded last (null: none) */
  let senseUp = null;
  /** @type {string | null} why there is no detectability map to show */
  let senseProblem = null;
  /** the map shown is for other settings (kinematics, modes) than the run drawn */
  let senseStale = false;
  function senseMapNow() {
    const s = store.get();
    const m = s.sense_map || null;
    senseProblem = !fe ? 'the FE wing is not ready yet'
      : !m ? 'no sensing result yet: open the Sensing panel (FE wing mode set) and wait for its map'
        : m.fe !== fe || m.n_nodes !== fe.n_nodes || m.field.length !== fe.nodes.length / 3 ? 'the sensing result is for another wing: keep the Sensing panel on screen until it has recomputed'
          : null;
    senseStale = !senseProblem && !!m && !!s.result && m.cfg_json !== JSON.stringify(s.result.cfg);
    return senseProblem ? null : m;
  }
  function applySense() {
    if (!view || !fe) return;
    const m = senseMapNow();
    if (fieldKey === 'sense' && senseUp === m) return;
    fieldKey = 'sense';
    senseUp = m;
    try {
      view.setNodeField(m ? m.field : new Float64Array(fe.nodes.length / 3), 1);
    } catch (e) {
      senseProblem = errorText(e);
    }
  }

  /** @type {{ x: number, y: number, ranks: number[] }[] | null} the sensor tags' grouping (redone at the text rate) */
  let sensorGroups = null;
  /** @type {HTMLElement[]} */
  const sensorDots = [];
  /** @type {HTMLElement[]} */
  const sensorTags = [];
  /**
   * Places the K sensors of `sense_map` on the drawn wing at pose `ang` and modal coordinates `q`
   * (each sensor is an FE node: its deflected position Σ_k φ_k q_k × exaggeration, rotated and
   * projected with the camera mirror; K ≤ 30, so this is a few hundred operations per frame).
   * The dots move every drawn frame; which sensors share a numbered tag is decided again only
   * when `regroup` (the text rate while playing) or the set changed. Moves only what moved a pixel.
   */
  function placeSensors(/** @type {number[]} */ ang, /** @type {ArrayLike<number>} */ q, /** @type {boolean} */ regroup) {
    const m = Number(colour.value) === SENSE_COLOUR && cam ? senseUp : null;
    if (!m || !fe || !m.sensors.length) {
      if (!sensorLayer.hidden) { sensorLayer.hidden = true; sensorLayer.dataset.sensors = '0'; }
      sensorGroups = null;
      return;
    }
    const [w, h] = canvasCss();
    const pr = S.projector(/** @type {S.Camera} */ (cam), w, h);
    const { nodes, shapes } = fe;
    const n = nodes.length / 3;
    const nm = shapes ? Math.min(q.length, Math.floor(shapes.length / n)) : 0;
    const ex = exaggeration();
    const pts = m.sensors.map((/** @type {any} */ sn) => {
      const i = sn.node;
      let dz = 0;
      for (let k = 0; k < nm; k++) dz += /** @type {ArrayLike<number>} */ (shapes)[k * n + i] * q[k];
      const p = S.rotate(ang[0], ang[1], ang[2], [nodes[3 * i], nodes[3 * i + 1], nodes[3 * i + 2] + ex * dz]);
      const sp = pr(p[0], p[1], p[2]);
      return { x: sp ? sp[0] : NaN, y: sp ? sp[1] : NaN, rank: sn.rank };
    });
    while (sensorDots.length < pts.length) {
      const d = el('span', { class: 'wl-w3-sdot' });
      d.style.willChange = 'transform';
      sensorDots.push(d);
      sensorLayer.append(d);
    }
    pts.forEach((p, j) => {
      const d = sensorDots[j];
      const ok = Number.isFinite(p.x) && Number.isFinite(p.y) && p.x >= 0 && p.y >= 0 && p.x <= w && p.y <= h;
      if (d.hidden !== !ok) d.hidden = !ok;
      if (d.dataset.rank !== String(p.rank)) d.dataset.rank = String(p.rank);
      const tf = ok ? `translate(${Math.round(p.x - 3)}px, ${Math.round(p.y - 3)}px)` : '';
      if (ok && d.style.transform !== tf) d.style.transform = tf;
    });
    for (let j = pts.length; j < sensorDots.length; j++) sensorDots[j].hidden = true;
    const byRank = new Map(pts.map((p) => [p.rank, p]));
    if (regroup || !sensorGroups || sensorGroups.reduce((a, g) => a + g.ranks.length, 0) !== pts.length || sensorGroups.some((g) => !byRank.has(g.ranks[0]))) {
      sensorGroups = clusterMarkers(pts.filter((p) => Number.isFinite(p.x) && Number.isFinite(p.y)), 22);
    }
    while (sensorTags.length < sensorGroups.length) {
      const t = el('span', { class: 'wl-w3-stag' });
      t.style.willChange = 'transform';
      sensorTags.push(t);
      sensorLayer.append(t);
    }
    sensorGroups.forEach((g, j) => {
      const t = sensorTags[j];
      const p = byRank.get(g.ranks[0]);
      const label = groupLabel(g.ranks, 6);
      if (t.textContent !== label) { t.textContent = label; t.dataset.ranks = g.ranks.join(','); t.title = `sensor${g.ranks.length > 1 ? 's' : ''} ${label} of the greedy placement (1 = chosen first)`; }
      // the tag sits up and to the right of its first sensor, kept inside the canvas
      const ok = !!p && p.x >= 0 && p.y >= 0 && p.x <= w && p.y <= h;
      if (t.hidden !== !ok) t.hidden = !ok;
      if (!ok || !p) return;
      const tx = Math.round(Math.min(w - 8 * label.length - 12, p.x + 5)), ty = Math.round(Math.max(0, p.y - 20));
      const tf = `translate(${tx}px, ${ty}px)`;
      if (t.style.transform !== tf) t.style.transform = tf;
    });
    for (let j = sensorGroups.length; j < sensorTags.length; j++) sensorTags[j].hidden = true;
    if (sensorLayer.hidden) sensorLayer.hidden = false;
    sensorLayer.dataset.sensors = String(pts.length);
  }

  /**
   * Colour 5: the whole-run strain map of the strain panel (store `strain_map`), uploaded to the
   * renderer once per run and choice (WingView.setNodeField with the limit S.mapLimit, as on the
   * panel's planform map).
   */
  let fieldKey = '';
  /** @type {string | null} */
  let fieldProblem = null;
  /** @type {ReturnType<typeof setTimeout> | undefined} */
  let fieldTimer;
  function applyField(force = false) {
    const s = store.get();
    if (!view || !fe || !s.result) return;
    const map = s.strain_map || S.DEFAULT_MAP;
    const key = `${map.component}/${map.stat}`;
    if (fieldKey === key && fieldResult === s.result) return;
    // A peak map is slow (see PEAK_DELAY_MS): made once the run stops changing, unless the
    // strain panel already made it; the previous map stays drawn meanwhile.
    if (s.modes === 'fe' && map.stat === 'peak' && !force && !S.cachedStrainMap(fe, s.result, map)) {
      clearTimeout(fieldTimer);
      fieldTimer = setTimeout(() => { applyField(true); draw(); }, PEAK_DELAY_MS);
      return;
    }
    fieldKey = key;
    fieldResult = s.result;
    const field = s.modes === 'fe' ? S.strainMap(fe, s.result, map, strainFieldOf(engine)) : null;
    fieldProblem = field ? null : s.modes === 'fe' ? 'the wing and the run do not match yet' : 'the paper mode set has no whole-wing strain (choose the FE wing)';
    try {
      fieldLimit = field ? S.mapLimit(field) : null;
      view.setNodeField(field || new Float64Array(fe.nodes.length / 3), fieldLimit);
    } catch (e) {
      fieldProblem = errorText(e);
    }
    fieldLabel = `${S.MAP_LABELS[map.stat]} of ${S.MAP_LABELS[map.component]}`;
  }
  /** @type {any} */
  let fieldResult = null;
  let fieldLabel = '';
  /** @type {number | null} the map's colour limit (S.mapLimit, as on the strain panel's map) */
  let fieldLimit = null;

  /** New analysis: time range now; colour ranges, run deflection and camera fit on the next frame. */
  function onResult() {
    const s = store.get();
    const r = s.result;
    if (!r) return;
    const a = r.analysis;
    const dur = a.sim.t[a.sim.t.length - 1] || 0;
    time.max = String(dur);
    time.step = String(1 / a.sim.sample_rate_hz);
    if (s.t3d != null && s.t3d > dur) store.set({ t3d: 0 });
    if (!exagTouched) exag.value = s.modes === 'fe' ? '0' : '1';
    dirty = true;
    if (!view || !fe) return;
    if (!pending) pending = requestAnimationFrame(() => { pending = 0; if (!store.get().playing) draw(); else refresh(); });
  }

  /** The per-run work, kept out of the slider's own redraw: ranges, deflection, camera fit. */
  function refresh() {
    if (!dirty || !view || !fe) return;
    dirty = false;
    const s = store.get();
    if (!s.result) return;
    const a = s.result.analysis;
    const qs = a.sim.modes.map((m) => m.q.total);
    const n = fe.nodes.length / 3;
    // Display ranges: with 3+ modes over RANGE_SAMPLES states (exact hull vertices for 1–2).
    // The core lists those states' samples (Analysis.extreme_samples, computed in the live
    // worker), so this redraw costs (states × nodes), not a pass over every sample.
    const states = a.extreme_samples ? S.statesAt(qs, a.extreme_samples) : S.extremeStates(qs, RANGE_SAMPLES);
    ranges = S.strainRangesAt(fe.strain_nodes, n, states, S.RANGE_QUANTILE);
    runDeflection = S.maxDeflectionAt(fe.shapes, n, states);
    applyRange();
    // Refit when the stroke, the canvas or the drawn deflection (true × exaggeration) changes.
    const lift = runDeflection * exaggeration();
    const liftKey = lift > 0 ? Math.round(Math.log10(lift) * 8) : -99;
    const key = `${s.alpha0}/${s.beta0}/${s.gamma0}/${s.alpha_phase}/${s.beta_phase}/${s.gamma_phase}/${canvas.width}x${canvas.height}/${liftKey}`;
    if (key !== fitKey) {
      fit(!fitKey);
      fitKey = key;
    }
  }

  function speedFactor() {
    const r = store.get().result;
    const fd = r ? r.analysis.sim.flap_freq_hz : 25;
    if (speed.value === 'flap1') return 1 / fd;
    if (speed.value === 'beat4') {
      const b = r ? beatInfo(r.analysis, r.k) : null;
      return b && b.period ? b.period / 4 : 1 / fd;
    }
    return Number(speed.value);
  }

  function describeTime(/** @type {number} */ tShown = store.get().t3d ?? 0) {
    const s = store.get();
    const r = s.result;
    const fd = r ? r.analysis.sim.flap_freq_hz : 25;
    const t = tShown;
    const f = speedFactor();
    const b = r ? beatInfo(r.analysis, r.k) : null;
    setText(timeText, `t = ${t.toFixed(4)} s · flap ${fmt(fd, 3)} Hz shown at ${fmt(fd * f, 3)} Hz` + (b && b.period ? ` · one beat every ${fmt(b.period / f, 3)} s` : ''));
    time.setAttribute('aria-valuetext', `${t.toFixed(4)} s`);
  }

  function setPlaying(on) {
    playBtn.textContent = on ? 'Pause' : 'Play';
    playBtn.setAttribute('aria-pressed', String(on));
    if (on) startLoop();
    else stopLoop('stopped');
  }

  const loopState = () => (document.hidden ? 'paused-hidden' : 'paused-offscreen');

  /** Ends the play loop; the instant it showed goes to the store (the cursor, the time slider). */
  function stopLoop(/** @type {string} */ why) {
    if (raf) cancelAnimationFrame(raf);
    raf = 0;
    box.dataset.loop = why;
    if (playT != null) {
      const t = playT;
      playT = null;
      if (store.get().t3d !== t) store.set({ t3d: t });
    }
  }

  /**
   * The play loop: per animation frame only the pose and q_k go to the GPU (WingView.setPose,
   * one uniform block); the texts follow every TEXT_MS and the store every PUSH_MS. It runs
   * only while the panel is on screen and the tab visible; a frame whose sample is the one
   * already drawn is skipped, and on a slow machine frames are drawn ≈ 30 per second.
   */
  function startLoop() {
    if (!view || raf || !store.get().playing) return;
    if (!onScreen || document.hidden) { stopLoop(loopState()); return; }
    box.dataset.loop = 'running';
    playT = store.get().t3d ?? 0;
    let prev = performance.now();
    let lastDraw = 0;
    let avg = 0;
    const step = (/** @type {number} */ now) => {
      raf = 0;
      if (!store.get().playing) { stopLoop('stopped'); return; }
      if (!onScreen || document.hidden) { stopLoop(loopState()); return; }
      raf = requestAnimationFrame(step);
      if (avg > SLOW_FRAME_MS && now - lastDraw < CAPPED_FRAME_MS) return;
      if (lastDraw) avg = avg ? 0.9 * avg + 0.1 * (now - lastDraw) : now - lastDraw;
      lastDraw = now;
      const dur = Number(time.max) || 0;
      let t = (playT ?? 0) + ((now - prev) / 1000) * speedFactor();
      prev = now;
      if (t > dur) t = 0;
      playT = t;
      draw(t);
      if (now - lastPush >= PUSH_MS) {
        lastPush = now;
        pushing = true;
        try { store.set({ t3d: t }); } finally { pushing = false; }
      }
    };
    raf = requestAnimationFrame(step);
  }

  /** Pauses the play loop off screen and in a hidden tab; resumes it when seen again. */
  function watchVisibility() {
    if (typeof IntersectionObserver === 'function') {
      vis = new IntersectionObserver((entries) => {
        onScreen = entries[entries.length - 1].isIntersecting;
        if (onScreen) startLoop();
      });
      vis.observe(box);
    }
    document.addEventListener('visibilitychange', onVisibility);
  }
  function onVisibility() { if (!document.hidden) startLoop(); }


  function bindCamera() {
    /** @type {number[] | null} */
    let last = null;
    /** @type {number[] | null} where the pointer went down (a click: up within 4 px of it) */
    let down = null;
    canvas.addEventListener('pointerdown', (e) => { last = [e.clientX, e.clientY]; down = last; canvas.setPointerCapture(e.pointerId); });
    canvas.addEventListener('pointerup', (e) => {
      if (down && Math.hypot(e.clientX - down[0], e.clientY - down[1]) < 4) {
        const b = canvas.getBoundingClientRect();
        pickAt(e.clientX - b.left, e.clientY - b.top);
      }
      down = null;
    });
    canvas.addEventListener('pointermove', (e) => {
      if (!last || !view) return;
      const dx = e.clientX - last[0], dy = e.clientY - last[1];
      view.orbit(dx, dy);
      if (cam) cam = S.orbit(cam, dx, dy);
      userCamera = true;
      last = [e.clientX, e.clientY];
      draw();
    });
    const end = () => { last = null; };
    canvas.addEventListener('pointerup', end);
    canvas.addEventListener('pointercancel', end);
    canvas.addEventListener('wheel', (e) => {
      if (!view) return;
      e.preventDefault();
      const f = e.deltaY > 0 ? 1.1 : 1 / 1.1;
      view.zoom(f);
      cam = S.zoom(cam, f);
      userCamera = true;
      draw();
    }, { passive: false });
    canvas.addEventListener('keydown', (e) => {
      if (!view) return;
      if (e.key === ' ') {
        e.preventDefault();
        store.set({ playing: !store.get().playing });
      } else if (view.key(e.key)) {
        e.preventDefault();
        cam = S.key(cam, e.key) || cam;
        userCamera = true;
        draw();
      }
    });
  }

  /** The drawn wing's nodes on screen at the instant shown (CSS pixels), for picking and the point mark. */
  function screenNodes(/** @type {number} */ t = playT ?? store.get().t3d ?? 0) {
    const s = store.get();
    const r = s.result;
    if (!fe || !cam || !r || !r.angles) return null;
    const a = r.analysis;
    const i = Math.min(a.sim.t.length - 1, Math.max(0, Math.round(t * a.sim.sample_rate_hz)));
    const ang = [r.angles.alpha[i], r.angles.beta[i], r.angles.gamma[i]];
    const q = a.sim.modes.map((m) => m.q.total[i]);
    const [w, h] = canvasCss();
    return { ang, q, proj: S.projectNodes(fe.nodes, fe.shapes, q, exaggeration(), ang, cam, w, h) };
  }

  /**
   * A click on the drawn wing at (x, y) CSS pixels: the front-most triangle there gives the
   * planform point (undeformed x, y), which becomes the strain point (mm). FE wings only.
   */
  function pickAt(x, y) {
    const s = store.get();
    if (!fe || s.modes !== 'fe') {
      status.textContent = 'The strain point can be chosen on an FE wing only (the paper’s strains exist only at P).';
      return null;
    }
    const sn = screenNodes();
    if (!sn) return null;
    const hit = S.pick(fe.nodes, fe.triangles, sn.proj, x, y);
    if (!hit) return null;
    /** @type {[number, number]} */
    const mm = [Math.round(hit.x * 1e6) / 1e3, Math.round(hit.y * 1e6) / 1e3];
    store.set({ strain_point: mm });
    return mm;
  }

  /**
   * Where the planform point (x, y) mm is drawn now (CSS px in the canvas): its triangle of the
   * flat planform gives barycentric weights, applied to the drawn (cambered, deflected, rotated,
   * projected) nodes. Null when the point is off the wing or behind the eye.
   */
  function drawnPoint(xmm, ymm, /** @type {number | undefined} */ t = undefined) {
    if (!fe) return null;
    const sn = screenNodes(t);
    if (!sn) return null;
    const hit = planformHit(xmm, ymm);
    if (!hit) return null;
    let px = 0, py = 0;
    hit.ids.forEach((i, j) => { px += hit.w[j] * sn.proj.xy[2 * i]; py += hit.w[j] * sn.proj.xy[2 * i + 1]; });
    return Number.isFinite(px) && Number.isFinite(py) ? [px, py] : null;
  }

  /** @type {{ fe: any, key: string, hit: any } | null} the last planform pick (fixed per wing and point) */
  let hitCache = null;
  /** The flat planform's triangle and barycentric weights at (x, y) mm (cached per wing and point). */
  function planformHit(/** @type {number} */ xmm, /** @type {number} */ ymm) {
    if (!fe) return null;
    const key = `${xmm}/${ymm}`;
    if (hitCache && hitCache.fe === fe && hitCache.key === key) return hitCache.hit;
    const n = fe.nodes.length / 3;
    const top = { xy: new Float64Array(2 * n), depth: new Float64Array(n) };
    for (let i = 0; i < n; i++) { top.xy[2 * i] = fe.nodes[3 * i]; top.xy[2 * i + 1] = fe.nodes[3 * i + 1]; }
    const hit = S.pick(fe.nodes, fe.triangles, top, xmm * 1e-3, ymm * 1e-3);
    hitCache = { fe, key, hit };
    return hit;
  }

  /** Places the strain-point ring over the drawn wing (hidden for the paper mode set). */
  function placePoint(/** @type {number | undefined} */ t = undefined) {
    const s = store.get();
    const p = s.strain_point || (fe && fe.strain_point_mm);
    if (!fe || !p || s.modes !== 'fe' || !cam) { pointMark.hidden = true; return; }
    const at = drawnPoint(p[0], p[1], t);
    const [cw, ch] = canvasCss();
    const ok = !!at && at[0] > 0 && at[1] > 0 && at[0] < cw && at[1] < ch;
    pointMark.hidden = !ok;
    if (at && ok) pointMark.style.transform = `translate(${Math.round(at[0] - 7)}px, ${Math.round(at[1] - 7)}px)`;
    const title = `strain point (${p[0]}, ${p[1]}) mm`;
    if (pointMark.title !== title) pointMark.title = title;
  }

  /** Moves the in-view labels to the projected axis tips (src/render/gpu.rs scene_geometry). */
  function placeSceneLabels(ang) {
    if (!cam || !fe) return;
    const l = S.spanOf(fe.nodes);
    const [w, h] = canvasCss();
    const pr = S.projector(cam, w, h);
    const fr = (p) => S.rotate(ang[0], ang[1], 0, p);
    const pts = [
      [0.35 * l, 0, 0], [0, 0.35 * l, 0], [0, 0, 0.35 * l],
      fr([0.7 * l, 0, 0]), fr([0, 0.45 * l, 0]), fr([0, 0, 0.45 * l]),
      [0, 0.6 * l, 0], [1.1 * l, 0, 0.9 * l],
    ];
    const show = { fixed: showAxes.checked, wing: showAxes.checked, body: showBody.checked, plane: showPlane.checked };
    // the plane's label goes to the first of its corners / edge midpoints that is on screen
    /**
     * @param {number[] | null} p
     * @returns {p is number[]}
     */
    const inView = (p) => !!p && p[0] > 10 && p[0] < w - 90 && p[1] > 20 && p[1] < h - 10;
    // ... the one farthest from the wing (its middle, at this pose), so it does not sit on the wing
    const mid = pr(...S.rotate(ang[0], ang[1], ang[2], [0.45 * l, -0.2 * l, 0])) || [w / 2, h / 2];
    const planeAt = [[1.1 * l, 0, 0.9 * l], [1.1 * l, 0, -0.9 * l], [0.5 * l, 0, 0.9 * l], [0.5 * l, 0, -0.9 * l], [-0.1 * l, 0, 0.9 * l], [-0.1 * l, 0, -0.9 * l], [1.1 * l, 0, 0]]
      .map((q) => pr(...q)).filter(inView)
      .sort((a, b) => Math.hypot(b[0] - mid[0], b[1] - mid[1]) - Math.hypot(a[0] - mid[0], a[1] - mid[1]))[0];
    LABELS.forEach(([, kind], j) => {
      const e = labelEls[j];
      const p = kind === 'plane' ? planeAt : pr(...pts[j]);
      const ok = show[kind] && p && p[0] > 4 && p[0] < w - 20 && p[1] > 8 && p[1] < h - 4;
      e.hidden = !ok;
      if (ok) e.style.transform = `translate(${Math.round(p[0] + 3)}px, ${Math.round(p[1] - 14)}px)`;
    });
  }

  /** Sets `e`'s text only when it differs (an unchanged text costs no layout or paint). */
  function setText(/** @type {HTMLElement} */ e, /** @type {string} */ t) { if (e.textContent !== t) e.textContent = t; }

  /**
   * Draws the frame at `tPlay` (the play loop) or at the store's t3d. While playing only the
   * pose and q_k change per frame (WingView.setPose); the legend and the texts are redone every
   * TEXT_MS, and a frame showing the sample already drawn is skipped.
   * @param {number} [tPlay]
   */
  function draw(tPlay) {
    const s = store.get();
    const r = s.result;
    const inLoop = tPlay != null;
    const tNow = inLoop ? tPlay : (playT ?? s.t3d ?? 0);
    const now = performance.now();
    const texts = !inLoop || now - lastText >= TEXT_MS;
    if (texts || now - lastPush >= PUSH_MS) {
      describeTime(tNow);
      time.value = String(tNow);
    }
    if (!view || !fe || !r || !r.angles) return;
    refresh();
    const a = r.analysis;
    const n = a.sim.t.length;
    const i = Math.min(n - 1, Math.max(0, Math.round(tNow * a.sim.sample_rate_hz)));
    if (inLoop && i === lastLoopI && !texts) return;
    lastLoopI = inLoop ? i : -1;
    const ang = [r.angles.alpha[i], r.angles.beta[i], r.angles.gamma[i]];
    const modes = a.sim.modes;
    if (qBuf.length !== modes.length) qBuf = new Float64Array(modes.length);
    for (let k = 0; k < modes.length; k++) qBuf[k] = modes[k].q.total[i];
    const q = qBuf;
    const isFe = s.modes === 'fe';
    const ex = exaggeration();
    /** @type {any} */
    let lg = null;
    try {
      const cm = Number(colour.value);
      if (texts || typeof view.setPose !== 'function') lg = view.set_frame(ang[0], ang[1], ang[2], q, ex, cm === SENSE_COLOUR ? 5 : cm);
      else view.setPose(ang[0], ang[1], ang[2], q);
      view.render();
    } catch (e) {
      status.textContent = `render: ${errorText(e)}`;
      return;
    }
    frames += 1;
    box.dataset.frames = String(frames);
    placeSceneLabels(ang);
    placePoint(tNow);
    placeSensors(ang, q, texts);
    if (!lg) return;
    lastText = now;
    box.dataset.modes = String(q.length);
    const d = lg.max_deflection_m;
    setText(exagText, `×${fmt(ex, 3)}`);
    exag.setAttribute('aria-valuetext', `deflection drawn ${fmt(ex, 3)} times true scale`);
    setText(status,
      `${view.backend() === 'webgpu' ? 'WebGPU' : 'WebGL2'} · ${view.triangles()} triangles · ` +
      `α ${ang[0].toFixed(3)}, β ${ang[1].toFixed(3)}, γ ${ang[2].toFixed(3)} rad · ` +
      (isFe ? `true largest deflection ${fmt(d * 1e3, 3)} mm, drawn ×${fmt(ex, 3)}` : `largest deflection ${fmt(d * 1e3, 3)} (paper q units, not SI), drawn ×${fmt(ex, 3)}`));
    const deflText = runDeflection == null ? '' : isFe
      ? `Largest deflection over the whole run: ${fmt(runDeflection * 1e3, 3)} mm (true scale, SI), about ${fmt((100 * runDeflection) / S.spanOf(fe.nodes), 2)} % of the ${fmt(S.spanOf(fe.nodes) * 1e3, 3)} mm span.`
      : `Paper mode set: Table 4’s a_k are not SI, so these deflections are in paper units (≈ 10× below SI), not mm; choose the FE wing mode set for millimetres.`;
    if (defl.dataset.text !== deflText) {
      defl.dataset.text = deflText;
      if (isFe) defl.textContent = deflText;
      else defl.replaceChildren(rich(deflText));
    }
    drawLegend(lg, isFe);
    const wingName = s.wing && s.wing.label ? s.wing.label : 'synthetic Manduca-like outline, not digitised';
    const noteText = isFe
      ? `The shell-FE wing (${wingName}; ${fe.n_nodes} nodes) with all ${a.sim.modes.length} of its modes driven by the simulated q_k(t): deflection Σ_k φ_k q_k(t); strain per the FE modal strain fields (dimensionless, true scale). Click the wing to choose the strain point (ring).`
      : `Paper mode set: the paper's q_k(t) (Table 4 units, not SI) drawn on the shell-FE wing's first ${a.sim.modes.length} mode shapes, so shapes and timing are right and magnitudes are not physical. Choose the FE wing mode set for SI deflection and strain.`;
    if (note.dataset.text !== noteText) {
      note.dataset.text = noteText;
      note.replaceChildren(rich(noteText));
    }
    setText(summary, `Wing at t = ${tNow.toFixed(4)} s: roll α ${ang[0].toFixed(3)}, pitch β ${ang[1].toFixed(3)}, yaw γ ${ang[2].toFixed(3)} rad; deflection now ${fmt(d * 1e3, 3)} ${isFe ? 'mm' : 'paper units'}, largest over the run ${fmt((runDeflection || 0) * 1e3, 3)}. ${legendText.textContent}`);
  }

  function drawLegend(lg, isFe) {
    if (!view) return;
    // Redrawn only when it changes (it is fixed for a run while the wing plays).
    const sensing = Number(colour.value) === SENSE_COLOUR;
    const key = `${lg.component}/${lg.min}/${lg.max}/${isFe}/${fieldProblem}/${fieldLabel}/${sensing ? `${senseProblem}/${senseStale}/${senseUp ? senseUp.max : ''}/${senseUp ? senseUp.mode : ''}/${senseUp ? senseUp.sensors.length : ''}` : ''}`;
    if (key === legendKey) return;
    legendKey = key;
    const c2 = context2d(legend);
    const { width: w, height: h } = legend;
    c2.clearRect(0, 0, w, h);
    const stops = view.legend_stops();
    if (!stops.length || lg.component === 'none') {
      legend.hidden = true;
      legendText.textContent = 'plain shading';
      return;
    }
    legend.hidden = false;
    const lo = stops[0], hi = stops[stops.length - 4];
    const g = c2.createLinearGradient(0, 0, w, 0);
    for (let j = 0; j < stops.length; j += 4) {
      const f = hi > lo ? (stops[j] - lo) / (hi - lo) : 0;
      const c = stops.slice(j + 1, j + 4).map((v) => Math.round(255 * Math.min(1, Math.max(0, v))));
      g.addColorStop(Math.min(1, Math.max(0, f)), `rgb(${c[0]},${c[1]},${c[2]})`);
    }
    c2.fillStyle = g;
    c2.fillRect(0, 0, w, h);
    const units = isFe ? 'strain (–)' : '(FE strain × paper q: not physical)';
    legendText.dataset.min = String(lg.min);
    legendText.dataset.max = String(lg.max);
    if (sensing) { legendText.replaceChildren(rich(senseLegend())); return; }
    legendText.textContent = lg.component === 'field'
      ? (fieldProblem ? `no strain map: ${fieldProblem}` : `${fieldLabel}: ${fmt(lg.min, 3)} … ${fmt(lg.max, 3)} strain (–), one map for the whole run (the hottest ${Math.round(100 * (1 - S.RANGE_QUANTILE))} % of the nodes saturate)`)
      : `${lg.component}: ${fmt(lg.min, 3)} … ${fmt(lg.max, 3)} ${units}, fixed for the whole run`;
  }

  /** The legend of colour 6: what the colours and the numbered tags mean, and on which scale. */
  function senseLegend() {
    const m = senseUp;
    if (senseProblem || !m) return `No detectability map: ${senseProblem || 'no sensing result yet: open the Sensing panel'}.`;
    const axis = m.body_rate.findIndex((/** @type {number} */ v) => v !== 0);
    const rate = axis >= 0 ? `ω_b = ${fmt(m.body_rate[axis], 3)} rad/s about body axis ${'xyz'[axis]}` : 'ω_b = 0';
    if (!(m.max > 0)) return `Rotation detectability D (Sensing panel, ${rate}): D = 0 everywhere, no rotation, nothing to detect.`;
    const scale = m.mode === 'absolute'
      ? `fixed log scale: grey = D ≤ 10^{${m.lo}}, dark red = D ≥ 10^{${m.hi}}; largest on this wing ${fmt(m.max, 3)}`
      : `log scale relative to this wing: grey = D ≤ ${fmt(10 ** m.lo, 3)} (${fmt(m.hi - m.lo, 2)} decade below the largest), dark red = the largest, ${fmt(m.max, 3)}`;
    return `Rotation detectability D per node from the Sensing panel (${rate}), ${scale}: the panel’s scale in this view’s colours (D = 1: the rotation’s strain as large as the 1 % stroke variation plus noise). Numbered tags: the ${m.sensors.length} best sensors (1 = chosen first) on the deflected wing, drawn on top even where the wing hides them.${senseStale ? ' This map is for earlier settings (kinematics or modes): the Sensing panel recomputes it when it is on screen.' : ''}`;
  }

  /** A new detectability map from the sensing panel; its "Show on the 3-D wing" button sets colour 6. */
  let seenShow = 0;
  function onSenseMap() {
    const m = store.get().sense_map;
    if (m && m.show > seenShow) {
      seenShow = m.show;
      colour.value = String(SENSE_COLOUR);
      // the legend says what the colours and tags are: shown even where the options start folded (phones)
      options.open = true;
      fieldKey = '';
      sensorGroups = null;
      if (!started) startWhenVisible();
      if (typeof box.scrollIntoView === 'function') box.scrollIntoView({ block: 'nearest' });
    }
    if (view && Number(colour.value) === SENSE_COLOUR) { sensorGroups = null; applyRange(); draw(); }
  }

  const unsub = [
    store.subscribe(['result'], onResult),
    store.subscribe(['sense_map'], onSenseMap),
    store.subscribe(['fe'], onFe),
    store.subscribe(['strain_map'], () => { fieldKey = ''; if (view && Number(colour.value) === 5) { applyRange(); draw(); } }),
    store.subscribe(['strain_point'], () => { if (view) placePoint(); }),
    // (a time set from outside while playing — the time slider, a click on the responses plot —
    // becomes the loop's time, so a pause then keeps it)
    store.subscribe(['t3d'], (s) => { if (pushing) return; if (playT != null) playT = s.t3d ?? 0; if (view) draw(); else describeTime(); }),
    store.subscribe(['playing'], (s) => setPlaying(!!s.playing)),
  ];
  if (store.get().t3d == null) store.set({ t3d: 0.505 });
  watchVisibility();

  return {
    startWhenVisible,
    start,
    get view() { return view; },
    get t() { return playT ?? store.get().t3d ?? 0; },
    get camera() { return cam; },
    get ranges() { return ranges; },
    get frames() { return frames; },
    get fe() { return fe; },
    pickAt,
    /** Where the strain point is drawn (CSS px in the canvas), or null when hidden. */
    pointOnScreen() {
      if (pointMark.hidden) return null;
      const m = /translate\((-?\d+)px, (-?\d+)px\)/.exec(pointMark.style.transform);
      return m ? [Number(m[1]) + 7, Number(m[2]) + 7] : null;
    },
    /** CSS px of the planform point (x, y) mm on the drawn wing at the current instant (tests). */
    screenOf: drawnPoint,
    setTime(t) {
      const r = store.get().result;
      const dur = r ? r.analysis.sim.t[r.analysis.sim.t.length - 1] : 2;
      store.set({ playing: false, t3d: Math.min(dur, Math.max(0, Number.isFinite(t) ? t : 0)) });
    },
    setPlaying(on) { store.set({ playing: !!on }); },
    setLayout(mode) { narrowNow = mode === 'narrow'; options.open = !narrowNow && !focusedNow; },
    /** A focused screen (www/screens.js) starts with the view options folded; the full page open. */
    setScreen(screen) {
      const f = screen !== 'full';
      if (f === focusedNow) return;
      focusedNow = f;
      options.open = !narrowNow && !focusedNow;
    },
    destroy() {
      unsub.forEach((f) => f());
      store.set({ playing: false });
      if (io) io.disconnect();
      if (ro) ro.disconnect();
      if (vis) vis.disconnect();
      document.removeEventListener('visibilitychange', onVisibility);
      if (raf) cancelAnimationFrame(raf);
      clearTimeout(fieldTimer);
      if (view) view.free();
      view = null;
    },
  };
}
