// The Kinematics panel's pure helpers (www/kinform.js): the editor's Fourier form of a core
// angle, the kinematics the hand editor makes (a measured table edited on its own grid), the
// label of edited kinematics, the preview's vertical range and words, and the "In use" line.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  fourierOf,
  nextHarmonicOrder,
  editedKinematics,
  editedLabel,
  valueRange,
  previewBounds,
  previewWords,
  inUseWords,
} from '../../www/kinform.js';
import { fmt } from '../../www/format.js';

const close = (a, b, tol = 1e-12) => assert.ok(Math.abs(a - b) <= tol, `${a} ≈ ${b}`);

test('fourierOf copies a Fourier angle (missing mean and phases are 0) and gives a sampled one nothing to edit', () => {
  const src = { kind: 'fourier', harmonics: [{ n: 2, amplitude: 0.3 }] };
  const f = fourierOf(src);
  assert.deepEqual(f, { mean: 0, harmonics: [{ n: 2, amplitude: 0.3, phase: 0 }] });
  f.harmonics[0].amplitude = 9;
  assert.equal(src.harmonics[0].amplitude, 0.3, 'the editor works on a copy');
  assert.deepEqual(fourierOf({ kind: 'fourier', mean: 0.1, harmonics: [{ n: 1, amplitude: 1, phase: -0.5 }] }), {
    mean: 0.1,
    harmonics: [{ n: 1, amplitude: 1, phase: -0.5 }],
  });
  assert.deepEqual(fourierOf({ kind: 'sampled', values: [1, 2] }), { mean: 0, harmonics: [] });
  assert.deepEqual(fourierOf(null), { mean: 0, harmonics: [] });
});

test('a new harmonic takes the order one above the highest there', () => {
  assert.equal(nextHarmonicOrder([]), 1);
  assert.equal(
    nextHarmonicOrder([
      { n: 3, amplitude: 0, phase: 0 },
      { n: 1, amplitude: 0, phase: 0 },
    ]),
    4,
  );
});

test('editedKinematics: Fourier angles as edited; a measured table gets the mean and harmonics added on its own grid', () => {
  const edit = {
    alpha: { mean: 0.1, harmonics: [{ n: 1, amplitude: 1, phase: 0 }] },
    beta: { mean: -0.2, harmonics: [{ n: 2, amplitude: 0.5, phase: 0.3 }] },
    gamma: { mean: 0, harmonics: [] },
  };
  const table = { kind: 'sampled', values: [0, 0, 0, 0], extra: 'kept' };
  const k = editedKinematics(edit, { alpha: table }, 30);
  assert.equal(k.flap_freq_hz, 30);
  assert.equal(k.alpha.kind, 'sampled');
  assert.equal(k.alpha.extra, 'kept', 'the table’s other fields are kept');
  // t_j = j T / 4: sin(2π j / 4) = 0, 1, 0, −1, plus the mean 0.1
  const want = [0.1, 1.1, 0.1, -0.9];
  for (const [j, v] of k.alpha.values.entries()) close(v, want[j]);
  assert.deepEqual(table.values, [0, 0, 0, 0], 'the table in use is not changed');
  assert.deepEqual(k.beta, { kind: 'fourier', mean: -0.2, harmonics: [{ n: 2, amplitude: 0.5, phase: 0.3 }] });
  assert.deepEqual(k.gamma, { kind: 'fourier', mean: 0, harmonics: [] });
  assert.deepEqual(Object.keys(k).sort(), ['alpha', 'beta', 'flap_freq_hz', 'gamma']);
});

test('edited kinematics are labelled once "edited", whatever was edited before', () => {
  assert.equal(editedLabel(null), 'edited kinematics');
  assert.equal(editedLabel({ label: 'hawkmoth.csv' }), 'edited hawkmoth.csv');
  assert.equal(editedLabel({ label: 'edited edited hawkmoth.csv' }), 'edited hawkmoth.csv');
});

test('the preview’s range covers the interpolant and the samples with 8 % margins; a flat stroke gets ±1 rad', () => {
  assert.deepEqual(valueRange([]), [Infinity, -Infinity]);
  assert.deepEqual(valueRange([2, -1, 0.5]), [-1, 2]);
  const ang = { alpha: [0, 2], beta: [-1, 0], gamma: [0, 0] };
  const b = previewBounds(ang, null);
  close(b.lo, -1 - 0.24);
  close(b.hi, 2 + 0.24);
  const withSamples = previewBounds(ang, { alpha: [3], beta: [-1], gamma: [0] });
  close(withSamples.lo, -1 - 0.32);
  close(withSamples.hi, 3 + 0.32);
  const flat = previewBounds({ alpha: [0], beta: [0], gamma: [0] }, undefined);
  close(flat.lo, -1.16);
  close(flat.hi, 1.16);
});

test('the preview’s words give the period, each angle’s range and the vertical range', () => {
  const ang = { alpha: [-0.8, 0.8], beta: [-0.5, 0.5], gamma: [-0.2, 0.2] };
  const b = previewBounds(ang, null);
  const w = previewWords(25, ang, false, b, fmt);
  assert.match(w, /^One flap period \(40 ms at 25 Hz\) of the kinematics in use: /);
  assert.match(
    w,
    /: α \(roll\) from -0\.8 to 0\.8 rad; β \(pitch\) from -0\.5 to 0\.5 rad; γ \(yaw\) from -0\.2 to 0\.2 rad\./,
  );
  assert.match(w, /Vertical range -0\.928 to 0\.928 rad\.$/);
  assert.ok(!w.includes('measured samples'));
  assert.match(previewWords(25, ang, true, b, fmt), /measured samples as dots and the core’s periodic interpolant/);
});

test('the "In use" line names the sliders or the custom kinematics and where they came from', () => {
  assert.match(inUseWords(null, fmt), /the sliders’ kinematics/);
  const k = (source) => ({ label: 'x.csv', source, kinematics: { flap_freq_hz: 26.5 } });
  assert.match(inUseWords(k('csv'), fmt), /^In use: x\.csv \(measured table, 26\.5 Hz\)\. The Parameters panel’s/);
  assert.match(inUseWords(k('edited'), fmt), /\(edited by hand, 26\.5 Hz\)/);
  assert.match(inUseWords(k('share'), fmt), /\(from the shared link, 26\.5 Hz\)/);
});
