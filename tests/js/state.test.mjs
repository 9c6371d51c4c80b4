// Unit tests of the lab's URL/attribute state parsing (www/state.js). Run: node --test tests/js
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { parseQuery, parsePairs, toQuery, defaults, snap, NUMERIC, overridesOf } from '../../www/state.js';

test('empty query gives the paper defaults', () => {
  const { state, rejected } = parseQuery('');
  assert.deepEqual(rejected, []);
  assert.equal(state.gamma0, 0.2);
  assert.equal(state.flap_hz, 25);
  assert.equal(state.modes, 'paper');
});

test('round trip of every parameter', () => {
  const s = defaults();
  s.gamma0 = 0.125;
  s.alpha_phase = -1.5;
  s.detrend = 'mean';
  s.mode = '2';
  s.duration = 1.5;
  const { state, rejected } = parseQuery('?' + toQuery(s));
  assert.deepEqual(rejected, []);
  assert.deepEqual(state, s);
});

test('hostile and malformed values are rejected by name, never echoed', () => {
  const { state, rejected } = parseQuery('?gamma0=<img src=x onerror=alert(1)>&alpha0=1e999&beta0=0x10&zeta=NaN');
  assert.equal(state.gamma0, 0.2);
  assert.equal(state.alpha0, 0.8);
  assert.equal(state.beta0, 0.5);
  assert.equal(state.zeta, 0);
  assert.deepEqual(rejected.map((r) => r.key).sort(), ['alpha0', 'beta0', 'gamma0', 'zeta']);
  for (const r of rejected) assert.ok(!r.why.includes('<') && !r.why.includes('onerror'));
});

test('out-of-range, unknown-choice and unknown parameters are rejected', () => {
  const { state, rejected } = parseQuery('?flap_hz=1000&modes=abaqus&bogus=1&duration=-1&gamma0=0.1&gamma0=0.2');
  assert.equal(state.flap_hz, 25);
  assert.equal(state.modes, 'paper');
  assert.equal(state.gamma0, 0.1);
  const keys = rejected.map((r) => r.key);
  for (const k of ['flap_hz', 'modes', 'bogus', 'duration', 'gamma0']) assert.ok(keys.includes(k), k);
});

test('the FE wing mode set is a valid choice', () => {
  const { state, rejected } = parseQuery('?modes=fe&mode=2');
  assert.equal(state.modes, 'fe');
  assert.equal(state.mode, '2');
  assert.deepEqual(rejected, []);
});

test('long hostile keys are truncated', () => {
  const { rejected } = parsePairs([['x'.repeat(500), '1']]);
  assert.equal(rejected[0].key.length, 41);
});

test('panels list is validated', () => {
  assert.deepEqual(parseQuery('?panels=spectrum,time').state.panels, ['time', 'spectrum']);
  assert.equal(parseQuery('?panels=spectrum,evil').rejected[0].key, 'panels');
});

test('snap keeps values on the slider grid', () => {
  const g = NUMERIC.find((p) => p.key === 'gamma0');
  assert.equal(snap(g, 0.2 + 0.005 + 1e-15), 0.205);
  assert.equal(snap(g, -1), 0);
  assert.equal(snap(g, 9), 0.5);
});

test('overridesOf names every numeric parameter by key (the core applies them)', () => {
  const s = defaults();
  s.zeta = 0.01;
  s.gamma_phase = 0.5;
  const o = overridesOf(s);
  assert.deepEqual(
    Object.keys(o),
    NUMERIC.map((p) => p.key),
  );
  assert.equal(o.zeta, 0.01);
  assert.equal(o.gamma_phase, 0.5);
  assert.equal(o.gamma0, 0.2);
  // The SimConfig itself (γ0 as the first yaw harmonic, ζ on every mode, 10 kHz) is checked on
  // the real wasm in tests/js/wasm.test.mjs.
});

test('wing parameters: URL round trip, written only when not default, clamp=root, whole n_modes', async () => {
  const { WING, customWing } = await import('../../www/state.js');
  const d = defaults();
  assert.equal(customWing(d), false);
  assert.ok(!/camber|n_modes|planform|outline|clamp/.test(toQuery(d)), 'short links stay short');
  const { state, rejected } = parseQuery(
    '?camber=0.05&clamp=2.5&n_modes=6&mesh_mm=0&e_pa=2e9&outline=slender&planform=examples/w.csv&mode=6&modes=fe',
  );
  assert.deepEqual(rejected, []);
  assert.equal(state.camber, 0.05);
  assert.equal(state.clamp, 2.5);
  assert.equal(state.n_modes, 6);
  assert.equal(state.mesh_mm, 0);
  assert.equal(state.e_pa, 2e9);
  assert.equal(state.outline, 'slender');
  assert.equal(state.planform, 'examples/w.csv');
  assert.equal(customWing(state), true);
  const back = parseQuery('?' + toQuery(state));
  assert.deepEqual(back.state, state);
  assert.equal(parseQuery('?clamp=root').state.clamp, 0);
  for (const w of WING) assert.ok(w.min <= w.def && w.def <= w.max, w.key);
  const bad = parseQuery('?n_modes=2.5&n_modes2=1&camber=0.9&clamp=strip');
  assert.deepEqual(bad.rejected.map((r) => r.key).sort(), ['camber', 'clamp', 'n_modes', 'n_modes2']);
  assert.match(bad.rejected.find((r) => r.key === 'n_modes').why, /whole number/);
});

test('planform= takes only a relative same-origin .csv/.json path', async () => {
  const { safePlanformPath } = await import('../../www/state.js');
  for (const ok of ['w.csv', 'examples/planform-tapered.csv', 'a/b_c-d.JSON']) assert.equal(safePlanformPath(ok), ok);
  for (const bad of [
    'https://evil.example/w.csv',
    '//evil.example/w.csv',
    '/abs/w.csv',
    '../w.csv',
    'a/../../w.csv',
    'w.txt',
    'javascript:alert(1)//.csv',
    'w.csv?x=1',
    'w .csv',
    'x'.repeat(201) + '.csv',
  ]) {
    assert.equal(safePlanformPath(bad), null, bad);
  }
  assert.match(parseQuery('?planform=https://evil.example/w.csv').rejected[0].why, /relative same-origin/);
});
