#!/usr/bin/env node
// A tiny static file server for the lab (no dependencies): 127.0.0.1 only, GET/HEAD only,
// no directory listings, no path traversal, correct MIME types (application/wasm matters for
// WebAssembly.instantiateStreaming). Plain static hosting: no COOP/COEP headers are needed.
// A file with a precompressed copy (scripts/precompress.mjs: file.br, file.gz) is sent as that
// copy, with Content-Encoding, to a browser that accepts it (Vary: Accept-Encoding).
//   node scripts/serve.mjs [root=www] [port=$PORT|8080] [--cors]   (port 0 = any free port)
// --cors (or startServer(root, port, { cors: true })) adds `Access-Control-Allow-Origin: *`,
// what a lab host must send when course pages on other origins load lab.js, its modules, the
// worker, the wasm and the stylesheets (docs/embedding.md, the element section).
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const MIME = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.wasm': 'application/wasm',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
  '.ts': 'text/plain; charset=utf-8',
  '.md': 'text/plain; charset=utf-8',
  '.txt': 'text/plain; charset=utf-8',
};

/**
 * Precompressed copies a file may have (scripts/precompress.mjs writes them), in the order they
 * are preferred: [file suffix, Content-Encoding].
 */
export const ENCODINGS = Object.freeze([Object.freeze(['.br', 'br']), Object.freeze(['.gz', 'gzip'])]);

/**
 * The copy of `file` (stat `st`) to send for the request's Accept-Encoding: the first of
 * ENCODINGS the browser accepts (q > 0) whose copy exists and is not older than the file, else
 * the file itself. Returns { path, size, encoding } (encoding null: as is).
 * @param {string} file
 * @param {fs.Stats} st
 * @param {string | undefined} accept
 */
export function pickEncoding(file, st, accept) {
  const accepted = new Set();
  for (const part of String(accept || '').split(',')) {
    const [name, ...params] = part.trim().toLowerCase().split(';');
    const q = params.map((x) => x.trim()).find((x) => x.startsWith('q='));
    if (name && !(q && Number(q.slice(2)) === 0)) accepted.add(name.trim());
  }
  for (const [suffix, name] of ENCODINGS) {
    if (!accepted.has(name)) continue;
    try {
      const cst = fs.statSync(file + suffix);
      if (cst.isFile() && cst.mtimeMs >= st.mtimeMs) return { path: file + suffix, size: cst.size, encoding: name };
    } catch {
      // no such copy
    }
  }
  return { path: file, size: st.size, encoding: null };
}

/**
 * Starts a server for `root` on 127.0.0.1:`port`; resolves to { server, url }.
 * @param {string} root
 * @param {number} [port]
 * @param {{ cors?: boolean }} [opts] cors: every response allows any origin (GET/HEAD)
 */
export function startServer(root, port = 0, opts = {}) {
  /** @type {Record<string, string>} */
  const cors = opts.cors ? { 'Access-Control-Allow-Origin': '*' } : {};
  const base = path.resolve(root);
  const server = http.createServer((req, res) => {
    if (req.method !== 'GET' && req.method !== 'HEAD') {
      if (req.method === 'OPTIONS' && opts.cors) {
        res.writeHead(204, { ...cors, 'Access-Control-Allow-Methods': 'GET, HEAD', 'Access-Control-Max-Age': '600' });
        res.end();
        return;
      }
      res.writeHead(405, { Allow: 'GET, HEAD', ...cors });
      res.end();
      return;
    }
    let rel;
    try {
      rel = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    } catch {
      res.writeHead(400, cors);
      res.end('bad request');
      return;
    }
    if (rel.endsWith('/')) rel += 'index.html';
    const file = path.resolve(base, '.' + rel);
    if (file !== base && !file.startsWith(base + path.sep)) {
      res.writeHead(403, cors);
      res.end('forbidden');
      return;
    }
    fs.stat(file, (err, st) => {
      if (err || !st.isFile()) {
        res.writeHead(404, { 'Content-Type': 'text/plain; charset=utf-8', ...cors });
        res.end('not found');
        return;
      }
      const body = pickEncoding(file, st, req.headers['accept-encoding']);
      res.writeHead(200, {
        'Content-Type': MIME[path.extname(file).toLowerCase()] || 'application/octet-stream',
        'Content-Length': body.size,
        'Cache-Control': 'no-cache',
        'X-Content-Type-Options': 'nosniff',
        Vary: 'Accept-Encoding',
        ...(body.encoding ? { 'Content-Encoding': body.encoding } : {}),
        ...cors,
      });
      if (req.method === 'HEAD') {
        res.end();
        return;
      }
      fs.createReadStream(body.path).pipe(res);
    });
  });
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, '127.0.0.1', () => {
      const { port: p } = server.address();
      resolve({ server, url: `http://127.0.0.1:${p}/` });
    });
  });
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const args = process.argv.slice(2);
  const cors = args.includes('--cors');
  const pos = args.filter((a) => !a.startsWith('--'));
  const root = pos[0] || 'www';
  const port = Number(pos[1] ?? process.env.PORT ?? 8080);
  if (!fs.existsSync(path.join(root, 'pkg', 'wingbeat.js'))) {
    console.error(`serve: ${root}/pkg/wingbeat.js is missing; run "npm start" (or scripts/build-web.sh ${root}) first`);
    process.exit(1);
  }
  startServer(root, port, { cors })
    .catch(() => startServer(root, 0, { cors }))
    .then(({ url }) => {
      console.log(
        `wingbeat lab: ${url}  (embed demo: ${url}embed-demo.html${cors ? '; CORS: any origin' : ''}; Ctrl-C stops)`,
      );
    });
}
