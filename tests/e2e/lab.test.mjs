// End-to-end tests of the browser lab in headless Chromium (Debian's /usr/bin/chromium through
// playwright-core). Run after scripts/build-web.sh www:  node --test tests/e2e/
// Screenshots go to test-output/ (gitignored).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { setup, openPage, waitRenders, renders, pngStats, plotPrint, OUT } from './helpers.mjs';

let env;
before(async () => {
  env = await setup();
});
after(async () => {
  if (env) await env.close();
});

/** The lab page on its full-page screen (these tests drive panels of every screen), unless the query picks a screen. */
async function lab(query = '', viewport) {
  const o = await openPage(env.browser, env.url, viewport);
  await o.page.goto(
    env.url + (/(^|[?&])screen=/.test(query) ? query : `${query || '?'}${query ? '&' : ''}screen=full`),
  );
  await waitRenders(o.page, 1);
  return o;
}

const cell = (page, field) => page.textContent(`wing-lab [data-field="${field}"]`);
const stateOf = (page, sel = 'wing-lab') => page.evaluate((s) => ({ ...document.querySelector(s).state }), sel);

/** Frequency of the largest non-DC bin of a spectrum of the selected mode. */
const peakHz = (page, term, sel = 'wing-lab') =>
  page.evaluate(
    ([t, s]) => {
      const lab = document.querySelector(s);
      const sp = lab.analysis.spectra[lab.modeIndex()][t];
      let best = 2;
      for (let i = 2; i < sp.psd.length; i++) if (sp.psd[i] > sp.psd[best]) best = i;
      return sp.freq_hz[best];
    },
    [term, sel],
  );

async function press(page, key, selector, sel = 'wing-lab') {
  const before = await renders(page, sel);
  await page.focus(selector);
  await page.keyboard.press(key);
  await waitRenders(page, before + 1, sel);
}

test('loads the paper case: numbers, spectra, no console errors, no external requests', async () => {
  const { page, problems, context } = await lab();
  assert.equal(await cell(page, 'feff-0'), '60.3064');
  assert.equal(await cell(page, 'freq-0'), '62.5');
  assert.match(await cell(page, 'stable-0'), /^stable/);
  assert.equal(await cell(page, 'coriolis-0'), '53.79');
  assert.match(await cell(page, 'beat2-0'), /^0\.0970/);
  // Coriolis force: DC plus 2 f_d = 50 Hz (Welch bins are 10000/8192 Hz wide).
  assert.ok(Math.abs((await peakHz(page, 'coriolis')) - 50) < 1.3);
  const dc = await page.evaluate(() => {
    const s = document.querySelector('wing-lab').analysis.spectra[0].coriolis.psd;
    return s[0] / Math.max(...s.slice(2));
  });
  assert.ok(dc > 0.1, 'DC part of the Coriolis force is visible (detrend none)');
  assert.match(await page.textContent('.wl-timing'), /compute [\d.]+ ms \+ draw [\d.]+ ms/);
  assert.ok(await page.isVisible('wing-lab [data-wing3d]'));
  assert.equal(await page.isVisible('.wl-notice'), false);
  assert.deepEqual(problems, []);
  await context.close();
});

