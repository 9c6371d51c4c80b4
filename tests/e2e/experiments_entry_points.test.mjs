// Every guided experiment is the same experiment however it is opened: its chip, the URL
// `?exp=<id>` alone, the `<wing-lab exp="<id>">` attribute (when the element connects, and
// changed on a running lab) and the iframe message API's `set({ exp: '<id>' })` each bring the
// experiment's settings (www/experiments.js experimentPatch), and the experiment's checks all hold
// on the result computed with them. One browser; one page per entry point, reused for all ten.
//   node --test --test-concurrency=1 tests/e2e/experiments_entry_points.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { setup, openPage, waitRenders } from './helpers.mjs';
import { startServer } from '../../scripts/serve.mjs';
import { EXPERIMENTS, experimentState } from '../../www/experiments.js';
import { NUMERIC } from '../../www/state.js';

/**
 * The checks each experiment must show (all holding) before it counts as open: the study-based
 * ones (yaw: the γ0 sweep, ic: the initial-condition map, the air experiments: the same case in
 * a vacuum) appear only once their worker study is in.
 */
const CHECKS = {
  beat: ['beat-period'],
  'no-yaw': ['coriolis-zero', 'envelope-zero'],
  damping: ['modulation-drop', 'stable'],
  yaw: ['share-rises', 'share-matches'],
  ic: ['rest-inside'],
  resonance: ['beat-period', 'stable'],
  instability: ['unstable', 'growth'],
  sensing: ['coriolis-present'],
  'air-beat': ['decays-within-a-beat', 'beat-gone'],
  'air-superharmonic': ['superharmonic-suppressed', 'third-harmonic-falls'],
  'neural-sensing': ['raw-cannot', 'encoding-can', 'one-sensor-chance'],
};
const PANEL_IN = '[data-panel="experiments"]';
const PANELS = 'controls,time,experiments,numbers';

let env;
/** The course page's origin (a second loopback server) for the iframe. */
let host;
let dir;
before(async () => {
  env = await setup();
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'wingbeat-exp-'));
  host = await startServer(dir, 0);
});
after(async () => {
  if (host) host.server.close();
  if (env) await env.close();
  if (dir) fs.rmSync(dir, { recursive: true, force: true });
});

test('the test covers every experiment of www/experiments.js', () => {
  assert.deepEqual(Object.keys(CHECKS).sort(), EXPERIMENTS.map((e) => e.id).sort());
});

/**
 * Waits until the lab (`hostSel` in `frame`) shows experiment `id`, its result was computed with
 * the lab's current parameters, and every check of CHECKS[id] is there and holds; then checks the
 * experiment's settings. On a timeout the message says which checks were seen.
 */
async function expectOpen(frame, id, hostSel = 'wing-lab', how = '') {
  const want = CHECKS[id];
  const keys = NUMERIC.map((p) => p.key);
  try {
    await frame.waitForFunction(
      ([sel, host, exp, ids, keys]) => {
        const lab = document.querySelector(host);
        const box = __wl.q(sel, host);
        if (!lab || !lab.store || !box || box.dataset.exp !== exp) return false;
        const s = lab.store.get();
        if (!s.result || keys.some((k) => s.result.params[k] !== s[k]) || s.result.params.modes !== s.modes)
          return false;
        const seen = Object.fromEntries(
          [...box.querySelectorAll('[data-check]')].map((c) => [c.dataset.check, c.dataset.holds === 'true']),
        );
        return ids.every((c) => seen[c] === true);
      },
      [PANEL_IN, hostSel, id, want, keys],
      { timeout: 120000, polling: 100 },
    );
  } catch (e) {
    const seen = await frame.evaluate(
      ([sel, host]) => {
        const box = __wl.q(sel, host);
        const lab = document.querySelector(host);
        return {
          exp: box && box.dataset.exp,
          checks: box && box.dataset.checks,
          text: box && (box.querySelector('.wl-exp-checks') || box).textContent.slice(0, 600),
          zeta: lab && lab.store && lab.store.get().zeta,
        };
      },
      [PANEL_IN, hostSel],
    );
    throw new Error(
      `${how} ${id}: checks ${want.join(', ')} did not all hold: ${JSON.stringify(seen)} (${e.message.split('\n')[0]})`,
    );
  }
  const st = await frame.evaluate((h) => ({ ...document.querySelector(h).state }), hostSel);
  const e = EXPERIMENTS.find((x) => x.id === id);
  const ref = experimentState(id);
  for (const p of NUMERIC) assert.equal(st[p.key], ref[p.key], `${how} ${id}: ${p.key}`);
  for (const [k, v] of Object.entries(e.params)) assert.equal(st[k], v, `${how} ${id}: ${k}`);
  assert.equal(st.exp, id);
}

