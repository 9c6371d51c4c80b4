// What the responses panel says about the beat follows the live numbers: undamped it swells and
// fades every T_beat (one beat shaded); with ζ = 0.01 over 10 s (the damping experiment) it says
// the beat decays, with τ = −1/σ from the Floquet growth rate, marks where it is gone, and the
// envelope measured after that time has indeed lost its swing; with ζ = 0.1 there is no beat to
// see. The whole-run overview the damping experiment points to is readable (plot area ≥ 100 px).
// Screenshots at 1280×800 and 390×844 go to test-output/ (and SHOTS_DIR when set).
//   node --test --test-concurrency=1 tests/e2e/beat_words.test.mjs   (after scripts/build-web.sh www)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { setup, openPage, waitRenders, OUT } from './helpers.mjs';

let env;
before(async () => {
  env = await setup();
  fs.mkdirSync(OUT, { recursive: true });
});
after(async () => {
  if (env) await env.close();
});

const PANELS = 'controls,time,numbers';

/** The beat box's words and numbers, and the analysis numbers they must follow. */
async function beatState(page) {
  return page.evaluate(() => {
    const lab = document.querySelector('wing-lab');
    const box = __wl.q('.wl-beat');
    const gone = __wl.q('.wl-beat-gone');
    const m = lab.analysis.sim.modes[lab.modeIndex()];
    const over = __wl.q('.wl-overview .u-over');
    return {
      text: box.textContent,
      fate: box.dataset.beatFate,
      tau: box.dataset.beatTau === '' ? null : Number(box.dataset.beatTau),
      goneAt: box.dataset.beatGoneAt === '' ? null : Number(box.dataset.beatGoneAt),
      early: gone ? Number(gone.dataset.early) : null,
      late: gone ? Number(gone.dataset.late) : null,
      tail: gone ? Number(gone.dataset.tail) : null,
      sigma: m.floquet.growth_rate_per_s,
      period: m.floquet.beat_period_s,
      overviewPlotPx: over ? over.getBoundingClientRect().height : 0,
    };
  });
}

test('undamped: the beat swells and fades every T_beat; ζ = 0.01 over 10 s: it decays with τ = −1/σ and is gone after 3τ; ζ = 0.1: no beat', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  await page.goto(`${env.url}?panels=${PANELS}`);
  await waitRenders(page, 1);
  const paper = await beatState(page);
  assert.equal(paper.fate, 'steady');
  assert.equal(paper.tau, null);
  assert.match(paper.text, /swell and fade once every Tbeat = 0\.09703 s/);

  await page.goto(`${env.url}?zeta=0.01&duration=10&panels=${PANELS}`);
  await waitRenders(page, 1);
  const d = await beatState(page);
  assert.equal(d.fate, 'decays');
  assert.ok(d.sigma < 0);
  assert.ok(Math.abs(d.tau + 1 / d.sigma) <= 1e-12 * d.tau, `τ = −1/σ: ${d.tau} vs ${-1 / d.sigma}`);
  assert.ok(Math.abs(d.goneAt - d.tau * Math.log(20)) <= 1e-12 * d.goneAt);
  // σ = −ζω1 for a damped mode (f1 = 62.5 Hz in the paper table).
  assert.ok(Math.abs(d.sigma + 0.01 * 2 * Math.PI * 62.5) < 1e-6, `σ = ${d.sigma}`);
  assert.doesNotMatch(d.text, /swell and fade once every/);
  assert.match(d.text, /The beat decays/);
  const tau3 = String(Number(d.tau.toPrecision(3)));
  assert.ok(d.text.includes(`= ${tau3} s`), `τ = ${tau3} s in "${d.text}"`);
  assert.ok(d.text.includes(`After ${Number(d.goneAt.toPrecision(3))} s`), d.text);
  // The words hold in the numbers: from the "gone" time on, the envelope's swing is a small
  // part of the first beats' (measured 0.040 vs 0.499: the free vibration at 5 % of its start
  // leaves a swing of about 5 % of the start's, the first beats being measured after one flap),
  // and over the last fifth it is nothing (6×10⁻⁴).
  assert.ok(d.early > 0.2, `swing of the first beats ${d.early}`);
  assert.ok(d.late < 0.1 * d.early, `swing from ${d.goneAt} s on: ${d.late} (first beats ${d.early})`);
  assert.ok(d.tail < 0.01 * d.early, `swing over the last fifth: ${d.tail} (first beats ${d.early})`);
  // The overview the damping experiment points to: a readable plot, not a 20 px strip.
  assert.ok(d.overviewPlotPx >= 100, `overview plot area ${d.overviewPlotPx} px`);
  const sec = page.locator('wing-lab [data-panel="time"]');
  await sec.screenshot({ path: path.join(OUT, 'beat-damped-1280.png') });
  if (process.env.SHOTS_DIR) await sec.screenshot({ path: path.join(process.env.SHOTS_DIR, 'beat-damped-1280.png') });

  await page.goto(`${env.url}?zeta=0.1&panels=${PANELS}`);
  await waitRenders(page, 1);
  const g = await beatState(page);
  assert.equal(g.fate, 'gone');
  assert.match(g.text, /No beat to see in mode 1/);
  assert.ok(g.goneAt < g.period, `gone after ${g.goneAt} s, within one beat period ${g.period} s`);
  assert.deepEqual(problems, []);
  await context.close();
});

test('the damped beat on a phone (390×844): words, overview and screenshot', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 390, height: 844 });
  await page.goto(`${env.url}?exp=damping&panels=${PANELS},experiments`);
  await waitRenders(page, 1);
  await page.waitForFunction(() => __wl.q('.wl-beat')?.dataset.beatFate === 'decays', null, { timeout: 30000 });
  const d = await beatState(page);
  assert.ok(d.overviewPlotPx >= 100, `overview plot area ${d.overviewPlotPx} px`);
  const sec = page.locator('wing-lab [data-panel="time"]');
  await sec.screenshot({ path: path.join(OUT, 'beat-damped-390.png') });
  if (process.env.SHOTS_DIR) await sec.screenshot({ path: path.join(process.env.SHOTS_DIR, 'beat-damped-390.png') });
  assert.deepEqual(problems, []);
  await context.close();
});
