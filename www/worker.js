// @ts-check
// Web Worker for the lab's expensive studies, so sliders never freeze: parameter sweeps
// (Fig. 6), the initial-condition map (Fig. 7), long damped runs (Fig. 8), the resonance map
// (Floquet numbers over flap frequency and α0), the paper report, the FE wing (`fe`) and the
// sensing analysis (`sense`).
// Protocol: in { id, kind, cfg, opts }; out { id, progress: [done, total] } | { id, result, ms }
// | { id, error }, and once { ready: true } when the wasm has loaded (a first message
// { wasmModule } hands over the page's compiled module). Typed arrays are
// transferred, not copied. The lab runs two of these workers: one for the studies (and `fe`),
// one for the live `analyze` of the sliders (www/engine.js requestLive), so neither waits for
// the other.
import init, * as wb from './pkg/wingbeat.js';
import { decimate } from './decimate.js';
import { errorText } from './format.js';

/**
 * The wasm, loaded on the first message: the page's own compiled module when the engine sends
 * it first ({ wasmModule }: no second download or compile), else fetched next to this file.
 * @type {Promise<unknown> | null}
 */
let ready = null;
function start(/** @type {WebAssembly.Module | undefined} */ module) {
  if (!ready) {
    ready = init({ module_or_path: module || new URL('./pkg/wingbeat_bg.wasm', import.meta.url) });
    // Tells the engine that the wasm is loaded (the live worker is used once it is).
    ready.then(() => scope.postMessage({ ready: true }), () => {});
  }
  return ready;
}

const jobs = {
  sweep({ cfg, opts }, progress) {
    return wb.sweep(cfg, opts, progress);
  },
  icmap({ cfg, opts }) {
    return wb.icMap(cfg, opts);
  },
  damping({ cfg, opts }, progress) {
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
    const [x, undamped, damped] = decimate(t, runs.map((r) => r.modes[mode].q.total), 1500);
    Object.assign(out, {
      t: x,
      undamped,
      damped,
      floquet: runs.map((r) => r.modes[mode].floquet),
      n: t.length,
    });
    return out;
  },
  resonance({ cfg, opts }, progress) {
    // Floquet effective frequency and largest |multiplier| per flap frequency (and α0).
    return wb.resonanceMap(cfg, opts, progress);
  },
  reproduce() {
    return wb.reproduce();
  },
  analyze({ cfg, opts, k }) {
    // The live analysis (engine.requestLive, run in the lab's own live worker so that a study
    // or the FE wing never delays it): the same wasm `analyze` the main thread would call, with
    // the angles on sim.t (one anglesAt call for builds whose analyze lacks them).
    const a = wb.analyze(cfg, opts, k);
    if (!(a.angles && a.angles.alpha) && typeof wb.anglesAt === 'function') {
      const flat = wb.anglesAt(cfg, a.sim.t);
      const n = Math.floor(flat.length / 3);
      const alpha = new Float64Array(n), beta = new Float64Array(n), gamma = new Float64Array(n);
      for (let i = 0; i < n; i++) {
        alpha[i] = flat[3 * i];
        beta[i] = flat[3 * i + 1];
        gamma[i] = flat[3 * i + 2];
      }
      /** @type {any} */ (a).angles = { alpha, beta, gamma };
    }
    return a;
  },
  fe({ input, opts }, progress) {
    // Shell FE modes of the wing (mesh, assembly, shift-invert eigen-solve): about a second for
    // the default wing. `opts` = { json?, strain_point_mm? } (the modes JSON document for
    // export). One wasm call: progress says only that it started; Cancel ends the worker.
    progress(0, 1);
    const r = wb.feModes(input, null, opts || undefined);
    progress(1, 1);
    return r;
  },
  sense({ cfg, fe, body_rate, opts }, progress) {
    // Sensing body rotation (wasm senseRotation, issue 14): two runs of the FE wing's modes
    // (with and without the body rate), the detectability map, the greedy sensors and Δε at a
    // point; progress after each stage. `fe` = { nodes, triangles, strain_nodes } of feModes.
    return wb.senseRotation(cfg, fe.nodes, fe.triangles, fe.strain_nodes, body_rate, opts || undefined, progress);
  },
};

function transferables(v, acc = []) {
  if (ArrayBuffer.isView(v)) acc.push(v.buffer);
  else if (Array.isArray(v)) v.forEach((x) => transferables(x, acc));
  else if (v && typeof v === 'object') Object.values(v).forEach((x) => transferables(x, acc));
  return acc;
}

function transferList(v) {
  return [...new Set(transferables(v))];
}

/** The worker's global scope (a DedicatedWorkerGlobalScope; tsconfig's lib is the page's DOM). */
const scope = /** @type {{ postMessage(message: unknown, transfer?: Transferable[]): void, onmessage: ((ev: MessageEvent) => void) | null }} */ (/** @type {unknown} */ (self));

scope.onmessage = async (ev) => {
  const { id, kind, wasmModule } = ev.data || {};
  if (wasmModule) {
    start(wasmModule);
    return;
  }
  try {
    await start(undefined);
    const job = jobs[kind];
    if (!job) throw new Error(`unknown job ${String(kind).slice(0, 40)}`);
    const t0 = performance.now();
    const result = job(ev.data, (done, total) => scope.postMessage({ id, progress: [done, total] }));
    const ms = performance.now() - t0;
    scope.postMessage({ id, result, ms }, transferList(result));
  } catch (e) {
    scope.postMessage({ id, error: errorText(e) });
  }
};
