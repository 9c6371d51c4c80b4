// Shared set-up for the browser end-to-end tests and the perf script: a static server on
// 127.0.0.1 and Debian's headless Chromium driven by playwright-core (never a downloaded browser).
//
// Reaching inside <wing-lab>. The element may render into an open shadow root (lab.shadowRoot)
// or into light DOM; the tests work with both:
//  * Playwright's own selectors (page.click, page.fill, page.locator, page.$eval, page.textContent,
//    page.waitForSelector, ...) pierce open shadow roots: 'wing-lab .wl-x' works as it is.
//  * Code that runs IN the page (page.evaluate, page.waitForFunction) must not use
//    document.querySelector / getElementById / document.activeElement for the lab's insides.
//    openPage() installs `window.__wl` in every frame (labHelpers() does it for other contexts):
//      __wl.lab(host = 'wing-lab')  the element (host: a CSS selector or the element itself)
//      __wl.root(host)              its shadow root if it has one, else the element
//      __wl.q(sel, host)            first match of `sel` inside the lab (sel WITHOUT 'wing-lab ')
//      __wl.qa(sel, host)           every match inside the lab, as an array
//      __wl.byId(id, host)          the element with that id inside the lab
//      __wl.active()                the focused element, followed down through open shadow roots
//      __wl.axe(sel, host)          an axe-core context item for `sel` inside the lab
//    The element's own properties and attributes (lab.store, lab.analysis, lab.wing3d,
//    lab.dataset.renders, ...) are on the host: __wl.lab().store.
import { chromium } from 'playwright-core';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { startServer } from '../../scripts/serve.mjs';

export const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
export const OUT = path.join(ROOT, 'test-output');
export const CHROMIUM = process.env.CHROMIUM_PATH || '/usr/bin/chromium';
/** openPage's viewport unless a test gives one. */
const DEFAULT_VIEWPORT = Object.freeze({ width: 1280, height: 720 });

export const ARGS = [
  '--no-sandbox',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--disable-quic',
];

/**
 * The browser of each test file's setup() keeps one cached browsing profile (a persistent
 * context in a temporary folder) that openPage() opens its pages in, unless a test asks for an
 * isolated one. A lab page opened again in the same profile revalidates its files with 304s and
 * takes V8's cached code for the wasm modules and scripts instead of compiling them again (an
 * off-the-record context, Playwright's newContext(), keeps no code cache): 4.3–4.9 CPU-seconds
 * per default lab page instead of 6.7–6.8 on this 2-core machine (2026-12-03, six loads each way),
 * what a student sees on a second visit. The first visit, the offline copy and the service worker
 * are tested in isolated contexts (first_load, offline, precache, sandbox).
 * @type {WeakMap<import('playwright-core').Browser, import('playwright-core').BrowserContext>}
 */
const SHARED = new WeakMap();

/**
 * Starts a static server on `root` and Debian's headless Chromium. `{ cached: false }` launches a
 * plain browser (every openPage then gets a fresh off-the-record context); the perf scripts use
 * it so their numbers stay cold-cache ones.
 * @param {string} [root]
 * @param {{ cached?: boolean }} [opts]
 */
export async function setup(root = process.env.LAB_ROOT || 'www', { cached = true } = {}) {
  const dir = path.join(ROOT, root);
  if (!fs.existsSync(path.join(dir, 'pkg', 'wingbeat.js'))) {
    throw new Error(`${root}/pkg is missing: run scripts/build-web.sh ${root} first (npm test does)`);
  }
  fs.mkdirSync(OUT, { recursive: true });
  const { server, url } = await startServer(dir, 0);
  let browser;
  let profile = null;
  if (cached) {
    profile = fs.mkdtempSync(path.join(os.tmpdir(), 'wingbeat-e2e-profile-'));
    const shared = await chromium.launchPersistentContext(profile, {
      executablePath: CHROMIUM,
      args: ARGS,
      headless: true,
      viewport: DEFAULT_VIEWPORT,
      acceptDownloads: true,
      serviceWorkers: 'block',
    });
    await labHelpers(shared);
    browser = /** @type {import('playwright-core').Browser} */ (shared.browser());
    SHARED.set(browser, shared);
  } else {
    browser = await chromium.launch({ executablePath: CHROMIUM, args: ARGS, headless: true });
  }
  return {
    server,
    url,
    browser,
    close: async () => {
      const shared = SHARED.get(browser);
      if (shared) await shared.close();
      await browser.close();
      server.close();
      if (profile) fs.rmSync(profile, { recursive: true, force: true });
    },
  };
}

