// @ts-check
// Parameters panel: the five main sliders first (α0, β0, γ0, f_d, ζ: a compact strip on a
// phone), then "More parameters" (phases, duration, mode set, selected mode, PSD detrend), the
// preset, warnings and the compute/draw timing. Reads and writes only the store.
import { NUMERIC, ENUMS, MAIN_KEYS, FE_LAB_INPUT, defaults, snap } from '../state.js';
import { el, activeIn } from '../dom.js';
import { mediumControl } from './medium.js';
import { fmt, plain, PAPER_UNITS_NOTE } from '../format.js';

export const title = 'Parameters';

const ENUM_TEXT = {
  modes: { paper: 'Paper table (Tables 3–4)', fe: 'FE wing (shell FE, computed here)' },
  mode: {
    1: 'Mode 1: spanwise bending',
    2: 'Mode 2: spanwise torsion',
    3: 'Mode 3',
    4: 'Mode 4',
    5: 'Mode 5',
    6: 'Mode 6',
    7: 'Mode 7',
    8: 'Mode 8',
  },
  detrend: { none: 'none (DC visible)', mean: 'mean', linear: 'linear' },
};

const valueText = (p, v) => (p.unit ? `${v} ${p.unit}` : String(v));

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, section, id } = ctx;
  const preset = el('button', {
    type: 'button',
    class: 'wl-preset',
    text: 'Paper forward flight',
    title: 'α0 = 0.8, β0 = 0.5, γ0 = 0.2 rad, f_d = 25 Hz, ζ = 0, phases 0, 2 s (paper Table 5)',
    onclick: () => {
      const { panels: _kept, ...d } = defaults(); // every parameter but the panel choice
      store.set(d);
    },
  });
  const inputs = {};
  const row = (p) => {
    const label = `${plain(p.label)}${p.unit ? ', in ' + p.unit : ''}`;
    const range = el('input', {
      type: 'range',
      id: id(p.key),
      min: p.min,
      max: p.max,
      step: p.step,
      'data-key': p.key,
      'aria-label': label,
    });
    const num = el('input', {
      type: 'number',
      id: id(`${p.key}-n`),
      min: p.min,
      max: p.max,
      step: p.step,
      'data-key': p.key,
      'aria-label': `${label}, exact value`,
    });
    /** A fluid acts on the FE wing's mode shapes: a density above 0 brings the FE mode set, as the Medium control does. */
    const patchOf = (/** @type {number} */ v) => {
      /** @type {Record<string, unknown>} */
      const patch = { [p.key]: v };
      if (p.key === 'air_density' && v > 0 && store.get().modes !== 'fe') patch.modes = 'fe';
      return patch;
    };
    range.addEventListener('input', () => store.set(patchOf(snap(p, Number(range.value)))));
    num.addEventListener('change', () => {
      const v = Number(num.value);
      if (num.value.trim() === '' || !Number.isFinite(v)) {
        num.setAttribute('aria-invalid', 'true');
        return;
      }
      num.removeAttribute('aria-invalid');
      const s = snap(p, v);
      store.set(patchOf(s));
      if (s !== v) num.value = String(s);
    });
    inputs[p.key] = { range, num, p };
    const lab = el(
      'label',
      { for: id(p.key), class: 'wl-label' },
      el('span', { class: 'wl-sym', rich: p.sym }),
      el('span', {
        class: 'wl-long',
        rich: p.label.includes(',') ? p.label.replace(/^[^,]*, /, '') : p.label.replace(p.sym, '').trim(),
      }),
      p.unit ? el('span', { class: 'wl-unit', text: ` (${p.unit})` }) : null,
    );
    return el('div', { class: 'wl-row', 'data-row': p.key }, lab, range, num);
  };
  const main = el(
    'div',
    { class: 'wl-sliders wl-main-sliders' },
    ...MAIN_KEYS.map((k) => row(NUMERIC.find((p) => p.key === k))),
  );
  const more = el(
    'div',
    { class: 'wl-sliders wl-more-sliders' },
    ...NUMERIC.filter((p) => !MAIN_KEYS.includes(p.key)).map(row),
  );
  const selects = {};
  const selBox = el('div', { class: 'wl-selects' });
  for (const e of ENUMS) {
    const s = el('select', { id: id(e.key), 'data-key': e.key });
    for (const c of e.choices)
      s.append(el('option', { value: c, text: ENUM_TEXT[e.key][c], disabled: (e.disabled || []).includes(c) }));
    s.addEventListener('change', () => store.set({ [e.key]: s.value }));
    selBox.append(el('div', { class: 'wl-row wl-select' }, el('label', { for: id(e.key), text: e.label }), s));
    selects[e.key] = s;
  }
  const medium = mediumControl({
    store,
    id,
    openMore: () => {
      setMore(true);
      inputs.air_density.num.focus();
    },
  });
  const warnEl = el('p', { class: 'wl-warn', role: 'status', hidden: true });
  const timingEl = el('p', { class: 'wl-timing', 'aria-live': 'off', text: 'loading wasm…' });
  const moreId = id('more');
  const moreBtn = el('button', {
    type: 'button',
    class: 'wl-more-toggle',
    'aria-expanded': 'true',
    'aria-controls': moreId,
    text: 'More parameters',
  });
  const moreBox = el(
    'div',
    { class: 'wl-more', id: moreId },
    el('h3', { class: 'wl-more-title', text: 'More parameters' }),
    more,
    selBox,
    el('div', { class: 'wl-presets' }, preset),
    el('p', { class: 'wl-note', rich: `Sampling: 10 kHz. ${PAPER_UNITS_NOTE}` }),
    el('p', {
      class: 'wl-note',
      rich: `FE wing: shell finite elements of the synthetic Manduca-like outline (not digitised), 13 % camber, root edge clamped, E = 13.11 GPa, ${FE_LAB_INPUT.mesh_size_mm} mm elements, first ${FE_LAB_INPUT.n_modes} modes; SI a_k and strain at P = (3, −6) mm. Computed once, in a worker. Your own outline, material, clamp and up to 8 modes: the Wing panel.`,
    }),
  );
  const kinNote = el('p', {
    class: 'wl-note',
    'data-note': 'kin',
    hidden: true,
    rich: 'Custom kinematics in use (Kinematics panel): α_0, β_0, γ_0, the phases and f_d do not apply; ζ and the duration do.',
  });
  section.append(kinNote);
  section.append(main, medium.element, moreBtn, moreBox, warnEl, timingEl);

  let narrow = false;
  /** @type {boolean | null} on a focused screen (null: not told yet) */
  let focused = null;
  const setMore = (/** @type {boolean} */ open) => {
    moreBox.hidden = !open;
    moreBtn.setAttribute('aria-expanded', String(open));
    moreBtn.textContent = open ? 'Fewer parameters' : 'More parameters…';
  };
  moreBtn.addEventListener('click', () => setMore(Boolean(moreBox.hidden)));
  const sync = (s) => {
    for (const { range, num, p } of Object.values(inputs)) {
      const v = s[p.key];
      if (Number(range.value) !== v) range.value = String(v);
      if (activeIn(num) !== num || Number(num.value) !== v) num.value = String(v);
      num.removeAttribute('aria-invalid');
      range.setAttribute('aria-valuetext', valueText(p, v));
    }
    for (const [k, sel] of Object.entries(selects)) if (sel.value !== s[k]) sel.value = s[k];
    medium.sync(s);
  };
  /** The selected-mode choices are 1..N, N = the modes of the config (2 for the paper table). */
  const labelModes = (s) => {
    const fe = s.fe;
    const useFe = s.modes === 'fe' && fe;
    const n = useFe ? fe.modes.length : 2;
    for (const o of selects.mode.options) {
      const k = Number(o.value) - 1;
      const on = k < n;
      o.hidden = !on;
      o.disabled = !on;
      if (!on) continue;
      o.textContent = useFe
        ? `Mode ${k + 1}: ${fe.kinds && fe.kinds[k] ? fe.kinds[k] : 'FE'} (FE, ${fmt(fe.modes[k].freq_hz, 4)} Hz)`
        : ENUM_TEXT.mode[o.value];
    }
    kinNote.hidden = !s.kin;
  };
  const keys = [...NUMERIC.map((p) => p.key), ...ENUMS.map((e) => e.key)];
  const unsub = [
    store.subscribe(keys, sync),
    store.subscribe(['fe', 'modes', 'kin'], labelModes),
    store.subscribe(['timing', 'result', 'status'], (s) => {
      if (s.status) timingEl.textContent = s.status;
      else if (s.timing && s.result) {
        const a = s.result.analysis;
        timingEl.textContent = `compute ${s.timing.compute.toFixed(1)} ms + draw ${s.timing.draw.toFixed(1)} ms (${a.sim.n} samples × ${a.sim.modes.length} modes)`;
      }
      const w = (s.result && s.result.analysis.sim.warnings) || [];
      warnEl.hidden = w.length === 0;
      warnEl.textContent = w.join(' ');
    }),
  ];
  sync(store.get());
  labelModes(store.get());
  return {
    inputs,
    selects,
    /** Phone: a compact strip of the five main sliders; "More parameters" folds away. */
    setLayout(mode) {
      narrow = mode === 'narrow';
      section.classList.toggle('wl-compact', narrow);
      setMore(!(narrow || focused));
    },
    /**
     * A focused screen (www/screens.js): the five main sliders, the rest folded under "More
     * parameters…" as on a phone (full labels kept); the full page shows them all.
     * @param {string} screen
     */
    setScreen(screen) {
      const f = screen !== 'full';
      if (f === focused) return;
      focused = f;
      section.classList.toggle('wl-foldable', focused);
      setMore(!(narrow || focused));
    },
    destroy() {
      for (const f of unsub) f();
    },
  };
}
