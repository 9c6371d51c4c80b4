// The 3-D wing panel in real headless Chromium: WebGL2 with default flags, WebGPU with the
// flag set from the toolchain notes, and the no-adapter fallback. Pixels are checked, not just
// the absence of errors (a blank canvas raises no error). Run after scripts/build-web.sh www.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { setup, openPage, waitRenders, pngStats, pngDiff, labHelpers, OUT, CHROMIUM, ARGS } from './helpers.mjs';

const WEBGPU_FLAGS = [
  '--enable-unsafe-webgpu',
  '--enable-features=Vulkan',
  '--use-vulkan=swiftshader',
  '--use-angle=swiftshader',
];

let env;
before(async () => {
  env = await setup();
});
after(async () => {
  if (env) await env.close();
});

async function ready3d(page, timeout = 90000) {
  // The panel starts when it scrolls into sight.
  await page.locator('section.wl-wing3d').scrollIntoViewIfNeeded();
  await page.waitForFunction(
    () => {
      const b = __wl.q('[data-wing3d]');
      return (
        b &&
        (b.dataset.state === 'ready' || b.dataset.state === 'unavailable') &&
        (b.dataset.state !== 'ready' || Number(b.dataset.frames || 0) > 0)
      );
    },
    null,
    { timeout },
  );
  return page.evaluate(() => ({ ...__wl.q('[data-wing3d]').dataset }));
}

const frames = (page) => page.evaluate(() => Number(__wl.q('[data-wing3d]').dataset.frames || 0));
/** Waits until every frame asked for is on screen (the view draws in a worker: asynchronously). */
const settled = (page) => page.evaluate(() => document.querySelector('wing-lab').wing3d.settled());

/** Screenshot of the 3-D canvas with its pixel statistics (pngStats) and the PNG bytes. */
async function canvasStats(page, name) {
  await settled(page);
  const buf = await page
    .locator('wing-lab [data-wing3d] canvas.wl-w3-canvas')
    .screenshot({ path: path.join(OUT, name) });
  const st = await pngStats(page, buf);
  return { ...st, buf };
}

/**
 * Counts, in window.__readbacks, every read-back a page script makes: WebGL readPixels, 2-D
 * getImageData, and toBlob / toDataURL of a canvas (the 3-D view must make none while it plays;
 * the browser's own compositor copy of the canvas is not a page call and not counted).
 */
async function readbacks(page) {
  await page.addInitScript(() => {
    const w = /** @type {any} */ (window);
    w.__readbacks = [];
    const wrap = (proto, name) => {
      if (!proto || !proto[name]) return;
      const orig = proto[name];
      proto[name] = function (...args) {
        w.__readbacks.push(name);
        return orig.apply(this, args);
      };
    };
    wrap(globalThis.WebGL2RenderingContext?.prototype, 'readPixels');
    wrap(globalThis.WebGLRenderingContext?.prototype, 'readPixels');
    wrap(globalThis.CanvasRenderingContext2D?.prototype, 'getImageData');
    wrap(globalThis.HTMLCanvasElement?.prototype, 'toBlob');
    wrap(globalThis.HTMLCanvasElement?.prototype, 'toDataURL');
  });
}

