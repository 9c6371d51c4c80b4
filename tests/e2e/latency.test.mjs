// The live analysis off the main thread (issue 12 item 1): rapid key presses on a slider end in
// the result of the final value, superseded requests are never drawn, and the numbers shown are
// those of a direct wasm computation for that value. Behaviour only; the speed is measured by
// `npm run perf` (scripts/perf.mjs), not here.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { setup, openPage, waitRenders } from './helpers.mjs';

let env;
before(async () => {
  env = await setup();
});
after(async () => {
  if (env) await env.close();
});

async function lab(query = '') {
  const o = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  // The full-page screen: the tests read the Floquet table, which is not on the first screen.
  await o.page.goto(
    env.url + (/(^|[?&])screen=/.test(query) ? query : `${query || '?'}${query ? '&' : ''}screen=full`),
  );
  await waitRenders(o.page, 1);
  // The first result is computed on the main thread; the sliders' go to the live worker once
  // it has loaded its wasm.
  await o.page.evaluate(() => {
    const w = /** @type {any} */ (window);
    const lab = __wl.lab();
    w.__drawn = [];
    w.__renderedFlap = null;
    lab.store.subscribe(['result'], (s) => w.__drawn.push(s.result.params.flap_hz));
    // `wl-rendered`: every panel shows the newest result (they redraw one task each).
    lab.addEventListener('wl-rendered', () => {
      w.__renderedFlap = lab.analysis.sim.flap_freq_hz;
    });
  });
  return o;
}

/** Starts the live worker (it starts at the first parameter change) and waits until it is ready. */
async function warm(page) {
  await page.evaluate(() => __wl.lab().engine.warmLive());
  await page.waitForFunction(() => __wl.lab().engine.liveInWorker, null, { timeout: 30000 });
  await page.evaluate(() => {
    /** @type {any} */ (window).__drawn = [];
  });
}

/** Waits until every panel shows the result for f_d = f. */
async function renderedAt(page, f) {
  await page.waitForFunction((x) => /** @type {any} */ (window).__renderedFlap === x, f, { timeout: 60000 });
}

/** The numbers panel's cells and the same quantities from a direct wasm computation of lab.config(). */
const compare = (page) =>
  page.evaluate(async () => {
    const lab = __wl.lab();
    const wb = await import('./pkg/wingbeat.js');
    const { fmt } = await import('./format.js');
    const cfg = lab.config();
    const k = lab.modeIndex();
    const direct = wb.analyze(cfg, { detrend: lab.state.detrend, segment_len: 8192 }, k);
    const shown = lab.analysis;
    let maxDiff = 0;
    for (let m = 0; m < direct.sim.modes.length; m++) {
      const a = direct.sim.modes[m].q.total,
        b = shown.sim.modes[m].q.total;
      if (a.length !== b.length) return { lengths: [a.length, b.length] };
      for (let i = 0; i < a.length; i++) maxDiff = Math.max(maxDiff, Math.abs(a[i] - b[i]));
    }
    const cell = (f) => __wl.q(`[data-field="${f}"]`).textContent;
    const f = direct.sim.modes[k].floquet;
    let peak = 0;
    for (const v of direct.sim.modes[k].q.total) peak = Math.max(peak, Math.abs(v));
    const sp = direct.spectra[k].total.psd,
      sq = shown.spectra[k].total.psd;
    let psdDiff = 0;
    for (let i = 0; i < sp.length; i++) psdDiff = Math.max(psdDiff, Math.abs(sp[i] - sq[i]));
    // The core's run-wide peaks (Analysis.peaks, used by the numbers, responses and strain
    // panels) equal a scan of every sample; its extreme_samples give the 3-D view the same
    // modal states as the page's own hull of the whole run (scene3d.extremeStates).
    const scan = (y) => {
      let p = 0;
      for (const v of y) p = Math.max(p, Math.abs(v));
      return p;
    };
    /** @type {string[]} */
    const peakMismatch = [];
    shown.sim.modes.forEach((m, j) => {
      for (const key of ['euler', 'centrifugal', 'coriolis', 'total']) {
        if (shown.peaks.q[j][key] !== scan(m.q[key]))
          peakMismatch.push(`q ${j} ${key}: ${shown.peaks.q[j][key]} vs ${scan(m.q[key])}`);
      }
    });
    const st = shown.sim.strain;
    if (!st || !shown.peaks.strain) peakMismatch.push('no strain peaks');
    else
      for (const key of ['eps_x', 'eps_y', 'gamma_xy'])
        if (shown.peaks.strain[key] !== scan(st[key])) peakMismatch.push(`strain ${key}`);
    const S = await import('./scene3d.js');
    const qs = shown.sim.modes.map((m) => m.q.total);
    const key = (st) =>
      st
        .map((x) => x.join())
        .sort()
        .join(';');
    const statesSame = key(S.statesAt(qs, shown.extreme_samples)) === key(S.extremeStates(qs, 1000));
    return {
      peakMismatch,
      statesSame,
      nStates: shown.extreme_samples.length,
      flap: shown.sim.flap_freq_hz,
      cfgFlap: cfg.kinematics.flap_freq_hz,
      maxDiff,
      psdDiff,
      feff: [cell(`feff-${k}`), fmt(f.effective_freq_hz, 6)],
      mod: [cell(`mod-${k}`), fmt(f.max_modulus, 8)],
      peak: [cell(`peak-${k}`), fmt(peak, 4)],
      anglesN: lab.store.get().result.angles.alpha.length,
      n: direct.sim.t.length,
    };
  });

