// The studies panel's CSV columns (www/views/studies-data.js): the sweep's columns for the mode
// asked for, the initial-condition map flattened q̇0-outer / q0-inner from its row-major grid, the
// damping study's columns named after its ζ. Run: node --test tests/js/studies_data.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { sweepColumns, icmapColumns, dampingColumns } from '../../www/views/studies-data.js';
import { UNITS } from '../../www/format.js';

const mode = (base) => ({
  euler: [base, base + 1],
  centrifugal: [base + 2, base + 3],
  coriolis: [base + 4, base + 5],
  effective_freq_hz: [base + 6, base + 7],
  beat_period_s: [base + 8, base + 9],
});

test('sweepColumns: the parameter, then the shares, f_eff and beat period of mode k (not another mode)', () => {
  const r = { values: [0.1, 0.2], modes: [mode(0), mode(100)] };
  const cols = sweepColumns(r, 1, 'gamma0', 'rad');
  assert.deepEqual(
    cols.map((c) => [c.name, c.unit]),
    [
      ['gamma0', 'rad'],
      ['euler_share', '%'],
      ['centrifugal_share', '%'],
      ['coriolis_share', '%'],
      ['effective_freq', 'Hz'],
      ['beat_period', 's'],
    ],
  );
  assert.deepEqual(
    cols.map((c) => Array.from(c.values)),
    [
      [0.1, 0.2],
      [100, 101],
      [102, 103],
      [104, 105],
      [106, 107],
      [108, 109],
    ],
  );
});

test('icmapColumns: one row per cell, q0 varying fastest, z taken from [j * n_q + i]', () => {
  // 3 values of q0 × 2 of q̇0; z = 10·j + i so each cell names its own place.
  const r = { n_q: 3, n_qdot: 2, q0: [-1, 0, 1], qdot0: [-5, 5], coriolis_percent: [0, 1, 2, 10, 11, 12] };
  const [q0, qd, z] = icmapColumns(r);
  assert.deepEqual([q0.name, qd.name, z.name], ['q0', 'qdot0', 'coriolis_share']);
  assert.deepEqual([q0.unit, qd.unit, z.unit], [UNITS.q.csv, `${UNITS.q.csv}/s`, '%']);
  assert.deepEqual(q0.values, [-1, 0, 1, -1, 0, 1]);
  assert.deepEqual(qd.values, [-5, -5, -5, 5, 5, 5]);
  assert.deepEqual(z.values, [0, 1, 2, 10, 11, 12]);
});

test('dampingColumns: time, undamped and damped, the last named after ζ', () => {
  const r = { t: [0, 1], undamped: [2, 3], damped: [4, 5], zeta: 0.02 };
  const cols = dampingColumns(r);
  assert.deepEqual(
    cols.map((c) => [c.name, c.unit, c.values]),
    [
      ['t', 's', [0, 1]],
      ['q_total_zeta0', UNITS.q.csv, [2, 3]],
      ['q_total_zeta0.02', UNITS.q.csv, [4, 5]],
    ],
  );
});
