#!/usr/bin/env node
// Measures the lab's 3-D view while it plays, in headless Chromium (software rendering), on
// WebGL2 (default flags) and on WebGPU (the flag set of ../shared/TOOLCHAIN.md):
//   * requestAnimationFrame intervals of the page (what the user sees: JS + GPU + compositing),
//     median and p90, and the wing's own drawn frames per second (data-frames);
//   * the JS time of every animation frame (all rAF callbacks of the frame summed: the wing's
//     draw and whatever else follows the 3-D time, such as the responses plot's cursor);
//   * the canvas: its CSS size, the backing store (device pixels) and the device pixel ratio;
//   * the Chromium console: "GPU stall due to ReadPixels" and other GPU warnings;
//   * optionally, slider latency while playing (keydown on γ0 → the lab's next render).
// The lab opens at its default layout (the 3-D panel first) in a 1280×800 viewport.
//
// Usage: node scripts/perf-3d.mjs [--seconds 5] [--only webgl2|webgpu] [--viewport 1280x800]
//        [--render worker|main|both] (the 3-D view drawn in its worker, the default, or on the page)
//        (after scripts/build-web.sh www). Writes test-output/perf-3d.json and prints a table.
// Library: `measure3d(browserOrPage, { url, seconds, viewport, sliders })` returns the same
// record for one browser (the backend is whatever the browser gives the page).
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { setup, openPage, WITH_SERVICE_WORKER, waitRenders, OUT, CHROMIUM, ARGS } from '../tests/e2e/helpers.mjs';

/** Chromium flags under which WebGPU renders on SwiftShader (TOOLCHAIN.md; other subsets draw blank). */
export const WEBGPU_FLAGS = [
  '--enable-unsafe-webgpu',
  '--enable-features=Vulkan',
  '--use-vulkan=swiftshader',
  '--use-angle=swiftshader',
];

const pct = (xs, p) => {
  if (!xs.length) return NaN;
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.floor(p * s.length))];
};
const r1 = (x) => (Number.isFinite(x) ? Math.round(x * 10) / 10 : null);
const stats = (xs) => ({ median: r1(pct(xs, 0.5)), p90: r1(pct(xs, 0.9)), n: xs.length });
const load = () =>
  os
    .loadavg()
    .map((x) => x.toFixed(2))
    .join(' ');

/**
 * CPU time (ms, user + system, all threads) of Chromium's processes under `rootPid`, by kind
 * (browser, gpu-process, renderer, utility …; node itself counts as 'browser'): what each side costs per frame, whatever the
 * machine's load (wall-clock intervals on a shared 2-core machine are mostly waiting).
 * Linux only (/proc); {} elsewhere or when the pid is unknown.
 */
export function cpuByProcess(rootPid) {
  /** @type {Record<string, number>} */
  const out = {};
  if (!rootPid || !fs.existsSync('/proc')) return out;
  const tick = 1000 / 100; // USER_HZ is 100 on Linux
  const kids = new Map();
  const info = new Map();
  for (const d of fs.readdirSync('/proc')) {
    if (!/^\d+$/.test(d)) continue;
    try {
      const st = fs.readFileSync(`/proc/${d}/stat`, 'utf8');
      const f = st.slice(st.lastIndexOf(')') + 2).split(' ');
      const ppid = Number(f[1]);
      const cpu = (Number(f[11]) + Number(f[12])) * tick;
      const cmd = fs.readFileSync(`/proc/${d}/cmdline`, 'utf8');
      const type = /--type=([\w-]+)/.exec(cmd);
      info.set(Number(d), { cpu, kind: type ? type[1] : 'browser' });
      if (!kids.has(ppid)) kids.set(ppid, []);
      kids.get(ppid).push(Number(d));
    } catch {
      /* gone */
    }
  }
  const walk = (pid) => {
    const i = info.get(pid);
    if (i) out[i.kind] = (out[i.kind] || 0) + i.cpu;
    for (const k of kids.get(pid) || []) walk(k);
  };
  walk(rootPid);
  return out;
}

/**
 * Plays the lab's 3-D view for `seconds` and measures it. `target`: a Playwright Browser (a page
 * is opened at `url` with `viewport`) or a Page already showing the lab.
 * @param {any} target
 * @param {{ url?: string, seconds?: number, viewport?: {width: number, height: number}, sliders?: number, setup?: string, pid?: number, render?: string }} [opts]
 *   `render: 'main'` draws the view on the page's main thread (the lab's `render` attribute), else
 *   in its worker where the browser can.
 */
