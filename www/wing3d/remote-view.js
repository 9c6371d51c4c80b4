// @ts-check
// The 3-D view drawn by a worker: RemoteWingView stands in for the wasm WingView on the page
// while www/render-worker.js owns the real one on the canvas's OffscreenCanvas. The panel calls
// it as it calls a WingView, with two differences it knows of: set_frame answers with a
// Promise of the legend (the frame is drawn by the worker), and the canvas's size is the
// worker's to set (resize).
//
// Frames are latest-wins: at most one draw is in flight; poses set meanwhile replace each other
// and the newest is drawn when the worker answers, so a slow rasteriser drops frames instead of
// queueing them. State calls (camera, scene, colours, size) go at once, in order, ahead of the
// next draw. The camera is kept here too (the worker's is the same): orbit, zoom and keys with
// the renderer's arithmetic mirrored in www/scene3d.js, and fitPoints with the renderer's own
// fit (WingView.fitCamera of the page's full build, no GPU), whose camera is then sent.
import * as S from '../scene3d.js';
import { readFromWorker } from './render-protocol.js';

/** How long the worker may take to load the module and make the view before the page draws itself (ms). */
export const START_TIMEOUT_MS = 20000;

/**
 * Whether this browser can hand a canvas to a worker (OffscreenCanvas with WebGL2 or WebGPU in
 * workers: Chromium 69+, Firefox 105+, Safari 17+).
 * @param {HTMLCanvasElement} canvas
 */
export function canRenderInWorker(canvas) {
  return (
    typeof OffscreenCanvas === 'function' &&
    typeof Worker === 'function' &&
    typeof (/** @type {any} */ (canvas).transferControlToOffscreen) === 'function'
  );
}

/** [tx, ty, tz, yaw, pitch, distance] → the mirror's Camera. */
const toCam = (/** @type {ArrayLike<number>} */ c) => ({
  target: [c[0], c[1], c[2]],
  yaw: c[3],
  pitch: c[4],
  distance: c[5],
  fov: S.defaultCamera(1).fov,
});
/** The mirror's Camera → [tx, ty, tz, yaw, pitch, distance]. */
const fromCam = (/** @type {S.Camera} */ c) => [c.target[0], c.target[1], c.target[2], c.yaw, c.pitch, c.distance];

/**
 * @typedef {{ frame: number[] | null, pose: number[], q: Float64Array,
 *   waiters: ((legend: any) => void)[] }} PendingDraw
 */

export class RemoteWingView {
  /**
   * Hands `canvas` to a new render worker and makes the view there for the FE wing `w`
   * (feModes' flat arrays). Resolves once the worker has drawn nothing yet but holds the view;
   * rejects with the worker's reason (the canvas is then spent: the caller makes a fresh one).
   * @param {HTMLCanvasElement} canvas sized (width, height) before the call
   * @param {{ nodes: ArrayLike<number>, triangles: ArrayLike<number>, shapes: ArrayLike<number>, strain_nodes: ArrayLike<number> }} w
   * @param {{ worker: Worker, module: WebAssembly.Module,
   *   fitCamera: (cam: number[], xyz: Float32Array, margin: number, aspect: number) => ArrayLike<number>,
   *   onError?: (what: string) => void, onDrawn?: (frames: number) => void, timeoutMs?: number }} o
   */
  static create(canvas, w, o) {
    const size = [canvas.width, canvas.height];
    const off = /** @type {any} */ (canvas).transferControlToOffscreen();
    const worker = o.worker;
    const rv = new RemoteWingView(worker, size, o.fitCamera, o.onError || (() => {}));
    rv.nNodes = Math.floor(w.nodes.length / 3);
    if (o.onDrawn) rv.onDrawn = o.onDrawn;
    return new Promise((resolve, reject) => {
      const timer = setTimeout(() => {
        worker.terminate();
        reject(new Error(`the render worker did not start within ${(o.timeoutMs ?? START_TIMEOUT_MS) / 1000} s`));
      }, o.timeoutMs ?? START_TIMEOUT_MS);
      rv.started = (/** @type {any} */ m) => {
        clearTimeout(timer);
        if (m.op === 'ready') {
          rv.info = { backend: m.backend, triangles: m.triangles };
          rv.cam = m.camera.slice();
          resolve(rv);
        } else {
          worker.terminate();
          reject(new Error(m.message));
        }
      };
      worker.onerror = (e) => {
        clearTimeout(timer);
        worker.terminate();
        reject(new Error(`the render worker failed: ${e.message || 'no reason given'}`));
      };
      // (the wing's arrays are copied, not transferred: the page keeps its FE wing)
      worker.postMessage(
        {
          op: 'init',
          module: o.module,
          canvas: off,
          nodes: w.nodes,
          triangles: w.triangles,
          shapes: w.shapes,
          strain_nodes: w.strain_nodes,
        },
        [off],
      );
    });
  }

