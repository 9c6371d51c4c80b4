// @ts-check
// Resonance map study panel: the Floquet effective frequency of each mode and the largest
// |multiplier| over a range of flap frequencies (wasm `resonanceMap`, a worker job through the
// engine, with progress and cancel), the lines f = n·f_d (n = 1…4) over the f_eff curves, and
// the unstable bands shaded and labelled; optionally α_0 as a second axis, drawn as a heat map
// of the largest |multiplier| with the f_eff = n·f_d crossings marked. Units on every axis, a
// text alternative (summary sentence + table: where unstable, where resonant), CSV, PNG and
// SVG export (the f_eff plot as a figure).
import { el } from '../dom.js';
import { plain, errorText } from '../format.js';
import { linePlot } from '../plot.js';
import { describe, toQuery } from '../state.js';
import { resonanceSummary, bands, fmt } from '../experiments.js';
import { MODE_COLORS, N_LINES, resonanceRow, resonanceCSV } from './resonance-data.js';
import { drawResonanceHeatmap } from './resonance-heatmap.js';

export const title = 'Resonance map: effective frequency and stability vs flap frequency';

const hexA = (hex, a) => {
  const n = parseInt(hex.slice(1), 16);
  return `rgba(${n >> 16},${(n >> 8) & 255},${n & 255},${a})`;
};

/** The text alternative: a table per mode (unstable bands, largest |λ|, resonances). */
function summaryTable(sum, caption) {
  const t = el('table', { class: 'wl-numtable wl-res-table' });
  t.append(el('caption', { class: 'wl-note', rich: caption }));
  t.append(
    el(
      'thead',
      {},
      el(
        'tr',
        {},
        ...['Mode', 'Unstable for f_d in (Hz)', 'Largest |λ| (at f_d)', 'f_{eff} = n·f_d at f_d (Hz)'].map((h) =>
          el('th', { scope: 'col', rich: h }),
        ),
      ),
    ),
  );
  const tb = el('tbody');
  for (const m of sum.modes) {
    tb.append(
      el(
        'tr',
        {},
        el('th', { scope: 'row', text: `${m.mode} (f = ${plain(fmt(m.freq_hz, 4))} Hz)` }),
        el('td', {
          text: m.unstable.length
            ? m.unstable
                .map(([a, b]) => (a === b ? plain(fmt(a, 4)) : `${plain(fmt(a, 4))}–${plain(fmt(b, 4))}`))
                .join(', ')
            : 'none',
        }),
        el('td', { text: `${plain(fmt(m.max_modulus, 6))} (${plain(fmt(m.max_at_hz, 4))} Hz)` }),
        el('td', {
          text: m.resonances.length
            ? m.resonances.map((c) => `${plain(fmt(c.flap_hz, 4))} (n = ${c.n})`).join(', ')
            : 'none',
        }),
      ),
    );
  }
  t.append(tb);
  return t;
}

/** Unstable bands of a row for linePlot (half a grid step either side), with their mode. */
function plotBands(row) {
  const dx = row.fd.length > 1 ? (row.fd[1] - row.fd[0]) / 2 : 0;
  const out = [];
  row.modes.forEach((m, k) => {
    const c = MODE_COLORS[k % MODE_COLORS.length];
    for (const [a, b] of bands(
      row.fd,
      m.stable.map((s) => !s),
    ))
      out.push({ x0: a - dx, x1: b + dx, fill: hexA(c, 0.16), color: c, mode: k + 1 });
  });
  return out;
}

/**
 * uPlot draw hook: hatches each unstable band (so it does not rely on colour) and writes
 * "mode k unstable" inside the bands wide enough for it, bottom-left, one row per mode.
 */
function bandMarks(getBands) {
  return (u) => {
    const ctx = u.ctx;
    const r = devicePixelRatio || 1;
    const { left, top, width, height } = u.bbox;
    ctx.save();
    ctx.beginPath();
    ctx.rect(left, top, width, height);
    ctx.clip();
    ctx.font = `${Math.round(11 * r)}px system-ui, sans-serif`;
    ctx.textAlign = 'left';
    ctx.textBaseline = 'top';
    for (const b of getBands()) {
      const x0 = Math.max(left, u.valToPos(b.x0, 'x', true));
      const x1 = Math.min(left + width, u.valToPos(b.x1, 'x', true));
      if (!(x1 > x0)) continue;
      ctx.strokeStyle = hexA(b.color, 0.45);
      ctx.lineWidth = r;
      for (let x = x0 - height; x < x1; x += 9 * r) {
        const a = Math.max(x, x0),
          e = Math.min(x + height, x1);
        ctx.beginPath();
        ctx.moveTo(a, top + height - (a - x));
        ctx.lineTo(e, top + height - (e - x));
        ctx.stroke();
      }
      const text = `mode ${b.mode} unstable`;
      const tw = ctx.measureText(text).width;
      if (x1 - x0 < tw + 8 * r) continue;
      const y = top + height - (17 + (b.mode - 1) * 15) * r;
      ctx.fillStyle = 'rgba(255,255,255,0.9)';
      ctx.fillRect(x0 + 3 * r, y - r, tw + 4 * r, 14 * r);
      ctx.fillStyle = b.color;
      ctx.fillText(text, x0 + 5 * r, y);
    }
    ctx.restore();
  };
}

