// End-to-end: the wing in air in headless Chromium. The Medium control is used from the keyboard
// (vacuum → air switches the mode set to the FE wing), and what the page then shows is checked
// against the lab's own analysis: the Floquet table's air rows (still-air frequency, ζ_a, decay
// time, the beat's fate), the beat's words naming the air's damping, the aerodynamic force in
// the spectrum panel (its colour's pixels there in air, none in a vacuum); a `?air_density=`
// URL alone opens the FE wing in air; a fluid with the paper's table modes is refused by name;
// axe finds nothing in the controls and the table; screenshots at 1280×800 and 390×844.
// Run after scripts/build-web.sh www:  node --test --test-concurrency=1 tests/e2e/air.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { setup, openPage, waitRenders, pngHasColours, OUT } from './helpers.mjs';

const require = createRequire(import.meta.url);
const AXE = require.resolve('axe-core/axe.min.js');
const AERO = '#0f7c8c'; // www/plot.js color('aerodynamic')

let env;
before(async () => {
  env = await setup();
});
after(async () => {
  if (env) await env.close();
});

/** Waits for a result in the medium `rho` (kg/m³) on the FE wing. */
async function waitMedium(page, rho) {
  await page.waitForFunction(
    (r) => {
      const l = document.querySelector('wing-lab');
      if (!l || !l.store) return false;
      const s = l.store.get();
      const a = s.result && s.result.analysis;
      if (!a || s.modes !== 'fe' || !s.fe) return false;
      return r > 0 ? !!a.sim.air && a.sim.air.aero.air_density_kg_m3 === r : !a.sim.air;
    },
    rho,
    { timeout: 90000 },
  );
  await page.waitForTimeout(300); // the panels draw after the result is published
}

const cell = (page, f) => page.evaluate((f) => __wl.q(`[data-field="${f}"]`).textContent, f);
const rowHidden = (page, r) => page.evaluate((r) => __wl.q(`tr[data-row="${r}"]`).hidden, r);