/** Defines window.__wl (see the top of this file) in every page and frame of a browser context. */
export async function labHelpers(context) {
  await context.addInitScript(() => {
    const lab = (host = 'wing-lab') => (typeof host === 'string' ? document.querySelector(host) : host);
    const root = (host) => {
      const l = lab(host);
      return l ? l.shadowRoot || l : null;
    };
    /** @type {any} */ (window).__wl = {
      lab,
      root,
      q: (sel, host) => root(host)?.querySelector(sel) ?? null,
      qa: (sel, host) => [...(root(host)?.querySelectorAll(sel) ?? [])],
      byId: (id, host) => root(host)?.querySelector(`[id="${CSS.escape(id)}"]`) ?? null,
      active: () => {
        let a = document.activeElement;
        while (a && a.shadowRoot && a.shadowRoot.activeElement) a = a.shadowRoot.activeElement;
        return a;
      },
      axe: (sel, host = 'wing-lab') =>
        root(host) instanceof ShadowRoot ? { fromShadowDom: [host, sel] } : `${host} ${sel}`,
    };
  });
}

/** openPage's options for a test about the service worker, or a measurement of a real visit. */
export const WITH_SERVICE_WORKER = Object.freeze({ serviceWorkers: /** @type {'allow'} */ ('allow') });

/**
 * The part of a BrowserContext a test gets from openPage() in the shared profile: its pages (the
 * first, any from newPage() and their pop-ups) and close(), which closes them. What would change
 * the profile for the tests after it (routes, init scripts, listeners, going offline) needs an
 * isolated context: openPage(browser, url, viewport, { isolated: true }).
 * @param {import('playwright-core').BrowserContext} shared
 * @param {{ width: number, height: number }} viewport
 */
function sharedPart(shared, viewport) {
  /** @type {Set<import('playwright-core').Page>} */
  const pages = new Set();
  const track = (/** @type {import('playwright-core').Page} */ p) => {
    pages.add(p);
    p.on('popup', track);
    p.on('close', () => pages.delete(p));
  };
  const refuse = (what) => () => {
    throw new Error(`openPage: ${what} would change the shared browser profile; open the page with { isolated: true }`);
  };
  return {
    async newPage() {
      const p = await shared.newPage();
      await p.setViewportSize(viewport);
      track(p);
      return p;
    },
    async close() {
      await Promise.all([...pages].map((p) => p.close().catch(() => {})));
    },
    route: refuse('context.route'),
    addInitScript: refuse('context.addInitScript'),
    on: refuse('context.on'),
    setOffline: refuse('context.setOffline'),
  };
}

/**
 * A page that records console errors, page errors, failed and off-host requests and dialogs.
 * The lab's service worker (the offline copy, www/sw.js) is blocked unless a test asks for it
 * with `WITH_SERVICE_WORKER` (`{ serviceWorkers: 'allow' }`): on every first visit it downloads the whole lab (≈ 6 MB) into
 * the cache, which is what first_load, offline, precache and sandbox test and ≈ 13 % of the
 * browser's CPU in a test file that opens many fresh pages (2026-12-03, experiments.test.mjs).
 * The page opens in the browser's shared, cached profile (setup()) unless the test asks for an
 * isolated context (`{ isolated: true }`, implied by allowing the service worker) or the browser
 * has none; either way `context.close()` ends what the test opened.
 * @param {import('playwright-core').Browser} browser
 * @param {string} _url
 * @param {{ width: number, height: number }} [viewport]
 * @param {{ serviceWorkers?: 'allow' | 'block', isolated?: boolean }} [opts]
 */
export async function openPage(browser, _url, viewport = DEFAULT_VIEWPORT, opts = {}) {
  const shared = SHARED.get(browser);
  /** @type {any} */
  let context;
  if (shared && !opts.isolated && (opts.serviceWorkers ?? 'block') === 'block') {
    context = sharedPart(shared, viewport);
  } else {
    context = await browser.newContext({
      viewport,
      acceptDownloads: true,
      serviceWorkers: opts.serviceWorkers ?? 'block',
    });
    await labHelpers(context);
  }
  const page = await context.newPage();
  const problems = [];
  page.on('console', (m) => {
    if (m.type() === 'error') problems.push(`console: ${m.text()}`);
  });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  page.on('dialog', (d) => {
    problems.push(`dialog: ${d.message()}`);
    d.dismiss();
  });
  // A request the browser cancels because its page or worker went away (a navigation, a closed
  // context) is not a fault; any other failure is. (A missing file is a 404 response, not a
  // failed request.)
  page.on('requestfailed', (r) => {
    const why = r.failure()?.errorText ?? '';
    if (why !== 'net::ERR_ABORTED') problems.push(`requestfailed: ${r.url()} (${why})`);
  });
  page.on('request', (r) => {
    if (!r.url().startsWith('http://127.0.0.1') && !r.url().startsWith('blob:') && !r.url().startsWith('data:'))
      problems.push(`external request: ${r.url()}`);
  });
  return { context, page, problems };
}

