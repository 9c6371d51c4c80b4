// The lab teaches (issue 8): wing first, the beat visible and explained, a 3-D view that fits
// the stroke with a fixed colour range, publishable exports, keyboard order = visual order,
// accessible canvases and target sizes — at 1280×800 and 390×844, in real headless Chromium.
// Run after scripts/build-web.sh www. Screenshots go to test-output/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { setup, openPage, waitRenders, pngStats, pngForeground, pngHasColours, waitWing3d, OUT } from './helpers.mjs';

const SIZES = [
  { name: 'desktop', width: 1280, height: 800 },
  { name: 'phone', width: 390, height: 844 },
];

let env;
before(async () => {
  env = await setup();
});
after(async () => {
  if (env) await env.close();
});

/** The lab page on its full-page screen (every panel), unless the query picks a screen. */
async function open(viewport, query = '') {
  const o = await openPage(env.browser, env.url, viewport);
  await o.page.goto(
    env.url + (/(^|[?&])screen=/.test(query) ? query : `${query || '?'}${query ? '&' : ''}screen=full`),
  );
  await waitRenders(o.page, 1);
  return o;
}

/** Waits for the 3-D view without scrolling (it must start by itself when on screen). */
async function ready3d(page) {
  await waitWing3d(page, 90000);
  await page.waitForTimeout(150);
}

const within = (b, vp) =>
  b && b.x >= 0 && b.y >= 0 && b.x + b.width <= vp.width + 0.5 && b.y + b.height <= vp.height + 0.5;

