#!/usr/bin/env node
// A tiny static file server for the lab (no dependencies): 127.0.0.1 only, GET/HEAD only,
// no directory listings, no path traversal, correct MIME types (application/wasm matters for
// WebAssembly.instantiateStreaming). Plain static hosting: no COOP/COEP headers are needed.
// A file with a precompressed copy (scripts/precompress.mjs: file.br, file.gz) is sent as that
// copy, with Content-Encoding, to a browser that accepts it (Vary: Accept-Encoding); other text
// files (the lab's modules, styles, pages) are compressed here once per version of the file and
// kept in memory (Brotli quality 11 or gzip 9, in the thread pool; every text file of the root
// is compressed in the background when the server starts). Every response has an ETag and
// Last-Modified (Cache-Control: no-cache), so a second visit revalidates with 304s instead of
// downloading again (the service worker, www/sw.js, serves it from its cache before that).
//   node scripts/serve.mjs [root=www] [port=$PORT|8080] [--cors] [--rebundle]   (port 0 = any free port)
// --rebundle (`npm start`): lab.bundle.js is rebuilt before it is sent when a module is newer.
// --cors (or startServer(root, port, { cors: true })) adds `Access-Control-Allow-Origin: *`,
// what a lab host must send when course pages on other origins load lab.js, its modules, the
// worker, the wasm and the stylesheets (docs/embedding.md, the element section).
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
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
  const accepted = acceptedSet(accept);
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

/** Text files compressed in memory when they have no precompressed copy, and the size below which it is not worth it. */
export const TEXT_EXT = Object.freeze(['.html', '.js', '.mjs', '.css', '.json', '.svg', '.ts', '.md', '.txt']);
const MIN_COMPRESS = 1024;
/** Files above this size are never compressed in memory (the wasm modules have copies on disk). */
const MAX_COMPRESS = 4 * 1024 * 1024;
/** What the in-memory copies may hold in all, bytes (the lab's text is ~0.3 MB compressed). */
const MEMO_CAP = 64 * 1024 * 1024;

/**
 * In-memory compressed copies, by file, encoding and version (mtime, size): one promise each.
 * @type {Map<string, Promise<Buffer>>}
 */
const memo = new Map();
let memoBytes = 0;

/**
 * The compressed body of `file` (stat `st`) in `encoding` ('br' or 'gzip'), compressed once per
 * version of the file; null when the file is not worth it (not text, too small or too large).
 * @param {string} file
 * @param {fs.Stats} st
 * @param {'br' | 'gzip'} encoding
 * @returns {Promise<Buffer> | null}
 */
export function compressedInMemory(file, st, encoding) {
  if (!TEXT_EXT.includes(path.extname(file).toLowerCase()) || st.size < MIN_COMPRESS || st.size > MAX_COMPRESS)
    return null;
  const key = `${file}\0${encoding}\0${st.mtimeMs}\0${st.size}`;
  let p = memo.get(key);
  if (!p) {
    if (memoBytes + st.size > MEMO_CAP) return null;
    memoBytes += st.size;
    p = fs.promises.readFile(file).then(
      (data) =>
        new Promise((resolve, reject) => {
          const done = (/** @type {Error | null} */ err, /** @type {Buffer} */ out) =>
            err ? reject(err) : resolve(out);
          if (encoding === 'br')
            zlib.brotliCompress(
              data,
              {
                params: {
                  [zlib.constants.BROTLI_PARAM_QUALITY]: 11,
                  [zlib.constants.BROTLI_PARAM_MODE]: zlib.constants.BROTLI_MODE_TEXT,
                  [zlib.constants.BROTLI_PARAM_SIZE_HINT]: data.length,
                },
              },
              done,
            );
          else zlib.gzip(data, { level: 9 }, done);
        }),
    );
    p.catch(() => memo.delete(key));
    memo.set(key, p);
  }
  return p;
}

/** The first of 'br', 'gzip' that `accept` (an Accept-Encoding header) allows, or null. */
export function acceptedEncoding(/** @type {string | undefined} */ accept) {
  const accepted = acceptedSet(accept);
  for (const [, name] of ENCODINGS) if (accepted.has(name)) return /** @type {'br' | 'gzip'} */ (name);
  return null;
}

function acceptedSet(/** @type {string | undefined} */ accept) {
  const accepted = new Set();
  for (const part of String(accept || '').split(',')) {
    const [name, ...params] = part.trim().toLowerCase().split(';');
    const q = params.map((x) => x.trim()).find((x) => x.startsWith('q='));
    if (name && !(q && Number(q.slice(2)) === 0)) accepted.add(name.trim());
  }
  return accepted;
}

/** @type {Map<string, Promise<void>>} a rebuild of a root's bundle in progress */
const rebuilding = new Map();
/**
 * Rebuilds `root`/lab.bundle.js when a module of `root` is newer (scripts/bundle.mjs, next to
 * this file; a copy of this server without it serves the bundle as it is).
 * @param {string} root
 */
async function rebundled(root) {
  let mod;
  try {
    mod = await import(new URL('./bundle.mjs', import.meta.url).href);
  } catch {
    return;
  }
  if (!rebuilding.has(root) && mod.bundleStale(root)) {
    const p = mod.bundle(root).then(() => undefined);
    rebuilding.set(root, p);
    p.finally(() => rebuilding.delete(root)).catch(() => {});
  }
  await rebuilding.get(root);
}

