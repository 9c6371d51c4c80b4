// <wing-lab>: the wingbeat browser lab as a custom element (light DOM, no framework).
//
//   <script type="module" src="lab.js"></script>
//   <wing-lab gamma0="0.1" flap_hz="25" panels="controls,numbers,spectrum"></wing-lab>
//
// Attributes: every URL parameter of www/state.js (alpha0, beta0, gamma0, flap_hz, zeta,
// alpha_phase, beta_phase, gamma_phase, duration, modes, mode, detrend, panels), plus
// `sync-url` (state read from and written to the page's query string) and `embed` (compact).
// Several labs on one page are independent: each has its own state and its own worker; they
// share the (stateless) wasm module. Assets resolve relative to this file, so the element
// works from any static host without a bundler, CDN or COOP/COEP headers.
import { NUMERIC, ENUMS, PANELS, SAMPLE_RATE_HZ, FE_LAB_INPUT, defaults, parsePairs, parseQuery, toQuery, snap, toConfig } from './state.js';
import { linePlot, autoWidth, decimate, toCSV, download, panelPNG, drawHeatmap, color, fmt, log10OrNull } from './plot.js';
import { Wing3D } from './wing3d.js';

const HERE = new URL('.', import.meta.url);

// Stylesheets, once per document.
function ensureStyles() {
  for (const href of ['vendor/uPlot.min.css', 'style.css']) {
    const url = new URL(href, HERE).href;
    if (![...document.querySelectorAll('link[rel=stylesheet]')].some((l) => l.href === url)) {
      const l = document.createElement('link');
      l.rel = 'stylesheet';
      l.href = url;
      document.head.appendChild(l);
    }
  }
}

let wasmPromise = null;
/** Loads and instantiates the wasm module once per page. */
export function loadWasm() {
  if (!wasmPromise) {
    wasmPromise = import(new URL('pkg/wingbeat.js', HERE).href).then(async (m) => {
      await m.default({ module_or_path: new URL('pkg/wingbeat_bg.wasm', HERE) });
      return m;
    });
  }
  return wasmPromise;
}

const Q_UNIT = 'kg^½·m';
const F_UNIT = 'kg^½·m/s²';
const LIVE_BUCKETS = 1500;
let instances = 0;

function el(tag, props = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) {
    if (k === 'class') e.className = v;
    else if (k === 'text') e.textContent = v;
    else if (k.startsWith('aria-') || k.startsWith('data-') || k === 'role' || k === 'for' || k === 'hidden') {
      if (v !== false && v != null) e.setAttribute(k, v === true ? '' : v);
    } else e[k] = v;
  }
  for (const c of children) if (c != null) e.append(c);
  return e;
}

const PANEL_TITLES = {
  controls: 'Parameters',
  numbers: 'Floquet & contributions',
  time: 'Responses (paper Fig. 5)',
  spectrum: 'Spectra of the force terms',
  strain: 'Strain at the point P (paper Fig. 9)',
  studies: 'Studies (paper Figs. 6–8)',
  wing3d: '3-D wing',
  report: 'Paper claims check',
};

export class WingLab extends HTMLElement {
  constructor() {
    super();
    this.uid = `wl${++instances}`;
    this.state = defaults();
    this.plots = {};
    this.renders = 0;
    this.jobs = new Map();
    this.jobId = 0;
    this.raf = 0;
  }

  connectedCallback() {
    if (this.built) return;
    this.built = true;
    ensureStyles();
    this.classList.add('wing-lab');
    const ignore = ['id', 'class', 'style', 'sync-url', 'embed', 'hidden', 'title', 'lang', 'dir'];
    const attrs = [...this.attributes]
      .filter((a) => !a.name.startsWith('aria-') && !a.name.startsWith('data-'))
      .map((a) => [a.name, a.value]);
    const fromAttrs = parsePairs(attrs, ignore);
    this.state = fromAttrs.state;
    const rejected = [...fromAttrs.rejected];
    if (this.hasAttribute('sync-url')) {
      const q = parseQuery(location.search);
      for (const [k, v] of new URLSearchParams(location.search)) {
        if (k === 'embed') continue;
        if (!q.rejected.some((r) => r.key === k) && k in q.state) this.state[k] = q.state[k];
      }
      rejected.push(...q.rejected.filter((r) => r.key !== 'embed'));
    }
    if (this.hasAttribute('embed')) this.classList.add('wl-embed');
    this.build();
    if (rejected.length) {
      this.notice(
        `Ignored ${rejected.length} invalid parameter(s), using defaults instead: ` +
          rejected.map((r) => `${r.key} (${r.why})`).join('; '),
      );
    }
    this.syncInputs();
    loadWasm()
      .then((wb) => {
        this.wb = wb;
        this.base = wb.defaultConfig();
        this.limits = wb.limits();
        this.root.classList.remove('wl-loading');
        this.render();
        if (this.state.panels.includes('wing3d')) this.wing3d.startWhenVisible(wb);
        this.dispatchEvent(new CustomEvent('wl-ready', { bubbles: true }));
      })
      .catch((e) => this.error(`Could not load the wasm module: ${e && e.message ? e.message : e}`));
  }

  disconnectedCallback() {
    if (this.worker) this.worker.terminate();
    this.worker = null;
    if (this.wing3d) this.wing3d.stop();
    for (const ro of this.observers || []) ro.disconnect();
  }

  // ---------- DOM ----------