test('WebGL2 (default flags): the wing flaps, bends and is coloured by strain', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url);
  await readbacks(page);
  await page.goto(env.url + '?screen=full'); // every panel, the view options open
  await waitRenders(page, 1);
  const ds = await ready3d(page);
  assert.equal(ds.state, 'ready', await page.textContent('wing-lab [data-wing3d]'));
  assert.equal(ds.backend, 'webgl2');
  assert.equal(ds.thread, 'worker', 'drawn off the main thread where the browser can');
  assert.match(await page.textContent('.wl-w3-status'), /WebGL2 · \d+ triangles/);
  // Paper mode set: the paper's q on the FE shapes, said so.
  assert.match(await page.textContent('section.wl-wing3d .wl-note'), /Table 4 units, not SI/);

  // A pose mid-stroke, γ_xy colouring: a wing with many colours over a plain background.
  await page.evaluate(() => document.querySelector('wing-lab').wing3d.setTime(0.01));
  const a = await canvasStats(page, 'wing3d-webgl2-gxy.png');
  assert.ok(
    a.foreground > 0.03 && a.foreground < 0.9,
    `wing covers part of the view: ${JSON.stringify({ ...a, buf: undefined })}`,
  );
  assert.ok(a.colours > 40, `strain colours and shading: ${a.colours}`);
  // The legend says what the colours mean, with units.
  assert.match(await page.textContent('.wl-w3-legend-text'), /gamma_xy|γ_xy|gxy/i);

  // Plain shading has far fewer hues than the strain colouring; the image changes.
  await page.selectOption('wing-lab [data-wing3d] ~ .wl-w3-controls select[aria-label="Colour the wing by"]', '0');
  const plain = await canvasStats(page, 'wing3d-webgl2-plain.png');
  assert.ok(!plain.buf.equals(a.buf), 'colour mode changes the picture');

  // A quarter flap period later (25 Hz → 0.01 s) the wing has rolled: the picture moves.
  await page.evaluate(() => document.querySelector('wing-lab').wing3d.setTime(0.02));
  const later = await canvasStats(page, 'wing3d-webgl2-later.png');
  assert.equal(
    await page.getAttribute('section.wl-wing3d input[aria-label^="Simulated time"]', 'aria-valuetext'),
    '0.0200 s',
  );
  assert.ok(!later.buf.equals(plain.buf), 'the pose follows time');

  // Play advances time and draws frames; the responses plot carries the 3-D cursor.
  const f0 = await frames(page);
  await page.click('.wl-w3-play');
  await page.waitForFunction((n) => Number(__wl.q('[data-wing3d]').dataset.frames) >= n + 10, f0, { timeout: 20000 });
  await page.click('.wl-w3-play');
  const t = await page.evaluate(() => document.querySelector('wing-lab').wing3d.t);
  assert.ok(t > 0.02, `time advanced: ${t}`);
  assert.ok(Math.abs((await page.evaluate(() => document.querySelector('wing-lab').timeCursor)) - t) < 2e-4);

  // The backing store is the canvas's CSS size × devicePixelRatio (1 here): nothing hidden
  // larger is drawn and scaled down.
  const bs = await page.evaluate(() => {
    const c = __wl.q('canvas.wl-w3-canvas');
    return {
      w: c.width,
      h: c.height,
      cw: c.clientWidth,
      ch: c.clientHeight,
      backing: __wl.q('[data-wing3d]').dataset.backing,
    };
  });
  assert.ok(Math.abs(bs.w - bs.cw) <= 1 && Math.abs(bs.h - bs.ch) <= 1, JSON.stringify(bs));
  assert.equal(bs.backing, `${bs.w}x${bs.h}`);

  // A played second reads nothing back from the canvas: no readPixels, getImageData or toBlob
  // on the 3-D canvas (counted by wrapping them before the page loads, see readbacks()).
  const rb0 = await page.evaluate(() => window.__readbacks.slice());
  const f2 = await frames(page);
  await page.click('.wl-w3-play');
  await page.waitForTimeout(1000);
  await page.click('.wl-w3-play');
  assert.ok((await frames(page)) > f2 + 3, 'it played');
  assert.deepEqual(await page.evaluate(() => window.__readbacks.slice()), rb0, 'no read-back while playing');

  // Orbit by keyboard on the focused canvas redraws.
  const f1 = await frames(page);
  await page.focus('wing-lab [data-wing3d] canvas');
  await page.keyboard.press('ArrowLeft');
  await page.waitForFunction((n) => Number(__wl.q('[data-wing3d]').dataset.frames) > n, f1, { timeout: 5000 });
  assert.deepEqual(problems, []);
  await context.close();
});

