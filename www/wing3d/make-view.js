// @ts-check
// Making the 3-D panel's view: in a worker (www/render-worker.js through RemoteWingView) where
// the engine offers one, else — or when the worker cannot make it — the wasm WingView on this
// thread, on a fresh canvas (a canvas handed to a worker is spent).
import { errorText } from '../format.js';
import * as S from '../scene3d.js';
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

/**
 * Makes the panel's view for the FE wing `w` (Wing3dPanel.makeView runs one at a time): the
 * first on the panel's canvas, a new wing's on a new canvas shown once ready (the old wing stays
 * drawn meanwhile). Returns false when no view could be made (the panel then says why).
 * @param {import('./panel.js').Wing3dPanel} p
 * @param {any} w
 */
export async function makePanelView(p, w) {
  const renderer = p.engine.renderer;
  if (!renderer) return false;
  const old = p.view;
  // The first view is made on the panel's canvas; a new wing's on a new canvas, shown once
  // ready (the old wing stays drawn meanwhile). A canvas handed to a worker that then failed
  // is spent: the view is made on the page, on another new canvas.
  if (!old) p.fitCanvas();
  let target = old ? p.newCanvas() : p.canvas;
  target.dataset.size = `${p.bw}x${p.bh}`;
  const made = await createWingView(w, {
    canvas: () => target,
    renderer,
    remote: wantWorker(p.dom.box, target) ? p.engine.renderWorker() : null,
    freshCanvas: () => {
      target = p.newCanvas();
      target.dataset.size = `${p.bw}x${p.bh}`;
    },
    onError: (/** @type {string} */ m) => {
      p.dom.status.textContent = m;
    },
    onDrawn: () => {
      p.frames += 1;
      p.dom.box.dataset.frames = String(p.frames);
    },
  });
  const show = () => {
    if (old) old.free();
    if (target === p.canvas) return;
    p.canvas.replaceWith(target);
    p.canvas = target;
    p.bindCanvas();
  };
  if (!made.view) {
    p.view = null;
    show();
    p.unavailable(made.problem);
    return false;
  }
  const view = made.view;
  p.view = view;
  p.workerProblem = made.workerProblem;
  p.fe = w;
  p.rig.reset(S.spanOf(w.nodes));
  p.fields.invalidate();
  p.dirty = true;
  const box = p.dom.box;
  box.dataset.state = 'ready';
  box.dataset.backend = view.backend();
  box.dataset.thread = made.thread;
  if (p.workerProblem) box.dataset.workerProblem = p.workerProblem;
  box.dataset.nodes = String(w.nodes.length / 3);
  // A worker's view draws its first frame before its canvas replaces the old wing's (no blank
  // canvas in between); a view on this thread draws once shown.
  if (typeof view.idle === 'function') {
    p.onScene();
    await view.idle();
    show();
    p.draw(); // (again once shown: a canvas out of the page may not keep a frame)
  } else {
    show();
    p.onScene();
  }
  // (the stage may have been resized while the view was made)
  if (target.dataset.size !== `${p.bw}x${p.bh}`) {
    p.bw = 0;
    p.fitCanvas();
    p.draw();
  }
  return true;
}
