// The lab embedded by iframe in a course page on another origin (issue 11, "iframe first"):
// origin A (a temporary folder: the course pages) embeds http://127.0.0.1:<B>/index.html?embed=1
// from origin B (www/, plain static hosting: no CORS, no special headers) with the host helper
// www/embed-host.js. Checks: compact layout from the first frame, auto-height within 1 s of a
// panel change, no inner scrollbar, the versioned postMessage API (set γ0, read back the Floquet
// numbers the lab shows, subscribe, errors that name the field), origin and source checks on both
// sides, parent_origin=, the sandbox attributes learning platforms use. Screenshots of the
// course page at 1280x800 and 390x844 go to test-output/.
//   node --test --test-concurrency=1 tests/e2e/iframe.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { ROOT, OUT, CHROMIUM, ARGS, openPage } from './helpers.mjs';
import { startServer } from '../../scripts/serve.mjs';

const LAB_ROOT = path.resolve(ROOT, process.env.LAB_ROOT || 'www');
const PANELS0 = 'controls,numbers';

/** @type {{ A: string, B: string, Bcors: string, C: string, servers: import('node:http').Server[], browser: import('playwright-core').Browser, dir: string }} */
let env;

/** The course page: a centred text column with the lab in it and the host helper from B. */
function coursePage(labSrc, { sandbox = null, helper = '', extra = '' } = {}) {
  return `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<link rel="icon" href="data:,">
<title>Course: flapping-wing dynamics, week 3</title>
<style>
  body { font: 17px/1.5 Georgia, serif; color: #222; background: #fffdf7; margin: 0; }
  main { max-width: 760px; margin: 0 auto; padding: 1rem; }
  iframe { display: block; width: 100%; border: 1px solid #bbb; border-radius: 4px; }
</style>
</head>
<body>
<main>
  <h1>Week 3: beats in the wing's response</h1>
  <p>Move γ<sub>0</sub> and watch the beat period in the table below.</p>
  <iframe id="lab" data-wingbeat title="wingbeat lab" src="${labSrc}"${sandbox !== null ? ` sandbox="${sandbox}"` : ''}></iframe>
  <p>After the lab: questions for the tutorial.</p>
  ${extra}
</main>
${helper}
<script>
  // Test probes (not part of the snippet): every message the page gets, and every height change.
  window.got = [];
  window.heights = [];
  addEventListener('message', function (e) { got.push({ origin: e.origin, fromLab: e.source === document.getElementById('lab').contentWindow, data: e.data }); });
  new MutationObserver(function () { heights.push({ t: performance.now(), h: document.getElementById('lab').style.height }); })
    .observe(document.getElementById('lab'), { attributes: true, attributeFilter: ['style'] });
</script>
</body>
</html>
`;
}

before(async () => {
  if (!fs.existsSync(path.join(LAB_ROOT, 'pkg', 'wingbeat.js')))
    throw new Error('www/pkg is missing: run scripts/build-web.sh www first');
  fs.mkdirSync(OUT, { recursive: true });
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'wingbeat-course-'));
  const b = await startServer(LAB_ROOT, 0);
  const bc = await startServer(LAB_ROOT, 0, { cors: true });
  const a = await startServer(dir, 0);
  const c = await startServer(dir, 0);
  const B = b.url,
    A = a.url,
    C = c.url,
    Bcors = bc.url;
  const helper = `<script src="${B}embed-host.js"></script>`;
  const src = (q = '') => `${B}index.html?embed=1&panels=${PANELS0}${q}`;
  fs.writeFileSync(
    path.join(dir, 'course.html'),
    coursePage(src(), {
      helper,
      extra: '<iframe id="other" title="other content" src="other.html" style="height:40px"></iframe>',
    }),
  );
  // A sibling frame of origin A: posts to the lab (must be ignored: wrong source).
  fs.writeFileSync(path.join(dir, 'other.html'), '<!doctype html><title>other</title><p>another widget</p>');
  // parent_origin pinned to A (works) and to C (the course page on A is ignored).
  fs.writeFileSync(
    path.join(dir, 'pinned.html'),
    coursePage(src(`&parent_origin=${encodeURIComponent(A.replace(/\/$/, ''))}`), { helper }),
  );
  fs.writeFileSync(
    path.join(dir, 'pinned-other.html'),
    coursePage(src(`&parent_origin=${encodeURIComponent(C.replace(/\/$/, ''))}`), { helper }),
  );
  // Not an origin (a path added): the API stays silent rather than answering anyone.
  fs.writeFileSync(
    path.join(dir, 'pinned-bad.html'),
    coursePage(src(`&parent_origin=${encodeURIComponent(A + 'course.html')}`), { helper }),
  );
  // The sandbox attributes of learning platforms.
  fs.writeFileSync(
    path.join(dir, 'sandbox-same.html'),
    coursePage(src(), { helper, sandbox: 'allow-scripts allow-same-origin' }),
  );
  fs.writeFileSync(path.join(dir, 'sandbox-scripts.html'), coursePage(src(), { helper, sandbox: 'allow-scripts' }));
  fs.writeFileSync(
    path.join(dir, 'sandbox-scripts-cors.html'),
    coursePage(`${Bcors}index.html?embed=1&panels=${PANELS0}`, {
      helper: `<script src="${Bcors}embed-host.js"></script>`,
      sandbox: 'allow-scripts',
    }),
  );
  const browser = await chromium.launch({ executablePath: CHROMIUM, args: ARGS, headless: true });
  env = { A, B, Bcors, C, dir, browser, servers: [a.server, b.server, bc.server, c.server] };
});

