// End-to-end tests of the guided experiments and the resonance map study in headless Chromium
// (Debian's /usr/bin/chromium via playwright-core). Experiments are loaded from their shareable
// URLs and their stated predictions checked numerically against the lab's own analysis. That
// every experiment opens from `?exp=<id>` (and its chip, the attribute and the message API) with
// all of its checks holding is experiments_entry_points.test.mjs's.
// Run after scripts/build-web.sh www:  node --test --test-concurrency=1 tests/e2e/experiments.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { setup, openPage, waitRenders, OUT } from './helpers.mjs';
import { experimentQuery } from '../../www/experiments.js';

let env;
before(async () => {
  env = await setup();
});
after(async () => {
  if (env) await env.close();
});

const PANEL_IN = '[data-panel="experiments"]'; // inside the lab (page.evaluate: __wl.q)
const PANEL = `wing-lab ${PANEL_IN}`; // Playwright selectors (they pierce the shadow root)
const BOX_IN = '[data-study="resonance"]';

async function openExperiment(id, viewport) {
  const o = await openPage(env.browser, env.url, viewport);
  await o.page.goto(`${env.url}?${experimentQuery(id)}`);
  await waitRenders(o.page, 1);
  await waitChecks(o.page, id);
  return o;
}

/** Waits until the experiment panel shows `id` with all of its checks computed. */
async function waitChecks(page, id) {
  const want = { yaw: 2, ic: 1, 'air-beat': 2, 'air-superharmonic': 2, 'neural-sensing': 3 }[id];
  await page.waitForFunction(
    ([sel, exp, n]) => {
      const box = __wl.q(sel);
      if (!box || box.dataset.exp !== exp) return false;
      const checks = box.querySelectorAll('[data-check]');
      return n ? checks.length >= n : checks.length > 0;
    },
    [PANEL_IN, id, want],
    { timeout: 60000 },
  );
}

const values = (page) => page.$eval(PANEL, (b) => JSON.parse(b.dataset.values || '{}'));
const text = (page) => page.$eval(`${PANEL} .wl-exp-detail`, (e) => e.textContent);

test('the Coriolis beat: the stated period is the Floquet value and the envelope repeats at it', async () => {
  const { page, context } = await openExperiment('beat');
  const v = await values(page);
  const feff = await page.evaluate(
    () => document.querySelector('wing-lab').store.get().result.analysis.sim.modes[0].floquet.effective_freq_hz,
  );
  assert.ok(Math.abs(feff - 60.30639396854428) < 1e-9);
  assert.ok(Math.abs(v.predicted_s - 1 / (feff - 50)) < 1e-12);
  assert.ok(Math.abs(v.measured_s - v.predicted_s) / v.predicted_s < 0.02, JSON.stringify(v));
  assert.match(
    await text(page),
    /feff = 60\.31 Hz and the Coriolis force drives at 2 fd = 50 Hz, so the envelope should repeat every Tbeat = 1\/\|60\.31 − 50\| = 0\.097 s/,
  );
  await context.close();
});

test('no yaw: the Coriolis response is identically zero in every mode', async () => {
  const { page, context } = await openExperiment('no-yaw');
  const r = await page.evaluate(() => {
    const a = document.querySelector('wing-lab').store.get().result.analysis;
    return {
      nonzero: a.sim.modes.map((m) => m.q.coriolis.filter((x) => x !== 0).length),
      force: a.forces.filter(Boolean).map((f) => f.coriolis.filter((x) => x !== 0).length),
      euler: a.sim.modes.map((m) => Math.max(...m.q.euler.map(Math.abs))),
      n: a.sim.t.length,
    };
  });
  assert.deepEqual(r.nonzero, [0, 0]);
  assert.ok(r.force.every((x) => x === 0));
  assert.ok(
    r.euler.every((x) => x > 0),
    'the wing still bends',
  );
  assert.ok(r.n > 10000);
  await context.close();
});

test('damping: ζ = 0.01 over 10 s lowers the beat modulation at least 10×', async () => {
  const { page, context } = await openExperiment('damping');
  const st = await page.evaluate(() => ({ ...document.querySelector('wing-lab').store.get() }));
  assert.equal(st.duration, 10);
  assert.equal(st.zeta, 0.01);
  const v = await values(page);
  assert.ok(v.ratio >= 10, JSON.stringify(v));
  assert.ok(v.early > 0.2, `early modulation ${v.early}`);
  const n = await page.evaluate(() => document.querySelector('wing-lab').store.get().result.analysis.sim.t.length);
  assert.equal(n, 100001);
  await context.close();
});

