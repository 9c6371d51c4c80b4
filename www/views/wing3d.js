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

export const title = '3-D wing';

/** Margin of the camera fit, as a fraction of the half-width and half-height (2 % of each side). */
const FIT_MARGIN = 0.04;

const COLOURS = [
  ['0', 'none (shading only)'],
  ['1', 'ε_x, spanwise strain'],
  ['2', 'ε_y, chordwise strain'],
  ['3', 'γ_xy, shear strain'],
  ['4', '|ε|, strain magnitude'],
];
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
  /** @type {IntersectionObserver | null} */
  let io = null;
  /** @type {ResizeObserver | null} */
  let ro = null;
  const box = el('div', { class: 'wl-wing3d-box', 'data-wing3d': '', 'data-state': 'loading' });
  if (!document.getElementById('wing3d')) box.id = 'wing3d';
  const summaryId = `${uid}-w3-sum`;
  const canvas = el('canvas', {
    class: 'wl-w3-canvas',
    tabindex: '0',
    role: 'img',
    'aria-label': `3-D view of the flexing wing. ${touch ? 'Drag to orbit, pinch or use the buttons to zoom.' : 'Drag, or use the arrow keys, to orbit; wheel or + and − to zoom; Space plays or pauses.'}`,
    'aria-describedby': summaryId,
    width: 640,
    height: 480,
  });
  // Labels drawn over the canvas at the projected tips of the axes and a corner of the stroke
  // plane (positions from the camera mirror; the legend below says the same in words).
  const LABELS = [
    ['I', 'fixed', 'rgb(200,110,110)'], ['J', 'fixed', 'rgb(110,190,110)'], ['K', 'fixed', 'rgb(130,150,230)'],
    ['I″', 'wing', 'rgb(255,90,80)'], ['J″', 'wing', 'rgb(100,255,100)'], ['K″', 'wing', 'rgb(120,165,255)'],
    ['body axis', 'body', 'rgb(220,220,220)'], ['stroke plane', 'plane', 'rgb(150,170,235)'],
  ];
  const overlay = el('div', { class: 'wl-w3-overlay', 'aria-hidden': 'true' });
  const labelEls = LABELS.map(([t, kind, c]) => {
    const e = el('span', { class: `wl-w3-label wl-w3-label-${kind}`, text: t });
    e.style.color = c;
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
  colour.addEventListener('change', () => { applyRange(); draw(); });
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
    fitCanvas();
    const renderer = engine.renderer;
    if (!renderer) return;
    try {
      view = await renderer.createFromArrays(canvas, fe.nodes, fe.triangles, fe.shapes, fe.strain_nodes);
    } catch (e) {
      unavailable(errorText(e));
      return;
    }
    cam = S.defaultCamera(S.spanOf(fe.nodes));
    box.dataset.state = 'ready';
    box.dataset.backend = view.backend();
    if (typeof ResizeObserver === 'function') {
      ro = new ResizeObserver(() => { if (fitCanvas()) { fit(false); draw(); } });
      ro.observe(stage);
    }
    onResult();
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

  /** Drawing-buffer size from the stage (device pixels). Returns true when it changed. */
  function fitCanvas() {
    const w = Math.max(160, Math.round(stage.clientWidth || 640));
    const aspect = w < 520 ? 0.72 : 0.78;
    const h = Math.max(140, Math.round(Math.min(w * aspect, 520)));
    const dpr = Math.min(2, globalThis.devicePixelRatio || 1);
    const W = Math.round(w * dpr), H = Math.round(h * dpr);
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
    view.set_strain_range(c > 0 && ranges && ranges[c] > 0 ? ranges[c] : null);
  }

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
    ranges = S.strainRanges(fe.strain_nodes, n, qs);
    runDeflection = S.maxDeflection(fe.shapes, n, qs);
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

  function describeTime() {
    const s = store.get();
    const r = s.result;
    const fd = r ? r.analysis.sim.flap_freq_hz : 25;
    const t = s.t3d ?? 0;
    const f = speedFactor();
    const b = r ? beatInfo(r.analysis, r.k) : null;
    timeText.textContent = `t = ${t.toFixed(4)} s · flap ${fmt(fd, 3)} Hz shown at ${fmt(fd * f, 3)} Hz` + (b && b.period ? ` · one beat every ${fmt(b.period / f, 3)} s` : '');
    time.setAttribute('aria-valuetext', `${t.toFixed(4)} s`);
  }

  function setPlaying(on) {
    playBtn.textContent = on ? 'Pause' : 'Play';
    playBtn.setAttribute('aria-pressed', String(on));
    if (on && view && !raf) {
      let prev = performance.now();
      const step = (now) => {
        const s = store.get();
        if (!s.playing) { raf = 0; return; }
        const dur = Number(time.max) || 0;
        let t = (s.t3d ?? 0) + ((now - prev) / 1000) * speedFactor();
        prev = now;
        if (t > dur) t = 0;
        store.set({ t3d: t });
        raf = requestAnimationFrame(step);
      };
      raf = requestAnimationFrame(step);
    }
  }

  function bindCamera() {
    /** @type {number[] | null} */
    let last = null;
    canvas.addEventListener('pointerdown', (e) => { last = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); });
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

  /** Moves the in-view labels to the projected axis tips (src/render/gpu.rs scene_geometry). */
  function placeSceneLabels(ang) {
    if (!cam || !fe) return;
    const l = S.spanOf(fe.nodes);
    const w = canvas.clientWidth, h = canvas.clientHeight;
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

  /** Draws the frame at the store's t3d. Cheap: no wasm call besides the renderer's own. */
  function draw() {
    const s = store.get();
    const r = s.result;
    describeTime();
    time.value = String(s.t3d ?? 0);
    if (!view || !fe || !r || !r.angles) return;
    refresh();
    const a = r.analysis;
    const n = a.sim.t.length;
    const i = Math.min(n - 1, Math.max(0, Math.round((s.t3d ?? 0) * a.sim.sample_rate_hz)));
    const ang = [r.angles.alpha[i], r.angles.beta[i], r.angles.gamma[i]];
    const q = new Float64Array(a.sim.modes.map((m) => m.q.total[i]));
    const isFe = s.modes === 'fe';
    const ex = exaggeration();
    let lg;
    try {
      lg = view.set_frame(ang[0], ang[1], ang[2], q, ex, Number(colour.value));
      view.render();
    } catch (e) {
      status.textContent = `render: ${errorText(e)}`;
      return;
    }
    frames += 1;
    box.dataset.frames = String(frames);
    placeSceneLabels(ang);
    const d = lg.max_deflection_m;
    exagText.textContent = `×${fmt(ex, 3)}`;
    exag.setAttribute('aria-valuetext', `deflection drawn ${fmt(ex, 3)} times true scale`);
    status.textContent =
      `${view.backend() === 'webgpu' ? 'WebGPU' : 'WebGL2'} · ${view.triangles()} triangles · ` +
      `α ${ang[0].toFixed(3)}, β ${ang[1].toFixed(3)}, γ ${ang[2].toFixed(3)} rad · ` +
      (isFe ? `true largest deflection ${fmt(d * 1e3, 3)} mm, drawn ×${fmt(ex, 3)}` : `largest deflection ${fmt(d * 1e3, 3)} (paper q units, not SI), drawn ×${fmt(ex, 3)}`);
    defl.textContent = runDeflection == null ? '' : isFe
      ? `Largest deflection over the whole run: ${fmt(runDeflection * 1e3, 3)} mm (true scale, SI), about ${fmt((100 * runDeflection) / S.spanOf(fe.nodes), 2)} % of the ${fmt(S.spanOf(fe.nodes) * 1e3, 3)} mm span.`
      : `Paper mode set: Table 4’s a_k are not SI, so these deflections are in paper units (≈ 10× below SI), not mm; choose the FE wing mode set for millimetres.`;
    if (!isFe) defl.replaceChildren(rich(defl.textContent));
    drawLegend(lg, isFe);
    note.replaceChildren(rich(isFe
      ? `The shell-FE wing (synthetic Manduca-like outline, not digitised) with its first ${a.sim.modes.length} modes driven by the simulated q_k(t); strain per the FE modal strain fields (dimensionless, true scale).`
      : `Paper mode set: the paper's q_k(t) (Table 4 units, not SI) drawn on the shell-FE wing's first ${a.sim.modes.length} mode shapes, so shapes and timing are right and magnitudes are not physical. Choose the FE wing mode set for SI deflection and strain.`));
    summary.textContent = `Wing at t = ${(s.t3d ?? 0).toFixed(4)} s: roll α ${ang[0].toFixed(3)}, pitch β ${ang[1].toFixed(3)}, yaw γ ${ang[2].toFixed(3)} rad; deflection now ${fmt(d * 1e3, 3)} ${isFe ? 'mm' : 'paper units'}, largest over the run ${fmt((runDeflection || 0) * 1e3, 3)}. ${legendText.textContent}`;
  }

  function drawLegend(lg, isFe) {
    if (!view) return;
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
    legendText.textContent = `${lg.component}: ${fmt(lg.min, 3)} … ${fmt(lg.max, 3)} ${units}, fixed for the whole run`;
    legendText.dataset.min = String(lg.min);
    legendText.dataset.max = String(lg.max);
  }

  const unsub = [
    store.subscribe(['result'], onResult),
    store.subscribe(['t3d'], () => { if (view) draw(); else describeTime(); }),
    store.subscribe(['playing'], (s) => setPlaying(!!s.playing)),
  ];
  if (store.get().t3d == null) store.set({ t3d: 0.505 });

  return {
    startWhenVisible,
    start,
    get view() { return view; },
    get t() { return store.get().t3d ?? 0; },
    get camera() { return cam; },
    get ranges() { return ranges; },
    get frames() { return frames; },
    setTime(t) {
      const r = store.get().result;
      const dur = r ? r.analysis.sim.t[r.analysis.sim.t.length - 1] : 2;
      store.set({ playing: false, t3d: Math.min(dur, Math.max(0, Number.isFinite(t) ? t : 0)) });
    },
    setPlaying(on) { store.set({ playing: !!on }); },
    setLayout(mode) { options.open = mode !== 'narrow'; },
    destroy() {
      unsub.forEach((f) => f());
      store.set({ playing: false });
      if (io) io.disconnect();
      if (ro) ro.disconnect();
      if (raf) cancelAnimationFrame(raf);
      if (view) view.free();
      view = null;
    },
  };
}