  build() {
    const id = (s) => `${this.uid}-${s}`;
    this.root = el('div', { class: 'wl-root wl-loading' });
    this.noticeEl = el('p', { class: 'wl-notice', role: 'status', hidden: true });
    this.errorEl = el('p', { class: 'wl-error', role: 'alert', hidden: true });
    this.root.append(this.noticeEl, this.errorEl);
    const grid = el('div', { class: 'wl-grid' });
    this.root.append(grid);
    this.panels = {};
    for (const name of PANELS) {
      const sec = el('section', { class: `wl-panel wl-${name}`, 'data-panel': name, 'aria-labelledby': id(`h-${name}`) });
      const head = el('div', { class: 'wl-head' }, el('h2', { id: id(`h-${name}`), text: PANEL_TITLES[name] }));
      if (['numbers', 'time', 'spectrum', 'strain'].includes(name)) head.append(this.exportButtons(name));
      sec.append(head);
      this.panels[name] = sec;
      grid.append(sec);
    }
    this.buildControls(id);
    this.buildNumbers();
    this.buildPlots();
    this.buildStudies();
    this.buildWing3d();
    this.buildReport();
    this.applyPanels();
    this.append(this.root);
  }

  exportButtons(name, label = PANEL_TITLES[name]) {
    const box = el('span', { class: 'wl-export' });
    box.append(
      el('button', { type: 'button', text: 'CSV', 'data-export': 'csv', 'data-target': name, 'aria-label': `Export ${label} as CSV`, onclick: () => this.exportCSV(name) }),
      el('button', { type: 'button', text: 'PNG', 'data-export': 'png', 'data-target': name, 'aria-label': `Export ${label} as PNG`, onclick: () => this.exportPNG(name) }),
    );
    return box;
  }

  buildControls(id) {
    const sec = this.panels.controls;
    const preset = el('button', {
      type: 'button',
      class: 'wl-preset',
      text: 'Paper forward flight',
      title: 'α0 = 0.8, β0 = 0.5, γ0 = 0.2 rad, f_d = 25 Hz, ζ = 0, phases 0, 2 s (paper Table 5)',
      onclick: () => {
        const keep = this.state.panels;
        this.state = defaults();
        this.state.panels = keep;
        this.syncInputs();
        this.schedule();
      },
    });
    sec.append(el('div', { class: 'wl-presets' }, preset));
    this.inputs = {};
    const form = el('div', { class: 'wl-sliders' });
    for (const p of NUMERIC) {
      const unit = p.unit ? ` (${p.unit})` : '';
      const range = el('input', {
        type: 'range',
        id: id(p.key),
        min: p.min,
        max: p.max,
        step: p.step,
        'data-key': p.key,
        'aria-label': `${p.label}${p.unit ? ', in ' + p.unit : ''}`,
      });
      const num = el('input', {
        type: 'number',
        id: id(`${p.key}-n`),
        min: p.min,
        max: p.max,
        step: p.step,
        'data-key': p.key,
        'aria-label': `${p.label}${p.unit ? ', in ' + p.unit : ''}, exact value`,
      });
      range.addEventListener('input', () => this.set(p.key, Number(range.value), 'range'));
      num.addEventListener('change', () => {
        const v = Number(num.value);
        if (num.value.trim() === '' || !Number.isFinite(v)) {
          num.setAttribute('aria-invalid', 'true');
          return;
        }
        num.removeAttribute('aria-invalid');
        this.set(p.key, v, 'number');
      });
      const row = el(
        'div',
        { class: 'wl-row' },
        el('label', { for: id(p.key), text: `${p.label}${unit}` }),
        range,
        num,
      );
      form.append(row);
      this.inputs[p.key] = { range, num, p };
    }
    sec.append(form);
    const selects = el('div', { class: 'wl-selects' });
    const enumText = {
      modes: { paper: 'Paper table (Tables 3–4)', fe: 'FE wing (shell FE, computed here)' },
      mode: { 1: 'Mode 1: spanwise bending', 2: 'Mode 2: spanwise torsion' },
      detrend: { none: 'none (DC visible)', mean: 'mean', linear: 'linear' },
    };
    this.selects = {};
    for (const e of ENUMS) {
      const s = el('select', { id: id(e.key), 'data-key': e.key });
      for (const c of e.choices) {
        s.append(el('option', { value: c, text: enumText[e.key][c], disabled: (e.disabled || []).includes(c) }));
      }
      s.addEventListener('change', () => this.set(e.key, s.value, 'select'));
      selects.append(el('div', { class: 'wl-row wl-select' }, el('label', { for: id(e.key), text: e.label }), s));
      this.selects[e.key] = s;
    }
    sec.append(selects);
    sec.append(
      el('p', {
        class: 'wl-note',
        text: 'Sampling: 10 kHz. Paper table: Table 4’s a_k are used as printed (not SI), so absolute q, forces and strains are in the paper’s units; shares, spectra shapes and frequencies are unaffected. ' +
          `FE wing: shell finite elements of the synthetic Manduca-like outline (not digitised), 13 % camber, root edge clamped, E = 13.11 GPa, ${FE_LAB_INPUT.mesh_size_mm} mm elements, first ${FE_LAB_INPUT.n_modes} modes; SI a_k and strain at P = (3, −6) mm. Computed once, in a worker.`,
      }),
    );
    this.timingEl = el('p', { class: 'wl-timing', 'aria-live': 'off', text: 'loading wasm…' });
    this.warnEl = el('p', { class: 'wl-warn', role: 'status', hidden: true });
    sec.append(this.warnEl, this.timingEl);
  }

