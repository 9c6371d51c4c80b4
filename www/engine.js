// @ts-check
// The lab's engine: the ONLY module that talks to the wasm module and to the Web Worker.
// Views never call wasm; they read results from the store (www/store.js), which www/lab.js
// fills from this engine. Unit-tested against a fake wasm object and a fake worker in
// tests/js/engine.test.mjs.
//
//   const engine = createEngine();              // browser defaults: pkg/ and worker.js next to this file
//   const wb = await engine.load();
//   const r = engine.analyze(params, fe);       // live: simulate + forces + spectra + envelope + angles
//   const r = await engine.requestLive(params); // the same in the live worker; null when superseded
//   const job = engine.run('sweep', { cfg, opts }, (done, total) => …); await job.promise; engine.cancel(job.id);
//   const fe = await engine.ensureFe();         // the wing in use (default: the lab's FE wing), in the worker
//   engine.setWing(input); const job = engine.computeWing(input, onProgress);  // your own wing
//   engine.setKinematics(kin); engine.setStrainPoint([x_mm, y_mm]);            // see config()
//
// Your own wing: `wingInput(params, points)` builds the FemInput (wasm `wingInput` when the
// build has it, which validates each key), `computeWing` solves it in the worker (progress,
// cancel) while the previous wing stays in use, and the FE results are kept per input (the
// last few), so switching back is instant. `config(params)` uses every mode of the wing in
// use, custom kinematics when set (the sliders' α, β, γ, phases and f_d then do not apply),
// and, when a strain point is set, the modes' modal strains there (wasm `modalStrainAt`).
//
// The live analysis runs off the main thread (`requestLive`): a second worker of worker.js, the
// live worker, separate from the study worker so that a sweep or the FE wing never delays a
// slider. A wasm call cannot be interrupted, so requests are coalesced instead: at most one is
// in flight and one waits; a newer request replaces the waiting one (which resolves to null)
// and makes the one in flight stale (its result, when it comes, resolves to null and is not
// drawn). Only the newest request's result reaches the caller. The live worker starts at the
// first parameter change and gets the page's compiled wasm module (no second download); until
// it has loaded, and when workers are unavailable, requestLive computes on the main thread as
// `analyze` does.
//
// Results carry the kinematic angles on the simulation's time grid (`angles.alpha/beta/gamma`),
// from wasm `analyze` when it provides them and otherwise from ONE `anglesAt` call per
// recompute (made lazily, on first read), so the 3-D view never crosses into wasm per frame.
import { overridesOf, FE_LAB_INPUT, SAMPLE_RATE_HZ, WING, customWing } from './state.js';

/** @typedef {typeof import('./pkg/wingbeat.js')} Wasm the wasm module's exports (www/pkg/wingbeat.d.ts) */
/** @typedef {import('./pkg/wingbeat.js').SimConfig} SimConfig */
/** @typedef {import('./pkg/wingbeat.js').Analysis} Analysis */
/** @typedef {import('./pkg/wingbeat.js').AngleSeries} AngleSeries */
/** @typedef {import('./pkg/wingbeat.js').FeModesResult & { modes_json?: string, max_nodes?: number, imported?: boolean }} FeModesResult */
/** @typedef {import('./pkg/wingbeat.js').FemInput} FemInput */
/** @typedef {import('./pkg/wingbeat.js').Kinematics} Kinematics */
/**
 * One live analysis: the config, the selected mode index k, the URL parameters it came from,
 * the wasm result, the angles on `analysis.sim.t` and the wasm time.
 * @typedef {{ cfg: SimConfig, k: number, params: import('./state.js').Params, analysis: Analysis, angles: AngleSeries | null, compute_ms: number }} LiveResult
 */
/** @typedef {{ resolve: (v: { result: any, ms: number }) => void, reject: (e: Error) => void, progress: (done: number, total: number) => void, kind: string }} Job */

const HERE = new URL('.', import.meta.url);

/** @type {Promise<Wasm> | null} */
let shared = null;
/** @type {WebAssembly.Module | null} the compiled wasm, handed to the workers (no second download or compile) */
let compiled = null;

