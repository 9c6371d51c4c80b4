// @ts-check
// <wing-lab>: the wingbeat browser lab as a custom element (no framework). It renders into an
// OPEN shadow root (lab.shadowRoot) with its own stylesheets (style.css, vendor/uPlot.min.css,
// loaded from lab.js's own URL), so no style leaks out into the host page and the page's
// styles do not reach inside; the host page sizes and places the element like any block.
//
//   <script type="module" src="lab.js"></script>
//   <wing-lab gamma0="0.1" flap_hz="25" panels="controls,numbers,spectrum"></wing-lab>
//
// Module map (model / view split in the manner of PhET sims; each module has one job):
//   state.js     pure: parameters, URL/attribute parsing and validation, overridesOf (the
//                SimConfig itself is the core's: engine.config → wasm applyOverrides)
//   store.js     observable state: get / set(patch) / subscribe(keys, fn); keys = the URL
//                parameters + result (latest analysis, with angles), fe, t3d (3-D instant),
//                playing, timing, status
//   engine.js    the ONLY module that talks to wasm and to the worker (worker.js): analyze,
//                FE wing, studies, cancel
//   decimate.js  the one min/max decimation (plots and worker)
//   format.js    numbers, units and rich-label markup (f_d, kg^½·m → sub/superscripts)
//   dom.js       el(), rich(), the shadow root's stylesheets, activeIn(), touch detection
//   layout.js    the grid from the element's own width and the panels shown (pure)
//   screens.js   the screens: which panels each shows, which one an experiment opens (pure)
//   plot.js      uPlot wrapper: HTML axis titles, keyboard legend toggles, markers, a11y summary
//   export.js    CSV, PNG (2×) and SVG figures from one drawing routine
//   beat.js      the beat period, the three-beat window, the force shares (pure)
//   scene3d.js   camera mirror, stroke fit, run-wide strain range and deflection (pure)
//   views/<panel>.js  one per panel; `export const title` and `mount(ctx)` → { destroy() }.
//                Views read the store and call ctx.* only; they never import engine.js.
//   lab.js       this element: parses attributes/URL, creates store + engine, lays out the
//                panels (order in LAYOUT below), mounts the views, recomputes on parameter
//                changes, keeps the URL in sync, exports.
// Adding a panel (e.g. views/experiments.js, views/resonance.js): add its name to PANELS in
// state.js, import it into VIEWS below, put it in LAYOUT (visual order = tab order), and give
// it a place in layout.js's TEMPLATES (the grid is computed there from the panels shown).
// The view gets ctx = { store, engine, section, uid, id(s), registerPlot(name, plot),
// registerExport(name, { csv, figure, table, canvas }), exportButtons(name, label, kinds),
// toCSV, emit(type, detail), notice(text), setParams(patch), showPanel(name) }.
// Screens (www/screens.js, the one table of screen → panels): a tablist above the grid opens one
// screen at a time (`screen` attribute / URL parameter, lab.screen, iframe set({screen})); the
// panels of other screens are hidden and skip their redraws until shown (viewStore).
//
// Attributes: every URL parameter of www/state.js (alpha0, beta0, gamma0, flap_hz, zeta,
// alpha_phase, beta_phase, gamma_phase, duration, modes, mode, detrend, panels), plus
// `sync-url` (state read from and written to the page's query string), `embed` (compact, one
// column) and `layout` (wide | medium | narrow: a fixed layout instead of the width's). They are
// read when the element connects; later changes apply too (observedAttributes).
// Several labs on one page are independent: each has its own store, engine and worker; they
// share the (stateless) wasm module. Assets resolve relative to this file, also when it is
// loaded from another origin (the lab's host must then send CORS headers; the worker starts
// from a same-origin Blob that imports worker.js, see engine.js).
// Test hooks: data-renders, data-layout (on the host), events wl-ready / wl-rendered / wl-study
// (bubbling and composed), and the properties state, analysis, plots, studies, wing3d,
// timeCursor, fe, config(), modeIndex(); inside: lab.shadowRoot.
import { NUMERIC, ENUMS, WING, parsePairs, parseQuery, toQuery, defaults, paramsOf, describe } from './state.js';
import { shareLink, decodeShare, fragmentValue, checkPoints } from './share.js';
import { experimentPatch } from './experiments.js';
import { createStore } from './store.js';
import { createEngine } from './engine.js';
import { el, shadowStyles } from './dom.js';
import { layoutMode, gridLayout, areasCss } from './layout.js';
import { SCREENS, EXPERIMENT_SCREEN, resolveScreen, screenOfPanel } from './screens.js';
import { plain, errorText } from './format.js';
import { toCSV, download, figurePNG, figureSVG, tablePNG, drawFigure, canvasPainter, context2d } from './export.js';
import * as controls from './views/controls.js';
import * as numbers from './views/numbers.js';
import * as time from './views/time.js';
import * as spectrum from './views/spectrum.js';
import * as strain from './views/strain.js';
import * as studies from './views/studies.js';
import * as wing3d from './views/wing3d.js';
import * as report from './views/report.js';
import * as experiments from './views/experiments.js';
import * as resonance from './views/resonance.js';
import * as wing from './views/wing.js';
import * as kinematics from './views/kinematics.js';
import * as modeshape from './views/modeshape.js';
import * as sensing from './views/sensing.js';

export { loadWasm } from './engine.js';

/**
 * The store's state: the URL parameters plus what the engine and the views derive.
 * @typedef {import('./state.js').Params & {
 *   result: import('./engine.js').LiveResult | null,
 *   fe: import('./engine.js').FeModesResult | null,
 *   t3d: number | null,
 *   playing: boolean,
 *   timing: { compute: number, draw: number, end: number } | null,
 *   status: string | null,
 *   wing: WingState | null,
 *   kin: KinState | null,
 *   strain_point: [number, number] | null,
 *   strain_map: { component: 'eps_x' | 'eps_y' | 'gamma_xy' | 'von_mises', stat: 'rms' | 'peak' } | null,
 *   sense_map?: import('./views/sensing.js').SenseMap | null,
 * }} LabState
 */
