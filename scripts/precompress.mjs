#!/usr/bin/env node
// Writes a Brotli (.br, quality 11) and a gzip (.gz, level 9) copy next to each of the lab's
// large built files (DIR/pkg/*.wasm, DIR/pkg/*.js, DIR/vendor/*.js, DIR/vendor/*.css), so a
// server can send them compressed without compressing on every request; scripts/serve.mjs
// sends the .br or .gz copy when the browser accepts it and the copy is not older than the
// file. The copies are left out of the service worker's precache list (the browser caches what
// it decoded). Used by scripts/build-web.sh.
//   node scripts/precompress.mjs www
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { fileURLToPath } from 'node:url';
import { ENCODINGS } from './serve.mjs';

export { ENCODINGS };

/**
 * The built files of `dir` worth compressing.
 * @param {string} dir
 */
export function compressible(dir) {
  const out = [];
  for (const [sub, exts] of [
    ['pkg', ['.wasm', '.js']],
    ['vendor', ['.js', '.css']],
  ]) {
    const d = path.join(dir, sub);
    if (!fs.existsSync(d)) continue;
    for (const name of fs.readdirSync(d)) if (exts.includes(path.extname(name))) out.push(path.join(d, name));
  }
  return out.sort();
}

/**
 * Writes `file`.br and `file`.gz; returns their sizes.
 * @param {string} file
 */
export function precompress(file) {
  const data = fs.readFileSync(file);
  const br = zlib.brotliCompressSync(data, {
    params: {
      [zlib.constants.BROTLI_PARAM_QUALITY]: 11,
      [zlib.constants.BROTLI_PARAM_SIZE_HINT]: data.length,
      [zlib.constants.BROTLI_PARAM_MODE]: file.endsWith('.wasm')
        ? zlib.constants.BROTLI_MODE_GENERIC
        : zlib.constants.BROTLI_MODE_TEXT,
    },
  });
  const gz = zlib.gzipSync(data, { level: 9 });
  const bytes = { br, gzip: gz };
  for (const [suffix, name] of ENCODINGS)
    fs.writeFileSync(`${file}${suffix}`, bytes[/** @type {'br' | 'gzip'} */ (name)]);
  return { raw: data.length, br: br.length, gz: gz.length };
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const dir = process.argv[2];
  if (!dir) {
    console.error('precompress: usage: node scripts/precompress.mjs <built lab folder>');
    process.exit(2);
  }
  let raw = 0;
  let br = 0;
  let gz = 0;
  const files = compressible(dir);
  for (const f of files) {
    // Copies already there and not older than the file (dist/pkg copied from www/pkg with its
    // times) are kept: Brotli at quality 11 takes seconds per megabyte.
    const t = fs.statSync(f).mtimeMs;
    const fresh = ENCODINGS.every(([suffix]) => fs.existsSync(f + suffix) && fs.statSync(f + suffix).mtimeMs >= t);
    const s = fresh
      ? { raw: fs.statSync(f).size, br: fs.statSync(f + '.br').size, gz: fs.statSync(f + '.gz').size }
      : precompress(f);
    raw += s.raw;
    br += s.br;
    gz += s.gz;
  }
  console.log(`precompress: ${files.length} files in ${dir}: ${raw} bytes, ${br} as Brotli, ${gz} as gzip`);
}
