// @ts-check
// The study worker's jobs (sweeps, the IC map, damped runs, the resonance map, the report, the
// FE wing, sensing): one worker for all of them, made on the first job; each job is a promise
// with progress. A wasm call cannot be interrupted, so cancelling a job terminates the worker
// (its other jobs fail with "cancelled" too) and the next job starts a fresh one. Tested with a
// fake worker in tests/js/engine.test.mjs.
import { jobMessage, readReply } from './protocol.js';

/** @typedef {{ resolve: (v: { result: any, ms: number }) => void, reject: (e: Error) => void, progress: (done: number, total: number) => void, kind: string }} Job */

/**
 * @param {() => Worker} start makes the worker (given the page's wasm module first, see wasm.js)
 */
export function createJobs(start) {
  /** @type {Worker | null} */
  let worker = null;
  /** @type {Map<number, Job>} */
  const jobs = new Map();
  let jobId = 0;

  function failAll(/** @type {string} */ why) {
    for (const j of jobs.values()) j.reject(new Error(why));
    jobs.clear();
  }

  function ensureWorker() {
    if (worker) return worker;
    const w = start();
    w.onmessage = (ev) => {
      const m = readReply(ev.data);
      if (m.type === 'ready') return;
      const job = jobs.get(/** @type {number} */ (m.id));
      if (!job) return;
      if (m.type === 'progress') job.progress(m.done, m.total);
      else {
        jobs.delete(/** @type {number} */ (m.id));
        if (m.type === 'error') job.reject(new Error(m.error));
        else job.resolve({ result: m.result, ms: m.ms });
      }
    };
    w.onerror = (ev) => {
      failAll((ev && ev.message) || 'worker failed');
      worker = null;
    };
    worker = w;
    return w;
  }

  return {
    /**
     * Runs job `kind` (see www/worker.js) with its inputs; resolves to { result, ms }.
     * @param {string} kind
     * @param {Record<string, any>} [payload]
     * @param {(done: number, total: number) => void} [onProgress]
     * @returns {{ id: number, promise: Promise<{ result: any, ms: number }> }}
     */
    run(kind, payload = {}, onProgress = () => {}) {
      const id = ++jobId;
      /** @type {Promise<{ result: any, ms: number }>} */
      const promise = new Promise((resolve, reject) => {
        jobs.set(id, { resolve, reject, progress: onProgress, kind });
        try {
          ensureWorker().postMessage(jobMessage(id, kind, payload));
        } catch (e) {
          jobs.delete(id);
          reject(e);
        }
      });
      return { id, promise };
    },
    /** Whether job `id` is still running. */
    running(/** @type {number} */ id) {
      return jobs.has(id);
    },
    /** Cancels job `id` by terminating the worker; false when it is not running. */
    cancel(/** @type {number} */ id) {
      if (!jobs.has(id) || !worker) return false;
      worker.terminate();
      worker = null;
      failAll('cancelled');
      return true;
    },
    /** Stops the worker; pending jobs fail with "disposed". */
    dispose() {
      if (worker) worker.terminate();
      worker = null;
      failAll('disposed');
    },
  };
}