/**
 * The wing in use when it is not the lab's default FE wing: the FemInput it was computed from
 * (null for imported modes), where it came from, and its outline (mm) for the editor and the
 * share fragment. `null` = the default wing (the paper table or the default FE wing).
 * @typedef {{ input: import('./pkg/wingbeat.js').FemInput | null, source: 'builtin' | 'file' | 'edited' | 'url' | 'import' | 'share', label: string, outline: string, points: [number, number][] | null }} WingState
 */
/**
 * Custom kinematics (null = the sliders' Fourier kinematics): the core's Kinematics, where they
 * came from, and for a measured table its samples (rad, one period) and the CSV text.
 * @typedef {{ kinematics: import('./pkg/wingbeat.js').Kinematics, source: 'csv' | 'edited' | 'share', label: string,
 *   samples?: { t: Float64Array | number[], alpha: Float64Array | number[], beta: Float64Array | number[], gamma: Float64Array | number[] } | null,
 *   csv?: { text: string, units: 'deg' | 'rad', flap_hz: number } | null }} KinState
 */
/** @typedef {ReturnType<typeof import('./plot.js').linePlot>} Plot */
/**
 * What a panel registers for export (each optional; `null` when there is nothing to export yet).
 * @typedef {{ csv?: () => string | null, figure?: () => any, table?: () => any, canvas?: () => HTMLCanvasElement | null }} ExportReg
 */
/**
 * What a view gets from the element (see the module map above).
 * @typedef {{
 *   store: import('./store.js').Store<LabState>,
 *   engine: ReturnType<typeof createEngine>,
 *   section: HTMLElement,
 *   uid: string,
 *   id: (s: string) => string,
 *   toCSV: typeof toCSV,
 *   registerPlot: (name: string, plot: Plot) => void,
 *   registerExport: (name: string, reg: ExportReg) => void,
 *   exportButtons: (name: string, label: string, kinds?: string[]) => HTMLElement,
 *   emit: (type: string, detail?: unknown) => void,
 *   notice: (text: string) => void,
 *   setParams: (patch: Partial<LabState>) => void,
 *   showPanel: (name: string) => void,
 * }} ViewContext
 */
/** A mounted view: destroy() always; some views add hooks (startWhenVisible, setLayout, studies …). */
/** @typedef {{ destroy(): void, [hook: string]: any }} View */

const VIEWS = { controls, numbers, time, spectrum, strain, studies, wing3d, report, experiments, resonance, wing, kinematics, modeshape, sensing };
/** DOM (= tab) order of the panels; layout.js places them so that it is also the visual order. */
export const LAYOUT = ['wing3d', 'controls', 'time', 'experiments', 'wing', 'kinematics', 'spectrum', 'numbers', 'modeshape', 'strain', 'sensing', 'studies', 'resonance', 'report'];
const PARAM_KEYS = [...NUMERIC.map((p) => p.key), ...ENUMS.map((e) => e.key), ...WING.map((w) => w.key), 'outline', 'planform'];
/** The keys that decide which wing is wanted. */
const WING_KEYS = [...WING.map((w) => w.key), 'outline', 'planform', 'wing'];
const FIG_W = 900, FIG_H = 560;
/** Attributes that are not lab parameters. */
const NOT_PARAMS = ['id', 'class', 'style', 'sync-url', 'embed', 'layout', 'hidden', 'title', 'lang', 'dir', 'slot', 'part', 'tabindex', 'nonce', 'role', 'inert', 'translate', 'is'];
/** Parameter attributes that apply live when changed after connection (planform= needs a fetch: not live). */
const LIVE_ATTRS = [...NUMERIC.map((p) => p.key), ...ENUMS.map((e) => e.key), ...WING.map((w) => w.key), 'outline', 'panels', 'exp', 'screen'];
const EVENT = { bubbles: true, composed: true };
let instances = 0;
/** Labs built so far on this page: the second one on is "lab 2", … in its sections' names. */
let labsBuilt = 0;

export class WingLab extends HTMLElement {
  // Made in connectedCallback / build(), before anything reads them:
  /** @type {import('./store.js').Store<LabState>} */
  store;
  /** @type {ReturnType<typeof createEngine>} */
  engine;
  /** @type {HTMLElement} */
  root;
  /** @type {HTMLElement} */
  noticeEl;
  /** @type {HTMLElement} */
  errorEl;
  /** @type {Record<string, HTMLElement>} */
  panels;
  /** @type {HTMLElement | null} the panels' grid (its template is set by applyLayout) */
  grid = null;
  /** @type {HTMLElement} the screen nav (a tablist, see buildNav) */
  nav;
  /** @type {HTMLElement} the line that says what the screen shown is for */
  aboutEl;
  /** @type {Record<string, HTMLButtonElement>} the nav's tabs by screen id */
  tabs = {};
  /** the grid's current columns and areas (CSS text) */
  gridCols = '';
  gridAreas = '';

  static get observedAttributes() { return ['embed', 'layout', ...LIVE_ATTRS]; }

