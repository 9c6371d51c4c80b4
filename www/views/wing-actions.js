// @ts-check
// The Wing panel's actions (views/wing.js): "Compute modes" (the draft checked by the core, then
// solved in the worker with progress and Cancel while the wing in use stays), the draft made
// the wing in use, a `wingbeat modes` JSON document imported as the wing in use or the wing in
// use exported as one, and "Default wing" (the panel's own reset, passed in). Writes the store;
// reads the draft (`form`), which it never edits.
import { WING } from '../state.js';
import { el } from '../dom.js';
import { fmt, errorText } from '../format.js';
import { download } from '../export.js';
import { modesDocument, feFromModesDocument, CHOSEN_POINT } from '../modesdoc.js';
import { wingPatch } from '../wingform.js';

/**
 * @param {import('../lab.js').ViewContext} ctx
 * @param {import('./wing-outline.js').WingForm} form
 * @param {{ say: (text: string, bad?: boolean) => void, reset: () => void }} on
 */
export function wingActions(ctx, form, on) {
  const { store, engine } = ctx;
  const { say } = on;
  const draft = form.draft;
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
    form.dirty = false;
    store.set(wingPatch(draft, p, own, input));
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
    on.reset();
  });

  /**
   * A `wingbeat modes` document → the wing in use (mesh and modes as computed by the CLI). The
   * full wasm module reads it (loaded behind the live one; at once when it is there).
   */
  const importModes = async (/** @type {string} */ text, /** @type {string} */ name) => {
    await engine.loadFull();
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

  return {
    row: el('div', { class: 'wl-wing-actions' }, computeBtn, cancelBtn, progress, exportBtn, resetBtn),
    compute,
    importModes,
    /** Whether a compute job is running (the store's wing changes wait for it). */
    get busy() {
      return !!job;
    },
    destroy() {
      if (job) clearInterval(job.timer);
    },
  };
}
