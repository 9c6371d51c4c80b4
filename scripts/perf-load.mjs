#!/usr/bin/env node
// The lab's first load as a pupil on a school link sees it (issue 25): a cold browser context
// (no HTTP cache, no service worker) at 1280×800 opens the lab from `npm start`'s server, under
// Chromium's network emulation (DevTools protocol Network.emulateNetworkConditions) or none, and
// we record
//   * first_plot_ms: navigation → the first complete render (the beat's numbers and the plots
//     drawn: the lab's `lastTiming.end`, on the page's clock from navigation start), once the
//     lab is visible (its stylesheets applied; the first animation frame that sees both);
//   * wing3d_ms: navigation → the 3-D view's first drawn frame (data-frames > 0);
//   * bytes_first_plot: bytes over the wire (Playwright's encoded body + headers sizes, page and
//     its workers) of the requests that finished before the first plot was seen, and their count;
//   * bytes_total: the same for everything loaded by the time the 3-D wing is drawn.
// Medians over RUNS cold loads per profile. Used by scripts/perf.mjs (its `load` section) and
// runnable alone:   node scripts/perf-load.mjs [--runs 5]   (after scripts/build-web.sh www)
// Limits, said with the numbers: emulation applies to the page's own requests; a worker's few
// module imports are not throttled (the workers get the compiled wasm from the page, so no
// module is downloaded twice).
import { setup, labHelpers } from '../tests/e2e/helpers.mjs';

/** The network profiles: none (localhost) and a school link (10 Mbit/s down, 5 up, 40 ms RTT). */
export const PROFILES = Object.freeze([
  Object.freeze({ name: 'localhost', conditions: null }),
  Object.freeze({
    name: '10 Mbit/s, 40 ms RTT',
    conditions: Object.freeze({
      offline: false,
      latency: 40,
      downloadThroughput: 10e6 / 8,
      uploadThroughput: 5e6 / 8,
    }),
  }),
]);

const median = (/** @type {number[]} */ xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length ? s[Math.floor(s.length / 2)] : NaN;
};

/**
 * One cold load of `url` under `conditions` (null: no emulation).
 * @param {import('playwright-core').Browser} browser
 * @param {string} url
 * @param {object | null} conditions
 */
export async function coldLoad(browser, url, conditions) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, serviceWorkers: 'block' });
  await labHelpers(context);
  const page = await context.newPage();
  const cdp = await context.newCDPSession(page);
  await cdp.send('Network.enable');
  await cdp.send('Network.setCacheDisabled', { cacheDisabled: true });
  if (conditions) await cdp.send('Network.emulateNetworkConditions', conditions);
  /** @type {{ at: number, req: import('playwright-core').Request }[]} */
  const finished = [];
  context.on('requestfinished', (req) => finished.push({ at: Date.now(), req }));
  /** @type {number | null} wall time (node) when the first plot was seen */
  let firstAt = null;
  await page.goto(url, { waitUntil: 'commit' });
  // The first plot counts once it can be seen: rendered, and the lab's root visible (it stays
  // hidden until its stylesheets apply). The later of the render's end and the first animation
  // frame that finds both.
  const firstPlot = await page.waitForFunction(
    () => {
      const lab = /** @type {any} */ (document.querySelector('wing-lab'));
      const root = lab && lab.shadowRoot && lab.shadowRoot.querySelector('.wl-root');
      if (!lab || !lab.lastTiming || !root || getComputedStyle(root).visibility !== 'visible') return null;
      return Math.max(lab.lastTiming.end, performance.now());
    },
    null,
    { timeout: 120000, polling: 'raf' },
  );
  firstAt = Date.now();
  const first_plot_ms = /** @type {number} */ (await firstPlot.jsonValue());
  const wing = await page.waitForFunction(
    () => {
      const b = /** @type {any} */ (window).__wl.q('[data-wing3d]');
      if (!b) return null;
      if (b.dataset.state === 'unavailable') return -1;
      return b.dataset.state === 'ready' && Number(b.dataset.frames || 0) > 0 ? performance.now() : null;
    },
    null,
    { timeout: 120000, polling: 'raf' },
  );
  const wing3d_ms = /** @type {number} */ (await wing.jsonValue());
  const doneAt = Date.now();
  let bytes_first_plot = 0,
    requests_first_plot = 0,
    bytes_total = 0,
    requests_total = 0;
  for (const { at, req } of finished) {
    if (at > doneAt) continue;
    const s = await req.sizes().catch(() => null);
    const n = s ? s.responseBodySize + s.responseHeadersSize : 0;
    bytes_total += n;
    requests_total++;
    if (firstAt !== null && at <= firstAt) {
      bytes_first_plot += n;
      requests_first_plot++;
    }
  }
  await context.close();
  return { first_plot_ms, wing3d_ms, bytes_first_plot, requests_first_plot, bytes_total, requests_total };
}

/**
 * `runs` cold loads per profile; medians (and every run) per profile.
 * @param {import('playwright-core').Browser} browser
 * @param {string} url
 * @param {number} runs
 */
export async function measureLoad(browser, url, runs = 5) {
  const out = [];
  for (const p of PROFILES) {
    const all = [];
    for (let i = 0; i < runs; i++) all.push(await coldLoad(browser, url, p.conditions));
    /** @type {Record<string, number>} */
    const med = {};
    for (const k of Object.keys(all[0])) med[k] = Math.round(median(all.map((r) => /** @type {any} */ (r)[k])));
    out.push({ profile: p.name, median: med, runs: all });
  }
  return out;
}

/** The load table (markdown) of measureLoad's result. */
export function loadTable(/** @type {Awaited<ReturnType<typeof measureLoad>>} */ rows) {
  const lines = [
    '| network (cold cache, 1280×800) | first plot (ms) | 3-D wing drawn (ms) | bytes before the first plot (requests) | bytes by the 3-D wing (requests) |',
    '|---|---|---|---|---|',
  ];
  for (const r of rows) {
    const m = r.median;
    lines.push(
      `| ${r.profile} | ${m.first_plot_ms} | ${m.wing3d_ms} | ${(m.bytes_first_plot / 1e3).toFixed(0)} kB (${m.requests_first_plot}) | ${(m.bytes_total / 1e3).toFixed(0)} kB (${m.requests_total}) |`,
    );
  }
  return lines.join('\n');
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const i = process.argv.indexOf('--runs');
  const runs = i > 0 ? Math.max(1, Number(process.argv[i + 1]) || 5) : 5;
  const env = await setup(undefined, { cached: false });
  try {
    const rows = await measureLoad(env.browser, env.url, runs);
    console.log(
      JSON.stringify(
        rows.map((r) => ({ profile: r.profile, median: r.median })),
        null,
        1,
      ),
    );
    console.log(loadTable(rows));
  } finally {
    await env.close();
  }
}