test('play pauses off screen and in a hidden tab, resumes when seen; phone backing store = CSS × DPR', async () => {
  // A phone at devicePixelRatio 3: the backing store is CSS × 2 (the cap), not × 3.
  const context = await env.browser.newContext({ viewport: { width: 390, height: 844 }, deviceScaleFactor: 3 });
  await labHelpers(context);
  const page = await context.newPage();
  await page.goto(env.url + '?screen=full'); // every panel, the view options open
  await waitRenders(page, 1);
  const ds = await ready3d(page);
  assert.equal(ds.state, 'ready');
  const bs = await page.evaluate(() => {
    const c = __wl.q('canvas.wl-w3-canvas');
    return {
      w: c.width,
      h: c.height,
      cw: c.getBoundingClientRect().width,
      ch: c.getBoundingClientRect().height,
      dpr: devicePixelRatio,
    };
  });
  assert.equal(bs.dpr, 3);
  assert.ok(Math.abs(bs.w - 2 * bs.cw) <= 2 && Math.abs(bs.h - 2 * bs.ch) <= 2, JSON.stringify(bs));

  const loop = () => page.evaluate(() => __wl.q('[data-wing3d]').dataset.loop);
  await page.locator('section.wl-wing3d').scrollIntoViewIfNeeded();
  await page.evaluate(() => document.querySelector('wing-lab').wing3d.setPlaying(true));
  await page.waitForFunction(() => __wl.q('[data-wing3d]').dataset.loop === 'running', null, { timeout: 5000 });
  const f0 = await frames(page);
  await page.waitForFunction((n) => Number(__wl.q('[data-wing3d]').dataset.frames) > n + 2, f0, { timeout: 10000 });

  // Scrolled out of sight: the loop stops drawing (the lab stays "playing").
  await page.evaluate(() => window.scrollTo(0, document.documentElement.scrollHeight));
  await page.waitForFunction(() => __wl.q('[data-wing3d]').dataset.loop === 'paused-offscreen', null, {
    timeout: 5000,
  });
  await settled(page); // (the frame in flight when it stopped)
  const f1 = await frames(page);
  await page.waitForTimeout(600);
  assert.equal(await frames(page), f1, 'no frames drawn off screen');
  assert.equal(await page.evaluate(() => document.querySelector('wing-lab').store.get().playing), true);

  // Back in sight: it plays on.
  await page.locator('section.wl-wing3d').scrollIntoViewIfNeeded();
  await page.waitForFunction(() => __wl.q('[data-wing3d]').dataset.loop === 'running', null, { timeout: 5000 });
  await page.waitForFunction((n) => Number(__wl.q('[data-wing3d]').dataset.frames) > n + 2, f1, { timeout: 10000 });

  // A hidden tab (document.hidden and its event, as the browser sends them): paused, then resumed.
  await page.evaluate(() => {
    Object.defineProperty(document, 'hidden', { configurable: true, get: () => true });
    document.dispatchEvent(new Event('visibilitychange'));
  });
  await page.waitForFunction(() => __wl.q('[data-wing3d]').dataset.loop === 'paused-hidden', null, { timeout: 5000 });
  await settled(page);
  const f2 = await frames(page);
  await page.waitForTimeout(400);
  assert.equal(await frames(page), f2, 'no frames drawn in a hidden tab');
  await page.evaluate(() => {
    Object.defineProperty(document, 'hidden', { configurable: true, get: () => false });
    document.dispatchEvent(new Event('visibilitychange'));
  });
  await page.waitForFunction(() => __wl.q('[data-wing3d]').dataset.loop === 'running', null, { timeout: 5000 });

  // Pause: the loop stops and the store holds the instant shown (the responses plot's cursor).
  await page.evaluate(() => document.querySelector('wing-lab').wing3d.setPlaying(false));
  assert.equal(await loop(), 'stopped');
  const t = await page.evaluate(() => [
    document.querySelector('wing-lab').wing3d.t,
    document.querySelector('wing-lab').timeCursor,
  ]);
  assert.equal(t[0], t[1]);
  await context.close();
});

