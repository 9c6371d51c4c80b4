// The lab's first load (issue 25): the first plot comes from the small live build of the wasm
// module (pkg/wingbeat_live_bg.wasm) and the full build (shell FE, sensing, renderer) loads
// behind it. With the full build unreachable, the paper case is still computed, drawn and
// re-computed on a slider press (in the live worker, which was given the live build), and the
// 3-D view says why it is missing; with both, each module is downloaded once (the workers get
// the page's compiled modules), the live one first, the page runs the bundle of the lab's modules
// (not the modules one by one), the full build's wasm is fetched together with its glue (not
// after it), and the 3-D wing is drawn.
//   node --test --test-concurrency=1 tests/e2e/first_load.test.mjs   (after scripts/build-web.sh www)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { setup, openPage, WITH_SERVICE_WORKER, waitRenders, renders, plotPrint, waitWing3d } from './helpers.mjs';

let env;
before(async () => {
  env = await setup();
});
after(async () => {
  if (env) await env.close();
});

const cell = (page, field) => page.textContent(`wing-lab [data-field="${field}"]`);
/** A wasm request of the page or its dedicated workers (the service worker's precache is left out). */
const pageWasm = (/** @type {import('playwright-core').Request} */ r) =>
  new URL(r.url()).pathname.endsWith('.wasm') && !r.serviceWorker();

test('without the full build: the paper case from the live build, a slider recomputes, the 3-D view says why it is missing', async () => {
  const { page, context } = await openPage(env.browser, env.url, { width: 1280, height: 800 }, WITH_SERVICE_WORKER);
  const asked = [];
  context.on('request', (r) => {
    if (pageWasm(r)) asked.push(new URL(r.url()).pathname);
  });
  await context.route(/\/pkg\/wingbeat(_bg\.wasm|\.js)$/, (route) => route.abort());
  try {
    await page.goto(env.url);
    await waitRenders(page, 1);
    // The paper's numbers (tests/e2e/lab.test.mjs has the same case with the full build).
    assert.equal(await cell(page, 'feff-0'), '60.3064');
    assert.equal(await cell(page, 'freq-0'), '62.5');
    assert.match(await cell(page, 'beat2-0'), /^0\.0970/);
    const state = await page.evaluate(() => {
      const e = /** @type {any} */ (document.querySelector('wing-lab')).engine;
      return { ready: e.ready, full: e.fullReady };
    });
    assert.deepEqual(state, { ready: true, full: false });
    // A slider press: recomputed (in the live worker once it is warm, else here).
    const print0 = await plotPrint(page);
    const n0 = await renders(page);
    await page.focus('wing-lab input[type=range][data-key="gamma0"]');
    await page.keyboard.press('ArrowRight');
    await waitRenders(page, n0 + 1);
    assert.notDeepEqual(await plotPrint(page), print0, 'γ0 changed the plotted responses');
    const lab = await page.evaluate(() => {
      const e = /** @type {any} */ (document.querySelector('wing-lab')).engine;
      return { inWorker: e.liveInWorker, stats: { ...e.liveStats } };
    });
    // The 3-D view: a clear sentence, not a blank box.
    await page.waitForFunction(() => __wl.q('[data-wing3d]')?.dataset.state === 'unavailable', null, {
      timeout: 30000,
    });
    assert.match(
      await page.evaluate(() => __wl.q('[data-wing3d]').textContent),
      /3-D view unavailable: the renderer could not be loaded/,
    );
    assert.ok(asked.includes('/pkg/wingbeat_live_bg.wasm'), asked.join(' '));
    // Only the blocked full build was refused: the live one loaded once.
    assert.equal(asked.filter((p) => p === '/pkg/wingbeat_live_bg.wasm').length, 1, JSON.stringify(lab));
  } finally {
    await context.close();
  }
});

