// <wing-lab> on a course page from another origin (issue 11, "an element that keeps to itself").
// Two loopback origins: B serves www/ with CORS (startServer(..., { cors: true })), A serves small
// course pages written by this test into a temp folder; each loads
// <script type="module" src="http://127.0.0.1:<B>/lab.js">. Checked in headless Chromium:
// the element defines and computes, the FE wing (worker, from a same-origin Blob) and the 3-D
// view work, every lab file comes from B, the host page's body font, margin, background and
// layout are unchanged, the layout follows the element's own width and the panels shown
// (one column in a 600 px column, `embed` from the first paint and when added later), two labs
// on a page pass axe-core, the lab runs under the strict Content-Security-Policy the docs give,
// and screenshots of a course page at 1280×800 and 390×844.
// Run after scripts/build-web.sh www:  node --test --test-concurrency=1 tests/e2e/element.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { createRequire } from 'node:module';
import { setup, openPage, pngStats, OUT, ROOT } from './helpers.mjs';
import { startServer } from '../../scripts/serve.mjs';

const require = createRequire(import.meta.url);
const AXE = require.resolve('axe-core/axe.min.js');

let env, lab, course, dir;
before(async () => {
  env = await setup();
  lab = await startServer(path.join(ROOT, 'www'), 0, { cors: true });
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'wl-course-'));
  course = await startServer(dir, 0);
  assert.notEqual(new URL(lab.url).origin, new URL(course.url).origin);
});
after(async () => {
  if (env) await env.close();
  if (lab) lab.server.close();
  if (course) course.server.close();
  if (dir) fs.rmSync(dir, { recursive: true, force: true });
});

const TEXT = `<p>A hawkmoth wing is thin and flexible. As it flaps, rotation pushes on it in three ways, and
  the wing answers at its own natural frequency: the response swells and fades, a beat.</p>`;

/**
 * Writes a course page into the temp folder and returns its URL on origin A: a serif body with
 * a margin and a background of its own, a centred column of `width` px, text, and `labs`
 * (HTML of <wing-lab> elements) loaded from origin B (none and no script: the same page without the lab).
 */
function coursePage(name, { labs = [], width = 720, extraHead = '', externalCss = false } = {}) {
  const css = `
  body { font-family: Georgia, "Times New Roman", serif; margin: 24px 12px; background: rgb(250, 246, 238); color: #222; line-height: 1.5; font-size: 18px; }
  .col { max-width: ${width}px; margin: 0 auto; }
  h1 { font-size: 28px; }
`;
  if (externalCss) fs.writeFileSync(path.join(dir, `${name}.css`), css);
  const html = `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>Course page: ${name}</title>
${externalCss ? `<link rel="stylesheet" href="${name}.css">` : `<style>${css}</style>`}
${labs.length ? `<script type="module" src="${lab.url}lab.js"></script>` : ''}
${extraHead}
</head><body>
<main class="col" aria-label="Course">
  <h1>Week 5: the wing as a spring</h1>
  ${TEXT}
  ${labs.map((l) => `<div class="slot">${l}</div>`).join('\n  ')}
  <p id="after">Questions: why does the beat period shrink when the flap frequency moves away from half the natural frequency?</p>
</main>
</body></html>`;
  fs.writeFileSync(path.join(dir, `${name}.html`), html);
  return `${course.url}${name}.html`;
}

/** Waits until the element `sel` is defined, has a shadow root and has rendered `n` times. */
async function waitLab(page, sel = 'wing-lab', n = 1, timeout = 30000) {
  await page.waitForFunction(
    ([s, k]) => {
      const l = document.querySelector(s);
      return customElements.get('wing-lab') && l && l.shadowRoot && Number(l.dataset.renders || 0) >= k;
    },
    [sel, n],
    { timeout },
  );
}