  constructor() {
    super();
    this.attachShadow({ mode: 'open' });
    this.uid = `wl${++instances}`;
    /** 1 for the first lab built on the page, 2 for the next, … (accessible names) */
    this.ordinal = 0;
    this.renders = 0;
    this.raf = 0;
    /** @type {Record<string, View>} */
    this.views = {};
    /** @type {Record<string, ExportReg>} */
    this.exportsReg = {};
    /** @type {Record<string, Plot>} */
    this.plotReg = {};
    /** @type {(() => void)[]} */
    this.unsub = [];
    /** @type {ResizeObserver | null} */
    this.ro = null;
    /** @type {{ compute: number, draw: number, end: number } | null} */
    this.lastTiming = null;
    /** Whether a new result's panel redraws are being run (one task each, see drainDraws). */
    this.drawing = false;
    /** @type {{ name: string, fn: Function }[]} */
    this.drawQueue = [];
    /** @type {{ name: string, fn: Function }[]} redraws skipped by hidden panels (flushStale) */
    this.stale = [];
    /** @type {string | undefined} the screen shown (applyPanels) */
    this.shownScreen = undefined;
    /** @type {string[] | null} its panels */
    this.shownPanels = null;
    /** @type {MessageChannel | null} */
    this.drawPort = null;
    /** bumped when the element is removed: a redraw sequence of the old build stops */
    this.drawGen = 0;
    /** @type {{ r: import('./engine.js').LiveResult, t1: number } | null} the result being drawn */
    this.pendingRender = null;
    /** Work that must finish before the first computation (planform= file, #s= fragment). */
    this.pending = 0;
    /** Why the wanted wing cannot be built ('' = it can). */
    this.wingError = '';
    this.feRunning = false;
    /** @type {ReturnType<typeof setTimeout> | undefined} */
    this.fragTimer = undefined;
  }

  // ---------- test and embedding hooks ----------
  get state() { return this.store ? paramsOf(this.store.get()) : defaults(); }
  get analysis() { const r = this.store && this.store.get().result; return r ? r.analysis : undefined; }
  get plots() { const o = {}; for (const [k, p] of Object.entries(this.plotReg)) o[k] = p.u; return o; }
  get studies() { return this.views.studies ? this.views.studies.studies : {}; }
  get wing3d() { return this.views.wing3d; }
  get timeCursor() { return this.store ? this.store.get().t3d : null; }
  get fe() { return this.engine ? this.engine.fe : null; }
  config() { return this.engine.config(this.state); }
  modeIndex() { return Number(this.state.mode) - 1; }

  connectedCallback() {
    if (this.built) return;
    this.built = true;
    if (!this.ordinal) this.ordinal = ++labsBuilt;
    const ignore = NOT_PARAMS;
    const attrs = [...this.attributes].filter((a) => !a.name.startsWith('aria-') && !a.name.startsWith('data-')).map((a) => [a.name, a.value]);
    const fromAttrs = parsePairs(attrs, ignore);
    const params = fromAttrs.state;
    const rejected = [...fromAttrs.rejected];
    if (this.hasAttribute('sync-url')) {
      const q = parseQuery(location.search);
      for (const [k] of new URLSearchParams(location.search)) {
        if (k === 'embed') continue;
        if (!q.rejected.some((r) => r.key === k) && k in q.state) params[k] = q.state[k];
      }
      rejected.push(...q.rejected.filter((r) => r.key !== 'embed'));
    }
    // A wing parameter, outline or planform file given without a mode set means the FE wing.
    const given = new Set([...attrs.map((a) => a[0]), ...(this.hasAttribute('sync-url') ? [...new URLSearchParams(location.search).keys()] : [])]);
    // A guided experiment (exp= attribute or URL) brings its parameters, as its chip does; values
    // given with it (and accepted) win.
    if (params.exp) Object.assign(params, experimentPatch(params.exp, [...given].filter((k) => !rejected.some((r) => r.key === k))));
    if (!given.has('modes') && WING_KEYS.some((k) => given.has(k) && !rejected.some((r) => r.key === k))) params.modes = 'fe';
    const nModes = params.modes === 'fe' ? params.n_modes : 2;
    if (Number(params.mode) > nModes) {
      rejected.push({ key: 'mode', why: `expected 1 to ${nModes} (the modes of the ${params.modes === 'fe' ? 'FE wing' : 'paper table'})` });
      params.mode = '1';
    }
    // A guided experiment opens the screen that shows what it talks about (screen= wins).
    if (params.exp && !params.screen) params.screen = EXPERIMENT_SCREEN[params.exp] || '';
    this.store = createStore({ ...params, screen: params.screen || '', result: null, fe: null, t3d: null, playing: false, timing: null, status: 'loading wasm…', wing: null, kin: null, strain_point: null, strain_map: null });
    this.engine = createEngine();
    this.build();
    if (rejected.length) {
      this.notice(`Ignored ${rejected.length} invalid parameter(s), using defaults instead: ` + rejected.map((r) => `${r.key} (${r.why})`).join('; '));
    }
    this.unsub.push(
      this.store.subscribe(PARAM_KEYS, () => {
        this.schedule();
        if (this.hasAttribute('sync-url')) this.scheduleUrl();
      }),
      this.store.subscribe(['panels', 'screen'], () => this.applyPanels()),
      this.store.subscribe(['exp', 'screen'], (st, changed) => {
        // Choosing an experiment (chip, attribute, message) opens its screen.
        if (st.exp && changed.includes('exp') && !changed.includes('screen') && EXPERIMENT_SCREEN[st.exp]) this.store.set({ screen: EXPERIMENT_SCREEN[st.exp] });
        if (this.hasAttribute('sync-url')) this.scheduleUrl();
      }),
      this.store.subscribe(['body_rate', 'body_axis'], () => { if (this.hasAttribute('sync-url')) this.scheduleUrl(); }),
      this.store.subscribe(WING_KEYS, () => { this.wantWing(); this.schedule(); }),
      this.store.subscribe(['modes', 'mode'], (st) => {
        const n = st.modes === 'fe' ? (st.fe ? st.fe.modes.length : 8) : 2;
        if (Number(st.mode) > n) this.store.set({ mode: '1' });
      }),
      this.store.subscribe(['kin'], (st) => { this.engine.setKinematics(st.kin ? st.kin.kinematics : null); this.schedule(); }),
      this.store.subscribe(['strain_point'], (st) => { this.engine.setStrainPoint(st.strain_point); this.schedule(); }),
      this.store.subscribe(['wing', 'kin', 'strain_point'], () => { if (this.hasAttribute('sync-url')) this.scheduleFragment(); }),
    );
    this.engine
      .load()
      .then(() => this.restoreShared())
      .then(() => {
        this.root.classList.remove('wl-loading');
        this.wantWing();
        this.render();
        // The live worker starts when someone is about to use the lab (focus or pointer inside
        // it, or the first parameter change), so it is ready before the first key press.
        const warm = () => { if (this.built) this.engine.warmLive(); };
        this.root.addEventListener('focusin', warm, { once: true });
        this.root.addEventListener('pointerdown', warm, { once: true });
        if (this.store.get().panels.includes('wing3d')) this.views.wing3d.startWhenVisible();
        this.dispatchEvent(new CustomEvent('wl-ready', EVENT));
      })
      .catch((e) => this.error(`Could not load the wasm module: ${errorText(e)}`));
  }