test('with both builds: the live one is asked for first, each is downloaded once, the 3-D wing is drawn', async () => {
  const { page, context, problems } = await openPage(
    env.browser,
    env.url,
    { width: 1280, height: 800 },
    WITH_SERVICE_WORKER,
  );
  /** @type {string[]} */
  const wasm = [];
  /** @type {string[]} script requests of the page and its workers (not the service worker's precache) */
  const scripts = [];
  context.on('request', (r) => {
    if (pageWasm(r)) wasm.push(new URL(r.url()).pathname);
    if (!r.serviceWorker() && new URL(r.url()).pathname.endsWith('.js')) scripts.push(new URL(r.url()).pathname);
  });
  // The full build's glue is held back (up to 3 s): its wasm, the big download, must be asked
  // for meanwhile, not only once the glue has arrived and run.
  let wasmWhileGlueHeld = null;
  await context.route(/\/pkg\/wingbeat\.js$/, async (route) => {
    const t0 = Date.now();
    while (wasmWhileGlueHeld === null && !wasm.includes('/pkg/wingbeat_bg.wasm') && Date.now() - t0 < 3000)
      await new Promise((r) => setTimeout(r, 20));
    // (the first glue request is the page's; the workers' come later and are not held for this)
    if (wasmWhileGlueHeld === null) wasmWhileGlueHeld = wasm.includes('/pkg/wingbeat_bg.wasm');
    await route.continue();
  });
  try {
    await page.goto(env.url);
    await waitRenders(page, 1);
    await waitWing3d(page);
    assert.equal(
      wasmWhileGlueHeld,
      true,
      `the full module's wasm asked for while its glue was on the way: ${wasm.join(' ')}`,
    );
    // The live worker runs a slider's recompute with the live build it was handed.
    await page.focus('wing-lab input[type=range][data-key="beta0"]');
    for (let i = 0; i < 3; i++) {
      const n = await renders(page);
      await page.keyboard.press('ArrowRight');
      await waitRenders(page, n + 1);
    }
    const e = await page.evaluate(() => {
      const en = /** @type {any} */ (document.querySelector('wing-lab')).engine;
      return { full: en.fullReady, renderer: en.hasRenderer, inWorker: en.liveInWorker, stats: { ...en.liveStats } };
    });
    // The page runs the bundle of the lab's modules (scripts/bundle.mjs), not the modules.
    assert.ok(scripts.includes('/lab.bundle.js'), scripts.join(' '));
    for (const m of ['/lab.js', '/state.js', '/engine.js', '/views/numbers.js'])
      assert.ok(!scripts.includes(m), `${m} fetched: ${scripts.join(' ')}`);
    assert.equal(e.full, true);
    assert.equal(e.renderer, true);
    assert.equal(wasm[0], '/pkg/wingbeat_live_bg.wasm', wasm.join(' '));
    assert.deepEqual([...wasm].sort(), ['/pkg/wingbeat_bg.wasm', '/pkg/wingbeat_live_bg.wasm'], wasm.join(' '));
    if (e.inWorker) assert.ok(e.stats.posted >= 1, JSON.stringify(e.stats));
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('a study at startup (modes=fe: the FE wing in the study worker) waits for the page’s full module: one download, and the worker is handed it', async () => {
  const { page, context, problems } = await openPage(
    env.browser,
    env.url,
    { width: 1280, height: 800 },
    WITH_SERVICE_WORKER,
  );
  /** @type {string[]} */
  const wasm = [];
  context.on('request', (r) => {
    if (pageWasm(r)) wasm.push(new URL(r.url()).pathname);
  });
  try {
    await page.goto(`${env.url}?modes=fe`);
    // The FE wing's first mode (the shell FE, not the paper table's 62.5 Hz).
    await page.waitForFunction(() => __wl.q('[data-field="freq-0"]')?.textContent === '62.49', null, {
      timeout: 60000,
    });
    assert.deepEqual(
      wasm.filter((p) => p === '/pkg/wingbeat_bg.wasm'),
      ['/pkg/wingbeat_bg.wasm'],
      `the full module is fetched once (the page's), not again by the worker: ${wasm.join(' ')}`,
    );
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
