// The "As a neuron sees it" panel's numbers (www/views/neural-data.js) on a hand-made report,
// and the page's study cache (www/lab/study-cache.js) that it shares with the guided
// experiment: one run for both askers, progress and results told to every listener, its own
// Cancel kept until asked again, a cancel from outside forgotten so the next ask reruns.
// Run: node --test tests/js/neural_panel.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  curveColumns,
  comparisonRows,
  setChoices,
  setOf,
  sensorWords,
  neuralWords,
} from '../../www/views/neural-data.js';
import { study, peekStudy, watchStudy, cancelStudy, studyKey } from '../../www/lab/study-cache.js';
import { NEURAL_STUDY, NEURAL_REQUEST } from '../../www/experiments/neural.js';

const curves = {
  all_sensors: 0.965,
  s0: 3e-4,
  random: [
    { sensors: 1, mean: 0.5, sd: 0.01, failed_fits: 0 },
    { sensors: 5, mean: 0.55, sd: 0.04, failed_fits: 0 },
    { sensors: 30, mean: 0.9, sd: 0.2, failed_fits: 0 },
  ],
  sparse: [
    { kept_modes: 5, sensors: [4, 2, 9], accuracy: 0.7 },
    { kept_modes: 10, sensors: [1, 2, 3], accuracy: 0.8 },
    { kept_modes: 15, sensors: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11], accuracy: 0.85 },
  ],
  greedy: [
    { sensors: [7], d_prime: 0.1, accuracy: 0.52 },
    { sensors: [7, 3, 8, 1, 0], d_prime: 1.2, accuracy: 0.75 },
  ],
};

test('the curve columns: x the sizes with a point, random mean ± sd, the best SSPOC set per size, all sensors, the published points', () => {
  const [x, mean, hi, lo, sparse, all, pub, greedy] = curveColumns(curves, true);
  assert.deepEqual(
    x,
    [1, 3, 5, 10, 11, 20, 30],
    'random sizes, SSPOC sizes (3, 11), greedy (1, 5) and the published 10, 20, 30',
  );
  assert.deepEqual(greedy, [52, null, 75, null, null, null, null]);
  assert.deepEqual(mean, [50, null, 55, null, null, null, 90]);
  assert.deepEqual(hi, [51, null, 59, null, null, null, 100], 'mean + sd, capped at 100 %');
  assert.deepEqual(lo, [49, null, 51, null, null, null, 70]);
  assert.deepEqual(sparse, [null, 80, null, null, 85, null, null], 'two 3-sensor sets: the better one');
  assert.ok(all.every((v) => v === 96.5));
  assert.deepEqual(pub, [null, null, null, 63.1, null, 81.4, 88.9]);
  const raw = curveColumns(curves, false);
  assert.deepEqual(raw[0], [1, 3, 5, 11, 30], 'no published points for raw strain');
  assert.ok(raw[6].every((v) => v === null));
});

test('the comparison rows and the set chooser say the report’s numbers', () => {
  const rep = {
    encoded: curves,
    raw: { ...curves, all_sensors: 0.49 },
    sensors: Array.from({ length: 338 }, (_, i) => [i % 26, 0]),
  };
  const rows = comparisonRows(rep);
  assert.deepEqual(rows[0].slice(0, 3), ['all 338 sensors', '96.5 %', '49.0 %']);
  assert.match(rows[0][3], /90\.0 % encoded, 48\.8 % raw/);
  assert.deepEqual(rows[1].slice(0, 2), ['1 random sensor (mean)', '50.0 %']);
  assert.equal(rows[2][1], '—', 'no 10-sensor random point in this report');
  assert.equal(rows[2][3], '63.1 %');
  assert.deepEqual(rows[4].slice(0, 2), ['greedy d′ set of 10 sensors', '—'], 'no 10-sensor greedy set here');
  assert.equal(rows[5][1], '85.0 % (11 sensors)', 'best SSPOC set of at most 15 sensors');
  const choices = setChoices(curves);
  assert.deepEqual(
    choices.map((c) => c.text),
    [
      'SSPOC, 5 modes kept: 3 sensors, 70.0 %',
      'SSPOC, 10 modes kept: 3 sensors, 80.0 %',
      'SSPOC, 15 modes kept: 11 sensors, 85.0 %',
      'greedy d′: 1 sensor, 52.0 %',
      'greedy d′: 5 sensors, 75.0 %',
    ],
  );
  assert.deepEqual(setOf(curves, choices[4].value).sensors, [7, 3, 8, 1, 0]);
  assert.equal(setOf(curves, choices[1].value).accuracy, 0.8);
  assert.equal(setOf(curves, 'nonsense:1'), null);
  const pos = [
    [0, 0],
    [4, -2],
    [50, -24],
  ];
  assert.equal(
    sensorWords([2, 1], pos),
    '2 sensors; nearest the root at x = 4 mm, farthest at x = 50 mm; 1 within 10 mm of the root',
  );
  assert.equal(sensorWords([], pos), 'no sensors');
  // The words follow the numbers: 85 % with 11 sensors beats random 5 (55 ± 4 %), below 96.5 %.
  assert.equal(
    neuralWords(rep, 'encoded'),
    'Encoded, all 338 sensors tell turning from still in 96.5 % of the test samples; random sets climb with their size. The best SSPOC set of at most 15 sensors (11 sensors, 85.0 %) does better than random sets of 5 (55.0 %), but falls short of all sensors, where in the paper about 10 SSPOC sensors came close to them (docs/sensing.md says what we know of why).',
  );
  const close = { ...rep, encoded: { ...curves, all_sensors: 0.86 } };
  assert.match(neuralWords(close, 'encoded'), /and as well as all sensors, as in the paper\.$/);
  assert.match(neuralWords(rep, 'raw'), /^Raw strain: 49\.0 % with all 338 sensors — chance\./);
});

