// @ts-check
// The 3-D wing panel's state and the wiring of its parts (views/wing3d.js mounts it; what the
// panel shows and why is said there). panel-dom.js builds the elements, camera.js keeps the
// renderer's camera and its mirror and binds drag / wheel / keys, frame-loop.js plays,
// marks.js places the labels, the strain point's ring and the sensors on the drawn wing (with
// picking.js and overlays.js), canvas.js sizes the canvas, legend.js draws the colour bar and its
// words, fields.js uploads colours 5 and 6, texts.js words the status lines.
import { isTouch } from '../dom.js';
import { errorText } from '../format.js';
import * as S from '../scene3d.js';
import { buildPanel, sizedCanvas, showUnavailable } from './panel-dom.js';
import { canvasSize } from './canvas.js';
import { createCameraRig, bindCamera, strokePoses, fitLift, refitKey } from './camera.js';
import { createFrameLoop, PUSH_MS } from './frame-loop.js';
import * as P from './picking.js';
import { createOverlays } from './overlays.js';
import { createWingMarks } from './marks.js';
import { createStrainLegend } from './legend.js';
import { createFields, FIELD_COLOUR, SENSE_COLOUR } from './fields.js';
import * as T from './texts.js';
import { RemoteWingView } from './remote-view.js';
import { makePanelView, wantWorker } from './make-view.js';
import { panelApi } from './panel-api.js';
import { writeFrameTexts, setText } from './frame-texts.js';

/**
 * States of the run (evenly spaced samples plus each mode's extremes) over which the colour
 * ranges and the largest deflection are taken when there are 3+ modes: 1000 keeps the per-run
 * work near 100 ms for 1653 nodes × 6 modes (4000 took 0.5 s), and the ranges are for display.
 */
const RANGE_SAMPLES = 1000;

/** While playing, the status, summary, legend and deflection texts change at most this often (ms). */
const TEXT_MS = 250;

/** One mounted 3-D panel (views/wing3d.js mounts it): its state, and the wiring of its parts. */
export class Wing3dPanel {
  /** @param {import('../lab.js').ViewContext} ctx */
  constructor(ctx) {
    const { store, section, engine, uid } = ctx;
    this.store = store;
    this.engine = engine;
    this.touch = isTouch();
    /**
     * The view: the wasm WingView on this thread, or a RemoteWingView whose worker owns it
     * (data-thread on the box says which).
     * @type {any}
     */
    this.view = null;
    /** the drawing buffer (device px); the canvas's own size is the worker's once transferred */
    this.bw = 0;
    this.bh = 0;
    /** why the view is drawn on this thread although the browser could draw it in a worker */
    this.workerProblem = '';
    /** the newest frame whose legend (texts) is awaited from the worker */
    this.textToken = 0;
    /** @type {Promise<boolean>} the view's making under way (makeView runs one at a time) */
    this.making = Promise.resolve(true);
    /** @type {import('../pkg/wingbeat.js').FeModesResult | null} */
    this.fe = null;
    this.started = false;
    this.frames = 0;
    /** @type {Record<number, number> | null} colour limit per colour mode (1 ε_x … 4 |ε|) */
    this.ranges = null;
    /** @type {number | null} largest true deflection over the run (m) */
    this.runDeflection = null;
    this.pending = 0;
    this.dirty = false;
    this.lastText = -Infinity;
    /** sample index of the last frame the play loop drew (-1: something else drew since) */
    this.lastLoopI = -1;
    /** reused for the per-frame modal coordinates */
    this.qBuf = new Float64Array(0);
    this.exagTouched = false;
    /** @type {IntersectionObserver | null} */
    this.io = null;
    /** @type {ResizeObserver | null} */
    this.ro = null;
    /** @type {Promise<void> | null} */
    this.remaking = null;
    this.seenShow = 0;
    this.narrowNow = false;
    /** @type {boolean | null} on a focused screen (null: not told yet) */
    this.focusedNow = null;
    /**
     * The canvas's CSS size, measured once per resize (fitCanvas clears it): the play loop places
     * labels every frame, and reading clientWidth after the previous frame's style writes forced
     * a style/layout pass each time.
     */
    this.cssW = 0;
    this.cssH = 0;
    this.overlays = createOverlays();
    this.dom = buildPanel(uid, this.touch, this.overlays.overlay, {
      play: () => store.set({ playing: !store.get().playing }),
      speed: () => this.describeTime(),
      time: (t) => store.set({ playing: false, t3d: t }),
      exag: () => {
        this.exagTouched = true;
        this.dirty = true;
        this.draw();
      },
      colour: () => {
        this.fields.invalidate();
        this.overlays.regroupSensors();
        this.applyRange();
        this.draw();
      },
      scene: () => this.onScene(),
      fit: () => {
        this.rig.user = false;
        this.rig.fitKey = '';
        this.fit(true);
        this.draw();
      },
    });
    this.canvas = this.dom.canvas;
    this.rig = createCameraRig(() => this.view);
    this.fields = createFields({
      store,
      engine,
      view: () => this.view,
      fe: () => this.fe,
      colour: () => this.colour(),
      draw: () => this.draw(),
    });
    this.marks = createWingMarks({
      store,
      rig: this.rig,
      overlays: this.overlays,
      fields: this.fields,
      dom: this.dom,
      fe: () => this.fe,
      cssSize: () => this.canvasCss(),
      colour: () => this.colour(),
      exaggeration: () => this.exaggeration(),
      tNow: () => this.tNow(),
    });
    this.drawLegend = createStrainLegend(this.dom.legend, this.dom.legendText);
    this.loop = createFrameLoop({
      box: this.dom.box,
      store,
      ready: () => !!this.view,
      draw: (t) => this.draw(t),
      speed: () => this.speedFactor(),
      duration: () => Number(this.dom.time.max) || 0,
    });
    const { box, summary, status, controls, defl } = this.dom;
    section.append(box, summary, status, controls, defl);
    this.bindCanvas();
    this.describeTime();
    this.unsub = this.subscribe();
    if (store.get().t3d == null) store.set({ t3d: 0.505 });
    this.loop.watch(box);
  }