  buildNumbers() {
    const sec = this.panels.numbers;
    const table = el('table', { class: 'wl-numtable' });
    const thead = el('thead', {}, el('tr', {}, el('th', { scope: 'col', text: 'Quantity' }), el('th', { scope: 'col', text: 'Mode 1' }), el('th', { scope: 'col', text: 'Mode 2' })));
    this.rows = [
      ['freq', 'Natural frequency f_k (Hz)'],
      ['feff', 'Floquet effective frequency (Hz)'],
      ['favg', 'Averaged-stiffness estimate (Hz)'],
      ['beat2', 'Beat period vs 2 f_d (s)'],
      ['beat', 'Beat period vs nearest n·f_d (s)'],
      ['mult', 'Floquet multipliers λ (per flap period)'],
      ['mod', 'max |λ|'],
      ['stable', 'Stability'],
      ['euler', 'Euler share (%)'],
      ['centrifugal', 'Centrifugal share (%)'],
      ['coriolis', 'Coriolis share (%)'],
      ['sum', 'Sum of shares (%)'],
      ['peak', `Peak |q| total (${Q_UNIT})`],
    ];
    const tbody = el('tbody');
    this.cells = {};
    for (const [key, label] of this.rows) {
      const tr = el('tr', {}, el('th', { scope: 'row', text: label }));
      for (const k of [0, 1]) {
        const td = el('td', { 'data-field': `${key}-${k}`, text: '—' });
        this.cells[`${key}-${k}`] = td;
        tr.append(td);
      }
      tbody.append(tr);
    }
    table.append(thead, tbody);
    sec.append(table);
    sec.append(
      el('p', {
        class: 'wl-note',
        text: 'Shares are 100·Σq_term²/Σq_total² (paper §4.1). They need not sum to 100 % because the partial responses are not orthogonal (cross terms).',
      }),
    );
  }

  buildPlots() {
    this.observers = [];
    const mk = (name, spec) => {
      const box = el('div', { class: 'wl-plot', 'data-plot': name });
      this.panels[name].append(box);
      const u = linePlot(box, spec);
      this.plots[name] = u;
      this.observers.push(autoWidth(u, box));
      return box;
    };
    const timeBox = mk('time', {
      xLabel: 't',
      xUnit: 's',
      markers: () => (this.timeCursor == null ? [] : [{ x: this.timeCursor, label: '3-D t', color: '#7a3cc2', row: 0 }]),
      yScales: { y: { label: 'q', unit: Q_UNIT } },
      series: [
        { label: 'Euler response', unit: Q_UNIT, color: color('euler') },
        { label: 'Centrifugal response', unit: Q_UNIT, color: color('centrifugal') },
        { label: 'Coriolis response', unit: Q_UNIT, color: color('coriolis') },
        { label: 'Total', unit: Q_UNIT, color: color('total'), width: 1.5 },
        { label: 'Coriolis envelope', unit: Q_UNIT, color: color('envelope'), dash: [6, 4] },
      ],
    });
    // A click on the responses plot poses the 3-D wing at that instant.
    const tu = this.plots.time;
    tu.over.addEventListener('click', (e) => {
      if (this.wing3d && this.wing3d.view) this.wing3d.setTime(tu.posToVal(e.offsetX, 'x'));
    });
    timeBox.title = 'Click to show this instant in the 3-D wing panel';
    const spec = this.panels.spectrum;
    mk('spectrum', {
      xLabel: 'f',
      xUnit: 'Hz',
      yScales: {
        y: { label: 'force PSD', unit: `(${F_UNIT})²/Hz`, log: true },
        y2: { label: 'response PSD', unit: `(${Q_UNIT})²/Hz`, log: true, side: 1 },
      },
      series: [
        { label: 'Euler force', unit: `(${F_UNIT})²/Hz`, color: color('euler') },
        { label: 'Centrifugal force', unit: `(${F_UNIT})²/Hz`, color: color('centrifugal') },
        { label: 'Coriolis force', unit: `(${F_UNIT})²/Hz`, color: color('coriolis') },
        { label: 'Stiffness term (α̇²cos²β+β̇²)·q', unit: `(${F_UNIT})²/Hz`, color: color('stiffness') },
        { label: 'Total response', unit: `(${Q_UNIT})²/Hz`, color: color('total'), scale: 'y2', dash: [3, 3] },
      ],
      markers: () => this.markers || [],
      height: 260,
    });
    spec.append(
      el('p', {
        class: 'wl-note',
        text: 'Welch PSD, Hann window, 8192-sample segments, one-sided. Grey lines: multiples n·f_d of the flap frequency; blue dashed: natural frequency f_k; red: Floquet effective frequency. Hover for values (legend).',
      }),
    );
    mk('strain', {
      xLabel: 't',
      xUnit: 's',
      yScales: { y: { label: 'strain', unit: 'paper units' } },
      series: [
        { label: 'ε_x', unit: '', color: color('eps_x') },
        { label: 'ε_y', unit: '', color: color('eps_y') },
        { label: 'γ_xy', unit: '', color: color('gamma_xy') },
      ],
    });
    this.panels.strain.append(
      (this.strainNote = el('p', { class: 'wl-note' })),
    );
  }

