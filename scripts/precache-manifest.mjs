#!/usr/bin/env node
// Writes DIR/precache.json, the service worker's precache list (www/sw.js): every file of the
// built lab folder that a browser may fetch, taken from the folder itself — never from matching
// text in the sources (that once picked up a string in views/studies.js as a module path and
// requested a file that does not exist). Called by scripts/build-web.sh for www/ and dist/.
//   node scripts/precache-manifest.mjs www
// Left out: sw.js (the worker itself) and this manifest, TypeScript declarations (*.d.ts),
// source maps, the wasm-pack/wasm-bindgen package metadata, and the download's own server and
// README (dist/serve.mjs, serve-lib.mjs, README.txt: for people, not for the browser).
import fs from 'node:fs';
import path from 'node:path';

export const MANIFEST = 'precache.json';
const SKIP_NAMES = new Set([
  'sw.js',
  MANIFEST,
  'serve.mjs',
  'serve-lib.mjs',
  'README.txt',
  '.gitignore',
  'package.json',
]);
// .br / .gz: scripts/precompress.mjs's copies, sent by the server in place of the file.
const SKIP_ENDINGS = ['.d.ts', '.map', '.tmp', '.br', '.gz'];

/**
 * The files of `dir` to precache, relative paths with '/' separators, sorted.
 * @param {string} dir
 * @returns {string[]}
 */
export function precacheFiles(dir) {
  /** @type {string[]} */
  const out = [];
  const walk = (rel) => {
    for (const ent of fs.readdirSync(path.join(dir, rel), { withFileTypes: true })) {
      const r = rel ? `${rel}/${ent.name}` : ent.name;
      if (ent.name.startsWith('.')) continue;
      if (ent.isDirectory()) walk(r);
      else if (ent.isFile() && !SKIP_NAMES.has(ent.name) && !SKIP_ENDINGS.some((e) => ent.name.endsWith(e)))
        out.push(r);
    }
  };
  walk('');
  return out.sort();
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const dir = process.argv[2];
  if (!dir || !fs.statSync(dir, { throwIfNoEntry: false })?.isDirectory()) {
    console.error('precache-manifest: usage: node scripts/precache-manifest.mjs <built lab folder>');
    process.exit(2);
  }
  const files = precacheFiles(dir);
  fs.writeFileSync(path.join(dir, MANIFEST), JSON.stringify({ version: 1, files }, null, 1) + '\n');
  console.log(`precache-manifest: ${dir}/${MANIFEST}: ${files.length} files`);
}