/**
 * Waits until the lab `sel` has rendered at least `n` times: up to 60 s. (ownwing.test.mjs's
 * 390×844 test, which waits for a 6-FE-mode result under edited measured kinematics, passes in
 * 12.5 s on this 2-core machine alone and timed out at the former 20 s while two builds ran beside
 * it, 2026-12-03; a passing test never waits longer than its render.)
 */
export async function waitRenders(page, n = 1, sel = 'wing-lab') {
  await page.waitForFunction(([s, k]) => Number(document.querySelector(s)?.dataset.renders || 0) >= k, [sel, n], {
    timeout: 60000,
  });
}

export async function renders(page, sel = 'wing-lab') {
  return page.evaluate((s) => Number(document.querySelector(s).dataset.renders || 0), sel);
}

/**
 * Counts distinct colours, non-white pixels and foreground pixels (unlike the most common
 * colour) of a PNG screenshot by decoding it in the page (no image library on the node side).
 */
export async function pngStats(page, buf) {
  const b64 = buf.toString('base64');
  return page.evaluate(async (data) => {
    const img = new Image();
    img.src = `data:image/png;base64,${data}`;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width;
    c.height = img.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    const colours = new Set();
    const count = new Map();
    let nonWhite = 0;
    for (let i = 0; i < d.length; i += 4) {
      const r = d[i],
        g = d[i + 1],
        b = d[i + 2];
      if (r < 245 || g < 245 || b < 245) nonWhite++;
      const k = (r << 16) | (g << 8) | b;
      if (colours.size < 5000) colours.add(k);
      count.set(k, (count.get(k) || 0) + 1);
    }
    // Foreground: pixels clearly unlike the most common colour (the background).
    const bg = [...count.entries()].sort((x, y) => y[1] - x[1])[0][0];
    let fg = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (Math.abs(d[i] - (bg >> 16)) + Math.abs(d[i + 1] - ((bg >> 8) & 255)) + Math.abs(d[i + 2] - (bg & 255)) > 30)
        fg++;
    }
    const n = c.width * c.height;
    return {
      width: c.width,
      height: c.height,
      nonWhite,
      fraction: nonWhite / n,
      colours: colours.size,
      foreground: fg / n,
    };
  }, b64);
}

/**
 * How two PNG screenshots of the same size differ, decoded in the page: the mean absolute
 * difference per channel (0–255) and the share of pixels differing by more than `tol` in summed
 * RGB, at the best of the shifts of up to `shift` px each way (an element screenshot can land a
 * pixel apart from one page to another: its box sits at a fraction of a pixel). Compared over
 * the interior that every shift covers. { width, height, mean, share, dx, dy } (share 1 and mean
 * 255 when the sizes differ).
 */
export async function pngDiff(page, a, b, { tol = 48, shift = 0 } = {}) {
  return page.evaluate(
    async ([x, y, tol, shift]) => {
      const pixels = async (data) => {
        const img = new Image();
        img.src = `data:image/png;base64,${data}`;
        await img.decode();
        const c = document.createElement('canvas');
        c.width = img.width;
        c.height = img.height;
        const ctx = c.getContext('2d');
        ctx.drawImage(img, 0, 0);
        return { w: c.width, h: c.height, d: ctx.getImageData(0, 0, c.width, c.height).data };
      };
      const [p, q] = [await pixels(x), await pixels(y)];
      if (p.w !== q.w || p.h !== q.h) return { width: p.w, height: p.h, mean: 255, share: 1, dx: 0, dy: 0 };
      let best = null;
      for (let dy = -shift; dy <= shift; dy++)
        for (let dx = -shift; dx <= shift; dx++) {
          let sum = 0,
            off = 0,
            n = 0;
          for (let j = shift; j < p.h - shift; j++)
            for (let i = shift; i < p.w - shift; i++) {
              const u = 4 * ((j + dy) * p.w + i + dx),
                v = 4 * (j * p.w + i);
              const e =
                Math.abs(p.d[u] - q.d[v]) + Math.abs(p.d[u + 1] - q.d[v + 1]) + Math.abs(p.d[u + 2] - q.d[v + 2]);
              sum += e;
              if (e > tol) off++;
              n++;
            }
          const r = { width: p.w, height: p.h, mean: sum / (3 * n), share: off / n, dx, dy };
          if (!best || r.mean < best.mean) best = r;
        }
      return best;
    },
    [a.toString('base64'), b.toString('base64'), tol, shift],
  );
}

