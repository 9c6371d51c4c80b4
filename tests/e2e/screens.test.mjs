// The lab's screens (www/screens.js) at 1280×800: each focused screen fits in about two screen
// heights with at most ~30 visible controls, `screen=` (URL), the `screen` attribute and the
// iframe API's set({screen}) open one, unknown values are refused by name, the tablist works
// from the keyboard, panels off screen do no redraw work until shown, a guided experiment opens
// its screen, `panels=` still shows exactly the chosen panels, the full page keeps everything,
// and axe finds no violations on any screen. Screenshots of every screen at 1280×800 and
// 390×844 go to test-output/screens/.
//   node --test --test-concurrency=1 tests/e2e/screens.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { setup, openPage, waitRenders, renders, OUT } from './helpers.mjs';
import { SCREENS, SCREEN_IDS, screenPanels } from '../../www/screens.js';
import { PANELS } from '../../www/state.js';

const require = createRequire(import.meta.url);
const AXE = require.resolve('axe-core/axe.min.js');
const SHOTS = path.join(OUT, 'screens');

// Budgets at 1280×800. Height: two screen heights (1600 px) plus the page's own header and
// footer (about 70 px at this width, outside the lab) and 10 % of a screen for text that wraps
// differently with other fonts: 1750 px. Controls: the ~30 of the issue, counted as every
// visible button, input, select, textarea, link and tabindex'd element in the lab (a slider's
// range and its number box count as two), except the screen tabs: they are the page's
// navigation, one tab stop (roving tabindex), not controls of the model; the page's own footer
// link is not the lab's (an embedded lab has none).
const MAX_HEIGHT = 1750;
// 31 since the Medium control (vacuum / helium / air) joined the main controls.
const MAX_CONTROLS = 31;
const FOCUSED = SCREENS.filter((s) => s.panels);

let env;
before(async () => {
  env = await setup();
  fs.mkdirSync(SHOTS, { recursive: true });
});
after(async () => {
  if (env) await env.close();
});

/** What the page shows: its height, the visible controls (page and lab), the visible panels. */
function measure(page, host = 'wing-lab') {
  return page.evaluate((h) => {
    const lab = document.querySelector(h);
    const sel = 'button, input:not([type=hidden]), select, textarea, a[href], [tabindex]:not([tabindex="-1"])';
    const seen = (e) =>
      e.checkVisibility({ visibilityProperty: true, opacityProperty: true }) && e.getBoundingClientRect().width > 0;
    const controls = [...lab.shadowRoot.querySelectorAll(sel)].filter(
      (e) => seen(e) && e.getAttribute('role') !== 'tab',
    );
    const kinds = {};
    for (const c of controls) {
      const k = c.tagName === 'INPUT' ? `input:${c.type}` : c.tagName.toLowerCase();
      kinds[k] = (kinds[k] || 0) + 1;
    }
    return {
      height: Math.ceil(document.documentElement.scrollHeight),
      labHeight: Math.ceil(lab.getBoundingClientRect().height),
      controls: controls.length,
      kinds,
      panels: [...lab.shadowRoot.querySelectorAll('.wl-panel')].filter((p) => !p.hidden).map((p) => p.dataset.panel),
      screen: lab.dataset.screen,
      selected: [...lab.shadowRoot.querySelectorAll('[role=tab][aria-selected=true]')].map((t) => t.dataset.screen),
    };
  }, host);
}

async function openScreen(query, viewport = { width: 1280, height: 800 }) {
  const o = await openPage(env.browser, env.url, viewport);
  await o.page.goto(`${env.url}${query}`);
  await waitRenders(o.page, 1);
  return o;
}

/** Waits until a shown 3-D view has its wing (its placeholder is taller than the view). */
async function settled(page) {
  await page.waitForFunction(
    () => {
      const box = __wl.q('[data-wing3d]');
      return !box || !box.checkVisibility() || box.dataset.state !== 'loading';
    },
    null,
    { timeout: 60000 },
  );
  await page.waitForTimeout(300);
}

