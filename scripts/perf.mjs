#!/usr/bin/env node
// Measures the lab's performance in headless Chromium and prints the numbers quoted in
// docs/lab.md (also written to test-output/perf.json):
//   * load-to-interactive: navigation start → first complete render (wasm loaded, paper case
//     computed and drawn, sliders live), median of 5 fresh page loads;
//   * the first load under network emulation (scripts/perf-load.mjs): first plot, 3-D wing and
//     bytes, cold cache, localhost and 10 Mbit/s with 40 ms RTT, medians of 5 (test-output/load.md);
//   * slider latency: keydown on the γ0 slider → redraw finished (includes the wait for the next
//     animation frame), plus its compute and draw parts, over 40 key presses;
//   * the 101×101 initial-condition map in wasm on the main thread (median of 20);
//   * slider latency per slider (issue 12 item 1; see sliderLatency below): Event Timing
//     keydown → next paint, Long Tasks (> 50 ms), the wasm compute and keydown → plots updated,
//     30 presses per slider, in two scenarios (the paper case with the 3-D view shown; f_d =
//     25.5 Hz at the longest duration with the 3-D view playing); the table is printed and
//     written to test-output/latency.md (LATENCY_STEPS, LATENCY_GAP_MS, LATENCY_SLIDERS=a,b
//     change the run);
//   * the 3-D view: frame time at 1280×720 of a ~10k-triangle synthetic wing (WebGL2, default
//     flags; set_frame + render, wall time per requestAnimationFrame with the GPU work
//     finished: median over 120 frames) and the same for the lab's FE wing;
//   * the lab's 3-D view playing at 1280×800 (WebGL2): scripts/perf-3d.mjs's measure3d;
//   * the shell FE wing of the lab (wasm feModes, 1.25 mm and the CLI's 1.0 mm), median of 3;
//   * the two wasm modules' sizes (full and live builds), raw, gzip -9 and Brotli 11.
// Usage: node scripts/perf.mjs [--screenshot] [--latency-only]   (--screenshot also writes
// docs/lab.png; --latency-only measures only the sliders, into test-output/perf-latency.json)
// Run `scripts/build-web.sh www` first (`npm run perf` does both).
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import os from 'node:os';
import { setup, openPage, WITH_SERVICE_WORKER, waitRenders, ROOT, OUT } from '../tests/e2e/helpers.mjs';
import { measure3d } from './perf-3d.mjs';
import { measureLoad, loadTable } from './perf-load.mjs';

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.floor(s.length / 2)];
};
const pct = (xs, p) => {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.floor(p * s.length))];
};
const r1 = (x) => Math.round(x * 10) / 10;

