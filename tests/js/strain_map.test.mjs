// The strain panel's map helpers (www/views/strain-map.js): which FE wing the map is drawn for,
// the strain point in use, and the engine's strain field handed to strainMap.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mapFeOf, strainPointOf, strainFieldOf, PEAK_DELAY_MS } from '../../www/views/strain-map.js';

const run = (n) => ({ analysis: { sim: { modes: Array.from({ length: n }, () => ({})) } } });

test('the map is drawn only for the FE mode set with a run of as many modes as the wing', () => {
  const fe = { n_modes: 3 };
  assert.equal(mapFeOf({ modes: 'fe', fe, result: run(3) }), fe);
  assert.equal(mapFeOf({ modes: 'paper', fe, result: run(3) }), null);
  assert.equal(mapFeOf({ modes: 'fe', fe, result: run(2) }), null, 'a run of another wing');
  assert.equal(mapFeOf({ modes: 'fe', fe: null, result: run(3) }), null);
  assert.equal(mapFeOf({ modes: 'fe', fe, result: null }), null);
});

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
