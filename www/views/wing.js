// @ts-check
// Wing panel: your own wing. Pick a built-in outline or load one from a file (the CLI's CSV
// `x_mm,y_mm` or JSON `[[x, y], …]`), edit it (drag points, add / remove, exact x and y by
// keyboard; checked live by the core's checkPlanform), set camber, clamp, material (with the
// paper's presets), element size (0 = automatic) and the number of modes (1–8), then "Compute
// modes": the solve runs in the worker with progress and Cancel while the wing in use stays.
// The same file input reads a `wingbeat modes` JSON document (import); "Export modes JSON"
// writes the wing in use in that format (for `wingbeat simulate --modes`).
// Reads and writes the store; calls ctx.engine for the wasm helpers (never wasm itself).
// This file holds the draft, the outline's source, the actions and the wing in use; its pieces:
// the outline editor (wing-outline.js), the parameters (wing-params.js), the pure form rules
// (www/wingform.js) and modes documents (www/modesdoc.js).
import { WING, customWing } from '../state.js';
import { el } from '../dom.js';
import { fmt, errorText } from '../format.js';
import { download } from '../export.js';
import { looksLikeModes, modesDocument, feFromModesDocument, CHOSEN_POINT } from '../modesdoc.js';
import { outlineEditor } from './wing-outline.js';
import { wingParams } from './wing-params.js';

