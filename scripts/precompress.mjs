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
import { promisify } from 'node:util';
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

const brotli = promisify(zlib.brotliCompress);
const gzip = promisify(zlib.gzip);

/**
 * Writes `file`.br and `file`.gz; resolves to their sizes. The compression runs on zlib's
 * thread pool, so several files (and each file's two copies) are compressed at once.
 * @param {string} file
 */
export async function precompress(file) {
  const data = await fs.promises.readFile(file);
  const [br, gz] = await Promise.all([
    brotli(data, {
      params: {
        [zlib.constants.BROTLI_PARAM_QUALITY]: 11,
        [zlib.constants.BROTLI_PARAM_SIZE_HINT]: data.length,
        [zlib.constants.BROTLI_PARAM_MODE]: file.endsWith('.wasm')
          ? zlib.constants.BROTLI_MODE_GENERIC
          : zlib.constants.BROTLI_MODE_TEXT,
      },
    }),
    gzip(data, { level: 9 }),
  ]);
  const bytes = { br, gzip: gz };
  await Promise.all(
    ENCODINGS.map(([suffix, name]) =>
      fs.promises.writeFile(`${file}${suffix}`, bytes[/** @type {'br' | 'gzip'} */ (name)]),
    ),
  );
  return { raw: data.length, br: br.length, gz: gz.length };
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const dir = process.argv[2];
  if (!dir) {
    console.error('precompress: usage: node scripts/precompress.mjs <built lab folder>');
    process.exit(2);
  }
  const files = compressible(dir);
  // Copies already there and not older than the file (dist/pkg copied from www/pkg with its
  // times) are kept: Brotli at quality 11 takes seconds per megabyte. The rest are compressed
  // side by side (the largest first, so the longest job starts at once).
  const sizes = await Promise.all(
    files
      .map((f) => ({ f, st: fs.statSync(f) }))
      .sort((a, b) => b.st.size - a.st.size)
      .map(({ f, st }) => {
        const fresh = ENCODINGS.every(
          ([suffix]) => fs.existsSync(f + suffix) && fs.statSync(f + suffix).mtimeMs >= st.mtimeMs,
        );
        return fresh
          ? { raw: st.size, br: fs.statSync(`${f}.br`).size, gz: fs.statSync(`${f}.gz`).size }
          : precompress(f);
      }),
  );
  const sum = (/** @type {'raw' | 'br' | 'gz'} */ k) => sizes.reduce((a, s) => a + s[k], 0);
  console.log(
    `precompress: ${files.length} files in ${dir}: ${sum('raw')} bytes, ${sum('br')} as Brotli, ${sum('gz')} as gzip`,
  );
}