for (const vp of SIZES) {
  test(`${vp.name} ${vp.width}×${vp.height}: the wing is in the first screen, fills ≥ 10 % of its canvas, and every pose of a flap stays inside`, async () => {
    const { page, problems, context } = await open(vp);
    await ready3d(page);
    const canvas = page.locator('wing-lab [data-wing3d] canvas.wl-w3-canvas');
    const cb = await canvas.boundingBox();
    assert.ok(within(cb, vp), `3-D canvas in the first viewport: ${JSON.stringify(cb)}`);
    // The five main sliders are in the first screen too.
    for (const key of ['alpha0', 'beta0', 'gamma0', 'flap_hz', 'zeta']) {
      const b = await page.locator(`wing-lab input[type=range][data-key="${key}"]`).boundingBox();
      assert.ok(within(b, vp), `${key} slider in the first viewport: ${JSON.stringify(b)}`);
    }
    if (vp.width >= 1000) {
      // Desktop: the responses plot with the beat is in the first screen, and the wing is the largest panel.
      const pb = await page.locator('wing-lab .wl-panel[data-panel="time"] canvas').first().boundingBox();
      assert.ok(within(pb, vp), `responses plot in the first viewport: ${JSON.stringify(pb)}`);
      assert.ok(await page.locator('wing-lab [data-beat]').isVisible());
      const areas = await page.$$eval('wing-lab .wl-panel', (ps) =>
        ps.map((p) => {
          const r = p.querySelector('canvas')?.getBoundingClientRect();
          return [p.dataset.panel, r ? r.width * r.height : 0];
        }),
      );
      const biggest = areas.sort((a, b) => b[1] - a[1])[0][0];
      assert.equal(biggest, 'wing3d', JSON.stringify(areas));
    }
    await page.screenshot({ path: path.join(OUT, `teach-${vp.name}.png`) });
    // Default view: the wing (and its frame) covers ≥ 10 % of the canvas pixels.
    const def = await pngStats(page, await canvas.screenshot({ path: path.join(OUT, `teach-${vp.name}-wing.png`) }));
    assert.ok(def.foreground >= 0.1, `foreground share ${def.foreground}`);
    // Without the axes, the body axis and the stroke plane: the wing ALONE covers ≥ 10 % of the
    // canvas at the default view, and over one flap period it never touches the edges.
    await page.evaluate(() => {
      __wl.q('section.wl-wing3d .wl-w3-options').open = true;
    });
    await page.uncheck('section.wl-wing3d input[type=checkbox][id$="-w3-axes"]');
    await page.uncheck('section.wl-wing3d input[type=checkbox][id$="-w3-body"]');
    await page.uncheck('section.wl-wing3d input[type=checkbox][id$="-w3-plane"]');
    await page.waitForTimeout(100);
    const alone = await pngForeground(
      page,
      await canvas.screenshot({ path: path.join(OUT, `teach-${vp.name}-wing-alone.png`) }),
      30,
      2,
    );
    assert.ok(alone.share >= 0.1, `the wing alone covers ${alone.share} of the canvas at the default view`);
    const shares = [];
    for (let j = 0; j < 12; j++) {
      await page.evaluate((t) => document.querySelector('wing-lab').wing3d.setTime(t), 0.5 + (j * 0.04) / 12);
      const fg = await pngForeground(page, await canvas.screenshot(), 30, 2);
      shares.push(fg.share);
      assert.ok(fg.x1 >= 0, 'the wing is drawn');
      assert.ok(
        fg.x0 > 3 && fg.y0 > 3 && fg.x1 < fg.width - 4 && fg.y1 < fg.height - 4,
        `pose ${j}: foreground box ${JSON.stringify(fg)} touches the edge`,
      );
    }
    const mean = shares.reduce((a, b) => a + b, 0) / shares.length;
    assert.ok(
      mean > 0.06 && Math.min(...shares) > 0.03,
      `the wing alone is large on screen: ${shares.map((s) => s.toFixed(3))}`,
    );
    fs.writeFileSync(
      path.join(OUT, `teach-${vp.name}-shares.json`),
      JSON.stringify({ withFrame: def.foreground, wingAloneDefault: alone.share, wingOnly: shares, mean }),
    );
    assert.deepEqual(problems, []);
    await context.close();
  });

  test(`${vp.name}: the beat period shown is the Floquet value, with its formula`, async () => {
    const { page, context } = await open(vp);
    const r = await page.evaluate(() => {
      const lab = document.querySelector('wing-lab');
      const f = lab.analysis.sim.modes[lab.modeIndex()].floquet;
      const box = __wl.q('.wl-beat');
      return {
        floquet: f.beat_period_s,
        feff: f.effective_freq_hz,
        n: f.beat_harmonic,
        fd: lab.analysis.sim.flap_freq_hz,
        shown: Number(box.querySelector('[data-beat]').dataset.beat),
        text: box.textContent,
        win: lab.plots.time.scales.x,
      };
    });
    assert.equal(r.shown, r.floquet);
    assert.ok(Math.abs(1 / Math.abs(r.feff - r.n * r.fd) - r.floquet) <= 1e-12 * r.floquet);
    assert.match(r.text, /Tbeat = 0\.09703 s/);
    assert.match(r.text, /Tbeat = 1\/\|feff − n·fd\| = 1\/\|60\.3064 − 50\| Hz = 0\.09703 s/);
    // The responses plot opens on about three beats, not the whole 2 s run.
    const span = r.win.max - r.win.min;
    assert.ok(Math.abs(span - 3 * r.floquet) < 1e-6, `window ${span} s`);
    if (vp.width < 1000) {
      // Phone: with the plot scrolled into view, the slider strip stays on screen above it.
      await page.locator('wing-lab .wl-panel[data-panel="time"] canvas').first().scrollIntoViewIfNeeded();
      await page.evaluate(() => window.scrollBy(0, -120));
      await page.waitForTimeout(100);
      const s = await page.locator('wing-lab input[type=range][data-key="gamma0"]').boundingBox();
      const p = await page.locator('wing-lab .wl-panel[data-panel="time"] canvas').first().boundingBox();
      assert.ok(within(s, vp) && s.y >= 0, `slider visible: ${JSON.stringify(s)}`);
      assert.ok(
        p.y >= s.y + s.height && p.y + p.height / 2 <= vp.height,
        `plot visible under the strip: ${JSON.stringify(p)} vs ${JSON.stringify(s)}`,
      );
      const before = Number(await page.evaluate(() => document.querySelector('wing-lab').dataset.renders));
      await page.focus('wing-lab input[type=range][data-key="gamma0"]');
      await page.keyboard.press('ArrowLeft');
      await waitRenders(page, before + 1);
      await page.screenshot({ path: path.join(OUT, 'teach-phone-scrolled.png') });
    }
    await context.close();
  });

  test(`${vp.name}: keyboard tab order follows the visual order; targets ≥ 24×24; canvases are named`, async () => {
    const { page, context } = await open(vp);
    // The 3-D view (first screen) has the FE wing computed in the worker; when it arrives the
    // mode-shape panel swaps its "Compute the FE wing's modes" button for the viewer. Wait for
    // it, or that swap can land in the middle of the Tab walk below.
    await page.waitForFunction(() => document.querySelector('wing-lab').fe, null, { timeout: 90000 });
    await page.waitForTimeout(200);
    await page.evaluate(() => window.scrollTo(0, 0));
    // Tabbable elements of the lab with their document-coordinate boxes (at scroll 0).
    const items = await page.evaluate(() => {
      const sel = 'a[href], button, input, select, textarea, summary, [tabindex]';
      const out = [];
      for (const e of __wl.qa(sel)) {
        if (e.disabled || e.tabIndex < 0) continue;
        const closed = e.closest('details:not([open])');
        if (closed && e.tagName !== 'SUMMARY') continue;
        const r = e.getBoundingClientRect();
        const cs = getComputedStyle(e);
        if (r.width === 0 || r.height === 0 || cs.visibility === 'hidden') continue;
        e.dataset.tabProbe = String(out.length);
        const panel = e.closest('.wl-panel');
        // The screen tabs (one tab stop) come before the panels.
        out.push({
          i: out.length,
          panel: panel ? panel.dataset.panel : e.closest('[role=tablist]') ? 'screens' : '',
          top: r.top + scrollY,
          left: r.left + scrollX,
          bottom: r.bottom + scrollY,
          tag: e.tagName,
          text: (e.getAttribute('aria-label') || e.textContent || '').slice(0, 30),
        });
      }
      return out;
    });
    assert.ok(items.length > 30);
    // Panel boxes at scroll 0 (the phone's slider strip is sticky: it moves once the page scrolls).
    const boxes = await page.$$eval('wing-lab .wl-panel, wing-lab [role=tablist]', (ps) =>
      Object.fromEntries(
        ps
          .filter((p) => !p.hidden)
          .map((p) => {
            const r = p.getBoundingClientRect();
            return [p.dataset.panel || 'screens', [r.top + scrollY, r.left]];
          }),
      ),
    );

    // Focus order, by pressing Tab from the page start (focus inside the lab's shadow root shows
    // on the page as the lab itself: __wl.active() follows it down).
    await page.evaluate(() => {
      const a = __wl.active();
      if (a && a.blur) a.blur();
      if (document.activeElement && document.activeElement !== document.body) document.activeElement.blur();
    });
    const order = [];
    for (let k = 0; k < items.length + 20 && order.length < items.length; k++) {
      await page.keyboard.press('Tab');
      const idx = await page.evaluate(() => {
        const a = __wl.active();
        return a && a.dataset ? a.dataset.tabProbe : undefined;
      });
      if (idx !== undefined && !order.includes(Number(idx))) order.push(Number(idx));
    }
    assert.equal(
      order.length,
      items.length,
      `every control is reachable by Tab; missing: ${JSON.stringify(items.filter((it) => !order.includes(it.i)).map((it) => [it.panel, it.tag, it.text]))}`,
    );
    const seq = order.map((i) => items[i]);
    // Panels are visited in reading order (top first, then left), each panel once.
    const panelsSeen = [];
    for (const it of seq) if (panelsSeen[panelsSeen.length - 1] !== it.panel) panelsSeen.push(it.panel);
    assert.equal(new Set(panelsSeen).size, panelsSeen.length, `each panel once: ${panelsSeen}`);
    const visual = [...panelsSeen].sort((a, b) =>
      Math.abs(boxes[a][0] - boxes[b][0]) < 8 ? boxes[a][1] - boxes[b][1] : boxes[a][0] - boxes[b][0],
    );
    assert.deepEqual(panelsSeen, visual, 'panel focus order = visual order');
    // Within a panel, focus never jumps back up to an earlier row.
    for (let j = 1; j < seq.length; j++) {
      const a = seq[j - 1],
        b = seq[j];
      if (a.panel !== b.panel) continue;
      const sameRow = b.top < a.bottom && a.top < b.bottom;
      assert.ok(
        sameRow ? b.left >= a.left - 1 : b.top >= a.top - 2,
        `${a.panel}: "${a.text}" (${a.top},${a.left}) → "${b.text}" (${b.top},${b.left})`,
      );
    }
    // WCAG 2.2 target size: buttons and selects at least 24×24 CSS px.
    const small = await page.$$eval('wing-lab button, wing-lab select', (es) =>
      es
        .filter((e) => {
          const r = e.getBoundingClientRect();
          return r.width > 0 && (r.width < 24 || r.height < 24);
        })
        .map(
          (e) =>
            `${e.tagName} ${e.textContent.slice(0, 20)} ${e.getBoundingClientRect().width}×${e.getBoundingClientRect().height}`,
        ),
    );
    assert.deepEqual(small, []);
    // Every visible canvas has an accessible name and a non-empty text alternative (or is
    // decorative): a short name plus a description (aria-describedby: the plots' data summaries),
    // or a name that is itself the whole text alternative — the mode-shape drawing's aria-label
    // says which mode, its kind, frequency, phase, exaggeration and colours, and it has no
    // aria-describedby (it is visible once the FE wing is in, waited for above).
    const canvases = await page.$$eval('wing-lab canvas', (cs) =>
      cs
        .filter((c) => c.getBoundingClientRect().width > 0)
        .map((c) => {
          if (c.getAttribute('aria-hidden') === 'true') return { ok: true };
          const name = c.getAttribute('aria-label') || '';
          const desc = (c.getAttribute('aria-describedby') || '')
            .split(/\s+/)
            .map((id) => c.getRootNode().getElementById(id)?.textContent || '')
            .join(' ');
          const described = name.length > 10 && desc.trim().length > 20;
          const selfContained = c.classList.contains('wl-ms-canvas') && name.length > 80;
          return {
            ok: c.getAttribute('role') === 'img' && (described || selfContained),
            name,
            desc: desc.slice(0, 60),
          };
        }),
    );
    assert.ok(canvases.length >= 4);
    for (const c of canvases) assert.ok(c.ok, JSON.stringify(c));
    // Axis titles are never clipped: each fits inside its plot.
    const clipped = await page.$$eval('wing-lab .wl-axis-titles span, wing-lab .wl-xtitle', (es) =>
      es
        .filter((e) => e.getBoundingClientRect().width > 0)
        .filter((e) => {
          const r = e.getBoundingClientRect(),
            p = e.closest('.wl-panel').getBoundingClientRect();
          return r.left < p.left - 0.5 || r.right > p.right + 0.5 || e.scrollWidth > e.clientWidth + 1;
        })
        .map((e) => e.textContent),
    );
    assert.deepEqual(clipped, []);
    await context.close();
  });
}