  /**
   * @param {Worker} worker
   * @param {number[]} size the drawing buffer [width, height], device px
   * @param {(cam: number[], xyz: Float32Array, margin: number, aspect: number) => ArrayLike<number>} fitCamera
   * @param {(what: string) => void} onError
   */
  constructor(worker, size, fitCamera, onError) {
    this.worker = worker;
    this.size = size;
    this.fitCamera = fitCamera;
    this.onError = onError;
    /** @type {((m: any) => void) | null} answers the start */
    this.started = null;
    this.info = { backend: '', triangles: 0 };
    /** the camera [tx, ty, tz, yaw, pitch, distance], as the worker's */
    this.cam = [0, 0, 0, 0, 0, 1];
    /** @type {number[]} the colour stops of the last legend */
    this.stops = [];
    this.seq = 0;
    /** @type {PendingDraw | null} the draw in flight */
    this.inFlight = null;
    /** @type {PendingDraw | null} the newest state not yet sent */
    this.next = null;
    /**
     * the last pose sent, for a render() with nothing new
     * @type {{ pose: number[], q: Float64Array }}
     */
    this.last = { pose: [0, 0, 0], q: new Float64Array(0) };
    this.wantDraw = false;
    /** frames the worker has drawn */
    this.drawn = 0;
    this.freed = false;
    /** the wing's node count (setNodeField's length) */
    this.nNodes = 0;
    /** @type {(() => void)[]} waiting for idle() */
    this.idlers = [];
    /** @type {Map<number, (r: any) => void>} runRanges answers awaited, by seq */
    this.rangeWaiters = new Map();
    /** @type {(frames: number) => void} told the count after each drawn frame */
    this.onDrawn = () => {};
    worker.onmessage = (e) => this.receive(e.data);
  }

  /** @param {any} data */
  receive(data) {
    const m = readFromWorker(data);
    if (!m) return;
    if (m.op === 'ready' || m.op === 'failed') {
      if (this.started) this.started(m);
      this.started = null;
      return;
    }
    if (m.op === 'error') {
      this.onError(`${m.name}: ${m.message}`);
      return;
    }
    if (m.op === 'ranges') {
      const f = this.rangeWaiters.get(m.seq);
      this.rangeWaiters.delete(m.seq);
      if (f) f(m.ranges ? { ranges: m.ranges, deflection: m.deflection } : null);
      this.notifyIdle();
      return;
    }
    const d = this.inFlight;
    this.inFlight = null;
    if (m.error) this.onError(`render: ${m.error}`);
    else {
      this.drawn += 1;
      this.onDrawn(this.drawn);
    }
    if (m.stops) this.stops = m.stops;
    if (d) for (const f of d.waiters) f(m.error ? null : m.legend);
    this.pump();
    this.notifyIdle();
  }

  busy() {
    return !!this.inFlight || this.wantDraw || this.rangeWaiters.size > 0;
  }

  notifyIdle() {
    if (!this.busy()) for (const f of this.idlers.splice(0)) f();
  }

  /**
   * Resolves once every frame and range asked for is done, and what their answers asked for in
   * turn (a frame drawn with new ranges): at once when nothing is awaited.
   */
  async idle() {
    for (;;) {
      if (!this.busy()) {
        // (answers resolve promises whose handlers may ask for more: let them run first)
        await new Promise((r) => setTimeout(r, 0));
        if (!this.busy() || this.freed) return;
      }
      await new Promise((resolve) => this.idlers.push(() => resolve(undefined)));
    }
  }

  /**
   * The run's colour ranges and largest deflection (strainmap.js runRanges), worked out by the
   * worker over the flat states `st` (runStates): resolves to { ranges, deflection }, or null.
   * @param {{ Q: Float64Array, S: number, m: number }} st
   * @returns {Promise<{ ranges: Record<number, number>, deflection: number } | null>}
   */
  runRanges(st) {
    if (this.freed) return Promise.resolve(null);
    const seq = ++this.seq;
    this.worker.postMessage({ op: 'ranges', seq, Q: st.Q, S: st.S, m: st.m }, [st.Q.buffer]);
    return new Promise((resolve) => this.rangeWaiters.set(seq, resolve));
  }

  /** Sends the newest state when nothing is in flight. */
  pump() {
    if (this.freed || this.inFlight || !this.wantDraw) return;
    const d = this.next || { frame: null, pose: this.last.pose, q: this.last.q, waiters: [] };
    this.next = null;
    this.wantDraw = false;
    this.inFlight = d;
    this.last = { pose: d.pose, q: d.q };
    this.worker.postMessage({ op: 'draw', seq: ++this.seq, frame: d.frame, pose: d.pose, q: d.q });
  }

