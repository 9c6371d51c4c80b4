// @ts-check
// The lab's engine: the ONLY module that talks to the wasm module and to the Web Workers.
// Views never call wasm; they read results from the store (www/store.js), which www/lab.js
// fills from this engine. This file wires the parts in www/engine/, one job each:
//   wasm.js      loading the wasm once per page, starting workers, reading anglesAt's output
//   protocol.js  the messages to and from www/worker.js (job kinds, replies, transfers)
//   requests.js  what a live recompute asks for, and the newest-wins queue of the live worker
//   jobs.js      the study worker's jobs: progress, errors, cancel
//   cache.js     the FE wings by input, the wing wanted vs in use, strains at the chosen point
// Unit-tested against a fake wasm object and fake workers in tests/js/engine*.test.mjs.
//
//   const engine = createEngine();              // browser defaults: pkg/ and worker.js in www/
//   const wb = await engine.load();
//   const r = engine.analyze(params, fe);       // live: simulate + forces + spectra + envelope + angles
//   const r = await engine.requestLive(params); // the same in the live worker; null when superseded
//   const job = engine.run('sweep', { cfg, opts }, (done, total) => …); await job.promise; engine.cancel(job.id);
//   const fe = await engine.ensureFe();         // the wing in use (default: the lab's FE wing), in the worker
//   engine.setWing(input); const job = engine.computeWing(input, onProgress);  // your own wing
//   engine.setKinematics(kin); engine.setStrainPoint([x_mm, y_mm]);            // see config()
//
// Your own wing: `wingInput(params, points)` builds the FemInput (wasm `wingInput`, which
// validates each key), `computeWing` solves it in the worker (progress, cancel) while the
// previous wing stays in use, and the FE results are kept per input (the last few), so switching
// back is instant. `config(params)` uses every mode of the wing in use, custom kinematics when
// set (the sliders' α, β, γ, phases and f_d then do not apply), and, when a strain point is set,
// the modes' modal strains there (wasm `modalStrainAt`).
//
// The live analysis runs off the main thread (`requestLive`, www/engine/requests.js): a second
// worker of worker.js, the live worker, separate from the study worker so that a sweep or the FE
// wing never delays a slider. It starts at the first parameter change (or focus in the lab) and
// gets the page's compiled wasm module (no second download); a request made while it loads waits
// for it (up to LIVE_START_WAIT_MS, then the page computes), and the first render and a page
// without workers compute on the main thread as `analyze` does. Results carry the
// kinematic angles on the simulation's time grid (`angles.alpha/beta/gamma`, from wasm
// `analyze`), so the 3-D view never crosses into wasm per frame.
//
// Two builds of the wasm module (scripts/build-web.sh, issue 25): `load()` resolves once the
// small live build has loaded (analysis, configs, outlines: the first plot needs nothing else)
// and starts loading the full build behind it (shell FE, sensing, the renderer); `loadFull()`
// resolves once that one is there. The study worker runs the full build, the live worker the
// live one. What needs the full build waits for it: the FE wing (ensureFe, computeWing) resolves
// only when the page has the full module too, so the modal strains of a wing in use are always
// at hand; the 3-D view awaits loadFull() before it asks for the renderer.
import { FE_LAB_INPUT, SAMPLE_RATE_HZ, WING, customWing } from './state.js';
import {
  createBuilds,
  loadWasm,
  defaultWorker,
  renderWorker,
  startWorker,
  startFullWorker,
  splitAngles,
} from './engine/wasm.js';
import { JOB } from './engine/protocol.js';
import { liveAsk, liveOverrides, createLiveQueue } from './engine/requests.js';
import { createJobs } from './engine/jobs.js';
import { createWings, createPointStrains, withWing, noWingInFluid } from './engine/cache.js';

export { loadWasm, splitAngles };
export { wingKey } from './engine/cache.js';