test('every slider moves by keyboard; number box, aria-valuetext, URL and plots follow', async () => {
  const { page, problems, context } = await lab();
  const keys = await page.evaluate(() =>
    [...__wl.qa('.wl-controls input[type=range][data-key]')].map((i) => i.dataset.key),
  );
  assert.equal(keys.length, 10);
  // The fluid density switches to the FE wing (a second computation): tests/e2e/air.test.mjs.
  for (const key of keys.filter((k) => k !== 'air_density')) {
    const range = `wing-lab input[type=range][data-key="${key}"]`;
    const num = `wing-lab input[type=number][data-key="${key}"]`;
    const [v0, max, step] = await page.$eval(range, (e) => [Number(e.value), Number(e.max), Number(e.step)]);
    const print0 = await plotPrint(page);
    const dir = v0 + step <= max ? 'ArrowRight' : 'ArrowLeft';
    await press(page, dir, range);
    const v1 = Number(await page.$eval(range, (e) => e.value));
    assert.ok(Math.abs(Math.abs(v1 - v0) - step) < 1e-9, `${key}: ${v0} -> ${v1}`);
    assert.equal(Number(await page.$eval(num, (e) => e.value)), v1, `${key} number box`);
    assert.match(await page.$eval(range, (e) => e.getAttribute('aria-valuetext')), new RegExp(`^${v1}`));
    await page.waitForFunction(([k, v]) => Number(new URLSearchParams(location.search).get(k)) === v, [key, v1]);
    assert.equal((await stateOf(page))[key], v1);
    const print1 = await plotPrint(page);
    assert.notDeepEqual(print1, print0, `${key}: plotted data changed`);
  }
  // γ0 → 0 (Home): the Coriolis force, its spectrum and its share vanish.
  await press(page, 'Home', 'wing-lab input[type=range][data-key="gamma0"]');
  assert.equal((await stateOf(page)).gamma0, 0);
  const maxCor = await page.evaluate(() => {
    const a = document.querySelector('wing-lab').analysis;
    return [Math.max(...a.spectra[0].coriolis.psd), Math.max(...a.spectra[0].euler.psd)];
  });
  assert.equal(maxCor[0], 0);
  assert.ok(maxCor[1] > 0);
  assert.equal(await cell(page, 'coriolis-0'), '0');
  assert.deepEqual(problems, []);
  await context.close();
});

test('sliders move by mouse drag; touch-action lets the page scroll', async () => {
  const { page, problems, context } = await lab();
  for (const key of ['gamma0', 'flap_hz', 'alpha0']) {
    const range = `wing-lab input[type=range][data-key="${key}"]`;
    const box = await page.locator(range).boundingBox();
    const before = await renders(page);
    const v0 = Number(await page.$eval(range, (e) => e.value));
    await page.mouse.move(box.x + box.width * 0.5, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width * 0.7, box.y + box.height / 2, { steps: 4 });
    await page.mouse.move(box.x + box.width * 0.9, box.y + box.height / 2, { steps: 4 });
    await page.mouse.up();
    await waitRenders(page, before + 1);
    await page.waitForTimeout(50);
    const v1 = Number(await page.$eval(range, (e) => e.value));
    assert.ok(v1 > v0, `${key}: ${v0} -> ${v1}`);
    assert.equal((await stateOf(page))[key], v1);
    assert.equal(Number(await page.$eval(`wing-lab input[type=number][data-key="${key}"]`, (e) => e.value)), v1);
  }
  assert.equal(await page.$eval('wing-lab input[type=range]', (e) => getComputedStyle(e).touchAction), 'pan-y');
  assert.deepEqual(problems, []);
  await context.close();
});

test('number boxes and the preset button', async () => {
  const { page, context } = await lab();
  const before = await renders(page);
  await page.fill('wing-lab input[type=number][data-key="flap_hz"]', '20');
  await page.press('wing-lab input[type=number][data-key="flap_hz"]', 'Enter');
  await waitRenders(page, before + 1);
  assert.equal(Number(await page.$eval('wing-lab input[type=range][data-key="flap_hz"]', (e) => e.value)), 20);
  // Coriolis force peak follows 2 f_d = 40 Hz; the Euler force has its largest line at f_d.
  assert.ok(Math.abs((await peakHz(page, 'coriolis')) - 40) < 1.3);
  assert.ok(Math.abs((await peakHz(page, 'euler')) - 20) < 1.3);
  // Out-of-range entry is clamped to the slider range.
  const b2 = await renders(page);
  await page.fill('wing-lab input[type=number][data-key="gamma0"]', '7');
  await page.press('wing-lab input[type=number][data-key="gamma0"]', 'Enter');
  await waitRenders(page, b2 + 1);
  assert.equal((await stateOf(page)).gamma0, 0.5);
  const b3 = await renders(page);
  await page.click('wing-lab .wl-preset');
  await waitRenders(page, b3 + 1);
  const s = await stateOf(page);
  assert.equal(s.flap_hz, 25);
  assert.equal(s.gamma0, 0.2);
  assert.equal(await cell(page, 'feff-0'), '60.3064');
  await context.close();
});

