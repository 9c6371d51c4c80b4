// The "As a neuron sees it" panel (www/views/neural.js) end to end in Chromium, on the Sensing
// screen: nothing runs until asked; the Run button, pressed from the keyboard, runs the
// published study once in the worker (wasm classifyRotation) and the panel shows it: the table
// says the report's numbers, raw strain near chance and encoded well above, the plot and the
// plate map carry the series' and the chosen sensors' colours; the strain and the sensor set
// switch from the keyboard; the guided experiment `neural-sensing` then reads the same result
// without a second run and says the same all-sensor accuracy; Cancel stops a run and Run starts
// it again; axe finds nothing; screenshots at 1280×800 and 390×844 (test-output/neural-*.png,
// and the whole panel in neural-panel-*.png).
// Run after scripts/build-web.sh www:  node --test --test-concurrency=1 tests/e2e/neural.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { createRequire } from 'node:module';
import { setup, openPage, waitRenders, pngHasColours, OUT } from './helpers.mjs';

const require = createRequire(import.meta.url);
const AXE = require.resolve('axe-core/axe.min.js');
const SEC = 'section.wl-neural';

let env;
before(async () => {
  env = await setup();
});
after(async () => {
  if (env) await env.close();
});

/** Counts the lab's worker jobs by kind (the engine's `run`, wrapped in the page). */
const countJobs = (page) =>
  page.evaluate(() => {
    const lab = /** @type {any} */ (document.querySelector('wing-lab'));
    const run = lab.engine.run.bind(lab.engine);
    /** @type {any} */ (window).__jobs = {};
    lab.engine.run = (kind, ...rest) => {
      window.__jobs[kind] = (window.__jobs[kind] || 0) + 1;
      return run(kind, ...rest);
    };
  });

const state = (page) => page.evaluate((sel) => __wl.q(sel).dataset.state, SEC);

