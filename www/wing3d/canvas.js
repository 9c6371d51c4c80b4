// @ts-check
// The 3-D canvas's size and context: its CSS height from the stage's width, its backing store
// (CSS size × devicePixelRatio, capped), and the WebGL2 context attributes made before wgpu takes
// the canvas. Pure sizing, tested in tests/js/wing3d_camera.test.mjs.
import { backingSize } from '../scene3d.js';

/**
 * The canvas's backing store: CSS size × devicePixelRatio, the ratio capped at MAX_DPR and the
 * area at MAX_BACKING_PX device pixels (a software rasteriser pays per pixel, every frame).
 */
export const MAX_DPR = 2;
export const MAX_BACKING_PX = 2_000_000;

/**
 * WebGL2 context attributes for the 3-D canvas when the browser offers no WebGPU adapter (wgpu
 * then takes this context as it is): no alpha channel, depth or stencil buffer on the canvas
 * (wgpu draws into its own targets and blits), no MSAA, no preserved drawing buffer (so the
 * browser never has to keep or read back a copy).
 */
export const WEBGL_ATTRIBUTES = {
  alpha: false,
  depth: false,
  stencil: false,
  antialias: false,
  preserveDrawingBuffer: false,
  powerPreference: 'high-performance',
};

/**
 * The canvas for a stage `stageWidth` CSS px wide (0: not laid out, 640 assumed): CSS width and
 * height (aspect 0.72 below 520 px, else 0.78; 160 × 140 at least, 520 px high at most) and the
 * backing store in device pixels for device pixel ratio `dpr`.
 * @param {number} stageWidth
 * @param {number} dpr
 */
export function canvasSize(stageWidth, dpr) {
  const w = Math.max(160, Math.round(stageWidth || 640));
  const aspect = w < 520 ? 0.72 : 0.78;
  const h = Math.max(140, Math.round(Math.min(w * aspect, 520)));
  const { width, height } = backingSize(w, h, dpr || 1, MAX_DPR, MAX_BACKING_PX);
  return { cssW: w, cssH: h, width, height };
}

/**
 * Without a WebGPU adapter wgpu draws with WebGL2 into the canvas's "webgl2" context; made
 * here first, that context has WEBGL_ATTRIBUTES instead of the defaults (an alpha channel and
 * a depth buffer nobody uses, each paid per pixel per frame by a software rasteriser). The
 * page's canvas, or the OffscreenCanvas the render worker draws on.
 * @param {HTMLCanvasElement | OffscreenCanvas} c
 */
export async function prepareContext(c) {
  try {
    const gpu = /** @type {any} */ (navigator).gpu;
    if (gpu && (await gpu.requestAdapter())) return;
  } catch {
    /* no WebGPU: WebGL2 */
  }
  try {
    c.getContext('webgl2', WEBGL_ATTRIBUTES);
  } catch {
    /* wgpu reports it */
  }
}