test('URL round trip restores the state and the numbers', async () => {
  const { page, context } = await lab('?gamma0=0.1&flap_hz=22.5&mode=2&detrend=mean&beta_phase=0.3');
  const s = await stateOf(page);
  assert.equal(s.gamma0, 0.1);
  assert.equal(s.flap_hz, 22.5);
  assert.equal(s.mode, '2');
  assert.equal(s.detrend, 'mean');
  assert.equal(s.beta_phase, 0.3);
  assert.equal(await page.$eval('wing-lab select[data-key="mode"]', (e) => e.value), '2');
  await press(page, 'ArrowRight', 'wing-lab input[type=range][data-key="alpha0"]');
  await page.waitForFunction(() => new URLSearchParams(location.search).get('alpha0') === '0.81');
  const url = page.url();
  const feff = await cell(page, 'feff-1');
  const { page: p2, context: c2, problems } = await lab(url.slice(env.url.length));
  assert.deepEqual(await stateOf(p2), await stateOf(page));
  assert.equal(await cell(p2, 'feff-1'), feff);
  assert.equal(await p2.isVisible('.wl-notice'), false);
  assert.deepEqual(problems, []);
  await c2.close();
  await context.close();
});

test('CSV export of plotted series has units and full resolution', async () => {
  const { page, context } = await lab();
  const read = async (target) => {
    const [dl] = await Promise.all([
      page.waitForEvent('download'),
      page.click(`wing-lab .wl-panel[data-panel="${target}"] .wl-head button[data-export="csv"]`),
    ]);
    return fs.readFileSync(await dl.path(), 'utf8');
  };
  const spec = (await read('spectrum')).trim().split('\n');
  assert.match(spec[0], /^# wingbeat lab; alpha0=0\.8/);
  const header = spec.find((l) => !l.startsWith('#'));
  assert.match(header, /^f \(Hz\),psd_euler_force \(\(kg\^½·m\/s²\)\^2\/Hz\),psd_centrifugal_force/);
  assert.match(header, /psd_coriolis_force/);
  assert.match(header, /psd_stiffness_force/);
  assert.match(header, /psd_total_response/);
  const rows = spec.filter((l) => !l.startsWith('#')).slice(1);
  assert.equal(rows.length, 8192 / 2 + 1);
  assert.equal(rows[0].split(',')[0], '0');
  const cor = rows.map((r) => Number(r.split(',')[3]));
  assert.ok(cor[0] > 0, 'DC of the Coriolis force');
  const time = (await read('time'))
    .trim()
    .split('\n')
    .filter((l) => !l.startsWith('#'));
  assert.match(time[0], /^t \(s\),euler_response \(kg\^½·m\)/);
  assert.equal(time.length - 1, 20001);
  // Linearity: total = euler + centrifugal + coriolis (zero initial conditions).
  const r = time[5000].split(',').map(Number);
  assert.ok(Math.abs(r[1] + r[2] + r[3] - r[4]) <= 1e-12 * Math.abs(r[4]) + 1e-20);
  const numbers = await read('numbers');
  assert.match(numbers, /Floquet effective frequency \(Hz\)","60\.3064"/);
  await context.close();
});

test('studies run in a worker with progress; sliders stay live meanwhile', async () => {
  const { page, problems, context } = await lab();
  await page.fill('wing-lab [data-study="sweep"] input[aria-label="points"]', '41');
  await page.click('wing-lab [data-run="sweep"]');
  // While the worker sweeps, the main thread still renders slider moves.
  await press(page, 'ArrowLeft', 'wing-lab input[type=range][data-key="beta0"]');
  await page.waitForFunction(() => /points in/.test(__wl.q('[data-study="sweep"] .wl-status').textContent), null, {
    timeout: 60000,
  });
  const sw = await page.evaluate(() => {
    const d = document.querySelector('wing-lab').studies.sweep.data;
    return {
      n: d.r.values.length,
      first: d.r.modes[0].coriolis[0],
      last: d.r.modes[0].coriolis[40],
      x: Array.from(d.r.values),
    };
  });
  assert.equal(sw.n, 41);
  assert.equal(sw.first, 0, 'γ0 = 0: no Coriolis share');
  assert.ok(sw.last > 50);
  await page.click('wing-lab [data-run="icmap"]');
  await page.waitForFunction(() => / in [\d.]+ ms/.test(__wl.q('[data-study="icmap"] .wl-status').textContent), null, {
    timeout: 60000,
  });
  const ic = await page.evaluate(() => document.querySelector('wing-lab').studies.icmap.data.r.coriolis_percent.length);
  assert.equal(ic, 101 * 101);
  await page.click('wing-lab [data-run="damping"]');
  await page.waitForFunction(() => /samples in/.test(__wl.q('[data-study="damping"] .wl-status').textContent), null, {
    timeout: 60000,
  });
  const [dl] = await Promise.all([
    page.waitForEvent('download'),
    page.click('wing-lab [data-study="sweep"] button[data-export="csv"]'),
  ]);
  const csv = fs.readFileSync(await dl.path(), 'utf8');
  assert.match(csv, /gamma0 \(rad\),euler_share \(%\),centrifugal_share \(%\),coriolis_share \(%\)/);
  assert.deepEqual(problems, []);
  await context.close();
});

test('screenshots: every panel has non-blank pixels; PNG export works', async () => {
  const { page, problems, context } = await lab();
  for (const [run, done] of [
    ['sweep', /points in/],
    ['icmap', / in [\d.]+ ms/],
    ['damping', /samples in/],
    ['report', /hold/],
  ]) {
    await page.click(`wing-lab [data-run="${run}"]`);
    await page.waitForFunction(
      ([r, re]) =>
        new RegExp(re).test(
          __wl.q(r === 'report' ? '.wl-report .wl-status' : `[data-study="${r}"] .wl-status`).textContent,
        ),
      [run, done.source],
      { timeout: 60000 },
    );
  }
  await page.screenshot({ path: path.join(OUT, 'lab-1280x720.png') });
  await page.screenshot({ path: path.join(OUT, 'lab-full.png'), fullPage: true });
  const panels = await page.$$eval('wing-lab .wl-panel', (ps) =>
    ps.filter((p) => !p.hidden).map((p) => p.dataset.panel),
  );
  for (const p of ['controls', 'numbers', 'time', 'spectrum', 'strain', 'studies', 'wing3d', 'report'])
    assert.ok(panels.includes(p), p);
  for (const name of panels) {
    const buf = await page
      .locator(`wing-lab .wl-panel[data-panel="${name}"]`)
      .screenshot({ path: path.join(OUT, `panel-${name}.png`) });
    const st = await pngStats(page, buf);
    assert.ok(st.fraction > 0.02 && st.colours > 8, `${name}: ${JSON.stringify(st)}`);
  }
  for (const name of ['time', 'spectrum', 'strain']) {
    // The plot canvases themselves carry lines, not just the legend.
    const buf = await page.locator(`wing-lab .wl-panel[data-panel="${name}"] canvas`).first().screenshot();
    const st = await pngStats(page, buf);
    assert.ok(st.colours > 8 && st.fraction > 0.03, `${name} canvas: ${JSON.stringify(st)}`);
  }
  const heat = await pngStats(page, await page.locator('wing-lab canvas.wl-heatmap').screenshot());
  assert.ok(heat.colours > 50, `heat map: ${JSON.stringify(heat)}`);
  const [dl] = await Promise.all([
    page.waitForEvent('download'),
    page.click('wing-lab .wl-panel[data-panel="spectrum"] .wl-head button[data-export="png"]'),
  ]);
  const png = fs.readFileSync(await dl.path());
  assert.equal(png.subarray(1, 4).toString(), 'PNG');
  assert.ok((await pngStats(page, png)).colours > 8);
  const [dl2] = await Promise.all([
    page.waitForEvent('download'),
    page.click('wing-lab .wl-panel[data-panel="numbers"] .wl-head button[data-export="png"]'),
  ]);
  assert.ok((await pngStats(page, fs.readFileSync(await dl2.path()))).fraction > 0.01);
  assert.deepEqual(problems, []);
  await context.close();
});

test('hostile URL: notice as text, defaults used, nothing injected', async () => {
  const q =
    '?gamma0=' +
    encodeURIComponent('<img src=x onerror=alert(1)>') +
    '&' +
    encodeURIComponent('<b>x</b>') +
    '=1&flap_hz=1e999&modes=abaqus';
  const { page, problems, context } = await lab(q);
  assert.ok(await page.isVisible('wing-lab .wl-notice'));
  const notice = await page.textContent('wing-lab .wl-notice');
  assert.match(notice, /gamma0/);
  assert.match(notice, /flap_hz/);
  assert.match(notice, /modes/);
  // No element from the URL anywhere (Playwright's selectors pierce the lab's shadow root); the
  // page's own scripts (main.js, a classic script since the iframe work, and modules) aside.
  assert.equal(await page.$$eval('img, b, script:not([type=module]):not([src="main.js"])', (e) => e.length), 0);
  assert.equal(await page.$eval('wing-lab .wl-notice', (e) => e.children.length), 0);
  const s = await stateOf(page);
  assert.equal(s.gamma0, 0.2);
  assert.equal(s.flap_hz, 25);
  assert.equal(s.modes, 'paper');
  assert.equal(await cell(page, 'feff-0'), '60.3064');
  await page.waitForTimeout(200);
  assert.deepEqual(problems, [], 'no dialog, no errors');
  await context.close();
});

test('embed demo: two independent labs and a chrome-less iframe', async () => {
  const o = await openPage(env.browser, env.url);
  const { page, problems, context } = o;
  await page.goto(env.url + 'embed-demo.html');
  await waitRenders(page, 1, '#lab-a');
  await waitRenders(page, 1, '#lab-b');
  const a0 = await stateOf(page, '#lab-a');
  const b0 = await stateOf(page, '#lab-b');
  assert.equal(a0.gamma0, 0.2);
  assert.equal(b0.gamma0, 0.05);
  assert.equal(b0.mode, '2');
  assert.deepEqual(b0.panels, ['controls', 'numbers', 'spectrum']);
  assert.equal(await page.isVisible('#lab-b .wl-panel[data-panel="time"]'), false);
  const rb = await renders(page, '#lab-b');
  await press(page, 'ArrowRight', '#lab-a input[type=range][data-key="gamma0"]', '#lab-a');
  await page.waitForTimeout(100);
  assert.equal((await stateOf(page, '#lab-a')).gamma0, 0.205);
  assert.equal((await stateOf(page, '#lab-b')).gamma0, 0.05);
  assert.equal(await renders(page, '#lab-b'), rb, 'lab B did not re-render');
  assert.equal(new URL(page.url()).search, '', 'embedded labs leave the host URL alone');
  // Ids are unique in each tree: the page's document and each lab's own root.
  const w3ids = await page.evaluate(() => [
    document.querySelectorAll('[id="wing3d"]').length,
    ...['#lab-a', '#lab-b'].map((h) => __wl.qa('[id="wing3d"]', h).length),
  ]);
  assert.ok(
    w3ids.every((n) => n <= 1),
    `id="wing3d" per tree: ${w3ids}`,
  );
  const frame = page.frameLocator('iframe');
  await frame.locator('wing-lab[data-renders]').waitFor({ timeout: 20000 });
  assert.equal(await frame.locator('header.site').isVisible(), false);
  assert.equal(await frame.locator('.wl-panel[data-panel="spectrum"]').isVisible(), false);
  assert.equal(await frame.locator('.wl-panel[data-panel="time"]').isVisible(), true);
  assert.deepEqual(problems, []);
  await context.close();
});

test('phone viewport: one column, no horizontal overflow', async () => {
  const { page, problems, context } = await lab('', { width: 390, height: 844 });
  const [sw, cw] = await page.evaluate(() => [
    document.documentElement.scrollWidth,
    document.documentElement.clientWidth,
  ]);
  assert.ok(sw <= cw + 1, `scrollWidth ${sw} > ${cw}`);
  const lefts = await page.$$eval('wing-lab .wl-panel', (ps) =>
    ps.filter((p) => !p.hidden).map((p) => Math.round(p.getBoundingClientRect().left)),
  );
  assert.equal(new Set(lefts).size, 1);
  await press(page, 'ArrowRight', 'wing-lab input[type=range][data-key="gamma0"]');
  await page.screenshot({ path: path.join(OUT, 'lab-phone.png'), fullPage: false });
  assert.deepEqual(problems, []);
  await context.close();
});
