// The engine (www/engine.js) against a fake wasm module and a fake worker: the only module
// that talks to wasm; the config comes from wasm applyOverrides (the core interprets every
// parameter); results carry the angles of wasm analyze (one crossing per recompute); worker jobs
// with progress, errors and cancellation. tests/js/wasm.test.mjs runs the same engine on the real
// wasm; the parts in www/engine/ have their own tests (engine_protocol, engine_requests,
// engine_cache).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createEngine, splitAngles } from '../../www/engine.js';
import { defaults } from '../../www/state.js';
import { fakeWorker } from './fake_worker.mjs';

function fakeWasm() {
  const calls = { analyze: 0, anglesAt: 0, applyOverrides: [] };
  const n = 5;
  const t = Float64Array.from({ length: n }, (_, i) => i / 10000);
  const spec = () => ({ freq_hz: new Float64Array([0, 1]), psd: new Float64Array([1, 2]) });
  const wb = {
    calls,
    defaultConfig: () => ({ modes: [{ name: 'm1', freq_hz: 62.5, a: [1, 0], zeta: 0, strains: [] }] }),
    limits: () => ({ max_samples: 2e6 }),
    // Stand-in for the core's apply_overrides: records its input and tags the result (what each
    // key means is the core's business, tested in tests/js/wasm.test.mjs and tests/params.rs).
    applyOverrides(base, overrides) {
      calls.applyOverrides.push({ base, overrides });
      if (overrides.duration > 10) throw new Error('invalid value for `overrides.duration`');
      return { ...base, applied: overrides };
    },
    analyze(cfg, opts, k) {
      calls.analyze++;
      calls.last = { cfg, opts, k };
      const sp = { euler: spec(), centrifugal: spec(), coriolis: spec(), stiffness_force: spec(), total: spec() };
      // As the real analyze: the angles α, β, γ on sim.t come with the result.
      const angles = { alpha: t.map((x) => x), beta: t.map((x) => 2 * x), gamma: t.map((x) => 3 * x) };
      return {
        sim: { t, n, sample_rate_hz: 10000, flap_freq_hz: 25, modes: [] },
        spectra: [sp],
        forces: [{ stiffness_force: 1 }],
        envelope: [],
        angles,
      };
    },
    anglesAt(_cfg, times) {
      calls.anglesAt++;
      const out = new Float64Array(3 * times.length);
      times.forEach((tt, i) => {
        out[3 * i] = tt;
        out[3 * i + 1] = 2 * tt;
        out[3 * i + 2] = 3 * tt;
      });
      return out;
    },
  };
  return wb;
}

test('analyze builds the config from the parameters; the angles come with the analysis (no anglesAt call)', async () => {
  const wb = fakeWasm();
  const e = createEngine({ load: async () => wb, createWorker: fakeWorker });
  assert.equal(e.ready, false);
  await e.load();
  assert.equal(e.ready, true);
  const p = defaults();
  p.gamma0 = 0.1;
  p.mode = '2';
  p.detrend = 'mean';
  const r = e.analyze(p);
  assert.equal(wb.calls.analyze, 1);
  assert.equal(r.angles, r.analysis.angles, 'the analysis’s own angles');
  assert.equal(wb.calls.anglesAt, 0, 'no second crossing for the angles');
  assert.equal(wb.calls.last.k, 1);
  assert.deepEqual(wb.calls.last.opts, { detrend: 'mean', segment_len: 8192 });
  // The config is the core's: base (the paper case at 10 kHz) plus every numeric parameter by key.
  assert.equal(wb.calls.applyOverrides.length, 1);
  assert.equal(wb.calls.last.cfg, r.cfg);
  assert.equal(r.cfg.applied.gamma0, 0.1);
  assert.deepEqual(Object.keys(r.cfg.applied).sort(), [
    'air_density',
    'alpha0',
    'alpha_phase',
    'beta0',
    'beta_phase',
    'duration',
    'flap_hz',
    'gamma0',
    'gamma_phase',
    'zeta',
  ]);
  assert.equal(r.cfg.sample_rate_hz, 10000);
  assert.equal(r.cfg.modes[0].name, 'm1');
  assert.equal(r.k, 1);
  assert.equal(r.angles.alpha.length, 5);
  assert.equal(r.angles.beta[2], 2 * r.analysis.sim.t[2]);
  assert.ok(r.compute_ms >= 0);
  assert.ok(r.analysis.spectra[0].stiffness_force);
  assert.equal(r.analysis.spectra[0].stiffness, undefined, 'no old alias: one name, stiffness_force');
  assert.equal(r.analysis.forces[0].stiffness_force, 1);
});

