// Measurements on sampled responses (www/measure.js) with values worked by hand: the peak |x|
// (signs, NaN, empty), the centred moving average's shrinking window at the ends, a beat of a
// known period and a response of a known growth rate. Run: node --test tests/js/measure.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { peakAbs, movingAverage, measureBeat, growthRate } from '../../www/measure.js';

test('peakAbs is the largest magnitude whatever its sign; empty is 0; a NaN sample is passed over', () => {
  assert.equal(peakAbs([1, -3, 2]), 3);
  assert.equal(peakAbs(new Float64Array([-0.5, 0.25])), 0.5);
  assert.equal(peakAbs([]), 0);
  assert.equal(peakAbs([Number.NaN, -2, 1]), 2);
});

test('movingAverage averages w samples around each one and fewer at the ends', () => {
  // w = 3: [lo, hi) = [i-1, i+2) clipped to the series.
  assert.deepEqual(Array.from(movingAverage([0, 3, 6, 9], 3)), [1.5, 3, 6, 7.5]);
  // w = 2: [i-1, i+1).
  assert.deepEqual(Array.from(movingAverage([2, 4, 8], 2)), [2, 3, 6]);
  // w below 1 is one sample: the series itself.
  assert.deepEqual(Array.from(movingAverage([5, -1, 7], 0)), [5, -1, 7]);
});

test('measureBeat: an envelope 1 + 0.5 cos(2π t / 0.1 s) has period 0.1 s and modulation index 0.5', () => {
  const fs = 2000;
  const env = Float64Array.from({ length: 2000 }, (_, i) => 1 + 0.5 * Math.cos((2 * Math.PI * i) / fs / 0.1));
  // The flap average at 1000 Hz is one sample: the envelope itself.
  const m = measureBeat(env, fs, 1000);
  assert.ok(Math.abs(m.period_s - 0.1) < 1e-3, `period ${m.period_s}`);
  assert.ok(Math.abs(m.modulation_index - 0.5) < 1e-3, `modulation ${m.modulation_index}`);
  assert.ok(m.crossings >= 9);
});

test('growthRate recovers σ of e^{σt} sin(2π f t) and is null with under three flap periods', () => {
  const fs = 4000;
  const f = 20;
  const x = Float64Array.from(
    { length: 8000 },
    (_, i) => Math.exp(3 * (i / fs)) * Math.sin(2 * Math.PI * f * (i / fs)),
  );
  assert.ok(Math.abs(growthRate(x, fs, f, 0, 1) - 3) < 0.05);
  assert.equal(growthRate(x.slice(0, 400), fs, f, 0, 1), null);
});
