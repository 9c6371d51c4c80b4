// @ts-check
// The Kinematics panel's hand editor (views/kinematics.js): the mean and the harmonics of each
// angle (a measured table keeps its samples: its mean offset and added harmonics only) and the
// flap frequency, loaded from the kinematics in use; "Use edited kinematics" checks them with the
// core and puts them in the store (`kin`), "Use the sliders" goes back to the sliders' stroke.
// The kinematics it makes are www/kinform.js's editedKinematics.
import { el } from '../dom.js';
import { errorText } from '../format.js';
import { ANGLES, SYM, fourierOf, nextHarmonicOrder, editedKinematics, editedLabel } from '../kinform.js';

/**
 * The editor's `<details>` box and `load()`, which fills it from the kinematics in use.
 * @param {import('../lab.js').ViewContext} ctx
 * @param {{ say: (text: string, bad?: boolean) => void, onReset: () => void }} hooks the panel's
 *   status line, and what else to forget when going back to the sliders
 */
export function kinematicsEditor(ctx, hooks) {
  const { store, engine, id } = ctx;
  const { say } = hooks;
  const editor = el('div', { class: 'wl-kin-editor', 'data-kin': 'editor' });
  /** @type {Record<string, import('../kinform.js').EditAngle>} */
  let edit = {};
  let editFlap = 25;
  /** Sampled angles in use are kept; the editor changes only their mean offset. */
  /** @type {Record<string, any>} */
  let sampled = {};
  const num = (idS, label, value, onchange, step = 0.01) => {
    const inp = el('input', { type: 'number', id: id(idS), step, value: String(value), 'aria-label': label });
    inp.addEventListener('change', () => {
      const v = Number(inp.value);
      if (inp.value.trim() === '' || !Number.isFinite(v)) {
        inp.setAttribute('aria-invalid', 'true');
        return;
      }
      inp.removeAttribute('aria-invalid');
      onchange(v);
    });
    return inp;
  };
  const load = () => {
    const s = store.get();
    let k;
    try {
      k = s.kin ? s.kin.kinematics : engine.ready ? engine.config(s).kinematics : null;
    } catch {
      k = null;
    }
    if (!k) return;
    editFlap = k.flap_freq_hz;
    edit = {};
    sampled = {};
    for (const a of ANGLES) {
      const ang = /** @type {any} */ (k[a]);
      if (ang && ang.kind === 'sampled') sampled[a] = { ...ang, values: ang.values.slice() };
      edit[a] = fourierOf(ang);
    }
    drawEditor();
  };
  /** The table of angle a's harmonics (order, amplitude, phase, a remove button per row). */
  const harmonicsTable = (a, e) => {
    const tbl = el(
      'table',
      { class: 'wl-kin-harm' },
      el('caption', { class: 'wl-sr', text: `Harmonics of ${SYM[a]}: amplitude · sin(n ω_d t + phase)` }),
      el(
        'thead',
        {},
        el(
          'tr',
          {},
          el('th', { scope: 'col', text: 'n' }),
          el('th', { scope: 'col', text: 'amplitude (rad)' }),
          el('th', { scope: 'col', text: 'phase (rad)' }),
          el('th', { scope: 'col', text: 'remove' }),
        ),
      ),
    );
    const body = el('tbody');
    e.harmonics.forEach((h, i) => {
      const rm = el('button', {
        type: 'button',
        text: 'Remove',
        'aria-label': `Remove harmonic ${i + 1} of ${SYM[a]}`,
      });
      rm.addEventListener('click', () => {
        e.harmonics.splice(i, 1);
        drawEditor();
      });
      const td = (child) => el('td', {}, child);
      body.append(
        el(
          'tr',
          {},
          td(
            num(
              `kin-${a}-n${i}`,
              `${SYM[a]} harmonic ${i + 1}: order n`,
              h.n,
              (v) => {
                h.n = Math.max(1, Math.round(v));
              },
              1,
            ),
          ),
          td(
            num(`kin-${a}-A${i}`, `${SYM[a]} harmonic ${i + 1}: amplitude, rad`, h.amplitude, (v) => {
              h.amplitude = v;
            }),
          ),
          td(
            num(`kin-${a}-p${i}`, `${SYM[a]} harmonic ${i + 1}: phase, rad`, h.phase, (v) => {
              h.phase = v;
            }),
          ),
          td(rm),
        ),
      );
    });
    tbl.append(body);
    return tbl;
  };
  const drawEditor = () => {
    editor.replaceChildren();
    for (const a of ANGLES) {
      const box = el('fieldset', { class: 'wl-kin-angle' }, el('legend', { text: `${SYM[a]}, rad` }));
      const e = edit[a];
      const setMean = (v) => {
        e.mean = v;
      };
      if (sampled[a]) {
        box.append(
          el('p', {
            class: 'wl-note',
            text: `Measured table (${sampled[a].values.length} samples per period): the mean offset and the harmonics below are added to it.`,
          }),
          el('label', { for: id(`kin-${a}-mean`), text: 'Mean offset (rad) ' }),
          num(`kin-${a}-mean`, `${SYM[a]} mean offset, rad`, e.mean, setMean),
        );
      } else {
        box.append(
          el('label', { for: id(`kin-${a}-mean`), text: 'Mean (rad) ' }),
          num(`kin-${a}-mean`, `${SYM[a]} mean, rad`, e.mean, setMean),
        );
      }
      const add = el('button', { type: 'button', text: 'Add harmonic', 'aria-label': `Add harmonic to ${SYM[a]}` });
      add.addEventListener('click', () => {
        e.harmonics.push({ n: nextHarmonicOrder(e.harmonics), amplitude: 0, phase: 0 });
        drawEditor();
      });
      if (e.harmonics.length) box.append(harmonicsTable(a, e));
      box.append(add);
      editor.append(box);
    }
    const flapRow = el(
      'div',
      { class: 'wl-kin-row' },
      el('label', { for: id('kin-edit-flap'), text: 'Flap frequency (Hz) ' }),
      num(
        'kin-edit-flap',
        'Flap frequency of the edited kinematics, Hz',
        editFlap,
        (v) => {
          editFlap = v;
        },
        0.1,
      ),
    );
    editor.append(flapRow);
  };
  const applyBtn = el('button', {
    type: 'button',
    class: 'wl-primary',
    text: 'Use edited kinematics',
    'data-kin': 'apply',
  });
  applyBtn.addEventListener('click', () => {
    const k = editedKinematics(edit, sampled, editFlap);
    // Checked by the core right away (the message names the field), before it reaches the store.
    try {
      engine.anglesAt({ ...engine.baseConfig, kinematics: k }, new Float64Array([0]));
    } catch (e) {
      say(`The edited kinematics are not valid: ${errorText(e)}`, true);
      return;
    }
    const prev = store.get().kin;
    store.set({
      kin: {
        kinematics: k,
        source: 'edited',
        label: editedLabel(prev),
        samples: prev && prev.samples ? prev.samples : null,
        csv: null,
      },
    });
    say('Using the edited kinematics.');
    ctx.emit('wl-kin', { state: 'edited' });
  });
  const resetBtn = el('button', { type: 'button', text: 'Use the sliders', 'data-kin': 'reset' });
  resetBtn.addEventListener('click', () => {
    store.set({ kin: null });
    hooks.onReset();
    say('Back to the sliders’ kinematics (α0, β0, γ0, phases, f_d).');
  });
  const reloadBtn = el('button', { type: 'button', text: 'Edit the kinematics in use', 'data-kin': 'load-editor' });
  reloadBtn.addEventListener('click', load);
  const box = el(
    'details',
    { class: 'wl-kin-edit' },
    el('summary', { text: 'Edit means and harmonics by hand' }),
    el('div', { class: 'wl-kin-actions' }, reloadBtn),
    editor,
    el('div', { class: 'wl-kin-actions' }, applyBtn, resetBtn),
  );
  return { box, load };
}