test('parametric instability: max |λ| > 1 is shown and the response grows at the Floquet rate', async () => {
  const { page, context } = await openExperiment('instability');
  const v = await values(page);
  assert.ok(v.max_modulus > 1, JSON.stringify(v));
  assert.ok(Math.abs(v.measured - v.sigma) / v.sigma < 0.15);
  const t = await text(page);
  assert.match(t, /max \|λ\| = 1\.0\d+ per flap period > 1/);
  await context.close();
});

test('a click on an experiment link applies it in place and writes a shareable URL', async () => {
  const o = await openPage(env.browser, env.url);
  await o.page.goto(env.url);
  await waitRenders(o.page, 1);
  await o.page.evaluate(() => {
    window.__samePage = true;
  });
  await o.page.click(`${PANEL} a[data-exp="no-yaw"]`);
  await waitChecks(o.page, 'no-yaw');
  await o.page.waitForFunction(() => new URLSearchParams(location.search).get('exp') === 'no-yaw');
  assert.equal(new URL(o.page.url()).searchParams.get('gamma0'), '0');
  assert.equal(await o.page.evaluate(() => window.__samePage), true, 'no page load');
  assert.equal(await o.page.getAttribute(`${PANEL} a[data-exp="no-yaw"]`, 'aria-current'), 'true');
  const href = await o.page.getAttribute(`${PANEL} a[data-exp="damping"]`, 'href');
  assert.match(href, /exp=damping/);
  assert.match(href, /zeta=0\.01/);
  assert.deepEqual(o.problems, []);
  await o.context.close();
});

test('resonance map: curves with n·f_d lines, unstable bands, summary, CSV, cancel', async () => {
  const o = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  const { page } = o;
  await page.goto(`${env.url}?screen=full`); // every panel, export buttons unfolded
  await waitRenders(page, 1);
  const box = `wing-lab ${BOX_IN}`;
  await page.click(`${box} [data-run="resonance"]`);
  await page.waitForFunction((s) => Number(__wl.q(s).dataset.done || 0) >= 1, BOX_IN, { timeout: 60000 });
  const summary = await page.textContent(`${box} [data-summary="resonance"]`);
  // The paper case (α0 = 0.8 rad): mode 1 is unstable in the first tongue (f_eff ≈ f_d) and
  // in a narrow second one near f_eff = 2 f_d; both are read from the wasm result, not assumed.
  assert.match(summary, /mode 1 \(f = 62\.5 Hz\): unstable for fd in [\d.,–\s]+ Hz/);
  assert.match(summary, /feff = n·fd at/);
  const res = await page.evaluate(() => document.querySelector('wing-lab').views.resonance.data());
  assert.equal(res.flap_hz.length, 221);
  const m0 = res.modes[0];
  const unstable = [...m0.stable].map((s, i) => (s ? null : res.flap_hz[i])).filter((x) => x != null);
  assert.ok(
    unstable.some((f) => f > 45 && f < 58),
    'first tongue of mode 1',
  );
  assert.ok([...m0.max_modulus].some((m) => m > 1.5));
  // Axis titles carry units.
  const axes = await page.$$eval(`${box} .wl-xtitle, ${box} .wl-ytitle`, (els) =>
    els.map((e) => e.textContent).join(' | '),
  );
  assert.match(axes, /flap frequency fd \(Hz\)/);
  assert.match(axes, /frequency f \(Hz\)/);
  assert.match(axes, /largest \|multiplier\| per flap period \(–\)/);
  // CSV export: one row per flap frequency, per-mode columns with units.
  const [dl] = await Promise.all([
    page.waitForEvent('download'),
    page.click('wing-lab [data-panel="resonance"] [data-export="csv"]'),
  ]);
  const csv = fs.readFileSync(await dl.path(), 'utf8');
  const lines = csv
    .trim()
    .split('\n')
    .filter((l) => !l.startsWith('#'));
  assert.match(
    lines[0],
    /^flap_freq \(Hz\),mode1_effective_freq \(Hz\),mode1_max_multiplier_modulus,mode1_beat_period \(s\)/,
  );
  assert.equal(lines.length, 222);
  // PNG and SVG of the f_eff plot as a figure (title, legend, parameter line), PNG at 2×.
  for (const kind of ['png', 'svg']) {
    const [d] = await Promise.all([
      page.waitForEvent('download'),
      page.click(`wing-lab [data-panel="resonance"] [data-export="${kind}"]`),
    ]);
    assert.equal(d.suggestedFilename(), `wingbeat-resonance.${kind}`);
    assert.ok(fs.statSync(await d.path()).size > 5000);
  }
  const ex = await page.evaluate(() => document.querySelector('wing-lab').lastExport);
  assert.equal(ex.kind, 'svg');
  // Screenshots of the panel at both sizes.
  await page.locator(box).scrollIntoViewIfNeeded();
  await page.locator(box).screenshot({ path: path.join(OUT, 'resonance-1280.png') });
  // A 2-D map (α0 axis) can be cancelled mid-run; the lab stays live.
  await page.check(`${box} input[type=checkbox]`);
  // 9 × 601 points: about 10 s of work in wasm, inside the core's work cap (resonance::MAX_WORK,
  // 1e7 steps; since the 1e-12 step rule of issue 12, 21 × 601 is over it and refused at once).
  await page.fill(`${box} .wl-res-axis2 input[aria-label^="α0 values"]`, '9');
  await page.fill(`${box} input[aria-label^="points"]`, '601');
  await page.click(`${box} [data-run="resonance"]`);
  await page.waitForSelector(`${box} [data-cancel="resonance"]:not([hidden])`);
  await page.click(`${box} [data-cancel="resonance"]`);
  await page.waitForFunction((s) => /Cancelled/.test(__wl.q(`${s} .wl-status`).textContent), BOX_IN);
  assert.equal(await page.isDisabled(`${box} [data-run="resonance"]`), false);
  // A map over the core's work cap is refused at once, with the core's own message.
  await page.fill(`${box} .wl-res-axis2 input[aria-label^="α0 values"]`, '201');
  await page.fill(`${box} input[aria-label^="points"]`, '2001');
  await page.click(`${box} [data-run="resonance"]`);
  await page.waitForFunction((s) => /Error: .*over the cap/.test(__wl.q(`${s} .wl-status`).textContent), BOX_IN, {
    timeout: 20000,
  });
  assert.deepEqual(o.problems, []);
  await o.context.close();
});

