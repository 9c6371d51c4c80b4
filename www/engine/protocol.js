// @ts-check
// The messages between the engine (www/engine.js) and its workers (www/worker.js), in one place:
// both sides build and read them with these functions, so a message's shape and the job kinds
// are written once. Pure (no DOM, no wasm); tested in tests/js/engine_protocol.test.mjs.
//
//   page → worker   { wasmModule, variant }          first: the page's compiled wasm module ('live' or 'full' build)
//                   { wasmPending: true | false }    or first: the module follows (wait for it) / will not (load it)
//                   { id, kind, ...payload }         a job; kind ∈ JOB_KINDS
//   worker → page   { ready: true }                  once, when the wasm has loaded
//                   { id, progress: [done, total] }  any number of times
//                   { id, result, ms }               the job's result (typed arrays transferred)
//                   { id, error }                    the job's error message

/** The jobs worker.js runs, by message kind. */
export const JOB = Object.freeze({
  sweep: 'sweep',
  icmap: 'icmap',
  damping: 'damping',
  resonance: 'resonance',
  reproduce: 'reproduce',
  fe: 'fe',
  sense: 'sense',
  analyze: 'analyze',
  classify: 'classify',
});
/** @type {readonly string[]} */
export const JOB_KINDS = Object.freeze(Object.values(JOB));

/**
 * Hands the page's compiled wasm module to a new worker (no second download or compile), and
 * says which build it is ('live' or 'full').
 * @param {WebAssembly.Module} module
 * @param {'live' | 'full'} [variant]
 */
export const wasmModuleMessage = (module, variant = 'full') => ({ wasmModule: module, variant });

/**
 * Tells a new worker that the page's compiled module is on its way (`true`: wait for it before
 * the first job) or will not come after all (`false`: load it yourself).
 * @param {boolean} coming
 */
export const wasmPendingMessage = (coming) => ({ wasmPending: coming });

/**
 * A job for the worker.
 * @param {number} id
 * @param {string} kind
 * @param {Record<string, unknown>} [payload] the job's inputs ({ cfg, opts }, { input, opts }, …)
 */
export const jobMessage = (id, kind, payload = {}) => ({ id, kind, ...payload });

/**
 * What the worker received: the wasm module, or a job (its id, kind and the whole message as
 * the job's inputs).
 * @param {unknown} data
 * @returns {{ wasmModule: WebAssembly.Module, variant: 'live' | 'full' } | { wasmPending: boolean } | { id: unknown, kind: unknown, job: Record<string, any> }}
 */
export function readRequest(data) {
  const d = /** @type {Record<string, any>} */ (data && typeof data === 'object' ? data : {});
  if ('wasmPending' in d && !('id' in d)) return { wasmPending: d.wasmPending === true };
  if (d.wasmModule) return { wasmModule: d.wasmModule, variant: d.variant === 'live' ? 'live' : 'full' };
  return { id: d.id, kind: d.kind, job: d };
}

export const readyMessage = () => ({ ready: true });
export const progressMessage = (
  /** @type {unknown} */ id,
  /** @type {number} */ done,
  /** @type {number} */ total,
) => ({
  id,
  progress: [done, total],
});
export const resultMessage = (/** @type {unknown} */ id, /** @type {unknown} */ result, /** @type {number} */ ms) => ({
  id,
  result,
  ms,
});
export const errorMessage = (/** @type {unknown} */ id, /** @type {string} */ error) => ({ id, error });

/**
 * @typedef {{ type: 'ready' }
 *   | { type: 'progress', id: unknown, done: number, total: number }
 *   | { type: 'error', id: unknown, error: string }
 *   | { type: 'result', id: unknown, result: any, ms: number }} Reply
 */

/**
 * Reads a worker's message (anything that is not `ready`, progress or an error is a result).
 * @param {unknown} data
 * @returns {Reply}
 */
export function readReply(data) {
  const d = /** @type {Record<string, any>} */ (data && typeof data === 'object' ? data : {});
  if (d.ready) return { type: 'ready' };
  if (d.progress) return { type: 'progress', id: d.id, done: d.progress[0], total: d.progress[1] };
  if (d.error != null) return { type: 'error', id: d.id, error: String(d.error) };
  return { type: 'result', id: d.id, result: d.result, ms: d.ms };
}

/**
 * The buffers of every typed array in a result, each once: posted as transferables, so a
 * result's long series move to the page instead of being copied.
 * @param {unknown} value
 * @returns {ArrayBufferLike[]}
 */
export function transferList(value) {
  /** @type {Set<ArrayBufferLike>} */
  const acc = new Set();
  const walk = (/** @type {unknown} */ v) => {
    if (ArrayBuffer.isView(v)) acc.add(v.buffer);
    else if (Array.isArray(v)) v.forEach(walk);
    else if (v && typeof v === 'object') Object.values(v).forEach(walk);
  };
  walk(value);
  return [...acc];
}