/** Compiles the wasm (streaming when the server sends application/wasm, else from its bytes). */
async function compileWasm(/** @type {URL} */ url) {
  const res = await fetch(url);
  if (!res.ok) throw new Error(`${url.pathname}: HTTP ${res.status}`);
  if (typeof WebAssembly.compileStreaming === 'function' && (res.headers.get('content-type') || '').startsWith('application/wasm')) {
    return WebAssembly.compileStreaming(res);
  }
  return WebAssembly.compile(await res.arrayBuffer());
}

/** Loads and instantiates the wasm module once per page (the module is stateless). */
export function loadWasm() {
  if (!shared) {
    /** @type {Promise<Wasm>} */
    const p = import(new URL('pkg/wingbeat.js', HERE).href).then(async (/** @type {Wasm} */ m) => {
      const mod = await compileWasm(new URL('pkg/wingbeat_bg.wasm', HERE));
      await m.default({ module_or_path: mod });
      compiled = mod;
      return m;
    });
    shared = p;
    p.catch(() => { shared = null; });
    return p;
  }
  return shared;
}

/** @type {string | null} the same-origin Blob URL that imports worker.js (made once) */
let bootstrapUrl = null;
/**
 * The study worker. Same origin: worker.js itself. When this module was loaded from another
 * origin (a course page using the lab's files from the lab's host, which must send CORS
 * headers), `new Worker(url)` would be refused, so the worker starts from a same-origin Blob
 * whose only line imports worker.js by its absolute URL; worker.js then loads the wasm relative
 * to its own URL (import.meta.url), i.e. from the lab's host.
 */