test('the Medium control, from the keyboard: air on the FE wing, the table and spectrum say what air does', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  await page.goto(`${env.url}?screen=full`);
  await waitRenders(page, 1);
  assert.equal(await rowHidden(page, 'still'), true, 'no air rows in a vacuum');
  // Keyboard: focus the Medium select and step down to helium, then air.
  await page.evaluate(() => __wl.q('select[data-key="medium"]').focus());
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('ArrowDown');
  assert.equal(await page.evaluate(() => __wl.q('select[data-key="medium"]').value), 'air');
  await waitMedium(page, 1.2);
  const st = await page.evaluate(() => {
    const s = document.querySelector('wing-lab').store.get();
    const m = s.result.analysis.sim.modes[0];
    return { modes: s.modes, rho: s.air_density, air: m.air, floquet: m.floquet, share: m.contribution_percent };
  });
  assert.equal(st.modes, 'fe', 'a fluid switched the mode set to the FE wing');
  assert.equal(st.rho, 1.2);
  // The added mass lowers mode 1 (62.5 Hz in a vacuum) and air damps it within a beat.
  assert.ok(st.air.still_air_freq_hz > 50 && st.air.still_air_freq_hz < 62, JSON.stringify(st.air));
  assert.ok(st.air.decay_time_s > 0.005 && st.air.decay_time_s < st.floquet.beat_period_s);
  assert.equal(await rowHidden(page, 'still'), false);
  assert.equal(Number(await cell(page, 'still-0')), Number(st.air.still_air_freq_hz.toPrecision(5)));
  assert.equal(Number(await cell(page, 'aero-0')), Number(st.share.aerodynamic.toPrecision(4)));
  assert.match(await cell(page, 'fate-0'), /^gone within one beat \(τ 0\.0\d+ s < 0\.\d+ s\)$/);
  const words = await page.evaluate(() => __wl.q('section.wl-time').textContent);
  assert.match(words, /No beat to see in mode 1/);
  assert.match(words, /the air’s damping \(cycle-averaged ζa = 0\.1\d+\)/);
  assert.doesNotMatch(await page.evaluate(() => __wl.root().textContent), /NaN/);
  // The spectrum panel: a legend button and drawn pixels of the aerodynamic force.
  const legend = page.locator('wing-lab section.wl-spectrum .wl-legend-item', { hasText: 'Aerodynamic force' });
  assert.equal(await legend.isVisible(), true);
  const spec = await page.locator('wing-lab section.wl-spectrum canvas').first().screenshot();
  assert.deepEqual(await pngHasColours(page, spec, [AERO]), { [AERO]: true }, 'aerodynamic PSD drawn');
  await page.locator('wing-lab section.wl-controls').screenshot({ path: path.join(OUT, 'air-controls-1280.png') });
  await page.locator('wing-lab section.wl-numbers').screenshot({ path: path.join(OUT, 'air-numbers-1280.png') });
  await page.addScriptTag({ path: AXE });
  const vs = await page.evaluate(async () => {
    const include = ['controls', 'numbers', 'spectrum'].map((n) => __wl.axe(`section.wl-${n}`));
    const r = await window.axe.run({ include }, { resultTypes: ['violations'] });
    return r.violations.map((v) => `${v.id}: ${v.help} — ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
  });
  assert.deepEqual(vs, []);
  // Back to a vacuum from the keyboard: the air rows and the aerodynamic series go.
  await page.evaluate(() => __wl.q('select[data-key="medium"]').focus());
  await page.keyboard.press('Home');
  await waitMedium(page, 0);
  assert.equal(await rowHidden(page, 'still'), true);
  assert.equal(await legend.isVisible(), false);
  const spec0 = await page.locator('wing-lab section.wl-spectrum canvas').first().screenshot();
  assert.deepEqual(await pngHasColours(page, spec0, [AERO]), { [AERO]: false }, 'nothing aerodynamic in a vacuum');
  assert.deepEqual(problems, []);
  await context.close();
});

test('a URL with air_density alone opens the FE wing in air; with the paper modes it is refused by name', async () => {
  for (const viewport of [
    { width: 1280, height: 800 },
    { width: 390, height: 844 },
  ]) {
    const { page, problems, context } = await openPage(env.browser, env.url, viewport);
    await page.goto(`${env.url}?air_density=1.2`);
    await waitMedium(page, 1.2);
    assert.equal(await page.evaluate(() => __wl.q('select[data-key="medium"]').value), 'air');
    await page.waitForTimeout(1500);
    await page.screenshot({ path: path.join(OUT, `air-beat-${viewport.width}.png`) });
    assert.deepEqual(problems, []);
    await context.close();
  }
  const { page, context } = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  await page.goto(`${env.url}?air_density=1.2&modes=paper`);
  await waitRenders(page, 0);
  await page.waitForFunction(() => /air_density = 1\.2 kg\/m³ needs the FE wing/.test(__wl.root().textContent), null, {
    timeout: 30000,
  });
  await context.close();
});

test('helium: the beat fades over about a beat instead of vanishing (custom density via the number box)', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  await page.goto(`${env.url}?air_density=0.18`);
  await waitMedium(page, 0.18);
  assert.equal(await page.evaluate(() => __wl.q('select[data-key="medium"]').value), 'helium');
  const fate = await cell(page, 'fate-0');
  assert.match(fate, /^(fades over [\d.]+ beats|gone within one beat) \(τ 0\.1\d* s/);
  // The density slider from the keyboard, from a vacuum with the paper's modes: the FE wing in 0.01 kg/m³.
  await page.goto(`${env.url}?screen=full`);
  await waitRenders(page, 1);
  await page.evaluate(() => __wl.q('input[type="range"][data-key="air_density"]').focus());
  await page.keyboard.press('ArrowRight');
  await waitMedium(page, 0.01);
  assert.equal(await page.evaluate(() => __wl.q('select[data-key="medium"]').value), 'custom');
  // A custom density typed into the slider's number box.
  await page.evaluate(() => {
    const n = __wl.q('input[data-key="air_density"][type="number"]');
    n.value = '0.6';
    n.dispatchEvent(new Event('change'));
  });
  await waitMedium(page, 0.6);
  assert.equal(await page.evaluate(() => __wl.q('select[data-key="medium"]').value), 'custom');
  fs.mkdirSync(OUT, { recursive: true });
  assert.deepEqual(problems, []);
  await context.close();
});

test('the sensing panel runs in the chosen medium and says so; air changes the detectability map', async () => {
  const best = {};
  for (const [name, q] of [
    ['air', 'screen=sensing&air_density=1.2'],
    ['vacuum', 'screen=sensing&modes=fe'],
  ]) {
    const { page, problems, context } = await openPage(env.browser, env.url, { width: 1280, height: 800 });
    await page.goto(`${env.url}?${q}`);
    await page.waitForFunction(
      () => {
        const l = document.querySelector('wing-lab');
        const b = l && l.shadowRoot && __wl.q('[data-sensemap]');
        return b && b.dataset.state === 'ready' && l.views.sensing.result;
      },
      null,
      { timeout: 120000 },
    );
    const r = await page.evaluate(() => {
      const res = document.querySelector('wing-lab').views.sensing.result;
      return { d: Array.from(res.d_best), status: __wl.q('section.wl-sensing').textContent };
    });
    assert.match(r.status, name === 'air' ? /Done, in a fluid of 1\.2 kg\/m³, in/ : /Done, in a vacuum, in/);
    assert.ok(
      r.d.every((v) => Number.isFinite(v) && v >= 0),
      name,
    );
    best[name] = r.d;
    assert.deepEqual(problems, [], name);
    await context.close();
  }
  const max = (a) => Math.max(...a);
  assert.equal(best.air.length, best.vacuum.length);
  assert.ok(Math.abs(max(best.air) / max(best.vacuum) - 1) > 0.05, `${max(best.air)} vs ${max(best.vacuum)}`);
});
