// Unit tests of the guided experiments (www/experiments.js) against synthetic analysis fixtures
// shaped like the wasm `analyze` result: signals whose beat period, modulation and growth rate
// are known in closed form, so each prediction's check is tested both where it must hold and
// where it must fail. Run: node --test tests/js/experiments.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  EXPERIMENTS,
  experiment,
  experimentState,
  experimentQuery,
  predict,
  bands,
  resonanceCrossings,
  resonanceSummary,
  leastStableMode,
  fmt,
} from '../../www/experiments.js';
import { measureBeat, growthRate, movingAverage } from '../../www/measure.js';
import { NUMERIC, ENUMS, EXPERIMENT_IDS, parsePairs, parseNumber } from '../../www/state.js';
import { plain } from '../../www/format.js';

const TAU = 2 * Math.PI;

/**
 * A fake `analyze` result. Mode 0's Coriolis response is A(cos 2π·2f_d t − e^{−σt} cos 2πf_eff t)
 * (a forced line at 2 f_d beating against a free vibration at f_eff, decaying at σ), with its
 * analytic envelope; `grow` makes mode `growMode`'s total response grow as e^{grow·t}.
 */
function fixture({
  fd = 25,
  feff = 60.30639,
  f1 = 62.5,
  fs = 4000,
  dur = 2,
  sigma = 0,
  zeta = 0,
  gamma0 = 0.2,
  floquetFeff = feff,
  grow = 0,
  growMode = 1,
  coriolisZero = false,
} = {}) {
  const n = Math.round(dur * fs) + 1;
  const t = new Float64Array(n);
  const qc = new Float64Array(n);
  const env = new Float64Array(n);
  const A = 1e-6;
  for (let i = 0; i < n; i++) {
    const ti = i / fs;
    t[i] = ti;
    if (coriolisZero) continue;
    const d = Math.exp(-sigma * ti);
    qc[i] = A * (Math.cos(TAU * 2 * fd * ti) - d * Math.cos(TAU * feff * ti));
    env[i] = A * Math.sqrt(1 + d * d - 2 * d * Math.cos(TAU * (feff - 2 * fd) * ti));
  }
  const mode = (k, f) => {
    const total = new Float64Array(n);
    for (let i = 0; i < n; i++) {
      const ti = i / fs;
      total[i] =
        (k === 0 ? qc[i] : 0) +
        0.3e-6 * Math.sin(TAU * fd * ti) +
        (grow && k === growMode ? 1e-9 * Math.exp(grow * ti) * Math.sin(TAU * 1.9 * fd * ti) : 0);
    }
    const mm = grow && k === growMode ? Math.exp(grow / fd) : Math.exp((-zeta * TAU * f) / fd);
    return {
      name: `mode ${k + 1}`,
      freq_hz: f,
      zeta,
      contribution_percent: { euler: 17.8, centrifugal: 3.2, coriolis: coriolisZero ? 0 : 53.8 },
      floquet: {
        effective_freq_hz: k === 0 ? floquetFeff : 1.9 * fd,
        max_modulus: mm,
        stable: mm <= 1,
        growth_rate_per_s: Math.log(mm) * fd,
        multipliers: [
          [mm, 0],
          [1 / mm, 0],
        ],
      },
      q: { euler: total, centrifugal: total, coriolis: k === 0 ? qc : new Float64Array(n), free: total, total },
    };
  };
  return {
    sim: { n, sample_rate_hz: fs, flap_freq_hz: fd, t, modes: [mode(0, f1), mode(1, 86.9)], warnings: [] },
    envelope: [env, null],
    gamma0,
  };
}

const text = (r) => plain(r.lines.join(' '));
const checksOf = (r) => Object.fromEntries(r.checks.map((c) => [c.id, c.holds]));

test('every experiment has an id, title, look text and in-range URL parameters', () => {
  const ids = new Set();
  for (const e of EXPERIMENTS) {
    assert.ok(/^[a-z-]+$/.test(e.id) && !ids.has(e.id), e.id);
    ids.add(e.id);
    assert.ok(e.title.length > 5 && e.look.length > 20);
    for (const [k, v] of Object.entries(e.params)) {
      const p = NUMERIC.find((q) => q.key === k);
      const en = ENUMS.find((q) => q.key === k);
      assert.ok(p || en, `${e.id}: unknown parameter ${k}`);
      if (p) assert.notEqual(parseNumber(p, String(v)), null, `${e.id}: ${k}=${v} outside the slider`);
      if (en) assert.ok(en.choices.includes(v));
    }
  }
  assert.equal(EXPERIMENTS.length, 11);
  assert.deepEqual(
    EXPERIMENTS.map((e) => e.id),
    EXPERIMENT_IDS,
    'state.js validates exp= against the same ids',
  );
});

