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
import { toConfig, FE_LAB_INPUT } from './state.js';

const HERE = new URL('.', import.meta.url);

let shared = null;
/** Loads and instantiates the wasm module once per page (the module is stateless). */
export function loadWasm() {
  if (!shared) {
    shared = import(new URL('pkg/wingbeat.js', HERE).href).then(async (m) => {
      await m.default({ module_or_path: new URL('pkg/wingbeat_bg.wasm', HERE) });
      return m;
    });
    shared.catch(() => { shared = null; });
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
 * Brings an `analyze` result to the current API contract, whichever wasm build produced it:
 * `spectra[k].stiffness_force` and `forces[k].stiffness_force` (older builds: `stiffness`).
 * The old key stays as an alias so either name reads the same series.
 */
export function normalise(a) {
  for (const group of [a.spectra || [], a.forces || []]) {
    for (const s of group) {
      if (!s) continue;
      if (s.stiffness_force == null && s.stiffness != null) s.stiffness_force = s.stiffness;
      if (s.stiffness == null && s.stiffness_force != null) s.stiffness = s.stiffness_force;
    }
  }
  return a;
}

/**
 * @param {{ load?: () => Promise<object>, createWorker?: () => Worker, feInput?: object }} [deps]
 *   `load` resolves to the wasm module's exports (default: loadWasm); `createWorker` makes the
 *   study worker (default: www/worker.js). Tests pass fakes.
 */
export function createEngine(deps = {}) {
  const load = deps.load || loadWasm;
  const createWorker = deps.createWorker || defaultWorker;
  const feInput = deps.feInput || FE_LAB_INPUT;
  let wb = null;
  let base = null;
  let worker = null;
  const jobs = new Map();
  let jobId = 0;
  let fePromise = null;
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
      return wb.limits();
    },
    /** The core's table of the lab's numeric parameters (wasm `parameters()`), or null in older builds. */
    parameters() {
      return wb && typeof wb.parameters === 'function' ? wb.parameters() : null;
    },
    /** The SimConfig for URL parameters: the paper table, or the FE wing's modes. */
    config(params) {
      const b = params.modes === 'fe' && fe ? { modes: fe.modes } : base;
      return toConfig(params, b);
    },
    /**
     * The live analysis of the selected mode: { cfg, k, analysis, angles, compute_ms }.
     * Throws the wasm error (its message names the field) for a rejected config.
     */
    analyze(params) {
      if (!wb) throw new Error('engine: wasm not loaded');
      const cfg = engine.config(params);
      const k = Number(params.mode) - 1;
      const t0 = now();
      const a = normalise(wb.analyze(cfg, { detrend: params.detrend, segment_len: 8192 }, k));
      const t1 = now();
      const res = { cfg, k, params, analysis: a, compute_ms: t1 - t0 };
      let angles = a.angles && a.angles.alpha ? a.angles : null;
      if (angles || typeof wb.anglesAt !== 'function') res.angles = angles;
      else {
        // Older wasm builds: ONE anglesAt call for the whole run, made when a view first reads
        // the angles (the 3-D view, on its next frame), so the slider's redraw does not wait.
        Object.defineProperty(res, 'angles', {
          enumerable: true,
          get() {
            if (!angles) angles = splitAngles(wb.anglesAt(cfg, a.sim.t));
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
        fePromise = engine.run('fe', { input: feInput }).promise.then(({ result }) => {
          fe = result;
          return fe;
        });
        fePromise.catch(() => { fePromise = null; });
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