/** The host page's own look: body styles and the boxes of its text. */
function hostLook(page) {
  return page.evaluate(() => {
    const b = getComputedStyle(document.body);
    const box = (e) => {
      const r = e.getBoundingClientRect();
      return [r.x, r.width, r.height].map((v) => Math.round(v * 10) / 10);
    };
    return {
      body: {
        fontFamily: b.fontFamily,
        fontSize: b.fontSize,
        margin: b.margin,
        backgroundColor: b.backgroundColor,
        color: b.color,
        lineHeight: b.lineHeight,
      },
      html: getComputedStyle(document.documentElement).backgroundColor,
      h1: [getComputedStyle(document.querySelector('h1')).fontFamily, ...box(document.querySelector('h1'))],
      p: [getComputedStyle(document.querySelector('p')).fontFamily, ...box(document.querySelector('p'))],
      after: getComputedStyle(document.querySelector('#after')).fontFamily,
      sheets: document.styleSheets.length,
    };
  });
}

/** Boxes of the visible panels of a lab (inside its shadow root). */
function panelBoxes(page, sel = 'wing-lab') {
  return page.evaluate((s) => {
    const l = document.querySelector(s);
    const grid = l.shadowRoot.querySelector('.wl-grid').getBoundingClientRect();
    const panels = [...l.shadowRoot.querySelectorAll('.wl-panel')]
      .filter((p) => !p.hidden)
      .map((p) => {
        const r = p.getBoundingClientRect();
        return {
          name: p.dataset.panel,
          x: Math.round(r.x),
          y: Math.round(r.y),
          w: Math.round(r.width),
          h: Math.round(r.height),
        };
      });
    return { layout: l.dataset.layout, grid: { x: Math.round(grid.x), w: Math.round(grid.width) }, panels };
  }, sel);
}