export const title = 'Wing';

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, engine, section, id } = ctx;

  // ---------- the draft: what the form shows, applied by "Compute modes" ----------
  /** @type {import('./wing-outline.js').WingForm} */
  const form = {
    draft: { params: {}, points: null, outline: 'manduca', source: 'builtin', label: '', planform: '' },
    selected: 0,
    dirty: false,
  };
  const draft = form.draft;

  const builtins = () => {
    const list = engine.ready ? engine.planforms() : [];
    return list.length
      ? list
      : [{ id: 'manduca', label: 'Manduca-like (synthetic, default)', note: '', points_mm: null }];
  };

  const fromStore = () => {
    const s = store.get();
    for (const w of WING) draft.params[w.key] = s[w.key];
    draft.outline = s.outline || 'manduca';
    draft.planform = s.planform || '';
    if (s.wing && s.wing.points) {
      draft.points = s.wing.points.map((p) => [p[0], p[1]]);
      draft.source = s.wing.source;
      draft.label = s.wing.label;
    } else {
      const b = builtins().find((p) => p.id === draft.outline);
      draft.points = b && b.points_mm ? b.points_mm.map((p) => [p[0], p[1]]) : null;
      draft.source = 'builtin';
      draft.label = b ? b.label : draft.outline;
    }
    form.selected = Math.min(form.selected, draft.points ? draft.points.length - 1 : 0);
    form.dirty = false;
  };

  const statusEl = el('p', { class: 'wl-note', role: 'status', 'data-wing': 'status' });
  const say = (text, bad = false) => {
    statusEl.textContent = text;
    statusEl.classList.toggle('wl-bad', bad);
    statusEl.setAttribute('role', bad ? 'alert' : 'status');
  };
  const outlineSel = el('select', { id: id('wing-outline'), 'data-wing': 'outline' });
  const editor = outlineEditor(ctx, form, {
    say,
    onOwn: () => {
      outlineSel.value = 'own';
    },
    onChecked: () => params.showAuto(),
  });
  const params = wingParams(ctx, form, { say, autoMesh: editor.autoMesh });
  const drawOutline = editor.draw;

  // ---------- outline source ----------
  const fillOutlines = () => {
    const cur = outlineSel.value;
    outlineSel.replaceChildren();
    for (const b of builtins()) outlineSel.append(el('option', { value: b.id, text: b.label }));
    outlineSel.append(el('option', { value: 'own', text: 'Own outline (file, link or edited)', disabled: true }));
    outlineSel.value = cur || draft.outline;
  };
  outlineSel.addEventListener('change', () => {
    const b = builtins().find((p) => p.id === outlineSel.value);
    if (!b) return;
    draft.outline = b.id;
    draft.points = b.points_mm ? b.points_mm.map((p) => [p[0], p[1]]) : null;
    draft.source = 'builtin';
    draft.label = b.label;
    draft.planform = '';
    form.selected = 0;
    form.dirty = true;
    drawOutline();
  });
  const fileIn = el('input', {
    type: 'file',
    id: id('wing-file'),
    accept: '.csv,.json,.txt,text/csv,application/json',
    'data-wing': 'file',
  });
  fileIn.addEventListener('change', async () => {
    const f = fileIn.files && fileIn.files[0];
    if (!f) return;
    try {
      if (f.size > 20e6) throw new Error(`${f.name} is larger than 20 MB`);
      const text = await f.text();
      if (looksLikeModes(text)) importModes(text, f.name);
      else {
        const format = /\.json$/i.test(f.name) || text.trimStart().startsWith('[') ? 'json' : 'csv';
        const pts = engine.parsePlanform(text, format);
        draft.points = pts.map((p) => [p[0], p[1]]);
        draft.source = 'file';
        draft.label = f.name.slice(0, 80);
        draft.planform = '';
        form.selected = 0;
        form.dirty = true;
        outlineSel.value = 'own';
        drawOutline();
        say(`Outline read from ${draft.label}: ${pts.length} points. Set the parameters and press “Compute modes”.`);
      }
    } catch (e) {
      say(`Could not read ${f.name}: ${errorText(e)}`, true);
    }
    fileIn.value = '';
  });

  // ---------- compute, cancel, export ----------
  const computeBtn = el('button', {
    type: 'button',
    class: 'wl-primary',
    text: 'Compute modes',
    'data-wing': 'compute',
  });
  const cancelBtn = el('button', { type: 'button', text: 'Cancel', 'data-wing': 'cancel', hidden: true });
  const progress = el('progress', { 'aria-label': 'Computing the wing’s modes', hidden: true });
  const exportBtn = el('button', {
    type: 'button',
    text: 'Export modes JSON',
    'data-wing': 'export',
    title: 'The wing in use as a `wingbeat modes` document (for wingbeat simulate --modes)',
  });
  const resetBtn = el('button', { type: 'button', text: 'Default wing', 'data-wing': 'reset' });
  const inUse = el('div', { class: 'wl-wing-inuse', 'data-wing': 'in-use' });
  /** @type {{ id: number, t0: number, timer: ReturnType<typeof setInterval> } | null} */
  let job = null;
  const busy = (on) => {
    progress.hidden = !on;
    cancelBtn.hidden = !on;
    computeBtn.disabled = on;
  };
  const compute = () => {
    if (job) return;
    /** @type {any} */
    const p = { ...store.get(), ...draft.params, outline: draft.outline, planform: draft.planform };
    const own = draft.source !== 'builtin' && draft.points;
    let input;
    try {
      input = engine.wingInput(p, own ? draft.points : draft.outline !== 'manduca' ? draft.points : null);
    } catch (e) {
      say(`The wing is not valid: ${errorText(e)}`, true);
      return;
    }
    const t0 = performance.now();
    const j = engine.computeWing(input, () => {});
    if (!j.id) return apply(p, own, input);
    busy(true);
    const timer = setInterval(
      () =>
        say(
          `Computing ${p.n_modes} modes in the worker… ${((performance.now() - t0) / 1000).toFixed(1)} s (the wing in use stays until this one is ready)`,
        ),
      250,
    );
    job = { id: j.id, t0, timer };
    say(`Computing ${p.n_modes} modes in the worker…`);
    ctx.emit('wl-wing', { state: 'started' });
    j.promise.then(
      (r) => {
        clearInterval(timer);
        job = null;
        busy(false);
        apply(p, own, input);
        say(
          `Computed in ${((performance.now() - t0) / 1000).toFixed(1)} s: ${r.n_nodes} nodes, element size ${fmt(r.mesh_size_mm, 3)} mm.`,
        );
        ctx.emit('wl-wing', { state: 'done' });
      },
      (e) => {
        clearInterval(timer);
        job = null;
        busy(false);
        const msg = errorText(e);
        if (msg === 'cancelled') say('Cancelled. The wing in use is unchanged.');
        else say(`The wing could not be computed: ${msg}. The wing in use is unchanged.`, true);
        ctx.emit('wl-wing', { state: msg === 'cancelled' ? 'cancelled' : 'failed', error: msg });
      },
    );
  };
  /** Makes the draft the wing in use (the store follows; the engine has the result cached). */
  const apply = (p, own, input) => {
    /** @type {Record<string, any>} */
    const patch = { modes: 'fe', outline: draft.outline, planform: draft.source === 'url' ? draft.planform : '' };
    for (const w of WING) patch[w.key] = p[w.key];
    patch.wing = own
      ? {
          input,
          source: draft.source,
          label: draft.label,
          outline: 'own',
          points: draft.points && draft.points.map((q) => [q[0], q[1]]),
        }
      : null;
    if (own) patch.outline = draft.outline;
    form.dirty = false;
    store.set(patch);
  };
  computeBtn.addEventListener('click', compute);
  cancelBtn.addEventListener('click', () => {
    if (job) engine.cancel(job.id);
  });
  exportBtn.addEventListener('click', () => {
    const s = store.get();
    const fe = s.fe;
    if (!fe || s.modes !== 'fe')
      return say('No FE wing in use yet: choose the FE wing mode set or compute a wing first.', true);
    const raw = /** @type {any} */ (fe).modes_json;
    if (typeof raw !== 'string')
      return say('This wasm build does not produce the modes document: rebuild www/pkg.', true);
    // A chosen strain point goes with the modes, first (the one simulate --modes reports).
    let json;
    try {
      json = modesDocument(raw, s.strain_point ? engine.modalStrainAt(s.strain_point) : null);
    } catch (e) {
      return say(`Could not export the modes: ${errorText(e)}`, true);
    }
    download('wingbeat-modes.json', new Blob([json], { type: 'application/json' }));
    const sp = s.strain_point;
    say(
      `Exported ${fe.modes.length} modes as wingbeat-modes.json${sp ? `, with the chosen strain point ${CHOSEN_POINT} = (${fmt(sp[0], 4)}, ${fmt(sp[1], 4)}) mm first` : ''} (use it with: wingbeat simulate --modes wingbeat-modes.json).`,
    );
    ctx.emit('wl-wing', { state: 'exported' });
  });
  resetBtn.addEventListener('click', () => {
    /** @type {Record<string, any>} */
    const patch = { wing: null, outline: 'manduca', planform: '' };
    for (const w of WING) patch[w.key] = w.def;
    store.set(patch);
    fromStore();
    fillOutlines();
    params.sync();
    drawOutline();
  });

  /** A `wingbeat modes` document → the wing in use (mesh and modes as computed by the CLI). */
  const importModes = (text, name) => {
    const r = engine.modesFromJson(text);
    const fe = feFromModesDocument(r, text);
    engine.useFe(fe, `import:${name}:${text.length}`);
    store.set({
      modes: 'fe',
      wing: { input: null, source: 'import', label: name.slice(0, 80), outline: 'file', points: null },
      fe,
      mode: '1',
      strain_point: null,
    });
    say(`Imported ${r.modes.length} modes from ${name}.`);
    ctx.emit('wl-wing', { state: 'imported' });
  };

  const describeInUse = (s) => {
    inUse.replaceChildren();
    if (s.modes !== 'fe') {
      inUse.append(
        el('p', {
          class: 'wl-note',
          text: 'In use: the paper table’s two modes (paper units). Compute a wing (or choose the FE wing mode set under Parameters) to use FE modes.',
        }),
      );
      return;
    }
    const fe = s.fe;
    if (!fe) {
      inUse.append(el('p', { class: 'wl-note', text: 'The FE wing is being computed…' }));
      return;
    }
    const src = s.wing
      ? `${s.wing.label} (${s.wing.source === 'import' ? 'imported modes' : 'own outline'})`
      : customWing(s)
        ? `${(builtins().find((b) => b.id === s.outline) || { label: s.outline }).label}`
        : 'the default synthetic Manduca-like wing';
    inUse.append(
      el('p', {
        class: 'wl-note',
        text: `In use: ${src}; ${fe.modes.length} modes, ${fe.n_nodes} nodes, element size ${fmt(fe.mesh_size_mm, 3)} mm${s.strain_point ? `, chosen strain point (${fmt(s.strain_point[0], 4)}, ${fmt(s.strain_point[1], 4)}) mm` : ''}${fe.strain_point_mm ? `, ${s.strain_point ? 'the wing’s own ' : ''}strain point (${fmt(fe.strain_point_mm[0], 4)}, ${fmt(fe.strain_point_mm[1], 4)}) mm` : ''}.`,
      }),
    );
    const ol = el('ol', { class: 'wl-wing-freqs', 'aria-label': 'Natural frequencies of the wing in use' });
    fe.modes.forEach((m, k) => {
      ol.append(
        el('li', {
          'data-field': `wing-freq-${k}`,
          text: `${fmt(m.freq_hz, 4)} Hz${fe.kinds && fe.kinds[k] ? ` (${fe.kinds[k]})` : ''}`,
        }),
      );
    });
    inUse.append(ol);
  };

  // One column in reading order (tab order = visual order): source, drawing, point editing,
  // the parameters as a grid filled row by row, the actions, the wing in use.
  section.append(
    el(
      'div',
      { class: 'wl-wing-src' },
      el('div', { class: 'wl-wing-field' }, el('label', { for: id('wing-outline'), text: 'Outline' }), outlineSel),
      el(
        'div',
        { class: 'wl-wing-field' },
        el('label', { for: id('wing-file'), text: 'Load a file (outline or modes JSON)' }),
        fileIn,
      ),
    ),
    el('p', {
      class: 'wl-note',
      text: 'Outline files: CSV with a header x_mm,y_mm (or i,x_mm,y_mm; # comments) or JSON [[x, y], …], in mm, x spanwise from the root (root edge on x = 0), chord toward −y. A `wingbeat modes` JSON document imports its modes.',
    }),
    editor.svg,
    editor.svgDesc,
    editor.pointsRow,
    editor.checkEl,
    params.box,
    el('div', { class: 'wl-wing-actions' }, computeBtn, cancelBtn, progress, exportBtn, resetBtn),
    statusEl,
    inUse,
  );

  const unsub = [
    store.subscribe([...WING.map((w) => w.key), 'outline', 'planform', 'wing'], () => {
      if (form.dirty || job) return;
      fromStore();
      fillOutlines();
      if (draft.source !== 'builtin') outlineSel.value = 'own';
      params.sync();
      drawOutline();
    }),
    store.subscribe(['fe', 'modes', 'wing', 'outline', 'strain_point'], (s) => {
      describeInUse(s);
      params.showAuto();
    }),
    store.subscribe(['fe', 'strain_point', 'modes'], () => {
      if (!form.dirty) drawOutline();
    }),
  ];
  const init = () => {
    fromStore();
    fillOutlines();
    params.fillPresets();
    if (draft.source !== 'builtin') outlineSel.value = 'own';
    params.sync();
    drawOutline();
    describeInUse(store.get());
  };
  init();
  // The built-in outlines and presets come from the wasm: refresh once it has loaded.
  const whenReady = setInterval(() => {
    if (!engine.ready) return;
    clearInterval(whenReady);
    if (!form.dirty) init();
    else params.fillPresets();
  }, 100);
  return {
    compute,
    get draft() {
      return draft;
    },
    destroy() {
      clearInterval(whenReady);
      if (job) clearInterval(job.timer);
      for (const f of unsub) f();
    },
  };
}