  buildStudies() {
    const sec = this.panels.studies;
    this.studies = {};
    const study = (key, title, controls, run, note) => {
      const box = el('div', { class: 'wl-study', 'data-study': key });
      const head = el('div', { class: 'wl-head' }, el('h3', { text: title }), this.exportButtons(key, title));
      const btn = el('button', { type: 'button', class: 'wl-run', text: 'Run', 'data-run': key });
      const prog = el('progress', { class: 'wl-progress', max: 1, value: 0, hidden: true, 'aria-label': `${title} progress` });
      const status = el('span', { class: 'wl-status', role: 'status' });
      const out = el('div', { class: 'wl-study-out' });
      btn.addEventListener('click', () => run(btn, prog, status, out));
      box.append(head, el('div', { class: 'wl-study-controls' }, ...controls, btn, prog, status));
      if (note) box.append(el('p', { class: 'wl-note', text: note }));
      box.append(out);
      sec.append(box);
      this.studies[key] = { box, out, status };
    };
    const num = (label, value, min, max, step) => {
      const i = el('input', { type: 'number', value, min, max, step, 'aria-label': label });
      return [el('label', { class: 'wl-inline' }, label + ' ', i), i];
    };
    const sel = (label, opts, value) => {
      const s = el('select', { 'aria-label': label });
      for (const [v, t] of opts) s.append(el('option', { value: v, text: t }));
      s.value = value;
      return [el('label', { class: 'wl-inline' }, label + ' ', s), s];
    };

    // Fig. 6: contribution vs a parameter.
    const [lp, sp] = sel('parameter', [['gamma0', 'γ0 (rad)'], ['alpha0', 'α0 (rad)'], ['beta0', 'β0 (rad)'], ['flap_hz', 'f_d (Hz)'], ['zeta', 'ζ']], 'gamma0');
    const [lf, from] = num('from', 0, -1e3, 1e3, 'any');
    const [lt, to] = num('to', 0.5, -1e3, 1e3, 'any');
    const [ln, pts] = num('points', 26, 2, 201, 1);
    sp.addEventListener('change', () => {
      const p = NUMERIC.find((q) => q.key === sp.value);
      from.value = p.min;
      to.value = p.max;
    });
    study('sweep', 'Contribution vs parameter (Fig. 6)', [lp, lf, lt, ln], (btn, prog, status, out) => {
      const opts = { param: sp.value, from: Number(from.value), to: Number(to.value), points: Math.round(Number(pts.value)) };
      this.runJob('sweep', { cfg: this.config(), opts }, btn, prog, status, (r, ms) => {
        this.drawSweep(out, r, opts);
        status.textContent = `${r.values.length} points in ${ms.toFixed(0)} ms (worker)`;
      });
    }, 'Each point is a full simulation of the current case with one parameter changed; selected mode shown.');

    // Fig. 7: initial-condition map.
    const [lg, grid] = num('grid', 101, 2, 401, 1);
    const [la, attr] = sel('attribution', [['forced', 'forced (paper)'], ['carried', 'carried']], 'forced');
    study('icmap', 'Initial-condition map (Fig. 7)', [lg, la], (btn, prog, status, out) => {
      const n = Math.round(Number(grid.value));
      const opts = { mode: this.modeIndex(), n_q: n, n_qdot: n, attribution: attr.value };
      this.runJob('icmap', { cfg: this.config(), opts }, btn, prog, status, (r, ms) => {
        this.drawIcMap(out, r);
        status.textContent = `${r.n_q}×${r.n_qdot} in ${ms.toFixed(1)} ms (worker); Coriolis share ${fmt(r.min_percent, 3)}–${fmt(r.max_percent, 3)} %, ${fmt(100 * r.fraction_above_60, 3)} % of cells above 60 %`;
      });
    }, 'Coriolis share of the selected mode over a grid of initial conditions (q0, q̇0) spanning the forced response’s range.');

    // Fig. 8: damping.
    const [lz, zeta] = num('ζ', 0.01, 0, 1, 0.001);
    const [ld, dur] = num('duration (s)', 10, 0.5, 60, 0.5);
    study('damping', 'Damping (Fig. 8)', [lz, ld], (btn, prog, status, out) => {
      const cfg = this.config();
      cfg.duration_s = Number(dur.value);
      const opts = { zeta: Number(zeta.value), mode: this.modeIndex() };
      this.runJob('damping', { cfg, opts }, btn, prog, status, (r, ms) => {
        this.drawDamping(out, r);
        status.textContent = `2 runs × ${r.n} samples in ${ms.toFixed(0)} ms (worker)`;
      });
    }, 'Total response of the selected mode, undamped vs damped, over a longer run: damping removes the beat.');
  }

  buildWing3d() {
    // One id per page: the primary (URL-synced or first) lab owns #wing3d (see wing3d.js).
    this.wing3d = new Wing3D(this, this.panels.wing3d);
  }

  /** Marks the 3-D view's instant on the responses plot (a redraw without recomputing paths). */
  showTimeCursor(t) {
    this.timeCursor = t;
    const u = this.plots.time;
    if (u && !this.panels.time.hidden) u.redraw(false, false);
  }

