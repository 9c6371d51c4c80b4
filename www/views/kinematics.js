// @ts-check
// Kinematics panel: your own stroke. Load measured angles from a CSV (a header naming `t` in
// seconds and any of `alpha`, `beta`, `gamma`; degrees or radians; one or more whole flap
// periods) — read by the core's kinematicsFromCsv, the function behind `wingbeat simulate
// --kinematics-csv` — and see the samples and the periodic interpolant the core uses (wasm
// anglesAt); or edit the mean and the harmonics of each angle by hand. The kinematics in use
// go to the store (`kin`); the engine puts them into every computation, and the share link
// carries them in its #s= fragment. "Use the sliders" goes back to the sliders' stroke.
import { el, activeIn } from '../dom.js';
import { fmt, errorText } from '../format.js';
import { DEFAULT_SAMPLED_MAX_HARMONIC } from '../fourier.js';

export const title = 'Kinematics';

const ANGLES = /** @type {const} */ (['alpha', 'beta', 'gamma']);
const SYM = { alpha: 'α (roll)', beta: 'β (pitch)', gamma: 'γ (yaw)' };
const COL = { alpha: '#1f6aa5', beta: '#b34700', gamma: '#1e7a1e' };
/** Points of the interpolant drawn per period. */
const PREVIEW_POINTS = 241;

/**
 * A Fourier angle for the editor: mean and harmonics (rad), from any core Angle (a sampled one
 * has no harmonics to edit: its mean offset only).
 * @param {any} a
 */