test("cross-origin: the element defines, computes, runs the FE wing in its worker and draws the 3-D wing; every lab file comes from the lab's origin; the host page is untouched", async () => {
  const plainUrl = coursePage('plain', { width: 1100 });
  const url = coursePage('fe', { labs: ['<wing-lab id="lab" modes="fe" gamma0="0.2"></wing-lab>'], width: 1100 });
  const { page, problems, context } = await openPage(env.browser, plainUrl, { width: 1280, height: 800 });
  await page.goto(plainUrl);
  const before = await hostLook(page);

  /** @type {string[]} */
  const requests = [];
  page.on('request', (r) => requests.push(r.url()));
  await page.addInitScript(() => {
    /** @type {any} */ (window).__events = { ready: 0, rendered: 0 };
    document.addEventListener('wl-ready', () => {
      /** @type {any} */ (window).__events.ready++;
    });
    document.addEventListener('wl-rendered', () => {
      /** @type {any} */ (window).__events.rendered++;
    });
  });
  await page.goto(url);
  await waitLab(page);
  const host = await page.evaluate(() => {
    const l = /** @type {any} */ (document.querySelector('wing-lab'));
    return {
      mode: l.shadowRoot.mode,
      display: getComputedStyle(l).display,
      lightChildren: l.children.length,
      events: /** @type {any} */ (window).__events,
      layout: l.dataset.layout,
    };
  });
  assert.equal(host.mode, 'open');
  assert.equal(host.display, 'block');
  assert.equal(host.lightChildren, 0, 'nothing is added to the light DOM');
  assert.ok(
    host.events.ready >= 1 && host.events.rendered >= 1,
    `events reach the document: ${JSON.stringify(host.events)}`,
  );

  // The FE wing: solved in the element's worker (a same-origin Blob importing B's worker.js).
  await page.waitForFunction(
    () => {
      const l = /** @type {any} */ (document.querySelector('wing-lab'));
      return (
        l.fe &&
        l.analysis &&
        l.analysis.sim.modes.length === l.fe.modes.length &&
        l.shadowRoot.querySelector('[data-field="freq-0"]')
      );
    },
    null,
    { timeout: 90000 },
  );
  const f1 = Number(
    await page.evaluate(
      () => document.querySelector('wing-lab').shadowRoot.querySelector('[data-field="freq-0"]').textContent,
    ),
  );
  assert.ok(Math.abs(f1 - 62.49) < 0.02, `FE f1 = ${f1}`);

  // The 3-D view draws the wing.
  await page.locator('wing-lab section.wl-wing3d').scrollIntoViewIfNeeded();
  await page.waitForFunction(
    () => {
      const b = document.querySelector('wing-lab').shadowRoot.getElementById('wing3d');
      return (
        b && (b.dataset.state === 'unavailable' || (b.dataset.state === 'ready' && Number(b.dataset.frames || 0) > 0))
      );
    },
    null,
    { timeout: 90000 },
  );
  assert.equal(
    await page.evaluate(() => document.querySelector('wing-lab').shadowRoot.getElementById('wing3d').dataset.state),
    'ready',
  );
  await page.evaluate(() => /** @type {any} */ (document.querySelector('wing-lab')).wing3d.setTime(0.5));
  await page.evaluate(() => /** @type {any} */ (document.querySelector('wing-lab')).wing3d.settled());
  const shot = await page
    .locator('wing-lab canvas.wl-w3-canvas')
    .screenshot({ path: path.join(OUT, 'element-wing3d.png') });
  const st = await pngStats(page, shot);
  assert.ok(st.foreground > 0.03 && st.colours > 40, `3-D canvas drawn: ${JSON.stringify(st)}`);

  // Keyboard inside the shadow root: a slider moves, the lab recomputes, the number box follows.
  const n0 = await page.evaluate(() => Number(document.querySelector('wing-lab').dataset.renders));
  await page.focus('wing-lab input[type=range][data-key="gamma0"]');
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction((k) => Number(document.querySelector('wing-lab').dataset.renders) > k, n0, {
    timeout: 20000,
  });
  const g = await page.evaluate(() => {
    const l = /** @type {any} */ (document.querySelector('wing-lab'));
    return {
      state: l.state.gamma0,
      box: Number(l.shadowRoot.querySelector('input[type=number][data-key="gamma0"]')?.value ?? NaN),
    };
  });
  assert.ok(Math.abs(g.state - 0.205) < 1e-9, `γ0 after ArrowRight: ${g.state}`);
  assert.ok(Number.isNaN(g.box) || Math.abs(g.box - g.state) < 1e-9, `number box follows: ${g.box}`);

  // Every file of the lab came from origin B; the worker started from a blob: URL of origin A.
  const B = new URL(lab.url).origin;
  for (const f of [
    'lab.js',
    'engine.js',
    'worker.js',
    'style.css',
    'vendor/uPlot.min.css',
    'pkg/wingbeat.js',
    'pkg/wingbeat_bg.wasm',
  ]) {
    assert.ok(
      requests.some((u) => u === `${B}/${f}`),
      `${f} from ${B}: ${requests.filter((u) => u.includes(f.split('/').pop())).join(', ')}`,
    );
  }
  assert.ok(
    !requests.some((u) => u.startsWith(new URL(course.url).origin) && /\.(js|css|wasm)$/.test(u)),
    'no lab file requested from the course origin',
  );

  // The host page: body font, margin, background, the text's font and boxes, unchanged.
  const withLab = await hostLook(page);
  assert.deepEqual(withLab.body, before.body);
  assert.equal(withLab.html, before.html);
  assert.deepEqual(withLab.h1, before.h1);
  assert.deepEqual(withLab.p, before.p);
  assert.equal(withLab.after, before.after);
  assert.equal(withLab.sheets, before.sheets, 'no stylesheet added to the document');
  // …and the lab keeps its own font inside.
  const inner = await page.evaluate(
    () => getComputedStyle(document.querySelector('wing-lab').shadowRoot.querySelector('.wl-panel')).fontFamily,
  );
  assert.match(inner, /system-ui/);
  assert.deepEqual(problems, []);
  await context.close();
});