  /**
   * The shell-FE wing of the lab (FE_LAB_INPUT), computed once per element in its worker.
   * Resolves to the wasm `feModes` result (typed arrays for the mesh and shapes).
   */
  ensureFe() {
    if (!this.fePromise) {
      this.fePromise = new Promise((resolve, reject) => {
        const id = ++this.jobId;
        this.jobs.set(id, { resolve: ([r]) => resolve(r), reject: (e) => reject(new Error(e)), progress: () => {} });
        this.ensureWorker().postMessage({ id, kind: 'fe', input: FE_LAB_INPUT });
      }).then((fe) => {
        this.fe = fe;
        const opts = this.selects.mode.options;
        fe.modes.slice(0, opts.length).forEach((m, k) => { opts[k].dataset.fe = `Mode ${k + 1}: ${fe.kinds[k]} (FE, ${fmt(fe.freq_hz[k], 4)} Hz)`; });
        this.labelModes();
        return fe;
      });
      this.fePromise.catch(() => { this.fePromise = null; });
    }
    return this.fePromise;
  }

  /** Mode-select labels for the active mode set (the FE wing's modes have their own kinds). */
  labelModes() {
    for (const o of this.selects.mode.options) {
      if (!o.dataset.paper) o.dataset.paper = o.textContent;
      o.textContent = this.state.modes === 'fe' && o.dataset.fe ? o.dataset.fe : o.dataset.paper;
    }
  }

  buildReport() {
    const sec = this.panels.report;
    const btn = el('button', { type: 'button', class: 'wl-run', text: 'Check the paper’s claims', 'data-run': 'report' });
    const prog = el('progress', { class: 'wl-progress', hidden: true, 'aria-label': 'report progress' });
    const status = el('span', { class: 'wl-status', role: 'status' });
    const out = el('div', { class: 'wl-report-out' });
    btn.addEventListener('click', () =>
      this.runJob('reproduce', {}, btn, prog, status, (r, ms) => {
        out.replaceChildren();
        const t = el('table', { class: 'wl-reporttable' });
        t.append(el('thead', {}, el('tr', {}, ...['Claim', '§', 'Paper says', 'wingbeat computes', 'Verdict'].map((h) => el('th', { scope: 'col', text: h })))));
        const tb = el('tbody');
        for (const c of r.claims) {
          tb.append(el('tr', { class: `wl-v-${c.verdict}` }, el('td', { text: c.id }), el('td', { text: c.section }), el('td', { text: c.paper_says }), el('td', { text: c.computed }), el('td', { text: c.verdict })));
        }
        t.append(tb);
        out.append(t);
        const s = r.summary;
        status.textContent = `${s.holds} hold, ${s.partly} partly, ${s.fails} fail, ${s.input} inputs (${ms.toFixed(0)} ms, worker)`;
      }),
    );
    sec.append(el('div', { class: 'wl-study-controls' }, btn, prog, status), el('p', { class: 'wl-note', text: 'The paper preset as printed, zero initial conditions; every verdict is computed.' }), out);
  }

  applyPanels() {
    for (const [name, sec] of Object.entries(this.panels)) sec.hidden = !this.state.panels.includes(name);
  }

  notice(text) {
    this.noticeEl.textContent = text;
    this.noticeEl.hidden = false;
  }

  error(text) {
    this.errorEl.textContent = text;
    this.errorEl.hidden = !text;
  }

  // ---------- state ----------

  set(key, value, from) {
    const p = NUMERIC.find((q) => q.key === key);
    if (p) {
      const v = snap(p, value);
      this.state[key] = v;
      const inp = this.inputs[key];
      if (from !== 'range') inp.range.value = String(v);
      if (from !== 'number' || v !== value) inp.num.value = String(v);
      inp.range.setAttribute('aria-valuetext', this.valueText(p, v));
    } else {
      const e = ENUMS.find((q) => q.key === key);
      if (!e || !e.choices.includes(value) || (e.disabled || []).includes(value)) return;
      this.state[key] = value;
    }
    this.schedule();
  }

  valueText(p, v) {
    return p.unit ? `${v} ${p.unit}` : String(v);
  }

  syncInputs() {
    for (const { range, num, p } of Object.values(this.inputs)) {
      const v = this.state[p.key];
      range.value = String(v);
      num.value = String(v);
      num.removeAttribute('aria-invalid');
      range.setAttribute('aria-valuetext', this.valueText(p, v));
    }
    for (const [k, s] of Object.entries(this.selects)) s.value = this.state[k];
    this.applyPanels();
  }

  modeIndex() {
    return Number(this.state.mode) - 1;
  }

  config() {
    const base = this.state.modes === 'fe' && this.fe ? { modes: this.fe.modes } : this.base;
    return toConfig(this.state, base);
  }

  schedule() {
    if (this.raf) return;
    this.raf = requestAnimationFrame(() => {
      this.raf = 0;
      this.render();
    });
  }

  // ---------- live compute + draw ----------

  render() {
    if (!this.wb) return;
    if (this.state.modes === 'fe' && !this.fe) {
      this.timingEl.textContent = 'computing the FE wing’s modes in a worker…';
      this.ensureFe().then(
        () => this.schedule(),
        (e) => this.error(`The FE wing could not be computed: ${e && e.message ? e.message : e}`),
      );
      return;
    }
    this.labelModes();
    const k = this.modeIndex();
    const t0 = performance.now();
    let a;
    const cfg = this.config();
    try {
      a = this.wb.analyze(cfg, { detrend: this.state.detrend, segment_len: 8192 }, k);
    } catch (e) {
      this.error(`Computation rejected: ${e && e.message ? e.message : e}`);
      return;
    }
    this.error('');
    const t1 = performance.now();
    this.analysis = a;
    this.drawNumbers(a);
    this.drawTime(a, k);
    this.drawSpectrum(a, k);
    this.drawStrain(a);
    this.wing3d.update(a, cfg);
    const warnings = a.sim.warnings || [];
    this.warnEl.hidden = warnings.length === 0;
    this.warnEl.textContent = warnings.join(' ');
    if (this.hasAttribute('sync-url')) this.scheduleUrl();
    // uPlot commits its redraw in a microtask queued by setData; ours runs after it.
    queueMicrotask(() => {
      const t2 = performance.now();
      this.renders += 1;
      this.lastTiming = { compute: t1 - t0, draw: t2 - t1, end: t2 };
      this.timingEl.textContent = `compute ${(t1 - t0).toFixed(1)} ms + draw ${(t2 - t1).toFixed(1)} ms (${a.sim.n} samples × ${a.sim.modes.length} modes)`;
      this.dataset.renders = String(this.renders);
      this.dispatchEvent(new CustomEvent('wl-rendered', { detail: this.lastTiming }));
    });
  }

