// @ts-check
// Assembles the npm package `wingbeat-lab` from the built lab (www/ after
// `scripts/build-web.sh www`) into an output folder that `npm pack` accepts:
//   node packaging/assemble.mjs <www-dir> <out-dir>
// Called by scripts/build-package.sh. Copies, never changes, the lab's files: the element
// (lab.js) and every module it or the worker imports (followed from the sources, so new
// modules come along by themselves), worker.js, style.css, vendor/ (uPlot + its licence) and
// pkg/ (the wasm module and its JS/TS bindings); adds package.json, lab.d.ts, README and the
// licences. The package has no dependencies (uPlot is vendored), so a tarball installs offline.
import { readFileSync, writeFileSync, mkdirSync, copyFileSync, existsSync, rmSync, readdirSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve, posix } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const root = resolve(here, '..');
const [wwwArg, outArg] = process.argv.slice(2);
if (!wwwArg || !outArg) {
  console.error('usage: node packaging/assemble.mjs <www-dir> <out-dir>');
  process.exit(2);
}
const www = resolve(wwwArg);
const out = resolve(outArg);

/** Files the lab loads by URL (not by import): engine.js and dom.js resolve them next to themselves. */
const ASSETS = [
  'worker.js',
  'render-worker.js',
  'style.css',
  'vendor/uPlot.esm.js',
  'vendor/uPlot.min.css',
  'vendor/uPlot.LICENSE',
  'pkg/wingbeat.js',
  'pkg/wingbeat.d.ts',
  'pkg/wingbeat_bg.wasm',
  'pkg/wingbeat_bg.wasm.d.ts',
  // The live build the lab paints its first plot from (docs/lab.md, "Two modules, one crate").
  'pkg/wingbeat_live.js',
  'pkg/wingbeat_live.d.ts',
  'pkg/wingbeat_live_bg.wasm',
  'pkg/wingbeat_live_bg.wasm.d.ts',
];

/** Relative module specifiers in `src`: static imports/re-exports and import('…') with a literal. */
function specifiers(src) {
  const found = new Set();
  const code = src.replace(/\/\*[\s\S]*?\*\//g, '').replace(/^\s*\/\/.*$/gm, '');
  for (const re of [/\bimport\s+(?:[^'"();]*?\s+from\s+)?['"](\.{1,2}\/[^'"]+)['"]/g, /\bexport\s+[^'";]*?\s+from\s+['"](\.{1,2}\/[^'"]+)['"]/g, /\bimport\(\s*['"](\.{1,2}\/[^'"]+)['"]\s*\)/g]) {
    for (const m of code.matchAll(re)) found.add(m[1]);
  }
  return [...found];
}

/** The module graph from the entry points, as paths relative to www/. */
function graph(entries) {
  const seen = new Set();
  const todo = [...entries];
  while (todo.length) {
    const rel = /** @type {string} */ (todo.pop());
    if (seen.has(rel)) continue;
    const file = join(www, rel);
    if (!existsSync(file)) throw new Error(`assemble: ${rel} is imported but missing in ${www}`);
    seen.add(rel);
    for (const spec of specifiers(readFileSync(file, 'utf8'))) {
      const next = posix.normalize(posix.join(posix.dirname(rel), spec));
      if (next.startsWith('..')) throw new Error(`assemble: ${rel} imports ${spec}, outside the lab`);
      todo.push(next);
    }
  }
  return seen;
}

const files = new Set([...graph(['lab.js', 'worker.js', 'render-worker.js']), ...ASSETS]);
for (const f of files) if (!existsSync(join(www, f))) throw new Error(`assemble: ${f} missing in ${www} (run scripts/build-web.sh www)`);

const cargo = readFileSync(join(root, 'Cargo.toml'), 'utf8');
const version = /^version\s*=\s*"([^"]+)"/m.exec(cargo)?.[1];
if (!version) throw new Error('assemble: no version in Cargo.toml');

rmSync(out, { recursive: true, force: true });
mkdirSync(out, { recursive: true });
for (const f of [...files].sort()) {
  mkdirSync(dirname(join(out, f)), { recursive: true });
  copyFileSync(join(www, f), join(out, f));
}
copyFileSync(join(here, 'lab.d.ts'), join(out, 'lab.d.ts'));
copyFileSync(join(here, 'README.md'), join(out, 'README.md'));
copyFileSync(join(root, 'LICENSE-MIT'), join(out, 'LICENSE-MIT'));
copyFileSync(join(root, 'LICENSE-APACHE'), join(out, 'LICENSE-APACHE'));

const pkg = {
  name: 'wingbeat-lab',
  version,
  description: 'The wingbeat lab as a <wing-lab> custom element: the inertial-elastic dynamics of a flapping insect wing (Jankauski & Shen, Eq. 13), computed in WebAssembly.',
  license: 'MIT OR Apache-2.0',
  author: 'the wingbeat authors',
  keywords: ['custom-element', 'web-component', 'webassembly', 'insect-flight', 'floquet', 'teaching'],
  type: 'module',
  main: './lab.js',
  module: './lab.js',
  types: './lab.d.ts',
  exports: {
    '.': { types: './lab.d.ts', default: './lab.js' },
    './lab.js': { types: './lab.d.ts', default: './lab.js' },
    './worker.js': './worker.js',
    './render-worker.js': './render-worker.js',
    './style.css': './style.css',
    './wasm': './pkg/wingbeat_bg.wasm',
    './wasm-live': './pkg/wingbeat_live_bg.wasm',
    './api': { types: './pkg/wingbeat.d.ts', default: './pkg/wingbeat.js' },
    './package.json': './package.json',
  },
  // Importing lab.js registers <wing-lab>; the stylesheets are loaded by URL.
  sideEffects: ['./lab.js', '*.css'],
  files: [...new Set([...files].map((f) => f.split('/')[0]))].sort().concat(['lab.d.ts', 'LICENSE-MIT', 'LICENSE-APACHE']),
  engines: { node: '>=20' },
};
writeFileSync(join(out, 'package.json'), JSON.stringify(pkg, null, 2) + '\n');

let bytes = 0;
const walk = (d) => { for (const n of readdirSync(d)) { const p = join(d, n); const s = statSync(p); if (s.isDirectory()) walk(p); else bytes += s.size; } };
walk(out);
console.log(`assemble: ${relative(process.cwd(), out) || out}/ wingbeat-lab@${version}: ${files.size + 5} files, ${bytes} bytes`);