function fourierOf(a) {
  if (a && a.kind === 'fourier')
    return {
      mean: a.mean || 0,
      harmonics: (a.harmonics || []).map((h) => ({ n: h.n, amplitude: h.amplitude, phase: h.phase || 0 })),
    };
  return { mean: 0, harmonics: [] };
}

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

  // ---------- preview (samples + the core's periodic interpolant) ----------
  const NS = 'http://www.w3.org/2000/svg';
  const svg = document.createElementNS(NS, 'svg');
  svg.setAttribute('class', 'wl-kin-svg');
  svg.setAttribute('role', 'img');
  svg.setAttribute('aria-labelledby', id('kin-desc'));
  svg.setAttribute('viewBox', '0 0 400 160');
  svg.setAttribute('preserveAspectRatio', 'none');
  const desc = el('p', { class: 'wl-note', id: id('kin-desc'), 'data-kin': 'summary' });
  const legend = el(
    'p',
    { class: 'wl-kin-legend', 'aria-hidden': 'true' },
    ...ANGLES.map((a) => el('span', { style: `color:${COL[a]}`, text: `— ${SYM[a]}  ` })),
    el('span', { class: 'wl-kin-dots', text: '● measured samples', hidden: true }),
  );
  const preview = (s) => {
    svg.replaceChildren();
    if (!engine.ready) return;
    let kinematics;
    try {
      kinematics = s.kin ? s.kin.kinematics : ctx.engine.config(s).kinematics;
    } catch {
      return;
    }
    if (!kinematics) return;
    const T = 1 / kinematics.flap_freq_hz;
    const t = Float64Array.from({ length: PREVIEW_POINTS }, (_, i) => (i * T) / (PREVIEW_POINTS - 1));
    let ang;
    try {
      ang = engine.anglesAt({ ...engine.baseConfig, kinematics }, t);
    } catch (e) {
      desc.textContent = `No preview: ${errorText(e)}`;
      return;
    }
    const samp = s.kin && s.kin.samples;
    /** @type {HTMLElement} */ (legend.querySelector('.wl-kin-dots')).hidden = !samp;
    let lo = Infinity,
      hi = -Infinity;
    for (const a of ANGLES)
      for (const v of ang[a]) {
        lo = Math.min(lo, v);
        hi = Math.max(hi, v);
      }
    if (samp)
      for (const a of ANGLES)
        for (const v of samp[a]) {
          lo = Math.min(lo, v);
          hi = Math.max(hi, v);
        }
    if (!(hi > lo)) {
      lo -= 1;
      hi += 1;
    }
    const pad = 0.08 * (hi - lo);
    lo -= pad;
    hi += pad;
    const X = (tt) => (400 * tt) / T,
      Y = (v) => 160 - (160 * (v - lo)) / (hi - lo);
    const zero = document.createElementNS(NS, 'line');
    zero.setAttribute('x1', '0');
    zero.setAttribute('x2', '400');
    zero.setAttribute('y1', String(Y(0)));
    zero.setAttribute('y2', String(Y(0)));
    zero.setAttribute('class', 'wl-kin-zero');
    svg.append(zero);
    for (const a of ANGLES) {
      const pl = document.createElementNS(NS, 'polyline');
      pl.setAttribute('points', Array.from(t, (tt, i) => `${X(tt).toFixed(2)},${Y(ang[a][i]).toFixed(2)}`).join(' '));
      pl.setAttribute('fill', 'none');
      pl.setAttribute('stroke', COL[a]);
      pl.setAttribute('stroke-width', '1.6');
      pl.setAttribute('vector-effect', 'non-scaling-stroke');
      svg.append(pl);
      if (samp) {
        const g = document.createElementNS(NS, 'g');
        g.setAttribute('fill', COL[a]);
        const n = samp.t.length;
        const stride = Math.max(1, Math.ceil(n / 400));
        for (let i = 0; i < n; i += stride) {
          const c = document.createElementNS(NS, 'circle');
          const tt = ((samp.t[i] % T) + T) % T;
          c.setAttribute('cx', X(tt).toFixed(2));
          c.setAttribute('cy', Y(samp[a][i]).toFixed(2));
          c.setAttribute('r', '1.8');
          g.append(c);
        }
        svg.append(g);
      }
    }
    const range = (arr) => {
      let a = Infinity,
        b = -Infinity;
      for (const v of arr) {
        a = Math.min(a, v);
        b = Math.max(b, v);
      }
      return [a, b];
    };
    desc.textContent =
      `One flap period (${fmt(T * 1e3, 4)} ms at ${fmt(kinematics.flap_freq_hz, 4)} Hz) of the kinematics in use${samp ? ', measured samples as dots and the core’s periodic interpolant as lines' : ''}: ` +
      ANGLES.map((a) => {
        const [mn, mx] = range(ang[a]);
        return `${SYM[a]} from ${fmt(mn, 3)} to ${fmt(mx, 3)} rad`;
      }).join('; ') +
      `. Vertical range ${fmt(lo, 3)} to ${fmt(hi, 3)} rad.`;
  };

  // ---------- hand editing: mean and harmonics of each angle ----------
  const editor = el('div', { class: 'wl-kin-editor', 'data-kin': 'editor' });
  /** @type {Record<string, { mean: number, harmonics: { n: number, amplitude: number, phase: number }[] }>} */
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
  const loadEditor = () => {
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
  const drawEditor = () => {
    editor.replaceChildren();
    for (const a of ANGLES) {
      const box = el('fieldset', { class: 'wl-kin-angle' }, el('legend', { text: `${SYM[a]}, rad` }));
      const e = edit[a];
      if (sampled[a]) {
        box.append(
          el('p', {
            class: 'wl-note',
            text: `Measured table (${sampled[a].values.length} samples per period): the mean offset and the harmonics below are added to it.`,
          }),
          el('label', { for: id(`kin-${a}-mean`), text: 'Mean offset (rad) ' }),
          num(`kin-${a}-mean`, `${SYM[a]} mean offset, rad`, e.mean, (v) => {
            e.mean = v;
          }),
        );
      } else {
        box.append(
          el('label', { for: id(`kin-${a}-mean`), text: 'Mean (rad) ' }),
          num(`kin-${a}-mean`, `${SYM[a]} mean, rad`, e.mean, (v) => {
            e.mean = v;
          }),
        );
      }
      {
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
          body.append(
            el(
              'tr',
              {},
              el(
                'td',
                {},
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
              el(
                'td',
                {},
                num(`kin-${a}-A${i}`, `${SYM[a]} harmonic ${i + 1}: amplitude, rad`, h.amplitude, (v) => {
                  h.amplitude = v;
                }),
              ),
              el(
                'td',
                {},
                num(`kin-${a}-p${i}`, `${SYM[a]} harmonic ${i + 1}: phase, rad`, h.phase, (v) => {
                  h.phase = v;
                }),
              ),
              el('td', {}, rm),
            ),
          );
        });
        tbl.append(body);
        const add = el('button', { type: 'button', text: 'Add harmonic', 'aria-label': `Add harmonic to ${SYM[a]}` });
        add.addEventListener('click', () => {
          const n = e.harmonics.reduce((m, h) => Math.max(m, h.n), 0) + 1;
          e.harmonics.push({ n, amplitude: 0, phase: 0 });
          drawEditor();
        });
        if (e.harmonics.length) box.append(tbl);
        box.append(add);
      }
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
    /** @type {any} */
    const k = { flap_freq_hz: editFlap };
    for (const a of ANGLES) {
      if (sampled[a]) {
        // Added on the table's own grid t_j = j T / N, so the core's interpolant carries them.
        const e = edit[a];
        const n = sampled[a].values.length;
        k[a] = {
          ...sampled[a],
          values: sampled[a].values.map(
            (v, j) =>
              v +
              e.mean +
              e.harmonics.reduce((acc, h) => acc + h.amplitude * Math.sin((2 * Math.PI * h.n * j) / n + h.phase), 0),
          ),
        };
      } else
        k[a] = {
          kind: 'fourier',
          mean: edit[a].mean,
          harmonics: edit[a].harmonics.map((h) => ({ n: h.n, amplitude: h.amplitude, phase: h.phase })),
        };
    }
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
        label: prev ? `edited ${prev.label}`.replace(/^(edited )+/, 'edited ') : 'edited kinematics',
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
    lastCsv = null;
    say('Back to the sliders’ kinematics (α0, β0, γ0, phases, f_d).');
  });
  const reloadBtn = el('button', { type: 'button', text: 'Edit the kinematics in use', 'data-kin': 'load-editor' });
  reloadBtn.addEventListener('click', loadEditor);
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
    el(
      'details',
      { class: 'wl-kin-edit' },
      el('summary', { text: 'Edit means and harmonics by hand' }),
      el('div', { class: 'wl-kin-actions' }, reloadBtn),
      editor,
      el('div', { class: 'wl-kin-actions' }, applyBtn, resetBtn),
    ),
  );

  const showInUse = (s) => {
    const k = s.kin;
    inUse.textContent = !k
      ? 'In use: the sliders’ kinematics (first harmonics α0, β0, γ0 with their phases, at f_d).'
      : `In use: ${k.label} (${k.source === 'csv' ? 'measured table' : k.source === 'edited' ? 'edited by hand' : 'from the shared link'}, ${fmt(k.kinematics.flap_freq_hz, 4)} Hz). The Parameters panel’s amplitudes, phases and f_d do not apply; ζ and the duration do.`;
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
    loadEditor();
  }, 100);
  return {
    destroy() {
      clearInterval(whenReady);
      for (const f of unsub) f();
    },
  };
}
