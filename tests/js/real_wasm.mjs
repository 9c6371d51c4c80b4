// The REAL wasm module (www/pkg, built by scripts/build-web.sh www; npm test builds it first),
// instantiated in node with the generated glue's initSync — no browser — and an engine on it
// without workers (everything computed on this thread). Shared by the tests that run the lab's
// JavaScript against the real core.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { createEngine } from '../../www/engine.js';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const PKG = path.join(ROOT, 'www', 'pkg');

/** The wasm module's exports (never skips: a missing build is a failure). */
export async function loadReal() {
  const glue = path.join(PKG, 'wingbeat.js');
  const bin = path.join(PKG, 'wingbeat_bg.wasm');
  assert.ok(
    fs.existsSync(glue) && fs.existsSync(bin),
    'www/pkg is missing: run `bash scripts/build-web.sh www` first (npm test does)',
  );
  const m = await import(new URL(`file://${glue}`).href);
  m.initSync({ module: fs.readFileSync(bin) });
  return m;
}

/**
 * The small test wing of the hostile-input tests: FE modes of a 30 × 8 mm rectangle, 2 modes,
 * 4 mm elements, damping ratio `zeta`.
 * @param {any} wb the wasm exports
 * @param {number} zeta
 */
export function smallWing(wb, zeta) {
  const planform_mm = [
    [0, 0],
    [0, -8],
    [30, -8],
    [30, 0],
  ];
  return wb.feModes({ planform_mm, n_modes: 2, mesh_size_mm: 4 }, zeta, undefined);
}

/** A loaded engine on the real wasm `wb` whose workers cannot start (it computes here). */
export async function realEngine(wb) {
  const e = createEngine({
    load: async () => wb,
    createWorker: () => {
      throw new Error('no worker in this test');
    },
  });
  await e.load();
  return e;
}
