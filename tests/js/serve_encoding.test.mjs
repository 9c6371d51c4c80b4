// The lab's server (scripts/serve.mjs) sends a file's precompressed copy (scripts/precompress.mjs)
// to a browser that accepts it: Brotli first, then gzip, never a copy older than the file,
// never an encoding refused with q=0; the bytes decode to the file; Vary and Content-Length say
// what was sent; the precache list leaves the copies out.
// Run: node --test tests/js/serve_encoding.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import http from 'node:http';
import zlib from 'node:zlib';
import { startServer } from '../../scripts/serve.mjs';
import { precompress, compressible } from '../../scripts/precompress.mjs';
import { precacheFiles } from '../../scripts/precache-manifest.mjs';

let dir;
let srv;
const text = 'export const x = 1;\n'.repeat(500);

before(async () => {
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'wingbeat-serve-'));
  fs.mkdirSync(path.join(dir, 'pkg'));
  fs.writeFileSync(path.join(dir, 'pkg', 'a.js'), text);
  fs.writeFileSync(path.join(dir, 'pkg', 'b.js'), text);
  fs.writeFileSync(path.join(dir, 'index.html'), '<p>lab</p>');
  for (const f of compressible(dir)) precompress(f);
  // b.js changes after its copies were written: they are stale.
  const old = new Date(Date.now() - 60_000);
  fs.utimesSync(path.join(dir, 'pkg', 'b.js.br'), old, old);
  fs.utimesSync(path.join(dir, 'pkg', 'b.js.gz'), old, old);
  srv = await startServer(dir, 0);
});
after(() => {
  if (srv) srv.server.close();
  if (dir) fs.rmSync(dir, { recursive: true, force: true });
});

/** GET (or HEAD) without any decoding: status, headers and the raw body. */
const get = (rel, accept, method = 'GET') =>
  new Promise((resolve, reject) => {
    const req = http.request(
      new URL(rel, srv.url),
      { method, headers: accept == null ? {} : { 'Accept-Encoding': accept } },
      (res) => {
        const chunks = [];
        res.on('data', (c) => chunks.push(c));
        res.on('end', () => resolve({ status: res.statusCode, headers: res.headers, body: Buffer.concat(chunks) }));
      },
    );
    req.on('error', reject);
    req.end();
  });

test('Brotli first, then gzip, else the file; the bytes decode to the file', async () => {
  const br = await get('pkg/a.js', 'gzip, deflate, br, zstd');
  assert.equal(br.headers['content-encoding'], 'br');
  assert.equal(br.headers.vary, 'Accept-Encoding');
  assert.equal(br.headers['content-type'], 'text/javascript; charset=utf-8');
  assert.equal(Number(br.headers['content-length']), br.body.length);
  assert.ok(br.body.length < text.length / 10, `compressed: ${br.body.length} bytes`);
  assert.equal(zlib.brotliDecompressSync(br.body).toString(), text);
  const gz = await get('pkg/a.js', 'gzip');
  assert.equal(gz.headers['content-encoding'], 'gzip');
  assert.equal(zlib.gunzipSync(gz.body).toString(), text);
  const none = await get('pkg/a.js', null);
  assert.equal(none.headers['content-encoding'], undefined);
  assert.equal(none.body.toString(), text);
  const refused = await get('pkg/a.js', 'br;q=0, gzip;q=0.5');
  assert.equal(refused.headers['content-encoding'], 'gzip', 'q=0 refuses br');
  const head = await get('pkg/a.js', 'br', 'HEAD');
  assert.equal(Number(head.headers['content-length']), br.body.length);
  assert.equal(head.body.length, 0);
});

test('a copy older than its file is never sent; files without copies are sent as they are', async () => {
  const stale = await get('pkg/b.js', 'br, gzip');
  assert.equal(stale.headers['content-encoding'], undefined);
  assert.equal(stale.body.toString(), text);
  const html = await get('index.html', 'br, gzip');
  assert.equal(html.headers['content-encoding'], undefined);
  assert.equal(html.body.toString(), '<p>lab</p>');
});

test('the precache list leaves the copies out', () => {
  const files = precacheFiles(dir);
  assert.ok(files.includes('pkg/a.js'));
  assert.ok(!files.some((f) => f.endsWith('.br') || f.endsWith('.gz')), files.join(' '));
});
