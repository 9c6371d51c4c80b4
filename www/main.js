// @ts-check
// Page bootstrap for index.html: a classic script, parser-blocking, in <head> (no inline
// script, so a strict CSP `script-src 'self'` is enough). Order matters:
//   1. At once, before <body> is parsed: `?embed=1` puts class `embed` on <html> (page.css then
//      hides header and footer), so not even the first frame shows the page chrome. A module or
//      deferred script runs too late for that: Chromium paints the parsed header first.
//   2. When the document is parsed: the element gets its `embed` attribute, THEN lab.js is
//      imported (defining <wing-lab>), so the element is compact (one column) from its first
//      paint instead of switching after it has laid out.
//   3. Inside a frame (window.parent !== window) embed-api.js posts the content height to the
//      parent and answers the versioned postMessage API (docs/embedding.md, section iframe).
//   4. offline.js registers the service worker (a no-op where unsupported or opted out).
// `parent_origin=` (the only origin an embedded lab talks to) is read here; it and `offline=`
// (offline.js) are taken out of the address before lab.js reads the query: they are page
// settings, not lab parameters.
(() => {
  // Absolute URLs for the imports: in a frame sandboxed without allow-same-origin this script
  // counts as cross-origin and a relative import() would resolve against about:blank.
  const script = /** @type {HTMLScriptElement | null} */ (document.currentScript);
  const here = (/** @type {string} */ file) => new URL(file, script && script.src ? script.src : location.href).href;
  const query = new URLSearchParams(location.search);
  const embed = query.get('embed') === '1';
  if (embed) document.documentElement.classList.add('embed');

  /**
   * The parent origin pinned with `parent_origin=`, or null (any parent; see the docs).
   * @type {string | null}
   */
  let parentOrigin = null;
  /** Why `parent_origin=` was refused ('' when fine or absent). */
  let parentOriginError = '';
  if (query.has('parent_origin')) {
    const raw = query.get('parent_origin') || '';
    parentOrigin = originOf(raw);
    if (!parentOrigin)
      parentOriginError = `parent_origin: expected an origin such as https://course.example (scheme, host, optional port; nothing else), got ${JSON.stringify(raw.length > 60 ? raw.slice(0, 60) + '…' : raw)}`;
  }
  // Page settings, not lab parameters: out of the address before lab.js reads it (the lab would
  // call them unknown). offline.js reads `offline=` from the navigation entry's URL.
  const PAGE_PARAMS = ['parent_origin', 'offline'];
  if (PAGE_PARAMS.some((k) => query.has(k))) {
    for (const k of PAGE_PARAMS) query.delete(k);
    const rest = query.toString();
    history.replaceState(history.state, '', `${location.pathname}${rest ? '?' + rest : ''}${location.hash}`);
  }

  /**
   * Resolves when `lab` has rendered and loaded its full module, or after 20 s (at once without
   * a lab element).
   * @param {HTMLElement | null} lab
   */
  const settled = (lab) =>
    new Promise((resolve) => {
      const engine = () => /** @type {any} */ (lab)?.engine;
      const full = () => {
        const e = engine();
        Promise.resolve(e && typeof e.loadFull === 'function' ? e.loadFull() : null).then(resolve, resolve);
      };
      setTimeout(resolve, 20000);
      if (!lab) resolve(undefined);
      else if (engine()?.ready) full();
      else lab.addEventListener('wl-ready', full, { once: true });
    });

  const start = async () => {
    const lab = document.getElementById('lab');
    if (embed && lab) lab.setAttribute('embed', '');
    // The bundle of lab.js, embed-api.js and their modules (scripts/bundle.mjs; built with the
    // wasm): one request, and the embedding API is there as soon as the element is.
    const bundle =
      /** @type {{ embedApi: typeof import('./embed-api.js'), offline: typeof import('./offline.js') }} */ (
        await import(here('lab.bundle.js'))
      );
    let framed = true;
    try {
      framed = window.parent !== window;
    } catch {
      framed = true;
    }
    if (framed && lab) {
      const api = bundle.embedApi;
      // A malformed parent_origin keeps the API silent (nothing answered, no height posted)
      // rather than falling back to "any parent": the host asked for a restriction.
      api.startEmbedApi(lab, { parentOrigin: parentOriginError ? 'invalid:' : parentOrigin });
      if (parentOriginError) console.warn(`wingbeat lab: ${parentOriginError}; the embedding API stays silent.`);
    }
    // The service worker's first install copies the whole site for offline use: it starts once
    // the lab has drawn and its full wasm module has loaded (or after 20 s), so it never competes
    // with the first plot or the 3-D wing for the connection. Registering may fail (no support,
    // opted out, a trimmed copy of the site): the page works without it.
    settled(lab)
      .then(() => bundle.offline.registerOffline())
      .catch(() => {});
  };
  if (document.readyState === 'loading')
    document.addEventListener(
      'DOMContentLoaded',
      () => {
        start();
      },
      { once: true },
    );
  else start();

  /**
   * The origin in `raw` if it is exactly an origin (`https://host[:port]`; http too, for
   * intranets and loopback tests), else null.
   * @param {string} raw
   * @returns {string | null}
   */
  function originOf(raw) {
    if (raw.length > 200) return null;
    try {
      const u = new URL(raw);
      if (u.protocol !== 'https:' && u.protocol !== 'http:') return null;
      if (u.origin !== raw.replace(/\/$/, '')) return null;
      return u.origin;
    } catch {
      return null;
    }
  }
})();