test('experiment URLs round-trip through the lab state parser', () => {
  for (const e of EXPERIMENTS) {
    const q = new URLSearchParams(experimentQuery(e.id));
    assert.equal(q.get('exp'), e.id);
    const { state, rejected } = parsePairs([...q.entries()]);
    assert.deepEqual(rejected, [], e.id);
    assert.equal(state.exp, e.id);
    const want = experimentState(e.id);
    for (const k of Object.keys(want)) if (k !== 'exp') assert.deepEqual(state[k], want[k], `${e.id}.${k}`);
  }
  assert.equal(experimentQuery('nope'), null);
  assert.equal(experiment('nope'), null);
});

test('measureBeat recovers a known beat period and modulation', () => {
  const a = fixture();
  const m = measureBeat(a.envelope[0], 4000, 25, 0, 1);
  const want = 1 / Math.abs(60.30639 - 50);
  assert.ok(Math.abs(m.period_s - want) / want < 0.005, `${m.period_s} vs ${want}`);
  assert.ok(m.modulation_index > 0.3, String(m.modulation_index));
  // A flat envelope has no beat.
  const flat = measureBeat(new Float64Array(8000).fill(1), 4000, 25);
  assert.equal(flat.period_s, null);
  assert.equal(flat.modulation_index, 0);
  // movingAverage of a constant is the constant.
  assert.deepEqual(Array.from(movingAverage([2, 2, 2, 2], 3)), [2, 2, 2, 2]);
});

test('beat: the Floquet prediction is stated with live numbers and checked against the envelope', () => {
  const r = predict('beat', fixture());
  assert.match(text(r), /feff = 60\.31 Hz .*2 fd = 50 Hz.*Tbeat = 1\/\|60\.31 − 50\| = 0\.097 s/);
  assert.equal(checksOf(r)['beat-period'], true);
  // A Floquet value that disagrees with the signal fails the check (not a tautology).
  const bad = predict('beat', fixture({ floquetFeff: 58 }));
  assert.equal(checksOf(bad)['beat-period'], false);
});

test('no yaw: Coriolis response and envelope exactly zero, else the check fails', () => {
  const a = fixture({ coriolisZero: true, gamma0: 0 });
  const r = predict('no-yaw', a, { state: { gamma0: 0 } });
  assert.deepEqual(checksOf(r), { 'coriolis-zero': true, 'envelope-zero': true });
  assert.match(text(r), /γ0 = 0 rad/);
  const r2 = predict('no-yaw', fixture());
  assert.deepEqual(checksOf(r2), { 'coriolis-zero': false, 'envelope-zero': false });
});

test('damping: ζ = 0.01 over 10 s lowers the modulation at least 10×; ζ = 0 does not', () => {
  const zeta = 0.01;
  const sigma = zeta * TAU * 62.5;
  const r = predict('damping', fixture({ dur: 10, sigma, zeta, fs: 2000 }));
  const c = checksOf(r);
  assert.equal(c['modulation-drop'], true, r.checks[0].label);
  assert.equal(c.stable, true);
  assert.ok(r.values.ratio >= 10);
  assert.match(text(r), /time constant 1\/\(ζ·2π·62\.5 Hz\) = 0\.255 s/);
  const r0 = predict('damping', fixture({ dur: 10, sigma: 0, zeta: 0, fs: 2000 }));
  assert.equal(checksOf(r0)['modulation-drop'], false);
});

test('yaw: uses the sweep result when it is there', () => {
  const a = fixture();
  const pending = predict('yaw', a, { state: { gamma0: 0.1 } });
  assert.match(pending.lines.join(' '), /computing/);
  assert.equal(pending.checks.length, 0);
  const sweep = {
    values: Float64Array.from([0, 0.05, 0.1, 0.15]),
    modes: [{ coriolis: Float64Array.from([0, 20, 53.8, 60]) }, { coriolis: Float64Array.from([0, 1, 2, 3]) }],
  };
  const r = predict('yaw', a, { state: { gamma0: 0.1 }, study: sweep });
  assert.deepEqual(checksOf(r), { 'share-rises': true, 'share-matches': true });
  sweep.modes[0].coriolis[3] = 10;
  assert.equal(checksOf(predict('yaw', a, { state: { gamma0: 0.1 }, study: sweep }))['share-rises'], false);
});

