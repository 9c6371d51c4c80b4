// The lab's engine in a fluid, on the REAL wasm module (www/pkg; built by npm test first): the
// medium is one parameter (`air_density`, the core's table), the wing's mesh and shapes travel
// beside the JSON config (engine.withWing; never inside the config a result or export keeps),
// and the live analysis then carries what the air does: the aerodynamic force, its spectrum and
// share, the still-air frequency and the free vibration's decay. A fluid on the paper's table
// modes is refused, naming `air_density`.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { defaults, FE_LAB_INPUT } from '../../www/state.js';
import { loadReal, realEngine } from './real_wasm.mjs';
import { withWing } from '../../www/engine/cache.js';

test('withWing attaches the wing only in a fluid and only to that wing’s modes', () => {
  const fe = {
    modes: [{}, {}],
    nodes: new Float64Array(9),
    triangles: new Uint32Array(3),
    shapes: new Float64Array(6),
  };
  const vac = { modes: [{}, {}] };
  assert.equal(withWing(vac, fe), vac, 'a vacuum: the config itself');
  const air = { modes: [{}, {}], aero: { air_density_kg_m3: 1.2 } };
  const w = withWing(air, fe);
  assert.notEqual(w, air, 'a copy: the caller’s config keeps no wing');
  assert.equal(air.wing, undefined);
  assert.equal(w.wing.nodes, fe.nodes);
  assert.equal(w.wing.triangles, fe.triangles);
  assert.equal(w.wing.shapes, fe.shapes);
  const other = { ...air, modes: [{}] };
  assert.equal(withWing(other, fe), other, 'modes of another wing: nothing attached');
  assert.equal(withWing(air, null), air, 'no wing yet');
});

test('the live analysis in air on the real wasm: aerodynamic force, share, spectrum and decay; vacuum unchanged', async () => {
  const wb = await loadReal();
  const e = await realEngine(wb);
  // The lab's default FE wing, solved here (the engine's worker path is tested elsewhere).
  const fe = wb.feModes({ ...FE_LAB_INPUT }, null, undefined);
  e.useFe(fe, 'test');
  const p = { ...defaults(), modes: 'fe', duration: 0.4, mode: '1' };
  assert.throws(
    () => e.config({ ...defaults(), air_density: 1.2 }),
    /air_density = 1\.2 kg\/m³ needs the FE wing's mode shapes/,
  );
  const vac = e.analyze(p);
  const air = e.analyze({ ...p, air_density: 1.2 });
  assert.equal(air.cfg.aero.air_density_kg_m3, 1.2);
  assert.equal(air.cfg.wing, undefined, 'the result’s config is plain JSON');
  assert.equal(vac.analysis.sim.air, undefined);
  assert.equal(vac.analysis.spectra[0].aerodynamic, undefined);
  const a = air.analysis;
  const m = a.sim.modes[0];
  assert.ok(a.sim.air && a.sim.air.points > 0, 'the run’s air summary');
  // The added mass lowers the first mode's frequency; air damps its free vibration.
  assert.ok(m.air.still_air_freq_hz < m.freq_hz, `${m.air.still_air_freq_hz} < ${m.freq_hz}`);
  assert.ok(m.air.decay_rate_per_s > 0 && m.air.aero_damping_ratio > 0);
  assert.ok(Math.abs(m.air.decay_time_s * m.air.decay_rate_per_s - 1) < 1e-12);
  assert.ok(m.contribution_percent.aerodynamic > 0);
  assert.ok(a.forces[0].aerodynamic instanceof Float64Array && a.forces[0].aerodynamic.length === a.sim.n);
  assert.ok(a.forces[0].aerodynamic.some((v) => v !== 0));
  assert.ok(a.spectra[0].aerodynamic.psd.every((v) => Number.isFinite(v) && v >= 0));
  // The same run through the plain wasm API with the wing attached by hand.
  const direct = wb.simulate({ ...air.cfg, wing: { nodes: fe.nodes, triangles: fe.triangles, shapes: fe.shapes } });
  assert.deepEqual(Array.from(direct.modes[0].q.total), Array.from(m.q.total));
  // Vacuum is what it was: a config with air_density 0 carries no aero block.
  assert.equal(vac.cfg.aero, undefined);
  assert.ok(Math.abs(vac.analysis.sim.modes[0].q.total[1000] - m.q.total[1000]) > 0, 'air changes the response');
});