after(async () => {
  if (!env) return;
  await env.browser.close();
  for (const s of env.servers) s.close();
  fs.rmSync(env.dir, { recursive: true, force: true });
});

/** The lab's frame of a course page, once it has rendered. */
async function labFrame(page, n = 1) {
  const handle = await page.waitForSelector('iframe#lab');
  const frame = await handle.contentFrame();
  await frame.waitForFunction((k) => Number(document.getElementById('lab')?.dataset.renders || 0) >= k, n, {
    timeout: 30000,
  });
  return frame;
}

/**
 * Waits until none of the page's requests (its frames' and their workers') is in flight for
 * `quiet` ms, so that a navigation the test makes next does not cancel loads the lab started
 * (the live worker, started by the first parameter change, loads worker.js and its modules) and
 * count them as failed. Fails, naming the loads, when they have not settled within `limit` ms.
 * Call trackLoads right after openPage (before the first goto).
 * @param {import('playwright-core').Page} page
 */
function trackLoads(page) {
  /** @type {Set<import('playwright-core').Request>} */
  const pending = new Set();
  page.on('request', (r) => pending.add(r));
  page.on('requestfinished', (r) => pending.delete(r));
  page.on('requestfailed', (r) => pending.delete(r));
  return async function settled(quiet = 300, limit = 15000) {
    const t0 = Date.now();
    let idleSince = pending.size ? 0 : Date.now();
    while (!idleSince || Date.now() - idleSince < quiet) {
      if (Date.now() - t0 > limit)
        throw new Error(`loads still in flight after ${limit} ms: ${[...pending].map((r) => r.url()).join(', ')}`);
      await new Promise((r) => setTimeout(r, 25));
      if (pending.size) idleSince = 0;
      else if (!idleSince) idleSince = Date.now();
    }
  };
}

/** Heights: the lab's content (inside the frame), the frame's viewport, the iframe element. */
async function heights(page, frame) {
  const inner = await frame.evaluate(() => {
    const html = document.documentElement;
    return {
      content: Math.ceil(html.getBoundingClientRect().height),
      scrollH: html.scrollHeight,
      clientH: html.clientHeight,
      scrollW: html.scrollWidth,
      clientW: html.clientWidth,
    };
  });
  const outer = await page.evaluate(() => document.getElementById('lab').clientHeight);
  return { ...inner, iframe: outer };
}

/** Calls the host helper's API on the course page (resolves with the reply, or { rejected }). */
function api(page, method, arg) {
  return page.evaluate(
    ([m, a]) => {
      const lab = window.wingbeatLab(document.getElementById('lab'));
      return lab[m](a).then(
        (r) => r,
        (e) => ({ rejected: e }),
      );
    },
    [method, arg],
  );
}

/** Posts a raw message to the lab frame from the course page and waits for a reply with `id`. */
function raw(page, msg, wait = 3000) {
  return page.evaluate(
    ([m, w]) =>
      new Promise((resolve) => {
        const frame = document.getElementById('lab');
        const on = (e) => {
          if (e.source === frame.contentWindow && e.data && e.data.id === m.id) {
            removeEventListener('message', on);
            resolve(e.data);
          }
        };
        addEventListener('message', on);
        frame.contentWindow.postMessage(m, '*');
        setTimeout(() => {
          removeEventListener('message', on);
          resolve(null);
        }, w);
      }),
    [msg, wait],
  );
}

