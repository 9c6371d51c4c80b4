// N modes everywhere, the mode-shape viewer and strain where you point, in real headless
// Chromium, on an FE wing with 6 modes (`?modes=fe&n_modes=6`): the numbers table, the mode
// picker and the 3-D view use all 6; the mode viewer shows each mode's frequency (equal to the
// table's); a click on the 3-D wing or on the planform map moves the strain point and changes
// the strain series; the whole-wing strain map colours the planform canvas and the 3-D wing
// (pixels checked); the new controls work from the keyboard; axe finds nothing; screenshots at
// 1280×800 and 390×844 go to test-output/.
// Run after scripts/build-web.sh www:  node --test --test-concurrency=1 tests/e2e/nmodes.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { setup, openPage, pngStats, OUT } from './helpers.mjs';

const require = createRequire(import.meta.url);
const AXE = require.resolve('axe-core/axe.min.js');
// The full-page screen: these tests use panels of several screens (table, spectra, 3-D, mode shapes, strain).
const SIX = '?modes=fe&n_modes=6&screen=full';

let env;
before(async () => {
  env = await setup();
});
after(async () => {
  if (env) await env.close();
});

/** Opens the lab with the 6-mode FE wing and waits until every view has it. */
async function openSix(viewport = { width: 1280, height: 800 }) {
  const o = await openPage(env.browser, env.url, viewport);
  await o.page.goto(`${env.url}${SIX}`);
  await o.page.waitForFunction(
    () => {
      const l = document.querySelector('wing-lab');
      const s = l && l.store && l.store.get();
      return s && s.fe && s.fe.n_modes === 6 && l.analysis && l.analysis.sim.modes.length === 6;
    },
    null,
    { timeout: 90000 },
  );
  return o;
}

/** Starts the 3-D view and waits for frames of the 6-mode wing; pauses at a fixed instant. */
async function ready3d(page) {
  await page.locator('section.wl-wing3d').scrollIntoViewIfNeeded();
  await page.waitForFunction(
    () => {
      const b = __wl.q('[data-wing3d]');
      return b && b.dataset.state === 'ready' && b.dataset.modes === '6' && Number(b.dataset.frames || 0) > 0;
    },
    null,
    { timeout: 90000 },
  );
  await page.evaluate(() => document.querySelector('wing-lab').wing3d.setTime(0.0123));
}

/** Share of warm pixels (the colour map's red end: red well above green; the plain tan is not) of a PNG. */
async function warmth(page, buf) {
  return page.evaluate(async (b64) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width;
    c.height = img.height;
    const x = c.getContext('2d');
    x.drawImage(img, 0, 0);
    const d = x.getImageData(0, 0, c.width, c.height).data;
    let warm = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] - d[i + 1] > 70 && d[i] > 150) warm++;
    return { warm: warm / (c.width * c.height) };
  }, buf.toString('base64'));
}

const strainSeries = (page) =>
  page.evaluate(() => {
    const st = document.querySelector('wing-lab').analysis.sim.strain;
    return st ? { point: st.point, ex: Array.from(st.eps_x.slice(0, 400)) } : null;
  });