test('the strain colour range is fixed for the run while playing', async () => {
  const { page, problems, context } = await open({ width: 1280, height: 800 });
  await ready3d(page);
  const read = () =>
    page.evaluate(() => {
      const d = __wl.q('.wl-w3-legend-text').dataset;
      return [Number(d.min), Number(d.max)];
    });
  const r0 = await read();
  const ranges = await page.evaluate(() => document.querySelector('wing-lab').wing3d.ranges);
  assert.ok(Math.abs(r0[1] - ranges[3]) <= 1e-6 * ranges[3], `${r0} vs ${ranges[3]}`);
  assert.ok(Math.abs(r0[0] + r0[1]) < 1e-12);
  const seen = new Set([r0.join()]);
  const f0 = await page.evaluate(() => Number(__wl.q('[data-wing3d]').dataset.frames));
  await page.click('.wl-w3-play');
  for (let j = 0; j < 8; j++) {
    await page.waitForTimeout(120);
    seen.add((await read()).join());
  }
  await page.click('.wl-w3-play');
  assert.ok((await page.evaluate(() => Number(__wl.q('[data-wing3d]').dataset.frames))) > f0 + 5, 'frames were drawn');
  assert.equal(seen.size, 1, `range changed while playing: ${[...seen]}`);
  // The speed presets: one flap per second, one beat in 4 s.
  await page.selectOption('section.wl-wing3d select[aria-label="Playback speed"]', 'flap1');
  assert.match(await page.textContent('.wl-w3-time'), /flap 25 Hz shown at 1 Hz/);
  await page.selectOption('section.wl-wing3d select[aria-label="Playback speed"]', 'beat4');
  assert.match(await page.textContent('.wl-w3-time'), /one beat every 4 s/);
  assert.deepEqual(problems, []);
  await context.close();
});