const cells = (frame) =>
  frame.evaluate(() => {
    const lab = document.getElementById('lab');
    const root = lab.shadowRoot || lab;
    const t = (f) => root.querySelector(`[data-field="${f}"]`)?.textContent ?? null;
    return [0, 1].map((k) => ({
      feff: t(`feff-${k}`),
      mod: t(`mod-${k}`),
      beat: t(`beat-${k}`),
      stable: t(`stable-${k}`),
    }));
  });

test('?embed=1 is compact from the first frame: header hidden, embed attribute, one column', async () => {
  const { context, page, problems } = await openPage(
    env.browser,
    env.B,
    { width: 720, height: 800 },
    { isolated: true },
  );
  // Runs before the page's own scripts: records what every frame (rAF = just before a paint)
  // shows until the lab has rendered.
  await context.addInitScript(() => {
    /** @type {any[]} */
    const frames = [];
    /** @type {any} */ (window).frames_seen = frames;
    const look = () => {
      const lab = document.getElementById('lab');
      const header = document.querySelector('header.site');
      const root = lab && (lab.shadowRoot || lab);
      const grid = root && root.querySelector('.wl-grid');
      frames.push({
        embedClass: document.documentElement.classList.contains('embed'),
        header: header ? getComputedStyle(header).display : 'not parsed yet',
        labEmbed: lab ? lab.hasAttribute('embed') : null,
        defined: !!customElements.get('wing-lab'),
        columns: grid ? getComputedStyle(grid).gridTemplateColumns.split(' ').filter(Boolean).length : 0,
        layout: lab ? lab.dataset.layout || '' : '',
        visible: !!(
          root &&
          root.querySelector('.wl-root') &&
          getComputedStyle(/** @type {Element} */ (root.querySelector('.wl-root'))).visibility === 'visible'
        ),
        rendered: lab ? Number(lab.dataset.renders || 0) : 0,
      });
      if (!(lab && Number(lab.dataset.renders || 0) >= 1) && frames.length < 2000) requestAnimationFrame(look);
    };
    requestAnimationFrame(look);
  });
  // offline= is a page setting (offline.js), like parent_origin=: no "unknown parameter" notice.
  await page.goto(`${env.B}index.html?embed=1&offline=1`);
  await page.waitForFunction(() => Number(document.getElementById('lab')?.dataset.renders || 0) >= 1, null, {
    timeout: 30000,
  });
  const frames = await page.evaluate(() => /** @type {any} */ (window).frames_seen);
  fs.writeFileSync(path.join(OUT, 'iframe-first-frames.json'), JSON.stringify(frames, null, 1));
  assert.ok(frames.length > 0, 'frames were recorded');
  assert.ok(
    frames.some((f) => f.visible),
    'the lab became visible while frames were recorded',
  );
  const painted = frames.filter((f) => f.header !== 'not parsed yet');
  for (const f of painted) {
    assert.equal(f.header, 'none', `the header is never shown in embed mode (frame ${JSON.stringify(f)})`);
    assert.ok(f.embedClass, `html.embed is set before any frame shows the page (${JSON.stringify(f)})`);
    // Before lab.js has defined the element it is an empty unknown element (nothing to show).
    if (f.defined)
      assert.ok(f.labEmbed, `the embed attribute is set before the element is defined (${JSON.stringify(f)})`);
    if (f.layout)
      assert.equal(
        f.layout,
        'narrow',
        `the compact layout from the first frame the element has one (${JSON.stringify(f)})`,
      );
    // While its stylesheets load the lab's root is invisible (its grid is not styled yet).
    if (f.visible) assert.equal(f.columns, 1, `one column in every frame that shows the lab (${JSON.stringify(f)})`);
  }
  const footer = await page.evaluate(() => getComputedStyle(document.querySelector('footer.site')).display);
  assert.equal(footer, 'none');
  assert.equal(new URL(page.url()).searchParams.get('embed'), '1', 'embed=1 stays in the address');
  const notice = await page.evaluate(() => {
    const lab = document.getElementById('lab');
    const n = (lab.shadowRoot || lab).querySelector('.wl-notice');
    return n && !n.hidden ? n.textContent : '';
  });
  assert.equal(notice, '', 'no notice about page settings');
  assert.deepEqual(problems, []);
  await context.close();
});

