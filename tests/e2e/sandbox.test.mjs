// What the iframe `sandbox` advice in docs/embedding.md rests on, measured in headless Chromium
// with the course page and the lab on two loopback origins (and on one, for the warning):
//   - `allow-scripts allow-same-origin`: Chromium's console warning "can escape its sandboxing",
//     on which page it appears, and whether the frame can in fact reach the course page (only
//     when both are on the same origin);
//   - `allow-scripts` alone (lab host with CORS, else nothing starts): what the lab can still do —
//     compute and draw the paper modes, size itself, answer messages — and what it cannot:
//     localStorage, a service worker (offline copy), a worker (FE wing, studies).
// The measurements go to test-output/sandbox-report.json.
//   node --test --test-concurrency=1 tests/e2e/sandbox.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { setup, openPage, WITH_SERVICE_WORKER, OUT, ROOT } from './helpers.mjs';
import { startServer } from '../../scripts/serve.mjs';

const WWW = path.join(ROOT, process.env.LAB_ROOT || 'www');
const WARNING = /can escape its sandboxing/;
let env;
let dir;
/** @type {{ server: import('node:http').Server, url: string }[]} */
const servers = [];
/** @type {Record<string, unknown>} */
const report = {};
before(async () => {
  env = await setup();
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'wingbeat-sandbox-'));
});
after(async () => {
  fs.mkdirSync(OUT, { recursive: true });
  fs.writeFileSync(path.join(OUT, 'sandbox-report.json'), JSON.stringify(report, null, 1));
  for (const s of servers) s.server.close();
  if (env) await env.close();
  if (dir) fs.rmSync(dir, { recursive: true, force: true });
});

const page = (
  src,
  sandbox,
) => `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>course</title></head>
<body><iframe id="lab" data-wingbeat title="wingbeat lab" src="${src}" sandbox="${sandbox}" style="width:100%;height:600px;border:0"></iframe></body></html>`;

/** What a script in the lab's frame can reach: the course page's document, storage, workers. */
async function probe(frame) {
  return frame.evaluate(async () => {
    const r = { origin: self.origin };
    try {
      r.parentDocument = !!window.parent.document.querySelector('iframe#lab');
    } catch (e) {
      r.parentDocument = `refused: ${e.name}`;
    }
    try {
      localStorage.setItem('wingbeat-probe', '1');
      r.localStorage = localStorage.getItem('wingbeat-probe') === '1';
      localStorage.removeItem('wingbeat-probe');
    } catch (e) {
      r.localStorage = `refused: ${e.name}`;
    }
    try {
      const reg = await navigator.serviceWorker.getRegistrations();
      r.serviceWorker = reg.length > 0;
    } catch (e) {
      r.serviceWorker = `refused: ${e.name}`;
    }
    return r;
  });
}

test('allow-scripts allow-same-origin: Chromium warns, and the frame can reach the course page, only when both are on one origin', async () => {
  const lab = await startServer(WWW, 0);
  const course = await startServer(dir, 0);
  servers.push(lab, course);
  fs.writeFileSync(
    path.join(dir, 'two-origins.html'),
    page(`${lab.url}index.html?embed=1&panels=controls,numbers`, 'allow-scripts allow-same-origin'),
  );
  // The lab's own folder as the course page's host: one origin (a copy of the page inside www/
  // would be a file in the repository; a second server on the same folder is another origin).
  const one = `${lab.url}index.html?embed=1&panels=controls,numbers`;
  for (const [name, url] of [
    ['two origins', `${course.url}two-origins.html`],
    ['one origin', null],
  ]) {
    const { context, page: p } = await openPage(env.browser, lab.url, undefined, WITH_SERVICE_WORKER);
    const warnings = [];
    p.on('console', (m) => {
      if (WARNING.test(m.text())) warnings.push(`${m.type()}: ${m.text()}`);
    });
    if (url) await p.goto(url);
    else {
      await p.goto(`${lab.url}embed-demo.html`);
      await p.evaluate(
        ([src]) => {
          document.body.innerHTML = '';
          const f = document.createElement('iframe');
          f.id = 'lab';
          f.title = 'wingbeat lab';
          f.setAttribute('sandbox', 'allow-scripts allow-same-origin');
          f.src = src;
          document.body.append(f);
        },
        [one],
      );
    }
    const frame = await (await p.waitForSelector('iframe#lab')).contentFrame();
    await frame.waitForFunction(() => Number(document.querySelector('wing-lab')?.dataset.renders || 0) >= 1, null, {
      timeout: 30000,
    });
    const r = await probe(frame);
    report[`allow-scripts allow-same-origin, ${name}`] = { warnings, ...r };
    if (name === 'one origin') {
      assert.equal(
        r.parentDocument,
        true,
        'same origin: the frame reaches the course page (it could remove its own sandbox)',
      );
      assert.equal(warnings.length, 1, 'same origin: Chromium warns that the frame can escape its sandbox');
    } else {
      assert.match(String(r.parentDocument), /^refused/, 'two origins: the course page is out of reach');
      assert.deepEqual(warnings, [], 'two origins: no warning (Chromium 156)');
    }
    assert.equal(r.localStorage, true);
    await context.close();
  }
});

test('allow-scripts alone (lab host with CORS): the paper lab runs; storage, service worker and workers do not', async () => {
  const lab = await startServer(WWW, 0, { cors: true });
  const course = await startServer(dir, 0);
  servers.push(lab, course);
  fs.writeFileSync(
    path.join(dir, 'scripts-only.html'),
    page(`${lab.url}index.html?embed=1&panels=controls,numbers,time`, 'allow-scripts'),
  );
  const { context, page: p } = await openPage(env.browser, course.url, undefined, WITH_SERVICE_WORKER);
  const warnings = [];
  p.on('console', (m) => {
    if (WARNING.test(m.text())) warnings.push(m.text());
  });
  await p.goto(`${course.url}scripts-only.html`);
  const frame = await (await p.waitForSelector('iframe#lab')).contentFrame();
  await frame.waitForFunction(() => Number(document.querySelector('wing-lab')?.dataset.renders || 0) >= 1, null, {
    timeout: 30000,
  });
  const r = await probe(frame);
  const lab2 = await frame.evaluate(() => {
    const l = document.querySelector('wing-lab');
    return { modes: l.analysis.sim.modes.length, feff: l.analysis.sim.modes[0].floquet.effective_freq_hz };
  });
  // The FE wing needs a worker: from an opaque origin the lab shows why and keeps the paper modes.
  await frame.evaluate(() => document.querySelector('wing-lab').store.set({ modes: 'fe' }));
  await frame.waitForFunction(
    () => {
      const l = document.querySelector('wing-lab');
      const e = l.shadowRoot.querySelector('.wl-error:not([hidden])');
      return e && /FE wing could not be computed/.test(e.textContent);
    },
    null,
    { timeout: 30000 },
  );
  const feError = await frame.evaluate(
    () => document.querySelector('wing-lab').shadowRoot.querySelector('.wl-error:not([hidden])').textContent,
  );
  report['allow-scripts only (CORS on the lab host)'] = { warnings, ...r, paper: lab2, feError };
  assert.equal(r.origin, 'null');
  assert.deepEqual(warnings, [], 'no escape warning without allow-same-origin');
  assert.match(String(r.localStorage), /^refused/);
  assert.match(String(r.serviceWorker), /^refused/);
  assert.match(String(r.parentDocument), /^refused/);
  assert.equal(lab2.modes, 2);
  assert.ok(lab2.feff > 0);
  assert.match(feError, /[Ww]orker/);
  await context.close();
});
