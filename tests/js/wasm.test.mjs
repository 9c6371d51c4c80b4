// The lab's JavaScript against the REAL wasm module (www/pkg, built by scripts/build-web.sh),
// instantiated in node with the generated glue's initSync — no browser. Never skips: a missing
// build is a failure (npm test builds it first).
//   * the slider table www/state.js NUMERIC agrees field by field with the core's table
//     (wasm `parameters()`, src/params.rs);
//   * the engine's config is the core's (wasm `applyOverrides`): γ0 is the yaw angle's first
//     harmonic, ζ applies to every mode, the lab samples at 10 kHz, and the URL state's defaults
//     give exactly the paper case (wasm `defaultConfig()`).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { NUMERIC, MEDIA, SAMPLE_RATE_HZ, defaults } from '../../www/state.js';
import { createEngine } from '../../www/engine.js';
import { loadReal } from './real_wasm.mjs';

const wbPromise = loadReal();

/**
 * The lab's rich-label markup read as the core's plain text: a subscript that is a digit or a
 * Greek letter is written inline (α_0 → α0, φ_α → φα), a Latin one keeps its underscore
 * (f_d), braces go (T_{sim} → T_sim).
 */
const plainSym = (s) => s.replace(/_\{([^}]*)\}/g, '_$1').replace(/_([^A-Za-z])/g, '$1');

test('the slider table agrees with the core’s parameter table, field by field', async () => {
  const wb = await wbPromise;
  const core = wb.parameters();
  assert.deepEqual(
    core.map((p) => p.key),
    NUMERIC.map((p) => p.key),
    'same keys, same order',
  );
  for (const p of NUMERIC) {
    const c = core.find((q) => q.key === p.key);
    assert.equal(p.min, c.min, `${p.key}.min`);
    assert.equal(p.max, c.max, `${p.key}.max`);
    assert.equal(p.step, c.step, `${p.key}.step`);
    assert.equal(p.def, c.default, `${p.key}.default`);
    assert.equal(p.unit, c.unit, `${p.key}.unit`);
    assert.equal(plainSym(p.sym), c.symbol, `${p.key}.symbol`);
    assert.equal(plainSym(p.label), c.label, `${p.key}.label`);
  }
});

test('the medium control’s named media are the core’s, with the same densities', async () => {
  const wb = await wbPromise;
  assert.deepEqual(
    wb.media(),
    MEDIA.map((m) => ({ ...m })),
  );
});

test('the URL defaults, applied by the core, are exactly the paper case at the lab’s sample rate', async () => {
  const wb = await wbPromise;
  const e = createEngine({
    load: async () => wb,
    createWorker: () => {
      throw new Error('no worker in this test');
    },
  });
  await e.load();
  const cfg = e.config(defaults());
  const paper = wb.defaultConfig();
  assert.equal(paper.sample_rate_hz, SAMPLE_RATE_HZ);
  assert.deepEqual(cfg, paper);
});