  /** The store's keys this panel follows; returns the unsubscribers. */
  subscribe() {
    const store = this.store;
    return [
      store.subscribe(['result'], () => this.onResult()),
      store.subscribe(['sense_map'], () => this.onSenseMap()),
      store.subscribe(['fe'], () => this.onFe()),
      store.subscribe(['strain_map'], () => {
        this.fields.invalidate();
        if (this.view && this.colour() === FIELD_COLOUR) {
          this.applyRange();
          this.draw();
        }
      }),
      store.subscribe(['strain_point'], () => {
        if (this.view) this.marks.placePoint();
      }),
      // (a time set from outside while playing — the time slider, a click on the responses plot —
      // becomes the loop's time, so a pause then keeps it)
      store.subscribe(['t3d'], (s) => {
        if (this.loop.pushing) return;
        if (this.loop.t != null) this.loop.t = s.t3d ?? 0;
        if (this.view) this.draw();
        else this.describeTime();
      }),
      store.subscribe(['playing'], (s) => this.setPlaying(!!s.playing)),
    ];
  }

  /** Drag, wheel, keys and clicks on the (current) canvas. */
  bindCanvas() {
    bindCamera(this.canvas, this.rig, {
      view: () => this.view,
      moved: () => this.draw(),
      click: (x, y) => {
        this.marks.pickAt(x, y);
      },
      togglePlay: () => this.store.set({ playing: !this.store.get().playing }),
    });
  }

  colour() {
    return Number(this.dom.colour.value);
  }

  exaggeration() {
    return 10 ** Number(this.dom.exag.value);
  }

  /** The instant shown: the play loop's, else the store's. */
  tNow() {
    return this.loop.t ?? this.store.get().t3d ?? 0;
  }

  speedFactor() {
    return T.speedFactor(this.dom.speed.value, this.store.get().result);
  }

  describeTime(/** @type {number} */ tShown = this.store.get().t3d ?? 0) {
    setText(this.dom.timeText, T.timeLine(tShown, this.store.get().result, this.speedFactor()));
    this.dom.time.setAttribute('aria-valuetext', `${tShown.toFixed(4)} s`);
  }

