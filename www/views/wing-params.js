// @ts-check
// The Wing panel's parameters (views/wing.js): the material preset menu and one number input per
// wing parameter (state.js WING; shown in its display unit, E in GPa), each checked against the
// core's range as it is typed in. Edits the panel's draft (`form`); never the store.
import { WING } from '../state.js';
import { el, activeIn } from '../dom.js';
import { fmt } from '../format.js';
import { MATERIAL_KEYS, SHOW, LABEL, clean, readWingValue, matchingPreset } from '../wingform.js';

/**
 * @param {import('../lab.js').ViewContext} ctx
 * @param {import('./wing-outline.js').WingForm} form
 * @param {{ say: (text: string, bad?: boolean) => void, autoMesh: () => number }} on
 */
export function wingParams(ctx, form, on) {
  const { store, engine, id } = ctx;
  // The core's material presets; none until the wasm has loaded (views/wing.js refills the menu then).
  const presets = () => (engine.ready ? engine.materialPresets() : []);
  const presetSel = el('select', { id: id('wing-preset'), 'data-wing': 'preset' });
  const fillPresets = () => {
    presetSel.replaceChildren(el('option', { value: '', text: 'Custom (as set below)' }));
    for (const p of presets()) presetSel.append(el('option', { value: p.id, text: p.label }));
    matchPreset();
  };
  const matchPreset = () => {
    const m = matchingPreset(presets(), form.draft.params);
    presetSel.value = m ? m.id : '';
  };
  presetSel.addEventListener('change', () => {
    const p = presets().find((q) => q.id === presetSel.value);
    if (!p) return;
    for (const k of MATERIAL_KEYS) form.draft.params[k] = p[k];
    form.dirty = true;
    sync();
  });
  /** @type {Record<string, HTMLInputElement>} */
  const inputs = {};
  const autoEl = el('span', { class: 'wl-unit wl-auto', 'data-wing': 'auto-mesh' });
  /** The automatic element size: of the draft's outline when checked, else the one in use. */
  const showAuto = () => {
    const fe = store.get().fe;
    const am = on.autoMesh();
    const a = Number.isFinite(am) ? am : null;
    autoEl.textContent =
      a != null
        ? `: ${fmt(a, 3)} mm`
        : fe && store.get().modes === 'fe' && form.draft.params.mesh_mm === 0
          ? `: ${fmt(fe.mesh_size_mm, 3)} mm in use`
          : '';
  };
  const rows = WING.map((w) => {
    const sh = SHOW[w.key];
    const inp = el('input', {
      type: 'number',
      id: id(`wing-${w.key}`),
      'data-wing': w.key,
      min: clean(w.min * sh.scale),
      max: clean(w.max * sh.scale),
      step: sh.step,
    });
    inputs[w.key] = inp;
    inp.addEventListener('change', () => {
      const r = readWingValue(w, inp.value);
      if ('error' in r) {
        inp.setAttribute('aria-invalid', 'true');
        on.say(r.error, true);
        return;
      }
      inp.removeAttribute('aria-invalid');
      form.draft.params[w.key] = r.value;
      form.dirty = true;
      matchPreset();
      showAuto();
    });
    return el(
      'div',
      { class: 'wl-wing-field' },
      el(
        'label',
        { for: id(`wing-${w.key}`) },
        LABEL[w.key],
        sh.unit ? el('span', { class: 'wl-unit' }, ` (${sh.unit}`, w.key === 'mesh_mm' ? autoEl : '', ')') : null,
      ),
      inp,
    );
  });
  /** The draft's parameters into the inputs (not the one being typed in). */
  const sync = () => {
    for (const w of WING) {
      const inp = inputs[w.key];
      if (activeIn(inp) !== inp) inp.value = String(clean(form.draft.params[w.key] * SHOW[w.key].scale));
      inp.removeAttribute('aria-invalid');
    }
    matchPreset();
    showAuto();
  };
  const box = el(
    'div',
    { class: 'wl-wing-params' },
    el('div', { class: 'wl-wing-field' }, el('label', { for: id('wing-preset'), text: 'Material preset' }), presetSel),
    ...rows,
  );
  return { box, sync, showAuto, fillPresets };
}