/** Compresses every text file under `dir` in the background (one at a time), for the first visit. */
function warm(/** @type {string} */ dir) {
  const files = [];
  const walk = (/** @type {string} */ d, /** @type {number} */ depth) => {
    if (depth > 6 || files.length > 2000) return;
    for (const e of fs.readdirSync(d, { withFileTypes: true })) {
      if (e.name.startsWith('.') || e.name === 'node_modules') continue;
      const f = path.join(d, e.name);
      if (e.isDirectory()) walk(f, depth + 1);
      else if (e.isFile() && TEXT_EXT.includes(path.extname(e.name).toLowerCase())) files.push(f);
    }
  };
  try {
    walk(dir, 0);
  } catch {
    return;
  }
  (async () => {
    for (const f of files) {
      try {
        const st = fs.statSync(f);
        if (fs.existsSync(f + '.br')) continue;
        for (const enc of /** @type {const} */ (['br', 'gzip'])) await compressedInMemory(f, st, enc);
      } catch {
        // gone or unreadable: served (or refused) when asked
      }
    }
  })();
}

/**
 * Starts a server for `root` on 127.0.0.1:`port`; resolves to { server, url }.
 * @param {string} root
 * @param {number} [port]
 * @param {{ cors?: boolean, warm?: boolean, rebundle?: boolean }} [opts] cors: every response
 *   allows any origin (GET/HEAD); warm (default true): compress the root's text files in the
 *   background now; rebundle: before sending lab.bundle.js, rebuild it when a module of the root
 *   is newer (scripts/bundle.mjs; `npm start`, so an edited module shows on reload)
 */
export function startServer(root, port = 0, opts = {}) {
  /** @type {Record<string, string>} */
  const cors = opts.cors ? { 'Access-Control-Allow-Origin': '*' } : {};
  const base = path.resolve(root);
  if (opts.warm !== false) warm(base);
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
    if (opts.rebundle && req.url && new URL(req.url, 'http://x').pathname === '/lab.bundle.js') {
      rebundled(base).then(
        () => handle(req, res),
        (e) => {
          res.writeHead(500, { 'Content-Type': 'text/plain; charset=utf-8', ...cors });
          res.end(`lab.bundle.js could not be rebuilt: ${e && e.message ? e.message : e}`);
        },
      );
      return;
    }
    handle(req, res);
  });
  /**
   * Answers one GET or HEAD request.
   * @param {http.IncomingMessage} req
   * @param {http.ServerResponse} res
   */
  function handle(req, res) {
    let rel;
    try {
      rel = decodeURIComponent(new URL(String(req.url), 'http://x').pathname);
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
      // A weak validator of this version of the file (the same for every encoding of it).
      const etag = `W/"${st.size.toString(16)}-${Math.floor(st.mtimeMs).toString(16)}"`;
      const common = {
        'Cache-Control': 'no-cache',
        ETag: etag,
        'Last-Modified': st.mtime.toUTCString(),
        'X-Content-Type-Options': 'nosniff',
        Vary: 'Accept-Encoding',
        ...cors,
      };
      const inm = req.headers['if-none-match'];
      if (inm && inm.split(',').some((t) => t.trim() === etag || t.trim() === '*')) {
        res.writeHead(304, common);
        res.end();
        return;
      }
      const type = MIME[path.extname(file).toLowerCase()] || 'application/octet-stream';
      const body = pickEncoding(file, st, req.headers['accept-encoding']);
      const enc = body.encoding ? null : acceptedEncoding(req.headers['accept-encoding']);
      const mem = enc ? compressedInMemory(file, st, enc) : null;
      const send = (
        /** @type {number} */ size,
        /** @type {string | null} */ encoding,
        /** @type {(() => void)} */ write,
      ) => {
        res.writeHead(200, {
          'Content-Type': type,
          'Content-Length': size,
          ...(encoding ? { 'Content-Encoding': encoding } : {}),
          ...common,
        });
        if (req.method === 'HEAD') res.end();
        else write();
      };
      if (mem)
        mem.then(
          (buf) => send(buf.length, enc, () => res.end(buf)),
          () => send(st.size, null, () => fs.createReadStream(file).pipe(res)),
        );
      else send(body.size, body.encoding, () => fs.createReadStream(body.path).pipe(res));
    });
  }
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
  const rebundle = args.includes('--rebundle');
  const pos = args.filter((a) => !a.startsWith('--'));
  const root = pos[0] || 'www';
  const port = Number(pos[1] ?? process.env.PORT ?? 8080);
  if (!fs.existsSync(path.join(root, 'pkg', 'wingbeat.js'))) {
    console.error(`serve: ${root}/pkg/wingbeat.js is missing; run "npm start" (or scripts/build-web.sh ${root}) first`);
    process.exit(1);
  }
  startServer(root, port, { cors, rebundle })
    .catch(() => startServer(root, 0, { cors, rebundle }))
    .then(({ url }) => {
      console.log(
        `wingbeat lab: ${url}  (embed demo: ${url}embed-demo.html${cors ? '; CORS: any origin' : ''}; Ctrl-C stops)`,
      );
    });
}