test('a chip opens each experiment with its settings and its checks hold', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url);
  // The full page: every chip stays listed (a focused screen lists its own experiments only).
  await page.goto(`${env.url}?panels=${PANELS}&screen=full`);
  await waitRenders(page, 1);
  // Start away from the defaults: a chip sets every slider of the experiment, not only its own.
  await page.evaluate(() => document.querySelector('wing-lab').store.set({ gamma0: 0.3, zeta: 0.05, duration: 1 }));
  for (const e of EXPERIMENTS) {
    // An experiment opens its own screen, which lists only its screen's chips: back to the full
    // page (every chip) before the next one.
    await page.evaluate(() => document.querySelector('wing-lab').store.set({ screen: 'full' }));
    await page.click(`wing-lab a.wl-exp-link[data-exp="${e.id}"]`);
    await expectOpen(page, e.id, 'wing-lab', 'chip');
  }
  assert.deepEqual(problems, []);
  await context.close();
});

test('the URL ?exp=<id> alone opens each experiment with its settings; values given with it win', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url);
  for (const e of EXPERIMENTS) {
    await page.goto(`${env.url}?exp=${e.id}&panels=${PANELS}`);
    await expectOpen(page, e.id, 'wing-lab', 'URL');
    assert.equal(await page.isVisible('wing-lab .wl-notice'), false, `${e.id}: no notice`);
    // …states its live prediction, and every check it shows holds (not only those of CHECKS).
    const detail = await page.textContent(`wing-lab ${PANEL_IN} .wl-exp-detail`);
    assert.match(detail, /The model predicts/, e.id);
    const shown = await page.$$eval(`wing-lab ${PANEL_IN} [data-check]`, (els) =>
      els.map((c) => [c.dataset.check, c.dataset.holds === 'true']),
    );
    for (const [k, holds] of shown) assert.equal(holds, true, `${e.id}: check ${k} — ${detail}`);
  }
  await page.goto(`${env.url}?exp=damping&zeta=0.02&panels=${PANELS}`);
  await waitRenders(page, 1);
  const st = await page.evaluate(() => document.querySelector('wing-lab').state);
  assert.equal(st.zeta, 0.02, 'zeta given in the URL');
  assert.equal(st.duration, 10, "the experiment's duration");
  assert.deepEqual(problems, []);
  await context.close();
});

test('the exp attribute opens each experiment, at connection and when changed on a running lab', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url);
  await page.goto(`${env.url}?panels=${PANELS}`);
  await waitRenders(page, 1);
  // A bare element per experiment, built the way a course page writes it (no sync-url).
  await page.evaluate(() => document.querySelector('wing-lab').remove());
  for (const e of EXPERIMENTS) {
    await page.evaluate(
      ([id, panels]) => {
        document.getElementById('t-lab')?.remove();
        const l = document.createElement('wing-lab');
        l.id = 't-lab';
        l.setAttribute('panels', panels);
        l.setAttribute('exp', id);
        document.body.append(l);
      },
      [e.id, PANELS],
    );
    await expectOpen(page, e.id, '#t-lab', 'attribute');
  }
  // The same element, its attribute changed while it runs.
  for (const e of EXPERIMENTS) {
    await page.evaluate((id) => document.getElementById('t-lab').setAttribute('exp', id), e.id);
    await expectOpen(page, e.id, '#t-lab', 'attribute change');
  }
  assert.deepEqual(problems, []);
  await context.close();
});

test("the iframe message API's set({ exp }) opens each experiment with its settings", async () => {
  const labSrc = `${env.url}index.html?embed=1&panels=${PANELS}`;
  fs.writeFileSync(
    path.join(dir, 'course.html'),
    `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>course</title></head>
<body><iframe id="lab" data-wingbeat title="wingbeat lab" src="${labSrc}" style="width:100%;border:0"></iframe>
<script src="${env.url}embed-host.js"></script></body></html>`,
  );
  const { page, problems, context } = await openPage(env.browser, host.url);
  await page.goto(`${host.url}course.html`);
  const frame = () => page.frames().find((f) => f.url().startsWith(env.url));
  await page.waitForFunction(() => typeof window.wingbeatLab === 'function');
  await page.waitForFunction((u) => [...document.querySelectorAll('iframe')].some((f) => f.src.startsWith(u)), env.url);
  while (!frame()) await page.waitForTimeout(50);
  await waitRenders(frame(), 1);
  for (const e of EXPERIMENTS) {
    const r = await page.evaluate(async (id) => {
      const s = await window.wingbeatLab(document.getElementById('lab')).set({ exp: id });
      return { exp: s.params.exp, zeta: s.params.zeta, duration: s.params.duration, modes: s.params.modes };
    }, e.id);
    const ref = experimentState(e.id);
    assert.equal(r.exp, e.id);
    assert.equal(r.zeta, ref.zeta, `${e.id}: ζ in the reply`);
    assert.equal(r.duration, ref.duration, `${e.id}: duration in the reply`);
    await expectOpen(frame(), e.id, 'wing-lab', 'message API');
  }
  // Values set with exp win over the experiment's.
  const r = await page.evaluate(
    async () => (await window.wingbeatLab(document.getElementById('lab')).set({ exp: 'damping', zeta: 0.02 })).params,
  );
  assert.equal(r.zeta, 0.02);
  assert.equal(r.duration, 10);
  assert.deepEqual(problems, []);
  await context.close();
});