function defaultWorker() {
  const url = new URL('worker.js', HERE);
  if (typeof location === 'undefined' || url.origin === location.origin) return new Worker(url, { type: 'module' });
  if (!bootstrapUrl) bootstrapUrl = URL.createObjectURL(new Blob([`import ${JSON.stringify(url.href)};\n`], { type: 'text/javascript' }));
  return new Worker(bootstrapUrl, { type: 'module' });
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

/** The key under which an FE result is kept: its input (and strain point request). */
export const wingKey = (input) => JSON.stringify(input || null);

/**
 * The FemInput of a wing from the lab's wing parameters (www/state.js WING) and an outline
 * (mm; null = the core's default outline), in plain JS: the same mapping as the core's
 * `wingInput` (src/params.rs), used when the wasm build does not have it. The default wing is
 * exactly FE_LAB_INPUT (so its results are shared with the FE mode set of the paper sliders).
 * @param {import('./state.js').Params} params
 * @param {[number, number][] | null} points
 * @returns {FemInput}
 */
export function plainWingInput(params, points) {
  if (!points && !customWing(params)) return { ...FE_LAB_INPUT };
  /** @type {FemInput} */
  const input = {
    camber: params.camber,
    clamp: params.clamp > 0 ? { strip: { x_mm: params.clamp } } : 'root',
    material: { thickness_m: params.thickness_um / 1e6, e_pa: params.e_pa, rho_kg_m3: params.rho, nu: params.nu },
    n_modes: params.n_modes,
  };
  if (params.mesh_mm > 0) input.mesh_size_mm = params.mesh_mm;
  if (points) input.planform_mm = points.map((p) => [p[0], p[1]]);
  return input;
}

/** How many FE results are kept (each is a few MB of typed arrays at most). */
const FE_CACHE = 4;

/**
 * @param {{ load?: () => Promise<Wasm>, createWorker?: () => Worker, createLiveWorker?: () => Worker, feInput?: import('./pkg/wingbeat.js').FemInput }} [deps]
 *   `load` resolves to the wasm module's exports (default: loadWasm); `createWorker` makes the
 *   study worker, `createLiveWorker` the live worker (default for both: www/worker.js). Tests
 *   pass fakes.
 */
export function createEngine(deps = {}) {
  const load = deps.load || loadWasm;
  const createWorker = deps.createWorker || defaultWorker;
  const createLiveWorker = deps.createLiveWorker || defaultWorker;
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
  /** The wing wanted now (its FemInput), and the FE results by wingKey (last FE_CACHE). */
  /** @type {FemInput} */
  let wanted = feInput;
  /** @type {Map<string, FeModesResult>} */
  const feCache = new Map();
  /** @type {Map<string, { id: number, promise: Promise<FeModesResult> }>} */
  const fePending = new Map();
  /** The wing in use (the last one ready that was wanted); stays until a new one is ready. */
  /** @type {FeModesResult | null} */
  let fe = null;
  /** @type {Kinematics | null} */
  let kin = null;
  /** @type {[number, number] | null} */
  let strainPoint = null;
  /** @type {{ fe: FeModesResult, key: string, strains: { eps_x: number, eps_y: number, gamma_xy: number }[] } | null} */
  let strainCache = null;

  // ---- the live worker (see the top of this file) ----
  /** @typedef {{ seq: number, cfg: SimConfig, k: number, params: import('./state.js').Params, opts: import('./pkg/wingbeat.js').WelchOptions, resolve: (r: LiveResult | null) => void, reject: (e: Error) => void }} LiveRequest */
  /** @type {Worker | null} */
  let live = null;
  /** the live worker has loaded its wasm (it said { ready: true }) */
  let liveReady = false;
  /** workers cannot be made here (no Worker, or the live worker failed): compute on the main thread */
  let liveBroken = false;
  /** the newest request's number: any other request's result is stale */
  let liveSeq = 0;
  /** @type {LiveRequest | null} the request the live worker is computing */
  let inflight = null;
  /** @type {LiveRequest | null} the newest request, waiting for the one in flight */
  let queued = null;
  const liveStats = { posted: 0, superseded: 0, stale: 0, sync: 0 };

  /** The live result of a wasm analysis (angles: from the analysis, else ONE lazy anglesAt call). */
  function liveResult(cfg, k, params, a, ms) {
    const w = /** @type {Wasm} */ (wb);
    /** @type {LiveResult} */
    const res = { cfg, k, params, analysis: a, angles: null, compute_ms: ms };
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
  }

  /** The page's compiled wasm module (loadWasm; null with a test's fake), handed to new workers. */
  function wasmModule() {
    return load === loadWasm ? compiled : null;
  }

  /** A new worker, given the page's compiled wasm first when there is one. */
  function startWorker(/** @type {() => Worker} */ make) {
    const w = make();
    const m = wasmModule();
    if (m) w.postMessage({ wasmModule: m });
    return w;
  }

  /** The live worker (made on first use), or null when workers are unavailable. */
  function liveWorker() {
    if (live || liveBroken) return live;
    try {
      live = startWorker(createLiveWorker);
    } catch {
      liveBroken = true;
      return null;
    }
    live.onmessage = (ev) => {
      const d = ev.data || {};
      if (d.ready) {
        liveReady = true;
        return;
      }
      const req = inflight;
      if (!req || d.id !== req.seq || d.progress) return;
      inflight = null;
      if (req.seq !== liveSeq) {
        liveStats.stale++;
        req.resolve(null);
      } else if (d.error != null) req.reject(new Error(d.error));
      else req.resolve(liveResult(req.cfg, req.k, req.params, d.result, d.ms));
      if (queued) {
        const q = queued;
        queued = null;
        postLive(q);
      }
    };
    live.onerror = () => {
      // The live worker could not start (or died): from now on compute on the main thread,
      // the newest request included.
      liveBroken = true;
      liveReady = false;
      if (live) live.terminate();
      live = null;
      const waiting = [inflight, queued];
      inflight = queued = null;
      for (const r of waiting) if (r) settleSync(r);
    };
    return live;
  }

  /** @param {LiveRequest} req */
  function postLive(req) {
    inflight = req;
    liveStats.posted++;
    /** @type {Worker} */ (live).postMessage({ id: req.seq, kind: 'analyze', cfg: req.cfg, opts: req.opts, k: req.k });
  }

  /** Computes a request on the main thread (or resolves null when it is no longer the newest). */
  function settleSync(/** @type {LiveRequest} */ req) {
    if (req.seq !== liveSeq) {
      req.resolve(null);
      return;
    }
    try {
      const t0 = now();
      const a = /** @type {Wasm} */ (wb).analyze(req.cfg, req.opts, req.k);
      liveStats.sync++;
      req.resolve(liveResult(req.cfg, req.k, req.params, a, now() - t0));
    } catch (e) {
      req.reject(/** @type {Error} */ (e));
    }
  }

  function remember(key, r) {
    feCache.delete(key);
    feCache.set(key, r);
    while (feCache.size > FE_CACHE) feCache.delete(/** @type {string} */ (feCache.keys().next().value));
  }

  /** The modes of the wing in use, with modal strains at the chosen point when one is set. */
  function feModesNow() {
    const f = /** @type {FeModesResult} */ (fe);
    if (!strainPoint) return f.modes;
    const w = /** @type {Wasm} */ (wb);
    const key = `${strainPoint[0]},${strainPoint[1]}`;
    if (!strainCache || strainCache.fe !== f || strainCache.key !== key) {
      const fn = /** @type {any} */ (w).modalStrainAt;
      if (typeof fn !== 'function') throw new Error('this wasm build has no modalStrainAt: rebuild www/pkg (scripts/build-web.sh www)');
      const n = f.modes.length;
      strainCache = { fe: f, key, strains: fn(f.nodes, f.triangles, f.strain_nodes, n, [strainPoint[0], strainPoint[1]]) };
    }
    const st = strainCache.strains;
    const name = 'S';
    return f.modes.map((m, k) => ({ ...m, strains: [{ point: name, eps_x: st[k].eps_x, eps_y: st[k].eps_y, gamma_xy: st[k].gamma_xy }] }));
  }

  function failAll(why) {
    for (const j of jobs.values()) j.reject(new Error(why));
    jobs.clear();
  }

  function ensureWorker() {
    if (!worker) {
      worker = startWorker(createWorker);
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
      if (params.modes === 'fe' && fe) b.modes = feModesNow();
      const o = overridesOf(params);
      if (kin) {
        // Custom kinematics: the table (or hand-edited series) is the whole stroke, so the
        // sliders' amplitudes, phases and flap frequency do not apply; ζ and duration do.
        b.kinematics = kin;
        for (const k of ['alpha0', 'beta0', 'gamma0', 'alpha_phase', 'beta_phase', 'gamma_phase', 'flap_hz']) delete o[k];
      }
      return wb.applyOverrides(b, o);
    },
    /** Custom kinematics (the core's Kinematics) or null for the sliders' Fourier kinematics. */
    setKinematics(/** @type {Kinematics | null} */ k) {
      kin = k;
    },
    get kinematics() {
      return kin;
    },
    /** The strain point (mm) for the modes' modal strains, or null for the FE result's own point. */
    setStrainPoint(/** @type {[number, number] | null} */ p) {
      strainPoint = p ? [Number(p[0]), Number(p[1])] : null;
    },
    get strainPoint() {
      return strainPoint;
    },
    /**
     * The modal strains of the wing in use at a point (mm): per mode { eps_x, eps_y, gamma_xy }
     * per unit q (wasm modalStrainAt). Throws, naming the point, when it is outside the mesh.
     * @param {[number, number]} p
     */
    modalStrainAt(p) {
      if (!wb || !fe) throw new Error('engine: no FE wing yet');
      return /** @type {any} */ (wb).modalStrainAt(fe.nodes, fe.triangles, fe.strain_nodes, fe.modes.length, [p[0], p[1]]);
    },
    /** The whole-wing strain field per node (wasm strainField), for the strain map. */
    strainField(qs, opts) {
      if (!wb || !fe) throw new Error('engine: no FE wing yet');
      return /** @type {any} */ (wb).strainField(fe.strain_nodes, fe.modes.length, qs, opts);
    },
    /** Whether this wasm build has `name` (new exports are detected, not assumed). */
    has(name) {
      return !!wb && typeof /** @type {any} */ (wb)[name] === 'function';
    },
    /** Built-in outlines (wasm `planforms()`), or [] when the build lacks it. */
    planforms() {
      return engine.has('planforms') ? /** @type {any} */ (wb).planforms() : [];
    },
    /** The core's wing parameter table (wasm `wingParameters()`) or null. */
    wingParameters() {
      return engine.has('wingParameters') ? /** @type {any} */ (wb).wingParameters() : null;
    },
    /** The paper's material presets (wasm `materialPresets()`) or []. */
    materialPresets() {
      return engine.has('materialPresets') ? /** @type {any} */ (wb).materialPresets() : [];
    },
    /** Outline points (mm) from CSV or JSON text (wasm `parsePlanform`); throws the parse error. */
    parsePlanform(/** @type {string} */ text, /** @type {'csv' | 'json'} */ format) {
      if (!engine.has('parsePlanform')) throw new Error('this wasm build cannot parse outlines: rebuild www/pkg');
      return /** @type {any} */ (wb).parsePlanform(text, format);
    },
    /** Live outline check (wasm `checkPlanform`): { ok, area_mm2, span_mm, chord_mm, default_mesh_size_mm } | { ok: false, error }. */
    checkPlanform(/** @type {[number, number][]} */ points) {
      if (!engine.has('checkPlanform')) return { ok: true };
      return /** @type {any} */ (wb).checkPlanform(points);
    },
    /** Measured kinematics from CSV text (wasm `kinematicsFromCsv`). */
    kinematicsFromCsv(/** @type {string} */ text, /** @type {{ units: 'deg' | 'rad', flap_hz: number, max_harmonic?: number }} */ opts) {
      if (!engine.has('kinematicsFromCsv')) throw new Error('this wasm build cannot read kinematics CSV: rebuild www/pkg');
      return /** @type {any} */ (wb).kinematicsFromCsv(text, opts);
    },
    /** A `wingbeat modes` JSON document → { modes, fe? } (wasm `modesFromJson`). */
    modesFromJson(/** @type {string} */ text) {
      if (!engine.has('modesFromJson')) throw new Error('this wasm build cannot read modes JSON: rebuild www/pkg');
      return /** @type {any} */ (wb).modesFromJson(text);
    },
    /** The kinematic angles (rad) at times t for a config: { alpha, beta, gamma } (wasm anglesAt). */
    anglesAt(/** @type {SimConfig} */ cfg, /** @type {Float64Array} */ t) {
      if (!wb) throw new Error('engine: wasm not loaded');
      return splitAngles(wb.anglesAt(cfg, t));
    },
    /**
     * The FemInput of a wing (see plainWingInput); through wasm `wingInput` when the build has
     * it, so the core validates every key (its error names the key and the range).
     * @param {import('./state.js').Params} params
     * @param {[number, number][] | null} points
     * @returns {FemInput}
     */
    wingInput(params, points) {
      if (!points && !customWing(params)) return { ...FE_LAB_INPUT };
      if (engine.has('wingInput')) {
        /** @type {Record<string, number>} */
        const o = {};
        for (const w of WING) o[w.core] = Number(params[w.key]);
        return /** @type {any} */ (wb).wingInput(o, points || undefined);
      }
      return plainWingInput(params, points);
    },
    /** Makes `input` the wing wanted (ensureFe() computes it; config() keeps the old one until then). */
    setWing(/** @type {FemInput} */ input) {
      wanted = input;
      const r = feCache.get(wingKey(input));
      if (r) fe = r;
    },
    /** Whether the wing in use is the one wanted. */
    get wingCurrent() {
      return !!fe && feCache.get(wingKey(wanted)) === fe;
    },
    /**
     * Solves a wing in the worker (wasm feModes with the modes JSON document), with progress;
     * on success it becomes the wing in use. Returns { id, promise } (cancel with cancel(id)).
     * @param {FemInput} input
     * @param {(done: number, total: number) => void} [onProgress]
     * @returns {{ id: number, promise: Promise<FeModesResult> }}
     */
    computeWing(input, onProgress) {
      const key = wingKey(input);
      const have = feCache.get(key);
      if (have) {
        wanted = input;
        fe = have;
        return { id: 0, promise: Promise.resolve(have) };
      }
      const pend = fePending.get(key);
      if (pend) return pend;
      const job = engine.run('fe', { input, opts: { json: true } }, onProgress);
      const promise = job.promise.then(({ result }) => {
        const r = /** @type {FeModesResult} */ (result);
        remember(key, r);
        if (wingKey(wanted) === key || !fe) fe = r;
        return r;
      });
      const entry = { id: job.id, promise };
      fePending.set(key, entry);
      const done = () => { if (fePending.get(key) === entry) fePending.delete(key); };
      promise.then(done, done);
      return entry;
    },
    /** Uses an already computed or imported FE result as the wing in use (modes JSON import). */
    useFe(/** @type {FeModesResult} */ r, /** @type {string} */ key) {
      remember(key, r);
      wanted = /** @type {any} */ ({ imported: key });
      feCache.set(wingKey(wanted), r);
      fe = r;
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
      return liveResult(cfg, k, params, a, now() - t0);
    },
    /**
     * The live analysis of `params` in the live worker (see the top of this file): resolves to
     * the same LiveResult as analyze(), or to null when a newer request superseded this one
     * before its result was ready (draw nothing then: the newer one's result follows). The
     * config is built here, on the main thread, so a value the core rejects throws at once
     * (naming the key); an error of the computation itself rejects the newest request's promise.
     * Until the live worker is ready (or without workers) it computes here, as analyze().
     * @param {import('./state.js').Params} params URL parameters (www/state.js)
     * @returns {Promise<LiveResult | null>}
     */
    requestLive(params) {
      if (!wb) throw new Error('engine: wasm not loaded');
      const cfg = engine.config(params);
      const seq = ++liveSeq;
      return new Promise((resolve, reject) => {
        /** @type {LiveRequest} */
        const req = { seq, cfg, k: Number(params.mode) - 1, params, opts: /** @type {import('./pkg/wingbeat.js').WelchOptions} */ ({ detrend: params.detrend, segment_len: 8192 }), resolve, reject };
        if (queued) {
          liveStats.superseded++;
          queued.resolve(null);
          queued = null;
        }
        // The first request (the first render) does not start the live worker: a lab that is
        // only looked at never loads a second worker; the first parameter change does.
        const w = seq > 1 ? liveWorker() : live;
        if (!w || !liveReady) settleSync(req);
        else if (inflight) queued = req;
        else postLive(req);
      });
    },
    /** Starts the live worker now (its wasm loads while the first result is computed here). */
    warmLive() {
      liveWorker();
    },
    /** Whether live requests go to the live worker (false: computed on the main thread). */
    get liveInWorker() {
      return !!live && liveReady;
    },
    /** Counters of live requests: posted to the worker, superseded while waiting, stale results dropped, computed on the main thread. */
    get liveStats() {
      return { ...liveStats };
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
      return true;
    },
    /**
     * The wing wanted (default: the lab's FE wing), computed once in the worker; resolves at
     * once when it is ready. A rejected computation is retried on the next call.
     * @param {FemInput} [input] the wing (default: the one set by setWing)
     * @returns {Promise<FeModesResult>}
     */
    ensureFe(input) {
      if (input) engine.setWing(input);
      const r = feCache.get(wingKey(wanted));
      if (r) {
        fe = r;
        return Promise.resolve(r);
      }
      const job = engine.computeWing(wanted);
      return job.promise;
    },
    /** Stops the worker (element removed from the page). */
    dispose() {
      if (worker) worker.terminate();
      worker = null;
      failAll('disposed');
      if (live) live.terminate();
      live = null;
      liveReady = false;
      liveSeq++;
      for (const r of [inflight, queued]) if (r) r.resolve(null);
      inflight = queued = null;
    },
  };
  return engine;
}