test('FE wing mode set: SI responses drive the 3-D wing; numbers come from the shell FE', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url);
  await page.goto(env.url + '?modes=fe&gamma0=0.2&screen=full');
  await page.locator('section.wl-wing3d').scrollIntoViewIfNeeded();
  await page.waitForFunction(
    () => document.querySelector('wing-lab').fe && Number(document.querySelector('wing-lab').dataset.renders || 0) > 0,
    null,
    { timeout: 90000 },
  );
  const f1 = Number(await page.textContent('wing-lab [data-field="freq-0"]'));
  // The lab's FE wing is the CLI's default (1 mm elements), calibrated to the paper's 62.5 Hz.
  assert.ok(Math.abs(f1 - 62.49) < 0.02, `FE f1 = ${f1}`);
  const feff = Number(await page.textContent('wing-lab [data-field="feff-0"]'));
  assert.ok(feff < f1 && feff > f1 - 4, `centrifugal softening lowers f_eff: ${feff} vs ${f1}`);
  // The selected-mode labels name the FE modes.
  assert.match(await page.textContent('wing-lab select[data-key="mode"] option[value="1"]'), /FE, 6\d\.\d+ Hz/);
  const ds = await ready3d(page);
  assert.equal(ds.state, 'ready');
  await page.evaluate(() => document.querySelector('wing-lab').wing3d.setTime(0.5));
  await settled(page); // (the worker draws the frame; its texts follow)
  assert.match(await page.textContent('.wl-w3-status'), /true largest deflection [\d.e+-]+ mm/);
  assert.match(await page.textContent('wing-lab .wl-strain .wl-note'), /SI/);
  const st = await canvasStats(page, 'wing3d-fe.png');
  assert.ok(st.foreground > 0.03 && st.colours > 40, JSON.stringify({ ...st, buf: undefined }));
  assert.deepEqual(problems, []);
  await context.close();
});

test('WebGPU (flags from the toolchain notes): same panel on the WebGPU backend, non-blank', async () => {
  const browser = await chromium.launch({ executablePath: CHROMIUM, args: [...ARGS, ...WEBGPU_FLAGS], headless: true });
  try {
    const { page, context } = await openPage(browser, env.url);
    await page.goto(env.url + '?panels=controls,wing3d');
    const ds = await ready3d(page);
    assert.equal(ds.state, 'ready', await page.textContent('wing-lab [data-wing3d]'));
    assert.equal(ds.backend, 'webgpu');
    await page.evaluate(() => document.querySelector('wing-lab').wing3d.setTime(0.01));
    await page.waitForTimeout(300);
    const st = await canvasStats(page, 'wing3d-webgpu.png');
    assert.ok(st.foreground > 0.03 && st.colours > 40, JSON.stringify({ ...st, buf: undefined }));
    await context.close();
  } finally {
    await browser.close();
  }
});

test('no WebGPU and no WebGL2: the panel says why and the rest of the lab works', async () => {
  const { page, context } = await openPage(env.browser, env.url);
  await page.addInitScript(() => {
    Object.defineProperty(Navigator.prototype, 'gpu', { get: () => undefined, configurable: true });
    const orig = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (kind, ...rest) {
      if (/webgl|webgpu/.test(String(kind))) return null;
      return orig.call(this, kind, ...rest);
    };
    // and no OffscreenCanvas: the view is made on the page (the fallback), where the above applies
    globalThis.OffscreenCanvas = undefined;
  });
  await page.goto(env.url + '?screen=full'); // every panel, the view options open
  await waitRenders(page, 1);
  const ds = await ready3d(page);
  assert.equal(ds.state, 'unavailable');
  assert.match(
    await page.textContent('wing-lab [data-wing3d]'),
    /3-D view unavailable: .+\. Everything else in the lab works without it\./,
  );
  // The live panels are unaffected: numbers, and a slider recomputes.
  assert.equal(await page.textContent('wing-lab [data-field="feff-0"]'), '60.3064');
  const before = Number(await page.evaluate(() => document.querySelector('wing-lab').dataset.renders));
  await page.focus('wing-lab input[type=range][data-key="gamma0"]');
  await page.keyboard.press('ArrowLeft');
  await waitRenders(page, before + 1);
  assert.notEqual(await page.textContent('wing-lab [data-field="coriolis-0"]'), '53.79');
  await context.close();
});