const env = await setup(undefined, { cached: false });
const log = (...a) => {
  if (process.env.PERF_DEBUG) console.error(...a);
};
const result = {};
try {
  // Load-to-interactive.
  const loads = [];
  for (let i = 0; i < (process.argv.includes('--latency-only') ? 0 : 5); i++) {
    const { page, context } = await openPage(env.browser, env.url, undefined, WITH_SERVICE_WORKER);
    await page.goto(env.url);
    await waitRenders(page, 1);
    loads.push(await page.evaluate(() => document.querySelector('wing-lab').lastTiming.end));
    await context.close();
  }
  log('loads', loads);
  if (loads.length) result.load_to_interactive_ms = { median: r1(median(loads)), all: loads.map(r1) };
  if (!process.argv.includes('--latency-only')) {
    // The first load as a pupil sees it: cold cache, localhost and a 10 Mbit/s, 40 ms link
    // (scripts/perf-load.mjs); the table goes to test-output/load.md.
    result.load = await measureLoad(env.browser, env.url, 5);
    const lt = loadTable(result.load);
    fs.mkdirSync(OUT, { recursive: true });
    fs.writeFileSync(path.join(OUT, 'load.md'), lt);
    console.log(lt);
  }

  const { page, context, problems } = await openPage(env.browser, env.url, undefined, WITH_SERVICE_WORKER);
  await page.goto(env.url);
  await waitRenders(page, 1);
  if (!process.argv.includes('--latency-only')) {
    // Legacy figure (docs/lab.md): γ0 keydown → redraw finished, 40 presses.
    await page.focus('wing-lab input[type=range][data-key="gamma0"]');
    const lat = [],
      comp = [],
      draw = [];
    await page.evaluate(() => {
      const lab = document.querySelector('wing-lab');
      const input = __wl.q('input[type=range][data-key="gamma0"]');
      window.__perf = { downs: [], renders: [] };
      input.addEventListener('keydown', (e) => window.__perf.downs.push(e.timeStamp));
      lab.addEventListener('wl-rendered', (e) => window.__perf.renders.push(e.detail));
    });
    for (let i = 0; i < 50; i++) {
      await page.keyboard.press(i % 2 ? 'ArrowLeft' : 'ArrowRight');
      await page.waitForFunction((n) => window.__perf.renders.length >= n, i + 1, { timeout: 20000 });
      await page.waitForTimeout(40);
    }
    const log_ = await page.evaluate(() => window.__perf);
    for (let i = 10; i < 50; i++) {
      const r = log_.renders[i];
      lat.push(r.end - log_.downs[i]);
      comp.push(r.compute);
      draw.push(r.draw);
    }
    result.slider = {
      keydown_to_redrawn_ms: { median: r1(median(lat)), p90: r1(pct(lat, 0.9)) },
      compute_ms: { median: r1(median(comp)), p90: r1(pct(comp, 0.9)) },
      draw_ms: { median: r1(median(draw)), p90: r1(pct(draw, 0.9)) },
      compute_plus_draw_ms: { median: r1(median(comp.map((c, i) => c + draw[i]))) },
      samples: lat.length,
    };
  }

  // Slider latency per slider (issue 12 item 1): Event Timing keydown → next paint, Long Tasks,
  // the wasm compute of each recompute and keydown → plots updated, STEPS key presses each.
  result.latency = await sliderLatency(env);
  const table = latencyTable(result.latency);
  fs.mkdirSync(OUT, { recursive: true });
  fs.writeFileSync(path.join(OUT, 'latency.md'), table);
  console.log(table);
  if (process.argv.includes('--latency-only')) {
    result.machine = machine();
    fs.writeFileSync(path.join(OUT, 'perf-latency.json'), JSON.stringify(result, null, 2));
    await context.close();
    await env.close();
    process.exit(0);
  }

  // IC map 101×101 in wasm, main thread.
  result.ic_map_101x101_ms = await page.evaluate(async () => {
    const wb = await import('./pkg/wingbeat.js');
    const cfg = document.querySelector('wing-lab').config();
    for (let i = 0; i < 5; i++) wb.icMap(cfg, { n_q: 101, n_qdot: 101 });
    const ts = [];
    for (let i = 0; i < 20; i++) {
      const t = performance.now();
      wb.icMap(cfg, { n_q: 101, n_qdot: 101 });
      ts.push(performance.now() - t);
    }
    ts.sort((a, b) => a - b);
    return { median: Math.round(ts[10] * 10) / 10, max: Math.round(ts[19] * 10) / 10 };
  });

  // 3-D frame time: a 1280×720 canvas, the synthetic wing on a 100 × 51 grid (10 149 triangles).
  result.wing3d = await page.evaluate(async () => {
    const wb = await import('./pkg/wingbeat.js');
    if (typeof wb.WingView !== 'function') return 'this build has no renderer';
    const c = document.createElement('canvas');
    c.width = 1280;
    c.height = 720;
    c.style.cssText = 'position:fixed;left:0;top:0;width:1280px;height:720px';
    document.body.append(c);
    const view = await wb.WingView.createSynthetic(c, 100, 51);
    const q = new Float64Array([1.5e-5, -1.5e-5]);
    const gl = c.getContext('webgl2');
    const times = [];
    let prev = 0;
    for (let i = 0; i < 140; i++) {
      await new Promise((r) => requestAnimationFrame(r));
      const t0 = performance.now();
      view.set_frame(0.8 * Math.sin(i / 10), 0.5 * Math.sin(i / 10), 0.2 * Math.sin(i / 10), q, 50, 4);
      view.render();
      if (gl) gl.finish();
      const t1 = performance.now();
      if (i >= 20) times.push(t1 - t0);
      if (i === 20) prev = t0;
      if (i === 139) prev = (t1 - prev) / 119;
    }
    times.sort((a, b) => a - b);
    const out = {
      backend: view.backend(),
      triangles: view.triangles(),
      size: '1280x720',
      frame_ms_median: Math.round(times[60] * 10) / 10,
      frame_ms_p90: Math.round(times[108] * 10) / 10,
      rAF_interval_ms: Math.round(prev * 10) / 10,
    };
    view.free();
    c.remove();
    return out;
  });
  result.fe_wasm_ms = await page.evaluate(async () => {
    const wb = await import('./pkg/wingbeat.js');
    const out = {};
    for (const h of [1.25, 1.0]) {
      const ts = [];
      let fe;
      for (let i = 0; i < 3; i++) {
        const t = performance.now();
        fe = wb.feModes({ n_modes: 2, mesh_size_mm: h });
        ts.push(performance.now() - t);
      }
      ts.sort((a, b) => a - b);
      out[`${h}mm`] = { median: Math.round(ts[1]), nodes: fe.n_nodes, f1_hz: Math.round(fe.freq_hz[0] * 100) / 100 };
    }
    return out;
  });

  if (process.argv.includes('--screenshot')) {
    // docs/lab.png: the first screen at 1280×800 (wing, sliders, responses with the beat).
    const shot = await openPage(env.browser, env.url, { width: 1280, height: 800 }, WITH_SERVICE_WORKER);
    await shot.page.goto(env.url);
    await waitRenders(shot.page, 1);
    await shot.page.waitForFunction(
      () => __wl.q('[data-wing3d]').dataset.state === 'ready' && Number(__wl.q('[data-wing3d]').dataset.frames) > 0,
      null,
      { timeout: 90000 },
    );
    await shot.page.waitForTimeout(400);
    await shot.page.mouse.move(1200, 780);
    await shot.page.screenshot({ path: path.join(ROOT, 'docs', 'lab.png') });
    // docs/lab_wing3d.png: the 3-D panel, FE wing mode set, mid-run.
    await shot.page.selectOption('wing-lab select[data-key="modes"]', 'fe');
    await shot.page.waitForFunction(
      () => document.querySelector('wing-lab').fe && /mm/.test(__wl.q('.wl-w3-defl').textContent),
      null,
      {
        timeout: 90000,
      },
    );
    await shot.page.evaluate(() => document.querySelector('wing-lab').wing3d.setTime(0.5125));
    await shot.page.waitForTimeout(300);
    await shot.page.locator('section.wl-wing3d').screenshot({ path: path.join(ROOT, 'docs', 'lab_wing3d.png') });
    // docs/lab_phone.png: the first screen of a phone.
    const phone = await openPage(env.browser, env.url, { width: 390, height: 844 }, WITH_SERVICE_WORKER);
    await phone.page.goto(env.url);
    await waitRenders(phone.page, 1);
    await phone.page.waitForFunction(
      () => __wl.q('[data-wing3d]').dataset.state === 'ready' && Number(__wl.q('[data-wing3d]').dataset.frames) > 0,
      null,
      { timeout: 90000 },
    );
    await phone.page.waitForTimeout(400);
    await phone.page.screenshot({ path: path.join(ROOT, 'docs', 'lab_phone.png') });
    result.screenshot = ['docs/lab.png', 'docs/lab_wing3d.png', 'docs/lab_phone.png'];
    await shot.context.close();
    await phone.context.close();
  }
  if (!process.argv.includes('--latency-only')) {
    // The lab's 3-D view playing at the default layout (WebGL2 with this browser's flags):
    // rAF intervals, JS and CPU per frame (scripts/perf-3d.mjs; run it alone for WebGPU too).
    await context.close();
    result.lab_3d_webgl2 = await measure3d(env.browser, {
      url: env.url,
      seconds: 5,
      viewport: { width: 1280, height: 800 },
    });
    log('lab 3-D view playing (WebGL2):', JSON.stringify(result.lab_3d_webgl2));
  } else {
    await context.close();
  }
  result.console_problems = problems;
} finally {
  await env.close();
}