  /**
   * @param {number} a
   * @param {number} b
   * @param {number} g
   * @param {ArrayLike<number>} q
   * @param {number[] | null} frame
   */
  stage(a, b, g, q, frame) {
    const n = this.next;
    this.next = {
      frame: frame || (n ? n.frame : null),
      pose: [a, b, g],
      q: Float64Array.from(q),
      waiters: n ? n.waiters : [],
    };
    return this.next;
  }

  backend() {
    return this.info.backend;
  }

  triangles() {
    return this.info.triangles;
  }

  /**
   * WingView.set_frame, drawn by the worker with the next render(): resolves to its legend (null
   * when the draw failed; the failure goes to onError).
   * @param {number} a
   * @param {number} b
   * @param {number} g
   * @param {ArrayLike<number>} q
   * @param {number} exaggeration
   * @param {number} colour
   * @returns {Promise<any>}
   */
  set_frame(a, b, g, q, exaggeration, colour) {
    const d = this.stage(a, b, g, q, [exaggeration, colour]);
    return new Promise((resolve) => d.waiters.push(resolve));
  }

  /** WingView.setPose (drawn with the next render()). */
  setPose(
    /** @type {number} */ a,
    /** @type {number} */ b,
    /** @type {number} */ g,
    /** @type {ArrayLike<number>} */ q,
  ) {
    this.stage(a, b, g, q, null);
    return 0;
  }

  /** Draws the newest state (now, or when the frame in flight is done). */
  render() {
    this.wantDraw = true;
    this.pump();
  }

  /** @param {string} name @param {unknown[]} args */
  send(name, args) {
    if (!this.freed) this.worker.postMessage({ op: 'call', name, args });
  }

  /** @param {boolean} axes @param {boolean} plane @param {boolean} body */
  set_scene(axes, plane, body) {
    this.send('set_scene', [axes, plane, body]);
  }

  /** @param {number | null} limit */
  set_strain_range(limit) {
    this.send('set_strain_range', [limit]);
  }

  /**
   * WingView.setNodeField: a wrong length is refused here, at once, as the view refuses it.
   * @param {ArrayLike<number>} values
   * @param {number | null} limit
   */
  setNodeField(values, limit) {
    if (values.length !== this.nNodes)
      throw new Error(`invalid value for \`values\`: ${values.length} values (allowed: one per node, ${this.nNodes})`);
    this.send('setNodeField', [Float64Array.from(values), limit]);
  }

  /** @param {number} tx @param {number} ty @param {number} tz @param {number} yaw @param {number} pitch @param {number} distance */
  setCamera(tx, ty, tz, yaw, pitch, distance) {
    const c = [tx, ty, tz, yaw, pitch, distance];
    if (!c.every(Number.isFinite) || !(distance > 0))
      throw new Error(`invalid camera: ${c.join(', ')} (allowed: finite numbers, distance > 0 m)`);
    // (as the renderer keeps it: yaw modulo 2π, pitch within its limit)
    this.cam = fromCam(S.orbit(toCam(c), 0, 0));
    this.send('setCamera', c);
  }

  camera() {
    return this.cam.slice();
  }

  /**
   * WingView.fitPoints with the renderer's fit run on the page (fitCamera), the result sent.
   * @param {Float32Array} xyz
   * @param {number} margin
   */
  fitPoints(xyz, margin) {
    const c = Array.from(this.fitCamera(this.cam, xyz, margin, this.size[0] / Math.max(1, this.size[1])));
    this.cam = c;
    this.send('setCamera', c);
    return c;
  }

  /** @param {number} dx @param {number} dy */
  orbit(dx, dy) {
    this.cam = fromCam(S.orbit(toCam(this.cam), dx, dy));
    this.send('orbit', [dx, dy]);
  }

  /** @param {number} f */
  zoom(f) {
    this.cam = fromCam(S.zoom(toCam(this.cam), f));
    this.send('zoom', [f]);
  }

  /** @param {string} k @returns {boolean} */
  key(k) {
    const c = S.key(toCam(this.cam), k);
    if (!c) return false;
    this.cam = fromCam(c);
    this.send('key', [k]);
    return true;
  }

  /** @param {number} w @param {number} h */
  resize(w, h) {
    if (!(Number.isInteger(w) && Number.isInteger(h) && w >= 1 && h >= 1 && w <= 32768 && h <= 32768))
      throw new Error(`resize: ${w} × ${h} (allowed: integers in [1, 32768] device px)`);
    this.size = [w, h];
    this.send('resize', [w, h]);
  }

  legend_stops() {
    return this.stops;
  }

  /** Ends the worker (and the view with it). */
  free() {
    if (this.freed) return;
    this.freed = true;
    for (const f of this.rangeWaiters.values()) f(null);
    this.rangeWaiters.clear();
    for (const f of this.idlers.splice(0)) f();
    this.worker.postMessage({ op: 'free' });
    // the worker closes itself; terminate in case it is stuck in a long frame
    setTimeout(() => this.worker.terminate(), 1000);
  }
}
