// @ts-check
// <wing-lab>: the wingbeat browser lab as a custom element (no framework). It renders into an
// OPEN shadow root (lab.shadowRoot) with its own stylesheets (style.css, vendor/uPlot.min.css,
// loaded from lab.js's own URL), so no style leaks out into the host page and the page's
// styles do not reach inside; the host page sizes and places the element like any block.
//
//   <script type="module" src="lab.js"></script>
//   <wing-lab gamma0="0.1" flap_hz="25" panels="controls,numbers,spectrum"></wing-lab>
//
// Module map (model / view split in the manner of PhET sims; each module has one job; the
// table in ARCHITECTURE.md, "The lab", says more):
//   state.js     pure: parameters, URL/attribute parsing and validation, overridesOf (the
//                SimConfig itself is the core's: engine.config → wasm applyOverrides)
//   store.js     observable state: get / set(patch) / subscribe(keys, fn); keys = the URL
//                parameters + result (latest analysis, with angles), fe, t3d (3-D instant),
//                playing, timing, status
//   engine.js    the ONLY module that talks to wasm and to the workers (worker.js); its parts
//                are in engine/ (wasm loading, worker protocol, live requests, jobs, caches)
//   decimate.js, format.js, dom.js, layout.js, screens.js, plot.js, export.js, beat.js,
//   scene3d.js   helpers: decimation, formatting, DOM, the grid, the screens, uPlot, figures,
//                the beat, the 3-D camera
//   views/<panel>.js  one per panel; `export const title` and `mount(ctx)` → { destroy() }.
//                Views read the store and call ctx.* only; they never import engine.js.
//   lab.js       this element: creates store + engine, lays out the panels (order in LAYOUT),
//                mounts the views, recomputes on parameter changes. Its parts are in lab/:
//                panels.js (the views and their order, LAYOUT), live.js (the live recompute,
//                the wing wanted, the FE wing), url.js (first state from attributes and URL,
//                URL writes, share fragment), draws.js (a new result's redraws, one panel per
//                task), nav.js (the screen tabs), exports.js (export buttons and downloads),
//                types.js (LabState, ViewContext, …).
// Adding a panel (e.g. views/experiments.js, views/resonance.js): add its name to PANELS in
// state.js, import it into VIEWS in lab/panels.js, put it in LAYOUT there (visual order = tab
// order), and give it a place in layout.js's TEMPLATES (the grid is computed there from the
// panels shown).
// The view gets ctx = { store, engine, section, uid, id(s), registerPlot(name, plot),
// registerExport(name, { csv, figure, table, canvas }), exportButtons(name, label, kinds),
// toCSV, emit(type, detail), notice(text), setParams(patch), showPanel(name) }.
// Screens (www/screens.js, the one table of screen → panels): a tablist above the grid opens one
// screen at a time (`screen` attribute / URL parameter, lab.screen, iframe set({screen})); the
// panels of other screens are hidden and skip their redraws until shown (lab/draws.js).
//
// Attributes: every URL parameter of www/state.js (alpha0, beta0, gamma0, flap_hz, zeta,
// alpha_phase, beta_phase, gamma_phase, duration, modes, mode, detrend, panels), plus
// `sync-url` (state read from and written to the page's query string), `embed` (compact, one
// column), `layout` (wide | medium | narrow: a fixed layout instead of the width's) and `render`
// (`main`: the 3-D view draws on the page's main thread instead of its worker, e.g. to compare;
// read when the view is made). They are read when the element connects; later changes apply too
// (observedAttributes).
// Several labs on one page are independent: each has its own store, engine and worker; they
// share the (stateless) wasm module. Assets resolve relative to this file, also when it is
// loaded from another origin (the lab's host must then send CORS headers; the worker starts
// from a same-origin Blob that imports worker.js, see engine/wasm.js).
// Test hooks: data-renders, data-layout (on the host), events wl-ready / wl-rendered / wl-study
// (bubbling and composed), and the properties state, analysis, plots, studies, wing3d,
// timeCursor, fe, config(), modeIndex(), views, lastExport, lastTiming; inside: lab.shadowRoot.
import { NUMERIC, ENUMS, WING, parsePairs, defaults, paramsOf, describe } from './state.js';
import { experimentPatch } from './experiments.js';
import { createStore } from './store.js';
import { createEngine } from './engine.js';
import { el, shadowStyles } from './dom.js';
import { layoutMode, gridLayout, areasCss } from './layout.js';
import { EXPERIMENT_SCREEN, SCREENS, resolveScreen, screenOfPanel } from './screens.js';
import { plain, errorText } from './format.js';
import { toCSV } from './export.js';
import { initialState, createUrlSync, WING_KEYS, LIVE_ATTRS } from './lab/url.js';
import { createDraws } from './lab/draws.js';
import { createLive } from './lab/live.js';
import { createNav } from './lab/nav.js';
import { exportPanel, exportButtons } from './lab/exports.js';
import { VIEWS, LAYOUT } from './lab/panels.js';

