// Offline use (www/offline.js registers www/sw.js from the page's main.js): after one visit of
// index.html over http://127.0.0.1 the service worker controls the page and holds the site's
// files; with the network blocked (context offline AND the server stopped) a reload computes,
// and the FE wing (modes=fe, computed in the worker, never fetched online) works too.
// `?offline=0` registers nothing and removes an earlier registration. file:// in Chromium: the
// lab does not start (what docs/embedding.md says). The single-folder download (dist/, when
// built) runs from its own `node serve.mjs` and from `python3 -m http.server`.
// Run: node --test --test-concurrency=1 tests/e2e/offline.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import fs from 'node:fs';
import { spawn, spawnSync } from 'node:child_process';
import { pathToFileURL } from 'node:url';
import { setup, openPage, WITH_SERVICE_WORKER, waitRenders, OUT, ROOT } from './helpers.mjs';
import { startServer } from '../../scripts/serve.mjs';

/** @type {Awaited<ReturnType<typeof setup>>} */
let env;
before(async () => {
  env = await setup();
});
after(async () => {
  await env.close();
});

/** Waits until a service worker controls the page; returns its cache names and cached URLs. */
async function waitControlled(page) {
  await page.waitForFunction(() => !!navigator.serviceWorker.controller, null, { timeout: 30000 });
  return page.evaluate(async () => {
    const names = (await caches.keys()).filter((n) => n.startsWith('wingbeat:'));
    const urls = [];
    for (const n of names) for (const r of await (await caches.open(n)).keys()) urls.push(r.url);
    return { names, urls };
  });
}

/** Polls an async predicate in the page (waitForFunction does not await promises). */
async function poll(page, fn, timeout = 15000) {
  const end = Date.now() + timeout;
  for (;;) {
    if (await page.evaluate(fn)) return;
    if (Date.now() > end) throw new Error(`timed out: ${fn}`);
    await page.waitForTimeout(200);
  }
}

test('after one visit the lab and the FE wing work with the network blocked', async () => {
  // A server of its own, so that stopping it blocks only this test.
  const { server, url } = await startServer(path.join(process.cwd(), 'www'), 0);
  const { context, page } = await openPage(env.browser, url, undefined, WITH_SERVICE_WORKER);
  /** @type {Set<string>} */
  const online = new Set();
  page.on('request', (r) => {
    const u = new URL(r.url());
    if (u.origin === new URL(url).origin && !u.pathname.endsWith('/sw.js')) {
      u.hash = '';
      if (r.isNavigationRequest()) u.search = '';
      online.add(u.href);
    }
  });
  try {
    await page.goto(url + 'index.html');
    await waitRenders(page, 1);
    // The real page path: main.js imports offline.js, which registers sw.js.
    const { names, urls } = await waitControlled(page);
    assert.equal(names.length, 1, `one cache: ${names}`);
    assert.match(
      names[0],
      new RegExp(`^wingbeat:${url.replace(/[.]/g, '\\.')}:`),
      'cache name: prefix, scope, build stamp',
    );
    const cached = new Set(urls);
    for (const f of [
      '',
      'index.html',
      'main.js',
      'offline.js',
      'lab.js',
      'worker.js',
      'engine.js',
      'style.css',
      'pkg/wingbeat.js',
      'pkg/wingbeat_bg.wasm',
      'vendor/uPlot.esm.js',
      'views/wing3d.js',
      'views/strain.js',
    ]) {
      assert.ok(cached.has(url + f), `precached: ${f || './'}`);
    }
    for (const u of online) assert.ok(cached.has(u), `every file the first visit fetched is cached: ${u}`);
    assert.ok(!urls.some((u) => u.endsWith('/sw.js')), 'sw.js itself is not cached');

    // Network gone: the browser context is offline and the server is stopped.
    await context.setOffline(true);
    await new Promise((resolve) => {
      server.closeAllConnections();
      server.close(resolve);
    });
    await page.reload();
    await waitRenders(page, 1);
    const paper = await page.evaluate(() => {
      const l = /** @type {any} */ (document.querySelector('wing-lab'));
      return {
        modes: l.analysis.sim.modes.length,
        f: l.analysis.sim.modes[0].floquet.effective_freq_hz,
        controlled: !!navigator.serviceWorker.controller,
        online: navigator.onLine,
      };
    });
    assert.equal(paper.controlled, true);
    assert.equal(paper.online, false);
    assert.equal(paper.modes, 2);
    assert.ok(Number.isFinite(paper.f) && paper.f > 0);

    // The FE wing: worker.js, its wasm and the FE views were never used online.
    await page.goto(url + 'index.html?modes=fe');
    await page.waitForFunction(
      () => {
        const l = /** @type {any} */ (document.querySelector('wing-lab'));
        const s = l && l.store && l.store.get();
        return (
          s &&
          s.fe &&
          s.fe.n_modes === 2 &&
          l.analysis &&
          l.analysis.sim.modes.length === 2 &&
          Number(l.dataset.renders) >= 1
        );
      },
      null,
      { timeout: 120000 },
    );
    const fe = await page.evaluate(() =>
      Array.from(/** @type {any} */ (document.querySelector('wing-lab')).store.get().fe.freq_hz),
    );
    assert.ok(Math.abs(fe[0] - 62.49) < 0.5, `FE f1 offline ${fe[0]} Hz (62.49 Hz online)`);
    await page.screenshot({ path: path.join(OUT, 'offline-fe.png') });
    const status = await page
      .locator('wing-lab [role="status"]')
      .first()
      .textContent()
      .catch(() => '');
    assert.doesNotMatch(String(status), /failed|error/i);
  } finally {
    await context.close();
    server.close();
  }
});