  /**
   * Writes the state to the query string: at once when the last write is older than 250 ms,
   * else once at the end of the burst (Chromium throttles pages that call replaceState at
   * frame rate, and a URL that changes 60 times a second helps nobody).
   */
  scheduleUrl() {
    const write = () => {
      this.urlTimer = 0;
      this.urlWritten = performance.now();
      const extra = new URLSearchParams(location.search).get('embed') === '1' ? { embed: '1' } : {};
      history.replaceState(null, '', `${location.pathname}?${toQuery(this.state, extra)}${location.hash}`);
    };
    if (this.urlTimer) return;
    const since = performance.now() - (this.urlWritten || -1e9);
    if (since >= 250) write();
    else this.urlTimer = setTimeout(write, 250 - since);
  }

  drawNumbers(a) {
    const set = (key, k, text) => {
      const c = this.cells[`${key}-${k}`];
      if (c) c.textContent = text;
    };
    a.sim.modes.slice(0, 2).forEach((m, k) => {
      const f = m.floquet;
      const c = m.contribution_percent;
      set('freq', k, fmt(m.freq_hz, 4));
      set('feff', k, fmt(f.effective_freq_hz, 6));
      set('favg', k, fmt(f.averaged_freq_hz, 6));
      set('beat2', k, f.beat_period_vs_2fd_s == null ? '— (none)' : fmt(f.beat_period_vs_2fd_s, 4));
      set('beat', k, f.beat_period_s == null ? '— (none)' : `${fmt(f.beat_period_s, 4)} (n = ${f.beat_harmonic})`);
      set('mult', k, f.multipliers.map(([re, im]) => `${fmt(re, 4)}${im >= 0 ? ' + ' : ' − '}${fmt(Math.abs(im), 4)}i`).join(', '));
      set('mod', k, fmt(f.max_modulus, 8));
      set('stable', k, f.stable ? `stable (growth ${fmt(f.growth_rate_per_s, 2)} 1/s)` : `UNSTABLE (growth ${fmt(f.growth_rate_per_s, 3)} 1/s)`);
      set('euler', k, fmt(c.euler, 4));
      set('centrifugal', k, fmt(c.centrifugal, 4));
      set('coriolis', k, fmt(c.coriolis, 4));
      set('sum', k, fmt(c.euler + c.centrifugal + c.coriolis, 4));
      let peak = 0;
      for (const v of m.q.total) peak = Math.max(peak, Math.abs(v));
      set('peak', k, fmt(peak, 4));
      const col = this.cells[`freq-${k}`].closest('table');
      col.dataset.selected = String(this.modeIndex() + 1);
    });
  }

  /** Decimation buckets for a time plot: one per CSS pixel of plot width (min and max each). */
  buckets(name) {
    const u = this.plots[name];
    const w = u && u.bbox ? u.bbox.width / devicePixelRatio : 0;
    return Math.min(LIVE_BUCKETS, Math.max(200, Math.round(w)));
  }

  drawTime(a, k) {
    const m = a.sim.modes[k];
    const d = decimate(a.sim.t, [m.q.euler, m.q.centrifugal, m.q.coriolis, m.q.total, a.envelope[k]], this.buckets('time'));
    this.plots.time.setData(d);
  }

  drawSpectrum(a, k) {
    const s = a.spectra[k];
    const fd = a.sim.flap_freq_hz;
    const f = a.sim.modes[k].floquet;
    const fk = a.sim.modes[k].freq_hz;
    const fmax = Math.min(SAMPLE_RATE_HZ / 2, Math.max(8 * fd, 1.6 * fk, 1.2 * f.effective_freq_hz));
    const freq = s.euler.freq_hz;
    let n = 0;
    while (n < freq.length && freq[n] <= fmax) n++;
    const pos = (arr) => {
      const out = new Array(n);
      for (let i = 0; i < n; i++) out[i] = log10OrNull(arr[i]); // log axis: zero power has no point
      return out;
    };
    this.plots.spectrum.setData([
      Array.from(freq.subarray(0, n)),
      pos(s.euler.psd),
      pos(s.centrifugal.psd),
      pos(s.coriolis.psd),
      pos(s.stiffness.psd),
      pos(s.total.psd),
    ]);
    const marks = [];
    for (let j = 1; j * fd <= fmax; j++) marks.push({ x: j * fd, label: `${j}f_d`, color: '#9a9a9a', row: 0 });
    marks.push({ x: fk, label: 'f_k', color: '#1f5fbf', dash: [5, 4], row: 1 });
    if (Number.isFinite(f.effective_freq_hz)) marks.push({ x: f.effective_freq_hz, label: 'f_eff', color: '#d62728', row: 2 });
    this.markers = marks;
  }