test("layout follows the element's own width and the panels shown; embed is compact from the first paint and when added later", async () => {
  const { page, problems, context } = await openPage(env.browser, coursePage('blank'), { width: 1280, height: 800 });

  // A 600 px course column: one column (narrow), every visible panel at the same left x.
  await page.goto(
    coursePage('col600', { labs: ['<wing-lab panels="controls,time,spectrum,numbers"></wing-lab>'], width: 600 }),
  );
  await waitLab(page);
  let b = await panelBoxes(page);
  assert.equal(b.layout, 'narrow');
  assert.equal(new Set(b.panels.map((p) => p.x)).size, 1, JSON.stringify(b));
  for (const p of b.panels)
    assert.ok(Math.abs(p.w - b.grid.w) <= 1, `${p.name} spans the column: ${JSON.stringify(b)}`);

  // 900 px with controls, numbers, spectrum: the sliders beside the spectrum and the numbers, no empty cell.
  await page.goto(
    coursePage('col900', { labs: ['<wing-lab panels="controls,numbers,spectrum"></wing-lab>'], width: 900 }),
  );
  await waitLab(page);
  b = await panelBoxes(page);
  assert.equal(b.layout, 'medium');
  const P = Object.fromEntries(b.panels.map((p) => [p.name, p]));
  assert.ok(P.controls.x < P.spectrum.x && P.spectrum.x === P.numbers.x, JSON.stringify(b));
  assert.ok(P.numbers.y > P.spectrum.y, 'numbers under the spectrum');
  assert.ok(Math.abs(P.spectrum.x + P.spectrum.w - (b.grid.x + b.grid.w)) <= 1, 'the spectrum reaches the right edge');
  assert.ok(P.controls.w >= 240 && P.controls.w <= 260, `sliders column ${P.controls.w}`);
  await page.screenshot({ path: path.join(OUT, 'element-col900.png'), fullPage: true });

  // `embed` added later: one column; removed: back to the width's layout.
  await page.evaluate(() => document.querySelector('wing-lab').setAttribute('embed', ''));
  await page.waitForFunction(() => document.querySelector('wing-lab').dataset.layout === 'narrow');
  b = await panelBoxes(page);
  assert.equal(new Set(b.panels.map((p) => p.x)).size, 1, JSON.stringify(b));
  await page.evaluate(() => document.querySelector('wing-lab').removeAttribute('embed'));
  await page.waitForFunction(() => document.querySelector('wing-lab').dataset.layout === 'medium');
  // A parameter attribute changed later applies too.
  await page.evaluate(() => document.querySelector('wing-lab').setAttribute('gamma0', '0.1'));
  await page.waitForFunction(() => /** @type {any} */ (document.querySelector('wing-lab')).state.gamma0 === 0.1);
  // panels changed later: the grid follows (one panel: full width).
  await page.evaluate(() => document.querySelector('wing-lab').setAttribute('panels', 'spectrum'));
  await page.waitForFunction(() => document.querySelector('wing-lab').shadowRoot.querySelector('.wl-controls').hidden);
  b = await panelBoxes(page);
  assert.deepEqual(
    b.panels.map((p) => p.name),
    ['spectrum'],
  );
  assert.ok(Math.abs(b.panels[0].w - b.grid.w) <= 1);

  // `embed` present before the element upgrades: narrow from its first layout on a wide page.
  const seen = coursePage('embedfirst', {
    labs: ['<wing-lab embed panels="controls,numbers,spectrum"></wing-lab>'],
    width: 1200,
    extraHead: `<script>
      window.__layouts = [];
      new MutationObserver(() => { const l = document.querySelector('wing-lab'); if (l && l.dataset.layout && window.__layouts.at(-1) !== l.dataset.layout) window.__layouts.push(l.dataset.layout); })
        .observe(document.documentElement, { subtree: true, attributes: true, attributeFilter: ['data-layout'] });
    </script>`,
  });
  await page.goto(seen);
  await waitLab(page);
  assert.deepEqual(await page.evaluate(() => /** @type {any} */ (window).__layouts), ['narrow']);
  b = await panelBoxes(page);
  assert.equal(new Set(b.panels.map((p) => p.x)).size, 1, JSON.stringify(b));
  assert.deepEqual(problems, []);
  await context.close();
});

