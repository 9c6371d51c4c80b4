// The sensing panel (www/views/sensing.js: rotation sensing) end to end: it opens from a URL with the
// body rate in it; a different rate gives different numbers (D ∝ ω_b² for small rates) and a
// different picture on the map canvas; a zero rate gives a Δε that is exactly zero in the wasm
// result; the point is picked with the keyboard alone; axe finds nothing in the panel; the
// paper's mode set says why there is no map and offers the switch. Logs the browser timing of
// the map (request → drawn) at the default mesh.
// Run after scripts/build-web.sh www:  node --test --test-concurrency=1 tests/e2e/sensing.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { setup, openPage, waitRenders, waitWing3d, OUT } from './helpers.mjs';
import { experimentQuery } from '../../www/experiments.js';

const require = createRequire(import.meta.url);
const AXE = require.resolve('axe-core/axe.min.js');
const SEC = 'section.wl-sensing';

let env;
before(async () => {
  env = await setup();
});
after(async () => {
  if (env) await env.close();
});

/** The view's last wasm result, summarised (typed arrays read in the page). */
const summary = (page) =>
  page.evaluate(() => {
    const r = document.querySelector('wing-lab').views.sensing.result;
    if (!r) return null;
    const all = (a) => Array.from(a);
    return {
      body_rate: r.body_rate,
      d_best: all(r.d_best),
      dq_nonzero: r.dq.map((q) => q.filter((v) => v !== 0).length),
      delta_nonzero: ['eps_x', 'eps_y', 'gamma_xy'].map((c) => r.delta[c].filter((v) => v !== 0).length),
      delta_peak: Math.max(...['eps_x', 'eps_y', 'gamma_xy'].map((c) => Math.max(...all(r.delta[c]).map(Math.abs)))),
      n: r.t.length,
      sensors: r.sensors.length,
      pd: all(r.pd),
      point_mm: r.point_mm,
      point_source: r.point_source,
    };
  });

/** Waits for a new result after `before` drawings of the map, then returns the map's state. */
async function waitReady(page, drawnBefore = -1) {
  await page.waitForFunction(
    ([d]) => {
      const b = __wl.q('[data-sensemap]');
      const c = __wl.q('.wl-sense-canvas');
      return (
        b &&
        b.dataset.state === 'ready' &&
        c &&
        Number(c.dataset.drawn || 0) > d &&
        document.querySelector('wing-lab').views.sensing.result
      );
    },
    [drawnBefore],
    { timeout: 90000 },
  );
  return page.evaluate(() => ({
    ms: Number(__wl.q('[data-sensemap]').dataset.ms),
    worker: Number(__wl.q('[data-sensemap]').dataset.workerMs),
    drawn: Number(__wl.q('.wl-sense-canvas').dataset.drawn),
  }));
}

/** Sets the rate through the panel's number input (as a user types it). */
async function setRate(page, v) {
  const drawn = await page.evaluate(() => Number(__wl.q('.wl-sense-canvas').dataset.drawn));
  await page.evaluate((x) => {
    const i = __wl.q('.wl-sense-controls input[type=number]');
    i.value = String(x);
    i.dispatchEvent(new Event('change', { bubbles: true }));
  }, v);
  await page.waitForFunction(
    (x) =>
      document.querySelector('wing-lab').views.sensing.result?.body_rate.some((w) => w === x) ||
      (x === 0 && document.querySelector('wing-lab').views.sensing.result?.body_rate.every((w) => w === 0)),
    v,
    { timeout: 90000 },
  );
  return waitReady(page, drawn);
}

const mapShot = (page) => page.locator(`wing-lab ${SEC} .wl-sense-canvas`).screenshot();