test('course page on origin A: the iframe from origin B sizes itself, no inner scrollbar, follows panel changes within 1 s', async () => {
  const { context, page, problems } = await openPage(env.browser, env.A, { width: 1280, height: 800 });
  await page.goto(`${env.A}course.html`);
  const frame = await labFrame(page);
  // The first height arrives with the first layout; wait until it has settled on the content.
  await page.waitForFunction(() => document.getElementById('lab').style.height !== '', null, { timeout: 10000 });
  await page.waitForTimeout(300);
  let h = await heights(page, frame);
  assert.ok(Math.abs(h.iframe - h.content) <= 1, `iframe ${h.iframe} px = content ${h.content} px`);
  assert.ok(h.scrollH <= h.clientH, `no vertical scrollbar inside the frame (${h.scrollH} <= ${h.clientH})`);
  assert.ok(h.scrollW <= h.clientW, `no horizontal scrollbar inside the frame (${h.scrollW} <= ${h.clientW})`);
  const first = h.iframe;

  // More panels: taller. The helper's set resolves after the recompute; the height must follow
  // within 1 s of the request.
  /** @type {{ label: string, latency: number, iframe: number, content: number }[]} */
  const changes = [];
  for (const panels of ['controls,numbers,time,spectrum', 'numbers', PANELS0]) {
    const t0 = await page.evaluate(() => performance.now());
    const reply = await api(page, 'set', { panels });
    assert.equal(reply.type, 'wingbeat:state', JSON.stringify(reply));
    assert.deepEqual(reply.params.panels, panels.split(','));
    // Sleep until 1 s after the request, then compare.
    const now = await page.evaluate(() => performance.now());
    await page.waitForTimeout(Math.max(0, 1000 - (now - t0)));
    h = await heights(page, frame);
    const last = await page.evaluate((t) => {
      const hs = window.heights.filter((x) => x.t >= t);
      return hs.length ? hs[hs.length - 1].t - t : -1;
    }, t0);
    changes.push({ label: panels, latency: Math.round(last), iframe: h.iframe, content: h.content });
    assert.ok(
      Math.abs(h.iframe - h.content) <= 1,
      `${panels}: iframe ${h.iframe} px = content ${h.content} px 1 s after the change`,
    );
    assert.ok(h.scrollH <= h.clientH, `${panels}: no inner scrollbar (${h.scrollH} <= ${h.clientH})`);
    assert.ok(last >= 0 && last < 1000, `${panels}: the iframe height changed within 1 s (${last} ms)`);
  }
  assert.ok(changes[0].iframe > first + 100, `more panels, taller iframe (${first} → ${changes[0].iframe})`);
  assert.ok(changes[1].iframe < first, `fewer panels, shorter iframe (${first} → ${changes[1].iframe})`);
  assert.ok(Math.abs(changes[2].iframe - first) <= 2, 'back to the first panels, back to the first height');
  fs.writeFileSync(path.join(OUT, 'iframe-heights.json'), JSON.stringify({ first, changes }, null, 1));

  // The host helper ignores a height message that is not from the lab's window.
  const before = await page.evaluate(() => document.getElementById('lab').style.height);
  await page.evaluate(() => window.postMessage({ type: 'wingbeat:height', version: 1, height: 5000 }, '*'));
  await page.waitForTimeout(200);
  assert.equal(
    await page.evaluate(() => document.getElementById('lab').style.height),
    before,
    'a height from the wrong source is ignored',
  );
  assert.deepEqual(problems, []);
  await context.close();
});