  disconnectedCallback() {
    this.raf = 0;
    this.drawing = false;
    this.drawQueue = [];
    this.stale = [];
    this.shownScreen = undefined;
    this.shownPanels = null;
    this.pendingRender = null;
    this.drawGen++;
    for (const v of Object.values(this.views)) if (v && v.destroy) v.destroy();
    this.unsub.forEach((f) => f());
    if (this.ro) this.ro.disconnect();
    this.ro = null;
    this.grid = null;
    this.gridCols = this.gridAreas = '';
    delete this.dataset.layout;
    this.engine.dispose();
    this.built = false;
    /** @type {ShadowRoot} */ (this.shadowRoot).replaceChildren();
    this.views = {};
    this.plotReg = {};
    this.exportsReg = {};
    this.unsub = [];
  }

  /**
   * `embed` and `layout` re-lay the grid; a parameter attribute changed after connection sets
   * that parameter (an invalid value is ignored with a notice, a removed one goes back to its
   * default). Before connection the attributes are read by connectedCallback.
   */
  attributeChangedCallback(name, old, value) {
    if (!this.built || !this.store || old === value) return;
    if (name === 'embed' || name === 'layout') {
      this.applyLayout();
      return;
    }
    const { state, rejected } = parsePairs(value == null ? [] : [[name, value]], []);
    if (rejected.length) {
      this.notice(`Ignored the attribute ${rejected.map((r) => `${r.key} (${r.why})`).join('; ')}.`);
      return;
    }
    // exp= opens the experiment with its parameters (as its chip does); removed, it closes it.
    this.store.set(name === 'exp' && state.exp ? /** @type {Partial<LabState>} */ (experimentPatch(state.exp)) : { [name]: state[name] });
  }

  // ---------- DOM ----------

  build() {
    const id = (s) => `${this.uid}-${s}`;
    this.root = el('div', { class: 'wl-root wl-loading' });
    this.noticeEl = el('p', { class: 'wl-notice', role: 'status', hidden: true });
    this.errorEl = el('p', { class: 'wl-error', role: 'alert', hidden: true });
    const grid = el('div', { class: 'wl-grid', id: id('screen'), role: 'tabpanel' });
    this.nav = this.buildNav(id);
    this.aboutEl = el('p', { class: 'wl-screen-about', id: id('screen-about') });
    this.root.append(this.noticeEl, this.errorEl, this.nav, this.aboutEl, grid);
    this.panels = {};
    const ctx0 = {
      store: this.store,
      engine: this.engine,
      uid: this.uid,
      id,
      toCSV,
      registerPlot: (name, plot) => { this.plotReg[name] = plot; },
      registerExport: (name, reg) => { this.exportsReg[name] = reg; },
      exportButtons: (name, label, kinds) => this.exportButtons(name, label, kinds),
      emit: (type, detail) => this.dispatchEvent(new CustomEvent(type, { detail, ...EVENT })),
      notice: (t) => this.notice(t),
      setParams: (patch) => this.store.set(patch),
      showPanel: (name) => this.showPanel(name),
    };
    // Several labs on a page: each names its sections after itself (unique landmarks): its
    // aria-label, else the caption of the figure it is in, else "lab N" from the second lab on.
    const labName = this.labName();
    for (const name of LAYOUT) {
      const view = VIEWS[name];
      const named = labName ? { 'aria-label': `${plain(view.title)} — ${labName}` } : { 'aria-labelledby': id(`h-${name}`) };
      const sec = el('section', { class: `wl-panel wl-${name}`, 'data-panel': name, ...named });
      const head = el('div', { class: 'wl-head' }, el('h2', { id: id(`h-${name}`), text: view.title }));
      sec.append(head);
      this.panels[name] = sec;
      grid.append(sec);
      this.views[name] = view.mount({ ...ctx0, store: this.viewStore(name), section: sec });
      const reg = this.exportsReg[name];
      if (reg) head.append(this.exportButtons(name, view.title, reg.figure ? ['csv', 'png', 'svg'] : ['csv', 'png']));
    }
    this.grid = grid;
    const shadow = /** @type {ShadowRoot} */ (this.shadowRoot);
    // Invisible (not unstyled) until style.css and uPlot's sheet have loaded: no flash.
    this.root.dataset.css = 'loading';
    shadowStyles(shadow).then(() => { delete this.root.dataset.css; });
    shadow.append(this.root);
    this.applyPanels();
    // Layout follows the element's own width (not the viewport) and the panels shown.
    if (typeof ResizeObserver === 'function') {
      this.ro = new ResizeObserver(() => this.applyLayout());
      this.ro.observe(this);
    }
  }

  /** The lab's own name in its sections' accessible names ('' = plain panel titles). */
  labName() {
    const own = (this.getAttribute('aria-label') || '').trim();
    if (own) return own;
    const fig = this.closest('figure');
    const caption = fig && fig.querySelector('figcaption');
    const text = caption ? (caption.textContent || '').replace(/\s+/g, ' ').trim() : '';
    if (text) return text;
    return this.ordinal > 1 ? `lab ${this.ordinal}` : '';
  }

