// The npm package a course site installs (issue 11, item 3): scripts/build-package.sh builds
// npm-package/wingbeat-lab-<version>.tgz from the built www/; this test checks the tarball's
// contents and package.json, installs it offline into a fresh temp folder (as a course site
// would: `npm install <tgz>`), type-checks a small TypeScript file against its types, then serves
// that folder with examples/course-site/index.html (import map → node_modules/wingbeat-lab/lab.js)
// and a page with a plain <script type=module src=/node_modules/…/lab.js>, and checks in headless
// Chromium that the element defines and computes with every file from the installed package.
// With WINGBEAT_TEST_VITE=1 it also builds the example with Vite (installed from npm) and checks dist/.
// Run after scripts/build-web.sh www:  node --test --test-concurrency=1 tests/e2e/package.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { execFileSync } from 'node:child_process';
import { chromium } from 'playwright-core';
import { openPage, OUT, ROOT, CHROMIUM, ARGS } from './helpers.mjs';
import { startServer } from '../../scripts/serve.mjs';

const version = /^version\s*=\s*"([^"]+)"/m.exec(fs.readFileSync(path.join(ROOT, 'Cargo.toml'), 'utf8'))?.[1];
const TGZ = path.join(ROOT, 'npm-package', `wingbeat-lab-${version}.tgz`);

let dir, site, browser;
before(async () => {
  execFileSync('bash', [path.join(ROOT, 'scripts/build-package.sh')], {
    cwd: ROOT,
    stdio: ['ignore', 'inherit', 'inherit'],
  });
  assert.ok(fs.existsSync(TGZ), `${TGZ} was not built`);
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'wl-pkg-'));
  fs.writeFileSync(
    path.join(dir, 'package.json'),
    JSON.stringify({ name: 'course-site', private: true, type: 'module' }),
  );
  // A local tarball with no dependencies: no registry access needed.
  execFileSync('npm', ['install', '--offline', '--no-audit', '--no-fund', '--loglevel=error', TGZ], {
    cwd: dir,
    stdio: ['ignore', 'inherit', 'inherit'],
  });
  fs.copyFileSync(path.join(ROOT, 'examples/course-site/index.html'), path.join(dir, 'index.html'));
  fs.writeFileSync(
    path.join(dir, 'direct.html'),
    `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,">
<title>Direct script tag</title><script type="module" src="/node_modules/wingbeat-lab/lab.js"></script></head>
<body><main><h1>Direct</h1><wing-lab embed panels="controls,numbers"></wing-lab></main></body></html>`,
  );
  site = await startServer(dir, 0);
  fs.mkdirSync(OUT, { recursive: true });
  browser = await chromium.launch({ executablePath: CHROMIUM, args: ARGS, headless: true });
});
after(async () => {
  if (browser) await browser.close();
  if (site) site.server.close();
  if (dir) fs.rmSync(dir, { recursive: true, force: true });
});

