// @ts-check
// The lab's service worker (registered by www/offline.js, never by the element): keeps a copy of
// the site's OWN files so that after one visit the lab works with the network off.
//   - install: precaches the files the lab needs, including those not fetched yet (the worker,
//     the wasm module, the views): the files listed in precache.json, the manifest that
//     scripts/build-web.sh writes from the built folder itself (every file it holds, less this
//     worker, the manifest and TypeScript declarations), so the list is the real files and never
//     a guess from the sources' text. A file added after the last build is cached when a page
//     first fetches it (network first, below).
//   - fetch: network first for same-origin GETs inside this scope (development never sees stale
//     files; each answer refreshes the copy), the copy when the network fails or has not answered
//     in NET_TIMEOUT_MS; cross-origin requests, other methods and range requests are left alone
//     (never cached).
//   - activate: deletes this scope's caches of other builds, then takes control of open pages.
//   - message `{ type: 'wingbeat:forget' }` (offline.js, on opt-out): from then on this worker
//     never opens its cache again, deletes it, and answers on the message's port. Without it a
//     fetch of a page it still controls could reopen (and so recreate) the cache just after the
//     page deleted it: caches.has() and caches.open() are two steps.
// Cache name: `wingbeat:<scope>:<BUILD>`; `npm run build` (scripts/build-web.sh dist) writes the
// build stamp into BUILD, so a new download replaces the old copy. A classic script (not a
// module) so that every browser with service workers can run it. docs/embedding.md, `offline`.
// Typed against the DOM library (tsconfig.json); the few service-worker types are declared here.

/**
 * @typedef {Event & { waitUntil(p: Promise<unknown>): void }} ExtendableEvt
 * @typedef {ExtendableEvt & { request: Request, respondWith(r: Promise<Response> | Response): void }} FetchEvt
 * @typedef {{
 *   addEventListener(type: 'install' | 'activate' | 'message', fn: (e: ExtendableEvt) => void): void,
 *   addEventListener(type: 'fetch', fn: (e: FetchEvt) => void): void,
 *   skipWaiting(): Promise<void>, clients: { claim(): Promise<void> }, registration: { scope: string },
 *   location: Location, caches: CacheStorage, fetch: typeof fetch,
 * }} SwScope
 */