  /**
   * Sets data-layout (narrow | medium | wide, from the element's width, `embed` and `layout`)
   * and the grid for the panels shown; tells the views when the mode changes.
   */
  applyLayout() {
    if (!this.grid) return;
    const w = this.getBoundingClientRect().width || this.clientWidth || 1200;
    const mode = layoutMode(w, { embed: this.hasAttribute('embed'), forced: this.getAttribute('layout') });
    const on = this.shownPanels || this.store.get().panels;
    const visible = LAYOUT.filter((p) => on.includes(p));
    const g = gridLayout(visible, mode);
    const cols = g.columns.join(' ');
    const areas = areasCss(g.rows);
    if (this.gridCols !== cols || this.gridAreas !== areas) {
      this.grid.style.gridTemplateColumns = cols;
      this.grid.style.gridTemplateAreas = areas;
      this.gridCols = cols;
      this.gridAreas = areas;
    }
    if (this.dataset.layout !== mode) {
      this.dataset.layout = mode;
      for (const v of Object.values(this.views)) if (v && v.setLayout) v.setLayout(mode);
    }
  }

  exportButtons(name, label, kinds = ['csv', 'png']) {
    // On a focused screen the kinds fold behind one "Export…" button (style.css); the full page
    // shows them all, as before.
    const box = el('span', { class: 'wl-export' });
    const toggle = el('button', { type: 'button', class: 'wl-export-toggle', 'aria-expanded': 'false', 'aria-label': `Export ${plain(label)}…`, text: 'Export…' });
    toggle.addEventListener('click', () => {
      const open = toggle.getAttribute('aria-expanded') !== 'true';
      toggle.setAttribute('aria-expanded', String(open));
      box.classList.toggle('wl-open', open);
    });
    box.append(toggle);
    for (const kind of kinds) {
      box.append(el('button', {
        type: 'button',
        text: kind.toUpperCase(),
        'data-export': kind,
        'data-target': name,
        'aria-label': `Export ${plain(label)} as ${kind.toUpperCase()}`,
        onclick: () => this.export(name, kind, label),
      }));
    }
    return box;
  }

  /**
   * Shows the panels of the screen in use (www/screens.js: the wanted screen and the author's
   * `panels=` choice), selects its tab, and redraws the panels that come into view with what
   * they skipped while hidden (hidden panels do not redraw, see viewStore).
   */
  applyPanels() {
    const st = this.store.get();
    const r = resolveScreen(st.screen || '', st.panels, LAYOUT);
    const before = this.shownScreen;
    this.shownScreen = r.id;
    this.shownPanels = r.shown;
    const shadow = /** @type {ShadowRoot} */ (this.shadowRoot);
    const focused = shadow.activeElement;
    for (const [name, sec] of Object.entries(this.panels)) {
      const was = sec.hidden;
      sec.hidden = !r.shown.includes(name);
      sec.style.gridArea = name;
      if (was && !sec.hidden) this.flushStale(name);
    }
    // The nav belongs to the whole lab: an author's own panel choice (panels=) is one page.
    const chosen = LAYOUT.every((p) => st.panels.includes(p));
    this.nav.hidden = !chosen;
    this.aboutEl.hidden = !chosen;
    // Without the tabs the grid is no tabpanel (an author's page of panels).
    if (this.grid) {
      if (chosen) {
        this.grid.setAttribute('role', 'tabpanel');
        this.grid.setAttribute('aria-describedby', this.aboutEl.id);
      } else {
        this.grid.removeAttribute('role');
        this.grid.removeAttribute('aria-describedby');
      }
    }
    for (const sc of SCREENS) {
      const tab = this.tabs[sc.id];
      const on = sc.id === r.id;
      tab.setAttribute('aria-selected', String(on));
      tab.tabIndex = on ? 0 : -1;
      if (on) {
        this.aboutEl.textContent = `${sc.label}: ${sc.about}.`;
        if (this.grid) {
          if (chosen) this.grid.setAttribute('aria-labelledby', tab.id);
          else this.grid.removeAttribute('aria-labelledby');
        }
      }
    }
    this.dataset.screen = r.id;
    // Views that show less on a focused screen (folded options) than on the full page.
    if (before !== r.id) for (const v of Object.values(this.views)) if (v && v.setScreen) v.setScreen(r.id);
    this.applyLayout();
    if (before !== undefined && before !== r.id) {
      // Focus that was in a panel now hidden goes to the selected tab (never lost to <body>).
      if (focused && focused !== this.tabs[r.id] && !(/** @type {HTMLElement} */ (focused)).checkVisibility?.()) this.tabs[r.id].focus();
      this.dispatchEvent(new CustomEvent('wl-screen', { detail: { screen: r.id, panels: r.shown.slice() }, ...EVENT }));
    }
  }

  /**
   * The screen nav: a tablist (one tab per screen of www/screens.js; arrow keys, Home and End
   * move between the tabs, Enter or Space opens one) above the panels' grid (its tabpanel).
   * @param {(s: string) => string} id
   */
  buildNav(id) {
    const labName = this.labName();
    const list = el('div', { class: 'wl-screens', role: 'tablist', 'aria-label': labName ? `Screens — ${labName}` : 'Screens of the lab' });
    this.tabs = {};
    for (const sc of SCREENS) {
      const tab = /** @type {HTMLButtonElement} */ (el('button', {
        type: 'button', role: 'tab', class: 'wl-tab', id: id(`tab-${sc.id}`), 'data-screen': sc.id,
        'aria-controls': id('screen'), 'aria-selected': 'false', tabindex: '-1', text: sc.label, title: sc.about,
      }));
      tab.addEventListener('click', () => this.showScreen(sc.id));
      this.tabs[sc.id] = tab;
      list.append(tab);
    }
    list.addEventListener('keydown', (e) => {
      const tabs = Object.values(this.tabs);
      const at = tabs.indexOf(/** @type {HTMLButtonElement} */ (e.target));
      if (at < 0) return;
      const to = { ArrowRight: at + 1, ArrowDown: at + 1, ArrowLeft: at - 1, ArrowUp: at - 1, Home: 0, End: tabs.length - 1 }[e.key];
      if (to === undefined) return;
      e.preventDefault();
      const next = tabs[(to + tabs.length) % tabs.length];
      for (const t of tabs) t.tabIndex = t === next ? 0 : -1;
      next.focus();
    });
    return list;
  }