test('6 modes: table, picker, spectra and 3-D view use every mode', async () => {
  const { page, problems, context } = await openSix();
  // Numbers table: one column per mode, every cell filled.
  assert.equal(await page.getAttribute('wing-lab table.wl-numtable', 'data-modes'), '6');
  const freqs = [];
  for (let k = 0; k < 6; k++) {
    const f = await page.textContent(`wing-lab [data-field="freq-${k}"]`);
    assert.ok(Number.isFinite(Number(f)) && Number(f) > 0, `mode ${k + 1} frequency: ${f}`);
    freqs.push(Number(f));
  }
  assert.ok(
    freqs.every((f, k) => k === 0 || f >= freqs[k - 1]),
    `ascending: ${freqs}`,
  );
  // Mode picker: modes 1..6 choosable; choosing 6 drives the responses and spectra.
  const picker = 'wing-lab select[id$="-mode"]';
  const enabled = await page.$$eval(`${picker} option`, (os) => os.filter((o) => !o.disabled).map((o) => o.value));
  for (const v of ['1', '2', '3', '4', '5', '6']) assert.ok(enabled.includes(v), `picker offers mode ${v}: ${enabled}`);
  await page.selectOption(picker, '6');
  await page.waitForFunction(() => document.querySelector('wing-lab').store.get().result.k === 5, null, {
    timeout: 20000,
  });
  // The panels redraw one per task after a new result (www/lab/draws.js): wait for the spectrum's.
  await page.locator('wing-lab section.wl-spectrum', { hasText: /Mode 6/ }).waitFor({ timeout: 20000 });
  assert.match(await page.textContent('wing-lab section.wl-spectrum'), /Mode 6/);
  assert.equal(await page.getAttribute('wing-lab table.wl-numtable', 'data-selected'), '6');
  // 3-D view: the deflection uses all six q_k.
  await ready3d(page);
  assert.equal(await page.getAttribute('wing-lab [data-wing3d]', 'data-modes'), '6');
  assert.match(await page.textContent('section.wl-wing3d .wl-note'), /all 6 of its modes/);
  // Another wing (3 modes): every view follows; the 3-D view is rebuilt on the new mesh.
  await page.evaluate(() => document.querySelector('wing-lab').store.set({ n_modes: 3 }));
  await page.waitForFunction(
    () => {
      const l = document.querySelector('wing-lab');
      return l.store.get().fe.n_modes === 3 && l.analysis.sim.modes.length === 3;
    },
    null,
    { timeout: 90000 },
  );
  await page.evaluate(() => document.querySelector('wing-lab').wing3d.setTime(0.03));
  await page.waitForFunction(() => __wl.q('[data-wing3d]').dataset.modes === '3', null, { timeout: 30000 });
  // Panels redraw a new result one task each (visible first), so the table may follow the 3-D view.
  await page.waitForFunction(() => __wl.q('table.wl-numtable')?.dataset.modes === '3', null, { timeout: 30000 });
  assert.equal(await page.getAttribute('wing-lab table.wl-numtable', 'data-modes'), '3');
  assert.equal(await page.locator('wing-lab section.wl-modeshape select option').count(), 3);
  assert.equal(await page.locator('wing-lab [data-wing3d] canvas.wl-w3-canvas').count(), 1);
  assert.deepEqual(problems, []);
  await context.close();
});

test('mode viewer: each mode alone with its frequency, kind and a_k; keyboard works', async () => {
  const { page, problems, context } = await openSix();
  const SEC_IN = 'section.wl-modeshape'; // inside the lab (page.evaluate: __wl.q)
  const sec = `wing-lab ${SEC_IN}`;
  await page.locator(sec).scrollIntoViewIfNeeded();
  await page.waitForFunction((s) => __wl.q(`${s} [data-modeshape]`).dataset.state === 'ready', SEC_IN);
  const fe = await page.evaluate(() => {
    const f = document.querySelector('wing-lab').store.get().fe;
    return { freq: Array.from(f.freq_hz), kinds: f.kinds };
  });
  assert.equal(await page.locator(`${sec} select option`).count(), 6);
  const shots = [];
  for (let k = 0; k < 6; k++) {
    await page.selectOption(`${sec} select`, String(k));
    const text = await page.textContent(`${sec} dl.wl-ms-info`);
    const shown = Number(/([\d.]+) Hz/.exec(await page.textContent(`${sec} dd[data-ms="natural"]`))[1]);
    assert.ok(Math.abs(shown - fe.freq[k]) / fe.freq[k] < 1e-4, `mode ${k + 1}: ${shown} vs ${fe.freq[k]}`);
    // the same frequency as the numbers table (4 significant digits there)
    const table = Number(await page.textContent(`wing-lab [data-field="freq-${k}"]`));
    assert.ok(Math.abs(table - fe.freq[k]) / fe.freq[k] < 1e-3, `table ${table} vs viewer ${fe.freq[k]}`);
    assert.ok(text.includes(fe.kinds[k]), `kind ${fe.kinds[k]} shown`);
    assert.match(text, /kg½·m/);
    shots.push(await page.locator(`${sec} canvas`).screenshot());
  }
  // each mode draws a different picture, with colours from the renderer's map
  for (let k = 1; k < 6; k++) assert.ok(!shots[k].equals(shots[k - 1]), `mode ${k + 1} differs from mode ${k}`);
  const st = await pngStats(page, shots[0]);
  assert.ok(st.colours > 30 && st.foreground > 0.1, JSON.stringify(st));
  // Keyboard only: focus the mode select, arrow down → next mode; Animate toggles with Space.
  await page.selectOption(`${sec} select`, '0');
  await page.focus(`${sec} select`);
  await page.keyboard.press('ArrowDown');
  await page.waitForFunction((s) => __wl.q(`${s} [data-modeshape]`).dataset.mode === '2', SEC_IN);
  await page.keyboard.press('Tab');
  const focused = await page.evaluate(() => __wl.active().className);
  assert.match(focused, /wl-ms-play/);
  const pressed = await page.getAttribute(`${sec} .wl-ms-play`, 'aria-pressed');
  await page.keyboard.press('Space');
  assert.notEqual(await page.getAttribute(`${sec} .wl-ms-play`, 'aria-pressed'), pressed);
  if ((await page.getAttribute(`${sec} .wl-ms-play`, 'aria-pressed')) === 'true') {
    const d0 = Number(await page.getAttribute(`${sec} [data-modeshape]`, 'data-drawn'));
    await page.waitForFunction(([s, n]) => Number(__wl.q(`${s} [data-modeshape]`).dataset.drawn) > n + 5, [SEC_IN, d0]);
  }
  assert.deepEqual(problems, []);
  await context.close();
});