test('two labs on a course page: unique section names, axe-core finds no violations', async () => {
  const url = coursePage('two', {
    labs: [
      '<wing-lab id="a" panels="controls,numbers,spectrum"></wing-lab>',
      '<wing-lab id="b" gamma0="0.05" mode="2" panels="controls,numbers,spectrum"></wing-lab>',
    ],
  });
  const { page, problems, context } = await openPage(env.browser, url, { width: 1280, height: 800 });
  await page.goto(url);
  await waitLab(page, '#a');
  await waitLab(page, '#b');
  const names = await page.evaluate(() =>
    [...document.querySelectorAll('wing-lab')].flatMap((l) =>
      [...l.shadowRoot.querySelectorAll('section.wl-panel')]
        .filter((s) => !s.hidden)
        .map((s) => {
          const by = s.getAttribute('aria-labelledby');
          return (
            s.getAttribute('aria-label') ||
            (by
              ? by
                  .split(/\s+/)
                  .map((id) => l.shadowRoot.getElementById(id)?.textContent || '')
                  .join(' ')
              : '')
          );
        }),
    ),
  );
  assert.equal(new Set(names).size, names.length, `section names are unique: ${names.join(' | ')}`);
  assert.ok(
    names.some((n) => /lab 2/.test(n)),
    names.join(' | '),
  );
  await page.addScriptTag({ path: AXE });
  const vs = await page.evaluate(async () => {
    const r = await /** @type {any} */ (window).axe.run(document, {
      resultTypes: ['violations'],
      rules: { 'target-size': { enabled: true } },
    });
    return r.violations.map((v) => ({
      rule: v.id,
      nodes: v.nodes.map((n) => `${JSON.stringify(n.target)} ${n.failureSummary}`),
    }));
  });
  fs.writeFileSync(path.join(OUT, 'axe-element-two.json'), JSON.stringify(vs, null, 2));
  assert.deepEqual(vs, []);
  assert.deepEqual(problems, []);
  await context.close();
});

for (const vp of [
  { width: 1280, height: 800 },
  { width: 390, height: 844 },
]) {
  test(`course page with the element at ${vp.width}×${vp.height}: fits the column, no sideways scroll (screenshot)`, async () => {
    const url = coursePage(`shot${vp.width}`, {
      labs: ['<wing-lab gamma0="0.1" panels="controls,numbers,spectrum"></wing-lab>'],
      width: 760,
    });
    const { page, problems, context } = await openPage(env.browser, url, vp);
    await page.goto(url);
    await waitLab(page);
    await page.waitForTimeout(200);
    const m = await page.evaluate(() => {
      const l = document.querySelector('wing-lab').getBoundingClientRect();
      const col = document.querySelector('.col').getBoundingClientRect();
      return {
        scroll: document.documentElement.scrollWidth,
        lab: [l.x, l.width],
        col: [col.x, col.width],
        layout: document.querySelector('wing-lab').dataset.layout,
      };
    });
    assert.ok(m.scroll <= vp.width, `no sideways scroll: ${JSON.stringify(m)}`);
    assert.deepEqual(m.lab, m.col, 'the element fills the course column');
    assert.equal(m.layout, vp.width < 800 ? 'narrow' : 'medium');
    await page.screenshot({ path: path.join(OUT, `element-course-${vp.width}.png`) });
    await page.screenshot({ path: path.join(OUT, `element-course-${vp.width}-full.png`), fullPage: true });
    assert.deepEqual(problems, []);
    await context.close();
  });
}

test('a course page with a strict Content-Security-Policy (the one the docs give) runs the lab from the other origin, FE worker included', async () => {
  const B = new URL(lab.url).origin;
  // No 'unsafe-inline' anywhere: the course page's own CSS is a file, and the lab adds no inline style or script.
  const csp = `default-src 'self'; script-src 'self' ${B} 'wasm-unsafe-eval'; style-src 'self' ${B}; connect-src 'self' ${B}; worker-src blob: ${B}; img-src 'self' data: blob:`;
  const url = coursePage('csp', {
    labs: ['<wing-lab modes="fe" panels="controls,numbers,spectrum"></wing-lab>'],
    externalCss: true,
    extraHead: `<meta http-equiv="Content-Security-Policy" content="${csp}">`,
  });
  const { page, problems, context } = await openPage(env.browser, url, { width: 1280, height: 800 });
  /** @type {string[]} */
  const violations = [];
  page.on('console', (m) => {
    if (/Content Security Policy/i.test(m.text())) violations.push(m.text());
  });
  await page.goto(url);
  await waitLab(page);
  await page.waitForFunction(
    () => {
      const l = /** @type {any} */ (document.querySelector('wing-lab'));
      return l.fe && l.analysis && l.analysis.sim.modes.length === l.fe.modes.length;
    },
    null,
    { timeout: 90000 },
  );
  assert.match(
    await page.evaluate(
      () => getComputedStyle(document.querySelector('wing-lab').shadowRoot.querySelector('.wl-panel')).fontFamily,
    ),
    /system-ui/,
  );
  assert.deepEqual(violations, []);
  assert.deepEqual(problems, []);
  await context.close();
});
