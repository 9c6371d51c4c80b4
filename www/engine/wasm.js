// @ts-check
// Where the engine's code comes from: the wasm module (loaded and compiled once per page, the
// module is stateless) and the workers (www/worker.js, given the page's compiled module first),
// and the one reader of anglesAt's interleaved output. Paths resolve next to www/engine.js, also
// when the lab is loaded from another origin.
import { wasmModuleMessage, wasmPendingMessage } from './protocol.js';

/** @typedef {typeof import('../pkg/wingbeat.js')} Wasm the wasm module's exports (www/pkg/wingbeat.d.ts) */

import { WWW } from '../base.js';

/**
 * The two builds of the module (scripts/build-web.sh): `live`, the live analysis alone (small:
 * the first plot is painted from it), and `full`, the whole API with the shell FE, sensing and
 * the renderer, loaded behind it. Both are stateless; each is loaded and compiled once per page.
 * @typedef {'live' | 'full'} Variant
 */
/** The glue and the module of each build, under pkg/. */
export const VARIANT_FILES = Object.freeze({
  live: Object.freeze({ glue: 'pkg/wingbeat_live.js', wasm: 'pkg/wingbeat_live_bg.wasm' }),
  full: Object.freeze({ glue: 'pkg/wingbeat.js', wasm: 'pkg/wingbeat_bg.wasm' }),
});

/** @type {Record<Variant, Promise<Wasm> | null>} */
const shared = { live: null, full: null };
/** @type {Record<Variant, WebAssembly.Module | null>} the compiled wasm, handed to the workers (no second download or compile) */
const compiled = { live: null, full: null };

/** Compiles the wasm (streaming when the server sends application/wasm, else from its bytes). */
async function compileWasm(/** @type {URL} */ url) {
  const res = await fetch(url);
  if (!res.ok) throw new Error(`${url.pathname}: HTTP ${res.status}`);
  if (
    typeof WebAssembly.compileStreaming === 'function' &&
    (res.headers.get('content-type') || '').startsWith('application/wasm')
  ) {
    return WebAssembly.compileStreaming(res);
  }
  return WebAssembly.compile(await res.arrayBuffer());
}

/**
 * Loads and instantiates one build of the module once per page.
 * @param {Variant} variant
 */
function loadVariant(variant) {
  const files = VARIANT_FILES[variant];
  let p = shared[variant];
  if (!p) {
    // The glue and the module are fetched together: the module (the big download) does not
    // wait for the glue to arrive and run first.
    p = Promise.all([import(new URL(files.glue, WWW).href), compileWasm(new URL(files.wasm, WWW))]).then(
      async ([/** @type {Wasm} */ m, mod]) => {
        await m.default({ module_or_path: mod });
        compiled[variant] = mod;
        return m;
      },
    );
    shared[variant] = p;
    p.catch(() => {
      shared[variant] = null;
    });
  }
  return p;
}

/** Loads and instantiates the full module once per page. */
export const loadWasm = () => loadVariant('full');

/**
 * Loads and instantiates the live module once per page (its exports are a subset of the full
 * module's: www/pkg/wingbeat_live.d.ts).
 */
export const loadLive = () => loadVariant('live');

/** The page's compiled full wasm module once loadWasm has loaded it, else null. */
export const compiledWasm = () => compiled.full;
/** The page's compiled live wasm module once loadLive has loaded it, else null. */
export const compiledLive = () => compiled.live;

/**
 * One engine's view of the two builds: `first()` loads the live build (the first plot's), `full()`
 * the full one (once; again after a failure), `loaded` is the full build's exports once there,
 * and the compiled modules to hand to new workers (null with a test's fake loaders).
 * @param {() => Promise<Wasm>} [load] the full build (default loadWasm)
 * @param {() => Promise<Wasm>} [loadFirst] the live build (default loadLive with the default
 *   `load`, else `load` itself: a test's fake is one object)
 */
export function createBuilds(load = loadWasm, loadFirst = load === loadWasm ? loadLive : load) {
  /** @type {Wasm | null} */
  let loaded = null;
  /** @type {Promise<Wasm> | null} */
  let loading = null;
  const full = () => {
    if (!loading) {
      loading = load().then((m) => (loaded = m));
      loading.catch(() => {
        loading = null;
      });
    }
    return loading;
  };
  return {
    first: loadFirst,
    full,
    get loaded() {
      return loaded;
    },
    fullModule: () => (load === loadWasm ? compiledWasm() : null),
    liveModule: () => (loadFirst === loadLive ? compiledLive() : null),
    /** The page's own loading of the full build, for startFullWorker (null with fakes). */
    fullComing: load === loadWasm ? full : null,
  };
}

/** @type {Record<string, string>} per worker file, the same-origin Blob URL that imports it (made once) */
const bootstrapUrls = {};
/**
 * A worker of www/worker.js. Same origin: worker.js itself. When the lab was loaded from another
 * origin (a course page using the lab's files from the lab's host, which must send CORS
 * headers), `new Worker(url)` would be refused, so the worker starts from a same-origin Blob
 * whose only line imports worker.js by its absolute URL; worker.js then loads the wasm relative
 * to its own URL (import.meta.url), i.e. from the lab's host.
 */
export function defaultWorker(file = 'worker.js') {
  const url = new URL(file, WWW);
  if (typeof location === 'undefined' || url.origin === location.origin) return new Worker(url, { type: 'module' });
  if (!bootstrapUrls[file])
    bootstrapUrls[file] = URL.createObjectURL(
      new Blob([`import ${JSON.stringify(url.href)};\n`], { type: 'text/javascript' }),
    );
  return new Worker(bootstrapUrls[file], { type: 'module' });
}

/** A worker of www/render-worker.js (the 3-D view drawn off the main thread), as defaultWorker makes it. */
export const renderWorker = () => defaultWorker('render-worker.js');

/**
 * A new worker from `make`, given the compiled wasm module first when there is one (`variant`
 * says which build it is; without a module the worker loads the full one itself).
 * @param {() => Worker} make
 * @param {WebAssembly.Module | null} module
 * @param {Variant} [variant]
 */
export function startWorker(make, module, variant = 'full') {
  const w = make();
  if (module) w.postMessage(wasmModuleMessage(module, variant));
  return w;
}

/**
 * A new worker for the full build: given the page's compiled module at once when it has it;
 * while the page is still loading it (`coming`, from createBuilds().full()), told that it
 * follows and then given it, so the worker neither downloads nor compiles the 4.6 MB module a
 * second time (a guided experiment in the address starts a study before the full build is in).
 * @param {() => Worker} make
 * @param {WebAssembly.Module | null} module
 * @param {(() => Promise<unknown>) | null} coming null with a test's fake loaders
 */
export function startFullWorker(make, module, coming) {
  if (module || !coming) return startWorker(make, module, 'full');
  const w = make();
  w.postMessage(wasmPendingMessage(true));
  coming().then(
    () => {
      const m = compiledWasm();
      w.postMessage(m ? wasmModuleMessage(m, 'full') : wasmPendingMessage(false));
    },
    () => w.postMessage(wasmPendingMessage(false)),
  );
  return w;
}

/**
 * Splits anglesAt's interleaved [α0, β0, γ0, α1, …] into three arrays.
 * @param {ArrayLike<number>} flat
 */
export function splitAngles(flat) {
  const n = Math.floor(flat.length / 3);
  const alpha = new Float64Array(n),
    beta = new Float64Array(n),
    gamma = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    alpha[i] = flat[3 * i];
    beta[i] = flat[3 * i + 1];
    gamma[i] = flat[3 * i + 2];
  }
  return { alpha, beta, gamma };
}