  onScene() {
    const { showAxes, showBody, showPlane } = this.dom;
    if (this.view) {
      this.view.set_scene(showAxes.checked, showPlane.checked, showBody.checked);
      this.draw();
    }
  }

  unavailable(/** @type {string} */ why) {
    showUnavailable(this.dom, why);
  }

  async start() {
    if (this.started) return;
    this.started = true;
    // The renderer is in the full wasm build, which loads behind the live one; a worker to draw
    // in starts loading meanwhile.
    this.dom.status.textContent = 'Loading the 3-D renderer…';
    if (wantWorker(this.dom.box, this.canvas) && typeof this.engine.prewarmRender === 'function')
      this.engine.prewarmRender();
    // The FE wing is asked for now too: its worker starts and loads its scripts while the full
    // build downloads, and computes as soon as the build reaches it. (Asked again below: the
    // same computation, unless another wing was wanted meanwhile.)
    this.engine.ensureFe().catch(() => {});
    try {
      await this.engine.loadFull();
    } catch (e) {
      this.unavailable(`the renderer could not be loaded: ${errorText(e)}`);
      return;
    }
    if (!this.engine.hasRenderer) {
      this.unavailable('this build of the lab has no renderer (built without the `render` feature)');
      return;
    }
    let fe;
    try {
      this.dom.status.textContent = 'Computing the shell FE wing (mesh + modes) in a worker, a few seconds…';
      fe = this.fe = await this.engine.ensureFe();
      this.store.set({ fe });
    } catch (e) {
      this.unavailable(`the FE wing could not be computed: ${errorText(e)}`);
      return;
    }
    if (!(await this.makeView(fe))) return;
    if (typeof ResizeObserver === 'function') {
      this.ro = new ResizeObserver(() => {
        if (this.fitCanvas()) {
          this.fit(false);
          this.draw();
        }
      });
      this.ro.observe(this.dom.stage);
    }
    this.onResult();
  }

  /** A new canvas sized as the panel's, not yet in the page (a new view is made on it, then shown). */
  newCanvas() {
    return sizedCanvas(this.dom.summaryId, this.touch, this.bw, this.bh, this.canvas.style.height);
  }

  /** (Re)creates the view for the FE wing `w` once any making under way is done (one canvas, one making). */
  makeView(/** @type {any} */ w) {
    const run = this.making.then(() => makePanelView(this, w));
    this.making = run.catch(() => false);
    return run;
  }

  /** A new FE wing in the store (the user's own wing, or another mode count): redraw with it. */
  onFe() {
    const w = this.store.get().fe;
    if (!this.started || !w || w === this.fe || this.remaking) return;
    this.remaking = this.makeView(w).then(() => {
      this.remaking = null;
      if (this.store.get().fe !== this.fe) this.onFe();
      else this.onResult();
    });
  }

  /** Starts now if the panel is on screen, else when it first scrolls into sight. */
  startWhenVisible() {
    if (this.started || this.io) return;
    if (typeof IntersectionObserver !== 'function') {
      this.start();
      return;
    }
    this.dom.status.textContent = 'The 3-D view starts when this panel is on screen.';
    const obs = new IntersectionObserver((entries) => {
      if (entries.some((e) => e.isIntersecting)) {
        obs.disconnect();
        this.start();
      }
    });
    this.io = obs;
    obs.observe(this.dom.box);
  }

  canvasCss() {
    if (!this.cssW || !this.cssH) {
      this.cssW = this.canvas.clientWidth;
      this.cssH = this.canvas.clientHeight;
    }
    return [this.cssW, this.cssH];
  }

  /** Drawing-buffer size from the stage (device pixels). Returns true when it changed. */
  fitCanvas() {
    this.cssW = 0;
    const { canvas, dom } = this;
    const { cssH: h, width: W, height: H } = canvasSize(dom.stage.clientWidth, globalThis.devicePixelRatio || 1);
    dom.box.dataset.backing = `${W}x${H}`;
    canvas.style.height = `${h}px`;
    if (this.bw === W && this.bh === H) return false;
    this.bw = W;
    this.bh = H;
    // (a canvas handed to the worker is sized there, by resize)
    if (!(this.view instanceof RemoteWingView)) {
      canvas.width = W;
      canvas.height = H;
    }
    if (this.view) {
      try {
        this.view.resize(W, H);
      } catch (e) {
        dom.status.textContent = `resize: ${errorText(e)}`;
      }
    }
    return true;
  }