test('strain where you point: 3-D click and planform map move the point; the series follows', async () => {
  const { page, problems, context } = await openSix();
  await ready3d(page);
  const before = await strainSeries(page);
  assert.ok(before, 'a strain series at the default point');
  // Click the drawn wing where the planform point (25, −15) mm is at this instant.
  const at = await page.evaluate(() => document.querySelector('wing-lab').wing3d.screenOf(25, -15));
  assert.ok(at, 'the point is on screen');
  const box = await page.locator('wing-lab [data-wing3d] canvas.wl-w3-canvas').boundingBox();
  await page.mouse.click(box.x + at[0], box.y + at[1]);
  await page.waitForFunction(() => !!document.querySelector('wing-lab').store.get().strain_point);
  const p = await page.evaluate(() => document.querySelector('wing-lab').store.get().strain_point);
  assert.ok(Math.hypot(p[0] - 25, p[1] + 15) < 1.5, `clicked near (25, −15) mm: ${p}`);
  // The engine recomputes the modal strains there: a different series.
  await page.waitForFunction(
    (ex0) => {
      const st = document.querySelector('wing-lab').analysis.sim.strain;
      return st && st.eps_x.slice(0, 400).some((v, i) => Math.abs(v - ex0[i]) > 1e-9);
    },
    before.ex,
    { timeout: 20000 },
  );
  // The ring on the 3-D wing sits where we clicked.
  const ring = await page.evaluate(() => document.querySelector('wing-lab').wing3d.pointOnScreen());
  assert.ok(ring && Math.hypot(ring[0] - at[0], ring[1] - at[1]) < 12, `ring at ${ring}, clicked ${at}`);
  // The panels redraw for a new result one task each after it arrives (www/lab/draws.js): the
  // strain panel's words follow the series.
  await page
    .waitForFunction(
      () => /strain point \(2\d(\.\d+)?, -1\d/.test(__wl.q('section.wl-strain .wl-note')?.textContent || ''),
      null,
      { timeout: 10000 },
    )
    .catch(() => {});
  assert.match(await page.textContent('wing-lab section.wl-strain .wl-note'), /strain point \(2\d(\.\d+)?, -1\d/);

  // The planform map: a click on it moves the point; arrow keys step it by 0.5 mm.
  const map = 'wing-lab canvas.wl-smap-canvas[id$="-smap"]'; // the strain panel's map (the sensing panel's map shares the class)
  await page.locator(map).scrollIntoViewIfNeeded();
  const mb = await page.locator(map).boundingBox();
  await page.mouse.click(mb.x + mb.width * 0.45, mb.y + mb.height * 0.3);
  await page.waitForFunction((p0) => {
    const q = document.querySelector('wing-lab').store.get().strain_point;
    return q && Math.hypot(q[0] - p0[0], q[1] - p0[1]) > 2;
  }, p);
  const p2 = await page.evaluate(() => document.querySelector('wing-lab').store.get().strain_point);
  await page.focus(map);
  await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('ArrowDown');
  const p3 = await page.evaluate(() => document.querySelector('wing-lab').store.get().strain_point);
  assert.ok(Math.abs(p3[0] - (p2[0] - 0.5)) < 1e-6 && Math.abs(p3[1] - (p2[1] - 0.5)) < 1e-6, `arrows: ${p2} → ${p3}`);
  assert.deepEqual(problems, []);
  await context.close();
});

test('whole-wing strain map colours the planform canvas and the 3-D wing', async () => {
  const { page, problems, context } = await openSix();
  const map = 'wing-lab canvas.wl-smap-canvas[id$="-smap"]'; // the strain panel's map (the sensing panel's map shares the class)
  await page.locator(map).scrollIntoViewIfNeeded();
  await page.waitForFunction(() => __wl.q('[data-smap]').dataset.state === 'ready');
  const a = await page.locator(map).screenshot({ path: path.join(OUT, 'nmodes-strainmap-gxy-rms.png') });
  const sa = await pngStats(page, a);
  const wa = await warmth(page, a);
  assert.ok(sa.colours > 30, `many colours: ${sa.colours}`);
  assert.ok(wa.warm > 0.005, `warm (high-strain) pixels: ${wa.warm}`);
  assert.match(await page.textContent('wing-lab .wl-smap-legend-text'), /RMS over the run of von Mises/);
  // Another component and statistic: another picture, and the store knows the choice.
  await page.selectOption('wing-lab select[id$="-smap-comp"]', 'eps_x');
  await page.selectOption('wing-lab select[id$="-smap-stat"]', 'peak');
  assert.deepEqual(await page.evaluate(() => document.querySelector('wing-lab').store.get().strain_map), {
    component: 'eps_x',
    stat: 'peak',
  });
  // a peak map is computed once the changes stop (PEAK_DELAY_MS)
  await page.waitForFunction(() => !('pending' in __wl.q('[data-smap]').dataset));
  const b = await page.locator(map).screenshot();
  assert.ok(!b.equals(a), 'the map follows the choice');
  assert.match(await page.textContent('wing-lab .wl-smap-legend-text'), /peak \|value\| over the run of ε_x/);
  // The map exports as CSV (one row per FE node, positions in mm) and PNG.
  const [dl] = await Promise.all([
    page.waitForEvent('download'),
    page.click('wing-lab [data-smap] button[data-export="csv"]'),
  ]);
  const csv = fs
    .readFileSync(await dl.path(), 'utf8')
    .trim()
    .split('\n');
  const nNodes = await page.evaluate(() => document.querySelector('wing-lab').store.get().fe.n_nodes);
  const head = csv.findIndex((l) => l.startsWith('x (mm)'));
  assert.equal(csv[head], 'x (mm),y (mm),peak_eps_x (strain (-))');
  assert.equal(csv.length - head - 1, nNodes);
  assert.ok(
    csv
      .slice(head + 1)
      .every((l) => l.split(',').length === 3 && l.split(',').every((v) => Number.isFinite(Number(v)))),
  );
  const [dl2] = await Promise.all([
    page.waitForEvent('download'),
    page.click('wing-lab [data-smap] button[data-export="png"]'),
  ]);
  assert.equal(
    fs
      .readFileSync(await dl2.path())
      .subarray(1, 4)
      .toString(),
    'PNG',
  );
  // The 3-D wing with colour 5 shows the same map.
  await ready3d(page);
  const canvas = 'wing-lab [data-wing3d] canvas.wl-w3-canvas';
  const settled = () => page.evaluate(() => document.querySelector('wing-lab').wing3d.settled());
  await page.selectOption('section.wl-wing3d select[aria-label="Colour the wing by"]', '0');
  await settled();
  const plain = await page.locator(canvas).screenshot();
  await page.selectOption('section.wl-wing3d select[aria-label="Colour the wing by"]', '5');
  await page.waitForFunction(() => /peak/.test(__wl.q('.wl-w3-legend-text').textContent));
  await settled();
  const mapped = await page.locator(canvas).screenshot({ path: path.join(OUT, 'nmodes-wing3d-strainmap.png') });
  const wp = await warmth(page, plain),
    wm = await warmth(page, mapped);
  assert.ok(wm.warm > wp.warm + 0.002, `3-D strain map adds warm pixels: ${wp.warm} → ${wm.warm}`);
  assert.deepEqual(problems, []);
  await context.close();
});

for (const viewport of [
  { width: 1280, height: 800 },
  { width: 390, height: 844 },
]) {
  test(`screenshots and axe (${viewport.width}×${viewport.height}, 6 modes, strain point moved)`, async () => {
    const { page, problems, context } = await openSix(viewport);
    await ready3d(page);
    await page.evaluate(() => document.querySelector('wing-lab').store.set({ strain_point: [20, -12] }));
    await page.waitForTimeout(500);
    for (const name of ['modeshape', 'strain', 'numbers', 'wing3d']) {
      await page
        .locator(`wing-lab section.wl-${name}`)
        .screenshot({ path: path.join(OUT, `nmodes-${name}-${viewport.width}.png`) });
    }
    await page.screenshot({ path: path.join(OUT, `nmodes-page-${viewport.width}.png`), fullPage: true });
    await page.evaluate(() => document.querySelector('wing-lab').views.modeshape.setPlaying(false));
    await page.addScriptTag({ path: AXE });
    const vs = await page.evaluate(async () => {
      // This file's panels (the whole page is tests/e2e/a11y.test.mjs's job).
      const include = ['modeshape', 'strain', 'numbers', 'wing3d'].map((n) => __wl.axe(`section.wl-${n}`));
      const r = await window.axe.run(
        { include },
        { resultTypes: ['violations'], rules: { 'target-size': { enabled: true } } },
      );
      return r.violations.map((v) => `${v.id}: ${v.help} — ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
    });
    fs.writeFileSync(path.join(OUT, `axe-nmodes-${viewport.width}.json`), JSON.stringify(vs, null, 2));
    assert.deepEqual(vs, []);
    assert.deepEqual(problems, []);
    await context.close();
  });
}