test('?offline=0 registers no service worker and removes an earlier one', async () => {
  const { context, page } = await openPage(env.browser, env.url, undefined, WITH_SERVICE_WORKER);
  try {
    await page.goto(env.url + 'index.html?offline=0');
    await waitRenders(page, 1);
    // offline.js runs after lab.js; give it time to (not) register.
    await page.waitForFunction(() => localStorage.getItem('wingbeat-offline') === 'off', null, { timeout: 10000 });
    await page.waitForTimeout(1500);
    const none = await page.evaluate(async () => ({
      regs: (await navigator.serviceWorker.getRegistrations()).length,
      controlled: !!navigator.serviceWorker.controller,
    }));
    assert.deepEqual(none, { regs: 0, controlled: false });
    // The choice is remembered (the lab rewrites its query, offline=0 leaves the address).
    await page.goto(env.url + 'index.html');
    await waitRenders(page, 1);
    await page.waitForTimeout(1500);
    assert.equal(await page.evaluate(async () => (await navigator.serviceWorker.getRegistrations()).length), 0);
    // offline=1 turns it back on; offline=0 then unregisters and deletes the caches.
    await page.goto(env.url + 'index.html?offline=1');
    await waitControlled(page);
    await page.goto(env.url + 'index.html?offline=0');
    await poll(page, async () => (await navigator.serviceWorker.getRegistrations()).length === 0);
    await poll(page, async () => (await caches.keys()).filter((n) => n.startsWith('wingbeat:')).length === 0);
    // and does not come back while the page (still controlled until it unloads) fetches files
    await page.evaluate(() => fetch('lab.js').then((r) => r.text()));
    // A page that was controlled stays so until it unloads; a new tab is not controlled.
    await page.close();
    await new Promise((r) => setTimeout(r, 1000));
    const fresh = await context.newPage();
    await fresh.goto(env.url + 'index.html');
    await waitRenders(fresh, 1);
    await fresh.waitForTimeout(1500);
    assert.deepEqual(
      await fresh.evaluate(async () => ({
        caches: (await caches.keys()).filter((n) => n.startsWith('wingbeat:')),
        regs: (await navigator.serviceWorker.getRegistrations()).length,
        controlled: !!navigator.serviceWorker.controller,
      })),
      { caches: [], regs: 0, controlled: false },
    );
  } finally {
    await context.close();
  }
});

