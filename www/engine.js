// @ts-check
// The lab's engine: the ONLY module that talks to the wasm module and to the Web Worker.
// Views never call wasm; they read results from the store (www/store.js), which www/lab.js
// fills from this engine. Unit-tested against a fake wasm object and a fake worker in
// tests/js/engine.test.mjs.
//
//   const engine = createEngine();              // browser defaults: pkg/ and worker.js next to this file
//   const wb = await engine.load();
//   const r = engine.analyze(params, fe);       // live: simulate + forces + spectra + envelope + angles
//   const job = engine.run('sweep', { cfg, opts }, (done, total) => …); await job.promise; engine.cancel(job.id);
//   const fe = await engine.ensureFe();         // the shell-FE wing, once, in the worker
//
// Results carry the kinematic angles on the simulation's time grid (`angles.alpha/beta/gamma`),
// from wasm `analyze` when it provides them and otherwise from ONE `anglesAt` call per
// recompute (made lazily, on first read), so the 3-D view never crosses into wasm per frame.
import { overridesOf, FE_LAB_INPUT, SAMPLE_RATE_HZ } from './state.js';

/** @typedef {typeof import('./pkg/wingbeat.js')} Wasm the wasm module's exports (www/pkg/wingbeat.d.ts) */
/** @typedef {import('./pkg/wingbeat.js').SimConfig} SimConfig */
/** @typedef {import('./pkg/wingbeat.js').Analysis} Analysis */
/** @typedef {import('./pkg/wingbeat.js').AngleSeries} AngleSeries */
/** @typedef {import('./pkg/wingbeat.js').FeModesResult} FeModesResult */
/**
 * One live analysis: the config, the selected mode index k, the URL parameters it came from,
 * the wasm result, the angles on `analysis.sim.t` and the wasm time.
 * @typedef {{ cfg: SimConfig, k: number, params: import('./state.js').Params, analysis: Analysis, angles: AngleSeries | null, compute_ms: number }} LiveResult
 */
/** @typedef {{ resolve: (v: { result: any, ms: number }) => void, reject: (e: Error) => void, progress: (done: number, total: number) => void, kind: string }} Job */

const HERE = new URL('.', import.meta.url);

/** @type {Promise<Wasm> | null} */
let shared = null;
/** Loads and instantiates the wasm module once per page (the module is stateless). */
export function loadWasm() {
  if (!shared) {
    /** @type {Promise<Wasm>} */
    const p = import(new URL('pkg/wingbeat.js', HERE).href).then(async (/** @type {Wasm} */ m) => {
      await m.default({ module_or_path: new URL('pkg/wingbeat_bg.wasm', HERE) });
      return m;
    });
    shared = p;
    p.catch(() => { shared = null; });
    return p;
  }
  return shared;
}

function defaultWorker() {
  return new Worker(new URL('worker.js', HERE), { type: 'module' });
}

const now = () => (typeof performance !== 'undefined' ? performance.now() : Date.now());

/** Splits anglesAt's interleaved [α0, β0, γ0, α1, …] into three arrays. */
export function splitAngles(flat) {
  const n = Math.floor(flat.length / 3);
  const alpha = new Float64Array(n), beta = new Float64Array(n), gamma = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    alpha[i] = flat[3 * i];
    beta[i] = flat[3 * i + 1];
    gamma[i] = flat[3 * i + 2];
  }
  return { alpha, beta, gamma };
}

/**
 * @param {{ load?: () => Promise<Wasm>, createWorker?: () => Worker, feInput?: import('./pkg/wingbeat.js').FemInput }} [deps]
 *   `load` resolves to the wasm module's exports (default: loadWasm); `createWorker` makes the
 *   study worker (default: www/worker.js). Tests pass fakes.
 */