test('rapid key presses on f_d end in the result of the final value; superseded results are not drawn', async () => {
  // 10 s at a non-integer flap frequency: each computation is long enough that presses queue.
  const { page, context, problems } = await lab('?flap_hz=25.5&duration=10');
  await warm(page);
  await page.focus('wing-lab input[type=range][data-key="flap_hz"]');
  const presses = 9;
  for (let i = 0; i < presses; i++) await page.keyboard.press('ArrowRight');
  const final = 25.5 + 0.5 * presses;
  // The slider and its label show the final value at once, whatever the computation's state.
  assert.equal(await page.evaluate(() => __wl.lab().state.flap_hz), final);
  await renderedAt(page, final);
  const drawn = await page.evaluate(() => /** @type {any} */ (window).__drawn);
  assert.equal(drawn[drawn.length - 1], final, `drawn in order: ${drawn.join(', ')}`);
  for (let i = 1; i < drawn.length; i++)
    assert.ok(drawn[i] > drawn[i - 1], `results drawn out of order: ${drawn.join(', ')}`);
  const stats = await page.evaluate(() => __wl.lab().engine.liveStats);
  // Every request ended one way: drawn, superseded while waiting, or dropped as stale.
  assert.equal(drawn.length + stats.superseded + stats.stale, presses, JSON.stringify({ drawn, stats }));
  const c = await compare(page);
  assert.equal(c.flap, final);
  assert.equal(c.cfgFlap, final);
  assert.equal(c.maxDiff, 0, 'the responses shown are the direct computation’s, bit for bit');
  assert.equal(c.psdDiff, 0);
  assert.equal(c.feff[0], c.feff[1]);
  assert.equal(c.mod[0], c.mod[1]);
  assert.equal(c.peak[0], c.peak[1]);
  assert.deepEqual(c.peakMismatch, [], 'the core’s peaks equal a scan of every sample');
  assert.ok(c.statesSame && c.nStates > 2, `extreme_samples: the hull of the whole run (${c.nStates} states)`);
  assert.equal(c.anglesN, c.n, 'angles on the whole time grid (for the 3-D view)');
  assert.deepEqual(problems, []);
  await context.close();
});

test('a slider moved while a study runs still updates the panels (separate live worker)', async () => {
  const { page, context, problems } = await lab();
  await warm(page);
  // A long study in the study worker; the live worker answers regardless.
  const jobId = await page.evaluate(() => {
    const lab = __wl.lab();
    const job = lab.engine.run('icmap', { cfg: { ...lab.config(), duration_s: 4 }, opts: { n_q: 101, n_qdot: 101 } });
    /** @type {any} */ (window).__study = 'running';
    job.promise.then(
      () => {
        /** @type {any} */ (window).__study = 'done';
      },
      () => {
        /** @type {any} */ (window).__study = 'cancelled';
      },
    );
    return job.id;
  });
  await page.focus('wing-lab input[type=range][data-key="flap_hz"]');
  await page.keyboard.press('ArrowLeft');
  await renderedAt(page, 24.5);
  const c = await compare(page);
  assert.equal(c.maxDiff, 0);
  assert.equal(c.feff[0], c.feff[1]);
  const stats = await page.evaluate(() => __wl.lab().engine.liveStats);
  assert.ok(stats.posted >= 1, `computed in the live worker, not here: ${JSON.stringify(stats)}`);
  await page.evaluate((id) => __wl.lab().engine.cancel(id), jobId);
  assert.deepEqual(problems, []);
  await context.close();
});