/** @typedef {import('./engine/wasm.js').Wasm} Wasm */
/** @typedef {import('./pkg/wingbeat.js').SimConfig} SimConfig */
/** @typedef {import('./pkg/wingbeat.js').Analysis} Analysis */
/** @typedef {import('./pkg/wingbeat.js').AngleSeries} AngleSeries */
/** @typedef {import('./engine/cache.js').FeModesResult} FeModesResult */
/** @typedef {import('./pkg/wingbeat.js').FemInput} FemInput */
/** @typedef {import('./pkg/wingbeat.js').Kinematics} Kinematics */
/** @typedef {import('./state.js').Params} Params */
/**
 * One live analysis: the config, the selected mode index k, the URL parameters it came from,
 * the wasm result, the angles on `analysis.sim.t` and the wasm time.
 * @typedef {{ cfg: SimConfig, k: number, params: Params, analysis: Analysis, angles: AngleSeries | null, compute_ms: number }} LiveResult
 */

const now = () => (typeof performance !== 'undefined' ? performance.now() : Date.now());

/**
 * The FemInput of a wing from the lab's wing parameters (www/state.js WING) and an outline
 * (mm; null = the core's default outline), in plain JS: the mapping of the core's `wingInput`
 * (src/params.rs), which the lab calls; tests/js/wing.test.mjs holds the two equal. The default
 * wing is exactly FE_LAB_INPUT (so its results are shared with the FE mode set of the paper
 * sliders).
 * @param {Params} params
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

/** The live result of a wasm analysis, with its angles. */
function liveResult(
  /** @type {ReturnType<typeof liveAsk>} */ ask,
  /** @type {Analysis} */ a,
  /** @type {number} */ ms,
) {
  /** @type {LiveResult} */
  const res = { cfg: ask.cfg, k: ask.k, params: ask.params, analysis: a, angles: a.angles, compute_ms: ms };
  return res;
}

/**
 * @param {{ load?: () => Promise<Wasm>, loadLive?: () => Promise<Wasm>, createWorker?: () => Worker, createLiveWorker?: () => Worker, createRenderWorker?: () => Worker, feInput?: FemInput }} [deps]
 *   `load` resolves to the full wasm module's exports (default: loadWasm), `loadLive` to the
 *   live build's (default: loadLive with the default `load`, else `load` itself);
 *   `createWorker` makes the study worker, `createLiveWorker` the live worker (default for
 *   both: www/worker.js). Tests pass fakes.
 */