export function createEngine(deps = {}) {
  const load = deps.load || loadWasm;
  const createWorker = deps.createWorker || defaultWorker;
  const feInput = deps.feInput || FE_LAB_INPUT;
  /** @type {Wasm | null} */
  let wb = null;
  /** @type {SimConfig | null} */
  let base = null;
  /** @type {Worker | null} */
  let worker = null;
  /** @type {Map<number, Job>} */
  const jobs = new Map();
  let jobId = 0;
  /** @type {Promise<FeModesResult> | null} */
  let fePromise = null;
  /** @type {FeModesResult | null} */
  let fe = null;

  function failAll(why) {
    for (const j of jobs.values()) j.reject(new Error(why));
    jobs.clear();
  }

  function ensureWorker() {
    if (!worker) {
      worker = createWorker();
      worker.onmessage = (ev) => {
        const { id, progress, result, error, ms } = ev.data || {};
        const job = jobs.get(id);
        if (!job) return;
        if (progress) job.progress(progress[0], progress[1]);
        else {
          jobs.delete(id);
          if (error != null) job.reject(new Error(error));
          else job.resolve({ result, ms });
        }
      };
      worker.onerror = (ev) => {
        failAll((ev && ev.message) || 'worker failed');
        worker = null;
      };
    }
    return worker;
  }

  const engine = {
    /** Resolves to the wasm module once loaded (and remembers its default config). */
    async load() {
      if (!wb) {
        const m = await load();
        base = m.defaultConfig();
        wb = m;
      }
      return wb;
    },
    get ready() {
      return !!wb;
    },
    /** The paper's default config (wasm defaultConfig), after load(). */
    get baseConfig() {
      return base;
    },
    /** The FE wing once computed (else null). */
    get fe() {
      return fe;
    },
    /** Whether this wasm build has the renderer (WingView). */
    get hasRenderer() {
      return !!wb && typeof wb.WingView === 'function';
    },
    /** The wasm module itself, for the renderer's WingView only (www/views/wing3d.js). */
    get renderer() {
      return wb && wb.WingView;
    },
    limits() {
      if (!wb) throw new Error('engine: wasm not loaded');
      return wb.limits();
    },
    /** The core's table of the lab's numeric parameters (wasm `parameters()`; null before load). */
    parameters() {
      return wb ? wb.parameters() : null;
    },
    /**
     * The SimConfig for URL parameters, built by the core (wasm `applyOverrides`): the paper
     * case (or, with modes=fe once computed, the FE wing's modes) at the lab's sample rate, with
     * every numeric parameter applied by its key. Throws the wasm error (naming the key) for a
     * value the core rejects.
     */
    /**
     * @param {import('./state.js').Params} params URL parameters (www/state.js)
     * @returns {SimConfig}
     */
    config(params) {
      if (!wb) throw new Error('engine: wasm not loaded');
      const b = { ...base, sample_rate_hz: SAMPLE_RATE_HZ };
      if (params.modes === 'fe' && fe) b.modes = fe.modes;
      return wb.applyOverrides(b, overridesOf(params));
    },
    /**
     * The live analysis of the selected mode: { cfg, k, analysis, angles, compute_ms }.
     * Throws the wasm error (its message names the field) for a rejected config.
     */
    /**
     * @param {import('./state.js').Params} params URL parameters (www/state.js)
     * @returns {LiveResult}
     */
    analyze(params) {
      const w = wb;
      if (!w) throw new Error('engine: wasm not loaded');
      const cfg = engine.config(params);
      const k = Number(params.mode) - 1;
      const t0 = now();
      const a = w.analyze(cfg, { detrend: params.detrend, segment_len: 8192 }, k);
      const t1 = now();
      /** @type {LiveResult} */
      const res = { cfg, k, params, analysis: a, angles: null, compute_ms: t1 - t0 };
      /** @type {AngleSeries | null} */
      let angles = a.angles && a.angles.alpha ? a.angles : null;
      if (angles || typeof w.anglesAt !== 'function') res.angles = angles;
      else {
        // Older wasm builds: ONE anglesAt call for the whole run, made when a view first reads
        // the angles (the 3-D view, on its next frame), so the slider's redraw does not wait.
        Object.defineProperty(res, 'angles', {
          enumerable: true,
          get() {
            if (!angles) angles = splitAngles(w.anglesAt(cfg, a.sim.t));
            return angles;
          },
        });
      }
      return res;
    },
    /**
     * Runs a study in the worker: kind ∈ sweep | icmap | damping | resonance | reproduce | fe (see
     * www/worker.js). Returns { id, promise } where promise resolves to { result, ms }.
     */
    /**
     * @param {string} kind
     * @param {Record<string, any>} [payload]
     * @param {(done: number, total: number) => void} [onProgress]
     * @returns {{ id: number, promise: Promise<{ result: any, ms: number }> }}
     */
    run(kind, payload = {}, onProgress = () => {}) {
      const id = ++jobId;
      const promise = new Promise((resolve, reject) => {
        jobs.set(id, { resolve, reject, progress: onProgress, kind });
        try {
          ensureWorker().postMessage({ id, kind, ...payload });
        } catch (e) {
          jobs.delete(id);
          reject(e);
        }
      });
      return { id, promise };
    },
    /**
     * The resonance map (wasm `resonanceMap`, run in the worker): Floquet f_eff and largest
     * |multiplier| of every mode over opts = { from_hz, to_hz, points, alpha0_values? }.
     * Same return value as run(): { id, promise } (cancel with cancel(id)).
     * @param {SimConfig} cfg
     * @param {import('./pkg/wingbeat.js').ResonanceOptions} opts
     * @param {(done: number, total: number) => void} [onProgress]
     */
    resonanceMap(cfg, opts, onProgress = () => {}) {
      return engine.run('resonance', { cfg, opts }, onProgress);
    },
    /** Whether job `id` is still running. */
    running(id) {
      return jobs.has(id);
    },
    /**
     * Cancels job `id`. A wasm call cannot be interrupted, so the worker is terminated (the
     * other jobs in it fail with "cancelled" too) and a fresh one starts on the next run.
     */
    cancel(id) {
      if (!jobs.has(id) || !worker) return false;
      worker.terminate();
      worker = null;
      failAll('cancelled');
      if (!fe) fePromise = null;
      return true;
    },
    /** The lab's shell-FE wing, computed once in the worker. */
    ensureFe() {
      if (fe) return Promise.resolve(fe);
      if (!fePromise) {
        /** @type {Promise<FeModesResult>} */
        const p = engine.run('fe', { input: feInput }).promise.then(({ result }) => {
          fe = /** @type {FeModesResult} */ (result);
          return fe;
        });
        fePromise = p;
        p.catch(() => { fePromise = null; });
        return p;
      }
      return fePromise;
    },
    /** Stops the worker (element removed from the page). */
    dispose() {
      if (worker) worker.terminate();
      worker = null;
      failAll('disposed');
    },
  };
  return engine;
}