const wasmBytes = (/** @type {string} */ name) => {
  const w = fs.readFileSync(path.join(ROOT, process.env.LAB_ROOT || 'www', 'pkg', name));
  return {
    raw: w.length,
    gzip9: zlib.gzipSync(w, { level: 9 }).length,
    brotli11: zlib.brotliCompressSync(w, { params: { [zlib.constants.BROTLI_PARAM_QUALITY]: 11 } }).length,
  };
};
result.wasm_bytes = wasmBytes('wingbeat_bg.wasm');
result.live_wasm_bytes = wasmBytes('wingbeat_live_bg.wasm');
result.machine = machine();
fs.mkdirSync(OUT, { recursive: true });
fs.writeFileSync(path.join(OUT, 'perf.json'), JSON.stringify(result, null, 2));
console.log(JSON.stringify(result, null, 2));

function machine() {
  return `${os.cpus().length} cores, load average ${os
    .loadavg()
    .map((x) => x.toFixed(2))
    .join(' ')} (1, 5, 15 min)`;
}

/**
 * Per-slider latency in a fresh 1280×800 page per scenario, with the 3-D view on screen:
 *   * keydown → next paint: the Event Timing API's `duration` of each keydown on the slider
 *     (rounded by the browser to 8 ms; entries under its 16 ms floor are not reported, so a
 *     key press without an entry counts as 16 ms, an upper bound);
 *   * long tasks (Long Tasks API, > 50 ms on the main thread) from the first key press to the
 *     last redraw, count and longest;
 *   * compute: the wasm time of each redraw (`wl-rendered` detail.compute);
 *   * keydown → plots updated: from the key press to the `wl-rendered` event of its result.
 * STEPS presses per slider (half one way, half back), each waiting for its redraw (≤ 3 s) and
 * LATENCY_GAP_MS more, as a person stepping a slider would.
 */