test('the panel opens from a URL; the rate changes the numbers and the map; zero rate gives Δε = 0 exactly', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  await page.goto(`${env.url}?panels=controls,sensing&modes=fe&body_rate=0.05&body_axis=x`);
  await waitRenders(page, 1);
  const t = await waitReady(page);
  const st = await page.evaluate(() => {
    const s = document.querySelector('wing-lab').store.get();
    return { r: s.body_rate, a: s.body_axis };
  });
  assert.deepEqual(st, { r: 0.05, a: 'x' });
  assert.equal(await page.evaluate(() => __wl.q('.wl-sense-controls select').value), 'x');
  const a = await summary(page);
  assert.deepEqual(a.body_rate, [0.05, 0, 0]);
  assert.equal(a.sensors, 30);
  assert.equal(a.pd.length, 30);
  assert.ok(a.n > 10000, `samples ${a.n}`);
  assert.ok(a.delta_peak > 0 && a.d_best.some((v) => v > 0), `peak ${a.delta_peak}`);
  assert.equal(a.point_source, 'best_sensor');
  // the K = 5 best sensors are all on the map (nearby ones share a label)
  const groups = await page.evaluate(() => JSON.parse(__wl.q('.wl-sense-canvas').dataset.markers));
  assert.deepEqual(
    groups.flat().sort((p, q) => p - q),
    [1, 2, 3, 4, 5],
  );
  // the absolute colour scale: the same D, the same colour on every map
  await page.evaluate(() => {
    const s = __wl.q('.wl-sense-controls select[id$="sense-scale"]');
    s.value = 'absolute';
    s.dispatchEvent(new Event('change', { bubbles: true }));
  });
  // timing (logged, not asserted: a benchmark, not a test): five more analyses at other rates
  const times = [t];
  for (const r of [0.06, 0.07, 0.08, 0.09, 0.1]) times.push(await setRate(page, r));
  const medOf = (k) => times.map((x) => x[k]).sort((p, q) => p - q)[times.length >> 1];
  console.log(
    `# sensing map in the browser (median of ${times.length}): ${medOf('ms')} ms from request to drawn map, ${medOf('worker')} ms of wasm in the worker; default FE wing, ${a.d_best.length} nodes, ${a.n} samples; all: ${times.map((x) => `${x.ms}/${x.worker}`).join(' ')} ms`,
  );
  fs.mkdirSync(OUT, { recursive: true });
  fs.writeFileSync(
    path.join(OUT, 'sensing-timing.json'),
    JSON.stringify({
      times,
      median_ms: medOf('ms'),
      median_worker_ms: medOf('worker'),
      nodes: a.d_best.length,
      samples: a.n,
    }),
  );
  await setRate(page, 0.05);
  const shotA = await mapShot(page);

  // a rate 4× larger: every D about 16× (Δε linear in ω_b to first order), and a brighter map
  await setRate(page, 0.2);
  const b = await summary(page);
  assert.deepEqual(b.body_rate, [0.2, 0, 0]);
  const ratios = b.d_best
    .map((v, i) => v / a.d_best[i])
    .filter(Number.isFinite)
    .sort((x, y) => x - y);
  const med = ratios[ratios.length >> 1];
  assert.ok(Math.abs(med - 16) < 0.8, `median D ratio ${med}`);
  const shotB = await mapShot(page);
  assert.notDeepEqual(shotA, shotB, 'the map canvas changed');
  const moved = await page.evaluate(
    async ([x, y]) => {
      const px = async (b64) => {
        const img = new Image();
        img.src = `data:image/png;base64,${b64}`;
        await img.decode();
        const c = document.createElement('canvas');
        c.width = img.width;
        c.height = img.height;
        const g = c.getContext('2d');
        g.drawImage(img, 0, 0);
        return g.getImageData(0, 0, c.width, c.height).data;
      };
      const p = await px(x),
        q = await px(y);
      let n = 0;
      for (let i = 0; i < Math.min(p.length, q.length); i += 4)
        if (Math.abs(p[i] - q[i]) + Math.abs(p[i + 1] - q[i + 1]) + Math.abs(p[i + 2] - q[i + 2]) > 30) n++;
      return n / (p.length / 4);
    },
    [shotA.toString('base64'), shotB.toString('base64')],
  );
  assert.ok(moved > 0.2, `share of map pixels that changed colour: ${moved}`);

  // the URL carries the rate (sync-url is on for the lab page)
  await page.waitForFunction(
    () => /body_rate=0\.2(&|$)/.test(location.search) && /body_axis=x/.test(location.search),
    null,
    {
      timeout: 5000,
    },
  );

  // the relative scale (default) shows the pattern: another axis, another picture
  await page.evaluate(() => {
    const s = __wl.q('.wl-sense-controls select[id$="sense-scale"]');
    s.value = 'relative';
    s.dispatchEvent(new Event('change', { bubbles: true }));
  });
  const shotX = await mapShot(page);
  await page.evaluate(() => {
    const s = __wl.q('.wl-sense-controls select[id$="sense-axis"]');
    s.value = 'y';
    s.dispatchEvent(new Event('change', { bubbles: true }));
  });
  await page.waitForFunction(
    () => document.querySelector('wing-lab').views.sensing.result?.body_rate[1] === 0.2,
    null,
    { timeout: 90000 },
  );
  await waitReady(page, (await page.evaluate(() => Number(__wl.q('.wl-sense-canvas').dataset.drawn))) - 1);
  assert.notDeepEqual(await mapShot(page), shotX, 'pitch and roll give different maps');

  // zero rate: Δq and Δε exactly 0 in the wasm result, D = 0 everywhere
  await setRate(page, 0);
  const z = await summary(page);
  assert.deepEqual(z.body_rate, [0, 0, 0]);
  assert.ok(
    z.dq_nonzero.every((n) => n === 0),
    `dq non-zero samples ${JSON.stringify(z.dq_nonzero)}`,
  );
  assert.deepEqual(z.delta_nonzero, [0, 0, 0]);
  assert.equal(z.delta_peak, 0);
  assert.ok(
    z.d_best.every((v) => v === 0),
    'D = 0 at every node',
  );
  assert.match(
    await page.evaluate(() => __wl.q('.wl-sense-canvas').closest('[data-sensemap]').textContent),
    /D = 0 everywhere/,
  );
  assert.deepEqual(problems, []);
  await context.close();
});

