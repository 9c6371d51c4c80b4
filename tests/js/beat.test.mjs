// The beat made explicit (www/beat.js): period = Floquet beat_period_s, formula terms, window.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { beatInfo, beatWindow, beatFate, modulation, shares } from '../../www/beat.js';

const analysis = (over = {}) => ({
  sim: {
    flap_freq_hz: 25,
    modes: [
      {
        freq_hz: 62.5,
        contribution_percent: { euler: 17.8, centrifugal: 3.2, coriolis: 53.8 },
        floquet: {
          effective_freq_hz: 60.30639396854428,
          beat_harmonic: 2,
          beat_period_s: 1 / (60.30639396854428 - 50),
          stable: true,
          max_modulus: 1,
          ...over,
        },
      },
    ],
  },
});

test('beatInfo: T_beat is the Floquet value and equals 1/|f_eff − n·f_d|', () => {
  const b = beatInfo(analysis(), 0);
  assert.equal(b.period, 1 / (60.30639396854428 - 50));
  assert.equal(b.n, 2);
  assert.equal(b.fHarm, 50);
  assert.ok(Math.abs(1 / b.diff - b.period) < 1e-12);
  assert.equal(beatInfo(analysis({ beat_period_s: null }), 0).period, null);
});

test('beatWindow: about three beats starting half a beat before an envelope maximum', () => {
  const rate = 10000,
    T = 0.097,
    n = 20001;
  const t = Float64Array.from({ length: n }, (_, i) => i / rate);
  const env = Float64Array.from(t, (x) => 1 + Math.cos((2 * Math.PI * x) / T));
  const w = beatWindow(t, env, T);
  assert.ok(Math.abs(w.x1 - w.x0 - 3 * T) < 1e-9);
  // the marked beat starts on a maximum of the envelope (x = T) and lasts one period
  assert.ok(Math.abs(w.mark[0] - T) < 2e-4, `${w.mark[0]}`);
  assert.ok(Math.abs(w.mark[1] - w.mark[0] - T) < 1e-12);
  assert.ok(Math.abs(w.measured - T) < 2e-4);
  assert.ok(w.x0 <= w.mark[0] && w.mark[1] <= w.x1);
});

test('beatWindow: no beat, or one too long for the run, shows the whole run', () => {
  const t = Float64Array.from({ length: 101 }, (_, i) => i / 100);
  const env = new Float64Array(101);
  assert.deepEqual(beatWindow(t, env, null), { x0: 0, x1: 1, mark: null, measured: null });
  assert.equal(beatWindow(t, env, 0.5).mark, null);
});

test('shares lists the three force terms', () => {
  assert.deepEqual(
    shares(analysis(), 0).map((s) => s.value),
    [17.8, 3.2, 53.8],
  );
});

test('smooth: a one-period moving average removes the ripple and keeps the slow swell', async () => {
  const { smooth } = await import('../../www/beat.js');
  const n = 4000,
    per = 400;
  const env = Float64Array.from(
    { length: n },
    (_, i) => 1 + 0.5 * Math.sin((2 * Math.PI * i) / 2000) + 0.2 * Math.sin((2 * Math.PI * i) / per),
  );
  const s = smooth(env, per);
  for (let i = per; i < n - per; i += 37) {
    // the swell survives, attenuated only by the window's own sinc factor (0.935 here)
    const g = Math.sin((Math.PI * per) / 2000) / ((Math.PI * per) / 2000);
    const slow = 1 + 0.5 * g * Math.sin((2 * Math.PI * (i - 0.5)) / 2000);
    assert.ok(Math.abs(s[i] - slow) < 2e-3, `${i}: ${s[i]} vs ${slow}`);
  }
});

test('beatFate: a damped beat decays with τ = −1/σ and is gone after ln(1/floor)·τ; undamped it stays', () => {
  const b = beatInfo(analysis(), 0); // T_beat = 0.0970 s
  // ζ = 0.01 at f1 = 62.5 Hz: σ = −ζω = −3.927 1/s, τ = 0.2546 s, gone (5 %) after 0.763 s.
  const sigma = -0.01 * 2 * Math.PI * 62.5;
  const f = beatFate(b, sigma, 10);
  assert.equal(f.kind, 'decays');
  assert.ok(Math.abs(f.tau - 1 / (0.01 * 2 * Math.PI * 62.5)) < 1e-12);
  assert.ok(Math.abs(f.goneAt - f.tau * Math.log(20)) < 1e-12);
  // The same damping in a run shorter than 3τ: the beat lasts the whole run.
  assert.equal(beatFate(b, sigma, 0.5).kind, 'steady');
  // Undamped (σ = 0) or unstable: steady; ζ = 0.1 kills it within one beat period: gone.
  assert.equal(beatFate(b, 0, 10).kind, 'steady');
  assert.equal(beatFate(b, 0, 10).tau, null);
  assert.equal(beatFate({ ...b, stable: false }, 0.5, 10).kind, 'steady');
  assert.equal(beatFate(b, -0.1 * 2 * Math.PI * 62.5, 2).kind, 'gone');
  assert.equal(beatFate({ ...b, period: null }, sigma, 10).kind, 'none');
});

test('modulation: (max − min)/(max + min) of the envelope inside a time window', () => {
  const t = Float64Array.from({ length: 1001 }, (_, i) => i / 1000);
  const env = Float64Array.from(t, (x) => (x < 0.5 ? 1 + 0.5 * Math.cos(40 * x) : 1));
  assert.ok(Math.abs(modulation(t, env, 0, 0.4) - 0.5) < 1e-3);
  assert.equal(modulation(t, env, 0.6, 1), 0);
  assert.equal(modulation(t, env, 2, 3), 0);
});