test('the engine’s config is built by the core: γ0 and phases on the first harmonic, ζ on every mode', async () => {
  const wb = await wbPromise;
  const e = createEngine({
    load: async () => wb,
    createWorker: () => {
      throw new Error('no worker in this test');
    },
  });
  await e.load();
  const s = defaults();
  s.zeta = 0.01;
  s.gamma_phase = 0.5;
  s.gamma0 = 0.125;
  s.flap_hz = 30;
  s.duration = 1.5;
  s.alpha_phase = -1.5;
  const c = e.config(s);
  const h1 = (a) => a.harmonics.find((h) => h.n === 1);
  assert.equal(h1(c.kinematics.gamma).amplitude, 0.125);
  assert.equal(h1(c.kinematics.gamma).phase, 0.5);
  assert.equal(h1(c.kinematics.alpha).phase, -1.5);
  assert.equal(h1(c.kinematics.alpha).amplitude, 0.8);
  assert.equal(c.kinematics.flap_freq_hz, 30);
  assert.equal(c.duration_s, 1.5);
  assert.equal(c.sample_rate_hz, 10000);
  assert.ok(c.modes.length === 2 && c.modes.every((m) => m.zeta === 0.01));
  assert.equal(e.baseConfig.modes[0].zeta, 0, 'the base config is not modified');
  // Same meaning as the sweep's parameter (one owner): the sweep's first point at γ0 = 0.125
  // and this engine's config at γ0 = 0.125 give the same Coriolis share.
  const sw = wb.sweep(e.config(defaults()), { param: 'gamma0', from: 0.125, to: 0.25, points: 2 });
  const sim = wb.simulate(e.config({ ...defaults(), gamma0: 0.125 }));
  assert.ok(
    Math.abs(sim.modes[0].contribution_percent.coriolis - sw.modes[0].coriolis[0]) < 1e-9,
    'applyOverrides γ0 = sweep γ0',
  );
  // The core rejects an out-of-range value by name (the URL parser keeps such values out).
  assert.throws(() => e.config({ ...defaults(), gamma0: 0.9 }), /gamma0/);
});

test('analyze on the real wasm: stiffness_force and the angles on sim.t', async () => {
  const wb = await wbPromise;
  const e = createEngine({
    load: async () => wb,
    createWorker: () => {
      throw new Error('no worker in this test');
    },
  });
  await e.load();
  const r = e.analyze({ ...defaults(), duration: 0.4 });
  const a = r.analysis;
  assert.ok(a.spectra[0].stiffness_force.psd.length > 0);
  assert.equal(a.forces[0].stiffness_force.length, a.sim.t.length);
  assert.equal(a.spectra[0].stiffness, undefined);
  assert.equal(r.angles.alpha.length, a.sim.t.length);
  assert.ok(Math.abs(r.angles.gamma[0]) < 1e-12 && Math.abs(r.angles.alpha[25]) > 0);
});

test('the share links’ DFT (fourier.js) samples a measured angle with the core’s default harmonic cap, and a typical table runs in the lab’s budget', async () => {
  const wb = await wbPromise;
  const { DEFAULT_SAMPLED_MAX_HARMONIC } = await import('../../www/fourier.js');
  assert.equal(DEFAULT_SAMPLED_MAX_HARMONIC, wb.limits().default_sampled_max_harmonic);
  // A 200-sample, one-period table at 25 Hz with a little measurement noise (deterministic):
  // with the default cap it runs under the browser's work budget (at 64 harmonics it was refused).
  const fd = 25,
    n = 200;
  let csv = 't,alpha,beta,gamma\n';
  for (let i = 0; i < n; i++) {
    const p = (2 * Math.PI * i) / n;
    const noise = 0.15 * Math.sin(37 * i * 1.618);
    csv += `${i / (n * fd)},${(45 * Math.sin(p) + noise).toFixed(6)},${(28 * Math.sin(p + 0.3)).toFixed(6)},${(11 * Math.sin(2 * p)).toFixed(6)}\n`;
  }
  const k = wb.kinematicsFromCsv(csv, { units: 'deg', flap_hz: fd });
  assert.equal(k.max_harmonic, DEFAULT_SAMPLED_MAX_HARMONIC);
  const r = wb.analyze({ ...wb.defaultConfig(), kinematics: k.kinematics }, undefined, 0);
  assert.ok(
    Number.isFinite(r.sim.modes[0].floquet.effective_freq_hz),
    'the measured stroke runs in the browser budget',
  );
  // and 64 harmonics (asked for) is still refused by name, so the budget is what the default keeps us under
  const k64 = wb.kinematicsFromCsv(csv, { units: 'deg', flap_hz: fd, max_harmonic: 64 });
  assert.throws(
    () => wb.analyze({ ...wb.defaultConfig(), kinematics: k64.kinematics }, undefined, 0),
    /highest harmonic|max_harmonic/,
  );
});