  /**
   * Opens a screen (an id of www/screens.js); false for an unknown id. `lab.screen = id` does
   * the same; the `screen` attribute and URL parameter are validated like the others.
   * @param {string} name
   */
  showScreen(name) {
    if (!SCREENS.some((sc) => sc.id === name)) return false;
    this.store.set({ screen: name });
    return true;
  }

  /** The screen shown (www/screens.js id). */
  get screen() { return this.shownScreen || ''; }
  set screen(v) { this.showScreen(String(v)); }

  /** Opens the screen that holds a panel (e.g. a guided experiment's "Go to" button). */
  showPanel(/** @type {string} */ name) {
    if (this.panels[name] && this.panels[name].hidden) this.showScreen(screenOfPanel(name, LAYOUT));
  }

  /** Redraws a panel that comes into view with the new results it skipped while hidden. */
  flushStale(/** @type {string} */ name) {
    const entries = this.stale.filter((e) => e.name === name);
    if (!entries.length) return;
    this.stale = this.stale.filter((e) => e.name !== name);
    for (const e of entries) this.deferDraw(e);
    if (!this.drawing) {
      this.drawing = true;
      this.drainDraws(() => { this.drawing = false; this.finishRender(); });
    }
  }

  notice(text) {
    this.noticeEl.textContent = text;
    this.noticeEl.hidden = false;
  }

  error(text) {
    this.errorEl.textContent = text;
    this.errorEl.hidden = !text;
  }

  // ---------- live compute ----------

  /**
   * Recomputes once the current task's parameter changes are in (a microtask: several set()
   * calls in one handler make one request). The request goes to the engine's live worker
   * (engine.requestLive), so the paint after a key press only shows the slider's new value;
   * the panels redraw when the newest result arrives, and superseded results are dropped.
   */
  schedule() {
    if (this.raf) return;
    this.raf = -1;
    queueMicrotask(() => {
      if (this.raf !== -1) return;
      this.raf = 0;
      if (this.built) this.render();
    });
  }

  /**
   * The outline of the wing wanted (mm), or null for the core's default: an own outline
   * (file, editor, planform= URL, share fragment) first, then a built-in one by id.
   * @param {Readonly<LabState>} s
   * @returns {[number, number][] | null}
   */
  wingPoints(s) {
    if (s.wing && s.wing.points) return s.wing.points;
    if (s.outline && s.outline !== 'manduca') {
      const b = this.engine.planforms().find((p) => p.id === s.outline);
      if (!b) throw new Error(`outline: no built-in outline "${s.outline}" in this wasm build`);
      return b.points_mm;
    }
    return null;
  }

  /** Tells the engine which wing is wanted (from the wing parameters and outline). */
  wantWing() {
    if (!this.engine.ready || this.pending) return;
    const s = this.store.get();
    if (s.wing && s.wing.source === 'import') return;
    try {
      this.engine.setWing(this.engine.wingInput(paramsOf(s), this.wingPoints(s)));
      this.wingError = '';
      // Already computed (cached, or just computed by the wing panel): use it now.
      if (this.engine.wingCurrent && s.fe !== this.engine.fe) this.feReady(this.engine.fe);
    } catch (e) {
      this.wingError = `The wing is not valid: ${errorText(e)}`;
      this.error(this.wingError);
    }
  }

  render() {
    if (!this.engine.ready || this.pending) return;
    const s = this.store.get();
    if (s.modes === 'fe' && !this.engine.wingCurrent && !this.wingError) {
      const first = !this.engine.fe;
      if (first) this.store.set({ status: 'computing the FE wing’s modes in a worker…' });
      if (!this.feRunning) {
        this.feRunning = true;
        this.engine.ensureFe().then(
          (fe) => { this.feRunning = false; this.feReady(fe); },
          (e) => {
            this.feRunning = false;
            // The lab stays usable: the previous wing (or, with none yet, the paper table's
            // modes) goes on, with the reason shown until the wing changes.
            this.wingError = `The FE wing could not be computed: ${errorText(e).replace(/\.?$/, ".")}${this.engine.fe ? ' The previous wing stays in use.' : ' Showing the paper table’s modes meanwhile.'}`;
            this.error(this.wingError);
            this.schedule();
          },
        );
      }
      if (first) return;
    }
    /** @type {Promise<import('./engine.js').LiveResult | null>} */
    let req;
    try {
      req = this.engine.requestLive(paramsOf(s));
    } catch (e) {
      this.error(`Computation rejected: ${errorText(e)}`);
      return;
    }
    const engine = this.engine;
    req.then(
      (r) => { if (r && this.engine === engine && this.built) this.publish(r); },
      (e) => { if (this.engine === engine && this.built) this.error(`Computation rejected: ${errorText(e)}`); },
    );
  }

  /**
   * The store as a view sees it: the same store, except that a subscription whose only change
   * is a new `result` runs in a task of its own (see publish), visible panels first, so that
   * redrawing all panels is never one long task and a key press can paint between two panels.
   * @param {string} name the panel
   * @returns {import('./store.js').Store<LabState>}
   */
  viewStore(name) {
    const store = this.store;
    return {
      get: store.get,
      set: store.set,
      subscribe: (keys, fn) => {
        if (keys === '*' || !keys.includes('result')) return store.subscribe(keys, fn);
        const entry = { name, fn };
        return store.subscribe(keys, (st, changed) => {
          const onlyResult = changed.length === 1 && changed[0] === 'result';
          // A panel off the current screen does no work for a new result until it is shown.
          const sec = this.panels[name];
          if (onlyResult && sec && sec.hidden) {
            if (!this.stale.includes(entry)) this.stale.push(entry);
          } else if (this.drawing && onlyResult) this.deferDraw(entry);
          else fn(st, changed);
        });
      },
    };
  }