test('postMessage API: set γ0 and β0, read back the Floquet numbers the lab shows; subscribe; errors name the field', async () => {
  const { context, page, problems } = await openPage(env.browser, env.A, { width: 1280, height: 800 });
  await page.goto(`${env.A}course.html`);
  const frame = await labFrame(page);

  const s0 = await api(page, 'get');
  assert.equal(s0.type, 'wingbeat:state');
  assert.equal(s0.version, 1);
  assert.equal(s0.params.gamma0, 0.2);
  assert.equal(s0.results.modes.length, 2);
  const shown0 = await cells(frame);
  assert.deepEqual(
    s0.results.modes.map((m) => m.shown),
    shown0,
    'get returns what the table shows',
  );

  // γ0: a fresh computation (the force shares move), but the Floquet numbers stay: the
  // parametric stiffness of Eq. 13 is α̇²cos²β + β̇², without γ (docs/embedding.md says so).
  const s1 = await api(page, 'set', { gamma0: 0.05 });
  assert.equal(s1.type, 'wingbeat:state', JSON.stringify(s1));
  assert.equal(s1.params.gamma0, 0.05);
  for (const k of [0, 1]) {
    const a = s0.results.modes[k],
      b = s1.results.modes[k];
    assert.notEqual(
      a.shares_percent.coriolis,
      b.shares_percent.coriolis,
      `mode ${k + 1}: new shares after γ0 (a new computation)`,
    );
    assert.equal(b.f_eff_hz, a.f_eff_hz, `mode ${k + 1}: γ0 does not enter the Floquet stiffness`);
    for (const key of ['f_eff_hz', 'max_modulus']) assert.ok(Number.isFinite(b[key]), key);
    assert.equal(typeof b.stable, 'boolean');
  }
  assert.deepEqual(
    s1.results.modes.map((m) => m.shown),
    await cells(frame),
    "the reply equals what the lab's numbers show after the set",
  );
  // β0 enters the stiffness: new Floquet numbers, equal to the table and to the element's analysis.
  const s2 = await api(page, 'set', { beta0: 0.3 });
  assert.equal(s2.type, 'wingbeat:state', JSON.stringify(s2));
  assert.equal(s2.params.gamma0, 0.05, 'a set leaves the other parameters alone');
  for (const k of [0, 1]) {
    const a = s1.results.modes[k],
      b = s2.results.modes[k];
    assert.ok(
      Math.abs(a.f_eff_hz - b.f_eff_hz) > 0.1,
      `mode ${k + 1}: new effective frequency (${a.f_eff_hz} → ${b.f_eff_hz} Hz)`,
    );
    assert.notEqual(a.beat_period_s, b.beat_period_s, `mode ${k + 1}: new beat period`);
  }
  const shown2 = await cells(frame);
  assert.deepEqual(
    s2.results.modes.map((m) => m.shown),
    shown2,
    "the reply equals what the lab's numbers show after the set",
  );
  const fromLab = await frame.evaluate(() =>
    document
      .getElementById('lab')
      .analysis.sim.modes.map((m) => [m.floquet.effective_freq_hz, m.floquet.max_modulus, m.floquet.beat_period_s]),
  );
  assert.deepEqual(
    s2.results.modes.map((m) => [m.f_eff_hz, m.max_modulus, m.beat_period_s]),
    fromLab,
    "the raw numbers are the element's analysis",
  );
  assert.match(s2.results.summary, /^Mode 1 of 2 \(paper table\): Floquet effective frequency [\d.]+ Hz/);
  const slider = await frame.evaluate(() => {
    const lab = document.getElementById('lab');
    return lab.state.gamma0;
  });
  assert.equal(slider, 0.05, "the lab's state has the new γ0");

  // subscribe: a result after every recompute (here: one started from the lab's own state).
  const sub = await api(page, 'subscribe');
  assert.equal(sub.type, 'wingbeat:subscribed');
  await page.evaluate(() => {
    window.got = [];
  });
  await frame.evaluate(() => document.getElementById('lab').store.set({ flap_hz: 30 }));
  await page.waitForFunction(
    () => window.got.some((m) => m.data && m.data.type === 'wingbeat:result' && m.data.params.flap_hz === 30),
    null,
    { timeout: 10000 },
  );
  const result = await page.evaluate(() =>
    window.got.find((m) => m.data.type === 'wingbeat:result' && m.data.params.flap_hz === 30),
  );
  assert.equal(result.fromLab, true);
  assert.equal(result.origin, env.B.replace(/\/$/, ''));
  assert.equal(result.data.version, 1);
  assert.deepEqual(
    result.data.results.modes.map((m) => m.shown),
    await cells(frame),
  );

  // Bad input: the error names the field and its range; nothing is applied.
  const bad = await api(page, 'set', { gamma0: 0.9, zeta: 0.01 });
  assert.equal(bad.rejected.type, 'wingbeat:error');
  assert.equal(bad.rejected.code, 'bad-params');
  assert.equal(bad.rejected.field, 'gamma0');
  assert.match(bad.rejected.message, /gamma0: expected a number in \[0, 0\.5\] rad/);
  assert.equal(
    await frame.evaluate(() => document.getElementById('lab').state.zeta),
    0,
    'a set with a bad field applies nothing',
  );
  const unknown = await api(page, 'set', { gamma: 0.1 });
  assert.equal(unknown.rejected.field, 'gamma');
  assert.match(unknown.rejected.message, /unknown parameter/);
  const panels = await api(page, 'set', { panels: 'controls,plots' });
  assert.equal(panels.rejected.field, 'panels');
  const mode = await api(page, 'set', { mode: '3' });
  assert.equal(mode.rejected.field, 'mode');
  assert.match(mode.rejected.message, /1 to 2/);
  const v2 = await raw(page, { type: 'wingbeat:get', version: 2, id: 'v2' });
  assert.equal(v2 && v2.code, 'bad-version');
  const nov = await raw(page, { type: 'wingbeat:get', id: 'nov' });
  assert.equal(nov && nov.code, 'bad-version', 'a message without a version is refused');
  const typ = await raw(page, { type: 'wingbeat:reset', version: 1, id: 'typ' });
  assert.equal(typ && typ.code, 'unknown-type');
  const foreign = await raw(page, { type: 'other-widget:ping', id: 'foreign' }, 500);
  assert.equal(foreign, null, 'messages of other widgets get no reply');
  fs.writeFileSync(
    path.join(OUT, 'iframe-api.json'),
    JSON.stringify(
      {
        before: s0.results,
        gamma0: s1.results,
        beta0: s2.results,
        errors: [bad.rejected, unknown.rejected, panels.rejected, mode.rejected, v2, typ],
      },
      null,
      1,
    ),
  );

  // A sibling frame of the same origin A is not the lab's parent: ignored, no reply.
  const other = page.frames().find((f) => f.url().endsWith('/other.html'));
  assert.ok(other, 'the sibling frame loaded');
  const siblingReply = await other.evaluate(
    () =>
      new Promise((resolve) => {
        addEventListener('message', (e) => resolve(e.data));
        parent.frames[0].postMessage({ type: 'wingbeat:set', version: 1, id: 'sib', params: { gamma0: 0.3 } }, '*');
        setTimeout(() => resolve(null), 1500);
      }),
  );
  assert.equal(siblingReply, null, 'no reply to a window that is not the parent');
  assert.equal(
    await frame.evaluate(() => document.getElementById('lab').state.gamma0),
    0.05,
    'γ0 unchanged by the sibling',
  );
  assert.deepEqual(problems, []);
  await context.close();
});

