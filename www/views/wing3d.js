// @ts-check
// 3-D wing panel: the shell-FE wing flapping (roll α, pitch β, yaw γ about the root), bending
// and twisting as the simulated q_k(t) say, coloured by strain — drawn by the wasm WingView
// (WebGPU where the browser has it, WebGL2 otherwise; a plain explanation where neither works).
//
// What makes it show the physics:
// * the camera fits the whole stroke (every pose of the run stays in frame; www/scene3d.js
//   mirrors the renderer's camera, so the fit is done here with orbit/zoom only);
// * one strain colour range per component for the whole run (robust maximum over time), fixed
//   while playing, so the beat shows as pulsing colour;
// * speeds "one flap per second" and "one beat in 4 s" besides fixed slow-motion factors;
// * the largest deflection over the run in mm for the FE wing (the paper table is not SI);
// * a legend for the stroke plane, the body axis and both frames, each hideable.
// The instant shown is the store's `t3d`; the angles come with the analysis (no wasm call per
// frame). Test hooks on the box: data-state (loading | ready | unavailable), data-backend,
// data-frames, data-coverage (estimated wing share of the canvas at the fitted view).
//
// The panel itself (its state and the wiring of its parts) is www/wing3d/panel.js; its parts
// live beside it in www/wing3d/.
import { Wing3dPanel } from '../wing3d/panel.js';

export const title = '3-D wing';

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  return new Wing3dPanel(ctx).api();
}