test('file:// in Chromium: the lab does not start (module import, fetch and worker refused), nothing is registered', async () => {
  const { context, page } = await openPage(env.browser, env.url, undefined, WITH_SERVICE_WORKER);
  /** @type {string[]} */
  const errors = [];
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  page.on('pageerror', (e) => errors.push(e.message));
  try {
    await page.goto(pathToFileURL(path.join(ROOT, 'www', 'index.html')).href);
    await page.waitForTimeout(3000);
    const r = await page.evaluate(async () => {
      /** @type {Record<string, string>} */
      const out = { defined: String(!!customElements.get('wing-lab')), origin: location.origin };
      try {
        await fetch('pkg/wingbeat_bg.wasm');
        out.fetch = 'ok';
      } catch (e) {
        out.fetch = String(e);
      }
      try {
        new Worker('worker.js', { type: 'module' });
        out.worker = 'constructed';
      } catch (e) {
        out.worker = String(e);
      }
      try {
        out.regs = String((await navigator.serviceWorker.getRegistrations()).length);
      } catch (e) {
        out.regs = String(e);
      }
      return out;
    });
    assert.equal(r.defined, 'false', 'the element never defines');
    assert.match(errors.join('\n'), /lab\.js.*(CORS|origin 'null')|Failed to fetch dynamically imported module/);
    assert.match(r.fetch, /Failed to fetch/);
    assert.match(r.worker, /SecurityError.*cannot be accessed from origin 'null'/);
    assert.notEqual(r.regs, '1');
  } finally {
    await context.close();
  }
});

/** Starts a command that prints a loopback URL or port; resolves to { url, stop }. */
function spawnServer(cmd, args, cwd, pattern) {
  return new Promise((resolve, reject) => {
    const child = spawn(cmd, args, { cwd, stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '';
    const timer = setTimeout(() => {
      child.kill();
      reject(new Error(`${cmd}: no address in 10 s: ${out}`));
    }, 10000);
    const read = (/** @type {Buffer} */ b) => {
      out += b.toString();
      const m = pattern.exec(out);
      if (m) {
        clearTimeout(timer);
        resolve({ url: m[1].startsWith('http') ? m[1] : `http://127.0.0.1:${m[1]}/`, stop: () => child.kill() });
      }
    };
    child.stdout.on('data', read);
    child.stderr.on('data', read);
    child.on('error', (e) => {
      clearTimeout(timer);
      reject(e);
    });
  });
}

test('the single-folder download (dist/) runs from node serve.mjs and from python3 -m http.server', async () => {
  // Never skipped: npm test builds dist/ first (scripts/test-all.sh e2e); a missing build fails here.
  const dist = path.join(ROOT, 'dist');
  assert.ok(fs.existsSync(path.join(dist, 'serve.mjs')), 'dist/ is not built: run `npm run build` (npm test does)');
  for (const f of [
    'index.html',
    'sw.js',
    'offline.js',
    'worker.js',
    'README.txt',
    'serve.mjs',
    'serve-lib.mjs',
    'pkg/wingbeat.js',
    'pkg/wingbeat_bg.wasm',
    'vendor/uPlot.esm.js',
  ]) {
    assert.ok(fs.existsSync(path.join(dist, f)), `dist/${f}`);
  }
  const stamp = /const BUILD = '([0-9a-f]{12})';/.exec(fs.readFileSync(path.join(dist, 'sw.js'), 'utf8'));
  assert.ok(stamp, 'dist/sw.js carries a build stamp');
  const servers = [['node', ['serve.mjs', '0'], /(http:\/\/127\.0\.0\.1:\d+\/)/]];
  if (spawnSync('python3', ['--version']).status === 0)
    servers.push(['python3', ['-u', '-m', 'http.server', '0', '--bind', '127.0.0.1'], /port (\d+)/]);
  for (const [cmd, args, pattern] of servers) {
    const srv = await spawnServer(
      /** @type {string} */ (cmd),
      /** @type {string[]} */ (args),
      dist,
      /** @type {RegExp} */ (pattern),
    );
    const { context, page } = await openPage(env.browser, srv.url, undefined, WITH_SERVICE_WORKER);
    try {
      await page.goto(srv.url);
      await waitRenders(page, 1);
      const { names } = await waitControlled(page);
      assert.deepEqual(names, [`wingbeat:${srv.url}:${stamp[1]}`], `${cmd}: cache named with the build stamp`);
    } finally {
      await context.close();
      srv.stop();
    }
  }
});
