// The responses plots' marks (www/views/time-marks.js): the beat band's label (period, decaying),
// the grey band only for a beat that decays away within a run, and the beat's repeats inside the
// window, the marked beat's own ends left out and none after a decaying beat is gone. Also the
// x window kept inside the data (www/plot/window.js clampWindow), which the panel's window uses.
// Run: node --test tests/js/time_marks.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { beatBand, goneBands, beatRepeats } from '../../www/views/time-marks.js';
import { clampWindow } from '../../www/plot/window.js';
import { plain } from '../../www/format.js';

const steady = { kind: 'steady', tau: null, goneAt: null, floor: 0.05 };
const decays = { kind: 'decays', tau: 0.5, goneAt: 1.2, floor: 0.05 };

test('beatBand spans the marked beat and names its period; a decaying beat says so', () => {
  const b = beatBand([0.1, 0.2], 0.09703, /** @type {any} */ (steady));
  assert.equal(b.x0, 0.1);
  assert.equal(b.x1, 0.2);
  assert.equal(plain(b.label), 'Tbeat = 0.09703 s');
  assert.match(beatBand([0.1, 0.2], 0.1, /** @type {any} */ (decays)).label, / \(decaying\)$/);
  assert.doesNotMatch(beatBand([0.1, 0.2], 0.1, null).label, /decaying/);
});

test('goneBands: from where a decaying beat is gone to the end of the run, else none', () => {
  const [g] = goneBands(/** @type {any} */ (decays), 2);
  assert.deepEqual([g.x0, g.x1], [1.2, 2]);
  assert.equal(g.label, 'beat gone (< 5 %)');
  assert.deepEqual(goneBands(/** @type {any} */ (steady), 2), []);
  assert.deepEqual(goneBands(null, 2), []);
  assert.deepEqual(goneBands(/** @type {any} */ ({ ...decays, goneAt: null }), 2), []);
  assert.deepEqual(goneBands(/** @type {any} */ (decays), null), [], 'no run, no band');
});

test('beatRepeats: every period inside the window but the marked beat’s two ends; none past a gone beat', () => {
  const near = (xs, want) => {
    assert.equal(xs.length, want.length, `${xs} vs ${want}`);
    for (const [i, x] of xs.entries()) assert.ok(Math.abs(x - want[i]) < 1e-12, `${xs} vs ${want}`);
  };
  near(beatRepeats(1, 0.5, 0, 3, null), [0, 0.5, 2, 2.5, 3]);
  near(beatRepeats(1, 0.5, 0, 3, /** @type {any} */ (decays)), [0, 0.5]);
  near(beatRepeats(1, 0.5, 1.6, 2.4, null), [2]);
  assert.deepEqual(beatRepeats(1, 0.5, null, 3, null), [], 'no window yet');
  // At most 40 periods either side.
  assert.equal(beatRepeats(0, 1, -1000, 1000, null).length, 79);
});

test('clampWindow keeps the window inside the data, its width kept, never wider than the data', () => {
  assert.deepEqual(clampWindow([2, 4], 0, 10), [2, 4]);
  assert.deepEqual(clampWindow([-1, 3], 0, 10), [0, 4]);
  assert.deepEqual(clampWindow([8, 12], 0, 10), [6, 10]);
  assert.deepEqual(clampWindow([-5, 20], 0, 10), [0, 10]);
});