test('anglesAt splits the interleaved wasm output; wingInput goes through wasm wingInput', async () => {
  const wb = fakeWasm();
  const seen = [];
  wb.wingInput = (o, pts) => {
    seen.push([o, pts]);
    return { n_modes: o.n_modes, planform_mm: pts };
  };
  const e = createEngine({ load: async () => wb, createWorker: fakeWorker });
  assert.throws(() => e.anglesAt({}, new Float64Array([0.5])), /not loaded/);
  assert.deepEqual(e.planforms(), [], 'no outlines before load');
  await e.load();
  const a = e.anglesAt({}, new Float64Array([0.5, 1]));
  assert.deepEqual([...a.alpha, ...a.beta, ...a.gamma], [0.5, 1, 1, 2, 1.5, 3]);
  assert.equal(wb.calls.anglesAt, 1);
  const pts = [
    [0, -2],
    [10, -2],
    [10, 0],
    [0, 0],
  ];
  const input = e.wingInput({ ...defaults(), n_modes: 3 }, pts);
  assert.deepEqual(input, { n_modes: 3, planform_mm: pts });
  assert.equal(seen[0][0].n_modes, 3, 'the wing parameters by the core’s keys');
  assert.deepEqual(
    e.wingInput(defaults(), null),
    { n_modes: 2, mesh_size_mm: 1 },
    'the default wing without a crossing',
  );
  assert.equal(seen.length, 1);
});

test('analyze before load throws; wasm errors pass through with their message', async () => {
  const wb = fakeWasm();
  wb.analyze = () => {
    throw new Error('invalid value for `duration_s`');
  };
  const e = createEngine({ load: async () => wb, createWorker: fakeWorker });
  assert.throws(() => e.analyze(defaults()), /not loaded/);
  assert.throws(() => e.config(defaults()), /not loaded/);
  await e.load();
  assert.throws(() => e.analyze(defaults()), /duration_s/);
  // A value the core rejects in applyOverrides: its error, naming the key, passes through.
  assert.throws(() => e.config({ ...defaults(), duration: 60 }), /overrides\.duration/);
});

test('worker jobs: progress, result, error; one worker for all jobs', async () => {
  let made = 0;
  let w;
  const e = createEngine({
    load: async () => fakeWasm(),
    createWorker: () => {
      made++;
      w = fakeWorker();
      return w;
    },
  });
  const prog = [];
  const a = e.run('sweep', { cfg: 1, opts: 2 }, (i, n) => prog.push([i, n]));
  const b = e.run('icmap', { cfg: 1 });
  assert.equal(made, 1);
  assert.deepEqual(
    w.posted.map((m) => [m.id, m.kind]),
    [
      [a.id, 'sweep'],
      [b.id, 'icmap'],
    ],
  );
  w.reply({ id: a.id, progress: [3, 10] });
  w.reply({ id: a.id, result: { ok: 1 }, ms: 12 });
  w.reply({ id: b.id, error: 'bad grid' });
  assert.deepEqual(await a.promise, { result: { ok: 1 }, ms: 12 });
  await assert.rejects(b.promise, /bad grid/);
  assert.deepEqual(prog, [[3, 10]]);
  assert.equal(e.running(a.id), false);
});

test('resonanceMap is a worker job of kind resonance with its options', async () => {
  let w;
  const e = createEngine({ load: async () => fakeWasm(), createWorker: () => (w = fakeWorker()) });
  const prog = [];
  const j = e.resonanceMap({ c: 1 }, { from_hz: 5, to_hz: 60, points: 3 }, (i, n) => prog.push([i, n]));
  assert.deepEqual(w.posted[0], {
    id: j.id,
    kind: 'resonance',
    cfg: { c: 1 },
    opts: { from_hz: 5, to_hz: 60, points: 3 },
  });
  w.reply({ id: j.id, progress: [1, 3] });
  w.reply({ id: j.id, result: { flap_hz: [5, 32.5, 60] }, ms: 4 });
  assert.deepEqual((await j.promise).result.flap_hz, [5, 32.5, 60]);
  assert.deepEqual(prog, [[1, 3]]);
});

