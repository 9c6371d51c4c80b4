// The one min/max decimation (www/decimate.js), shared by the plots and the worker.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { decimate } from '../../www/decimate.js';

test('short series are copied unchanged (as Float64Array)', () => {
  const [x, y] = decimate([0, 1, 2], [[5, 6, 7]], 10);
  assert.ok(x instanceof Float64Array && y instanceof Float64Array);
  assert.deepEqual(Array.from(y), [5, 6, 7]);
});

test('each bucket keeps its min and max in time order; peaks survive', () => {
  const n = 10000;
  const x = Float64Array.from({ length: n }, (_, i) => i / n);
  const y = Float64Array.from({ length: n }, (_, i) => Math.sin(2 * Math.PI * 50 * x[i]));
  y[4321] = 9; // a spike
  const [xo, yo] = decimate(x, [y], 100);
  assert.equal(xo.length, 200);
  assert.equal(Math.max(...yo), 9);
  assert.ok(Math.min(...yo) < -0.99);
  for (let i = 1; i < xo.length; i++) assert.ok(xo[i] >= xo[i - 1]);
});

test('several series stay aligned on one x grid', () => {
  const x = Array.from({ length: 1000 }, (_, i) => i);
  const [xo, a, b] = decimate(x, [x, x.map((v) => -v)], 50);
  assert.equal(a.length, xo.length);
  for (let i = 0; i < a.length; i++) assert.equal(a[i], -b[i]);
});
