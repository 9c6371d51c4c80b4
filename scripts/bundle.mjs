#!/usr/bin/env node
// Bundles the lab's modules into one minified file, DIR/lab.bundle.js (esbuild): lab.js, the
// embedding API (embed-api.js) and the service worker's registration (offline.js) with everything
// they import, which the lab's page (main.js) imports instead of those three: one request instead of ~95 modules discovered
// level by level (each level a round trip; six at a time over HTTP/1.1), a third of the bytes
// (issue 25). The modules themselves stay as they are: an embedding course page, the npm
// package and the tests may import lab.js directly. What the lab loads by URL (the wasm glue,
// the worker, the stylesheets, uPlot's sheet) is not bundled: those URLs are built from
// www/base.js, which resolves to the same folder from the bundle as from its own file.
//   node scripts/bundle.mjs www      (scripts/build-web.sh runs it for www/ and dist/)
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

/** The bundle's file name, next to lab.js. */
export const BUNDLE = 'lab.bundle.js';

/**
 * Writes DIR/lab.bundle.js from DIR/lab.js; resolves to { bytes, inputs }.
 * @param {string} dir
 */
export async function bundle(dir) {
  const esbuild = await import('esbuild');
  const out = path.join(dir, BUNDLE);
  const r = await esbuild.build({
    // lab.js defines <wing-lab>; the page (main.js) also takes the embedding API and the
    // service worker's registration from the bundle, so they share its modules.
    stdin: {
      contents: [
        "export * from './lab.js';",
        "export * as embedApi from './embed-api.js';",
        "export * as offline from './offline.js';",
      ].join('\n'),
      resolveDir: path.resolve(dir),
      sourcefile: 'lab.bundle.entry.js',
      loader: 'js',
    },
    outfile: out,
    bundle: true,
    format: 'esm',
    platform: 'browser',
    target: 'es2022',
    // BUNDLE_NO_MINIFY=1: readable names and lines, for a profile of the page (not for shipping).
    minify: !process.env.BUNDLE_NO_MINIFY,
    // Class and function names stay (error messages and the custom element's class name).
    keepNames: true,
    legalComments: 'none',
    metafile: true,
    logLevel: 'warning',
    banner: {
      js: '// wingbeat lab: www/lab.js and its modules, bundled by scripts/bundle.mjs (the sources are next to this file).',
    },
  });
  return { bytes: fs.statSync(out).size, inputs: Object.keys(r.metafile.inputs).length };
}

/**
 * Whether DIR/lab.bundle.js is missing or older than any JavaScript module of DIR (pkg/, vendor/
 * and the bundle itself aside): then `bundle(dir)` should run again.
 * @param {string} dir
 */
export function bundleStale(dir) {
  let built = 0;
  try {
    built = fs.statSync(path.join(dir, BUNDLE)).mtimeMs;
  } catch {
    return true;
  }
  const walk = (/** @type {string} */ d, /** @type {number} */ depth) => {
    if (depth > 4) return false;
    for (const e of fs.readdirSync(d, { withFileTypes: true })) {
      if (e.name.startsWith('.') || ['pkg', 'vendor', 'node_modules', 'examples'].includes(e.name)) continue;
      const f = path.join(d, e.name);
      if (e.isDirectory()) {
        if (walk(f, depth + 1)) return true;
      } else if (e.name.endsWith('.js') && e.name !== BUNDLE && fs.statSync(f).mtimeMs > built) return true;
    }
    return false;
  };
  return walk(dir, 0);
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const dir = process.argv[2];
  if (!dir) {
    console.error('bundle: usage: node scripts/bundle.mjs <lab folder>');
    process.exit(2);
  }
  const { bytes, inputs } = await bundle(dir);
  console.log(`bundle: ${path.join(dir, BUNDLE)}: ${inputs} modules, ${bytes} bytes`);
}
