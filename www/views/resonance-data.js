// @ts-check
// The resonance map's data shaping, pure (no DOM): one α0 row of a result as plain arrays, the
// CSV of a whole map, and what the heat map draws (the largest |multiplier| over all modes per
// cell and its range; the f_eff = n·f_d crossings of each mode, row by row). The panel is
// views/resonance.js; the heat map's painting is views/resonance-heatmap.js.
import { toCSV } from '../export.js';
import { resonanceCrossings } from '../experiments.js';

/** One colour per mode (cycled), shared by the curves, the bands and the heat map's dots. */
export const MODE_COLORS = ['#1f5fbf', '#c2410c', '#2e7d32', '#7b1fa2'];
/** How many lines f = n·f_d are drawn and searched for crossings (n = 1…N_LINES). */
export const N_LINES = 4;

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
  return toCSV(cols, [
    caseLine,
    'Floquet analysis per flap frequency (wasm resonanceMap); natural frequencies ' +
      r.modes.map((m, k) => `f${k + 1} = ${m.freq_hz} Hz`).join(', '),
  ]);
}

/**
 * The heat map's values: per (α0, f_d) cell (row-major, α0 rows) the largest |multiplier| over
 * all modes, and the range of the finite ones (widened to 1e-6 when flat or empty).
 */
export function heatmapField(r) {
  const nx = r.flap_hz.length;
  const ny = r.alpha0.length;
  const z = new Float64Array(nx * ny);
  for (let i = 0; i < z.length; i++) z[i] = Math.max(...r.modes.map((m) => m.max_modulus[i]));
  let zmin = Infinity,
    zmax = -Infinity;
  for (const v of z)
    if (Number.isFinite(v)) {
      zmin = Math.min(zmin, v);
      zmax = Math.max(zmax, v);
    }
  if (!(zmax > zmin)) zmax = zmin + 1e-6;
  return { z, zmin, zmax };
}

/**
 * Where each mode's f_eff crosses n·f_d (n = 1…N_LINES), row by row: one entry per mode, a list
 * per n (in the order first met) of [f_d, α0] points.
 * @returns {Array<Array<{ n: number, points: Array<[number, number]> }>>}
 */
export function heatmapCrossings(r) {
  const nx = r.flap_hz.length;
  const ny = r.alpha0.length;
  return r.modes.map((m) => {
    /** @type {Map<number, Array<[number, number]>>} */
    const pts = new Map();
    for (let j = 0; j < ny; j++) {
      const feff = Array.from(m.effective_freq_hz.slice(j * nx, j * nx + nx));
      const st = Array.from(m.stable.slice(j * nx, j * nx + nx)).map(Boolean);
      for (const c of resonanceCrossings(Array.from(r.flap_hz), feff, N_LINES, st)) {
        if (!pts.has(c.n)) pts.set(c.n, []);
        pts.get(c.n)?.push([c.flap_hz, r.alpha0[j]]);
      }
    }
    return [...pts].map(([n, points]) => ({ n, points }));
  });
}
