// @ts-check
// The live requests: what one recompute asks for, and the newest-wins queue that sends it to
// the live worker. Tested with a fake worker in tests/js/engine_requests.test.mjs.
//
// A wasm call cannot be interrupted, so requests are coalesced instead of cancelled: at most one
// is in flight and one waits; a newer request replaces the waiting one (which resolves to null)
// and makes the one in flight stale (its result, when it comes, resolves to null and is not
// drawn). Only the newest request's result reaches the caller. The first request (the first
// render) is computed on the main thread (`here`); a later one made while the live worker is still
// loading its wasm waits for it (it says { ready: true }) for up to `startWait` ms, so a key press
// never blocks the page with a computation (a 10 s run at 25.5 Hz: 150–400 ms); past that, and
// when workers are unavailable or the worker failed, requests are computed here.
import { overridesOf } from '../state.js';
import { JOB, jobMessage, readReply } from './protocol.js';

/** Longest wait (ms) of a request for the live worker to finish starting before it is computed on the main thread. */
export const LIVE_START_WAIT_MS = 2000;

/** Welch segment length of the live analysis's spectra. */
export const LIVE_SEGMENT_LEN = 8192;

/** The slider keys that custom kinematics replace (the table is the whole stroke). */
export const STROKE_KEYS = Object.freeze([
  'alpha0',
  'beta0',
  'gamma0',
  'alpha_phase',
  'beta_phase',
  'gamma_phase',
  'flap_hz',
]);

/**
 * The overrides the core applies for URL parameters: every numeric parameter by key, less the
 * stroke's when custom kinematics are in use (ζ and the duration still apply).
 * @param {import('../state.js').Params} params
 * @param {boolean} customKinematics
 */
export function liveOverrides(params, customKinematics) {
  const o = overridesOf(params);
  if (customKinematics) for (const k of STROKE_KEYS) delete o[/** @type {keyof typeof o} */ (k)];
  return o;
}

/**
 * What one recompute asks of wasm `analyze`: the config, the selected mode's index and the
 * spectra's options. `run` is the config wasm is given: `cfg` itself, or in a fluid `cfg` with
 * the wing's mesh and shapes attached (engine.withWing), which stays out of `cfg` (the plain
 * JSON config a result and its exports carry).
 * @param {import('../state.js').Params} params
 * @param {import('../pkg/wingbeat.js').SimConfig} cfg
 * @param {import('../pkg/wingbeat.js').SimConfig} [run]
 */
export function liveAsk(params, cfg, run = cfg) {
  /** @type {import('../pkg/wingbeat.js').WelchOptions} */
  const opts = { detrend: params.detrend, segment_len: LIVE_SEGMENT_LEN };
  return { cfg, run, k: Number(params.mode) - 1, params, opts };
}
/** @typedef {ReturnType<typeof liveAsk>} LiveAsk */

/**
 * @template R
 * @typedef {LiveAsk & { seq: number, resolve: (r: R | null) => void, reject: (e: Error) => void }} LiveRequest
 */

/**
 * The newest-wins queue of live requests.
 * @template R the result handed to the caller
 * @param {{
 *   start: () => Worker,
 *   here: (ask: LiveAsk) => R,
 *   fromWorker: (ask: LiveAsk, result: any, ms: number) => R,
 *   startWait?: number,
 * }} deps `start` makes the live worker (may throw: then everything is computed here); `here`
 *   computes a request on the main thread (throws the wasm error); `fromWorker` turns the
 *   worker's reply into the caller's result; `startWait` (ms, default
 *   {@link LIVE_START_WAIT_MS}) is how long a request waits for a starting worker.
 */