test('the worker draws the pixels the page draws; a worker that cannot start falls back to the page', async () => {
  /** The 3-D canvas at t = 0.013 s, ε_x colours, drawn by the worker or (render="main") the page. */
  const shoot = async (main, name, route = null) => {
    const { page, problems, context } = await openPage(env.browser, env.url, undefined, { isolated: !!route });
    if (main)
      await page.addInitScript(() =>
        document.addEventListener('DOMContentLoaded', () =>
          document.querySelector('wing-lab').setAttribute('render', 'main'),
        ),
      );
    if (route) await context.route('**/render-worker.js', route);
    await page.goto(env.url + '?panels=controls,wing3d');
    const ds = await ready3d(page);
    assert.equal(ds.state, 'ready', await page.textContent('wing-lab [data-wing3d]'));
    await page.evaluate(() => {
      // (the view options are folded on this screen: set the colour as its select would)
      const sel = __wl.q('[data-wing3d] ~ .wl-w3-controls select[aria-label="Colour the wing by"]');
      sel.value = '1';
      sel.dispatchEvent(new Event('change', { bubbles: true }));
      document.querySelector('wing-lab').wing3d.setTime(0.013);
      // (the HTML labels over the canvas are placed by the page alike in both: compare the GPU's pixels)
      __wl.q('.wl-w3-overlay').style.visibility = 'hidden';
    });
    await page.waitForTimeout(300); // (a page-drawn WebGL frame can reach the screen a moment later)
    const st = await canvasStats(page, name);
    const legend = await page.textContent('.wl-w3-legend-text');
    const camera = await page.evaluate(() => document.querySelector('wing-lab').wing3d.camera);
    await context.close();
    return { ds, st, legend, camera, problems };
  };
  const w = await shoot(false, 'wing3d-thread-worker.png');
  const m = await shoot(true, 'wing3d-thread-main.png');
  assert.equal(w.ds.thread, 'worker');
  assert.equal(m.ds.thread, 'main');
  assert.deepEqual(w.problems, []);
  assert.ok(w.st.foreground > 0.03 && w.st.colours > 40, JSON.stringify({ ...w.st, buf: undefined }));
  // the same camera (the renderer's fit, run on the page for the worker) and the same legend
  for (const k of ['yaw', 'pitch', 'distance'])
    assert.ok(
      Math.abs(w.camera[k] - m.camera[k]) < 1e-4 * Math.max(1, Math.abs(m.camera[k])),
      `${k}: ${w.camera[k]} vs ${m.camera[k]}`,
    );
  assert.equal(w.legend, m.legend);
  const page = await (await env.browser.newContext()).newPage();
  const diff = await pngDiff(page, w.st.buf, m.st.buf, { shift: 1 });
  await page.context().close();
  // the same picture: one GPU rasteriser draws both (seen: identical, the element a pixel lower)
  assert.ok(diff.mean < 0.5 && diff.share < 0.002, `worker vs page: ${JSON.stringify(diff)}`);

  // A render worker that cannot make the view (here: it says so at once) → drawn on the page.
  const f = await shoot(false, 'wing3d-thread-fallback.png', (r) =>
    r.fulfill({
      contentType: 'text/javascript',
      body: "onmessage = () => postMessage({ op: 'failed', message: 'test: no GPU in this worker' });",
    }),
  );
  assert.equal(f.ds.thread, 'main');
  assert.match(f.ds.workerProblem || '', /test: no GPU in this worker/);
  const fd = await (async () => {
    const p2 = await (await env.browser.newContext()).newPage();
    const d = await pngDiff(p2, f.st.buf, m.st.buf, { shift: 1 });
    await p2.context().close();
    return d;
  })();
  assert.ok(fd.mean < 0.5 && fd.share < 0.002, `fallback vs page: ${JSON.stringify(fd)}`);
});