  /** Units of the strain series: SI (dimensionless) for the FE wing, the paper's otherwise. */
  strainUnit() {
    return this.state.modes === 'fe' ? 'strain (–)' : 'paper units';
  }

  drawStrain(a) {
    this.strainNote.textContent = this.state.modes === 'fe'
      ? 'Σ_k ε_k q_k(t) at P = (3, −6) mm from the FE modal strain fields (top surface, dimensionless, SI).'
      : 'Σ_k ε_k q_k(t) with the Table 6 modal strains at P (both modes). Paper units: Table 4/6 data are not SI.';
    const s = a.sim.strain;
    if (!s) {
      this.plots.strain.setData([[0], [null], [null], [null]]);
      return;
    }
    this.plots.strain.setData(decimate(a.sim.t, [s.eps_x, s.eps_y, s.gamma_xy], this.buckets('strain')));
  }

  // ---------- studies (worker) ----------

  ensureWorker() {
    if (!this.worker) {
      this.worker = new Worker(new URL('worker.js', HERE), { type: 'module' });
      this.worker.onmessage = (ev) => {
        const { id, progress, result, error, ms } = ev.data;
        const job = this.jobs.get(id);
        if (!job) return;
        if (progress) job.progress(progress);
        else {
          this.jobs.delete(id);
          if (error != null) job.reject(error);
          else job.resolve([result, ms]);
        }
      };
      this.worker.onerror = (ev) => {
        for (const job of this.jobs.values()) job.reject(ev.message || 'worker failed');
        this.jobs.clear();
        this.worker = null;
      };
    }
    return this.worker;
  }

  runJob(kind, payload, btn, prog, status, done) {
    const id = ++this.jobId;
    btn.disabled = true;
    prog.hidden = false;
    prog.removeAttribute('value');
    status.textContent = 'computing…';
    const finish = () => {
      btn.disabled = false;
      prog.hidden = true;
    };
    new Promise((resolve, reject) => {
      this.jobs.set(id, {
        resolve,
        reject,
        progress: ([i, n]) => {
          prog.max = n;
          prog.value = i;
          status.textContent = `${i} / ${n}`;
        },
      });
      this.ensureWorker().postMessage({ id, kind, ...payload });
    })
      .then(([r, ms]) => {
        finish();
        done(r, ms);
        this.dispatchEvent(new CustomEvent('wl-study', { detail: { kind } }));
      })
      .catch((e) => {
        finish();
        status.textContent = `Error: ${e}`;
      });
  }

  drawSweep(out, r, opts) {
    const k = this.modeIndex();
    const p = NUMERIC.find((q) => q.key === opts.param);
    const unit = p && p.unit ? p.unit : '–';
    out.replaceChildren();
    const box = el('div', { class: 'wl-plot' });
    out.append(box);
    const u = linePlot(box, {
      xLabel: p ? p.sym : opts.param,
      xUnit: unit,
      yScales: { y: { label: 'share', unit: '%' } },
      series: [
        { label: 'Euler', unit: '%', color: color('euler') },
        { label: 'Centrifugal', unit: '%', color: color('centrifugal') },
        { label: 'Coriolis', unit: '%', color: color('coriolis') },
      ],
      height: 220,
    });
    this.observers.push(autoWidth(u, box));
    const m = r.modes[k];
    u.setData([Array.from(r.values), Array.from(m.euler), Array.from(m.centrifugal), Array.from(m.coriolis)]);
    this.studies.sweep.data = { r, k, param: opts.param, unit, plot: u };
  }

  drawIcMap(out, r) {
    out.replaceChildren();
    const canvas = el('canvas', { class: 'wl-heatmap', width: 560, height: 360, role: 'img', 'aria-label': 'Heat map of the Coriolis share (%) over initial conditions q0 and q̇0' });
    out.append(canvas);
    drawHeatmap(canvas, {
      nx: r.n_q,
      ny: r.n_qdot,
      x: r.q0,
      y: r.qdot0,
      z: r.coriolis_percent,
      zmin: r.min_percent,
      zmax: r.max_percent,
      xLabel: `q0 (${Q_UNIT})`,
      yLabel: `q̇0 (${Q_UNIT}/s)`,
      zLabel: 'Coriolis share (%)',
    });
    this.studies.icmap.data = { r, canvas };
  }

  drawDamping(out, r) {
    out.replaceChildren();
    const box = el('div', { class: 'wl-plot' });
    out.append(box);
    const u = linePlot(box, {
      xLabel: 't',
      xUnit: 's',
      yScales: { y: { label: 'q total', unit: Q_UNIT } },
      series: [
        { label: 'ζ = 0', unit: Q_UNIT, color: '#999' },
        { label: `ζ = ${r.zeta}`, unit: Q_UNIT, color: color('envelope') },
      ],
      height: 220,
    });
    this.observers.push(autoWidth(u, box));
    u.setData([Array.from(r.t), Array.from(r.undamped), Array.from(r.damped)]);
    this.studies.damping.data = { r, plot: u };
  }

  // ---------- export ----------