  /** Queues a panel's redraw for a new result (once per panel and function). */
  deferDraw(/** @type {{ name: string, fn: Function }} */ entry) {
    if (!this.drawQueue.includes(entry)) this.drawQueue.push(entry);
  }

  /**
   * Runs the queued redraws one task each (a MessageChannel message: not clamped like
   * setTimeout), the panels on screen first; then `done`.
   * @param {() => void} done
   */
  drainDraws(done) {
    const port = this.drawPort || (this.drawPort = new MessageChannel());
    // Each panel's place (0 on screen, 1 off screen, 2 hidden), measured once per drain: a
    // measurement after each panel's redraw would force a layout every task.
    /** @type {Map<string, number>} */
    const rank = new Map();
    const visible = (/** @type {string} */ n) => {
      let r = rank.get(n);
      if (r === undefined) {
        const sec = this.panels[n];
        if (!sec || sec.hidden) r = 2;
        else {
          const b = sec.getBoundingClientRect();
          r = b.bottom > 0 && b.top < (window.innerHeight || 800) ? 0 : 1;
        }
        rank.set(n, r);
      }
      return r;
    };
    const gen = this.drawGen;
    const step = () => {
      if (!this.built || gen !== this.drawGen) return;
      if (!this.drawQueue.length) {
        done();
        return;
      }
      // One panel per task, the most visible first (ties: the order they subscribed in).
      let best = 0, bestV = 3;
      for (let i = 0; i < this.drawQueue.length; i++) {
        const v = visible(this.drawQueue[i].name);
        if (v < bestV) { best = i; bestV = v; }
      }
      const [e] = this.drawQueue.splice(best, 1);
      try {
        e.fn(this.store.get(), ['result']);
      } finally {
        port.port1.onmessage = step;
        port.port2.postMessage(0);
      }
    };
    step();
  }

  /** The newest live result: into the store (the views redraw, a panel per task), then `wl-rendered`. */
  publish(/** @type {import('./engine.js').LiveResult} */ r) {
    this.error(this.wingError);
    const t1 = performance.now();
    // A result arriving while the previous one's panels are still being drawn: the queue keeps
    // one entry per panel, each reads the newest result when it runs.
    const first = !this.drawing;
    this.drawing = true;
    this.pendingRender = { r, t1: this.pendingRender ? this.pendingRender.t1 : t1 };
    this.store.set({ result: r, status: null });
    if (first) this.drainDraws(() => { this.drawing = false; this.finishRender(); });
  }

  /** All panels show the newest result: timing, data-renders and `wl-rendered`. */
  finishRender() {
    const pend = this.pendingRender;
    this.pendingRender = null;
    if (!pend) return;
    const { r, t1 } = pend;
    // uPlot commits its redraw in a microtask queued by setData; ours runs after it.
    queueMicrotask(() => {
      const t2 = performance.now();
      this.renders += 1;
      this.lastTiming = { compute: r.compute_ms, draw: t2 - t1, end: t2 };
      this.store.set({ timing: this.lastTiming });
      this.dataset.renders = String(this.renders);
      this.dispatchEvent(new CustomEvent('wl-rendered', { detail: this.lastTiming, ...EVENT }));
    });
  }

  /** A wing became ready: publish it, keep the selected mode within 1..N, recompute. */
  feReady(fe) {
    const s = this.store.get();
    /** @type {Partial<LabState>} */
    const patch = { fe };
    if (Number(s.mode) > fe.modes.length) patch.mode = '1';
    // A chosen strain point that is not on the new wing falls back to the wing's own point.
    if (s.strain_point) {
      try {
        this.engine.modalStrainAt(s.strain_point);
      } catch {
        patch.strain_point = null;
        this.notice(`The chosen strain point (${s.strain_point.join(', ')}) mm is not on this wing; using the wing's own strain point.`);
      }
    }
    this.store.set(patch);
    this.schedule();
  }

  /**
   * Restores what the URL carries beyond the query: a `planform=` file (same origin, relative)
   * and the `#s=` fragment (outline, kinematics, strain point). Each failure is a notice; the
   * lab then goes on with the defaults for that part.
   */
  async restoreShared() {
    if (!this.hasAttribute('sync-url')) return;
    this.pending++;
    const notes = [];
    try {
      const s = this.store.get();
      if (s.planform) {
        try {
          const points = await this.fetchPlanform(s.planform);
          this.store.set({ wing: { input: null, source: 'url', label: s.planform, outline: 'file', points } });
        } catch (e) {
          notes.push(`The planform file “${s.planform}” could not be used (${errorText(e)}); using the built-in outline.`);
          this.store.set({ planform: '' });
        }
      }
      const frag = fragmentValue(location.hash);
      if (frag) {
        try {
          const st = await decodeShare(frag);
          /** @type {Partial<LabState>} */
          const patch = {};
          if (st.outline) {
            const points = checkPoints(st.outline);
            patch.wing = { input: null, source: 'share', label: typeof st.outline_label === 'string' ? st.outline_label.slice(0, 80) : 'shared outline', outline: 'shared', points };
            patch.planform = '';
          }
          if (st.kin) patch.kin = this.kinFromShare(st.kin);
          if (st.strain_point) patch.strain_point = checkPoints([st.strain_point, st.strain_point, st.strain_point], 'strain_point')[0];
          this.store.set(patch);
        } catch (e) {
          notes.push(`The shared wing/kinematics in the link (#s=…) could not be restored: ${errorText(e)}. The lab uses its defaults for them.`);
        }
      }
    } finally {
      this.pending--;
    }
    if (notes.length) this.notice(notes.join(' '));
  }

