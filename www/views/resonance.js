// Resonance map study view: the Floquet effective frequency of each mode and the largest
// |multiplier| over a range of flap frequencies (wasm `resonanceMap`, run as a worker job), with
// the lines f = n·f_d (n = 1…4) over the f_eff curves and the unstable bands shaded; optionally
// α0 as a second axis, drawn as a heat map of the largest |multiplier|. Every axis has units;
// the text alternative (summary sentence + table) says where the wing is unstable and where
// f_eff meets n·f_d. CSV export of the full grid.
//
// The view owns its DOM only. It talks to the computation through `run(cfg, opts, onProgress)`
// → { promise, cancel } (the engine's worker job) and asks the host for the current config and
// case line; see `mountResonance` below.
import { uPlot, fmt, toCSV, download, viridis } from '../plot.js';
import { resonanceSummary, resonanceCrossings, bands } from '../experiments.js';

const MODE_COLORS = ['#1f5fbf', '#c2410c', '#2e7d32', '#7b1fa2'];
const N_LINES = 4;

function el(tag, props = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) {
    if (k === 'class') e.className = v;
    else if (k === 'text') e.textContent = v;
    else if (k.startsWith('aria-') || k.startsWith('data-') || k === 'role' || k === 'for' || k === 'hidden') {
      if (v !== false && v != null) e.setAttribute(k, v === true ? '' : v);
    } else e[k] = v;
  }
  for (const c of children) if (c != null) e.append(c);
  return e;
}

const hexA = (hex, a) => {
  const n = parseInt(hex.slice(1), 16);
  return `rgba(${n >> 16},${(n >> 8) & 255},${n & 255},${a})`;
};

/** The row `row` (α0 index) of a result as plain arrays, one entry per mode. */
export function resonanceRow(r, row = 0) {
  const nx = r.flap_hz.length;
  const fd = Array.from(r.flap_hz);
  const slice = (a) => Array.from(a.subarray ? a.subarray(row * nx, row * nx + nx) : a.slice(row * nx, row * nx + nx));
  return {
    fd,
    modes: r.modes.map((m) => ({
      freq_hz: m.freq_hz,
      feff: slice(m.effective_freq_hz),
      mod: slice(m.max_modulus),
      beat: slice(m.beat_period_s),
      stable: slice(m.stable).map((s) => !!s),
    })),
  };
}

/** CSV of a resonance map: one row per (α0, f_d), per-mode columns. */
export function resonanceCSV(r, caseLine) {
  const nx = r.flap_hz.length;
  const ny = r.alpha0 ? r.alpha0.length : 1;
  const cols = [];
  if (r.alpha0) {
    const a = [];
    for (let j = 0; j < ny; j++) for (let i = 0; i < nx; i++) a.push(r.alpha0[j]);
    cols.push({ name: 'alpha0', unit: 'rad', values: a });
  }
  const f = [];
  for (let j = 0; j < ny; j++) for (let i = 0; i < nx; i++) f.push(r.flap_hz[i]);
  cols.push({ name: 'flap_freq', unit: 'Hz', values: f });
  r.modes.forEach((m, k) => {
    cols.push({ name: `mode${k + 1}_effective_freq`, unit: 'Hz', values: m.effective_freq_hz });
    cols.push({ name: `mode${k + 1}_max_multiplier_modulus`, unit: '', values: m.max_modulus });
    cols.push({ name: `mode${k + 1}_beat_period`, unit: 's', values: m.beat_period_s });
    cols.push({ name: `mode${k + 1}_stable`, unit: '1 = stable', values: Array.from(m.stable) });
  });
  return toCSV(cols, [caseLine, 'Floquet analysis per flap frequency (wasm resonanceMap); natural frequencies ' + r.modes.map((m, k) => `f${k + 1} = ${m.freq_hz} Hz`).join(', ')]);
}

