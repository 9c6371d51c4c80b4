// The guided experiments of the wing in air (www/experiments/air.js): the spectral measure on a
// synthetic signal with known harmonics, and both predictions on the REAL wasm (www/pkg) for the
// lab's FE wing, the live run in air and the study's run in a vacuum, as the lab computes them.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { psdNear, superharmonicRatio, AIR_EXPERIMENTS } from '../../www/experiments/air.js';
import { experimentState, predict } from '../../www/experiments.js';
import { EXPERIMENT_SCREEN } from '../../www/screens.js';
import { FE_LAB_INPUT } from '../../www/state.js';
import { loadReal, realEngine } from './real_wasm.mjs';

test('the 3f_d/1f_d ratio reads the harmonics’ peaks: amplitudes 2 and 0.5 give 0.25', () => {
  // A one-sided PSD with a peak of A²/2·(1/df) at f_d and 3f_d, noise elsewhere.
  const df = 0.5;
  const freq = Float64Array.from({ length: 400 }, (_, i) => i * df);
  const psd = freq.map(() => 1e-12);
  const fd = 20.5;
  psd[Math.round(fd / df)] = (2 * 2) / 2 / df;
  psd[Math.round((3 * fd) / df)] = (0.5 * 0.5) / 2 / df;
  const a = { sim: { flap_freq_hz: fd }, spectra: [{ total: { freq_hz: freq, psd } }] };
  assert.equal(psdNear({ freq_hz: freq, psd }, fd), 4);
  const r = superharmonicRatio(a, 0);
  assert.ok(Math.abs(r.ratio - 0.25) < 1e-12, String(r.ratio));
});

test('the air experiments open with the FE wing in air, on the screen that shows them', () => {
  for (const e of AIR_EXPERIMENTS) {
    const s = experimentState(e.id);
    assert.equal(s.modes, 'fe', e.id);
    assert.equal(s.air_density, 1.2, e.id);
  }
  assert.equal(EXPERIMENT_SCREEN['air-beat'], 'beat', 'the responses plot');
  assert.equal(EXPERIMENT_SCREEN['air-superharmonic'], 'research', 'the Floquet table beside it');
});

test('both air predictions hold on the real wasm: the beat is gone in air, the 3f_d superharmonic is suppressed', async () => {
  const wb = await loadReal();
  const e = await realEngine(wb);
  e.useFe(wb.feModes({ ...FE_LAB_INPUT }, null, undefined), 'test');
  for (const id of ['air-beat', 'air-superharmonic']) {
    const s = experimentState(id);
    const air = e.analyze(s).analysis;
    const vac = e.analyze({ ...s, air_density: 0 }).analysis;
    const pending = predict(id, air, { mode: 0, state: s });
    assert.ok(
      pending.lines.some((l) => l.includes('computing')),
      `${id}: says the vacuum run is pending`,
    );
    const p = predict(id, air, { mode: 0, state: s, study: vac });
    assert.ok(p.checks.length >= 2, id);
    for (const c of p.checks) assert.equal(c.holds, true, `${id}: ${c.label}`);
    assert.ok(!p.lines.join(' ').includes('NaN'), id);
  }
});