test('cancel terminates the worker, fails its jobs, and the next job gets a fresh worker', async () => {
  const workers = [];
  const e = createEngine({
    load: async () => fakeWasm(),
    createWorker: () => {
      const w = fakeWorker();
      workers.push(w);
      return w;
    },
  });
  const a = e.run('sweep', {});
  assert.equal(e.cancel(a.id), true);
  await assert.rejects(a.promise, /cancelled/);
  assert.equal(workers[0].terminated, true);
  assert.equal(e.cancel(a.id), false);
  e.run('reproduce');
  assert.equal(workers.length, 2);
});

test('ensureFe runs once in the worker and then the config uses the FE modes', async () => {
  let w;
  const e = createEngine({
    load: async () => fakeWasm(),
    createWorker: () => (w = fakeWorker()),
    feInput: { n_modes: 2, mesh_size_mm: 1 },
  });
  await e.load();
  const p1 = e.ensureFe();
  const p2 = e.ensureFe();
  assert.equal(w.posted.length, 1);
  assert.deepEqual(w.posted[0].input, { n_modes: 2, mesh_size_mm: 1 });
  w.reply({
    id: w.posted[0].id,
    result: { modes: [{ name: 'fe1', freq_hz: 62.49, a: [1, 0], zeta: 0, strains: [] }] },
    ms: 1,
  });
  const fe = await p1;
  assert.equal(await p2, fe);
  assert.equal(e.fe, fe);
  const p = defaults();
  p.modes = 'fe';
  p.zeta = 0.02;
  const cfg = e.config(p);
  assert.equal(cfg.modes[0].name, 'fe1');
  assert.equal(cfg.applied.zeta, 0.02, 'ζ applied by the core to the FE modes');
  assert.equal(e.config(defaults()).modes[0].name, 'm1');
});

test('a failing worker rejects pending jobs; dispose terminates', async () => {
  let w;
  const e = createEngine({ load: async () => fakeWasm(), createWorker: () => (w = fakeWorker()) });
  const a = e.run('sweep');
  w.onerror({ message: 'boom' });
  await assert.rejects(a.promise, /boom/);
  e.run('sweep').promise.catch(() => {});
  e.dispose();
  assert.equal(w.terminated, true);
});

test('splitAngles', () => {
  const s = splitAngles(new Float64Array([1, 2, 3, 4, 5, 6]));
  assert.deepEqual([...s.alpha, ...s.beta, ...s.gamma], [1, 4, 2, 5, 3, 6]);
});

test('parameters(): the core table once loaded, else null', async () => {
  const wb = fakeWasm();
  wb.parameters = () => [{ key: 'alpha0', min: 0, max: 1.5, step: 0.01, default: 0.8 }];
  const e = createEngine({ load: async () => wb, createWorker: fakeWorker });
  assert.equal(e.parameters(), null);
  await e.load();
  assert.equal(e.parameters()[0].key, 'alpha0');
});

