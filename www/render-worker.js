// @ts-check
// The 3-D view's worker: it owns the WingView (the wgpu renderer of the full wasm build) on the
// OffscreenCanvas the page handed over (canvas.transferControlToOffscreen), so drawing a frame —
// a long task on a software rasteriser — never holds up the page's sliders, plots and labels.
// The page's side is www/wing3d/remote-view.js; the messages are www/wing3d/render-protocol.js.
// The page sends its compiled full module with `init` (no second download or compile).
import { WWW } from './base.js';
import { VARIANT_FILES } from './engine/wasm.js';
import { errorText } from './format.js';
import { prepareContext } from './wing3d/canvas.js';
import { readToWorker } from './wing3d/render-protocol.js';
import { rangesOfStates } from './strainmap.js';

const scope = /** @type {any} */ (globalThis);
/** @type {any} the WingView, once made */
let view = null;
/** @type {OffscreenCanvas | null} */
let canvas = null;
/** @type {Promise<void> | null} */
let starting = null;
/** @type {{ nodes: ArrayLike<number>, strain_nodes: ArrayLike<number>, shapes: ArrayLike<number> } | null} the wing, for `ranges` */
let wing = null;

/** @param {import('./wing3d/render-protocol.js').FromWorker} m */
const post = (m) => scope.postMessage(m);
/** The full build's glue, loading from the start (the page may start this worker ahead of its module). */
const glueReady = import(new URL(VARIANT_FILES.full.glue, WWW).href);
glueReady.catch(() => {});

/**
 * Loads the full build from the page's compiled module and makes the view (the WebGL2 context
 * attributes set first where there is no WebGPU adapter, as on the page: canvas.js
 * prepareContext).
 * @param {import('./wing3d/render-protocol.js').InitMsg} m
 */
async function init(m) {
  const glue = await glueReady;
  await glue.default({ module_or_path: m.module });
  canvas = m.canvas;
  wing = { nodes: m.nodes, strain_nodes: m.strain_nodes, shapes: m.shapes };
  await prepareContext(canvas);
  view = await glue.WingView.createFromArrays(canvas, m.nodes, m.triangles, m.shapes, m.strain_nodes);
  post({ op: 'ready', backend: view.backend(), triangles: view.triangles(), camera: Array.from(view.camera()) });
}

/** @param {import('./wing3d/render-protocol.js').DrawMsg} m */
function draw(m) {
  /** @type {any} */
  let legend = null;
  /** @type {number[] | null} */
  let stops = null;
  try {
    const [a, b, g] = m.pose;
    if (m.frame) {
      legend = view.set_frame(a, b, g, m.q, m.frame[0], m.frame[1]);
      stops = Array.from(view.legend_stops());
    } else view.setPose(a, b, g, m.q);
    view.render();
    post({ op: 'drawn', seq: m.seq, legend, stops, error: null });
  } catch (e) {
    post({ op: 'drawn', seq: m.seq, legend: null, stops: null, error: errorText(e) });
  }
}

/** @param {import('./wing3d/render-protocol.js').CallMsg} m */
function call(m) {
  try {
    if (m.name === 'resize' && canvas) {
      // the drawing buffer is the worker's now: the page cannot size its canvas any more
      const [w, h] = m.args.map(Number);
      if (Number.isInteger(w) && Number.isInteger(h) && w >= 1 && h >= 1 && w <= 32768 && h <= 32768) {
        canvas.width = w;
        canvas.height = h;
      }
    }
    view[m.name](...m.args);
  } catch (e) {
    post({ op: 'error', name: m.name, message: errorText(e) });
  }
}

scope.onmessage = (/** @type {MessageEvent} */ e) => {
  const m = readToWorker(e.data);
  if (!m) return;
  if (m.op === 'init') {
    if (!starting)
      starting = init(m).catch((err) => {
        view = null;
        post({ op: 'failed', message: errorText(err) });
      });
    return;
  }
  if (!view) return;
  if (m.op === 'draw') draw(m);
  else if (m.op === 'ranges') {
    try {
      const r = rangesOfStates(/** @type {any} */ (wing), m);
      post({ op: 'ranges', seq: m.seq, ranges: r.ranges, deflection: r.deflection });
    } catch {
      post({ op: 'ranges', seq: m.seq, ranges: null, deflection: 0 });
    }
  } else if (m.op === 'call') call(m);
  else if (m.op === 'free') {
    view.free();
    view = null;
    scope.close();
  }
};