test('resonance map with α0 as a second axis draws a heat map; phone layout screenshots', async () => {
  for (const viewport of [
    { width: 1280, height: 800 },
    { width: 390, height: 844 },
  ]) {
    const o = await openPage(env.browser, env.url, viewport);
    const { page } = o;
    // The experiment opens The beat (the responses); its map is on the Research screen.
    await page.goto(`${env.url}?${experimentQuery('instability')}&screen=research`);
    await waitRenders(page, 1);
    await waitChecks(page, 'instability');
    await page.locator(PANEL).scrollIntoViewIfNeeded();
    await page.locator(PANEL).screenshot({ path: path.join(OUT, `experiments-${viewport.width}.png`) });
    const box = `wing-lab ${BOX_IN}`;
    await page.check(`${box} input[type=checkbox]`);
    await page.fill(`${box} input[aria-label^="points"]`, '111');
    await page.fill(`${box} .wl-res-axis2 input[aria-label^="α0 values"]`, '11');
    await page.click(`${box} [data-run="resonance"]`);
    await page.waitForFunction((s) => Number(__wl.q(s).dataset.done || 0) >= 1, BOX_IN, { timeout: 60000 });
    const res = await page.evaluate(() => {
      const r = document.querySelector('wing-lab').views.resonance.data();
      return { nx: r.flap_hz.length, ny: r.alpha0 && r.alpha0.length, n: r.modes[0].max_modulus.length };
    });
    assert.deepEqual(res, { nx: 111, ny: 11, n: 1221 });
    await page.waitForTimeout(100);
    const canvas = page.locator(`${box} canvas.wl-res-heatmap`);
    assert.ok(await canvas.isVisible());
    const bb = await canvas.boundingBox();
    assert.ok(bb.width <= viewport.width, 'heat map fits the width');
    await page.locator(box).screenshot({ path: path.join(OUT, `resonance-2d-${viewport.width}.png`) });
    assert.deepEqual(o.problems, []);
    await o.context.close();
  }
});