export async function measure3d(target, opts = {}) {
  // Chromium runs as a child of this node process (Playwright's launch); other browsers of the
  // same process count too, so measure with the others idle.
  const pid = opts.pid ?? process.pid;
  const seconds = opts.seconds ?? 5;
  const viewport = opts.viewport ?? { width: 1280, height: 800 };
  const own = typeof target.newContext === 'function';
  /** @type {any} */
  let page = target;
  let context = null;
  if (own) {
    ({ page, context } = await openPage(target, opts.url, viewport, WITH_SERVICE_WORKER));
    if (opts.render === 'main')
      await page.addInitScript(() =>
        document.addEventListener('DOMContentLoaded', () => {
          const lab = document.querySelector('wing-lab');
          if (lab) lab.setAttribute('render', 'main');
        }),
      );
  }
  const consoleLog = [];
  const onConsole = (m) => consoleLog.push({ type: m.type(), text: m.text() });
  page.on('console', onConsole);
  try {
    if (own) {
      await page.goto(opts.url);
      await waitRenders(page, 1);
    }
    await page.waitForFunction(
      () => {
        const b = __wl.q('[data-wing3d]');
        return (
          b && (b.dataset.state === 'unavailable' || (b.dataset.state === 'ready' && Number(b.dataset.frames || 0) > 0))
        );
      },
      null,
      { timeout: 120000 },
    );
    const info = await page.evaluate(() => {
      const b = __wl.q('[data-wing3d]');
      const c = __wl.q('canvas.wl-w3-canvas');
      const r = c ? c.getBoundingClientRect() : null;
      return {
        state: b.dataset.state,
        backend: b.dataset.backend || null,
        thread: b.dataset.thread || null,
        css: r ? [Math.round(r.width), Math.round(r.height)] : null,
        backing: b.dataset.backing ? b.dataset.backing.split('x').map(Number) : null,
        dpr: devicePixelRatio,
        onScreen: !!r && r.bottom > 0 && r.top < innerHeight,
      };
    });
    if (info.state !== 'ready') return { ...info, load: load() };
    // An experiment's own set-up (e.g. a smaller drawing buffer), run in the page.
    if (opts.setup) await page.evaluate(opts.setup);
    await page.waitForTimeout(500);
    consoleLog.length = 0;
    // Every rAF callback is timed (wrapped at run time, so it works on a page given to us) and
    // the frame's callbacks summed; a loop of our own records the intervals.
    await page.evaluate(() => {
      const w = /** @type {any} */ (window);
      const raw = w.__perf3dRaf || window.requestAnimationFrame.bind(window);
      w.__perf3dRaf = raw;
      const js = new Map();
      window.requestAnimationFrame = (cb) =>
        raw((ts) => {
          const t0 = performance.now();
          try {
            cb(ts);
          } finally {
            js.set(ts, (js.get(ts) || 0) + performance.now() - t0);
          }
        });
      w.__perf3d = { ts: [], js, on: true };
      const loop = (ts) => {
        if (!w.__perf3d.on) return;
        w.__perf3d.ts.push(ts);
        raw(loop);
      };
      raw(loop);
    });
    const f0 = await page.evaluate(() => Number(__wl.q('[data-wing3d]').dataset.frames || 0));
    await page.evaluate(() => document.querySelector('wing-lab').wing3d.setPlaying(true));
    const t0 = Date.now();
    const cpu0 = cpuByProcess(pid);
    await page.waitForTimeout(seconds * 1000);
    const cpu1 = cpuByProcess(pid);
    const f1p = await page.evaluate(() => Number(__wl.q('[data-wing3d]').dataset.frames || 0));
    const played = (Date.now() - t0) / 1000;
    const slider = [];
    if (opts.sliders) {
      // Slider latency while playing: keydown on γ0 → the lab's next finished render.
      await page.evaluate(() => {
        const w = /** @type {any} */ (window);
        w.__perf3dKeys = { downs: [], ends: [] };
        __wl
          .q('input[type=range][data-key="gamma0"]')
          .addEventListener('keydown', (e) => w.__perf3dKeys.downs.push(e.timeStamp));
        document
          .querySelector('wing-lab')
          .addEventListener('wl-rendered', (e) => w.__perf3dKeys.ends.push(e.detail.end));
      });
      await page.focus('wing-lab input[type=range][data-key="gamma0"]');
      for (let i = 0; i < opts.sliders; i++) {
        const n = await page.evaluate(() => window.__perf3dKeys.ends.length);
        await page.keyboard.press(i % 2 ? 'ArrowLeft' : 'ArrowRight');
        await page.waitForFunction((k) => window.__perf3dKeys.ends.length > k, n, { timeout: 20000 }).catch(() => {});
        await page.waitForTimeout(60);
      }
      const k = await page.evaluate(() => window.__perf3dKeys);
      for (let i = 0; i < Math.min(k.downs.length, k.ends.length); i++) slider.push(k.ends[i] - k.downs[i]);
    }
    const drawn = f1p - f0;
    /** @type {Record<string, number>} CPU ms per drawn frame, by process */
    const cpu = {};
    for (const k of Object.keys(cpu1)) if (cpu0[k] != null && drawn > 0) cpu[k] = r1((cpu1[k] - cpu0[k]) / drawn);
    const still = await page.evaluate(() => document.querySelector('wing-lab').store.get().playing);
    const rec = await page.evaluate(() => {
      const w = /** @type {any} */ (window);
      w.__perf3d.on = false;
      document.querySelector('wing-lab').wing3d.setPlaying(false);
      window.requestAnimationFrame = w.__perf3dRaf;
      const ts = w.__perf3d.ts;
      return { ts, js: ts.map((t) => w.__perf3d.js.get(t) || 0) };
    });
    const iv = [];
    for (let i = 11; i < rec.ts.length; i++) iv.push(rec.ts[i] - rec.ts[i - 1]);
    const gpu = consoleLog.filter((m) => /ReadPixels|GPU stall|GL Driver Message|WebGL:|WebGPU/i.test(m.text));
    return {
      ...info,
      viewport: `${viewport.width}x${viewport.height}`,
      playing_throughout: !!still,
      raf_interval_ms: stats(iv),
      fps_median: r1(1000 / pct(iv, 0.5)),
      wing_frames_per_s: r1(drawn / played),
      cpu_ms_per_frame: cpu,
      js_per_frame_ms: stats(rec.js.slice(10)),
      slider_keydown_to_render_ms: opts.sliders ? stats(slider) : undefined,
      readpixels_warnings: gpu.filter((m) => /ReadPixels/i.test(m.text)).length,
      gpu_console: [...new Set(gpu.map((m) => `${m.type}: ${m.text}`))].slice(0, 8),
      load: load(),
    };
  } finally {
    page.off('console', onConsole);
    if (context) await context.close();
  }
}