// long: the engine's whole API object, one short documented method per operation (the logic is in engine/*.js)
export function createEngine(deps = {}) {
  const builds = createBuilds(deps.load, deps.loadLive);
  const loadFull = builds.full;
  /** The live build's exports (the first plot's), once loaded. @type {Wasm | null} */
  let wb = null;
  /** @type {SimConfig | null} */
  let base = null;
  /** @type {Kinematics | null} */
  let kin = null;
  /** @type {[number, number] | null} */
  let strainPoint = null;
  /** @type {Worker | null} a render worker started ahead (prewarmRender) */
  let spareRender = null;

  /** The wasm module, or a throw when it has not loaded yet. */
  const need = () => {
    if (!wb) throw new Error('engine: wasm not loaded');
    return wb;
  };
  /** The full build, or a throw when it has not loaded yet. */
  const needFull = () => {
    const wf = builds.loaded;
    if (!wf) throw new Error('engine: the full wasm module has not loaded yet');
    return wf;
  };
  /** The full build and the wing in use, or a throw. */
  const needFe = () => {
    const f = wings.fe;
    const wf = builds.loaded;
    if (!wf || !f) throw new Error('engine: no FE wing yet');
    return { w: wf, f };
  };
  /** wasm analyze of one ask on this thread, timed. */
  const analyzeHere = (/** @type {ReturnType<typeof liveAsk>} */ ask) => {
    const t0 = now();
    const a = need().analyze(ask.run, ask.opts, ask.k);
    return liveResult(ask, a, now() - t0);
  };

  const jobs = createJobs(() =>
    startFullWorker(deps.createWorker || defaultWorker, builds.fullModule(), builds.fullComing),
  );
  const live = createLiveQueue({
    start: () => startWorker(deps.createLiveWorker || defaultWorker, builds.liveModule(), 'live'),
    here: analyzeHere,
    fromWorker: (ask, a, ms) => liveResult(ask, a, ms),
  });
  const wings = createWings({
    initial: deps.feInput || FE_LAB_INPUT,
    // The wing is used once the page has the full build too (its modal strains need it).
    solve: (input, onProgress) => {
      const job = jobs.run(JOB.fe, { input, opts: { json: true } }, onProgress);
      return { ...job, promise: Promise.all([job.promise, loadFull()]).then(([r]) => r) };
    },
  });
  const modesAt = createPointStrains((f, p) =>
    needFull().modalStrainAt(f.nodes, f.triangles, f.strain_nodes, f.modes.length, p),
  );

  const engine = {
    /**
     * Resolves to the live build once loaded (and remembers its default config); the full
     * build starts loading then, behind it.
     */
    async load() {
      if (!wb) {
        const m = await builds.first();
        base = m.defaultConfig();
        wb = m;
        loadFull().catch(() => {});
      }
      return wb;
    },
    /** Resolves to the full build once loaded (loading it now if load() has not). */
    loadFull,
    get ready() {
      return !!wb;
    },
    /** Whether the full build has loaded. */
    get fullReady() {
      return !!builds.loaded;
    },
    /** The paper's default config (wasm defaultConfig), after load(). */
    get baseConfig() {
      return base;
    },
    /** The FE wing in use (else null). */
    get fe() {
      return wings.fe;
    },
    /** Whether the full build has loaded and has the renderer (WingView; false for a test's fake). */
    get hasRenderer() {
      const wf = builds.loaded;
      return !!wf && typeof wf.WingView === 'function';
    },
    /** The full build's WingView, for the views that draw the wing with the renderer. */
    get renderer() {
      const wf = builds.loaded;
      return wf && wf.WingView;
    },
    /**
     * Starts a render worker now, for renderWorker() to hand out later: its scripts and the
     * wasm glue load while the full build downloads, not after it (the 3-D view calls this when
     * it starts, before it waits for the full build).
     */
    prewarmRender() {
      if (!spareRender && typeof Worker === 'function') spareRender = (deps.createRenderWorker || renderWorker)();
    },
    /**
     * What the 3-D view needs to draw from a worker (www/render-worker.js): a new render worker,
     * the page's compiled full module for it, and the renderer's camera fit (WingView.fitCamera,
     * run on the page). Null while the full build is not loaded, or with a test's fake loaders.
     * @returns {{ worker: Worker, module: WebAssembly.Module, fitCamera: (cam: number[], xyz: Float32Array, margin: number, aspect: number) => ArrayLike<number> } | null}
     */
    renderWorker() {
      const module = builds.fullModule();
      const wf = builds.loaded;
      if (!module || !wf || typeof wf.WingView !== 'function' || typeof wf.WingView.fitCamera !== 'function')
        return null;
      const worker = spareRender || (deps.createRenderWorker || renderWorker)();
      spareRender = null;
      return {
        worker,
        module,
        fitCamera: (cam, xyz, margin, aspect) => wf.WingView.fitCamera(cam, xyz, margin, aspect),
      };
    },
    limits() {
      return need().limits();
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
     * @param {Params} params URL parameters (www/state.js)
     * @returns {SimConfig}
     */
    config(params) {
      const w = need();
      const b = { ...base, sample_rate_hz: SAMPLE_RATE_HZ };
      if (params.modes === 'fe' && wings.fe) b.modes = modesAt(wings.fe, strainPoint);
      else if (Number(params.air_density) > 0) throw new Error(noWingInFluid(params.air_density));
      // Custom kinematics: the table (or hand-edited series) is the whole stroke.
      if (kin) b.kinematics = kin;
      return w.applyOverrides(b, liveOverrides(params, !!kin));
    },
    /** `cfg` with the wing in use attached in a fluid (engine/cache.js withWing). */
    withWing(/** @type {SimConfig} */ cfg) {
      return withWing(cfg, wings.fe);
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
      const { w, f } = needFe();
      return w.modalStrainAt(f.nodes, f.triangles, f.strain_nodes, f.modes.length, [p[0], p[1]]);
    },
    /**
     * The whole-wing strain field per node (wasm strainField), for the strain map.
     * @param {(Float64Array | number[])[]} qs
     * @param {import('./pkg/wingbeat.js').StrainFieldOptions} opts
     */
    strainField(qs, opts) {
      const { w, f } = needFe();
      return w.strainField(f.strain_nodes, f.modes.length, qs, opts);
    },
    /** Built-in outlines (wasm `planforms()`), or [] before load. */
    planforms() {
      return wb ? wb.planforms() : [];
    },
    /** The core's wing parameter table (wasm `wingParameters()`) or null before load. */
    wingParameters() {
      return wb ? wb.wingParameters() : null;
    },
    /** The paper's material presets (wasm `materialPresets()`) or [] before load. */
    materialPresets() {
      return wb ? wb.materialPresets() : [];
    },
    /** Outline points (mm) from CSV or JSON text (wasm `parsePlanform`); throws the parse error. */
    parsePlanform(/** @type {string} */ text, /** @type {'csv' | 'json'} */ format) {
      return need().parsePlanform(text, format);
    },
    /** Live outline check (wasm `checkPlanform`): { ok, area_mm2, span_mm, chord_mm, default_mesh_size_mm } | { ok: false, error }. */
    checkPlanform(/** @type {[number, number][]} */ points) {
      return need().checkPlanform(points);
    },
    /** Measured kinematics from CSV text (wasm `kinematicsFromCsv`). */
    kinematicsFromCsv(
      /** @type {string} */ text,
      /** @type {import('./pkg/wingbeat.js').CsvKinematicsOptions} */ opts,
    ) {
      return need().kinematicsFromCsv(text, opts);
    },
    /**
     * A `wingbeat modes` JSON document → { modes, fe? } (wasm `modesFromJson`). The modes come
     * out of the core's serializer, so every field of each is there (strains included).
     * @param {string} text
     * @returns {{ modes: Required<import('./pkg/wingbeat.js').Mode>[], fe?: import('./pkg/wingbeat.js').ImportedFe }}
     */
    modesFromJson(text) {
      return /** @type {{ modes: Required<import('./pkg/wingbeat.js').Mode>[] }} */ (needFull().modesFromJson(text));
    },
    /** The kinematic angles (rad) at times t for a config: { alpha, beta, gamma } (wasm anglesAt). */
    anglesAt(/** @type {SimConfig} */ cfg, /** @type {Float64Array} */ t) {
      return splitAngles(need().anglesAt(cfg, t));
    },
    /**
     * The FemInput of a wing (wasm `wingInput`, so the core validates every key: its error
     * names the key and the range); the default wing is the lab's FE wing.
     * @param {Params} params
     * @param {[number, number][] | null} points
     * @returns {FemInput}
     */
    wingInput(params, points) {
      if (!points && !customWing(params)) return { ...FE_LAB_INPUT };
      /** @type {Record<string, number>} */
      const o = {};
      for (const w of WING) o[w.core] = Number(params[w.key]);
      return need().wingInput(o, points || undefined);
    },
    /** Makes `input` the wing wanted (ensureFe() computes it; config() keeps the old one until then). */
    setWing(/** @type {FemInput} */ input) {
      wings.want(input);
    },
    /** Whether the wing in use is the one wanted. */
    get wingCurrent() {
      return wings.current;
    },
    /**
     * Solves a wing in the worker (wasm feModes with the modes JSON document), with progress;
     * on success it becomes the wing in use. Returns { id, promise } (cancel with cancel(id)).
     * @param {FemInput} input
     * @param {(done: number, total: number) => void} [onProgress]
     * @returns {{ id: number, promise: Promise<FeModesResult> }}
     */
    computeWing(input, onProgress) {
      return wings.compute(input, onProgress);
    },
    /** Uses an already computed or imported FE result as the wing in use (modes JSON import). */
    useFe(/** @type {FeModesResult} */ r, /** @type {string} */ key) {
      wings.use(r, key);
    },
    /**
     * The wing wanted (default: the lab's FE wing), computed once in the worker; resolves at
     * once when it is ready. A rejected computation is retried on the next call.
     * @param {FemInput} [input] the wing (default: the one set by setWing)
     * @returns {Promise<FeModesResult>}
     */
    ensureFe(input) {
      return wings.ensure(input);
    },
    /**
     * The live analysis of the selected mode on this thread: { cfg, k, analysis, angles,
     * compute_ms }. Throws the wasm error (its message names the field) for a rejected config.
     * @param {Params} params URL parameters (www/state.js)
     * @returns {LiveResult}
     */
    analyze(params) {
      need();
      const cfg = engine.config(params);
      return analyzeHere(liveAsk(params, cfg, engine.withWing(cfg)));
    },
    /**
     * The live analysis of `params` in the live worker: resolves to the same LiveResult as
     * analyze(), or to null when a newer request superseded this one before its result was
     * ready (draw nothing then: the newer one's result follows). The config is built here, on
     * the main thread, so a value the core rejects throws at once (naming the key); an error of
     * the computation itself rejects the newest request's promise.
     * @param {Params} params URL parameters (www/state.js)
     * @returns {Promise<LiveResult | null>}
     */
    requestLive(params) {
      need();
      const cfg = engine.config(params);
      return live.request(liveAsk(params, cfg, engine.withWing(cfg)));
    },
    /** Starts the live worker now (its wasm loads while the first result is computed here). */
    warmLive() {
      live.warm();
    },
    /** Whether live requests go to the live worker (false: computed on the main thread). */
    get liveInWorker() {
      return live.inWorker;
    },
    /** Counters of live requests: posted to the worker, superseded while waiting, stale results dropped, computed on the main thread. */
    get liveStats() {
      return live.stats;
    },
    /**
     * Runs a study in the worker: kind ∈ JOB of www/engine/protocol.js (see www/worker.js).
     * Returns { id, promise } where promise resolves to { result, ms }.
     * @param {string} kind
     * @param {Record<string, any>} [payload]
     * @param {(done: number, total: number) => void} [onProgress]
     */
    run(kind, payload, onProgress) {
      // A study's config in a fluid carries the wing in use (its mesh and shapes), as a live one does.
      const p = payload && payload.cfg ? { ...payload, cfg: engine.withWing(payload.cfg) } : payload;
      return jobs.run(kind, p, onProgress);
    },
    /**
     * The resonance map (wasm `resonanceMap`, run in the worker): Floquet f_eff and largest
     * |multiplier| of every mode over opts = { from_hz, to_hz, points, alpha0_values? }.
     * Same return value as run(): { id, promise } (cancel with cancel(id)).
     * @param {SimConfig} cfg
     * @param {import('./pkg/wingbeat.js').ResonanceOptions} opts
     * @param {(done: number, total: number) => void} [onProgress]
     */
    resonanceMap(cfg, opts, onProgress) {
      return jobs.run(JOB.resonance, { cfg: engine.withWing(cfg), opts }, onProgress);
    },
    /** Whether job `id` is still running. */
    running(/** @type {number} */ id) {
      return jobs.running(id);
    },
    /**
     * Cancels job `id`. A wasm call cannot be interrupted, so the worker is terminated (the
     * other jobs in it fail with "cancelled" too) and a fresh one starts on the next run.
     */
    cancel(/** @type {number} */ id) {
      return jobs.cancel(id);
    },
    /** Stops the workers (element removed from the page). */
    dispose() {
      jobs.dispose();
      live.dispose();
    },
  };
  return engine;
}
