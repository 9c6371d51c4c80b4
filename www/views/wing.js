// @ts-check
// Wing panel: your own wing. Pick a built-in outline or load one from a file (the CLI's CSV
// `x_mm,y_mm` or JSON `[[x, y], …]`), edit it (drag points, add / remove, exact x and y by
// keyboard; checked live by the core's checkPlanform), set camber, clamp, material (with the
// paper's presets), element size (0 = automatic) and the number of modes (1–8), then "Compute
// modes": the solve runs in the worker with progress and Cancel while the wing in use stays.
// The same file input reads a `wingbeat modes` JSON document (import); "Export modes JSON"
// writes the wing in use in that format (for `wingbeat simulate --modes`).
// Reads and writes the store; calls ctx.engine for the wasm helpers (never wasm itself).
// This file holds the draft, the outline's source and the wing in use; its pieces: the outline
// editor (wing-outline.js), the parameters (wing-params.js), the actions (wing-actions.js:
// compute, cancel, import, export, reset), the pure form rules (www/wingform.js) and modes
// documents (www/modesdoc.js).
import { WING, customWing } from '../state.js';
import { el } from '../dom.js';
import { fmt, errorText } from '../format.js';
import { looksLikeModes } from '../modesdoc.js';
import { outlineEditor } from './wing-outline.js';
import { wingParams } from './wing-params.js';
import { wingActions } from './wing-actions.js';

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
      if (looksLikeModes(text)) await actions.importModes(text, f.name);
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

  // ---------- compute, cancel, import, export, reset ----------
  const actions = wingActions(ctx, form, {
    say,
    reset: () => {
      fromStore();
      fillOutlines();
      params.sync();
      drawOutline();
    },
  });

  const inUse = el('div', { class: 'wl-wing-inuse', 'data-wing': 'in-use' });
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
    actions.row,
    statusEl,
    inUse,
  );

  const unsub = [
    store.subscribe([...WING.map((w) => w.key), 'outline', 'planform', 'wing'], () => {
      if (form.dirty || actions.busy) return;
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
    compute: actions.compute,
    get draft() {
      return draft;
    },
    destroy() {
      clearInterval(whenReady);
      actions.destroy();
      for (const f of unsub) f();
    },
  };
}