(() => {
  /** Replaced by scripts/build-web.sh dist with the build's stamp. */
  const BUILD = 'dev';
  /** How long a request waits for the network before the copy answers (when there is one). */
  const NET_TIMEOUT_MS = 4000;
  /** Most files precached (a guard against a runaway manifest). */
  const MAX_FILES = 300;
  /** The build's file list (scripts/build-web.sh): { version: 1, files: [path relative to the scope] }. */
  const MANIFEST = 'precache.json';
  const sw = /** @type {SwScope} */ (/** @type {unknown} */ (self));
  const SCOPE = sw.registration.scope;
  const CACHE = `wingbeat:${SCOPE}:${BUILD}`;
  /** Set by the opt-out message: the copy is gone and must not come back. */
  let forgotten = false;
  /** Entry files, relative to the scope. Install fails (and is retried) if one of ESSENTIAL fails. */
  const ESSENTIAL = [
    './',
    'index.html',
    'main.js',
    'lab.js',
    'lab.bundle.js',
    'worker.js',
    'render-worker.js',
    'style.css',
    'pkg/wingbeat_live.js',
    'pkg/wingbeat_live_bg.wasm',
    'pkg/wingbeat.js',
    'pkg/wingbeat_bg.wasm',
  ];

  /** @param {string} href */
  const inScope = (href) => href.startsWith(SCOPE) && !href.endsWith('/sw.js');

  /**
   * The build's file list: absolute URLs inside the scope (the manifest is checked: a list of
   * relative paths, no scheme, no `..`). Throws when it cannot be read: install then fails and
   * is retried on the next visit.
   */
  async function manifest() {
    const res = await fetch(
      new Request(new URL(MANIFEST, SCOPE).href, { cache: 'reload', credentials: 'same-origin' }),
    );
    if (!res.ok) throw new Error(`precache: ${MANIFEST}: HTTP ${res.status} (scripts/build-web.sh writes it)`);
    const m = await res.json();
    if (!m || m.version !== 1 || !Array.isArray(m.files))
      throw new Error(`precache: ${MANIFEST}: expected { version: 1, files: [...] }`);
    /** @type {string[]} */
    const out = [];
    for (const f of m.files) {
      if (typeof f !== 'string' || /^[a-z]+:|^\/|(^|\/)\.\.(\/|$)/i.test(f)) continue;
      const u = new URL(f, SCOPE).href;
      if (inScope(u)) out.push(u);
    }
    return out.slice(0, MAX_FILES);
  }

  /** Fetches the entry files and every file of the build's manifest into the cache. */
  async function precache() {
    const cache = await caches.open(CACHE);
    const must = new Set(ESSENTIAL.map((p) => new URL(p, SCOPE).href));
    const all = [...new Set([...must, ...(await manifest())])];
    // A few at a time: the browser's connections to the host (6 over HTTP/1.1) are shared with
    // the page, whose own first loads should not queue behind the whole copy.
    let next = 0;
    const one = async () => {
      while (next < all.length) {
        const url = all[next++];
        try {
          // Revalidated against the browser's HTTP cache (the server's ETags): what the page has
          // just downloaded (the wasm modules above all) is not downloaded a second time.
          const res = await fetch(new Request(url, { cache: 'no-cache', credentials: 'same-origin' }));
          if (!res.ok || res.redirected || res.type !== 'basic') throw new Error(`HTTP ${res.status}`);
          await cache.put(url, res);
        } catch (e) {
          if (must.has(url)) throw new Error(`precache: ${url}: ${e instanceof Error ? e.message : e}`);
        }
      }
    };
    await Promise.all([one(), one(), one()]);
  }

  sw.addEventListener('install', (e) => {
    e.waitUntil(precache().then(() => sw.skipWaiting()));
  });

  sw.addEventListener('activate', (e) => {
    e.waitUntil(
      (async () => {
        for (const name of await caches.keys()) {
          if (name.startsWith(`wingbeat:${SCOPE}:`) && name !== CACHE) await caches.delete(name);
        }
        await sw.clients.claim();
      })(),
    );
  });

  /**
   * The cache key of a request: pages without their query (the lab's state lives there and
   * changes all the time), everything else as it is.
   * @param {Request} req
   */
  function keyOf(req) {
    const u = new URL(req.url);
    u.hash = '';
    if (req.mode === 'navigate') u.search = '';
    return u.href;
  }

  /**
   * Network first, the copy when the network fails (or is slow and a copy exists). `done`
   * settles when the copy has been refreshed (the event waits for it).
   * @param {Request} req
   * @returns {{ response: Promise<Response>, done: Promise<unknown> }}
   */
  function networkFirst(req) {
    const key = keyOf(req);
    // The copy is used (and refreshed) only while it exists: after an opt-out deleted it
    // (offline.js), the page this worker still controls must not bring it back.
    /** @type {Promise<Cache | null>} */
    const cache = forgotten
      ? Promise.resolve(null)
      : caches.has(CACHE).then(
          (has) => (has && !forgotten ? caches.open(CACHE) : null),
          () => null,
        );
    /** @type {Promise<unknown>[]} */
    const puts = [];
    const net = fetch(req).then((res) => {
      if (res.ok && res.type === 'basic' && !res.redirected) {
        const copy = res.clone();
        puts.push(cache.then((c) => c && c.put(key, copy)).catch(() => {}));
      }
      return res;
    });
    const dirPage = req.mode === 'navigate' && key.endsWith('/');
    /** @type {Promise<Response | undefined>} */
    const copy = cache
      .then(async (c) => (c ? (await c.match(key)) || (dirPage ? c.match(`${key}index.html`) : undefined) : undefined))
      .catch(() => undefined);
    /** @type {Promise<Response | null>} */
    const late = new Promise((resolve) => setTimeout(() => copy.then((hit) => resolve(hit || null)), NET_TIMEOUT_MS));
    const response = (async () => {
      try {
        const first = await Promise.race([net, late]);
        return first || (await net);
      } catch (err) {
        const hit = await copy;
        if (hit) return hit;
        throw err;
      }
    })();
    const done = net.then(
      () => Promise.all(puts),
      () => {},
    );
    return { response, done };
  }

  sw.addEventListener('message', (e) => {
    const data = /** @type {MessageEvent} */ (/** @type {unknown} */ (e)).data;
    const port = /** @type {MessageEvent} */ (/** @type {unknown} */ (e)).ports?.[0];
    if (!data || data.type !== 'wingbeat:forget') return;
    forgotten = true;
    e.waitUntil(
      (async () => {
        for (const name of await caches.keys()) if (name.startsWith(`wingbeat:${SCOPE}:`)) await caches.delete(name);
      })()
        .catch(() => {})
        .then(() => port?.postMessage({ type: 'wingbeat:forgotten' })),
    );
  });

  sw.addEventListener('fetch', (e) => {
    const req = e.request;
    if (req.method !== 'GET' || req.headers.has('range')) return;
    const url = new URL(req.url);
    if (url.origin !== sw.location.origin || !inScope(url.href)) return;
    const { response, done } = networkFirst(req);
    e.respondWith(response);
    e.waitUntil(done);
  });
})();