test('initial conditions: the share from rest lies inside the map range', () => {
  const a = fixture();
  const map = {
    n_q: 3,
    n_qdot: 3,
    q0: [-1, 0, 1],
    qdot0: [-1, 0, 1],
    coriolis_percent: new Float64Array(9),
    min_percent: 6.6,
    max_percent: 90,
    fraction_above_60: 0.119,
    attribution: 'forced',
  };
  const r = predict('ic', a, { study: map });
  assert.equal(checksOf(r)['rest-inside'], true);
  assert.match(r.lines.join(' '), /6\.6 % to 90 %; 11\.9 % of the starts/);
  assert.equal(checksOf(predict('ic', a, { study: { ...map, min_percent: 60 } }))['rest-inside'], false);
});

test('resonance: a slow beat near f_eff = 2 f_d is predicted and measured', () => {
  // f_d = 29 Hz, f_eff = 59.2 Hz: T_beat = 1/1.2 s.
  const r = predict('resonance', fixture({ fd: 29, feff: 59.2, dur: 4, fs: 3000 }));
  assert.equal(checksOf(r)['beat-period'], true, r.checks[0].label);
  assert.equal(checksOf(r).stable, true);
  assert.match(text(r), /Tbeat = 1\/\|59\.2 − 58\| = 0\.833 s/);
});

test('instability: max |λ| > 1 and the response grows at the Floquet rate', () => {
  const a = fixture({ fd: 41.5, grow: 6, growMode: 1 });
  assert.equal(leastStableMode(a), 1);
  const r = predict('instability', a);
  assert.deepEqual(checksOf(r), { unstable: true, growth: true });
  assert.match(text(r), /mode 2 .*max \|λ\| = 1\.155\d* per flap period > 1/);
  const stable = predict('instability', fixture({ fd: 41.5 }));
  assert.equal(checksOf(stable).unstable, false);
  assert.ok(Math.abs(growthRate(a.sim.modes[1].q.total, 4000, 41.5) - 6) < 0.5);
});

test('predict never throws', () => {
  const r = predict('beat', { sim: null });
  assert.match(r.lines[0], /could not be computed/);
  assert.match(predict('zzz', {}).lines[0], /Unknown experiment/);
});

test('resonance map summaries: bands, crossings and the text alternative', () => {
  assert.deepEqual(bands([1, 2, 3, 4, 5], [false, true, true, false, true]), [
    [2, 3],
    [5, 5],
  ]);
  assert.deepEqual(bands([1, 2], [false, false]), []);
  // f_eff = 60 Hz flat: crosses n·f_d at 60, 30, 20, 15 Hz.
  const fd = Array.from({ length: 111 }, (_, i) => 5 + 0.5 * i);
  const c = resonanceCrossings(
    fd,
    fd.map(() => 60),
  );
  assert.deepEqual(
    c.map((x) => x.n),
    [4, 3, 2, 1],
  );
  for (const x of c) assert.ok(Math.abs(x.flap_hz - 60 / x.n) < 1e-9);
  const r = {
    flap_hz: Float64Array.from(fd),
    modes: [
      {
        freq_hz: 62.5,
        effective_freq_hz: Float64Array.from(fd.map(() => 60)),
        max_modulus: Float64Array.from(fd.map((f) => (Math.abs(f - 30) < 0.6 ? 1.02 : 1))),
        beat_period_s: new Float64Array(111),
        stable: Uint8Array.from(fd.map((f) => (Math.abs(f - 30) < 0.6 ? 0 : 1))),
      },
    ],
  };
  const s = resonanceSummary(r);
  assert.deepEqual(s.modes[0].unstable, [[29.5, 30.5]]);
  assert.match(s.sentence, /unstable for f_d in 29\.5–30\.5 Hz \(largest \|λ\| 1\.02 at 29\.5 Hz\)/);
  // The crossing at 30 Hz lies in the unstable band (f_eff locks there): a band, not a resonance.
  assert.match(plain(s.sentence), /feff = n·fd at 15 Hz \(n = 4\), 20 Hz \(n = 3\), 60 Hz \(n = 1\)\./);
  assert.equal(fmt(1e-7, 2), '1.0×10^{−7}');
  assert.equal(plain(fmt(-2.5e-6, 2)), '−2.5×10⁻⁶');
});