test('keyboard only: Tab to the map, arrow keys move the point, Δε follows', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  await page.goto(`${env.url}?panels=sensing&modes=fe&body_rate=1`);
  await waitRenders(page, 1);
  await waitReady(page);
  const p0 = await page.evaluate(() => __wl.q('.wl-sense-canvas').dataset.point);
  // from the K slider, Tab reaches the export buttons and then the map
  await page.evaluate(() => __wl.q('.wl-sense-controls input[type=range][id$="sense-k"]').focus());
  for (let i = 0; i < 6; i++) {
    if (await page.evaluate(() => __wl.active()?.classList.contains('wl-sense-canvas'))) break;
    await page.keyboard.press('Tab');
  }
  assert.equal(
    await page.evaluate(() => __wl.active()?.classList.contains('wl-sense-canvas')),
    true,
    'the map is reachable with Tab',
  );
  const peak0 = await page.evaluate(() => Number(__wl.q('[data-sensemap]').dataset.deltaPeak));
  for (let i = 0; i < 8; i++) await page.keyboard.press('ArrowRight');
  await page.keyboard.press('Shift+ArrowRight');
  const p1 = await page.evaluate(() => __wl.q('.wl-sense-canvas').dataset.point);
  assert.notEqual(p1, p0);
  const [x0] = p0.split(',').map(Number),
    [x1] = p1.split(',').map(Number);
  assert.ok(Math.abs(x1 - x0 - 6) < 1e-9, `${p0} → ${p1}`);
  // the job for the picked point comes back with its series and spectrum
  await page.waitForFunction(
    (p) => {
      const r = document.querySelector('wing-lab').views.sensing.result;
      return r && r.point_source === 'opts' && `${r.point_mm[0]},${r.point_mm[1]}` === p;
    },
    p1,
    { timeout: 60000 },
  );
  const peak1 = await page.evaluate(() => Number(__wl.q('[data-sensemap]').dataset.deltaPeak));
  assert.ok(peak1 > 0 && peak1 !== peak0, `${peak0} → ${peak1}`);
  assert.match(await page.evaluate(() => __wl.q('section.wl-sensing .wl-smap-point').textContent), /picked point/);
  assert.deepEqual(problems, []);
  await context.close();
});

/** Share of pixels whose colour differs by more than 30 (summed RGB) between two PNGs of one size. */
const pixelChange = (page, x, y) =>
  page.evaluate(
    async ([a, b]) => {
      const px = async (b64) => {
        const img = new Image();
        img.src = `data:image/png;base64,${b64}`;
        await img.decode();
        const c = document.createElement('canvas');
        c.width = img.width;
        c.height = img.height;
        const g = c.getContext('2d');
        g.drawImage(img, 0, 0);
        return g.getImageData(0, 0, c.width, c.height).data;
      };
      const p = await px(a),
        q = await px(b);
      let n = 0;
      for (let i = 0; i < Math.min(p.length, q.length); i += 4)
        if (Math.abs(p[i] - q[i]) + Math.abs(p[i + 1] - q[i + 1]) + Math.abs(p[i + 2] - q[i + 2]) > 30) n++;
      return n / (p.length / 4);
    },
    [x.toString('base64'), y.toString('base64')],
  );

