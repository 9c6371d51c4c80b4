// The lab's bundle (scripts/bundle.mjs): lab.js and its modules in one file; stale when a module
// is newer; `npm start`'s server (scripts/serve.mjs --rebundle) rebuilds it before sending it, so
// an edited module shows on reload; a server without the option sends the file as it is.
// Run: node --test tests/js/bundle.test.mjs
import { test, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import http from 'node:http';
import { bundle, bundleStale, BUNDLE } from '../../scripts/bundle.mjs';
import { startServer } from '../../scripts/serve.mjs';

const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'wingbeat-bundle-'));
after(() => fs.rmSync(dir, { recursive: true, force: true }));

const write = (rel, text, ageS = 0) => {
  const f = path.join(dir, rel);
  fs.mkdirSync(path.dirname(f), { recursive: true });
  fs.writeFileSync(f, text);
  const t = new Date(Date.now() + ageS * 1000);
  fs.utimesSync(f, t, t);
};
const get = (url) =>
  new Promise((resolve, reject) => {
    http
      .get(url, (res) => {
        const chunks = [];
        res.on('data', (c) => chunks.push(c));
        res.on('end', () => resolve({ status: res.statusCode, body: Buffer.concat(chunks).toString() }));
      })
      .on('error', reject);
  });

test('one file from the module graph; stale when a module (not pkg/ or vendor/) is newer', async () => {
  write('lab.js', "import { A } from './views/a.js';\nexport const LAB = 'lab:' + A;\n", -60);
  write('views/a.js', "export const A = 'first-version';\n", -60);
  write('embed-api.js', "export const startEmbedApi = () => 'api';\n", -60);
  write('offline.js', "export const registerOffline = () => 'sw';\n", -60);
  write('pkg/glue.js', 'export const G = 1;\n', -60);
  assert.equal(bundleStale(dir), true, 'no bundle yet');
  const r = await bundle(dir);
  assert.ok(r.inputs >= 4, `${r.inputs} inputs`);
  const text = fs.readFileSync(path.join(dir, BUNDLE), 'utf8');
  assert.match(text, /first-version/);
  assert.doesNotMatch(text, /\bimport\b.*views\/a\.js/, 'the module is inside, not imported');
  assert.equal(bundleStale(dir), false);
  // The page takes the element, the embedding API and the service worker's registration from it.
  const m = await import(`${path.join(dir, BUNDLE)}?v=1`);
  assert.equal(m.LAB, 'lab:first-version');
  assert.equal(m.embedApi.startEmbedApi(), 'api');
  assert.equal(m.offline.registerOffline(), 'sw');
  write('pkg/glue.js', 'export const G = 2;\n', 60);
  assert.equal(bundleStale(dir), false, 'pkg/ is not bundled');
  write('views/a.js', "export const A = 'second-version';\n", 60);
  assert.equal(bundleStale(dir), true, 'an edited module');
});

test('the --rebundle server sends the bundle of the modules as they are now; without it, the file', async () => {
  write('index.html', '<p>lab</p>');
  write('pkg/wingbeat.js', '// glue\n');
  const plain = await startServer(dir, 0, { warm: false });
  const live = await startServer(dir, 0, { warm: false, rebundle: true });
  try {
    const before = await get(new URL(BUNDLE, plain.url));
    assert.match(before.body, /first-version/, 'as built');
    const fresh = await get(new URL(BUNDLE, live.url));
    assert.equal(fresh.status, 200);
    assert.match(fresh.body, /second-version/, 'rebuilt with the edited module');
    write('views/a.js', "export const A = 'third-version';\n", 120);
    assert.match((await get(new URL(BUNDLE, live.url))).body, /third-version/);
    assert.match((await get(new URL('views/a.js', live.url))).body, /third-version/, 'the modules are served too');
  } finally {
    plain.server.close();
    live.server.close();
  }
});
