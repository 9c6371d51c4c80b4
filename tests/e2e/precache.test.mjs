// The service worker's precache list is the build's manifest (www/precache.json, written by
// scripts/build-web.sh from the folder itself): on a first and a second visit of index.html no
// request of the page or of its service worker fails or asks for a file that does not exist (the
// server's own log, which sees the worker's requests too), the page logs no console error, and the
// copy holds exactly the manifest's files, each of which exists.
//   node --test --test-concurrency=1 tests/e2e/precache.test.mjs   (after scripts/build-web.sh www)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { setup, openPage, WITH_SERVICE_WORKER, waitRenders, ROOT } from './helpers.mjs';
import { startServer } from '../../scripts/serve.mjs';
import { precacheFiles } from '../../scripts/precache-manifest.mjs';

const WWW = path.join(ROOT, process.env.LAB_ROOT || 'www');
let env;
before(async () => {
  env = await setup();
});
after(async () => {
  if (env) await env.close();
});

test('the manifest lists the built folder’s real files (and only those)', () => {
  const m = JSON.parse(fs.readFileSync(path.join(WWW, 'precache.json'), 'utf8'));
  assert.equal(m.version, 1);
  for (const f of m.files)
    assert.ok(fs.statSync(path.join(WWW, f), { throwIfNoEntry: false })?.isFile(), `listed and present: ${f}`);
  for (const f of [
    'index.html',
    'lab.js',
    'worker.js',
    'views/studies.js',
    'pkg/wingbeat_bg.wasm',
    'vendor/uPlot.esm.js',
    'examples/planform-tapered.csv',
  ])
    assert.ok(m.files.includes(f), f);
  assert.ok(!m.files.some((f) => f === 'sw.js' || f === 'precache.json' || f.endsWith('.d.ts')));
  // The same rule as the build's (a stale manifest would miss a file added since).
  assert.deepEqual(m.files, precacheFiles(WWW));
});

test('first and second visit: no failed or missing request (page or service worker), no console error', async () => {
  const { server, url } = await startServer(WWW, 0);
  /** @type {{ path: string, status: number }[]} */
  const log = [];
  server.on('request', (req, res) =>
    res.on('finish', () => log.push({ path: String(req.url), status: res.statusCode })),
  );
  const { context, page, problems } = await openPage(env.browser, url, undefined, WITH_SERVICE_WORKER);
  try {
    await page.goto(url + 'index.html');
    await waitRenders(page, 1);
    // Installed, precached and in control (install finishes before activation).
    await page.waitForFunction(() => !!navigator.serviceWorker.controller, null, { timeout: 60000 });
    const cached = await page.evaluate(async () => {
      const names = (await caches.keys()).filter((n) => n.startsWith('wingbeat:'));
      const urls = [];
      for (const n of names) for (const r of await (await caches.open(n)).keys()) urls.push(r.url);
      return urls;
    });
    const bad1 = log.filter((r) => r.status >= 400);
    assert.deepEqual(bad1, [], 'first visit: every request answered');
    const m = JSON.parse(fs.readFileSync(path.join(WWW, 'precache.json'), 'utf8'));
    for (const f of m.files) assert.ok(cached.includes(url + f), `precached: ${f}`);
    assert.ok(
      log.some((r) => r.path === '/precache.json'),
      'the worker read the manifest',
    );
    const first = log.length;
    // Second visit: a reload, then the page opened again in a new tab of the same browser. (The
    // first page's late loads — the worker's modules — finish first: a reload would cancel them.)
    await page.waitForLoadState('networkidle');
    await page.reload();
    await waitRenders(page, 1);
    const p2 = await context.newPage();
    const more = [];
    p2.on('console', (msg) => {
      if (msg.type() === 'error') more.push(`console: ${msg.text()}`);
    });
    p2.on('pageerror', (e) => more.push(`pageerror: ${e.message}`));
    await p2.goto(url + 'index.html?gamma0=0.1');
    await waitRenders(p2, 1);
    await page.waitForLoadState('networkidle');
    await p2.waitForLoadState('networkidle');
    assert.ok(log.length > first, 'the second visit went to the server (network first)');
    assert.deepEqual(
      log.filter((r) => r.status >= 400),
      [],
      'second visit: every request answered',
    );
    assert.deepEqual([...problems, ...more], [], 'no console error, page error or failed request');
  } finally {
    await context.close();
    server.close();
  }
});
