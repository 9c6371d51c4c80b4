// @ts-check
// The studies panel's data as CSV columns (www/export.js toCSV), from the worker's results: the
// force-term shares against a parameter (Fig. 6), the initial-condition map flattened row by row
// (Fig. 7), and the damped and undamped responses (Fig. 8). Pure; used by views/studies.js and
// unit-tested in tests/js/studies_data.test.mjs.
import { UNITS } from '../format.js';

/** @typedef {{ name: string, unit: string, values: ArrayLike<number> }} Column */

/**
 * The sweep's columns: the parameter, mode k's three shares, f_eff and the beat period.
 * @param {{ values: ArrayLike<number>, modes: { euler: ArrayLike<number>, centrifugal: ArrayLike<number>,
 *   coriolis: ArrayLike<number>, effective_freq_hz: ArrayLike<number>, beat_period_s: ArrayLike<number> }[] }} r
 * @param {number} k 0-based mode
 * @param {string} param the parameter swept (www/state.js key)
 * @param {string} unit its unit
 * @returns {Column[]}
 */
export function sweepColumns(r, k, param, unit) {
  const m = r.modes[k];
  return [
    { name: param, unit, values: r.values },
    { name: 'euler_share', unit: '%', values: m.euler },
    { name: 'centrifugal_share', unit: '%', values: m.centrifugal },
    { name: 'coriolis_share', unit: '%', values: m.coriolis },
    { name: 'effective_freq', unit: 'Hz', values: m.effective_freq_hz },
    { name: 'beat_period', unit: 's', values: m.beat_period_s },
  ];
}

/**
 * The initial-condition map as three columns, one row per cell (q̇0 outer, q0 inner), from its
 * row-major grid `coriolis_percent[j * n_q + i]`.
 * @param {{ n_q: number, n_qdot: number, q0: ArrayLike<number>, qdot0: ArrayLike<number>, coriolis_percent: ArrayLike<number> }} r
 * @returns {Column[]}
 */
export function icmapColumns(r) {
  const q0 = [],
    qd = [],
    z = [];
  for (let j = 0; j < r.n_qdot; j++)
    for (let i = 0; i < r.n_q; i++) {
      q0.push(r.q0[i]);
      qd.push(r.qdot0[j]);
      z.push(r.coriolis_percent[j * r.n_q + i]);
    }
  return [
    { name: 'q0', unit: UNITS.q.csv, values: q0 },
    { name: 'qdot0', unit: `${UNITS.q.csv}/s`, values: qd },
    { name: 'coriolis_share', unit: '%', values: z },
  ];
}

/**
 * The damping study's columns: time, the undamped and the damped total response.
 * @param {{ t: ArrayLike<number>, undamped: ArrayLike<number>, damped: ArrayLike<number>, zeta: number }} r
 * @returns {Column[]}
 */
export function dampingColumns(r) {
  return [
    { name: 't', unit: 's', values: r.t },
    { name: 'q_total_zeta0', unit: UNITS.q.csv, values: r.undamped },
    { name: `q_total_zeta${r.zeta}`, unit: UNITS.q.csv, values: r.damped },
  ];
}