async function sliderLatency(env) {
  const STEPS = Number(process.env.LATENCY_STEPS || 30);
  const GAP = Number(process.env.LATENCY_GAP_MS || 60);
  const keys = ['alpha0', 'beta0', 'gamma0', 'flap_hz', 'zeta', 'alpha_phase', 'beta_phase', 'gamma_phase', 'duration'];
  const only = process.env.LATENCY_SLIDERS ? process.env.LATENCY_SLIDERS.split(',') : keys;
  const scenarios = [
    { name: 'paper case, 2 s, 3-D view shown (paused)', query: '', play: false },
    { name: 'f_d 25.5 Hz, 10 s (longest), 3-D view playing', query: '?flap_hz=25.5&duration=10', play: true },
    {
      name: '6 FE modes, f_d 25.5 Hz, 10 s, 3-D view playing',
      query: '?modes=fe&n_modes=6&flap_hz=25.5&duration=10',
      play: true,
    },
  ].filter((_, i) => !process.env.LATENCY_SCENARIOS || process.env.LATENCY_SCENARIOS.split(',').includes(String(i)));
  // LATENCY_RENDER=main: the 3-D view drawn on the page's main thread (the lab's render="main"),
  // for the side-by-side with the worker (the default)
  const render = process.env.LATENCY_RENDER || 'worker';
  const out = [];
  for (const sc of scenarios) {
    const { page, context } = await openPage(
      env.browser,
      env.url + sc.query,
      { width: 1280, height: 800 },
      WITH_SERVICE_WORKER,
    );
    if (render === 'main')
      await page.addInitScript(() =>
        document.addEventListener('DOMContentLoaded', () => {
          const lab = document.querySelector('wing-lab');
          if (lab) lab.setAttribute('render', 'main');
        }),
      );
    await page.goto(env.url + sc.query);
    await waitRenders(page, 1);
    await page
      .waitForFunction(
        () =>
          __wl.q('[data-wing3d]') &&
          __wl.q('[data-wing3d]').dataset.state === 'ready' &&
          Number(__wl.q('[data-wing3d]').dataset.frames) > 0,
        null,
        { timeout: 90000 },
      )
      .catch(() => {});
    if (sc.play) await page.evaluate(() => __wl.lab().store.set({ playing: true }));
    await page.evaluate(() => {
      const lab = __wl.lab();
      const w = /** @type {any} */ (window);
      w.__lat = { downs: [], events: [], long: [], renders: [] };
      window.addEventListener('keydown', (e) => w.__lat.downs.push(e.timeStamp), true);
      lab.addEventListener('wl-rendered', (e) => w.__lat.renders.push(e.detail));
      new PerformanceObserver((l) => {
        for (const x of l.getEntries())
          if (x.name === 'keydown') w.__lat.events.push({ start: x.startTime, duration: x.duration });
      }).observe(/** @type {any} */ ({ type: 'event', durationThreshold: 16, buffered: false }));
      new PerformanceObserver((l) => {
        for (const x of l.getEntries()) w.__lat.long.push({ start: x.startTime, duration: x.duration });
      }).observe({ type: 'longtask', buffered: false });
    });
    for (const key of only) {
      const sel = `wing-lab input[type=range][data-key="${key}"]`;
      await page.focus(sel);
      const atMax = await page.evaluate((k) => {
        const r = __wl.q(`input[type=range][data-key="${k}"]`);
        return Number(r.value) >= Number(r.max) - 1e-9;
      }, key);
      await page.evaluate(() => {
        const w = /** @type {any} */ (window);
        w.__lat.downs = [];
        w.__lat.events = [];
        w.__lat.long = [];
        w.__lat.renders = [];
      });
      const t0 = await page.evaluate(() => performance.now());
      const perPress = [];
      for (let i = 0; i < STEPS; i++) {
        const before = await page.evaluate(() => /** @type {any} */ (window).__lat.renders.length);
        const up = i < STEPS / 2 !== atMax;
        await page.keyboard.press(up ? 'ArrowRight' : 'ArrowLeft');
        await page
          .waitForFunction((n) => /** @type {any} */ (window).__lat.renders.length > n, before, { timeout: 3000 })
          .catch(() => {});
        const r = await page.evaluate((n) => {
          const w = /** @type {any} */ (window);
          return {
            down: w.__lat.downs[w.__lat.downs.length - 1],
            render: w.__lat.renders[w.__lat.renders.length - 1],
            fresh: w.__lat.renders.length > n,
          };
        }, before);
        perPress.push(r);
        await page.waitForTimeout(GAP);
      }
      await page.waitForTimeout(200);
      const lat = await page.evaluate(() => /** @type {any} */ (window).__lat);
      const paint = perPress.map((p) => {
        const e = lat.events.find((x) => Math.abs(x.start - p.down) < 1);
        return e ? e.duration : 16;
      });
      const fresh = perPress.filter((p) => p.fresh && p.render);
      const compute = fresh.map((p) => p.render.compute);
      const plots = fresh.map((p) => p.render.end - p.down);
      const long = lat.long.filter((x) => x.start >= t0);
      const thread = await page.evaluate(() => __wl.q('[data-wing3d]').dataset.thread || null);
      out.push({
        scenario: `${sc.name} (3-D drawn on the ${thread === 'worker' ? 'worker' : 'main thread'})`,
        slider: key,
        presses: perPress.length,
        keydown_to_paint_ms: {
          median: r1(median(paint)),
          p90: r1(pct(paint, 0.9)),
          max: r1(Math.max(...paint)),
          under_16: paint.filter((_, i) => !lat.events.find((x) => Math.abs(x.start - perPress[i].down) < 1)).length,
        },
        long_tasks: { count: long.length, longest_ms: long.length ? r1(Math.max(...long.map((x) => x.duration))) : 0 },
        compute_ms: compute.length ? { median: r1(median(compute)), p90: r1(pct(compute, 0.9)) } : null,
        keydown_to_plots_ms: plots.length ? { median: r1(median(plots)), p90: r1(pct(plots, 0.9)) } : null,
        redraws: fresh.length,
      });
      log(out[out.length - 1]);
    }
    await context.close();
  }
  return { steps: STEPS, gap_ms: GAP, machine: machine(), rows: out };
}

/** The latency rows as a Markdown table. */
function latencyTable(l) {
  const lines = [
    `Slider latency, headless Chromium, 1280×800, ${l.steps} key presses per slider (${l.machine})`,
    '',
    '| scenario | slider | keydown→paint median (ms) | p90 (ms) | long tasks >50 ms (longest) | compute median / p90 (ms) | keydown→plots median / p90 (ms) |',
    '|---|---|---|---|---|---|---|',
  ];
  for (const r of l.rows) {
    lines.push(
      `| ${r.scenario} | ${r.slider} | ${r.keydown_to_paint_ms.median} | ${r.keydown_to_paint_ms.p90} | ${r.long_tasks.count} (${r.long_tasks.longest_ms}) | ${r.compute_ms ? `${r.compute_ms.median} / ${r.compute_ms.p90}` : '–'} | ${r.keydown_to_plots_ms ? `${r.keydown_to_plots_ms.median} / ${r.keydown_to_plots_ms.p90}` : '–'} |`,
    );
  }
  lines.push(
    '',
    'keydown→paint: Event Timing duration (8 ms granularity; a press with no entry, i.e. under 16 ms, counts as 16).',
  );
  return lines.join('\n') + '\n';
}