test('parent_origin=: the pinned origin is answered, any other is ignored (no reply, no height); a malformed one silences the API', async () => {
  const { context, page, problems } = await openPage(env.browser, env.A, { width: 1000, height: 800 });
  const settled = trackLoads(page);
  await page.goto(`${env.A}pinned.html`);
  const frame = await labFrame(page);
  await page.waitForFunction(() => document.getElementById('lab').style.height !== '', null, { timeout: 10000 });
  const ok = await api(page, 'set', { gamma0: 0.1 });
  assert.equal(ok.type, 'wingbeat:state');
  assert.equal(ok.params.gamma0, 0.1);
  assert.equal(
    new URL(frame.url()).searchParams.get('parent_origin'),
    null,
    'parent_origin is not a lab parameter (taken out of the address)',
  );
  const notice = await frame.evaluate(() => {
    const lab = document.getElementById('lab');
    const n = (lab.shadowRoot || lab).querySelector('.wl-notice');
    return n && !n.hidden ? n.textContent : '';
  });
  assert.equal(notice, '', 'no "invalid parameter" notice for parent_origin');

  // The set above started the lab's live worker: its module loads finish before the page is left.
  await settled();
  await page.goto(`${env.A}pinned-other.html`);
  await labFrame(page);
  await page.waitForTimeout(500);
  const got = await page.evaluate(() => window.got.filter((m) => m.fromLab).map((m) => m.data.type));
  assert.deepEqual(got, [], 'nothing is posted to an origin other than parent_origin');
  assert.equal(
    await page.evaluate(() => document.getElementById('lab').style.height),
    '',
    'no height reaches the other origin',
  );
  const r = await raw(page, { type: 'wingbeat:get', version: 1, id: 'x' }, 1500);
  assert.equal(r, null, 'requests from the other origin are ignored');

  await settled();
  await page.goto(`${env.A}pinned-bad.html`);
  await labFrame(page);
  await page.waitForTimeout(500);
  assert.deepEqual(
    await page.evaluate(() => window.got.filter((m) => m.fromLab).map((m) => m.data.type)),
    [],
    'a malformed parent_origin: nothing posted',
  );
  assert.equal(
    await raw(page, { type: 'wingbeat:get', version: 1, id: 'y' }, 1500),
    null,
    'a malformed parent_origin: nothing answered',
  );
  assert.deepEqual(problems, []);
  await context.close();
});