export function createLiveQueue({ start, here, fromWorker, startWait = LIVE_START_WAIT_MS }) {
  /** @type {Worker | null} */
  let live = null;
  /** the live worker has loaded its wasm (it said { ready: true }) */
  let ready = false;
  /** workers cannot be made here (no Worker, or the live worker failed): compute on the main thread */
  let broken = false;
  /** the newest request's number: any other request's result is stale */
  let seq = 0;
  /** @type {LiveRequest<R> | null} the request the live worker is computing */
  let inflight = null;
  /** @type {LiveRequest<R> | null} the newest request, waiting for the one in flight */
  let queued = null;
  const stats = { posted: 0, superseded: 0, stale: 0, sync: 0 };
  /** @type {ReturnType<typeof setTimeout> | null} the wait for a starting worker; past it, compute here */
  let startTimer = null;
  /** the starting worker took longer than `startWait`: compute here until it is ready */
  let startLate = false;

  function post(/** @type {LiveRequest<R>} */ req) {
    inflight = req;
    stats.posted++;
    /** @type {Worker} */ (live).postMessage(
      jobMessage(req.seq, JOB.analyze, { cfg: req.run, opts: req.opts, k: req.k }),
    );
  }

  /** Computes a request on the main thread (or resolves null when it is no longer the newest). */
  function settleHere(/** @type {LiveRequest<R>} */ req) {
    if (req.seq !== seq) {
      req.resolve(null);
      return;
    }
    try {
      const r = here(req);
      stats.sync++;
      req.resolve(r);
    } catch (e) {
      req.reject(/** @type {Error} */ (e));
    }
  }

  function onReply(/** @type {MessageEvent} */ ev) {
    const m = readReply(ev.data);
    if (m.type === 'ready') {
      ready = true;
      stopWaiting();
      // The newest request that waited for the worker goes to it now.
      if (queued && !inflight) {
        const q = queued;
        queued = null;
        post(q);
      }
      return;
    }
    const req = inflight;
    if (!req || m.id !== req.seq || m.type === 'progress') return;
    inflight = null;
    if (req.seq !== seq) {
      stats.stale++;
      req.resolve(null);
    } else if (m.type === 'error') req.reject(new Error(m.error));
    else req.resolve(fromWorker(req, m.result, m.ms));
    if (queued) {
      const q = queued;
      queued = null;
      post(q);
    }
  }

  function stopWaiting() {
    if (startTimer != null) clearTimeout(startTimer);
    startTimer = null;
  }

  /** Waits for the starting worker with `req` (the newest); computes it here when the wait runs out. */
  function waitForStart(/** @type {LiveRequest<R>} */ req) {
    queued = req;
    if (startTimer != null) return;
    startTimer = setTimeout(() => {
      startTimer = null;
      if (ready) return;
      startLate = true;
      const q = queued;
      queued = null;
      if (q) settleHere(q);
    }, startWait);
  }

  /** The live worker could not start (or died): from now on compute here, the newest request included. */
  function onFailure() {
    stopWaiting();
    broken = true;
    ready = false;
    if (live) live.terminate();
    live = null;
    const waiting = [inflight, queued];
    inflight = queued = null;
    for (const r of waiting) if (r) settleHere(r);
  }

  /** The live worker (made on first use), or null when workers are unavailable. */
  function worker() {
    if (live || broken) return live;
    try {
      live = start();
    } catch {
      broken = true;
      return null;
    }
    live.onmessage = onReply;
    live.onerror = onFailure;
    return live;
  }

  return {
    /**
     * Resolves to the request's result, or to null when a newer request superseded it.
     * @param {LiveAsk} ask
     * @returns {Promise<R | null>}
     */
    request(ask) {
      const n = ++seq;
      return new Promise((resolve, reject) => {
        /** @type {LiveRequest<R>} */
        const req = { ...ask, seq: n, resolve, reject };
        if (queued) {
          stats.superseded++;
          queued.resolve(null);
          queued = null;
        }
        // The first request (the first render) does not start the live worker: a lab that is
        // only looked at never loads a second worker; the first parameter change does.
        const w = n > 1 ? worker() : live;
        if (!w || (!ready && (n === 1 || startLate))) settleHere(req);
        else if (!ready) waitForStart(req);
        else if (inflight) queued = req;
        else post(req);
      });
    },
    /** Starts the live worker now (its wasm loads while the lab is looked at). */
    warm() {
      worker();
    },
    /** Whether requests go to the live worker (false: computed on the main thread). */
    get inWorker() {
      return !!live && ready;
    },
    /** Counters: posted to the worker, superseded while waiting, stale results dropped, computed here. */
    get stats() {
      return { ...stats };
    },
    /** Stops the live worker; a request in flight or waiting resolves to null. */
    dispose() {
      stopWaiting();
      if (live) live.terminate();
      live = null;
      ready = false;
      seq++;
      for (const r of [inflight, queued]) if (r) r.resolve(null);
      inflight = queued = null;
    },
  };
}