test('own wing: the old wing stays in use until the new one is ready; results are kept per input', async () => {
  const { plainWingInput } = await import('../../www/engine.js');
  const workers = [];
  const e = createEngine({
    load: async () => fakeWasm(),
    createWorker: () => {
      const w = fakeWorker();
      workers.push(w);
      return w;
    },
  });
  await e.load();
  const first = e.ensureFe();
  const w = workers[0];
  const r1 = { modes: [{ name: 'a', freq_hz: 62.49, a: [1, 0], zeta: 0, strains: [] }] };
  w.reply({ id: w.posted[0].id, result: r1, ms: 1 });
  assert.equal(await first, r1);
  const p = { ...defaults(), n_modes: 3, camber: 0.05 };
  const input = plainWingInput(p, [
    [0, -2],
    [10, -2],
    [10, 0],
    [0, 0],
  ]);
  assert.deepEqual(input.clamp, 'root');
  assert.equal(input.n_modes, 3);
  assert.equal(input.material.thickness_m, 81e-6);
  assert.equal(input.planform_mm.length, 4);
  const job = e.computeWing(input, () => {});
  assert.deepEqual(w.posted[1].opts, { json: true });
  assert.equal(e.fe, r1, 'old wing in use while the new one computes');
  const r2 = { modes: [1, 2, 3].map((k) => ({ name: `b${k}`, freq_hz: 10 * k, a: [1, 0], zeta: 0, strains: [] })) };
  w.reply({ id: w.posted[1].id, result: r2, ms: 1 });
  assert.equal(await job.promise, r2);
  assert.equal(e.fe, r1, 'a computed wing is used only once it is wanted');
  e.setWing(input);
  assert.equal(e.fe, r2);
  assert.equal(e.wingCurrent, true);
  const pf = { ...defaults(), modes: 'fe' };
  assert.equal(e.config(pf).modes.length, 3, 'every mode of the wing');
  // Back to the default wing: cached, no new job.
  const n = w.posted.length;
  assert.equal(await e.ensureFe(plainWingInput(defaults(), null)), r1);
  assert.equal(w.posted.length, n);
  // Cancel: the job fails with "cancelled", the wing in use stays.
  const job3 = e.computeWing({ ...input, n_modes: 4 });
  assert.equal(e.cancel(job3.id), true);
  await assert.rejects(job3.promise, /cancelled/);
  assert.equal(e.fe, r1);
});

test('custom kinematics replace the sliders’ stroke; a strain point replaces the modes’ strains', async () => {
  const wb = fakeWasm();
  const calls = [];
  wb.modalStrainAt = (_nodes, _tris, _sn, n, pt) => {
    calls.push(pt);
    return Array.from({ length: n }, (_, k) => ({ eps_x: k + pt[0], eps_y: 0, gamma_xy: 0 }));
  };
  let w;
  const e = createEngine({ load: async () => wb, createWorker: () => (w = fakeWorker()) });
  await e.load();
  const pr = e.ensureFe();
  w.reply({
    id: w.posted[0].id,
    result: {
      nodes: new Float64Array(3),
      triangles: new Uint32Array(0),
      strain_nodes: new Float64Array(0),
      modes: [
        { freq_hz: 1, a: [1, 0], strains: [{ point: 'P', eps_x: 9, eps_y: 9, gamma_xy: 9 }] },
        { freq_hz: 2, a: [1, 0], strains: [] },
      ],
    },
    ms: 1,
  });
  await pr;
  const kin = {
    flap_freq_hz: 30,
    alpha: { kind: 'sampled', values: [0, 1, 0, -1] },
    beta: { kind: 'fourier' },
    gamma: { kind: 'fourier' },
  };
  e.setKinematics(kin);
  const p = { ...defaults(), modes: 'fe', zeta: 0.01 };
  let cfg = e.config(p);
  assert.equal(cfg.kinematics, kin);
  assert.deepEqual(
    Object.keys(cfg.applied).sort(),
    ['air_density', 'duration', 'zeta'],
    'only ζ, the duration and the medium apply to custom kinematics',
  );
  e.setStrainPoint([4, -2]);
  cfg = e.config(p);
  assert.deepEqual(
    cfg.modes.map((m) => m.strains[0].eps_x),
    [4, 5],
  );
  e.config(p);
  assert.equal(calls.length, 1, 'modal strains computed once per point and wing');
  e.setStrainPoint(null);
  e.setKinematics(null);
  cfg = e.config(p);
  assert.equal(cfg.modes[0].strains[0].eps_x, 9);
  assert.equal(Object.keys(cfg.applied).length, 10);
});