function table(rows) {
  const head =
    '| backend (drawn on) | canvas CSS px → backing px (DPR) | rAF interval median / p90 (ms) | fps (median) | wing frames/s | JS per frame median / p90 (ms) | CPU ms per frame: renderer / GPU process / browser | ReadPixels warnings | load |';
  const lines = [head, '|---|---|---|---|---|---|---|---|---|'];
  for (const r of rows) {
    if (!r.raf_interval_ms) {
      lines.push(`| ${r.backend || r.state} | – | – | – | – | – | – | – | ${r.load} |`);
      continue;
    }
    lines.push(
      `| ${r.backend} (${r.thread || '?'}) | ${r.css.join('×')} → ${r.backing.join('×')} (${r.dpr}) | ${r.raf_interval_ms.median} / ${r.raf_interval_ms.p90} | ${r.fps_median} | ${r.wing_frames_per_s} | ${r.js_per_frame_ms.median} / ${r.js_per_frame_ms.p90} | ${r.cpu_ms_per_frame.renderer} / ${r.cpu_ms_per_frame['gpu-process']} / ${r.cpu_ms_per_frame.browser} | ${r.readpixels_warnings} | ${r.load} |`,
    );
  }
  return lines.join('\n');
}

async function main() {
  const argv = process.argv.slice(2);
  const arg = (k, d) => {
    const i = argv.indexOf(k);
    return i >= 0 ? argv[i + 1] : d;
  };
  const seconds = Number(arg('--seconds', '5'));
  const only = arg('--only', null);
  const [vw, vh] = arg('--viewport', '1280x800').split('x').map(Number);
  const sliders = Number(arg('--sliders', '0'));
  const setupJs = arg('--setup', undefined);
  const query = arg('--query', '');
  const renders = arg('--render', 'worker') === 'both' ? ['worker', 'main'] : [arg('--render', 'worker')];
  const env = await setup(undefined, { cached: false });
  const rows = [];
  try {
    for (const render of renders) {
      const opts = {
        url: env.url + query,
        setup: setupJs,
        seconds,
        viewport: { width: vw, height: vh },
        sliders,
        render,
      };
      if (!only || only === 'webgl2') rows.push({ flags: 'default', ...(await measure3d(env.browser, opts)) });
      if (!only || only === 'webgpu') {
        const b = await chromium.launch({ executablePath: CHROMIUM, args: [...ARGS, ...WEBGPU_FLAGS], headless: true });
        try {
          rows.push({ flags: 'webgpu', ...(await measure3d(b, opts)) });
        } finally {
          await b.close();
        }
      }
    }
  } finally {
    await env.close();
  }
  const out = { date: new Date().toISOString(), machine: `${os.cpus().length} cores`, rows };
  fs.mkdirSync(OUT, { recursive: true });
  fs.writeFileSync(path.join(OUT, 'perf-3d.json'), JSON.stringify(out, null, 2));
  console.log(JSON.stringify(out, null, 2));
  console.log(table(rows));
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  await main();
}
