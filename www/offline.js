// @ts-check
// Offline use in a classroom: registers the lab's service worker (www/sw.js), which keeps a copy
// of the site's own files so that after one visit the lab works with the network off. Called by
// the page (main.js, from the bundle lab.bundle.js, once the lab has drawn and loaded its full
// wasm module); the <wing-lab> element itself never registers a service worker (a host page
// decides that for its origin).
//
// registerOffline() does nothing when:
//   - the browser has no service workers, or the page is not a secure context (https:, or http:
//     on localhost / 127.0.0.1 / [::1]); file:// pages never qualify;
//   - sw.js would be on another origin than the page (a service worker must be same-origin);
//   - the user or host opted out (offlineOptOut below).
// Opting out also unregisters a service worker this lab registered earlier for the same scope
// and deletes its caches, so `?offline=0` is also the way to clear the offline copy.
import { WWW } from './base.js';

/** localStorage key: 'off' keeps the lab from registering its service worker in this browser. */
export const OFFLINE_STORAGE_KEY = 'wingbeat-offline';
/** Cache names of sw.js start with this (then the scope, then the build stamp). */
export const CACHE_PREFIX = 'wingbeat:';

/**
 * Why offline use is off for this page ('' when it is on). Pure apart from its arguments.
 * `?offline=0` (in the address, or in the URL the page was first opened with: the lab rewrites
 * its query as sliders move) turns it off and remembers that in localStorage; `?offline=1`
 * turns it back on and forgets the choice. `<meta name="wingbeat-offline" content="off">` in the
 * host page turns it off for that page.
 * @param {{ urls: string[], meta: string | null, storage: Pick<Storage, 'getItem' | 'setItem' | 'removeItem'> | null }} env
 * @returns {string}
 */
export function offlineOptOut({ urls, meta, storage }) {
  /** @type {string | null} */
  let param = null;
  for (const u of urls) {
    try {
      const v = new URL(u).searchParams.get('offline');
      if (v !== null) {
        param = v;
        break;
      }
    } catch {
      // not a URL: ignore
    }
  }
  try {
    if (param === '0' || param === 'off') storage?.setItem(OFFLINE_STORAGE_KEY, 'off');
    else if (param === '1' || param === 'on') storage?.removeItem(OFFLINE_STORAGE_KEY);
  } catch {
    // storage refused (sandboxed frame, privacy mode): the URL still decides for this page
  }
  if (param === '0' || param === 'off') return 'the address has offline=0';
  if (meta && meta.trim().toLowerCase() === 'off') return 'the page has <meta name="wingbeat-offline" content="off">';
  /** @type {string | null} */
  let stored = null;
  try {
    stored = storage ? storage.getItem(OFFLINE_STORAGE_KEY) : null;
  } catch {
    stored = null;
  }
  if (stored === 'off' && param !== '1' && param !== 'on') return `localStorage["${OFFLINE_STORAGE_KEY}"] is "off"`;
  return '';
}

/** @returns {Storage | null} */
function localStore() {
  try {
    return window.localStorage;
  } catch {
    return null;
  }
}

/** How long the opt-out waits for the worker to confirm it deleted its copy. */
const FORGET_TIMEOUT_MS = 3000;

/**
 * Tells a service worker of this lab to drop its copy and never reopen it (sw.js, message
 * `wingbeat:forget`); resolves when it answers, or after FORGET_TIMEOUT_MS (a worker of an older
 * build does not answer). Never rejects.
 * @param {ServiceWorker | null} worker
 * @returns {Promise<void>}
 */
function forget(worker) {
  if (!worker) return Promise.resolve();
  return new Promise((resolve) => {
    const channel = new MessageChannel();
    const timer = setTimeout(resolve, FORGET_TIMEOUT_MS);
    channel.port1.onmessage = () => {
      clearTimeout(timer);
      resolve();
    };
    try {
      worker.postMessage({ type: 'wingbeat:forget' }, [channel.port2]);
    } catch {
      clearTimeout(timer);
      resolve();
    }
  });
}

/**
 * Registers ./sw.js (next to this file) when supported and not opted out; removes this lab's
 * registration and caches when opted out. Never throws; resolves when done (callers need not wait).
 * @returns {Promise<void>}
 */
export async function registerOffline() {
  try {
    if (typeof navigator === 'undefined' || !('serviceWorker' in navigator)) return;
    if (!/^https?:$/.test(location.protocol) || !window.isSecureContext) return;
    const swUrl = new URL('sw.js', WWW);
    if (swUrl.origin !== location.origin) return;
    const scope = new URL('./', swUrl).href;
    const nav = /** @type {PerformanceNavigationTiming | undefined} */ (
      performance.getEntriesByType?.('navigation')[0]
    );
    const metaEl = document.querySelector('meta[name="wingbeat-offline"]');
    const why = offlineOptOut({
      urls: [location.href, ...(nav && nav.name ? [nav.name] : [])],
      meta: metaEl ? metaEl.getAttribute('content') : null,
      storage: localStore(),
    });
    if (why) {
      const reg = await navigator.serviceWorker.getRegistration(scope);
      if (reg && reg.scope === scope) {
        // First the worker stops using its copy (it still serves pages it controls until they
        // unload, and would otherwise reopen a cache deleted under it), then it goes.
        await forget(reg.active || reg.waiting || reg.installing);
        await reg.unregister();
        if (typeof caches !== 'undefined') {
          for (const name of await caches.keys())
            if (name.startsWith(`${CACHE_PREFIX}${scope}:`)) await caches.delete(name);
        }
      }
      return;
    }
    await navigator.serviceWorker.register(swUrl, { scope, updateViaCache: 'none' });
  } catch (e) {
    // Offline use is an extra: the lab works without it.
    console.warn('wingbeat lab: offline use is not available here:', e instanceof Error ? e.message : e);
  }
}
