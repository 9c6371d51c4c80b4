// The wing a config carries for the air (`cfg.wing`, read as typed arrays beside the JSON config)
// under hostile values on the REAL wasm: revoked proxies, throwing getters, objects posing as
// huge arrays, BigInt arrays, wrong lengths, NaN coordinates, out-of-range indices. Each call
// must be refused with an Error naming the field (never a trap), and the instance must still
// compute the valid air run afterwards, with the same result as before.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadReal, smallWing } from './real_wasm.mjs';

test('hostile wings are refused by name, never trap, and leave the instance working', async () => {
  const wb = await loadReal();
  const fe = smallWing(wb, 0);
  const cfg = {
    ...wb.defaultConfig(),
    modes: fe.modes,
    duration_s: 0.05,
    sample_rate_hz: 2000,
    aero: { air_density_kg_m3: 1.2 },
  };
  const good = { nodes: fe.nodes, triangles: fe.triangles, shapes: fe.shapes };
  const before = wb.simulate({ ...cfg, wing: good }).modes[0].q.total;
  const revoked = Proxy.revocable({}, {});
  revoked.revoke();
  const throwing = {
    get nodes() {
      throw new Error('boom');
    },
    triangles: fe.triangles,
    shapes: fe.shapes,
  };
  const nanNodes = Float64Array.from(fe.nodes);
  nanNodes[1] = Number.NaN;
  const badTri = Uint32Array.from(fe.triangles);
  badTri[2] = 1e6;
  const cases = [
    ['a number', 5, /config\.wing/],
    ['a string', 'wing', /config\.wing/],
    ['an array', [1, 2, 3], /config\.wing/],
    ['a typed array', new Float64Array(3), /config\.wing/],
    ['a revoked proxy', revoked.proxy, /config\.wing/],
    ['a throwing getter', throwing, /config\.wing\.nodes/],
    ['nodes posing as 2e9 numbers', { ...good, nodes: { length: 2e9 } }, /config\.wing\.nodes/],
    ['BigInt nodes', { ...good, nodes: new BigInt64Array(9) }, /config\.wing\.nodes/],
    ['nodes not in threes', { ...good, nodes: fe.nodes.slice(0, fe.nodes.length - 1) }, /config\.wing\.nodes/],
    ['one shape short', { ...good, shapes: fe.shapes.slice(0, fe.shapes.length / 2) }, /config\.wing\.shapes/],
    ['a NaN coordinate', { ...good, nodes: nanNodes }, /wing\.nodes\[0\]/],
    ['an index past the nodes', { ...good, triangles: badTri }, /wing\.triangles\[0\]/],
    ['negative indices', { ...good, triangles: Float64Array.from(fe.triangles, (v) => -v - 1) }, /wing\.triangles/],
    ['no triangles', { ...good, triangles: new Uint32Array(0) }, /config\.wing\.triangles/],
  ];
  for (const [what, wing, name] of cases) {
    let err = null;
    try {
      wb.simulate({ ...cfg, wing });
    } catch (e) {
      err = e;
    }
    assert.ok(err instanceof Error, `${what}: refused`);
    assert.ok(!(err instanceof WebAssembly.RuntimeError), `${what}: trapped (${err.message})`);
    assert.match(err.message, name, what);
  }
  // A getter on the config itself that throws when `wing` is read.
  const sly = { ...cfg };
  Object.defineProperty(sly, 'wing', {
    enumerable: true,
    get() {
      throw new Error('nope');
    },
  });
  assert.throws(() => wb.simulate(sly), /`config`/);
  const after = wb.simulate({ ...cfg, wing: good }).modes[0].q.total;
  assert.deepEqual(Array.from(after), Array.from(before), 'the instance computes as before');
});