test("sandbox: allow-scripts allow-same-origin works from plain static hosting; allow-scripts alone needs CORS on the lab's host", async () => {
  /** @type {Record<string, unknown>} */
  const report = {};
  // The usual learning-platform attributes: everything works.
  {
    const { context, page, problems } = await openPage(env.browser, env.A, { width: 1000, height: 800 });
    await page.goto(`${env.A}sandbox-same.html`);
    const frame = await labFrame(page);
    await page.waitForFunction(() => document.getElementById('lab').style.height !== '', null, { timeout: 10000 });
    const s = await api(page, 'set', { gamma0: 0.1 });
    assert.equal(s.type, 'wingbeat:state');
    const h = await heights(page, frame);
    assert.ok(Math.abs(h.iframe - h.content) <= 1 && h.scrollH <= h.clientH, JSON.stringify(h));
    // The FE wing needs the module worker: check it computes in this sandbox too.
    const fe = await api(page, 'set', { modes: 'fe' });
    assert.equal(fe.type, 'wingbeat:state', JSON.stringify(fe));
    assert.equal(fe.results.mode_set, 'fe');
    assert.equal(fe.results.error, null);
    assert.ok(
      Math.abs(fe.results.modes[0].freq_hz - 62.49) < 0.05,
      `the FE wing's f1 (${fe.results.modes[0].freq_hz} Hz)`,
    );
    report['allow-scripts allow-same-origin'] = { works: true, fe_f1_hz: fe.results.modes[0].freq_hz };
    assert.deepEqual(problems, []);
    await context.close();
  }
  // allow-scripts only: the frame's origin is opaque ("null"). From plain static hosting the
  // module scripts are refused (a module from another origin needs CORS): nothing starts.
  {
    const { context, page, problems } = await openPage(env.browser, env.A, { width: 1000, height: 800 });
    await page.goto(`${env.A}sandbox-scripts.html`);
    await page.waitForTimeout(3000);
    const frame = await (await page.$('iframe#lab')).contentFrame();
    const started = await frame.evaluate(() => !!customElements.get('wing-lab'));
    report['allow-scripts, no CORS'] = { started, problems: problems.slice(0, 5) };
    assert.equal(started, false, 'allow-scripts alone on plain static hosting: the lab does not start');
    await context.close();
  }
  // allow-scripts only with CORS on the lab's host: record what works.
  {
    const { context, page, problems } = await openPage(env.browser, env.A, { width: 1000, height: 800 });
    await page.goto(`${env.A}sandbox-scripts-cors.html`);
    const handle = await page.waitForSelector('iframe#lab');
    const frame = await handle.contentFrame();
    let rendered = true;
    try {
      await frame.waitForFunction(() => Number(document.getElementById('lab')?.dataset.renders || 0) >= 1, null, {
        timeout: 20000,
      });
    } catch {
      rendered = false;
    }
    const inside = await frame.evaluate(() => {
      const lab = document.getElementById('lab');
      const root = lab && (lab.shadowRoot || lab);
      const err = root && root.querySelector('.wl-error:not([hidden])');
      const notice = root && root.querySelector('.wl-notice:not([hidden])');
      return {
        origin: self.origin,
        defined: !!customElements.get('wing-lab'),
        renders: Number(lab?.dataset.renders || 0),
        error: err ? err.textContent : '',
        notice: notice ? notice.textContent : '',
      };
    });
    // The height message follows the first layout (a ResizeObserver in the frame): give it a moment.
    await page
      .waitForFunction(() => document.getElementById('lab').style.height !== '', null, { timeout: 5000 })
      .catch(() => {});
    const heightSet = await page.evaluate(() => document.getElementById('lab').style.height);
    let feReply = null;
    if (rendered) feReply = await api(page, 'set', { modes: 'fe' });
    report['allow-scripts, CORS'] = {
      rendered,
      inside,
      heightSet,
      fe:
        feReply &&
        (feReply.rejected
          ? feReply.rejected
          : {
              mode_set: feReply.results && feReply.results.mode_set,
              fe_f1_hz: feReply.results && feReply.results.modes[0].freq_hz,
            }),
      problems: problems.slice(0, 8),
    };
    assert.equal(inside.origin, 'null', 'the frame runs with an opaque origin');
    // With CORS the lab starts and talks (the helper accepts the opaque origin "null" from that
    // frame only: it checks the source window and the sandbox attribute), but the worker cannot
    // start from an opaque origin: the FE wing (and what needs it) falls back to the paper modes
    // with the reason shown, and the API reply carries that reason. docs/embedding.md says so.
    assert.ok(rendered && inside.defined && !inside.error, JSON.stringify(inside));
    assert.match(heightSet, /^\d+px$/);
    const feError = await frame.evaluate(() => {
      const lab = document.getElementById('lab');
      const e = (lab.shadowRoot || lab).querySelector('.wl-error:not([hidden])');
      return e ? e.textContent : '';
    });
    /** @type {any} */ (report['allow-scripts, CORS']).fe_error = feError;
    /** @type {any} */ (report['allow-scripts, CORS']).problems = problems.slice(0, 8);
    fs.writeFileSync(path.join(OUT, 'iframe-sandbox.json'), JSON.stringify(report, null, 1));
    assert.equal(feReply && feReply.type, 'wingbeat:state', JSON.stringify(feReply));
    assert.match(feError, /FE wing could not be computed.*[Ww]orker/);
    assert.equal(feReply.results.error, feError, 'the reply carries the reason the lab shows');
    assert.equal(feReply.results.modes[0].freq_hz, 62.5, "the paper table's modes meanwhile");
    assert.equal(feReply.results.mode_set, 'paper', 'mode_set says where the numbers come from');
    await context.close();
  }
  fs.writeFileSync(path.join(OUT, 'iframe-sandbox.json'), JSON.stringify(report, null, 1));
});

