// @ts-check
// The planform map shared by the strain panel and the sensing panel: a 2-D canvas showing the
// FE wing seen from above (x spanwise, y chordwise, mm), sized to the planform's aspect and the
// panel's width (redrawn when that changes), on which a click or the arrow keys pick a point (mm),
// drawn as a ring, and whether a point lies on the wing.
import { context2d } from './export.js';
import { pick } from './scene3d.js';
import { fmt } from './format.js';

/** Arrow-key step of the picked point on a map, mm (Shift: ×4). */
export const KEY_STEP_MM = 0.5;

/**
 * Pure: the map's size in CSS pixels and its frame for a planform whose nodes are `nodes`
 * (m, x y z per node) drawn `widthCss` wide with `pad` pixels of margin; the height follows the
 * planform's aspect (at most 360 px). A point (x, y) in mm is drawn at
 * ((x − x0)·k, (y1 − y)·k).
 * @param {ArrayLike<number>} nodes
 * @param {number} widthCss
 * @param {number} pad
 * @returns {{ cssW: number, cssH: number, frame: { x0: number, y1: number, k: number } }}
 */
export function planformFrame(nodes, widthCss, pad) {
  const n = Math.floor(nodes.length / 3);
  let x0 = Infinity,
    x1 = -Infinity,
    y0 = Infinity,
    y1 = -Infinity;
  for (let i = 0; i < n; i++) {
    const x = nodes[3 * i] * 1e3,
      y = nodes[3 * i + 1] * 1e3;
    x0 = Math.min(x0, x);
    x1 = Math.max(x1, x);
    y0 = Math.min(y0, y);
    y1 = Math.max(y1, y);
  }
  if (!(n > 0)) {
    x0 = 0;
    x1 = 1;
    y0 = 0;
    y1 = 1;
  }
  const cssW = Math.max(200, Math.min(720, widthCss));
  const k = (cssW - 2 * pad) / Math.max(1e-9, x1 - x0);
  const cssH = Math.round(Math.min(360, (y1 - y0) * k + 2 * pad));
  const kk = Math.min(k, (cssH - 2 * pad) / Math.max(1e-9, y1 - y0));
  return { cssW, cssH, frame: { x0: x0 - pad / kk, y1: y1 + pad / kk, k: kk } };
}

/**
 * Pure: whether the point (x, y), mm, lies on the meshed planform (the wing seen from above:
 * inside one of its triangles, edges included).
 * @param {ArrayLike<number>} nodes m, x y z per node
 * @param {ArrayLike<number>} triangles node indices, three per triangle
 * @param {number} x mm
 * @param {number} y mm
 */
export function onPlanform(nodes, triangles, x, y) {
  const n = Math.floor(nodes.length / 3);
  const xy = new Float64Array(2 * n);
  for (let i = 0; i < n; i++) {
    xy[2 * i] = nodes[3 * i] * 1e3;
    xy[2 * i + 1] = nodes[3 * i + 1] * 1e3;
  }
  return !!pick(nodes, triangles, { xy, depth: new Float64Array(n) }, x, y);
}

/**
 * Sizes `canvas` for the planform (CSS size from the panel's width, backing store at the device
 * pixel ratio, at most 2) and clears it; returns the 2-D context set to draw in CSS pixels.
 * @param {HTMLCanvasElement} canvas
 * @param {ArrayLike<number>} nodes
 * @param {number} pad
 */
export function fitPlanform(canvas, nodes, pad) {
  const { cssW, cssH, frame } = planformFrame(
    nodes,
    canvas.parentElement ? canvas.parentElement.clientWidth : 600,
    pad,
  );
  const dpr = Math.min(2, globalThis.devicePixelRatio || 1);
  canvas.style.width = `${cssW}px`;
  canvas.style.height = `${cssH}px`;
  if (canvas.width !== Math.round(cssW * dpr) || canvas.height !== Math.round(cssH * dpr)) {
    canvas.width = Math.round(cssW * dpr);
    canvas.height = Math.round(cssH * dpr);
  }
  const c2 = context2d(canvas);
  c2.setTransform(dpr, 0, 0, dpr, 0, 0);
  c2.clearRect(0, 0, cssW, cssH);
  return { c2, cssW, cssH, frame };
}

/**
 * Fills the planform's triangles, each in the colour `rgbOf(a, b, c)` of its three node indices
 * (outlined in the same colour so no seams show between them), in the frame of fitPlanform.
 * @param {CanvasRenderingContext2D} c2
 * @param {ArrayLike<number>} nodes m, x y z per node
 * @param {ArrayLike<number>} triangles node indices, three per triangle
 * @param {{ x0: number, y1: number, k: number }} frame
 * @param {(a: number, b: number, c: number) => number[]} rgbOf
 */