test('the 3-D wing coloured by detectability, with the K best sensors as numbered markers', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  await page.goto(`${env.url}?panels=controls,wing3d,sensing&modes=fe&body_rate=0.05&body_axis=x`);
  await waitRenders(page, 1);
  const w3 = 'section.wl-wing3d';
  await page.locator(`wing-lab ${w3}`).scrollIntoViewIfNeeded();
  await waitWing3d(page, 90000);
  const colourSel = 'select[id$="w3-colour"]';
  const setColour = (v) =>
    page.evaluate(
      ([sel, x]) => {
        const s = __wl.q(sel);
        s.value = x;
        s.dispatchEvent(new Event('change', { bubbles: true }));
      },
      [colourSel, v],
    );
  // before any sensing result: the option says what to do, and no markers are drawn. The
  // sensing result may arrive at any moment, so the store, the legend and the markers are read
  // together, and the words are checked only if there was still no result then.
  if (!(await page.evaluate(() => document.querySelector('wing-lab').store.get().sense_map))) {
    await setColour('6');
    // A view in the render worker answers with the frame's legend: the words follow it.
    await page.evaluate(() => document.querySelector('wing-lab').wing3d.settled());
    const seen = await page.evaluate(
      (sel) => ({
        map: !!document.querySelector('wing-lab').store.get().sense_map,
        text: __wl.q(`${sel} .wl-w3-legend-text`)?.textContent ?? '',
        dots: __wl.qa('.wl-w3-sdot:not([hidden])').length,
      }),
      w3,
    );
    if (!seen.map) {
      assert.match(seen.text, /open the Sensing panel/);
      assert.equal(seen.dots, 0);
    }
  }
  // the strain colouring (whole-run strain map) at a fixed instant, for comparison
  await page.evaluate(() => document.querySelector('wing-lab').wing3d.setTime(0.3));
  await setColour('5');
  // After the view has settled: a new wing (the FE result arriving late on a busy machine) is
  // drawn on a new canvas that replaces the old one.
  const shot = async () => {
    await page.evaluate(() => document.querySelector('wing-lab').wing3d.settled());
    return page.locator(`wing-lab ${w3} canvas.wl-w3-canvas`).screenshot();
  };
  const strainShot = await shot();

  // the sensing panel computes when on screen; its button shows the map on the 3-D wing
  await page.locator(`wing-lab ${SEC}`).scrollIntoViewIfNeeded();
  await waitReady(page);
  const K = await page.evaluate(() => Number(__wl.q('.wl-sense-controls input[type=range][id$="sense-k"]').value));
  assert.equal(K, 5);
  await page.locator(`wing-lab ${SEC} button[data-show3d]`).click();
  assert.equal(await page.evaluate((sel) => __wl.q(sel).value, colourSel), '6');
  await page.waitForFunction((k) => Number(__wl.q('.wl-w3-sensors')?.dataset.sensors) === k, K, { timeout: 30000 });
  await page.waitForTimeout(300);
  const senseShot = await shot();
  const changed = await pixelChange(page, strainShot, senseShot);
  assert.ok(
    changed > 0.03,
    `share of 3-D canvas pixels that changed colour from the strain map to detectability: ${changed}`,
  );
  // the legend names the map, its scale and the markers (the words follow the drawn frame)
  await page.evaluate(() => document.querySelector('wing-lab').wing3d.settled());
  const legendText = await page.textContent(`wing-lab ${w3} .wl-w3-legend-text`);
  assert.match(legendText, /Rotation detectability D/);
  assert.match(legendText, /0\.05 rad\/s about body axis x/);
  assert.match(legendText, /5 best sensors/);
  // K dots, each inside the canvas, and tags that together carry the ranks 1 … K
  const marks = await page.evaluate(() => {
    const c = __wl.q('section.wl-wing3d canvas.wl-w3-canvas').getBoundingClientRect();
    const dots = __wl.qa('.wl-w3-sdot:not([hidden])').map((d) => {
      const b = d.getBoundingClientRect();
      return { rank: Number(d.dataset.rank), x: b.left + b.width / 2 - c.left, y: b.top + b.height / 2 - c.top };
    });
    const tags = __wl.qa('.wl-w3-stag:not([hidden])').map((t) => t.dataset.ranks);
    return { w: c.width, h: c.height, dots, tags };
  });
  assert.equal(marks.dots.length, K);
  assert.deepEqual(
    marks.dots.map((d) => d.rank).sort((a, b) => a - b),
    [1, 2, 3, 4, 5],
  );
  for (const d of marks.dots)
    assert.ok(
      d.x >= 0 && d.x <= marks.w && d.y >= 0 && d.y <= marks.h,
      `sensor ${d.rank} at (${d.x}, ${d.y}) inside ${marks.w}×${marks.h}`,
    );
  assert.deepEqual(
    marks.tags
      .join(',')
      .split(',')
      .map(Number)
      .sort((a, b) => a - b),
    [1, 2, 3, 4, 5],
  );
  // each dot sits on its sensor node as drawn now (the deflected wing at this instant)
  const onNode = await page.evaluate(() => {
    const lab = document.querySelector('wing-lab');
    const m = lab.store.get().sense_map;
    return m.sensors.map((sn) => lab.wing3d.screenOf(sn.x_mm, sn.y_mm));
  });
  for (const [j, p] of onNode.entries()) {
    const d = marks.dots.find((x) => x.rank === j + 1);
    assert.ok(
      p && Math.hypot(p[0] - d.x, p[1] - d.y) < 2.5,
      `sensor ${j + 1}: dot (${d.x}, ${d.y}) vs the wing point ${JSON.stringify(p)}`,
    );
  }
  // a larger K on the panel gives more markers on the 3-D wing
  await page.evaluate(() => {
    const k = __wl.q('.wl-sense-controls input[type=range][id$="sense-k"]');
    k.value = '8';
    k.dispatchEvent(new Event('input', { bubbles: true }));
  });
  await page.waitForFunction(() => __wl.qa('.wl-w3-sdot:not([hidden])').length === 8, null, { timeout: 10000 });
  await page.screenshot({ path: path.join(OUT, 'sensing-wing3d-1280.png') });
  // new kinematics while the sensing panel is off screen (it computes only when seen): the 3-D
  // legend says the map is for earlier settings
  await page.evaluate(() => window.scrollTo(0, 0));
  assert.equal(
    await page.evaluate(() => {
      const b = __wl.q('section.wl-sensing').getBoundingClientRect();
      return b.top < innerHeight && b.bottom > 0;
    }),
    false,
    'sensing panel off screen',
  );
  const cfg0 = await page.evaluate(() => JSON.stringify(document.querySelector('wing-lab').store.get().result.cfg));
  await page.evaluate(() => document.querySelector('wing-lab').store.set({ alpha0: 0.7 }));
  await page.waitForFunction(
    (c) => JSON.stringify(document.querySelector('wing-lab').store.get().result.cfg) !== c,
    cfg0,
    {
      timeout: 60000,
    },
  );
  await page.waitForFunction(
    () => /for earlier settings/.test(__wl.q('section.wl-wing3d .wl-w3-legend-text').textContent),
    null,
    {
      timeout: 30000,
    },
  );
  assert.deepEqual(problems, []);
  await context.close();
});