test('the tarball holds the element, worker, styles, wasm, types, licences and nothing else', () => {
  const files = execFileSync('tar', ['tzf', TGZ], { encoding: 'utf8' })
    .trim()
    .split('\n')
    .map((f) => f.replace(/^package\//, ''));
  for (const f of [
    'package.json',
    'README.md',
    'LICENSE-MIT',
    'LICENSE-APACHE',
    'lab.js',
    'lab.d.ts',
    'worker.js',
    'engine.js',
    'style.css',
    'pkg/wingbeat.js',
    'pkg/wingbeat.d.ts',
    'pkg/wingbeat_bg.wasm',
    'pkg/wingbeat_live.js',
    'pkg/wingbeat_live_bg.wasm',
    'vendor/uPlot.esm.js',
    'vendor/uPlot.min.css',
    'vendor/uPlot.LICENSE',
  ]) {
    assert.ok(files.includes(f), `${f} missing from the tarball`);
  }
  // Page-only files (the site's bootstrap, service worker, iframe host script) and anything
  // that is not the built lab stay out.
  for (const f of files) {
    assert.ok(!/\.(map|rs|mjs|ts\.map|html)$/.test(f), `unexpected file ${f}`);
    assert.ok(
      !['main.js', 'sw.js', 'offline.js', 'embed-host.js', 'page.css', 'index.html'].includes(f),
      `page-only file ${f} in the package`,
    );
  }
  const size = fs.statSync(TGZ).size;
  assert.ok(size < 4e6, `tarball ${size} bytes`);
});

test('package.json: name, version, licence, exports that exist, no dependencies', () => {
  const pkg = JSON.parse(fs.readFileSync(path.join(dir, 'node_modules/wingbeat-lab/package.json'), 'utf8'));
  assert.equal(pkg.name, 'wingbeat-lab');
  assert.equal(pkg.version, version);
  assert.equal(pkg.license, 'MIT OR Apache-2.0');
  assert.equal(pkg.type, 'module');
  assert.equal(pkg.dependencies, undefined);
  assert.ok(!pkg.private);
  const targets = [];
  for (const v of Object.values(pkg.exports)) {
    if (typeof v === 'string') targets.push(v);
    else targets.push(...Object.values(v));
  }
  targets.push(pkg.types, pkg.main);
  for (const t of targets)
    assert.ok(fs.existsSync(path.join(dir, 'node_modules/wingbeat-lab', t)), `export target ${t} missing`);
  for (const k of ['.', './worker.js', './style.css', './wasm', './wasm-live', './api'])
    assert.ok(k in pkg.exports, `export ${k}`);
});

test('its types check in a TypeScript project that imports the package', () => {
  fs.writeFileSync(
    path.join(dir, 'use.ts'),
    `import { WingLab, loadWasm } from 'wingbeat-lab';
import type { Analysis } from 'wingbeat-lab/api';
const lab: WingLab | null = document.querySelector('wing-lab');
if (lab) {
  lab.addEventListener('wl-rendered', (e) => { const ms: number = e.detail.compute; console.log(ms); });
  const g: number = lab.state.gamma0;
  lab.store?.set({ gamma0: g / 2 });
  const a: Analysis | undefined = lab.analysis;
  console.log(a, lab.config().duration_s);
}
loadWasm().then((api) => console.log(typeof api.parameters));
`,
  );
  fs.writeFileSync(
    path.join(dir, 'tsconfig.json'),
    JSON.stringify({
      compilerOptions: {
        target: 'es2022',
        module: 'esnext',
        moduleResolution: 'bundler',
        lib: ['esnext', 'dom'],
        strict: true,
        noEmit: true,
        types: [],
      },
      files: ['use.ts'],
    }),
  );
  execFileSync(path.join(ROOT, 'node_modules/.bin/tsc'), ['-p', dir], {
    cwd: dir,
    stdio: ['ignore', 'inherit', 'inherit'],
  });
});

/**
 * Opens `url`, waits until the lab `sel` has computed, and checks it: defined, panels and numbers
 * shown, and every request of the site other than the page itself answered from
 * node_modules/wingbeat-lab/ (the installed package; `allow` adds the site's own bundle).
 */
async function checkLab(url, sel, { gamma0, shot, allow = /^$/ } = {}) {
  const { context, page: p, problems } = await openPage(browser, url, { width: 1000, height: 900 });
  const urls = [];
  p.on('request', (r) => urls.push(new URL(r.url())));
  await p.goto(url);
  await p.waitForFunction((s) => Number(document.querySelector(s)?.getAttribute('data-renders') || 0) >= 1, sel, {
    timeout: 30000,
  });
  // The full wasm build loads behind the live one (docs/lab.md, "Two modules, one crate").
  await p.waitForFunction((s) => /** @type {any} */ (document.querySelector(s))?.engine?.fullReady, sel, {
    timeout: 30000,
  });
  const info = await p.evaluate((s) => {
    const lab = /** @type {any} */ (document.querySelector(s));
    const root = lab.shadowRoot || lab;
    return {
      defined: !!customElements.get('wing-lab'),
      sections: root.querySelectorAll('section').length,
      numbers: (root.textContent || '').includes('Hz'),
      gamma0: lab.state.gamma0,
    };
  }, sel);
  assert.ok(info.defined);
  assert.ok(info.sections >= 2, `${info.sections} panels`);
  assert.ok(info.numbers, 'no computed numbers shown');
  if (gamma0 !== undefined) assert.equal(info.gamma0, gamma0);
  const here = new URL(url);
  const lab = urls.filter((u) => u.origin === here.origin && u.pathname !== here.pathname && !allow.test(u.pathname));
  assert.ok(lab.length > 5);
  for (const u of lab)
    assert.ok(u.pathname.startsWith('/node_modules/wingbeat-lab/'), `${u.pathname} loaded from outside the package`);
  assert.ok(lab.some((u) => u.pathname.endsWith('/pkg/wingbeat_live_bg.wasm')));
  assert.ok(lab.some((u) => u.pathname.endsWith('/pkg/wingbeat_bg.wasm')));
  assert.deepEqual(problems, []);
  if (shot) await p.screenshot({ path: path.join(OUT, shot), fullPage: true });
  await context.close();
}

test('installed package: the course site (import map) defines the element and computes', async () => {
  await checkLab(`${site.url}index.html`, 'figure wing-lab', { gamma0: 0.1, shot: 'package-course-site.png' });
});

test('installed package: a plain <script type=module src=/node_modules/wingbeat-lab/lab.js> works', async () => {
  await checkLab(`${site.url}direct.html`, 'wing-lab');
});

// Needs vite from the npm registry (a devDependency of the example only), so it is opt-in.
test('the course site built with Vite (examples/course-site/vite.config.js) works', {
  skip: !process.env.WINGBEAT_TEST_VITE && 'set WINGBEAT_TEST_VITE=1 to run (installs vite from npm)',
}, async () => {
  const ex = JSON.parse(fs.readFileSync(path.join(ROOT, 'examples/course-site/package.json'), 'utf8'));
  const vdir = fs.mkdtempSync(path.join(os.tmpdir(), 'wl-vite-'));
  try {
    for (const f of ['index.html', 'vite.config.js'])
      fs.copyFileSync(path.join(ROOT, 'examples/course-site', f), path.join(vdir, f));
    fs.writeFileSync(
      path.join(vdir, 'package.json'),
      JSON.stringify({ name: 'course-site-vite', private: true, type: 'module' }),
    );
    execFileSync(
      'npm',
      ['install', '--no-audit', '--no-fund', '--loglevel=error', TGZ, `vite@${ex.devDependencies.vite}`],
      {
        cwd: vdir,
        stdio: ['ignore', 'inherit', 'inherit'],
      },
    );
    execFileSync(path.join(vdir, 'node_modules/.bin/vite'), ['build', '--logLevel', 'warn'], {
      cwd: vdir,
      stdio: ['ignore', 'inherit', 'inherit'],
    });
    const dist = await startServer(path.join(vdir, 'dist'), 0);
    try {
      await checkLab(`${dist.url}index.html`, 'figure wing-lab', { gamma0: 0.1, allow: /^\/assets\// });
    } finally {
      dist.server.close();
    }
  } finally {
    fs.rmSync(vdir, { recursive: true, force: true });
  }
});