export { loadWasm } from './engine.js';
export { LAYOUT };

/** @typedef {import('./lab/types.js').LabState} LabState */
/** @typedef {import('./lab/types.js').WingState} WingState */
/** @typedef {import('./lab/types.js').KinState} KinState */
/** @typedef {import('./lab/types.js').Plot} Plot */
/** @typedef {import('./lab/types.js').ExportReg} ExportReg */
/** @typedef {import('./lab/types.js').ViewContext} ViewContext */
/** @typedef {import('./lab/types.js').View} View */

const PARAM_KEYS = [
  ...NUMERIC.map((p) => p.key),
  ...ENUMS.map((e) => e.key),
  ...WING.map((w) => w.key),
  'outline',
  'planform',
];
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
  /** @type {ReturnType<typeof createDraws>} */
  draws;
  /** @type {ReturnType<typeof createLive>} */
  live;
  /** @type {ReturnType<typeof createUrlSync>} */
  url;
  /** @type {ReturnType<typeof createNav>} */
  nav;
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
  /** the grid's current columns and areas (CSS text) */
  gridCols = '';
  gridAreas = '';

  static get observedAttributes() {
    return ['embed', 'layout', ...LIVE_ATTRS];
  }

  constructor() {
    super();
    this.attachShadow({ mode: 'open' });
    this.uid = `wl${++instances}`;
    /** 1 for the first lab built on the page, 2 for the next, … (accessible names) */
    this.ordinal = 0;
    this.renders = 0;
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
    /** @type {import('./lab/exports.js').ExportDone | undefined} the last export (a test hook) */
    this.lastExport = undefined;
    /** @type {string | undefined} the screen shown (applyPanels) */
    this.shownScreen = undefined;
    /** @type {string[] | null} its panels */
    this.shownPanels = null;
  }

  // ---------- test and embedding hooks ----------
  get state() {
    return this.store ? paramsOf(this.store.get()) : defaults();
  }
  get analysis() {
    const r = this.store && this.store.get().result;
    return r ? r.analysis : undefined;
  }
  get plots() {
    const o = {};
    for (const [k, p] of Object.entries(this.plotReg)) o[k] = p.u;
    return o;
  }
  get studies() {
    return this.views.studies ? this.views.studies.studies : {};
  }
  get wing3d() {
    return this.views.wing3d;
  }
  get timeCursor() {
    return this.store ? this.store.get().t3d : null;
  }
  get fe() {
    return this.engine ? this.engine.fe : null;
  }
  config() {
    return this.engine.config(this.state);
  }
  modeIndex() {
    return Number(this.state.mode) - 1;
  }

  connectedCallback() {
    if (this.built) return;
    this.built = true;
    if (!this.ordinal) this.ordinal = ++labsBuilt;
    const syncUrl = this.hasAttribute('sync-url');
    const attrs = /** @type {[string, string][]} */ (
      [...this.attributes]
        .filter((a) => !a.name.startsWith('aria-') && !a.name.startsWith('data-'))
        .map((a) => [a.name, a.value])
    );
    const { params, rejected } = initialState({ attrs, search: syncUrl ? location.search : null });
    this.store = createStore({
      ...params,
      screen: params.screen || '',
      result: null,
      fe: null,
      t3d: null,
      playing: false,
      timing: null,
      status: 'loading wasm…',
      wing: null,
      kin: null,
      strain_point: null,
      strain_map: null,
    });
    const engine = createEngine();
    this.engine = engine;
    this.live = createLive({
      store: this.store,
      engine,
      alive: () => !!this.built && this.engine === engine,
      error: (t) => this.error(t),
      notice: (t) => this.notice(t),
      publish: (r) => this.draws.publish(r),
    });
    this.draws = createDraws({
      store: this.store,
      section: (name) => this.panels[name],
      live: () => !!this.built,
      rendered: (r, t1) => this.finishRender(r, t1),
    });
    this.url = createUrlSync({
      store: this.store,
      engine: this.engine,
      notice: (t) => this.notice(t),
      params: () => this.state,
    });
    this.build();
    if (rejected.length) {
      this.notice(
        `Ignored ${rejected.length} invalid parameter(s), using defaults instead: ` +
          rejected.map((r) => `${r.key} (${r.why})`).join('; '),
      );
    }
    this.subscribe();
    this.engine
      .load()
      .then(() => this.restoreShared())
      .then(() => {
        this.root.classList.remove('wl-loading');
        this.live.wantWing();
        this.live.render();
        // The live worker starts when someone is about to use the lab (focus or pointer inside
        // it, or the first parameter change), so it is ready before the first key press.
        const warm = () => {
          if (this.built) this.engine.warmLive();
        };
        this.root.addEventListener('focusin', warm, { once: true });
        this.root.addEventListener('pointerdown', warm, { once: true });
        if (this.store.get().panels.includes('wing3d')) this.views.wing3d.startWhenVisible();
        this.dispatchEvent(new CustomEvent('wl-ready', EVENT));
      })
      .catch((e) => this.error(`Could not load the wasm module: ${errorText(e)}`));
  }

  /** What follows a change of the store: recomputes, the wing wanted, the screen, URL writes. */
  subscribe() {
    const syncUrl = () => this.hasAttribute('sync-url');
    this.unsub.push(
      this.store.subscribe(PARAM_KEYS, () => {
        this.live.schedule();
        if (syncUrl()) this.url.scheduleQuery();
      }),
      this.store.subscribe(['panels', 'screen'], () => this.applyPanels()),
      this.store.subscribe(['exp', 'screen'], (st, changed) => {
        // Choosing an experiment (chip, attribute, message) opens its screen.
        if (st.exp && changed.includes('exp') && !changed.includes('screen') && EXPERIMENT_SCREEN[st.exp])
          this.store.set({ screen: EXPERIMENT_SCREEN[st.exp] });
        if (syncUrl()) this.url.scheduleQuery();
      }),
      this.store.subscribe(['body_rate', 'body_axis'], () => {
        if (syncUrl()) this.url.scheduleQuery();
      }),
      this.store.subscribe(WING_KEYS, () => {
        this.live.wantWing();
        this.live.schedule();
      }),
      this.store.subscribe(['modes', 'mode'], (st) => {
        const n = st.modes === 'fe' ? (st.fe ? st.fe.modes.length : 8) : 2;
        if (Number(st.mode) > n) this.store.set({ mode: '1' });
      }),
      this.store.subscribe(['kin'], (st) => {
        this.engine.setKinematics(st.kin ? st.kin.kinematics : null);
        this.live.schedule();
      }),
      this.store.subscribe(['strain_point'], (st) => {
        this.engine.setStrainPoint(st.strain_point);
        this.live.schedule();
      }),
      this.store.subscribe(['wing', 'kin', 'strain_point'], () => {
        if (syncUrl()) this.url.scheduleFragment();
      }),
    );
  }

  disconnectedCallback() {
    this.live.reset();
    this.draws.reset();
    this.shownScreen = undefined;
    this.shownPanels = null;
    for (const v of Object.values(this.views)) if (v && v.destroy) v.destroy();
    for (const f of this.unsub) f();
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
    this.store.set(
      name === 'exp' && state.exp
        ? /** @type {Partial<LabState>} */ (experimentPatch(state.exp))
        : { [name]: state[name] },
    );
  }

  // ---------- DOM ----------

  build() {
    const id = (s) => `${this.uid}-${s}`;
    this.root = el('div', { class: 'wl-root wl-loading' });
    this.noticeEl = el('p', { class: 'wl-notice', role: 'status', hidden: true });
    this.errorEl = el('p', { class: 'wl-error', role: 'alert', hidden: true });
    const grid = el('div', { class: 'wl-grid', id: id('screen'), role: 'tabpanel' });
    this.nav = createNav({ id, labName: this.labName(), open: (screen) => this.showScreen(screen) });
    this.root.append(this.noticeEl, this.errorEl, this.nav.list, this.nav.about, grid);
    this.panels = {};
    /** @type {Omit<ViewContext, 'section'>} */
    const ctx0 = {
      store: this.store,
      engine: this.engine,
      uid: this.uid,
      id,
      toCSV,
      registerPlot: (name, plot) => {
        this.plotReg[name] = plot;
      },
      registerExport: (name, reg) => {
        this.exportsReg[name] = reg;
      },
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
      const named = labName
        ? { 'aria-label': `${plain(view.title)} — ${labName}` }
        : { 'aria-labelledby': id(`h-${name}`) };
      const sec = el('section', { class: `wl-panel wl-${name}`, 'data-panel': name, ...named });
      const head = el('div', { class: 'wl-head' }, el('h2', { id: id(`h-${name}`), text: view.title }));
      sec.append(head);
      this.panels[name] = sec;
      grid.append(sec);
      this.views[name] = view.mount({ ...ctx0, store: this.draws.viewStore(name), section: sec });
      const reg = this.exportsReg[name];
      if (reg) head.append(this.exportButtons(name, view.title, reg.figure ? ['csv', 'png', 'svg'] : ['csv', 'png']));
    }
    this.grid = grid;
    const shadow = /** @type {ShadowRoot} */ (this.shadowRoot);
    // Invisible (not unstyled) until style.css and uPlot's sheet have loaded: no flash.
    this.root.dataset.css = 'loading';
    shadowStyles(shadow).then(() => {
      delete this.root.dataset.css;
    });
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

  /** A panel's export buttons (lab/exports.js). */
  exportButtons(/** @type {string} */ name, /** @type {string} */ label, kinds = ['csv', 'png']) {
    return exportButtons(name, label, kinds, (n, kind, l) => this.export(n, kind, l));
  }

  /** Downloads panel `name`'s export of `kind` (csv | png | svg); a notice when there is nothing yet. */
  async export(/** @type {string} */ name, /** @type {string} */ kind, label = name) {
    const done = await exportPanel(this.exportsReg[name], name, kind, label, {
      notice: (t) => this.notice(t),
      describe: () => describe(this.store.get()),
    });
    if (done) this.lastExport = done;
  }

  /**
   * Shows the panels of the screen in use (www/screens.js: the wanted screen and the author's
   * `panels=` choice), selects its tab, and redraws the panels that come into view with what
   * they skipped while hidden (hidden panels do not redraw, see lab/draws.js).
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
      if (was && !sec.hidden) this.draws.flush(name);
    }
    // The nav belongs to the whole lab: an author's own panel choice (panels=) is one page.
    this.nav.select(
      r.id,
      LAYOUT.every((p) => st.panels.includes(p)),
      this.grid,
    );
    this.dataset.screen = r.id;
    // Views that show less on a focused screen (folded options) than on the full page.
    if (before !== r.id) for (const v of Object.values(this.views)) if (v && v.setScreen) v.setScreen(r.id);
    this.applyLayout();
    if (before !== undefined && before !== r.id) {
      // Focus that was in a panel now hidden goes to the selected tab (never lost to <body>).
      const tab = this.nav.tabs[r.id];
      if (focused && focused !== tab && !(/** @type {HTMLElement} */ (focused).checkVisibility?.())) tab.focus();
      this.dispatchEvent(new CustomEvent('wl-screen', { detail: { screen: r.id, panels: r.shown.slice() }, ...EVENT }));
    }
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
  get screen() {
    return this.shownScreen || '';
  }
  set screen(v) {
    this.showScreen(String(v));
  }

  /** Opens the screen that holds a panel (e.g. a guided experiment's "Go to" button). */
  showPanel(/** @type {string} */ name) {
    if (this.panels[name] && this.panels[name].hidden) this.showScreen(screenOfPanel(name, LAYOUT));
  }

  notice(text) {
    this.noticeEl.textContent = text;
    this.noticeEl.hidden = false;
  }

  error(text) {
    this.errorEl.textContent = text;
    this.errorEl.hidden = !text;
  }

  /** All panels show the newest result (published at t1): timing, data-renders and `wl-rendered`. */
  finishRender(/** @type {import('./engine.js').LiveResult} */ r, /** @type {number} */ t1) {
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

  /** Restores the `planform=` file and the `#s=` fragment (lab/url.js) before the first computation. */
  async restoreShared() {
    if (!this.hasAttribute('sync-url')) return;
    await this.live.holding(() => this.url.restore());
  }
}

if (!customElements.get('wing-lab')) customElements.define('wing-lab', WingLab);
