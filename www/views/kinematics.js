// @ts-check
// Kinematics panel: your own stroke. Load measured angles from a CSV (a header naming `t` in
// seconds and any of `alpha`, `beta`, `gamma`; degrees or radians; one or more whole flap
// periods) — read by the core's kinematicsFromCsv, the function behind `wingbeat simulate
// --kinematics-csv` — and see the samples and the periodic interpolant the core uses (wasm
// anglesAt); or edit the mean and the harmonics of each angle by hand. The kinematics in use
// go to the store (`kin`); the engine puts them into every computation, and the share link
// carries them in its #s= fragment. "Use the sliders" goes back to the sliders' stroke.
// This file reads the CSV and wires the panel; its pieces: the preview (kinematics-preview.js),
// the hand editor (kinematics-editor.js) and the pure helpers (www/kinform.js).
import { el, activeIn } from '../dom.js';
import { fmt, errorText } from '../format.js';
import { DEFAULT_SAMPLED_MAX_HARMONIC } from '../fourier.js';
import { inUseWords } from '../kinform.js';
import { kinematicsPreview } from './kinematics-preview.js';
import { kinematicsEditor } from './kinematics-editor.js';

export const title = 'Kinematics';

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, engine, section, id } = ctx;

  // ---------- CSV ----------
  const fileIn = el('input', { type: 'file', id: id('kin-file'), accept: '.csv,.txt,text/csv', 'data-kin': 'file' });
  const unitsSel = el(
    'select',
    { id: id('kin-units'), 'data-kin': 'units' },
    el('option', { value: 'deg', text: 'degrees' }),
    el('option', { value: 'rad', text: 'radians' }),
  );
  const flapIn = el('input', {
    type: 'number',
    id: id('kin-flap'),
    min: 0.1,
    max: 1000,
    step: 0.1,
    'data-kin': 'flap_hz',
  });
  const harmIn = el('input', {
    type: 'number',
    id: id('kin-harm'),
    min: 1,
    max: 1000,
    step: 1,
    placeholder: String(DEFAULT_SAMPLED_MAX_HARMONIC),
    'data-kin': 'max_harmonic',
  });
  const statusEl = el('p', { class: 'wl-note', role: 'status', 'data-kin': 'status' });
  /** @type {{ text: string, name: string } | null} */
  let lastCsv = null;
  const say = (text, bad = false) => {
    statusEl.textContent = text;
    statusEl.classList.toggle('wl-bad', bad);
    statusEl.setAttribute('role', bad ? 'alert' : 'status');
  };
  const readCsv = () => {
    if (!lastCsv) return;
    const flap = Number(flapIn.value);
    if (!(flap > 0)) return say('Flap frequency: expected a number > 0 Hz.', true);
    /** @type {{ units: 'deg' | 'rad', flap_hz: number, max_harmonic?: number }} */
    const opts = { units: /** @type {'deg' | 'rad'} */ (unitsSel.value), flap_hz: flap };
    if (harmIn.value.trim() !== '') opts.max_harmonic = Math.round(Number(harmIn.value));
    try {
      const r = engine.kinematicsFromCsv(lastCsv.text, opts);
      store.set({
        kin: {
          kinematics: r.kinematics,
          source: 'csv',
          label: lastCsv.name,
          samples: r.samples,
          csv: {
            text: lastCsv.text,
            units: opts.units,
            flap_hz: flap,
            ...(opts.max_harmonic ? { max_harmonic: opts.max_harmonic } : {}),
          },
        },
      });
      const n = r.samples && r.samples.t ? r.samples.t.length : 0;
      say(
        `Read ${lastCsv.name}: ${n} samples over ${r.n_periods} period(s) at ${fmt(flap, 4)} Hz, in ${opts.units === 'deg' ? 'degrees' : 'radians'}.${r.warnings && r.warnings.length ? ' ' + r.warnings.join(' ') : ''}`,
      );
      ctx.emit('wl-kin', { state: 'loaded' });
    } catch (e) {
      say(`Could not use ${lastCsv.name}: ${errorText(e)}`, true);
    }
  };
  fileIn.addEventListener('change', async () => {
    const f = fileIn.files && fileIn.files[0];
    if (!f) return;
    if (f.size > 20e6) {
      say(`${f.name} is larger than 20 MB.`, true);
      return;
    }
    lastCsv = { text: await f.text(), name: f.name.slice(0, 80) };
    fileIn.value = '';
    readCsv();
  });
  for (const c of [unitsSel, flapIn, harmIn])
    c.addEventListener('change', () => {
      if (lastCsv) readCsv();
    });

  // ---------- the preview and the hand editor ----------
  const { svg, legend, desc, draw: preview } = kinematicsPreview(ctx);
  const editor = kinematicsEditor(ctx, {
    say,
    onReset: () => {
      lastCsv = null;
    },
  });
  const inUse = el('p', { class: 'wl-note', 'data-kin': 'in-use' });

  section.append(
    el('p', {
      class: 'wl-note',
      text: 'Measured kinematics: a CSV with a header row naming t (s) and any of alpha, beta, gamma (a missing angle is 0), one or more whole flap periods, t increasing; the angles in the units chosen below. The core folds them onto one period and interpolates them periodically.',
    }),
    el('div', { class: 'wl-kin-row' }, el('label', { for: id('kin-file'), text: 'Load a CSV ' }), fileIn),
    el(
      'div',
      { class: 'wl-kin-row' },
      el('label', { for: id('kin-units'), text: 'Angle units ' }),
      unitsSel,
      el('label', { for: id('kin-flap'), text: ' Flap frequency (Hz) ' }),
      flapIn,
      el('label', { for: id('kin-harm'), text: ' Highest harmonic ' }),
      harmIn,
    ),
    statusEl,
    inUse,
    svg,
    legend,
    desc,
    editor.box,
  );

  const showInUse = (s) => {
    inUse.textContent = inUseWords(s.kin, fmt);
  };
  const unsub = [
    store.subscribe(
      ['kin', 'alpha0', 'beta0', 'gamma0', 'alpha_phase', 'beta_phase', 'gamma_phase', 'flap_hz', 'result'],
      (s, changed) => {
        if (changed.includes('result') && changed.length === 1 && svg.childNodes.length) return;
        preview(s);
        showInUse(s);
      },
    ),
    store.subscribe(['flap_hz'], (s) => {
      if (!lastCsv && activeIn(flapIn) !== flapIn) flapIn.value = String(s.flap_hz);
    }),
  ];
  flapIn.value = String(store.get().flap_hz);
  showInUse(store.get());
  const whenReady = setInterval(() => {
    if (!engine.ready) return;
    clearInterval(whenReady);
    preview(store.get());
    editor.load();
  }, 100);
  return {
    destroy() {
      clearInterval(whenReady);
      for (const f of unsub) f();
    },
  };
}
