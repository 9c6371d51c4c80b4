// Accessibility scan with axe-core (npm devDependency, injected from node_modules: no CDN) of
// the lab page — with a guided experiment open and the resonance map drawn, so their content is
// scanned too — and of the embedding demo (both <wing-lab> elements and the iframe), at a
// desktop and a phone viewport. Every axe rule that is on by default (WCAG 2.0/2.1/2.2 A and AA
// plus best practices), and target-size (WCAG 2.2 AA 2.5.8, off by default), must report no
// violations.
// Run after scripts/build-web.sh www:  node --test --test-concurrency=1 tests/e2e/a11y.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { setup, openPage, waitRenders, OUT } from './helpers.mjs';
import { experimentQuery } from '../../www/experiments.js';

const require = createRequire(import.meta.url);
const AXE = require.resolve('axe-core/axe.min.js');

let env;
before(async () => {
  env = await setup();
});
after(async () => {
  if (env) await env.close();
});

/** Injects axe into every frame and runs it on the top document (iframes included). */
async function scan(page) {
  for (const f of page.frames()) await f.addScriptTag({ path: AXE });
  return page.evaluate(async () => {
    // target-size (WCAG 2.2 AA, 24×24 CSS px) is off by default in axe 4.14: turn it on.
    const r = await window.axe.run(document, {
      resultTypes: ['violations'],
      iframes: true,
      rules: { 'target-size': { enabled: true } },
    });
    return r.violations.map((v) => ({
      rule: v.id,
      impact: v.impact,
      help: v.help,
      nodes: v.nodes.map((n) => ({ target: n.target.join(' '), html: n.html.slice(0, 160), why: n.failureSummary })),
    }));
  });
}

const report = (vs) =>
  vs
    .map(
      (v) =>
        `${v.rule} (${v.impact}): ${v.help}\n${v.nodes.map((n) => `   ${n.target}  ${n.html}\n     ${n.why}`).join('\n')}`,
    )
    .join('\n');

function save(name, vs) {
  fs.mkdirSync(OUT, { recursive: true });
  fs.writeFileSync(path.join(OUT, name), JSON.stringify(vs, null, 2));
}

for (const viewport of [
  { width: 1280, height: 800 },
  { width: 390, height: 844 },
]) {
  test(`axe: the lab page has no violations (${viewport.width}×${viewport.height}, experiment + resonance map open)`, async () => {
    const { page, problems, context } = await openPage(env.browser, env.url, viewport);
    // The full page: every panel scanned at once (tests/e2e/screens.test.mjs scans each screen).
    await page.goto(`${env.url}?${experimentQuery('beat')}&screen=full`);
    await waitRenders(page, 1);
    await page.waitForFunction(() => __wl.q('[data-panel="experiments"] [data-check]'), null, { timeout: 30000 });
    const inner = '[data-study="resonance"]';
    const box = `wing-lab ${inner}`;
    await page.fill(`${box} input[aria-label^="points"]`, '56');
    await page.click(`${box} [data-run="resonance"]`);
    await page.waitForFunction((s) => Number(__wl.q(s).dataset.done || 0) >= 1, inner, { timeout: 60000 });
    const vs = await scan(page);
    save(`axe-lab-${viewport.width}.json`, vs);
    assert.deepEqual(
      vs.map((v) => v.rule),
      [],
      report(vs),
    );
    assert.deepEqual(problems, []);
    await context.close();
  });
}

test('axe: the embedding demo has no violations (two elements and the iframe)', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  await page.goto(`${env.url}embed-demo.html`);
  await waitRenders(page, 1, '#lab-a');
  await waitRenders(page, 1, '#lab-b');
  await page.locator('iframe').scrollIntoViewIfNeeded();
  const frame = page.frames().find((f) => f !== page.mainFrame());
  await frame.waitForFunction(() => Number(document.querySelector('wing-lab')?.dataset.renders || 0) >= 1, null, {
    timeout: 30000,
  });
  const vs = await scan(page);
  save('axe-embed.json', vs);
  assert.deepEqual(
    vs.map((v) => v.rule),
    [],
    report(vs),
  );
  assert.deepEqual(problems, []);
  await context.close();
});