test("the lab's page under a strict CSP on its own host (no inline script or style needed): renders, sizes itself, answers", async () => {
  const { context, page, problems } = await openPage(
    env.browser,
    env.A,
    { width: 1000, height: 800 },
    { isolated: true },
  );
  const csp =
    "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; style-src 'self'; worker-src 'self' blob:; img-src 'self' data: blob:; connect-src 'self'";
  await context.route(`${env.B}index.html*`, async (route) => {
    const r = await route.fetch();
    await route.fulfill({ response: r, headers: { ...r.headers(), 'content-security-policy': csp } });
  });
  await context.addInitScript(() => {
    /** @type {any} */ (window).cspViolations = [];
    document.addEventListener('securitypolicyviolation', (e) =>
      /** @type {any} */ (window).cspViolations.push(`${e.violatedDirective} ${e.blockedURI}`),
    );
  });
  await page.goto(`${env.A}course.html`);
  const frame = await labFrame(page);
  await page.waitForFunction(() => document.getElementById('lab').style.height !== '', null, { timeout: 10000 });
  const fe = await api(page, 'set', { modes: 'fe' });
  assert.equal(fe.type, 'wingbeat:state', JSON.stringify(fe));
  assert.equal(fe.results.mode_set, 'fe');
  assert.equal(fe.results.error, null);
  const violations = await frame.evaluate(() => /** @type {any} */ (window).cspViolations);
  assert.deepEqual(violations, [], "no CSP violation inside the lab's frame");
  assert.deepEqual(problems, []);
  await context.close();
});

test('screenshots: the course page at 1280x800 and 390x844, the lab fits the column', async () => {
  for (const vp of [
    { width: 1280, height: 800 },
    { width: 390, height: 844 },
  ]) {
    const { context, page, problems } = await openPage(env.browser, env.A, vp);
    await page.goto(`${env.A}course.html`);
    const frame = await labFrame(page);
    await page.waitForFunction(() => document.getElementById('lab').style.height !== '', null, { timeout: 10000 });
    await page.waitForTimeout(500);
    const h = await heights(page, frame);
    assert.ok(Math.abs(h.iframe - h.content) <= 1, `${vp.width}: iframe ${h.iframe} = content ${h.content}`);
    assert.ok(h.scrollH <= h.clientH, `${vp.width}: no vertical inner scrollbar`);
    assert.ok(h.scrollW <= h.clientW, `${vp.width}: no horizontal inner scrollbar (${h.scrollW} <= ${h.clientW})`);
    const pageOverflow = await page.evaluate(
      () => document.documentElement.scrollWidth - document.documentElement.clientWidth,
    );
    assert.ok(pageOverflow <= 0, `${vp.width}: the course page does not scroll sideways`);
    await page.screenshot({ path: path.join(OUT, `iframe-course-${vp.width}x${vp.height}.png`), fullPage: true });
    // With the plots: uPlot sizes itself to the column; still no inner scrollbar.
    await api(page, 'set', { panels: 'controls,numbers,time,spectrum' });
    await page.waitForTimeout(1000);
    const hp = await heights(page, frame);
    assert.ok(
      Math.abs(hp.iframe - hp.content) <= 1 && hp.scrollH <= hp.clientH && hp.scrollW <= hp.clientW,
      `${vp.width} with plots: ${JSON.stringify(hp)}`,
    );
    await page.screenshot({ path: path.join(OUT, `iframe-course-plots-${vp.width}x${vp.height}.png`), fullPage: true });
    assert.deepEqual(problems, []);
    await context.close();
  }
});