test('FE wing: the largest deflection of the run in mm; paper set says it is not SI', async () => {
  const { page, context } = await open({ width: 1280, height: 800 });
  await ready3d(page);
  assert.match(await page.textContent('.wl-w3-defl'), /not SI/);
  await page.selectOption('wing-lab select[data-key="modes"]', 'fe');
  await page.waitForFunction(
    () => /Largest deflection over the whole run: [\d.]+ mm/.test(__wl.q('.wl-w3-defl').textContent),
    null,
    {
      timeout: 60000,
    },
  );
  await context.close();
});

test('PNG export is 2× with the legend swatches and the parameter line; SVG export too', async () => {
  const { page, problems, context } = await open({ width: 1280, height: 800 });
  const [dl] = await Promise.all([
    page.waitForEvent('download'),
    page.click('wing-lab .wl-panel[data-panel="time"] .wl-head button[data-export="png"]'),
  ]);
  const png = fs.readFileSync(await dl.path());
  fs.writeFileSync(path.join(OUT, 'export-time.png'), png);
  const info = await page.evaluate(() => document.querySelector('wing-lab').lastExport);
  assert.equal(png.readUInt32BE(16), 1800);
  assert.equal(png.readUInt32BE(20), 1120);
  assert.equal(info.width, 1800);
  const colours = info.legend;
  assert.ok(colours.length >= 5, JSON.stringify(info));
  const has = await pngHasColours(page, png, colours, [0, 0.85, 1, 1]);
  for (const [c, ok] of Object.entries(has)) assert.ok(ok, `legend swatch ${c} in the bottom of the PNG`);
  const fig = await page.evaluate(() => document.querySelector('wing-lab').exportsReg.time.figure().params);
  assert.match(fig, /α_0 = 0\.8 rad, β_0 = 0\.5 rad, γ_0 = 0\.2 rad, f_d = 25 Hz/);
  const [dl2] = await Promise.all([
    page.waitForEvent('download'),
    page.click('wing-lab .wl-panel[data-panel="spectrum"] .wl-head button[data-export="svg"]'),
  ]);
  const svg = fs.readFileSync(await dl2.path(), 'utf8');
  assert.match(svg, /<svg[^>]+width="900"/);
  assert.match(svg, /Spectra of the force terms/);
  assert.match(svg, /Stiffness force S\(t\)·q/);
  assert.match(svg, /baseline-shift="super"[^>]*>½</);
  assert.deepEqual(problems, []);
  await context.close();
});

