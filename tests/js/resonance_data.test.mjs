// The resonance map's pure data shaping (www/views/resonance-data.js): one α0 row as plain
// arrays, the CSV of a map, the heat map's values and its f_eff = n·f_d crossing dots.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { resonanceRow, resonanceCSV, heatmapField, heatmapCrossings, N_LINES } from '../../www/views/resonance-data.js';

// A 2 (α0) × 3 (f_d) map with two modes, laid out as the wasm returns it (row-major, α0 rows).
function map() {
  return {
    flap_hz: Float64Array.from([10, 20, 30]),
    alpha0: Float64Array.from([0.5, 0.8]),
    modes: [
      {
        freq_hz: 25,
        // row 0: f_eff - f_d = 5, -5, -15 → crosses n = 1 at f_d = 15; row 1: above 4·f_d throughout
        effective_freq_hz: Float64Array.from([15, 15, 15, 200, 210, 220]),
        max_modulus: Float64Array.from([1, 1.2, 1, 1, NaN, 1.5]),
        beat_period_s: Float64Array.from([0.1, 0.2, 0.3, 0.4, 0.5, 0.6]),
        stable: Uint8Array.from([1, 1, 1, 1, 1, 0]),
      },
      {
        freq_hz: 70,
        effective_freq_hz: Float64Array.from([70, 70, 70, 70, 70, 70]),
        max_modulus: Float64Array.from([1.1, 1, 1, 2, 1, 1]),
        beat_period_s: Float64Array.from([1, 1, 1, 1, 1, 1]),
        stable: Uint8Array.from([1, 1, 1, 1, 1, 1]),
      },
    ],
  };
}

test('resonanceRow takes the chosen α0 row of every mode as plain arrays, stable as booleans', () => {
  const row = resonanceRow(map(), 1);
  assert.deepEqual(row.fd, [10, 20, 30]);
  assert.equal(row.modes.length, 2);
  assert.deepEqual(row.modes[0].feff, [200, 210, 220]);
  assert.deepEqual(row.modes[0].beat, [0.4, 0.5, 0.6]);
  assert.deepEqual(row.modes[0].stable, [true, true, false]);
  assert.equal(row.modes[1].freq_hz, 70);
  assert.deepEqual(resonanceRow(map()).modes[0].feff, [15, 15, 15], 'row 0 by default');
});

test('resonanceCSV writes one row per (α0, f_d) with per-mode columns and the case as a comment', () => {
  const lines = resonanceCSV(map(), 'case line').trim().split('\n');
  assert.equal(lines[0], '# case line');
  assert.match(lines[1], /f1 = 25 Hz, f2 = 70 Hz/);
  const head = lines[2].split(',');
  assert.deepEqual(head.slice(0, 3), ['alpha0 (rad)', 'flap_freq (Hz)', 'mode1_effective_freq (Hz)']);
  assert.equal(head.length, 2 + 4 * 2);
  assert.equal(lines.length, 3 + 6);
  assert.deepEqual(lines[3 + 4].split(',').slice(0, 4), ['0.8', '20', '210', ''], 'NaN |λ| left empty');
  const oneRow = { ...map(), alpha0: undefined };
  assert.ok(resonanceCSV(oneRow, 'c').split('\n')[2].startsWith('flap_freq (Hz)'), 'no α0 column without α0');
});

test('heatmapField is the largest |λ| over modes per cell, its range over the finite cells', () => {
  const { z, zmin, zmax } = heatmapField(map());
  assert.deepEqual(Array.from(z.slice(0, 4)), [1.1, 1.2, 1, 2]);
  assert.ok(Number.isNaN(z[4]), 'a NaN in any mode makes the cell NaN');
  assert.equal(zmin, 1);
  assert.equal(zmax, 2);
  const flat = map();
  for (const m of flat.modes) m.max_modulus.fill(1);
  const f = heatmapField(flat);
  assert.equal(f.zmin, 1);
  assert.equal(f.zmax, 1 + 1e-6, 'a flat field gets a tiny range, not a zero one');
});

test('heatmapCrossings marks each mode’s f_eff = n·f_d points with their α0', () => {
  const [m1, m2] = heatmapCrossings(map());
  assert.deepEqual(m1, [{ n: 1, points: [[15, 0.5]] }]);
  // mode 2: f_eff = 70 crosses 3·f_d at 23.3 Hz in both rows, 4·f_d at 17.5 Hz
  assert.deepEqual(
    m2.map((c) => c.n),
    [4, 3],
    'in the order first met along f_d',
  );
  assert.equal(m2[1].points.length, 2);
  assert.ok(Math.abs(m2[1].points[0][0] - 70 / 3) < 1e-12);
  assert.deepEqual(
    m2[1].points.map((p) => p[1]),
    [0.5, 0.8],
  );
  assert.ok(m2.every((c) => c.n <= N_LINES));
});
