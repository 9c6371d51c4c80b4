// The lab's server (scripts/serve.mjs) sends a file's precompressed copy (scripts/precompress.mjs)
// to a browser that accepts it: Brotli first, then gzip, never a copy older than the file,
// never an encoding refused with q=0; text files without a copy are compressed in memory, per
// version of the file; the bytes decode to the file; Vary and Content-Length say what was sent;
// ETags make a revalidation a 304; the precache list leaves the copies out.
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
const css = '.wl-panel { margin: 0; }\n'.repeat(200);

before(async () => {
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'wingbeat-serve-'));
  fs.mkdirSync(path.join(dir, 'pkg'));
  fs.writeFileSync(path.join(dir, 'pkg', 'a.js'), text);
  fs.writeFileSync(path.join(dir, 'pkg', 'b.js'), text);
  fs.writeFileSync(path.join(dir, 'index.html'), '<p>lab</p>');
  fs.writeFileSync(path.join(dir, 'style.css'), css);
  fs.writeFileSync(path.join(dir, 'img.png'), Buffer.alloc(4000, 7));
  for (const f of compressible(dir)) await precompress(f);
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
const get = (rel, accept, method = 'GET', extra = {}) =>
  new Promise((resolve, reject) => {
    const req = http.request(
      new URL(rel, srv.url),
      { method, headers: { ...(accept == null ? {} : { 'Accept-Encoding': accept }), ...extra } },
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

test('a copy older than its file is never sent: the file itself is compressed in memory instead', async () => {
  // The stale copies hold other bytes: what is sent must decode to the file, not to them.
  fs.writeFileSync(path.join(dir, 'pkg', 'b.js.br'), zlib.brotliCompressSync('stale'));
  const old = new Date(Date.now() - 60_000);
  fs.utimesSync(path.join(dir, 'pkg', 'b.js.br'), old, old);
  const fresh = await get('pkg/b.js', 'br, gzip');
  assert.equal(fresh.headers['content-encoding'], 'br');
  assert.equal(zlib.brotliDecompressSync(fresh.body).toString(), text);
  const plain = await get('pkg/b.js', 'identity');
  assert.equal(plain.headers['content-encoding'], undefined);
  assert.equal(plain.body.toString(), text);
});

test('text files without copies are compressed in memory; small ones and other types are sent as they are', async () => {
  const style = await get('style.css', 'gzip');
  assert.equal(style.headers['content-encoding'], 'gzip');
  assert.equal(Number(style.headers['content-length']), style.body.length);
  assert.equal(zlib.gunzipSync(style.body).toString(), css);
  // A new version of the file is compressed anew (never the old version's bytes).
  fs.writeFileSync(path.join(dir, 'style.css'), css + '/* v2 */');
  const later = new Date(Date.now() + 5_000);
  fs.utimesSync(path.join(dir, 'style.css'), later, later);
  const v2 = await get('style.css', 'br');
  assert.equal(v2.headers['content-encoding'], 'br');
  assert.equal(zlib.brotliDecompressSync(v2.body).toString(), css + '/* v2 */');
  const html = await get('index.html', 'br, gzip');
  assert.equal(html.headers['content-encoding'], undefined, 'under 1 kB: not worth it');
  assert.equal(html.body.toString(), '<p>lab</p>');
  const png = await get('img.png', 'br, gzip');
  assert.equal(png.headers['content-encoding'], undefined, 'not text');
  assert.equal(png.body.length, 4000);
});

test('every response carries a validator; a revalidation of the same version is a 304 without a body', async () => {
  const first = await get('pkg/a.js', 'br');
  const etag = first.headers.etag;
  assert.match(String(etag), /^W\/"[0-9a-f]+-[0-9a-f]+"$/);
  assert.ok(first.headers['last-modified']);
  assert.equal(first.headers['cache-control'], 'no-cache');
  const again = await get('pkg/a.js', 'br', 'GET', { 'If-None-Match': String(etag) });
  assert.equal(again.status, 304);
  assert.equal(again.body.length, 0);
  const other = await get('pkg/a.js', 'br', 'GET', { 'If-None-Match': 'W/"0-0"' });
  assert.equal(other.status, 200);
  assert.equal(zlib.brotliDecompressSync(other.body).toString(), text);
});

test('the precache list leaves the copies out', () => {
  const files = precacheFiles(dir);
  assert.ok(files.includes('pkg/a.js'));
  assert.ok(!files.some((f) => f.endsWith('.br') || f.endsWith('.gz')), files.join(' '));
});