/** A fake engine whose jobs end when the test says. */
function fakeEngine() {
  const jobs = [];
  return {
    jobs,
    run(kind, payload, onProgress) {
      let resolve;
      let reject;
      const promise = new Promise((a, b) => {
        resolve = a;
        reject = b;
      });
      const job = { id: jobs.length + 1, kind, payload, onProgress, resolve, reject, cancelled: false };
      jobs.push(job);
      return { id: job.id, promise };
    },
    cancel(id) {
      const j = jobs.find((x) => x.id === id);
      j.cancelled = true;
      j.reject(new Error('cancelled'));
    },
  };
}

const tick = () => new Promise((r) => setTimeout(r, 0));

test('the study cache runs a study once for every asker and tells each listener', async () => {
  const engine = fakeEngine();
  const key = studyKey(NEURAL_STUDY.kind, { ...NEURAL_REQUEST });
  assert.equal(
    key,
    studyKey('classify', NEURAL_REQUEST, { any: 'config' }),
    'the lab config is not part of the classification key',
  );
  assert.notEqual(studyKey('sweep', { a: 1 }, { b: 1 }), studyKey('sweep', { a: 1 }, { b: 2 }));
  let calls = 0;
  const unwatch = watchStudy(key, () => calls++);
  assert.equal(peekStudy(key), null, 'watching starts nothing');
  const a = study(engine, 'classify', { opts: NEURAL_REQUEST }, key);
  const b = study(engine, 'classify', { cfg: {}, opts: NEURAL_REQUEST }, key);
  assert.equal(a, b);
  assert.equal(engine.jobs.length, 1, 'one run for both');
  engine.jobs[0].onProgress(2, 6);
  assert.deepEqual([a.done, a.total], [2, 6]);
  engine.jobs[0].resolve({ result: { report: 'r' }, ms: 5 });
  await tick();
  assert.deepEqual(peekStudy(key).result, { report: 'r' });
  assert.ok(calls >= 3, `listener told of start, progress and result (${calls})`);
  unwatch();
});

test('its own Cancel stays until asked again; a cancel from outside reruns on the next ask', async () => {
  const engine = fakeEngine();
  const key = 'classify|cancel-test';
  const e = study(engine, 'classify', {}, key);
  cancelStudy(engine, key);
  await tick();
  assert.ok(e.cancelled && !e.result && !e.error, 'cancelled, no error shown');
  assert.equal(study(engine, 'classify', {}, key), e, 'not restarted by a plain ask');
  assert.equal(engine.jobs.length, 1);
  const again = study(engine, 'classify', {}, key, { restart: true });
  assert.notEqual(again, e);
  assert.equal(engine.jobs.length, 2);
  // Another study's Cancel ends the worker: this one fails with "cancelled" and is forgotten.
  engine.jobs[1].reject(new Error('cancelled'));
  await tick();
  assert.equal(peekStudy(key), null);
  study(engine, 'classify', {}, key);
  assert.equal(engine.jobs.length, 3, 'the next ask reruns it');
  engine.jobs[2].reject(new Error('wasm: options.rank out of range'));
  await tick();
  assert.equal(peekStudy(key).error, 'wasm: options.rank out of range');
});
