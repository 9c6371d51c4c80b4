// WingView's methods (the 3-D view; node has no canvas, so tests/js/wasm_hostile_inputs.test.mjs
// reaches only its constructors) called in headless Chromium with random arguments of every JS
// type from a seeded PRNG, mixed with valid ones: after every call nothing trapped
// (WebAssembly.RuntimeError), the view still answers (camera() gives six finite numbers and
// set_frame with valid arguments works), and every refusal is an Error naming its argument in
// backticks. Run after scripts/build-web.sh www.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { setup } from './helpers.mjs';

let env;
before(async () => {
  env = await setup();
});
after(async () => {
  if (env) await env.close();
});

test('WingView methods refuse hostile arguments by name, without trapping or leaving the view dead', async (t) => {
  const page = await env.browser.newPage();
  // any light same-origin document will do (the lab page itself would start its own work)
  await page.goto(`${env.url}/style.css`);
  const out = await page.evaluate(async () => {
    const wb = await import('/pkg/wingbeat.js');
    await wb.default();
    const canvas = document.createElement('canvas');
    canvas.width = 64;
    canvas.height = 48;
    document.body.appendChild(canvas);
    const view = await wb.WingView.createSynthetic(canvas, 8, 4);
    let a = 20 >>> 0;
    const r = () => {
      a = (a + 0x6d2b79f5) >>> 0;
      let x = a;
      x = Math.imul(x ^ (x >>> 15), x | 1);
      x ^= x + Math.imul(x ^ (x >>> 7), x | 61);
      return ((x ^ (x >>> 14)) >>> 0) / 4294967296;
    };
    const pick = (xs) => xs[Math.floor(r() * xs.length)];
    const hostile = () =>
      pick([
        () => ['undefined', undefined],
        () => ['null', null],
        () => ['NaN', NaN],
        () => ['Infinity', Infinity],
        () => ['-0', -0],
        () => ['2^53', 2 ** 53],
        () => ['2^32', 2 ** 32],
        () => ['-1', -1],
        () => ['1.5', 1.5],
        () => ['1e300', 1e300],
        () => ['"3"', '3'],
        () => ['"ArrowLeft"', 'ArrowLeft'],
        () => ['long string', 'x'.repeat(1e6)],
        () => ['true', true],
        () => ['symbol', Symbol('s')],
        () => ['bigint', 10n],
        () => ['function', () => 1],
        () => ['{}', {}],
        () => ['{ length: 2e9 }', { length: 2e9 }],
        () => [
          'sparse 2^32-1',
          (() => {
            const x = [];
            x.length = 2 ** 32 - 1;
            return x;
          })(),
        ],
        () => ['[1, 2]', [1, 2]],
        () => ['["1"]', ['1']],
        () => ['Float64Array(3)', new Float64Array(3)],
        () => ['Float32Array(9)', new Float32Array(9)],
        () => ['BigInt64Array(2)', new BigInt64Array(2)],
        () => ['Float64Array(1e6)', new Float64Array(1e6)],
        () => [
          'revoked proxy',
          (() => {
            const p = Proxy.revocable([], {});
            p.revoke();
            return p.proxy;
          })(),
        ],
        () => [
          'throwing getter',
          {
            get length() {
              throw new Error('g');
            },
          },
        ],
      ])();
    const q = new Float64Array(2);
    let nNodes = 0;
    for (let n = 1; n <= 2000 && !nNodes; n++) {
      try {
        view.setNodeField(new Float64Array(n), 1);
        nNodes = n;
      } catch {
        /* not the node count */
      }
    }
    const valid = {
      set_frame: [0.1, 0.2, 0.3, q, 10, 4],
      setPose: [0.1, 0.2, 0.3, q],
      set_strain_range: [null],
      setNodeField: [new Float64Array(nNodes), 1],
      set_scene: [true, false, true],
      setCamera: [0, 0, 0, 0.5, 0.3, 0.2],
      fitPoints: [new Float32Array([0, 0, 0, 0.05, 0, 0]), 0.04],
      resize: [64, 48],
      orbit: [3, 4],
      zoom: [1.1],
      key: ['ArrowLeft'],
      render: [],
      camera: [],
      legend_stops: [],
      backend: [],
      triangles: [],
    };
    const methods = Object.keys(valid);
    const counts = { calls: 0, refused: 0, traps: 0, dead: 0, unclear: 0 };
    const problems = [];
    const alive = () => {
      try {
        const c = view.camera();
        view.set_frame(0.1, 0.2, 0.3, q, 10, 4);
        return c.length === 6 && c.every(Number.isFinite);
      } catch {
        return false;
      }
    };
    for (let i = 0; i < 1500; i++) {
      const name = pick(methods);
      const v = valid[name];
      const n = Math.max(v.length, 1);
      const which = Math.floor(r() * n);
      const all = r() < 0.25;
      const labels = [];
      const args = [];
      for (let j = 0; j < n; j++) {
        if (!all && j !== which && j < v.length) {
          args.push(v[j]);
          labels.push('valid');
        } else {
          const [l, x] = hostile();
          args.push(x);
          labels.push(l);
        }
      }
      counts.calls++;
      try {
        view[name](...args);
      } catch (e) {
        counts.refused++;
        const what = `${name}(${labels.join(', ')})`;
        if (e instanceof WebAssembly.RuntimeError) {
          counts.traps++;
          problems.push(`TRAP ${what}: ${e.message}`);
        } else if (!(e instanceof Error) || !/`[^`]+`|fitPoints: /.test(e.message)) {
          counts.unclear++;
          problems.push(`UNCLEAR ${what}: ${e && e.message}`.slice(0, 300));
        }
      }
      if (!alive()) {
        counts.dead++;
        problems.push(`DEAD after ${name}(${labels.join(', ')})`);
        break;
      }
    }
    return { counts, problems: problems.slice(0, 30) };
  });
  t.diagnostic(JSON.stringify(out.counts));
  for (const p of out.problems) t.diagnostic(p);
  assert.ok(out.counts.calls >= 500);
  assert.deepEqual(
    { traps: out.counts.traps, dead: out.counts.dead, unclear: out.counts.unclear },
    { traps: 0, dead: 0, unclear: 0 },
    out.problems.join('\n'),
  );
  await page.close();
});

test('the constructors take an HTMLCanvasElement or an OffscreenCanvas, and refuse anything else by name', async () => {
  const page = await env.browser.newPage();
  await page.goto(`${env.url}/style.css`);
  const out = await page.evaluate(async () => {
    const wb = await import('/pkg/wingbeat.js');
    await wb.default();
    const refused = [];
    for (const [label, c] of [
      ['{}', {}],
      ['null', null],
      ['a div', document.createElement('div')],
      ['a string', 'canvas'],
    ]) {
      try {
        await wb.WingView.createSynthetic(c, 4, 2);
        refused.push(`${label}: accepted`);
      } catch (e) {
        refused.push(`${label}: ${e instanceof WebAssembly.RuntimeError ? 'TRAP' : ''}${e.message}`);
      }
    }
    // an OffscreenCanvas (as a worker gets one) draws like a canvas of the page
    const off = new OffscreenCanvas(32, 24);
    const view = await wb.WingView.createSynthetic(off, 4, 2);
    view.set_frame(0.1, 0.2, 0.3, new Float64Array(2), 10, 4);
    view.render();
    const backend = view.backend();
    view.free();
    return { refused, backend };
  });
  for (const r of out.refused)
    assert.match(r, /^[^:]+: invalid value for `canvas`: .*an HTMLCanvasElement or an OffscreenCanvas/, r);
  assert.match(out.backend, /^(webgpu|webgl2)$/);
  await page.close();
});