/** Injects axe and runs every default rule plus target-size on the whole page. */
async function axe(page) {
  await page.addScriptTag({ path: AXE });
  return page.evaluate(async () => {
    const r = await window.axe.run(document, {
      resultTypes: ['violations'],
      rules: { 'target-size': { enabled: true } },
    });
    return r.violations.map((v) => `${v.id}: ${v.help} — ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
  });
}

const measured = [];
after(() => {
  if (measured.length) fs.writeFileSync(path.join(SHOTS, 'measured.json'), JSON.stringify(measured, null, 2));
});

for (const s of FOCUSED) {
  test(`screen ${s.id} at 1280×800: at most ${MAX_HEIGHT} px tall, at most ${MAX_CONTROLS} visible controls, its panels only, no axe violations`, async () => {
    const { page, problems, context } = await openScreen(`?screen=${s.id}`);
    await settled(page);
    const m = await measure(page);
    measured.push({ screen: s.id, viewport: '1280x800', ...m });
    assert.equal(m.screen, s.id);
    assert.deepEqual(m.selected, [s.id]);
    assert.deepEqual(m.panels.slice().sort(), screenPanels(s.id, PANELS).sort());
    assert.ok(m.height <= MAX_HEIGHT, `${s.id}: page height ${m.height} px > ${MAX_HEIGHT} px`);
    assert.ok(
      m.controls <= MAX_CONTROLS,
      `${s.id}: ${m.controls} visible controls > ${MAX_CONTROLS}: ${JSON.stringify(m.kinds)}`,
    );
    await page.screenshot({ path: path.join(SHOTS, `${s.id}-1280.png`), fullPage: true });
    assert.deepEqual(await axe(page), []);
    assert.deepEqual(problems, []);
    await context.close();
  });
}

test('the full page keeps every panel (and is the long page it was), with no axe violations', async () => {
  const { page, problems, context } = await openScreen('?screen=full');
  await settled(page);
  const m = await measure(page);
  measured.push({ screen: 'full', viewport: '1280x800', ...m });
  assert.deepEqual(m.panels.slice().sort(), PANELS.slice().sort());
  assert.ok(m.controls > 100, `full page: ${m.controls} controls`);
  assert.ok(m.height > 3 * 800, `full page: ${m.height} px`);
  await page.screenshot({ path: path.join(SHOTS, 'full-1280.png'), fullPage: true });
  assert.deepEqual(await axe(page), []);
  assert.deepEqual(problems, []);
  await context.close();
});

test('phone 390×844: every screen shown, screenshots, no axe violations', async () => {
  const { page, problems, context } = await openScreen('', { width: 390, height: 844 });
  for (const id of SCREEN_IDS) {
    await page.evaluate((s) => {
      document.querySelector('wing-lab').screen = s;
    }, id);
    await page.waitForFunction((s) => document.querySelector('wing-lab').dataset.screen === s, id);
    await settled(page);
    const m = await measure(page);
    measured.push({ screen: id, viewport: '390x844', ...m });
    await page.screenshot({ path: path.join(SHOTS, `${id}-390.png`), fullPage: true });
    assert.deepEqual(await axe(page), [], id);
  }
  assert.deepEqual(problems, []);
  await context.close();
});

test('no screen= opens The beat; screen= opens its screen and is kept in the URL; an unknown one is refused by name', async () => {
  const a = await openScreen('');
  assert.equal((await measure(a.page)).screen, 'beat');
  await a.context.close();
  const b = await openScreen('?screen=wing');
  assert.equal((await measure(b.page)).screen, 'wing');
  // A tab click is written back to the URL (shareable).
  await b.page.click('wing-lab [role=tab][data-screen="research"]');
  await b.page.waitForFunction(() => new URLSearchParams(location.search).get('screen') === 'research', null, {
    timeout: 5000,
  });
  assert.deepEqual((await measure(b.page)).panels.sort(), screenPanels('research', PANELS).sort());
  await b.context.close();
  const c = await openScreen('?screen=everything');
  const notice = await c.page.textContent('wing-lab .wl-notice');
  assert.match(notice, /screen \(expected one of beat, forces, wing, sensing, research, full\)/);
  assert.equal((await measure(c.page)).screen, 'beat');
  await c.context.close();
});

test('keyboard: Tab reaches the selected tab, arrows move between tabs, Enter and Space open a screen, Tab enters it', async () => {
  const { page, context } = await openScreen('');
  const active = () =>
    page.evaluate(() => {
      const a = __wl.active();
      return a
        ? {
            screen: a.dataset.screen || null,
            role: a.getAttribute('role'),
            panel: a.closest('.wl-panel')?.dataset.panel || null,
          }
        : null;
    });
  await page.focus('body');
  await page.keyboard.press('Tab');
  assert.deepEqual(await active(), { screen: 'beat', role: 'tab', panel: null });
  await page.keyboard.press('ArrowRight');
  assert.equal((await active()).screen, 'forces');
  assert.equal((await measure(page)).screen, 'beat', 'arrows move the focus only');
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => document.querySelector('wing-lab').dataset.screen === 'forces');
  assert.equal((await active()).screen, 'forces', 'the focus stays on the tab');
  await page.keyboard.press('End');
  assert.equal((await active()).screen, 'full');
  await page.keyboard.press('Home');
  assert.equal((await active()).screen, 'beat');
  await page.keyboard.press('ArrowLeft');
  assert.equal((await active()).screen, 'full', 'arrows wrap around');
  await page.keyboard.press('ArrowLeft');
  assert.equal((await active()).screen, 'research');
  await page.keyboard.press(' ');
  await page.waitForFunction(() => document.querySelector('wing-lab').dataset.screen === 'research');
  // One tab stop for the whole tablist: Tab goes on into the screen's panels.
  await page.keyboard.press('Tab');
  const inside = await active();
  assert.ok(inside.panel && screenPanels('research', PANELS).includes(inside.panel), JSON.stringify(inside));
  // The tab's ARIA wiring: selected state, controls the tabpanel, which is labelled by it.
  const aria = await page.evaluate(() => {
    const tab = __wl.q('[role=tab][aria-selected=true]');
    const panel = __wl.byId(tab.getAttribute('aria-controls'));
    return {
      role: panel.getAttribute('role'),
      labelledby: panel.getAttribute('aria-labelledby'),
      tab: tab.id,
      tabindexes: __wl.qa('[role=tab]').map((t) => t.tabIndex),
    };
  });
  assert.equal(aria.role, 'tabpanel');
  assert.equal(aria.labelledby, aria.tab);
  assert.deepEqual(aria.tabindexes.filter((t) => t === 0).length, 1);
  await context.close();
});

test('panels off screen do no redraw work until shown; then they show the newest result', async () => {
  const { page, context } = await openScreen('?screen=wing');
  const timeSum = () =>
    page.evaluate(() => {
      const u = document.querySelector('wing-lab').plots.time;
      let s = 0;
      for (const series of u.data.slice(1)) for (const v of series) if (v != null) s += Math.abs(v);
      return s;
    });
  const before = await timeSum();
  const n = await renders(page);
  await page.evaluate(() => document.querySelector('wing-lab').store.set({ gamma0: 0.1 }));
  await waitRenders(page, n + 1);
  assert.equal(await timeSum(), before, 'the hidden responses plot was not redrawn');
  await page.click('wing-lab [role=tab][data-screen="beat"]');
  await page.waitForFunction(
    (b) => {
      const u = document.querySelector('wing-lab').plots.time;
      let s = 0;
      for (const series of u.data.slice(1)) for (const v of series) if (v != null) s += Math.abs(v);
      return Math.abs(s - b) > 1e-9 * b;
    },
    before,
    { timeout: 10000 },
  );
  await context.close();
});

test('a guided experiment opens the screen that shows it (chip, URL), and screen= wins over it', async () => {
  const { page, context } = await openScreen('?screen=full');
  await page.click('wing-lab [data-exp="resonance"]');
  await page.waitForFunction(() => document.querySelector('wing-lab').dataset.screen === 'beat');
  await page.waitForFunction(() => new URLSearchParams(location.search).get('screen') === 'beat', null, {
    timeout: 5000,
  });
  // Its study is on another screen: "Go to the resonance map" opens that screen, the
  // experiment's text still shown.
  await page.click('wing-lab .wl-exp-go');
  await page.waitForFunction(() => document.querySelector('wing-lab').dataset.screen === 'research');
  assert.ok(await page.isVisible('wing-lab [data-panel="experiments"] .wl-exp-title'));
  assert.ok(await page.isVisible('wing-lab [data-panel="resonance"] [data-run="resonance"]'));
  await page.goto(`${env.url}?exp=ic`);
  await waitRenders(page, 1);
  assert.equal((await measure(page)).screen, 'research');
  await page.goto(`${env.url}?exp=ic&screen=beat`);
  await waitRenders(page, 1);
  assert.equal((await measure(page)).screen, 'beat');
  // A focused screen lists its own experiments and says where the others are.
  const chips = await page.evaluate(() =>
    __wl
      .qa('a.wl-exp-link[data-exp]')
      .filter((a) => a.checkVisibility())
      .map((a) => a.dataset.exp),
  );
  assert.deepEqual(chips.sort(), ['air-beat', 'beat', 'damping', 'instability', 'no-yaw', 'resonance']);
  assert.match(
    await page.textContent('wing-lab .wl-exp-elsewhere'),
    /More experiments on the “Sensing” and “Research” screens/,
  );
  await context.close();
});

test('panels= still shows exactly the chosen panels (no screen nav), also across screens', async () => {
  for (const list of ['controls,numbers,spectrum', 'controls,experiments,sensing']) {
    const { page, context } = await openScreen(`?panels=${list}`);
    const m = await measure(page);
    assert.deepEqual(m.panels.sort(), list.split(',').sort(), list);
    assert.equal(await page.evaluate(() => __wl.q('[role=tablist]').hidden), true);
    await context.close();
  }
});

test('the screen attribute of <wing-lab> and the iframe API set({screen}) open a screen; a bad value is refused by name', async () => {
  const { page, problems, context } = await openScreen('');
  // A second element on the page, as a course page would write it; then the attribute changed live.
  await page.evaluate(() => {
    const l = document.createElement('wing-lab');
    l.id = 'second';
    l.setAttribute('screen', 'forces');
    document.querySelector('main').append(l);
  });
  await waitRenders(page, 1, '#second');
  assert.equal((await measure(page, '#second')).screen, 'forces');
  await page.evaluate(() => document.querySelector('#second').setAttribute('screen', 'wing'));
  await page.waitForFunction(() => document.querySelector('#second').dataset.screen === 'wing');
  await page.evaluate(() => document.querySelector('#second').setAttribute('screen', 'nowhere'));
  assert.match(await page.textContent('#second .wl-notice'), /screen \(expected one of /);
  assert.equal((await measure(page, '#second')).screen, 'wing');
  await page.evaluate(() => document.querySelector('#second').remove());
  // The iframe API.
  await page.evaluate((u) => {
    const f = document.createElement('iframe');
    f.id = 'frame';
    f.title = 'embedded lab';
    f.src = `${u}index.html?embed=1`;
    f.style.cssText = 'width:1000px;height:600px';
    document.querySelector('main').append(f);
  }, env.url);
  const frame = await (await page.waitForSelector('#frame')).contentFrame();
  await frame.waitForFunction(() => Number(document.getElementById('lab')?.dataset.renders || 0) >= 1, null, {
    timeout: 30000,
  });
  const call = (msg) =>
    page.evaluate(
      (m) =>
        new Promise((resolve) => {
          const f = document.getElementById('frame');
          const on = (e) => {
            if (e.source === f.contentWindow && e.data && e.data.id === m.id) {
              removeEventListener('message', on);
              resolve(e.data);
            }
          };
          addEventListener('message', on);
          f.contentWindow.postMessage(m, '*');
          setTimeout(() => resolve(null), 10000);
        }),
      msg,
    );
  const ok = await call({ type: 'wingbeat:set', version: 1, id: 's1', params: { screen: 'sensing' } });
  assert.equal(ok.type, 'wingbeat:state', JSON.stringify(ok));
  assert.equal(ok.params.screen, 'sensing');
  assert.equal(await frame.evaluate(() => document.getElementById('lab').dataset.screen), 'sensing');
  const bad = await call({ type: 'wingbeat:set', version: 1, id: 's2', params: { screen: 'home' } });
  assert.equal(bad.type, 'wingbeat:error');
  assert.equal(bad.field, 'screen');
  assert.match(bad.message, /screen: expected one of beat, forces, wing, sensing, research, full/);
  const got = await call({ type: 'wingbeat:get', version: 1, id: 'g1' });
  assert.equal(got.params.screen, 'sensing');
  assert.deepEqual(problems, []);
  await context.close();
});

test('a focused screen folds the export kinds behind one Export… button; opened, they export', async () => {
  const { page, problems, context } = await openScreen('?screen=beat');
  const head = 'wing-lab [data-panel="time"] .wl-head';
  assert.equal(await page.isVisible(`${head} [data-export="csv"]`), false);
  assert.equal(await page.getAttribute(`${head} .wl-export-toggle`, 'aria-expanded'), 'false');
  await page.click(`${head} .wl-export-toggle`);
  assert.equal(await page.getAttribute(`${head} .wl-export-toggle`, 'aria-expanded'), 'true');
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click(`${head} [data-export="csv"]`)]);
  assert.equal(dl.suggestedFilename(), 'wingbeat-time.csv');
  // The full page shows the kinds as before, with no toggle.
  await page.click('wing-lab [role=tab][data-screen="full"]');
  await page.waitForFunction(() => document.querySelector('wing-lab').dataset.screen === 'full');
  assert.equal(await page.isVisible(`${head} .wl-export-toggle`), false);
  assert.equal(await page.isVisible(`wing-lab [data-panel="spectrum"] .wl-head [data-export="svg"]`), true);
  assert.deepEqual(problems, []);
  await context.close();
});