export function fillPlanform(c2, nodes, triangles, frame, rgbOf) {
  const px = (/** @type {number} */ i) => (nodes[3 * i] * 1e3 - frame.x0) * frame.k;
  const py = (/** @type {number} */ i) => (frame.y1 - nodes[3 * i + 1] * 1e3) * frame.k;
  c2.lineWidth = 0.6;
  for (let t = 0; t + 2 < triangles.length; t += 3) {
    const a = triangles[t],
      b = triangles[t + 1],
      c = triangles[t + 2];
    const rgb = rgbOf(a, b, c);
    c2.fillStyle = `rgb(${rgb[0]},${rgb[1]},${rgb[2]})`;
    c2.strokeStyle = c2.fillStyle;
    c2.beginPath();
    c2.moveTo(px(a), py(a));
    c2.lineTo(px(b), py(b));
    c2.lineTo(px(c), py(c));
    c2.closePath();
    c2.fill();
    c2.stroke();
  }
}

/**
 * Picking on a map: a click chooses the point under the pointer, an arrow key moves the current
 * point by KEY_STEP_MM (×4 with Shift). `choose(x, y)` (mm) validates and applies it.
 * @param {HTMLCanvasElement} canvas
 * @param {() => ({ x0: number, y1: number, k: number } | null)} frameOf the frame last drawn
 * @param {() => (number[] | null)} pointOf the current point (mm), or null when there is none
 * @param {(x: number, y: number) => unknown} choose
 */
export function pickOnMap(canvas, frameOf, pointOf, choose) {
  canvas.addEventListener('click', (e) => {
    const f = frameOf();
    if (!f) return;
    const b = canvas.getBoundingClientRect();
    choose(f.x0 + (e.clientX - b.left) / f.k, f.y1 - (e.clientY - b.top) / f.k);
  });
  canvas.addEventListener('keydown', (e) => {
    const d = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] }[e.key];
    if (!d) return;
    e.preventDefault();
    const p = pointOf();
    if (!p) return;
    const step = KEY_STEP_MM * (e.shiftKey ? 4 : 1);
    choose(p[0] + d[0] * step, p[1] + d[1] * step);
  });
}

/**
 * A point chosen on a map (mm), rounded to 0.001 mm, when it lies on the wing; else null, and
 * `note` says that it is outside the wing.
 * @param {{ nodes: ArrayLike<number>, triangles: ArrayLike<number> }} fe
 * @param {number} x mm
 * @param {number} y mm
 * @param {{ textContent: string | null }} note
 * @returns {[number, number] | null}
 */
export function pointOnWing(fe, x, y, note) {
  if (!onPlanform(fe.nodes, fe.triangles, x, y)) {
    note.textContent = `(${fmt(x, 3)}, ${fmt(y, 3)}) mm is outside the wing: choose a point on the wing.`;
    return null;
  }
  const r = (/** @type {number} */ v) => Math.round(v * 1000) / 1000;
  return [r(x), r(y)];
}

/**
 * A ring around a point on a map, with a dark and a light edge so it shows on every colour.
 * @param {CanvasRenderingContext2D} c2
 * @param {number} x canvas px
 * @param {number} y canvas px
 * @param {number} radius canvas px
 * @param {string} light the inner edge's colour
 */
export function drawRing(c2, x, y, radius, light) {
  c2.lineWidth = 3;
  c2.strokeStyle = '#111';
  c2.beginPath();
  c2.arc(x, y, radius, 0, 2 * Math.PI);
  c2.stroke();
  c2.lineWidth = 1.5;
  c2.strokeStyle = light;
  c2.beginPath();
  c2.arc(x, y, radius, 0, 2 * Math.PI);
  c2.stroke();
}

/**
 * Calls `redraw()` when the map's box changes width by more than 4 px (where the browser has
 * ResizeObserver); `disconnect()` stops watching.
 * @param {HTMLElement} box
 * @param {() => void} redraw
 */
export function watchWidth(box, redraw) {
  /** @type {ResizeObserver | null} */
  let ro = null;
  if (typeof ResizeObserver === 'function') {
    let lastW = 0;
    ro = new ResizeObserver(() => {
      const w = box.clientWidth;
      if (w && Math.abs(w - lastW) > 4) {
        lastW = w;
        redraw();
      }
    });
    ro.observe(box);
  }
  return {
    disconnect() {
      if (ro) ro.disconnect();
    },
  };
}
