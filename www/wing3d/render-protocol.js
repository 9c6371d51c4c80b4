// @ts-check
// The messages between the 3-D panel's view (www/wing3d/remote-view.js, on the page) and the
// render worker (www/render-worker.js, which owns the WingView on an OffscreenCanvas), in one
// place: each side builds and reads them here, so neither can drift from the other.
//
// page → worker
//   init  { module, canvas, nodes, triangles, shapes, strain_nodes }   (canvas transferred)
//   draw  { seq, frame: [exaggeration, colour] | null, pose: [α, β, γ], q }: WingView.set_frame
//         (with frame) or setPose, then render; answered by `drawn`
//   call  { name, args }: one of CALLS (state changes with no answer but a failure's `error`)
//   ranges { seq, Q, S, m }: the run's colour ranges and largest deflection over S modal states
//         (strainmap.js rangesOfStates on the worker's wing), answered by `ranges`
//   free  {}
// worker → page
//   ready  { backend, triangles, camera }  or  failed { message }
//   drawn  { seq, legend, stops, error }   (legend and stops only for a draw with frame)
//   error  { name, message }               (a call the view refused)
//   ranges { seq, ranges, deflection }     (ranges null when they could not be worked out)

/** The WingView methods a `call` may name: the view's state setters, nothing else. */
export const CALLS = Object.freeze([
  'set_scene',
  'set_strain_range',
  'setNodeField',
  'setCamera',
  'orbit',
  'zoom',
  'key',
  'resize',
]);

/**
 * @typedef {{ op: 'init', module: WebAssembly.Module, canvas: OffscreenCanvas, nodes: ArrayLike<number>,
 *   triangles: ArrayLike<number>, shapes: ArrayLike<number>, strain_nodes: ArrayLike<number> }} InitMsg
 * @typedef {{ op: 'draw', seq: number, frame: number[] | null, pose: number[], q: Float64Array }} DrawMsg
 * @typedef {{ op: 'call', name: string, args: unknown[] }} CallMsg
 * @typedef {{ op: 'ranges', seq: number, Q: Float64Array, S: number, m: number }} RangesMsg
 * @typedef {{ op: 'free' }} FreeMsg
 * @typedef {InitMsg | DrawMsg | CallMsg | RangesMsg | FreeMsg} ToWorker
 * @typedef {{ op: 'ready', backend: string, triangles: number, camera: number[] }} ReadyMsg
 * @typedef {{ op: 'failed', message: string }} FailedMsg
 * @typedef {{ op: 'drawn', seq: number, legend: any, stops: number[] | null, error: string | null }} DrawnMsg
 * @typedef {{ op: 'error', name: string, message: string }} ErrorMsg
 * @typedef {{ op: 'ranges', seq: number, ranges: Record<number, number> | null, deflection: number }} RangesReply
 * @typedef {ReadyMsg | FailedMsg | DrawnMsg | ErrorMsg | RangesReply} FromWorker
 */

/**
 * The page's message `data` as one the worker acts on, or null (anything else is ignored).
 * @param {any} d
 * @returns {ToWorker | null}
 */
export function readToWorker(d) {
  if (!d || typeof d !== 'object') return null;
  switch (d.op) {
    case 'init':
      return d.module instanceof WebAssembly.Module && d.canvas ? d : null;
    case 'draw':
      return Number.isInteger(d.seq) && Array.isArray(d.pose) && d.pose.length === 3 && d.q instanceof Float64Array
        ? d
        : null;
    case 'call':
      return CALLS.includes(d.name) && Array.isArray(d.args) ? d : null;
    case 'ranges':
      return Number.isInteger(d.seq) &&
        d.Q instanceof Float64Array &&
        Number.isInteger(d.S) &&
        Number.isInteger(d.m) &&
        d.S >= 0 &&
        d.m >= 0 &&
        d.Q.length === d.S * d.m
        ? d
        : null;
    case 'free':
      return d;
    default:
      return null;
  }
}

/**
 * The worker's message `data` as one the page acts on, or null.
 * @param {any} d
 * @returns {FromWorker | null}
 */
export function readFromWorker(d) {
  if (!d || typeof d !== 'object') return null;
  switch (d.op) {
    case 'ready':
      return typeof d.backend === 'string' && Array.isArray(d.camera) && d.camera.length === 6 ? d : null;
    case 'failed':
    case 'error':
      return typeof d.message === 'string' ? d : null;
    case 'drawn':
    case 'ranges':
      return Number.isInteger(d.seq) ? d : null;
    default:
      return null;
  }
}
