// @ts-check
// Studies panel (paper Figs. 6–8), computed on demand in the worker through the engine:
// contribution vs a parameter, the initial-condition map, damping. Each can be cancelled.
import { el } from '../dom.js';
import { fmt, UNITS, errorText } from '../format.js';
import { linePlot, color, drawHeatmap } from '../plot.js';
import { NUMERIC, toQuery, describe } from '../state.js';
import { sweepColumns, icmapColumns, dampingColumns } from './studies-data.js';

export const title = 'Studies (paper Figs. 6–8)';

const Q = UNITS.q.label;

/**
 * A labelled number box: [label, input].
 * @param {string} label
 * @param {number} value
 * @param {number} min
 * @param {number} max
 * @param {number | 'any'} step
 * @returns {[HTMLLabelElement, HTMLInputElement]}
 */
function num(label, value, min, max, step) {
  const i = el('input', { type: 'number', value, min, max, step, 'aria-label': label });
  return [el('label', { class: 'wl-inline' }, label + ' ', i), i];
}
/**
 * A labelled select: [label, select].
 * @param {string} label
 * @param {[string, string][]} opts value, text
 * @param {string} value
 * @returns {[HTMLLabelElement, HTMLSelectElement]}
 */
function sel(label, opts, value) {
  const s = el('select', { 'aria-label': label });
  for (const [v, t] of opts) s.append(el('option', { value: v, text: t }));
  s.value = value;
  return [el('label', { class: 'wl-inline' }, label + ' ', s), s];
}

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, section, engine } = ctx;
  const studies = {};
  const plots = [];
  const study = (key, heading, controls, run, note) => {
    const box = el('div', { class: 'wl-study', 'data-study': key });
    const head = el('div', { class: 'wl-head' }, el('h3', { text: heading }), ctx.exportButtons(key, heading));
    const btn = el('button', { type: 'button', class: 'wl-run', text: 'Run', 'data-run': key });
    const cancel = el('button', { type: 'button', class: 'wl-cancel', text: 'Cancel', hidden: true });
    const prog = el('progress', {
      class: 'wl-progress',
      max: 1,
      value: 0,
      hidden: true,
      'aria-label': `${heading} progress`,
    });
    const status = el('span', { class: 'wl-status', role: 'status' });
    const out = el('div', { class: 'wl-study-out' });
    btn.addEventListener('click', () => run(btn, prog, status, out, cancel));
    box.append(head, el('div', { class: 'wl-study-controls' }, ...controls, btn, cancel, prog, status));
    if (note) box.append(el('p', { class: 'wl-note', text: note }));
    box.append(out);
    section.append(box);
    studies[key] = { box, out, status, heading };
  };
  const params = () => store.get();
  const cfg = () => engine.config(params());
  const modeIndex = () => Number(params().mode) - 1;

  function runJob(kind, payload, btn, prog, status, cancel, done) {
    btn.disabled = true;
    prog.hidden = false;
    prog.removeAttribute('value');
    status.textContent = 'computing…';
    const job = engine.run(kind, payload, (i, n) => {
      prog.max = n;
      prog.value = i;
      status.textContent = `${i} / ${n}`;
    });
    cancel.hidden = false;
    cancel.onclick = () => engine.cancel(job.id);
    const finish = () => {
      btn.disabled = false;
      prog.hidden = true;
      cancel.hidden = true;
    };
    job.promise
      .then(({ result, ms }) => {
        finish();
        done(result, ms);
        ctx.emit('wl-study', { kind });
      })
      .catch((e) => {
        finish();
        status.textContent = errorText(e) === 'cancelled' ? 'Cancelled.' : `Error: ${errorText(e)}`;
      });
  }

  // Fig. 6: contribution vs a parameter.
  const [lp, sp] = sel(
    'parameter',
    [
      ['gamma0', 'γ0 (rad)'],
      ['alpha0', 'α0 (rad)'],
      ['beta0', 'β0 (rad)'],
      ['flap_hz', 'f_d (Hz)'],
      ['zeta', 'ζ'],
    ],
    'gamma0',
  );
  const [lf, from] = num('from', 0, -1e3, 1e3, 'any');
  const [lt, to] = num('to', 0.5, -1e3, 1e3, 'any');
  const [ln, pts] = num('points', 26, 2, 201, 1);
  sp.addEventListener('change', () => {
    const p = NUMERIC.find((q) => q.key === sp.value);
    if (!p) return;
    from.value = String(p.min);
    to.value = String(p.max);
  });
  study(
    'sweep',
    'Contribution vs parameter (Fig. 6)',
    [lp, lf, lt, ln],
    (btn, prog, status, out, cancel) => {
      const opts = {
        param: sp.value,
        from: Number(from.value),
        to: Number(to.value),
        points: Math.round(Number(pts.value)),
      };
      runJob('sweep', { cfg: cfg(), opts }, btn, prog, status, cancel, (r, ms) => {
        drawSweep(out, r, opts);
        status.textContent = `${r.values.length} points in ${ms.toFixed(0)} ms (worker)`;
      });
    },
    'Each point is a full simulation of the current case with one parameter changed; selected mode shown.',
  );

  // Fig. 7: initial-condition map.
  const [lg, grid] = num('grid', 101, 2, 401, 1);
  const [la, attr] = sel(
    'attribution',
    [
      ['forced', 'forced (paper)'],
      ['carried', 'carried'],
    ],
    'forced',
  );
  study(
    'icmap',
    'Initial-condition map (Fig. 7)',
    [lg, la],
    (btn, prog, status, out, cancel) => {
      const n = Math.round(Number(grid.value));
      const opts = { mode: modeIndex(), n_q: n, n_qdot: n, attribution: attr.value };
      runJob('icmap', { cfg: cfg(), opts }, btn, prog, status, cancel, (r, ms) => {
        drawIcMap(out, r);
        status.textContent = `${r.n_q}×${r.n_qdot} in ${ms.toFixed(1)} ms (worker); Coriolis share ${fmt(r.min_percent, 3)}–${fmt(r.max_percent, 3)} %, ${fmt(100 * r.fraction_above_60, 3)} % of cells above 60 %`;
      });
    },
    'Coriolis share of the selected mode over a grid of initial conditions (q0, q̇0) spanning the forced response’s range.',
  );

  // Fig. 8: damping.
  const [lz, zeta] = num('ζ', 0.01, 0, 1, 0.001);
  const [ld, dur] = num('duration (s)', 10, 0.5, 60, 0.5);
  study(
    'damping',
    'Damping (Fig. 8)',
    [lz, ld],
    (btn, prog, status, out, cancel) => {
      const c = cfg();
      c.duration_s = Number(dur.value);
      const opts = { zeta: Number(zeta.value), mode: modeIndex() };
      runJob('damping', { cfg: c, opts }, btn, prog, status, cancel, (r, ms) => {
        drawDamping(out, r);
        status.textContent = `2 runs × ${r.n} samples in ${ms.toFixed(0)} ms (worker)`;
      });
    },
    'Total response of the selected mode, undamped vs damped, over a longer run: damping removes the beat.',
  );

  function drawSweep(out, r, opts) {
    const k = modeIndex();
    const p = NUMERIC.find((q) => q.key === opts.param);
    const unit = p && p.unit ? p.unit : '–';
    out.replaceChildren();
    const plot = linePlot(out, {
      name: 'sweep',
      title: 'Contribution vs parameter',
      ariaLabel: `Force-term shares of mode ${k + 1} against ${p ? p.label : opts.param}`,
      xLabel: p ? p.sym : opts.param,
      xUnit: unit,
      yLabel: 'share (%)',
      series: [
        { label: 'Euler', color: color('euler') },
        { label: 'Centrifugal', color: color('centrifugal') },
        { label: 'Coriolis', color: color('coriolis') },
      ],
      height: 220,
    });
    plots.push(plot);
    const m = r.modes[k];
    plot.setData([Array.from(r.values), Array.from(m.euler), Array.from(m.centrifugal), Array.from(m.coriolis)]);
    plot.setSummary(
      `${r.values.length} values of ${opts.param} from ${fmt(r.values[0], 3)} to ${fmt(r.values[r.values.length - 1], 3)} ${unit}: Coriolis share from ${fmt(m.coriolis[0], 3)} % to ${fmt(m.coriolis[m.coriolis.length - 1], 3)} %.`,
    );
    studies.sweep.data = { r, k, param: opts.param, unit, plot: plot.u, wrap: plot, sym: p ? p.sym : opts.param };
  }

  function drawIcMap(out, r) {
    out.replaceChildren();
    const desc = `ic-desc-${Math.random().toString(36).slice(2)}`;
    const canvas = el('canvas', {
      class: 'wl-heatmap',
      width: 560,
      height: 360,
      role: 'img',
      'aria-label': 'Heat map of the Coriolis share (%) over initial conditions q0 and q̇0',
      'aria-describedby': desc,
    });
    out.append(
      canvas,
      el('p', {
        class: 'wl-sr',
        id: desc,
        text: `Coriolis share of mode ${r.mode + 1} over ${r.n_q}×${r.n_qdot} initial conditions: from ${fmt(r.min_percent, 3)} % to ${fmt(r.max_percent, 3)} %, ${fmt(100 * r.fraction_above_60, 3)} % of the cells above 60 %.`,
      }),
    );
    drawHeatmap(canvas, {
      nx: r.n_q,
      ny: r.n_qdot,
      x: r.q0,
      y: r.qdot0,
      z: r.coriolis_percent,
      zmin: r.min_percent,
      zmax: r.max_percent,
      xLabel: `q_0 (${Q})`,
      yLabel: `q̇_0 (${Q}/s)`,
      zLabel: 'Coriolis share (%)',
    });
    studies.icmap.data = { r, canvas };
  }

  function drawDamping(out, r) {
    out.replaceChildren();
    const plot = linePlot(out, {
      name: 'damping',
      title: 'Damping',
      ariaLabel: `Total response of mode ${r.mode + 1} without damping and with ζ = ${r.zeta}`,
      xLabel: 't',
      xUnit: 's',
      yLabel: `q total (${Q})`,
      series: [
        { label: 'ζ = 0', color: '#999' },
        { label: `ζ = ${r.zeta}`, color: color('envelope') },
      ],
      height: 220,
    });
    plots.push(plot);
    plot.setData([Array.from(r.t), Array.from(r.undamped), Array.from(r.damped)]);
    plot.setSummary(`Total response over ${fmt(r.t[r.t.length - 1], 3)} s, undamped and with ζ = ${r.zeta}.`);
    studies.damping.data = { r, plot: plot.u, wrap: plot };
  }

  const case_ = () => `wingbeat lab; ${toQuery(store.get())}`;
  ctx.registerExport('sweep', {
    csv: () => {
      const st = studies.sweep.data;
      if (!st) return null;
      return ctx.toCSV(sweepColumns(st.r, st.k, st.param, st.unit), [case_(), `mode ${st.k + 1}`]);
    },
    figure: () => {
      const st = studies.sweep.data;
      if (!st) return null;
      return {
        title: `Force-term shares vs ${st.param}, mode ${st.k + 1} (paper Fig. 6)`,
        params: describe(store.get()),
        x: st.r.values,
        xLabel: `${st.sym} (${st.unit})`,
        yLabel: 'share (%)',
        series: st.wrap.exportSeries(),
      };
    },
  });
  ctx.registerExport('icmap', {
    csv: () => {
      const st = studies.icmap.data;
      if (!st) return null;
      const r = st.r;
      return ctx.toCSV(icmapColumns(r), [case_(), `mode ${r.mode + 1}; attribution ${r.attribution}`]);
    },
    canvas: () => (studies.icmap.data ? studies.icmap.data.canvas : null),
  });
  ctx.registerExport('damping', {
    csv: () => {
      const st = studies.damping.data;
      if (!st) return null;
      return ctx.toCSV(dampingColumns(st.r), [
        case_(),
        `mode ${st.r.mode + 1}; min/max-decimated to the plotted points`,
      ]);
    },
    figure: () => {
      const st = studies.damping.data;
      if (!st) return null;
      return {
        title: `Damping removes the beat, mode ${st.r.mode + 1} (paper Fig. 8)`,
        params: describe(store.get()),
        x: st.r.t,
        xLabel: 't (s)',
        yLabel: `q total (${Q})`,
        series: st.wrap.exportSeries(),
      };
    },
  });
  return {
    studies,
    destroy: () => {
      for (const p of plots) p.destroy();
    },
  };
}