  /** Fits the camera to the whole stroke (camera.js rig.fit), from several directions when `search`. */
  fit(/** @type {boolean} */ search) {
    const fe = this.fe;
    if (!fe) return;
    const lift = fitLift(this.runDeflection, this.exaggeration(), S.spanOf(fe.nodes));
    const coverage = this.rig.fit(search, fe, strokePoses(this.store.get().result), lift, this.bw, this.bh);
    if (coverage != null) this.dom.box.dataset.coverage = coverage.toFixed(3);
  }

  applyRange() {
    this.fields.applyRange(this.ranges);
  }

  /** A new detectability map from the sensing panel; its "Show on the 3-D wing" button sets colour 6. */
  onSenseMap() {
    const m = this.store.get().sense_map;
    const { colour, options, box } = this.dom;
    if (m && m.show > this.seenShow) {
      this.seenShow = m.show;
      colour.value = String(SENSE_COLOUR);
      // the legend says what the colours and tags are: shown even where the options start folded (phones)
      options.open = true;
      this.fields.invalidate();
      this.overlays.regroupSensors();
      if (!this.started) this.startWhenVisible();
      if (typeof box.scrollIntoView === 'function') box.scrollIntoView({ block: 'nearest' });
    }
    if (this.view && this.colour() === SENSE_COLOUR) {
      this.overlays.regroupSensors();
      this.applyRange();
      this.draw();
    }
  }

  /** New analysis: time range now; colour ranges, run deflection and camera fit on the next frame. */
  onResult() {
    const s = this.store.get();
    const r = s.result;
    if (!r) return;
    const a = r.analysis;
    const dur = a.sim.t[a.sim.t.length - 1] || 0;
    this.dom.time.max = String(dur);
    this.dom.time.step = String(1 / a.sim.sample_rate_hz);
    if (s.t3d != null && s.t3d > dur) this.store.set({ t3d: 0 });
    if (!this.exagTouched) this.dom.exag.value = s.modes === 'fe' ? '0' : '1';
    this.dirty = true;
    if (!this.view || !this.fe) return;
    if (!this.pending)
      this.pending = requestAnimationFrame(() => {
        this.pending = 0;
        if (!this.store.get().playing) this.draw();
        else this.refresh();
      });
  }

  /** The per-run work, kept out of the slider's own redraw: ranges, deflection, camera fit. */
  refresh() {
    const fe = this.fe;
    if (!this.dirty || !this.view || !fe) return;
    this.dirty = false;
    const s = this.store.get();
    if (!s.result) return;
    // Display ranges: with 3+ modes over RANGE_SAMPLES states (exact hull vertices for 1–2),
    // the core's Analysis.extreme_samples. A view in a worker works them out there (for a
    // 6-mode wing a long task), except for the first fit, which needs them before the first frame.
    const view = this.view;
    const result = s.result;
    if (typeof view.runRanges === 'function' && this.rig.fitKey) {
      view.runRanges(S.runStates(result.analysis, RANGE_SAMPLES)).then((/** @type {any} */ r) => {
        if (!r || this.view !== view || this.store.get().result !== result) return;
        this.useRanges(r);
        this.draw();
      });
      return;
    }
    this.useRanges(S.runRanges(fe, result.analysis, RANGE_SAMPLES));
  }

  /** A run's colour ranges and largest deflection: applied, and the camera refitted when the stroke or the drawn deflection changed. */
  useRanges(/** @type {{ ranges: Record<number, number>, deflection: number }} */ r) {
    this.ranges = r.ranges;
    this.runDeflection = r.deflection;
    this.applyRange();
    const key = refitKey(this.store.get(), this.bw, this.bh, this.runDeflection * this.exaggeration());
    if (key !== this.rig.fitKey) {
      this.fit(!this.rig.fitKey);
      this.rig.fitKey = key;
    }
  }

