// @ts-check
// Where the engine's code comes from: the wasm module (loaded and compiled once per page, the
// module is stateless) and the workers (www/worker.js, given the page's compiled module first),
// and the one reader of anglesAt's interleaved output. Paths resolve next to www/engine.js, also
// when the lab is loaded from another origin.
import { wasmModuleMessage } from './protocol.js';

/** @typedef {typeof import('../pkg/wingbeat.js')} Wasm the wasm module's exports (www/pkg/wingbeat.d.ts) */

/** The lab's folder (www/): pkg/ and worker.js are there. */
const WWW = new URL('../', import.meta.url);

/** @type {Promise<Wasm> | null} */
let shared = null;
/** @type {WebAssembly.Module | null} the compiled wasm, handed to the workers (no second download or compile) */
let compiled = null;

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

/** Loads and instantiates the wasm module once per page (the module is stateless). */
export function loadWasm() {
  if (!shared) {
    /** @type {Promise<Wasm>} */
    const p = import(new URL('pkg/wingbeat.js', WWW).href).then(async (/** @type {Wasm} */ m) => {
      const mod = await compileWasm(new URL('pkg/wingbeat_bg.wasm', WWW));
      await m.default({ module_or_path: mod });
      compiled = mod;
      return m;
    });
    shared = p;
    p.catch(() => {
      shared = null;
    });
    return p;
  }
  return shared;
}

/** The page's compiled wasm module once loadWasm has loaded it, else null. */
export const compiledWasm = () => compiled;

/** @type {string | null} the same-origin Blob URL that imports worker.js (made once) */
let bootstrapUrl = null;
/**
 * A worker of www/worker.js. Same origin: worker.js itself. When the lab was loaded from another
 * origin (a course page using the lab's files from the lab's host, which must send CORS
 * headers), `new Worker(url)` would be refused, so the worker starts from a same-origin Blob
 * whose only line imports worker.js by its absolute URL; worker.js then loads the wasm relative
 * to its own URL (import.meta.url), i.e. from the lab's host.
 */
export function defaultWorker() {
  const url = new URL('worker.js', WWW);
  if (typeof location === 'undefined' || url.origin === location.origin) return new Worker(url, { type: 'module' });
  if (!bootstrapUrl)
    bootstrapUrl = URL.createObjectURL(
      new Blob([`import ${JSON.stringify(url.href)};\n`], { type: 'text/javascript' }),
    );
  return new Worker(bootstrapUrl, { type: 'module' });
}

/**
 * A new worker from `make`, given the compiled wasm module first when there is one.
 * @param {() => Worker} make
 * @param {WebAssembly.Module | null} module
 */
export function startWorker(make, module) {
  const w = make();
  if (module) w.postMessage(wasmModuleMessage(module));
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
