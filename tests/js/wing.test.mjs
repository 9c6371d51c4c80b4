// The lab's wing table (www/state.js WING) against the core's (wasm `wingParameters()`,
// src/params.rs) on the REAL wasm in node, and the engine's wing input through wasm
// `wingInput` equal to the plain-JS mapping. Needs www/pkg (scripts/build-web.sh www).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { WING, defaults } from '../../www/state.js';
import { createEngine, plainWingInput } from '../../www/engine.js';
import { loadReal } from './real_wasm.mjs';

test('the wing table has the core’s keys, ranges and steps (the lab’s own defaults aside)', async () => {
  const wb = await loadReal();
  const core = wb.wingParameters();
  assert.deepEqual(
    WING.map((w) => w.core),
    core.map((c) => c.key),
  );
  for (const w of WING) {
    const c = core.find((q) => q.key === w.core);
    assert.equal(w.min, c.min, `${w.key}.min`);
    assert.equal(w.max, c.max, `${w.key}.max`);
    assert.ok(w.def >= c.min && w.def <= c.max, `${w.key} default in range`);
  }
});

test('the wing input through wasm wingInput equals the plain mapping (own outline, strip clamp, automatic mesh)', async () => {
  const wb = await loadReal();
  const e = createEngine({
    load: async () => wb,
    createWorker: () => /** @type {any} */ ({ postMessage() {}, terminate() {} }),
  });
  await e.load();
  const p = {
    ...defaults(),
    camber: 0.07,
    clamp: 1.5,
    e_pa: 2e9,
    rho: 1200,
    nu: 0.35,
    thickness_um: 50,
    mesh_mm: 0,
    n_modes: 6,
  };
  const pts = [
    [0, -4],
    [20, -3.5],
    [22, -2],
    [20, -0.3],
    [0, 0],
  ];
  const core = e.wingInput(p, pts);
  const plain = plainWingInput(p, pts);
  for (const k of ['camber', 'clamp', 'material', 'n_modes', 'planform_mm']) assert.deepEqual(core[k], plain[k], k);
  assert.ok(core.mesh_size_mm == null, 'automatic mesh: no size');
  assert.throws(() => e.wingInput({ ...p, n_modes: 9 }, pts), /n_modes/);
  // The default wing is the lab's FE wing, whatever the core table's defaults.
  assert.deepEqual(e.wingInput(defaults(), null), { n_modes: 2, mesh_size_mm: 1 });
});