/**
 * Bounding box of the foreground (pixels unlike the most common colour by more than `tol` in
 * summed RGB) of a PNG, decoded in the page: { x0, y0, x1, y1, width, height, share }.
 */
export async function pngForeground(page, buf, tol = 30, inset = 0) {
  const b64 = buf.toString('base64');
  return page.evaluate(
    async ([data, tol, inset]) => {
      const img = new Image();
      img.src = `data:image/png;base64,${data}`;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.width;
      c.height = img.height;
      const ctx = c.getContext('2d');
      ctx.drawImage(img, 0, 0);
      const d = ctx.getImageData(0, 0, c.width, c.height).data;
      const count = new Map();
      for (let i = 0; i < d.length; i += 4) {
        const k = (d[i] << 16) | (d[i + 1] << 8) | d[i + 2];
        count.set(k, (count.get(k) || 0) + 1);
      }
      const bg = [...count.entries()].sort((x, y) => y[1] - x[1])[0][0];
      let x0 = Infinity,
        y0 = Infinity,
        x1 = -1,
        y1 = -1,
        fg = 0;
      for (let y = inset; y < c.height - inset; y++) {
        for (let x = inset; x < c.width - inset; x++) {
          const i = 4 * (y * c.width + x);
          if (
            Math.abs(d[i] - (bg >> 16)) + Math.abs(d[i + 1] - ((bg >> 8) & 255)) + Math.abs(d[i + 2] - (bg & 255)) >
            tol
          ) {
            fg++;
            if (x < x0) x0 = x;
            if (x > x1) x1 = x;
            if (y < y0) y0 = y;
            if (y > y1) y1 = y;
          }
        }
      }
      return { x0, y0, x1, y1, width: c.width, height: c.height, share: fg / (c.width * c.height) };
    },
    [b64, tol, inset],
  );
}

/** Whether every colour (hex #rrggbb) occurs exactly in a region (fractions of the image) of a PNG. */
export async function pngHasColours(page, buf, colours, region = [0, 0, 1, 1]) {
  const b64 = buf.toString('base64');
  return page.evaluate(
    async ([data, colours, region]) => {
      const img = new Image();
      img.src = `data:image/png;base64,${data}`;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.width;
      c.height = img.height;
      const ctx = c.getContext('2d');
      ctx.drawImage(img, 0, 0);
      const [fx0, fy0, fx1, fy1] = region;
      const x0 = Math.floor(fx0 * c.width),
        y0 = Math.floor(fy0 * c.height);
      const d = ctx.getImageData(x0, y0, Math.ceil((fx1 - fx0) * c.width), Math.ceil((fy1 - fy0) * c.height)).data;
      const seen = new Set();
      for (let i = 0; i < d.length; i += 4)
        seen.add(`#${[d[i], d[i + 1], d[i + 2]].map((v) => v.toString(16).padStart(2, '0')).join('')}`);
      return Object.fromEntries(colours.map((col) => [col, seen.has(col.toLowerCase())]));
    },
    [b64, colours, region],
  );
}

/** A cheap fingerprint of what the lab `sel`'s plots show: the sum of |y| of every series, per plot. */
export const plotPrint = (page, sel = 'wing-lab') =>
  page.evaluate((s) => {
    const lab = document.querySelector(s);
    const out = {};
    for (const [name, u] of Object.entries(lab.plots)) {
      let sum = 0;
      for (const series of u.data.slice(1)) for (const v of series) if (v != null) sum += Math.abs(v);
      out[name] = sum;
    }
    return out;
  }, sel);

/** Waits until the 3-D view is ready and has drawn at least one frame of the wing. */
export async function waitWing3d(page, timeout = 60000) {
  await page.waitForFunction(
    () => {
      const b = __wl.q('[data-wing3d]');
      return b && b.dataset.state === 'ready' && Number(b.dataset.frames || 0) > 0;
    },
    null,
    { timeout },
  );
}