test('the paper mode set says why there is no map and switches to the FE wing', async () => {
  const { page, context } = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  await page.goto(`${env.url}?panels=controls,sensing`);
  await waitRenders(page, 1);
  const txt = await page.evaluate(() => __wl.q('.wl-sense-needfe').textContent);
  assert.match(txt, /only the FE wing has/);
  // the guided experiment link is shareable (exp=sensing, modes=fe)
  const href = await page.evaluate(() => __wl.q('section.wl-sensing a.wl-sense-exp').href);
  assert.match(href, /exp=sensing/);
  assert.match(href, /modes=fe/);
  await page.locator(`wing-lab ${SEC} .wl-sense-needfe button`).click();
  await waitReady(page);
  assert.equal(await page.evaluate(() => document.querySelector('wing-lab').store.get().modes), 'fe');
  await context.close();
});

for (const viewport of [
  { width: 1280, height: 800 },
  { width: 390, height: 844 },
]) {
  test(`axe: the sensing panel has no violations (${viewport.width}×${viewport.height}); screenshot`, async () => {
    const { page, problems, context } = await openPage(env.browser, env.url, viewport);
    await page.goto(`${env.url}?${experimentQuery('sensing', { panels: 'controls,experiments,sensing' })}`);
    await waitRenders(page, 1);
    // the panel computes only when it is on screen
    await page.locator(`wing-lab ${SEC}`).scrollIntoViewIfNeeded();
    await waitReady(page);
    await page.evaluate(() => {
      for (const d of __wl.qa('.wl-sense-details')) d.open = true;
    });
    await page.addScriptTag({ path: AXE });
    const vs = await page.evaluate(async () => {
      const r = await window.axe.run(
        { include: [__wl.axe('section.wl-sensing')] },
        { resultTypes: ['violations'], rules: { 'target-size': { enabled: true } } },
      );
      return r.violations.map((v) => `${v.id}: ${v.help} — ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
    });
    assert.deepEqual(vs, []);
    await page.locator(`wing-lab ${SEC}`).scrollIntoViewIfNeeded();
    await page.screenshot({ path: path.join(OUT, `sensing-${viewport.width}.png`) });
    assert.deepEqual(problems, []);
    await context.close();
  });
}