test('touch devices get touch wording', async () => {
  const context = await env.browser.newContext({
    viewport: { width: 390, height: 844 },
    hasTouch: true,
    isMobile: true,
  });
  const page = await context.newPage();
  await page.goto(env.url);
  await waitRenders(page, 1);
  const coarse = await page.evaluate(() => matchMedia('(pointer: coarse)').matches);
  const hint = await page.textContent('wing-lab .wl-hint');
  if (coarse) {
    assert.match(hint, /tap/);
    assert.doesNotMatch(await page.textContent('wing-lab .wl-spectrum'), /Hover/);
  } else {
    assert.match(hint, /click/);
  }
  await context.close();
});

test('the sliders agree with the core’s parameter table (wasm parameters())', async () => {
  const { page, context } = await open({ width: 1280, height: 800 });
  const table = await page.evaluate(() => document.querySelector('wing-lab').engine.parameters());
  assert.ok(Array.isArray(table) && table.length > 0, 'the lab’s wasm has parameters()');
  const { NUMERIC } = await import('../../www/state.js');
  for (const p of NUMERIC) {
    const c = table.find((q) => q.key === p.key);
    assert.ok(c, `core has ${p.key}`);
    assert.equal(c.min, p.min, `${p.key} min`);
    assert.equal(c.max, p.max, `${p.key} max`);
    assert.equal(c.step, p.step, `${p.key} step`);
    assert.equal(c.default, p.def, `${p.key} default`);
  }
  await context.close();
});
