#!/usr/bin/env node
// Measures the lab's performance in headless Chromium and prints the numbers quoted in
// docs/lab.md (also written to test-output/perf.json):
//   * load-to-interactive: navigation start → first complete render (wasm loaded, paper case
//     computed and drawn, sliders live), median of 5 fresh page loads;
//   * slider latency: keydown on the γ0 slider → redraw finished (includes the wait for the next
//     animation frame), plus its compute and draw parts, over 40 key presses;
//   * the 101×101 initial-condition map in wasm on the main thread (median of 20);
//   * the 3-D view: frame time at 1280×720 of a ~10k-triangle synthetic wing (WebGL2, default
//     flags; set_frame + render, wall time per requestAnimationFrame with the GPU work
//     finished: median over 120 frames) and the same for the lab's FE wing;
//   * the shell FE wing of the lab (wasm feModes, 1.25 mm and the CLI's 1.0 mm), median of 3;
//   * the wasm module's size, raw and gzipped (-9).
// Usage: node scripts/perf.mjs [--screenshot]   (--screenshot also writes docs/lab.png)
// Run `scripts/build-web.sh www` first (`npm run perf` does both).
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { setup, openPage, waitRenders, ROOT, OUT } from '../tests/e2e/helpers.mjs';

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.floor(s.length / 2)];
};
const pct = (xs, p) => {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.floor(p * s.length))];
};
const r1 = (x) => Math.round(x * 10) / 10;

const env = await setup();
const log = (...a) => { if (process.env.PERF_DEBUG) console.error(...a); };
const result = {};
try {
  // Load-to-interactive.
  const loads = [];
  for (let i = 0; i < 5; i++) {
    const { page, context } = await openPage(env.browser, env.url);
    await page.goto(env.url);
    await waitRenders(page, 1);
    loads.push(await page.evaluate(() => document.querySelector('wing-lab').lastTiming.end));
    await context.close();
  }
  log('loads', loads);
  result.load_to_interactive_ms = { median: r1(median(loads)), all: loads.map(r1) };

  const { page, context, problems } = await openPage(env.browser, env.url);
  await page.goto(env.url);
  await waitRenders(page, 1);
  // Warm up, then measure slider moves.
  await page.focus('wing-lab input[type=range][data-key="gamma0"]');
  const lat = [], comp = [], draw = [];
  // Persistent listeners: every keydown on the slider and every finished render is logged.
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
  log(log_.downs.length, log_.renders.length);
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
    const out = { backend: view.backend(), triangles: view.triangles(), size: '1280x720', frame_ms_median: Math.round(times[60] * 10) / 10, frame_ms_p90: Math.round(times[108] * 10) / 10, rAF_interval_ms: Math.round(prev * 10) / 10 };
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
    const shot = await openPage(env.browser, env.url, { width: 1280, height: 800 });
    await shot.page.goto(env.url);
    await waitRenders(shot.page, 1);
    await shot.page.waitForFunction(() => __wl.q('[data-wing3d]').dataset.state === 'ready' && Number(__wl.q('[data-wing3d]').dataset.frames) > 0, null, { timeout: 90000 });
    await shot.page.waitForTimeout(400);
    await shot.page.mouse.move(1200, 780);
    await shot.page.screenshot({ path: path.join(ROOT, 'docs', 'lab.png') });
    // docs/lab_wing3d.png: the 3-D panel, FE wing mode set, mid-run.
    await shot.page.selectOption('wing-lab select[data-key="modes"]', 'fe');
    await shot.page.waitForFunction(() => document.querySelector('wing-lab').fe && /mm/.test(__wl.q('.wl-w3-defl').textContent), null, { timeout: 90000 });
    await shot.page.evaluate(() => document.querySelector('wing-lab').wing3d.setTime(0.5125));
    await shot.page.waitForTimeout(300);
    await shot.page.locator('section.wl-wing3d').screenshot({ path: path.join(ROOT, 'docs', 'lab_wing3d.png') });
    // docs/lab_phone.png: the first screen of a phone.
    const phone = await openPage(env.browser, env.url, { width: 390, height: 844 });
    await phone.page.goto(env.url);
    await waitRenders(phone.page, 1);
    await phone.page.waitForFunction(() => __wl.q('[data-wing3d]').dataset.state === 'ready' && Number(__wl.q('[data-wing3d]').dataset.frames) > 0, null, { timeout: 90000 });
    await phone.page.waitForTimeout(400);
    await phone.page.screenshot({ path: path.join(ROOT, 'docs', 'lab_phone.png') });
    result.screenshot = ['docs/lab.png', 'docs/lab_wing3d.png', 'docs/lab_phone.png'];
    await shot.context.close();
    await phone.context.close();
  }
  result.console_problems = problems;
  await context.close();
} finally {
  await env.close();
}

const wasm = fs.readFileSync(path.join(ROOT, process.env.LAB_ROOT || 'www', 'pkg', 'wingbeat_bg.wasm'));
result.wasm_bytes = { raw: wasm.length, gzip9: zlib.gzipSync(wasm, { level: 9 }).length };
result.machine = `${(await import('node:os')).cpus().length} cores, load average ${(await import('node:os')).loadavg().map((x) => x.toFixed(1)).join(' ')}`;
fs.mkdirSync(OUT, { recursive: true });
fs.writeFileSync(path.join(OUT, 'perf.json'), JSON.stringify(result, null, 2));
console.log(JSON.stringify(result, null, 2));