  /** A `planform=` file: relative same-origin URL only (state.js checked the text), CSV or JSON. */
  async fetchPlanform(path) {
    const url = new URL(path, location.href);
    if (url.origin !== location.origin) throw new Error('only same-origin files can be loaded');
    const res = await fetch(url, { credentials: 'same-origin' });
    if (!res.ok) throw new Error(`HTTP ${res.status}`);
    const text = await res.text();
    if (text.length > 1e6) throw new Error('the file is larger than 1 MB');
    return this.engine.parsePlanform(text, /\.json$/i.test(path) ? 'json' : 'csv');
  }

  /**
   * Kinematics from a share fragment: the CSV again (same core function) or the config itself.
   * @returns {import('./lab.js').KinState}
   */
  kinFromShare(k) {
    if (!k || typeof k !== 'object') throw new Error('kin: expected an object');
    if (k.csv && typeof k.csv.text === 'string') {
      const r = this.engine.kinematicsFromCsv(k.csv.text, { units: k.csv.units, flap_hz: k.csv.flap_hz, max_harmonic: k.csv.max_harmonic });
      return { kinematics: k.kinematics || r.kinematics, source: /** @type {const} */ ('share'), label: String(k.label || 'shared kinematics').slice(0, 80), samples: r.samples, csv: k.csv };
    }
    if (!k.kinematics || typeof k.kinematics !== 'object') throw new Error('kin.kinematics: expected the core’s Kinematics object');
    // Checked by the core on the first computation (applyOverrides validates the config).
    return { kinematics: k.kinematics, source: /** @type {const} */ ('share'), label: String(k.label || 'shared kinematics').slice(0, 80), samples: null, csv: null };
  }

  /** Writes the `#s=` fragment (own outline, kinematics, strain point) after the state settles. */
  scheduleFragment() {
    clearTimeout(this.fragTimer);
    this.fragTimer = setTimeout(() => this.writeFragment(), 300);
  }

  async writeFragment() {
    const s = this.store.get();
    /** @type {Record<string, unknown>} */
    const st = {};
    if (s.wing && s.wing.points && s.wing.source !== 'url' && s.wing.source !== 'import') {
      st.outline = s.wing.points;
      st.outline_label = s.wing.label;
    }
    if (s.kin) {
      const csv = s.kin.csv && s.kin.csv.text.length <= 20000 ? s.kin.csv : null;
      st.kin = { label: s.kin.label, kinematics: s.kin.kinematics, csv };
    }
    if (s.strain_point) st.strain_point = s.strain_point;
    let hash = '';
    if (Object.keys(st).length) {
      try {
        // The finest rounding that keeps the whole link within 2000 characters; a notice if not.
        hash = (await shareLink(st, location.href.split('#')[0], (m) => this.notice(m))).hash;
      } catch {
        hash = '';
      }
    }
    if (hash !== location.hash && !(hash === '' && !location.hash)) {
      history.replaceState(null, '', `${location.pathname}${location.search}${hash}`);
    }
  }

  /** Query-string writes: at most one per 250 ms while sliders move (Chromium throttles more). */
  scheduleUrl() {
    const write = () => {
      this.urlTimer = 0;
      this.urlWritten = performance.now();
      /** @type {Record<string, string>} */
      const extra = new URLSearchParams(location.search).get('embed') === '1' ? { embed: '1' } : {};
      history.replaceState(null, '', `${location.pathname}?${toQuery(this.state, extra)}${location.hash}`);
    };
    if (this.urlTimer) return;
    const since = performance.now() - (this.urlWritten || -1e9);
    // Never in the key press's own task: history.replaceState costs ~10 ms in Chromium, which
    // would delay the paint of the slider's new value.
    this.urlTimer = setTimeout(write, Math.max(20, 250 - since));
  }

  // ---------- export ----------

  async export(name, kind, label = name) {
    const reg = this.exportsReg[name];
    const nothing = () => this.notice(`Nothing to export yet for “${plain(label)}”: run it first.`);
    if (!reg) return nothing();
    if (kind === 'csv') {
      const text = reg.csv && reg.csv();
      if (!text) return nothing();
      download(`wingbeat-${name}.csv`, new Blob([text], { type: 'text/csv;charset=utf-8' }));
      this.lastExport = { name, kind };
      return;
    }
    const fig = reg.figure && reg.figure();
    if (kind === 'svg') {
      if (!fig) return nothing();
      const probe = canvasPainter(context2d(document.createElement('canvas')));
      download(`wingbeat-${name}.svg`, new Blob([figureSVG(fig, FIG_W, FIG_H, (s, size) => probe.measure(s, size))], { type: 'image/svg+xml' }));
      this.lastExport = { name, kind };
      return;
    }
    let out;
    if (fig) out = await figurePNG(fig, FIG_W, FIG_H, 2);
    else if (reg.table && reg.table()) out = await tablePNG(plain(label), describe(this.store.get()), reg.table(), 2);
    else if (reg.canvas && reg.canvas()) out = await canvasPNG(plain(label), describe(this.store.get()), reg.canvas());
    else return nothing();
    download(`wingbeat-${name}.png`, out.blob);
    this.lastExport = { name, kind, width: out.width, height: out.height, legend: fig ? fig.series.filter((s) => s.show !== false).map((s) => s.color) : [] };
  }
}

/** A drawn canvas (the heat map) with title and parameter line, at 2×. */
function canvasPNG(title, params, src) {
  const w = Math.max(600, src.width + 32), h = src.height + 90;
  const c = document.createElement('canvas');
  c.width = 2 * w;
  c.height = 2 * h;
  const ctx = context2d(c);
  ctx.scale(2, 2);
  const p = canvasPainter(ctx);
  p.rect(0, 0, w, h, '#fff');
  p.text(16, 26, title, { size: 17, weight: 'bold', color: '#111' });
  p.text(16, 46, params.length > 130 ? params.slice(0, 127) + '…' : params, { size: 11, color: '#444' });
  ctx.drawImage(src, 16, 64);
  return new Promise((resolve) => c.toBlob((blob) => resolve({ blob, width: c.width, height: c.height }), 'image/png'));
}

void drawFigure;

if (!customElements.get('wing-lab')) customElements.define('wing-lab', WingLab);
