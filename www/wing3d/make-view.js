// @ts-check
// Making the 3-D panel's view: in a worker (www/render-worker.js through RemoteWingView) where
// the engine offers one, else — or when the worker cannot make it — the wasm WingView on this
// thread, on a fresh canvas (a canvas handed to a worker is spent).
import { errorText } from '../format.js';
import { prepareContext } from './canvas.js';
import { RemoteWingView, canRenderInWorker } from './remote-view.js';

/**
 * Whether the panel in `box` draws `canvas` in a worker: the default where the browser can hand
 * a canvas over; on this thread with `render="main"` on the lab element (or no OffscreenCanvas).
 * @param {HTMLElement} box
 * @param {HTMLCanvasElement} canvas
 */
export function wantWorker(box, canvas) {
  const root = /** @type {any} */ (box.getRootNode());
  const lab = root && root.host ? root.host : box.closest('wing-lab');
  return !(lab && lab.getAttribute('render') === 'main') && canRenderInWorker(canvas);
}

/**
 * @param {{ nodes: any, triangles: any, shapes: any, strain_nodes: any }} w the FE wing (feModes' flat arrays)
 * @param {{ canvas: () => HTMLCanvasElement, renderer: any,
 *   remote: { worker: Worker, module: WebAssembly.Module, fitCamera: (cam: number[], xyz: Float32Array, margin: number, aspect: number) => ArrayLike<number> } | null,
 *   freshCanvas: () => void, onError: (m: string) => void, onDrawn: (n: number) => void }} o
 *   `canvas()` is the panel's canvas now (freshCanvas replaces it), `renderer` the full build's
 *   WingView class, `remote` what the engine's renderWorker() gave (null: draw here).
 * @returns {Promise<{ view: any, thread: 'worker' | 'main', workerProblem: string, problem: string }>}
 *   `view` null when neither worked (`problem` says why); `workerProblem`: why the worker was
 *   not used although offered.
 */
export async function createWingView(w, o) {
  let workerProblem = '';
  if (o.remote) {
    try {
      const view = await RemoteWingView.create(o.canvas(), w, { ...o.remote, onError: o.onError, onDrawn: o.onDrawn });
      return { view, thread: 'worker', workerProblem, problem: '' };
    } catch (e) {
      workerProblem = errorText(e);
      o.freshCanvas();
    }
  }
  const canvas = o.canvas();
  await prepareContext(canvas);
  try {
    const view = await o.renderer.createFromArrays(canvas, w.nodes, w.triangles, w.shapes, w.strain_nodes);
    return { view, thread: 'main', workerProblem, problem: '' };
  } catch (e) {
    return { view: null, thread: 'main', workerProblem, problem: errorText(e) };
  }
}