for (const viewport of [
  { width: 1280, height: 800 },
  { width: 390, height: 844 },
]) {
  test(`the panel runs the study from the keyboard and shows it (${viewport.width}×${viewport.height})`, async () => {
    const { page, problems, context } = await openPage(env.browser, env.url, viewport);
    await page.goto(`${env.url}?screen=sensing`);
    await waitRenders(page, 1);
    await countJobs(page);
    assert.equal(await state(page), 'idle', 'nothing runs until asked');
    const run = page.locator(`wing-lab ${SEC} button[data-run="neural"]`);
    await run.scrollIntoViewIfNeeded();
    await run.focus();
    await page.keyboard.press('Enter');
    await page.waitForFunction((sel) => __wl.q(sel).dataset.state === 'ready', SEC, { timeout: 180000, polling: 200 });
    const seen = await page.evaluate((sel) => {
      const sec = __wl.q(sel);
      const rows = [...sec.querySelectorAll('.wl-neural-table tbody tr')].map((tr) =>
        [...tr.children].map((td) => td.textContent),
      );
      return {
        rows,
        jobs: window.__jobs,
        set: Number(sec.dataset.neuralSet),
        status: sec.querySelector('.wl-status').textContent,
      };
    }, SEC);
    assert.deepEqual(seen.jobs, { classify: 1 });
    const pct = (s) => Number(s.replace(/ %.*/, ''));
    const [enc, raw] = [pct(seen.rows[0][1]), pct(seen.rows[0][2])];
    assert.match(seen.rows[0][0], /^all 338 sensors$/);
    assert.ok(raw <= 60 && raw >= 40, `raw strain near chance: ${raw} %`);
    assert.ok(enc >= raw + 20, `encoded well above raw: ${enc} vs ${raw} %`);
    assert.ok(pct(seen.rows[1][1]) <= 55, `one random sensor near chance: ${seen.rows[1][1]}`);
    assert.ok(seen.set >= 1 && seen.set <= 15, `the default set is the best of at most 15 sensors: ${seen.set}`);
    assert.match(seen.status, /^Done: the plate's first modes \d/);
    // Pixels: the plot draws the random mean (blue) and the SSPOC points (orange); the plate its chosen sensors.
    await page.locator(`wing-lab ${SEC} .wl-neural-plate`).scrollIntoViewIfNeeded();
    const plate = await page.locator(`wing-lab ${SEC} .wl-neural-plate`).screenshot();
    assert.deepEqual(await pngHasColours(page, plate, ['#e66100']), { '#e66100': true });
    const plot = await page.locator(`wing-lab ${SEC} [data-plot="neural-accuracy"] canvas`).first().screenshot();
    assert.deepEqual(await pngHasColours(page, plot, ['#e66100', '#1f5fbf']), { '#e66100': true, '#1f5fbf': true });
    // Raw strain from the keyboard: the plot's text alternative and the words follow.
    await page.locator(`wing-lab ${SEC} input[value="encoded"]`).focus();
    await page.keyboard.press('ArrowDown');
    const rawWords = await page.evaluate((sel) => {
      const sec = __wl.q(sel);
      return {
        checked: sec.querySelector('input[value="raw"]').checked,
        note: sec.querySelector('.wl-neural-body > p.wl-note').textContent,
      };
    }, SEC);
    assert.ok(rawWords.checked);
    assert.match(rawWords.note, /^Raw strain: [\d.]+ % with all 338 sensors — chance/);
    await page.locator(`wing-lab ${SEC} input[value="raw"]`).focus();
    await page.keyboard.press('ArrowUp');
    // Another SSPOC set from the keyboard: the map's set follows the chooser.
    const sel = page.locator(`wing-lab ${SEC} select`);
    await sel.focus();
    await page.keyboard.press('End');
    const last = await page.evaluate((s) => {
      const sec = __wl.q(s);
      const opt = sec.querySelector('select').selectedOptions[0].textContent;
      return { opt, set: Number(sec.dataset.neuralSet) };
    }, SEC);
    assert.equal(last.set, Number(last.opt.match(/: (\d+) sensor/)[1]), `map shows the chosen set: ${last.opt}`);
    // The guided experiment reads the same result: no second run, the same all-sensor accuracy.
    await page.evaluate(() => document.querySelector('wing-lab').store.set({ exp: 'neural-sensing' }));
    await page.waitForFunction(() => __wl.qa('[data-panel="experiments"] [data-check]').length >= 3, null, {
      timeout: 30000,
    });
    const exp = await page.evaluate(() => ({
      text: __wl.q('[data-panel="experiments"] [data-exp-predict]').textContent,
      jobs: window.__jobs,
    }));
    assert.deepEqual(exp.jobs, { classify: 1 }, 'the experiment did not run the study again');
    assert.ok(
      exp.text.includes(`encoded strain tells turning from still in ${enc}`),
      `same number: ${enc} % in “${exp.text.slice(0, 200)}…”`,
    );
    // axe and the screenshot.
    await page.addScriptTag({ path: AXE });
    const vs = await page.evaluate(async (s) => {
      const r = await window.axe.run(
        { include: [__wl.axe(s)] },
        { resultTypes: ['violations'], rules: { 'target-size': { enabled: true } } },
      );
      return r.violations.map((v) => `${v.id}: ${v.help} — ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
    }, SEC);
    assert.deepEqual(vs, []);
    await page.locator(`wing-lab ${SEC} [data-plot="neural-accuracy"]`).scrollIntoViewIfNeeded();
    await page.screenshot({ path: path.join(OUT, `neural-${viewport.width}.png`) });
    await page.locator(`wing-lab ${SEC}`).screenshot({ path: path.join(OUT, `neural-panel-${viewport.width}.png`) });
    assert.deepEqual(problems, []);
    await context.close();
  });
}

test('Cancel stops a run; Run starts it again', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  await page.goto(`${env.url}?screen=sensing`);
  await waitRenders(page, 1);
  await countJobs(page);
  await page.locator(`wing-lab ${SEC} button[data-run="neural"]`).click();
  await page.waitForFunction((sel) => __wl.q(sel).dataset.state === 'computing', SEC, { timeout: 10000 });
  await page.locator(`wing-lab ${SEC} button.wl-cancel`).click();
  await page.waitForFunction((sel) => __wl.q(sel).dataset.state === 'cancelled', SEC, { timeout: 10000 });
  const after = await page.evaluate((sel) => {
    const sec = __wl.q(sel);
    return {
      run: sec.querySelector('button[data-run]').disabled,
      cancel: sec.querySelector('button.wl-cancel').hidden,
      status: sec.querySelector('.wl-status').textContent,
    };
  }, SEC);
  assert.deepEqual(after, { run: false, cancel: true, status: 'Cancelled.' });
  await page.locator(`wing-lab ${SEC} button[data-run="neural"]`).click();
  await page.waitForFunction((sel) => __wl.q(sel).dataset.state === 'ready', SEC, { timeout: 180000, polling: 200 });
  assert.deepEqual(await page.evaluate(() => window.__jobs), { classify: 2 });
  assert.deepEqual(problems, []);
  await context.close();
});