/**
 * The export figure has no y-range option: the n·f_d lines (series after the modes) are cut
 * where they leave the f_eff range (1.15 × the largest f_eff), so the figure keeps the plot's
 * scale instead of stretching to 4·f_d.
 */
function clipLines(series, nModes) {
  let hi = 10;
  for (const s of series.slice(0, nModes))
    for (const v of s.y) if (v != null && Number.isFinite(v)) hi = Math.max(hi, v);
  const top = 1.15 * hi;
  return series.map((s, i) =>
    i < nModes ? s : { ...s, y: Array.from(s.y, (v) => (v != null && v <= top ? v : null)) },
  );
}

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, section, engine } = ctx;
  const uid = ctx.id('res');
  /**
   * A labelled number box (rich label): [label, input].
   * @param {string} label
   * @param {number} value
   * @param {number} min
   * @param {number} max
   * @param {number | 'any'} step
   * @returns {[HTMLLabelElement, HTMLInputElement]}
   */
  const num = (label, value, min, max, step) => {
    const i = el('input', { type: 'number', value, min, max, step, 'aria-label': plain(label) });
    return [el('label', { class: 'wl-inline' }, el('span', { rich: label }), ' ', i), i];
  };
  const [lf, from] = num('f_d from (Hz)', 5, 0.1, 1000, 'any');
  const [lt, to] = num('to (Hz)', 60, 0.1, 1000, 'any');
  const [ln, pts] = num('points', 221, 2, 2001, 1);
  const two = el('input', { type: 'checkbox', id: `${uid}-2d` });
  const l2 = el(
    'label',
    { class: 'wl-inline wl-check', for: `${uid}-2d` },
    two,
    ' ',
    el('span', { rich: 'α_0 as a second axis' }),
  );
  const [la0, a0from] = num('α_0 from (rad)', 0.2, 0, 1.5, 0.05);
  const [la1, a0to] = num('α_0 to (rad)', 1.2, 0, 1.5, 0.05);
  const [lan, a0n] = num('α_0 values', 11, 2, 201, 1);
  const axis2 = el('span', { class: 'wl-res-axis2', hidden: true }, la0, la1, lan);
  two.addEventListener('change', () => {
    axis2.hidden = !two.checked;
  });
  const runBtn = el('button', { type: 'button', class: 'wl-run', text: 'Run', 'data-run': 'resonance' });
  const cancelBtn = el('button', {
    type: 'button',
    class: 'wl-cancel',
    text: 'Cancel',
    'data-cancel': 'resonance',
    hidden: true,
  });
  const prog = el('progress', {
    class: 'wl-progress',
    max: 1,
    value: 0,
    hidden: true,
    'aria-label': 'Resonance map progress',
  });
  const status = el('span', { class: 'wl-status', role: 'status' });
  const box = el('div', { class: 'wl-study wl-resonance', 'data-study': 'resonance' });
  const out = el('div', { class: 'wl-study-out' });
  box.append(
    el('div', { class: 'wl-study-controls' }, lf, lt, ln, l2, axis2, runBtn, cancelBtn, prog, status),
    el('p', {
      class: 'wl-note',
      rich: 'Floquet analysis of Eq. 13 at each flap frequency, with the other parameters as set (no time series): the effective natural frequency f_{eff} of each mode (top) and the largest |multiplier| of the monodromy matrix over one flap period (bottom; above 1 the mode grows without bound — a parametric instability; shaded bands). Where f_{eff} meets a grey line n·f_d the flapping drives the mode at resonance and the beat period 1/|f_{eff} − n·f_d| becomes infinite.',
    }),
    out,
  );
  section.append(box);

  /** @type {import('../pkg/wingbeat.js').ResonanceMapResult | null} */
  let result = null;
  /** @type {Promise<unknown> | null} */
  let current = null;
  let rowIndex = 0;
  /** @type {import('../lab.js').Plot | null} */
  let fPlot = null;
  /** @type {import('../lab.js').Plot | null} */
  let mPlot = null;
  /** @type {ResizeObserver | null} */
  let heat = null;
  const cleanup = () => {
    for (const p of [fPlot, mPlot]) if (p) p.destroy();
    if (heat) heat.disconnect();
    fPlot = mPlot = heat = null;
  };

  function draw(r) {
    cleanup();
    out.replaceChildren();
    const sumBox = el('div', { class: 'wl-res-summary' });
    if (r.alpha0) {
      const canvas = el('canvas', {
        class: 'wl-heatmap wl-res-heatmap',
        role: 'img',
        'aria-label': `Heat map of the largest Floquet multiplier modulus over flap frequency ${plain(fmt(r.flap_hz[0], 3))}–${plain(fmt(r.flap_hz[r.flap_hz.length - 1], 3))} Hz (across) and roll amplitude α0 ${plain(fmt(r.alpha0[0], 3))}–${plain(fmt(r.alpha0[r.alpha0.length - 1], 3))} rad (up); dots mark f_eff = n·f_d. The table below gives the numbers for the chosen α0 row.`,
      });
      out.append(canvas);
      const rowSel = el('select', { id: `${uid}-row` });
      r.alpha0.forEach((a, j) => {
        rowSel.append(el('option', { value: String(j), text: `α0 = ${plain(fmt(a, 4))} rad` }));
      });
      let best = 0;
      const a0 = store.get().alpha0;
      r.alpha0.forEach((a, j) => {
        if (Math.abs(a - a0) < Math.abs(r.alpha0[best] - a0)) best = j;
      });
      rowSel.value = String(best);
      rowIndex = best;
      rowSel.addEventListener('change', () => {
        rowIndex = Number(rowSel.value);
        drawRow(r, sumBox);
      });
      out.append(
        el(
          'p',
          { class: 'wl-inline' },
          el('label', { for: `${uid}-row`, text: 'Curves and table below for ' }),
          rowSel,
        ),
      );
      const paint = () => drawResonanceHeatmap(canvas, r);
      requestAnimationFrame(paint);
      if (typeof ResizeObserver === 'function') {
        heat = new ResizeObserver(paint);
        heat.observe(canvas);
      }
    } else rowIndex = 0;
    const row0 = resonanceRow(r, rowIndex);
    const modeSeries = row0.modes.map((m, k) => ({
      label: `mode ${k + 1}: f_{eff} (f_${k + 1} = ${fmt(m.freq_hz, 4)} Hz)`,
      unit: 'Hz',
      color: MODE_COLORS[k % MODE_COLORS.length],
      width: 2,
    }));
    const lineSeries = [];
    for (let n = 1; n <= N_LINES; n++)
      lineSeries.push({
        label: `${n}·f_d`,
        unit: 'Hz',
        color: ['#6b6b6b', '#8a8a8a', '#9e9e9e', '#b0b0b0'][n - 1],
        dash: [6, 3 + n],
        width: 1,
      });
    fPlot = linePlot(out, {
      name: 'resonance-feff',
      title: 'Effective frequency vs flap frequency',
      xLabel: 'flap frequency f_d',
      xUnit: 'Hz',
      yLabel: 'frequency f (Hz)',
      series: [...modeSeries, ...lineSeries],
      height: 260,
      bands: () => plotBands(resonanceRow(r, rowIndex)),
      hooks: { draw: [bandMarks(() => plotBands(resonanceRow(r, rowIndex)))] },
      ariaLabel:
        'Effective frequency of each mode against flap frequency, with the lines n·f_d and the unstable bands shaded',
      keys: true,
    });
    // Keep the n·f_d lines from stretching the axis: the y range follows the f_eff curves.
    const nm = row0.modes.length;
    fPlot.u.scales.y.range = (u) => {
      let hi = 10;
      for (let k = 1; k <= nm; k++)
        for (const v of u.data[k] || []) if (v != null && Number.isFinite(v)) hi = Math.max(hi, v);
      return [0, hi * 1.15];
    };
    mPlot = linePlot(out, {
      name: 'resonance-modulus',
      title: 'Largest Floquet multiplier vs flap frequency',
      xLabel: 'flap frequency f_d',
      xUnit: 'Hz',
      yLabel: 'largest |multiplier| per flap period (–)',
      series: row0.modes.map((_m, k) => ({
        label: `mode ${k + 1}: max |λ|`,
        unit: '',
        color: MODE_COLORS[k % MODE_COLORS.length],
        width: 2,
      })),
      height: 170,
      bands: () => plotBands(resonanceRow(r, rowIndex)),
      hooks: { draw: [bandMarks(() => plotBands(resonanceRow(r, rowIndex)))] },
      ariaLabel: 'Largest Floquet multiplier modulus of each mode against flap frequency; above 1 is unstable',
      keys: true,
    });
    mPlot.u.scales.y.range = (u) => {
      let lo = 1,
        hi = 1;
      for (let k = 1; k <= nm; k++)
        for (const v of u.data[k] || [])
          if (v != null && Number.isFinite(v)) {
            lo = Math.min(lo, v);
            hi = Math.max(hi, v);
          }
      const pad = Math.max(1e-3, (hi - lo) * 0.08);
      return [lo - pad, hi + pad];
    };
    out.append(sumBox);
    drawRow(r, sumBox);
  }

  function drawRow(r, sumBox) {
    if (!fPlot || !mPlot) return;
    const row = resonanceRow(r, rowIndex);
    const x = row.fd;
    const lines = [];
    for (let n = 1; n <= N_LINES; n++) lines.push(x.map((f) => n * f));
    fPlot.setData([x, ...row.modes.map((m) => m.feff.map((v) => (Number.isFinite(v) ? v : null))), ...lines]);
    mPlot.setData([x, ...row.modes.map((m) => m.mod.map((v) => (Number.isFinite(v) ? v : null)))]);
    const sum = resonanceSummary(r, rowIndex);
    const which = r.alpha0 ? ` (α_0 = ${fmt(r.alpha0[rowIndex], 4)} rad)` : '';
    const sentence = sum.sentence.replace('Resonance map,', `Resonance map${which},`);
    fPlot.setSummary(plain(sentence));
    mPlot.setSummary(plain(sentence));
    sumBox.replaceChildren(
      el('p', { class: 'wl-res-sentence', 'data-summary': 'resonance', rich: sentence }),
      summaryTable(sum, `Where each mode is unstable and where f_{eff} meets n·f_d${which}`),
    );
  }

  function run(opts) {
    if (current) return current;
    const o = opts || { from_hz: Number(from.value), to_hz: Number(to.value), points: Math.round(Number(pts.value)) };
    if (!opts && two.checked) {
      const n = Math.max(2, Math.round(Number(a0n.value)));
      const lo = Number(a0from.value),
        hi = Number(a0to.value);
      o.alpha0_values = Array.from({ length: n }, (_, j) => lo + ((hi - lo) * j) / (n - 1));
    }
    runBtn.disabled = true;
    cancelBtn.hidden = false;
    prog.hidden = false;
    prog.removeAttribute('value');
    status.textContent = 'computing…';
    const job = engine.resonanceMap(engine.config(store.get()), o, (done, total) => {
      prog.max = total;
      prog.value = done;
      status.textContent = `${done} / ${total}`;
    });
    cancelBtn.onclick = () => engine.cancel(job.id);
    const finish = () => {
      current = null;
      runBtn.disabled = false;
      cancelBtn.hidden = true;
      prog.hidden = true;
    };
    current = job.promise.then(
      ({ result: r, ms }) => {
        finish();
        result = r;
        draw(r);
        const cells = r.flap_hz.length * (r.alpha0 ? r.alpha0.length : 1);
        status.textContent = `${cells} Floquet analyses × ${r.modes.length} modes in ${ms.toFixed(0)} ms (worker)`;
        box.dataset.done = String(Number(box.dataset.done || 0) + 1);
        ctx.emit('wl-study', { kind: 'resonance' });
        return r;
      },
      (e) => {
        finish();
        status.textContent = errorText(e) === 'cancelled' ? 'Cancelled.' : `Error: ${errorText(e)}`;
        return null;
      },
    );
    return current;
  }
  runBtn.addEventListener('click', () => run());

  ctx.registerExport('resonance', {
    csv: () => (result ? resonanceCSV(result, `wingbeat lab; ${toQuery(store.get())}`) : null),
    figure: () => {
      if (!result || !fPlot) return null;
      const row = resonanceRow(result, rowIndex);
      return {
        title: `Resonance map: effective frequency vs flap frequency${result.alpha0 ? ` (α_0 = ${fmt(result.alpha0[rowIndex], 4)} rad)` : ''}`,
        params: describe(store.get()),
        x: fPlot.u.data[0],
        xRange: fPlot.xWindow(),
        xLabel: 'flap frequency f_d (Hz)',
        yLabel: 'frequency f (Hz)',
        series: clipLines(fPlot.exportSeries(), row.modes.length),
        bands: plotBands(row).map((b) => ({
          x0: b.x0,
          x1: b.x1,
          color: b.color,
          fill: b.fill,
          label: b.x1 - b.x0 > 0.06 * (row.fd[row.fd.length - 1] - row.fd[0]) ? `mode ${b.mode} unstable` : '',
        })),
        note:
          'Shaded: Floquet-unstable (largest |multiplier| > 1). Grey: n·f_d. ' +
          plain(resonanceSummary(result, rowIndex).sentence),
      };
    },
  });

  return {
    run,
    data: () => result,
    destroy() {
      cleanup();
    },
  };
}