/** uPlot draw hook: shaded unstable bands (per mode) and labels of the n·f_d lines. */
function bandHook(getRow, labelLines) {
  return (u) => {
    const row = getRow();
    if (!row) return;
    const ctx = u.ctx;
    const { left, top, width, height } = u.bbox;
    const dpr = devicePixelRatio;
    ctx.save();
    ctx.beginPath();
    ctx.rect(left, top, width, height);
    ctx.clip();
    const dx = row.fd.length > 1 ? (row.fd[1] - row.fd[0]) / 2 : 0;
    row.modes.forEach((m, k) => {
      for (const [a, b] of bands(row.fd, m.stable.map((s) => !s))) {
        const x0 = u.valToPos(a - dx, 'x', true);
        const x1 = u.valToPos(b + dx, 'x', true);
        ctx.fillStyle = hexA(MODE_COLORS[k % MODE_COLORS.length], 0.18);
        ctx.fillRect(x0, top, Math.max(x1 - x0, 2 * dpr), height);
        // hatch, so the band does not rely on colour alone
        ctx.strokeStyle = hexA(MODE_COLORS[k % MODE_COLORS.length], 0.55);
        ctx.lineWidth = dpr;
        for (let x = x0 - height; x < x1; x += 8 * dpr) {
          ctx.beginPath();
          ctx.moveTo(Math.max(x, x0), top + height - Math.max(0, x0 - x));
          ctx.lineTo(Math.min(x + height, x1), top + height - Math.min(height, x1 - x));
          ctx.stroke();
        }
      }
    });
    if (labelLines) {
      ctx.fillStyle = '#555';
      ctx.font = `${Math.round(11 * dpr)}px system-ui, sans-serif`;
      ctx.textBaseline = 'bottom';
      const xmax = u.scales.x.max;
      const ymax = u.scales.y.max;
      for (let n = 1; n <= N_LINES; n++) {
        // label where the line leaves the plot (top edge or right edge)
        const xe = Math.min(xmax, ymax / n);
        const px = u.valToPos(xe, 'x', true);
        const py = u.valToPos(n * xe, 'y', true);
        const text = `${n}·f_d`;
        const w = ctx.measureText(text).width;
        ctx.fillText(text, Math.min(px - w - 3 * dpr, left + width - w - 2 * dpr), Math.max(py + 14 * dpr, top + 14 * dpr));
      }
    }
    ctx.restore();
  };
}

function plotSpec(kind, row, height, getRow) {
  const modes = row.modes;
  const isF = kind === 'feff';
  const series = [
    { label: 'f_d (Hz)', value: (u, v) => (v == null ? '—' : `${fmt(v, 4)} Hz`) },
    ...modes.map((m, k) => ({
      label: isF ? `Mode ${k + 1}: f_eff (f${k + 1} = ${fmt(m.freq_hz, 4)} Hz)` : `Mode ${k + 1}: max |λ|`,
      stroke: MODE_COLORS[k % MODE_COLORS.length],
      width: 2,
      points: { show: false },
      value: (u, v) => (v == null ? '—' : isF ? `${fmt(v, 5)} Hz` : fmt(v, 6)),
    })),
  ];
  if (isF) {
    for (let n = 1; n <= N_LINES; n++) {
      series.push({ label: `${n}·f_d`, stroke: '#8a8a8a', width: 1, dash: n === 2 ? [] : [5, 4], points: { show: false }, value: (u, v) => (v == null ? '—' : `${fmt(v, 4)} Hz`) });
    }
  }
  const nm = modes.length;
  // y range from the data shown (recomputed when the α0 row changes)
  const yRange = (u) => {
    const vals = [];
    for (let k = 1; k <= nm; k++) for (const v of u.data[k] || []) if (v != null && Number.isFinite(v)) vals.push(v);
    if (isF) return [0, Math.max(10, ...vals) * 1.15];
    const hi = Math.max(1.0, ...vals);
    const lo = Math.min(1.0, ...vals);
    const pad = Math.max(1e-3, (hi - lo) * 0.08);
    return [lo - pad, hi + pad];
  };
  return {
    width: 600,
    height,
    scales: { x: { time: false }, y: { range: yRange } },
    axes: [
      { label: 'flap frequency f_d (Hz)', stroke: '#333', grid: { stroke: '#e5e5e5' } },
      { label: isF ? 'frequency f (Hz)' : 'largest |Floquet multiplier| (per flap period, –)', stroke: '#333', grid: { stroke: '#e5e5e5' }, size: 64, values: (u, vals) => vals.map((v) => fmt(v, isF ? 3 : 5)) },
    ],
    series,
    cursor: { drag: { x: true, y: false }, points: { show: false } },
    legend: { live: true },
    hooks: { draw: [bandHook(getRow, isF)] },
  };
}