test('live requests: coalesced in the live worker; only the newest result reaches the store', async () => {
  const { createStore } = await import('../../www/store.js');
  const wb = fakeWasm();
  let lw;
  let made = 0;
  const e = createEngine({
    load: async () => wb,
    createWorker: fakeWorker,
    createLiveWorker: () => {
      made++;
      lw = fakeWorker();
      return lw;
    },
  });
  await e.load();
  const store = createStore({ result: null });
  const drawn = [];
  store.subscribe(['result'], (s) => drawn.push(s.result.params.gamma0));
  const ask = (g) =>
    e.requestLive({ ...defaults(), gamma0: g }).then((r) => {
      if (r) store.set({ result: r });
      return r;
    });
  // Before the live worker says it is ready: computed on the main thread (the first render).
  const first = await ask(0.1);
  assert.equal(made, 0, 'the first request (first render) does not start the live worker');
  e.warmLive();
  assert.equal(made, 1);
  assert.equal(wb.calls.analyze, 1);
  assert.equal(first.params.gamma0, 0.1);
  assert.equal(e.liveInWorker, false);
  lw.reply({ ready: true });
  assert.equal(e.liveInWorker, true);
  // Three quick moves: the first goes to the worker, the second waits, the third replaces it.
  const a = ask(0.2),
    b = ask(0.3),
    c = ask(0.4);
  assert.equal(lw.posted.length, 1, 'one request in flight at a time');
  assert.equal(lw.posted[0].kind, 'analyze');
  assert.equal(lw.posted[0].cfg.applied.gamma0, 0.2);
  assert.equal(await b, null, 'the waiting request is superseded at once');
  const out = (gamma) => ({
    sim: { t: new Float64Array(2), n: 2 },
    spectra: [],
    forces: [],
    envelope: [],
    angles: { alpha: new Float64Array(2), beta: new Float64Array(2), gamma: new Float64Array(2) },
    tag: gamma,
  });
  // The stale in-flight result comes back: dropped, and the newest request is posted.
  lw.reply({ id: lw.posted[0].id, result: out(0.2), ms: 5 });
  assert.equal(await a, null, 'a result for a superseded request is not delivered');
  assert.equal(lw.posted.length, 2);
  assert.equal(lw.posted[1].cfg.applied.gamma0, 0.4);
  lw.reply({ id: lw.posted[1].id, progress: [1, 2] });
  lw.reply({ id: 999, result: out(9), ms: 1 });
  lw.reply({ id: lw.posted[1].id, result: out(0.4), ms: 7 });
  const rc = await c;
  assert.equal(rc.analysis.tag, 0.4);
  assert.equal(rc.compute_ms, 7);
  assert.equal(rc.k, 0);
  assert.ok(rc.angles.gamma instanceof Float64Array);
  assert.deepEqual(drawn, [0.1, 0.4], 'only the first and the newest results reached the store');
  assert.equal(wb.calls.analyze, 1, 'the worker did the rest');
  assert.deepEqual(e.liveStats, { posted: 2, superseded: 1, stale: 1, sync: 1 });
  // An error of the newest request rejects; a stale one is dropped silently.
  const d = ask(0.5);
  lw.reply({ id: lw.posted[2].id, error: 'invalid value for `duration_s`' });
  await assert.rejects(d, /duration_s/);
  // A value the core rejects throws at once, before anything is posted.
  assert.throws(() => e.requestLive({ ...defaults(), duration: 60 }), /overrides\.duration/);
  assert.equal(lw.posted.length, 3);
  // The worker dies: the newest request is computed on the main thread from then on.
  const f = ask(0.6),
    g = ask(0.7);
  lw.onerror({ message: 'boom' });
  assert.equal(await f, null);
  assert.equal((await g).params.gamma0, 0.7);
  assert.equal(lw.terminated, true);
  assert.equal((await ask(0.8)).params.gamma0, 0.8);
  assert.equal(made, 1, 'no new worker after a failure');
  assert.equal(wb.calls.analyze, 3);
  // dispose: a request in flight resolves to null.
  e.dispose();
});

test('without workers, live requests compute on the main thread', async () => {
  const wb = fakeWasm();
  const e = createEngine({
    load: async () => wb,
    createWorker: fakeWorker,
    createLiveWorker: () => {
      throw new Error('no Worker here');
    },
  });
  await e.load();
  const r = await e.requestLive({ ...defaults(), gamma0: 0.25 });
  assert.equal(r.params.gamma0, 0.25);
  assert.equal(wb.calls.analyze, 1);
  assert.equal(e.liveInWorker, false);
});
