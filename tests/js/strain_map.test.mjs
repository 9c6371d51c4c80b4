// The strain panel's map helpers (www/views/strain-map.js): the strain point in use and the
// engine's strain field handed to strainMap. Which FE wing the map is drawn for is senseFe
// (www/sensemap.js), tested in sensemap.test.mjs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { strainPointOf, strainFieldOf, PEAK_DELAY_MS } from '../../www/views/strain-map.js';

test('the strain point: the store’s, else the FE wing’s default, else (3, −6) mm', () => {
  assert.deepEqual(strainPointOf({ strain_point: [10, -2], fe: { strain_point_mm: [5, -5] } }), [10, -2]);
  assert.deepEqual(strainPointOf({ strain_point: null, fe: { strain_point_mm: [5, -5] } }), [5, -5]);
  assert.deepEqual(strainPointOf({ strain_point: null, fe: null }), [3, -6]);
});

test('strainFieldOf passes the run’s q and the map’s options to the engine, or is null without one', () => {
  assert.equal(strainFieldOf(null), null);
  assert.equal(strainFieldOf({}), null);
  const seen = [];
  const field = new Float64Array([1, 2]);
  const f = strainFieldOf({
    strainField: (qs, opts) => {
      seen.push([qs, opts]);
      return field;
    },
  });
  const qs = [new Float64Array([0.5])];
  const opts = { component: 'eps_x', stat: 'rms' };
  assert.equal(f(new Float64Array(0), 2, qs, opts), field);
  assert.deepEqual(seen, [[qs, opts]]);
  assert.ok(PEAK_DELAY_MS > 0 && PEAK_DELAY_MS <= 1000);
});
