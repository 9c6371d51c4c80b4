// The guided experiment of sensing as the published studies measure it
// (www/experiments/neural.js): its prediction on a hand-made report (the numbers it reads and
// where), and on the REAL wasm (www/pkg): the study's request through classifyRotation, every
// check holding. Run: node --test tests/js/experiments_neural.test.mjs (after build-web.sh www).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { NEURAL_EXPERIMENTS, NEURAL_REQUEST, bestSparse } from '../../www/experiments/neural.js';
import { predict } from '../../www/experiments.js';
import { EXPERIMENT_SCREEN } from '../../www/screens.js';
import { loadReal } from './real_wasm.mjs';

const curves = (all, one, ten, sparse) => ({
  all_sensors: all,
  s0: 1e-4,
  random: [
    { sensors: 1, mean: one, sd: 0.01, failed_fits: 0 },
    { sensors: 10, mean: ten, sd: 0.05, failed_fits: 0 },
  ],
  sparse,
});

test('the prediction reads the report: encoded vs raw, one and ten random sensors, the best small SSPOC set', () => {
  const sparse = [
    { kept_modes: 5, sensors: [1, 2, 3], accuracy: 0.7 },
    { kept_modes: 10, sensors: Array.from({ length: 12 }, (_, i) => i), accuracy: 0.83 },
    { kept_modes: 20, sensors: Array.from({ length: 30 }, (_, i) => i), accuracy: 0.95 },
  ];
  assert.equal(bestSparse({ sparse }, 15).accuracy, 0.83, 'the 30-sensor set is too large');
  const study = {
    modes: [{ freq_hz: 13.5, zeta: 0.37, kind: 'spanwise bending' }],
    report: {
      test_samples: 300,
      sensors: new Array(338),
      encoded: curves(0.97, 0.5, 0.6, sparse),
      raw: curves(0.49, 0.5, 0.49, []),
    },
  };
  const p = predict('neural-sensing', {}, { study });
  const holds = Object.fromEntries(p.checks.map((c) => [c.id, c.holds]));
  assert.deepEqual(holds, { 'raw-cannot': true, 'encoding-can': true, 'one-sensor-chance': true });
  assert.equal(p.values.sparse_best, 0.83);
  assert.match(p.lines.join(' '), /97 %.*49 %/);
  // Raw strain that separates, or encoding that does not help, fails the checks.
  study.report.raw = curves(0.9, 0.5, 0.6, []);
  const q = predict('neural-sensing', {}, { study });
  assert.deepEqual(
    q.checks.filter((c) => !c.holds).map((c) => c.id),
    ['raw-cannot', 'encoding-can'],
  );
  // Before the study: says so, no checks.
  assert.equal(predict('neural-sensing', {}, {}).checks.length, 0);
  assert.equal(EXPERIMENT_SCREEN['neural-sensing'], 'sensing');
});

test('on the real wasm the study request computes and every check holds', async () => {
  const wb = await loadReal();
  const seen = [];
  const r = wb.classifyRotation(structuredClone(NEURAL_REQUEST), (d, t) => seen.push([d, t]));
  assert.deepEqual(seen.at(-1), [6, 6]);
  assert.equal(r.report.sensors.length, 26 * 13);
  const p = NEURAL_EXPERIMENTS[0].predict({}, { study: r });
  for (const c of p.checks) assert.ok(c.holds, `${c.id}: ${c.label}`);
  assert.ok(p.values.encoded_all > 0.9, String(p.values.encoded_all));
  assert.throws(() => wb.classifyRotation({ grid_step_mm: 0 }), /request\.grid_step_mm/);
});