  csvFor(name) {
    const a = this.analysis;
    const k = this.modeIndex();
    const case_ = `wingbeat lab; ${toQuery(this.state)}`;
    if (name === 'time' && a) {
      const m = a.sim.modes[k];
      return toCSV(
        [
          { name: 't', unit: 's', values: a.sim.t },
          { name: 'euler_response', unit: Q_UNIT, values: m.q.euler },
          { name: 'centrifugal_response', unit: Q_UNIT, values: m.q.centrifugal },
          { name: 'coriolis_response', unit: Q_UNIT, values: m.q.coriolis },
          { name: 'total_response', unit: Q_UNIT, values: m.q.total },
          { name: 'coriolis_envelope', unit: Q_UNIT, values: a.envelope[k] },
        ],
        [case_, `mode ${k + 1}: ${m.name}; full resolution (the plot is min/max-decimated)`],
      );
    }
    if (name === 'spectrum' && a) {
      const s = a.spectra[k];
      const pu = `(${F_UNIT})^2/Hz`;
      return toCSV(
        [
          { name: 'f', unit: 'Hz', values: s.euler.freq_hz },
          { name: 'psd_euler_force', unit: pu, values: s.euler.psd },
          { name: 'psd_centrifugal_force', unit: pu, values: s.centrifugal.psd },
          { name: 'psd_coriolis_force', unit: pu, values: s.coriolis.psd },
          { name: 'psd_stiffness_term', unit: pu, values: s.stiffness.psd },
          { name: 'psd_total_response', unit: `(${Q_UNIT})^2/Hz`, values: s.total.psd },
        ],
        [case_, `mode ${k + 1}; Welch, Hann, 8192-sample segments, detrend ${this.state.detrend}; all bins up to Nyquist`],
      );
    }
    if (name === 'strain' && a && a.sim.strain) {
      const s = a.sim.strain;
      return toCSV(
        [
          { name: 't', unit: 's', values: a.sim.t },
          { name: 'eps_x', unit: this.strainUnit(), values: s.eps_x },
          { name: 'eps_y', unit: this.strainUnit(), values: s.eps_y },
          { name: 'gamma_xy', unit: this.strainUnit(), values: s.gamma_xy },
        ],
        [case_, `strain at point ${s.point}`],
      );
    }
    if (name === 'numbers' && a) {
      const rows = this.rows.map(([key, label]) => [label, this.cells[`${key}-0`].textContent, this.cells[`${key}-1`].textContent]);
      return ['# ' + case_, 'quantity,mode 1,mode 2', ...rows.map((r) => r.map((c) => `"${c.replace(/"/g, '""')}"`).join(','))].join('\n') + '\n';
    }
    const st = this.studies[name] && this.studies[name].data;
    if (name === 'sweep' && st) {
      const m = st.r.modes[st.k];
      return toCSV(
        [
          { name: st.param, unit: st.unit, values: st.r.values },
          { name: 'euler_share', unit: '%', values: m.euler },
          { name: 'centrifugal_share', unit: '%', values: m.centrifugal },
          { name: 'coriolis_share', unit: '%', values: m.coriolis },
          { name: 'effective_freq', unit: 'Hz', values: m.effective_freq_hz },
          { name: 'beat_period', unit: 's', values: m.beat_period_s },
        ],
        [case_, `mode ${st.k + 1}`],
      );
    }
    if (name === 'icmap' && st) {
      const r = st.r;
      const q0 = [], qd = [], z = [];
      for (let j = 0; j < r.n_qdot; j++) for (let i = 0; i < r.n_q; i++) { q0.push(r.q0[i]); qd.push(r.qdot0[j]); z.push(r.coriolis_percent[j * r.n_q + i]); }
      return toCSV(
        [
          { name: 'q0', unit: Q_UNIT, values: q0 },
          { name: 'qdot0', unit: `${Q_UNIT}/s`, values: qd },
          { name: 'coriolis_share', unit: '%', values: z },
        ],
        [case_, `mode ${r.mode + 1}; attribution ${r.attribution}`],
      );
    }
    if (name === 'damping' && st) {
      return toCSV(
        [
          { name: 't', unit: 's', values: st.r.t },
          { name: 'q_total_zeta0', unit: Q_UNIT, values: st.r.undamped },
          { name: `q_total_zeta${st.r.zeta}`, unit: Q_UNIT, values: st.r.damped },
        ],
        [case_, `mode ${st.r.mode + 1}; min/max-decimated to the plotted points`],
      );
    }
    return null;
  }

  exportCSV(name) {
    const text = this.csvFor(name);
    if (!text) {
      this.notice(`Nothing to export yet for “${name}”: run it first.`);
      return;
    }
    download(`wingbeat-${name}.csv`, new Blob([text], { type: 'text/csv' }));
  }

  async exportPNG(name) {
    let canvases = [];
    let lines = [];
    const title = PANEL_TITLES[name] || (this.studies[name] && this.studies[name].box.querySelector('h3').textContent) || name;
    if (this.plots[name]) canvases = [this.plots[name].ctx.canvas];
    else if (name === 'numbers') lines = this.rows.map(([key, label]) => `${label}: mode 1 ${this.cells[`${key}-0`].textContent}; mode 2 ${this.cells[`${key}-1`].textContent}`);
    else if (name === 'icmap' && this.studies.icmap.data) canvases = [this.studies.icmap.data.canvas];
    else if (this.studies[name] && this.studies[name].data && this.studies[name].data.plot) canvases = [this.studies[name].data.plot.ctx.canvas];
    if (!canvases.length && !lines.length) {
      this.notice(`Nothing to export yet for “${name}”: run it first.`);
      return;
    }
    const blob = await panelPNG(title, canvases, lines);
    download(`wingbeat-${name}.png`, blob);
  }
}

if (!customElements.get('wing-lab')) customElements.define('wing-lab', WingLab);
