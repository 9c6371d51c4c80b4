// @ts-check
// Web Worker for the lab's expensive studies, so sliders never freeze: parameter sweeps
// (Fig. 6), the initial-condition map (Fig. 7), long damped runs (Fig. 8), the resonance map
// (Floquet numbers over flap frequency and α0), the paper report, the FE wing (`fe`), the
// sensing analysis (`sense`) and the live analysis of the sliders (`analyze`).
// Its messages are built and read by www/engine/protocol.js (the engine uses the same module):
// a first { wasmModule } hands over the page's compiled module, { ready: true } says the wasm
// has loaded, then per job { id, kind, ...inputs } in and progress, a result (typed arrays
// transferred, not copied) or an error out. The lab runs two of these workers: one for the
// studies (and `fe`), one for the live `analyze` of the sliders (www/engine/requests.js), so
// neither waits for the other.
import { decimate } from './decimate.js';
import { WWW } from './base.js';
import { VARIANT_FILES } from './engine/wasm.js';
import { errorText } from './format.js';
import {
  JOB,
  readRequest,
  readyMessage,
  progressMessage,
  resultMessage,
  errorMessage,
  transferList,
} from './engine/protocol.js';

/**
 * The wasm, loaded on the first message: the page's own compiled module when the engine sends
 * it first ({ wasmModule, variant }: no second download or compile; the live worker gets the
 * small live build, www/engine/wasm.js), else the full build fetched next to this file. The
 * glue is imported to match the module (the two builds' glue differ).
 * @type {Promise<unknown> | null}
 */
let ready = null;
/**
 * While the page has said its compiled module follows ({ wasmPending: true }): resolves to it,
 * or to undefined when the page says it will not come after all.
 * @type {Promise<{ module: WebAssembly.Module, variant: 'live' | 'full' } | undefined> | null}
 */
let pending = null;
/** @type {((m: { module: WebAssembly.Module, variant: 'live' | 'full' } | undefined) => void) | null} */
let deliver = null;

/**
 * The loaded module's exports, set before `ready` resolves (typed as the full build; the live
 * build has a subset, and the live worker is only given `analyze` jobs).
 * @type {typeof import('./pkg/wingbeat.js')}
 */
let wb = /** @type {any} */ (null);
function start(/** @type {WebAssembly.Module | undefined} */ module, variant = 'full') {
  if (!ready) {
    const files = VARIANT_FILES[variant === 'live' ? 'live' : 'full'];
    ready = import(new URL(files.glue, WWW).href).then(async (m) => {
      await m.default({ module_or_path: module || new URL(files.wasm, WWW) });
      wb = m;
    });
    // Tells the engine that the wasm is loaded (the live worker is used once it is).
    ready.then(
      () => scope.postMessage(readyMessage()),
      () => {},
    );
  }
  return ready;
}

/**
 * The jobs by kind (www/engine/protocol.js JOB): each gets the job's message and a progress
 * callback, and returns the result to post.
 * @type {Record<string, (job: Record<string, any>, progress: (done: number, total: number) => void) => unknown>}
 */
const jobs = {
  [JOB.sweep]({ cfg, opts }, progress) {
    return wb.sweep(cfg, opts, progress);
  },
  [JOB.icmap]({ cfg, opts }) {
    return wb.icMap(cfg, opts);
  },
  [JOB.damping]({ cfg, opts }, progress) {
    // Fig. 8: the same case undamped and with ζ = opts.zeta over a longer run.
    const mode = opts.mode;
    const out = { zeta: opts.zeta, duration_s: cfg.duration_s, mode };
    const runs = [];
    for (const [i, z] of [0, opts.zeta].entries()) {
      const c = { ...cfg, modes: cfg.modes.map((m) => ({ ...m, zeta: z })) };
      const r = wb.simulate(c);
      runs.push(r);
      progress(i + 1, 2);
    }
    const t = runs[0].t;
    const [x, undamped, damped] = decimate(
      t,
      runs.map((r) => r.modes[mode].q.total),
      1500,
    );
    Object.assign(out, {
      t: x,
      undamped,
      damped,
      floquet: runs.map((r) => r.modes[mode].floquet),
      n: t.length,
    });
    return out;
  },
  [JOB.resonance]({ cfg, opts }, progress) {
    // Floquet effective frequency and largest |multiplier| per flap frequency (and α0).
    return wb.resonanceMap(cfg, opts, progress);
  },
  [JOB.reproduce]() {
    return wb.reproduce();
  },
  [JOB.analyze]({ cfg, opts, k }) {
    // The live analysis (engine.requestLive, run in the lab's own live worker so that a study
    // or the FE wing never delays it): the same wasm `analyze` the main thread would call; its
    // result carries the angles on sim.t.
    return wb.analyze(cfg, opts, k);
  },
  [JOB.fe]({ input, opts }, progress) {
    // Shell FE modes of the wing (mesh, assembly, shift-invert eigen-solve): about a second for
    // the default wing. `opts` = { json?, strain_point_mm? } (the modes JSON document for
    // export). One wasm call: progress says only that it started; Cancel ends the worker.
    progress(0, 1);
    const r = wb.feModes(input, null, opts || undefined);
    progress(1, 1);
    return r;
  },
  [JOB.sense]({ cfg, fe, body_rate, opts }, progress) {
    // Sensing body rotation (wasm senseRotation): two runs of the FE wing's modes
    // (with and without the body rate), the detectability map, the greedy sensors and Δε at a
    // point; progress after each stage. `fe` = { nodes, triangles, strain_nodes } of feModes.
    return wb.senseRotation(cfg, fe.nodes, fe.triangles, fe.strain_nodes, body_rate, opts || undefined, progress);
  },
  [JOB.classify]({ opts }, progress) {
    // Sensing as the published studies measure it (wasm classifyRotation): the published plate,
    // two runs from rest, encoding and classification; `opts` is the request. Progress after the
    // FE solve and each stage.
    return wb.classifyRotation(opts, progress);
  },
};

/** The worker's global scope (a DedicatedWorkerGlobalScope; tsconfig's lib is the page's DOM). */
const scope =
  /** @type {{ postMessage(message: unknown, transfer?: Transferable[]): void, onmessage: ((ev: MessageEvent) => void) | null }} */ (
    /** @type {unknown} */ (self)
  );

scope.onmessage = async (ev) => {
  const req = readRequest(ev.data);
  if ('wasmPending' in req) {
    if (req.wasmPending && !ready && !pending) pending = new Promise((resolve) => (deliver = resolve));
    else if (!req.wasmPending && deliver) deliver(undefined);
    return;
  }
  if ('wasmModule' in req) {
    if (deliver) deliver({ module: req.wasmModule, variant: req.variant });
    start(req.wasmModule, req.variant);
    return;
  }
  const { id, kind } = req;
  try {
    // The page's module when it said one follows, else the full build fetched here.
    await (pending ? pending.then((m) => start(m && m.module, m ? m.variant : 'full')) : start(undefined));
    const job = Object.hasOwn(jobs, String(kind)) ? jobs[String(kind)] : null;
    if (!job) throw new Error(`unknown job ${String(kind).slice(0, 40)}`);
    const t0 = performance.now();
    const result = job(req.job, (done, total) => scope.postMessage(progressMessage(id, done, total)));
    const ms = performance.now() - t0;
    scope.postMessage(resultMessage(id, result, ms), transferList(result));
  } catch (e) {
    scope.postMessage(errorMessage(id, errorText(e)));
  }
};