function plotData(kind, row) {
  const x = row.fd;
  if (kind === 'feff') {
    const lines = [];
    for (let n = 1; n <= N_LINES; n++) lines.push(x.map((f) => n * f));
    return [x, ...row.modes.map((m) => m.feff.map((v) => (Number.isFinite(v) ? v : null))), ...lines];
  }
  return [x, ...row.modes.map((m) => m.mod.map((v) => (Number.isFinite(v) ? v : null)))];
}

/**
 * Heat map of the largest |multiplier| over all modes on (f_d, α0), with the f_eff = n·f_d
 * resonance curves of each mode drawn over it and a colour bar. Pixel-exact, DPR-aware.
 */
export function drawResonanceHeatmap(canvas, r) {
  const cssW = canvas.clientWidth || 640;
  const cssH = Math.round(Math.min(420, Math.max(260, cssW * 0.55)));
  const dpr = devicePixelRatio || 1;
  canvas.width = Math.round(cssW * dpr);
  canvas.height = Math.round(cssH * dpr);
  canvas.style.height = `${cssH}px`;
  const ctx = canvas.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.fillStyle = '#fff';
  ctx.fillRect(0, 0, cssW, cssH);
  const L = 64, R = 96, T = 10, B = 44;
  const pw = cssW - L - R;
  const ph = cssH - T - B;
  const nx = r.flap_hz.length;
  const ny = r.alpha0.length;
  const z = new Float64Array(nx * ny);
  for (let i = 0; i < z.length; i++) z[i] = Math.max(...r.modes.map((m) => m.max_modulus[i]));
  let zmin = Infinity, zmax = -Infinity;
  for (const v of z) if (Number.isFinite(v)) { zmin = Math.min(zmin, v); zmax = Math.max(zmax, v); }
  if (!(zmax > zmin)) zmax = zmin + 1e-6;
  const img = ctx.createImageData(nx, ny);
  for (let j = 0; j < ny; j++) {
    for (let i = 0; i < nx; i++) {
      const v = z[j * nx + i];
      const [cr, cg, cb] = Number.isFinite(v) ? viridis((v - zmin) / (zmax - zmin)) : [200, 200, 200];
      const o = ((ny - 1 - j) * nx + i) * 4;
      img.data[o] = cr; img.data[o + 1] = cg; img.data[o + 2] = cb; img.data[o + 3] = 255;
    }
  }
  const tmp = document.createElement('canvas');
  tmp.width = nx;
  tmp.height = ny;
  tmp.getContext('2d').putImageData(img, 0, 0);
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(tmp, L, T, pw, ph);
  const f0 = r.flap_hz[0], f1 = r.flap_hz[nx - 1];
  const a0 = r.alpha0[0], a1 = r.alpha0[ny - 1];
  const X = (f) => L + ((f - f0) / (f1 - f0 || 1)) * pw;
  const Y = (a) => T + ph - ((a - a0) / (a1 - a0 || 1)) * ph;
  // Resonance curves: where each mode's f_eff crosses n·f_d, row by row.
  ctx.save();
  ctx.beginPath();
  ctx.rect(L, T, pw, ph);
  ctx.clip();
  r.modes.forEach((m, k) => {
    const pts = new Map();
    for (let j = 0; j < ny; j++) {
      const feff = Array.from(m.effective_freq_hz.slice(j * nx, j * nx + nx));
      for (const c of resonanceCrossings(Array.from(r.flap_hz), feff, N_LINES)) {
        if (!pts.has(c.n)) pts.set(c.n, []);
        pts.get(c.n).push([c.flap_hz, r.alpha0[j]]);
      }
    }
    ctx.strokeStyle = '#fff';
    ctx.fillStyle = MODE_COLORS[k % MODE_COLORS.length];
    for (const [, list] of pts) {
      for (const [f, a] of list) {
        ctx.beginPath();
        ctx.arc(X(f), Y(a), 2.5, 0, 2 * Math.PI);
        ctx.fill();
        ctx.lineWidth = 0.8;
        ctx.stroke();
      }
    }
  });
  ctx.restore();
  ctx.strokeStyle = '#333';
  ctx.lineWidth = 1;
  ctx.strokeRect(L, T, pw, ph);
  ctx.fillStyle = '#222';
  ctx.font = '11px system-ui, sans-serif';
  ctx.textAlign = 'center';
  for (let k = 0; k <= 5; k++) {
    const f = f0 + ((f1 - f0) * k) / 5;
    ctx.fillText(fmt(f, 3), X(f), T + ph + 14);
  }
  ctx.textAlign = 'right';
  for (let k = 0; k <= 4; k++) {
    const a = a0 + ((a1 - a0) * k) / 4;
    ctx.fillText(fmt(a, 3), L - 4, Y(a) + 4);
  }
  ctx.textAlign = 'center';
  ctx.fillText('flap frequency f_d (Hz)', L + pw / 2, cssH - 10);
  ctx.save();
  ctx.translate(14, T + ph / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.fillText('roll amplitude α0 (rad)', 0, 0);
  ctx.restore();
  const cx = cssW - R + 14;
  for (let y = 0; y < ph; y++) {
    const [cr, cg, cb] = viridis(1 - y / ph);
    ctx.fillStyle = `rgb(${cr},${cg},${cb})`;
    ctx.fillRect(cx, T + y, 14, 1);
  }
  ctx.strokeRect(cx, T, 14, ph);
  ctx.fillStyle = '#222';
  ctx.textAlign = 'left';
  ctx.fillText(fmt(zmax, 5), cx + 18, T + 9);
  ctx.fillText(fmt(zmin, 5), cx + 18, T + ph);
  ctx.save();
  ctx.translate(cssW - 8, T + ph / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.fillText('largest |multiplier| (–)', 0, 0);
  ctx.restore();
  return { zmin, zmax };
}

/** The text alternative: a sentence and a table (per mode: unstable bands, largest |λ|, resonances). */
function summaryTable(sum, caption) {
  const t = el('table', { class: 'wl-numtable wl-res-table' });
  t.append(el('caption', { class: 'wl-note', text: caption }));
  t.append(el('thead', {}, el('tr', {}, ...['Mode', 'Unstable f_d bands (Hz)', 'Largest |λ| (at f_d)', 'f_eff = n·f_d at f_d (Hz)'].map((h) => el('th', { scope: 'col', text: h })))));
  const tb = el('tbody');
  for (const m of sum.modes) {
    tb.append(el('tr', {},
      el('th', { scope: 'row', text: `${m.mode} (f = ${fmt(m.freq_hz, 4)} Hz)` }),
      el('td', { text: m.unstable.length ? m.unstable.map(([a, b]) => (a === b ? fmt(a, 4) : `${fmt(a, 4)}–${fmt(b, 4)}`)).join(', ') : 'none' }),
      el('td', { text: `${fmt(m.max_modulus, 6)} (${fmt(m.max_at_hz, 4)} Hz)` }),
      el('td', { text: m.resonances.length ? m.resonances.map((c) => `${fmt(c.flap_hz, 4)} (n = ${c.n})`).join(', ') : 'none' }),
    ));
  }
  t.append(tb);
  return t;
}

/**
 * Mounts the resonance-map study in `box` (an element). host:
 *   run(cfg, opts, onProgress(done, total)) → { promise, cancel }   the engine's worker job
 *   config() → the current SimConfig;  caseLine() → the CSV's parameter comment
 *   state() → the lab state (for the default α0 range)
 *   onResult?(r)                                    called after each finished map
 * Returns { box, run(opts?), data() }.
 */
export function mountResonance(box, host) {
  box.classList.add('wl-study', 'wl-resonance');
  box.dataset.study = 'resonance';
  const uid = `res${Math.random().toString(36).slice(2, 8)}`;
  const title = 'Resonance map: f_eff and stability vs flap frequency';
  const head = el('div', { class: 'wl-head' }, el('h3', { id: `${uid}-h`, text: title }));
  const csvBtn = el('button', { type: 'button', text: 'CSV', 'data-export': 'csv', 'data-target': 'resonance', 'aria-label': `Export ${title} as CSV` });
  head.append(el('span', { class: 'wl-export' }, csvBtn));
  const num = (label, value, min, max, step, unit) => {
    const i = el('input', { type: 'number', value, min, max, step, 'aria-label': `${label}${unit ? ` (${unit})` : ''}` });
    return [el('label', { class: 'wl-inline' }, `${label}${unit ? ` (${unit})` : ''} `, i), i];
  };
  const [lf, from] = num('f_d from', 5, 0.1, 200, 'any', 'Hz');
  const [lt, to] = num('to', 60, 0.1, 200, 'any', 'Hz');
  const [ln, pts] = num('points', 221, 2, 2001, 1, '');
  const two = el('input', { type: 'checkbox', id: `${uid}-2d` });
  const l2 = el('label', { class: 'wl-inline', for: `${uid}-2d` }, two, ' α0 as a second axis');
  const [la0, a0from] = num('α0 from', 0.2, 0, 1.5, 0.05, 'rad');
  const [la1, a0to] = num('α0 to', 1.2, 0, 1.5, 0.05, 'rad');
  const [lan, a0n] = num('α0 values', 21, 2, 101, 1, '');
  const axis2 = el('span', { class: 'wl-res-axis2', hidden: true }, la0, la1, lan);
  two.addEventListener('change', () => { axis2.hidden = !two.checked; });
  const runBtn = el('button', { type: 'button', class: 'wl-run', text: 'Run', 'data-run': 'resonance' });
  const cancelBtn = el('button', { type: 'button', class: 'wl-cancel', text: 'Cancel', 'data-cancel': 'resonance', hidden: true });
  const prog = el('progress', { class: 'wl-progress', max: 1, value: 0, hidden: true, 'aria-label': `${title} progress` });
  const status = el('span', { class: 'wl-status', role: 'status' });
  const note = el('p', { class: 'wl-note', text: 'Floquet analysis of Eq. 13 at each flap frequency (no time series): the effective natural frequency f_eff of each mode, and the largest |multiplier| of the monodromy matrix over one flap period (> 1: the mode grows without bound — a parametric instability). Where f_eff meets a line n·f_d the flapping drives the mode at resonance and the beat period 1/|f_eff − n·f_d| becomes infinite. Hatched bands: unstable. The other parameters are the current ones.' });
  const out = el('div', { class: 'wl-study-out' });
  box.replaceChildren(head, el('div', { class: 'wl-study-controls' }, lf, lt, ln, l2, axis2, runBtn, cancelBtn, prog, status), note, out);

  let result = null;
  let current = null;
  let plots = [];
  let ro = null;
  let rowIndex = 0;

  const clearPlots = () => {
    for (const u of plots) u.destroy();
    plots = [];
    if (ro) ro.disconnect();
    ro = null;
  };

  function draw(r) {
    clearPlots();
    out.replaceChildren();
    const sumBox = el('div', { class: 'wl-res-summary' });
    if (r.alpha0) {
      const canvas = el('canvas', { class: 'wl-heatmap wl-res-heatmap', role: 'img', 'aria-label': `Heat map of the largest Floquet multiplier modulus over flap frequency ${fmt(r.flap_hz[0], 3)}–${fmt(r.flap_hz[r.flap_hz.length - 1], 3)} Hz and roll amplitude α0 ${fmt(r.alpha0[0], 3)}–${fmt(r.alpha0[r.alpha0.length - 1], 3)} rad; dots mark f_eff = n·f_d; the table below gives the numbers per α0 row.` });
      canvas.style.width = '100%';
      out.append(canvas);
      const rowSel = el('select', { 'aria-label': 'α0 row shown in the curves below' });
      r.alpha0.forEach((a, j) => rowSel.append(el('option', { value: String(j), text: `α0 = ${fmt(a, 4)} rad` })));
      const state = host.state ? host.state() : null;
      let best = 0;
      if (state) r.alpha0.forEach((a, j) => { if (Math.abs(a - state.alpha0) < Math.abs(r.alpha0[best] - state.alpha0)) best = j; });
      rowSel.value = String(best);
      rowIndex = best;
      rowSel.addEventListener('change', () => { rowIndex = Number(rowSel.value); drawRows(r, sumBox); });
      out.append(el('label', { class: 'wl-inline' }, 'Curves for ', rowSel));
      requestAnimationFrame(() => drawResonanceHeatmap(canvas, r));
      const ro2 = new ResizeObserver(() => drawResonanceHeatmap(canvas, r));
      ro2.observe(canvas);
      plots.push({ destroy: () => ro2.disconnect() });
    } else {
      rowIndex = 0;
    }
    const fBox = el('div', { class: 'wl-plot', 'data-plot': 'resonance-feff', role: 'img', 'aria-label': 'Effective frequency of each mode against flap frequency, with the lines n·f_d; summary in the table below' });
    const mBox = el('div', { class: 'wl-plot', 'data-plot': 'resonance-modulus', role: 'img', 'aria-label': 'Largest Floquet multiplier modulus of each mode against flap frequency; summary in the table below' });
    out.append(fBox, mBox, sumBox);
    const row = resonanceRow(r, rowIndex);
    const getRow = () => resonanceRow(r, rowIndex);
    const fu = new uPlot(plotSpec('feff', row, 260, getRow), plotData('feff', row), fBox);
    const mu = new uPlot(plotSpec('mod', row, 180, getRow), plotData('mod', row), mBox);
    plots.push(fu, mu);
    const resize = () => {
      const w = Math.max(280, fBox.clientWidth);
      for (const u of [fu, mu]) if (Math.abs(u.width - w) > 2) u.setSize({ width: w, height: u.height });
    };
    ro = new ResizeObserver(resize);
    ro.observe(fBox);
    resize();
    drawRows(r, sumBox);
  }

  function drawRows(r, sumBox) {
    const row = resonanceRow(r, rowIndex);
    for (const u of plots) {
      if (u.data && u.series) {
        const kind = u.series.length > r.modes.length + 1 ? 'feff' : 'mod';
        u.setData(plotData(kind, row));
      }
    }
    const sum = resonanceSummary(r, rowIndex);
    const which = r.alpha0 ? ` (α0 = ${fmt(r.alpha0[rowIndex], 4)} rad)` : '';
    sumBox.replaceChildren(
      el('p', { class: 'wl-res-sentence', 'data-summary': 'resonance', text: sum.sentence.replace('Resonance map,', `Resonance map${which},`) }),
      summaryTable(sum, `Where each mode is unstable and where f_eff meets n·f_d${which}`),
    );
  }

  function start(opts) {
    if (current) return current.promise;
    const o = opts || {
      from_hz: Number(from.value),
      to_hz: Number(to.value),
      points: Math.round(Number(pts.value)),
    };
    if (!opts && two.checked) {
      const n = Math.max(2, Math.round(Number(a0n.value)));
      const lo = Number(a0from.value);
      const hi = Number(a0to.value);
      o.alpha0_values = Array.from({ length: n }, (_, j) => lo + ((hi - lo) * j) / (n - 1));
    }
    runBtn.disabled = true;
    cancelBtn.hidden = false;
    prog.hidden = false;
    prog.removeAttribute('value');
    status.textContent = 'computing…';
    const t0 = performance.now();
    const job = host.run(host.config(), o, (done, total) => {
      prog.max = total;
      prog.value = done;
      status.textContent = `${done} / ${total}`;
    });
    const finish = () => {
      current = null;
      runBtn.disabled = false;
      cancelBtn.hidden = true;
      prog.hidden = true;
    };
    current = {
      cancel: job.cancel,
      promise: job.promise.then(
        (r) => {
          finish();
          result = r;
          draw(r);
          const cells = r.flap_hz.length * (r.alpha0 ? r.alpha0.length : 1);
          status.textContent = `${cells} Floquet analyses × ${r.modes.length} modes in ${(performance.now() - t0).toFixed(0)} ms (worker)`;
          box.dataset.done = String(Number(box.dataset.done || 0) + 1);
          if (host.onResult) host.onResult(r);
          return r;
        },
        (e) => {
          finish();
          const msg = String(e && e.message ? e.message : e);
          status.textContent = /cancel/i.test(msg) ? 'Cancelled.' : `Error: ${msg}`;
          return null;
        },
      ),
    };
    return current.promise;
  }

  runBtn.addEventListener('click', () => start());
  cancelBtn.addEventListener('click', () => { if (current) current.cancel(); });
  csvBtn.addEventListener('click', () => {
    if (!result) {
      status.textContent = 'Nothing to export yet: run the map first.';
      return;
    }
    download('wingbeat-resonance.csv', new Blob([resonanceCSV(result, host.caseLine())], { type: 'text/csv' }));
  });
  return { box, run: start, data: () => result, cancel: () => current && current.cancel() };
}