  /**
   * Draws the frame at `tPlay` (the play loop) or at the store's t3d. While playing only the
   * pose and q_k change per frame (WingView.setPose); the legend and the texts are redone every
   * TEXT_MS, and a frame showing the sample already drawn is skipped.
   * @param {number} [tPlay]
   */
  draw(tPlay) {
    const s = this.store.get();
    const r = s.result;
    const inLoop = tPlay != null;
    const tNow = inLoop ? tPlay : this.tNow();
    const now = performance.now();
    const texts = !inLoop || now - this.lastText >= TEXT_MS;
    if (texts || now - this.loop.lastPush >= PUSH_MS) {
      this.describeTime(tNow);
      this.dom.time.value = String(tNow);
    }
    const { view, fe } = this;
    if (!view || !fe || !r || !r.angles) return;
    this.refresh();
    const a = r.analysis;
    const i = P.sampleIndex(a.sim, tNow);
    if (inLoop && i === this.lastLoopI && !texts) return;
    this.lastLoopI = inLoop ? i : -1;
    const ang = [r.angles.alpha[i], r.angles.beta[i], r.angles.gamma[i]];
    const modes = a.sim.modes;
    if (this.qBuf.length !== modes.length) this.qBuf = new Float64Array(modes.length);
    const q = this.qBuf;
    for (let k = 0; k < modes.length; k++) q[k] = modes[k].q.total[i];
    const ex = this.exaggeration();
    /** @type {any} */
    let lg = null;
    try {
      const cm = this.colour();
      if (texts || typeof view.setPose !== 'function')
        lg = view.set_frame(ang[0], ang[1], ang[2], q, ex, cm === SENSE_COLOUR ? 5 : cm);
      else view.setPose(ang[0], ang[1], ang[2], q);
      view.render();
    } catch (e) {
      this.dom.status.textContent = `render: ${errorText(e)}`;
      return;
    }
    if (!(view instanceof RemoteWingView)) {
      this.frames += 1;
      this.dom.box.dataset.frames = String(this.frames);
    }
    this.marks.placeOverlays(ang, q, tNow, texts);
    if (!lg) return;
    this.lastText = now;
    const nModes = modes.length;
    if (typeof lg.then !== 'function') {
      this.frameTexts(lg, ang, ex, tNow, nModes);
      return;
    }
    // drawn by the worker: the texts follow its legend, unless a newer frame's is awaited by then
    const token = ++this.textToken;
    lg.then((/** @type {any} */ l) => {
      if (l && token === this.textToken && this.view === view) this.frameTexts(l, ang, ex, tNow, nModes);
    });
  }

  /** The texts of a drawn frame (its legend `lg`): frame-texts.js. */
  frameTexts(
    /** @type {any} */ lg,
    /** @type {number[]} */ ang,
    /** @type {number} */ ex,
    /** @type {number} */ t,
    /** @type {number} */ nModes,
  ) {
    writeFrameTexts(this, lg, ang, ex, t, nModes);
  }

  setPlaying(/** @type {boolean} */ on) {
    const btn = this.dom.playBtn;
    btn.textContent = on ? 'Pause' : 'Play';
    btn.setAttribute('aria-pressed', String(on));
    if (on) this.loop.start();
    else this.loop.stop('stopped');
  }

  setLayout(/** @type {string} */ mode) {
    this.narrowNow = mode === 'narrow';
    this.dom.options.open = !this.narrowNow && !this.focusedNow;
  }

  /** A focused screen (www/screens.js) starts with the view options folded; the full page open. */
  setScreen(/** @type {string} */ screen) {
    const f = screen !== 'full';
    if (f === this.focusedNow) return;
    this.focusedNow = f;
    this.dom.options.open = !this.narrowNow && !this.focusedNow;
  }

  destroy() {
    for (const f of this.unsub) f();
    this.store.set({ playing: false });
    if (this.io) this.io.disconnect();
    if (this.ro) this.ro.disconnect();
    this.loop.destroy();
    this.fields.destroy();
    if (this.view) this.view.free();
    this.view = null;
  }

  /** What the lab (and its tests) see of the panel (panel-api.js). */
  api() {
    return panelApi(this);
  }
}
