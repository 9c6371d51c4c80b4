// @ts-check
// What the 3-D panel draws over the canvas: the names of the axes and of the stroke plane at
// their projected positions, the strain point's ring, and the sensing panel's K best sensors (a
// dot each, a numbered tag per group of sensors closer on screen than a tag). Positions come
// from the camera mirror (www/scene3d.js); where things go is worked out by the pure functions
// here (tests/js/wing3d_overlays.test.mjs), and createOverlays() moves the elements.
import { el } from '../dom.js';
import * as S from '../scene3d.js';
import { clusterMarkers, groupLabel } from '../sensemap.js';

/**
 * The labels drawn at the projected tips of the axes and a corner of the stroke plane (the
 * legend under the view says the same in words): text, kind (which checkbox shows it), colour.
 */
export const LABELS = [
  ['I', 'fixed', 'rgb(200,110,110)'],
  ['J', 'fixed', 'rgb(110,190,110)'],
  ['K', 'fixed', 'rgb(130,150,230)'],
  ['I″', 'wing', 'rgb(255,90,80)'],
  ['J″', 'wing', 'rgb(100,255,100)'],
  ['K″', 'wing', 'rgb(120,165,255)'],
  ['body axis', 'body', 'rgb(220,220,220)'],
  ['stroke plane', 'plane', 'rgb(150,170,235)'],
];

/**
 * Where each of LABELS goes on a w × h canvas (its translate, CSS px), or null when hidden (its
 * kind switched off, or its anchor off screen). Anchors: the axis tips of src/render/gpu.rs
 * scene_geometry for a wing of span `span` at pose `ang`; the stroke plane's label goes to the
 * one of its corners / edge midpoints on screen that is farthest from the wing's middle.
 * @param {S.Camera} cam
 * @param {number} span m
 * @param {number[]} ang [α, β, γ]
 * @param {number} w
 * @param {number} h
 * @param {Record<string, boolean>} show per kind (fixed, wing, body, plane)
 * @returns {(number[] | null)[]}
 */
export function labelPlaces(cam, span, ang, w, h, show) {
  const l = span;
  const pr = S.projector(cam, w, h);
  const fr = (/** @type {number[]} */ p) => S.rotate(ang[0], ang[1], 0, p);
  const pts = [
    [0.35 * l, 0, 0],
    [0, 0.35 * l, 0],
    [0, 0, 0.35 * l],
    fr([0.7 * l, 0, 0]),
    fr([0, 0.45 * l, 0]),
    fr([0, 0, 0.45 * l]),
    [0, 0.6 * l, 0],
    [1.1 * l, 0, 0.9 * l],
  ];
  /**
   * @param {number[] | null} p
   * @returns {p is number[]}
   */
  const inView = (p) => !!p && p[0] > 10 && p[0] < w - 90 && p[1] > 20 && p[1] < h - 10;
  const mid = pr(...S.rotate(ang[0], ang[1], ang[2], [0.45 * l, -0.2 * l, 0])) || [w / 2, h / 2];
  const planeAt = [
    [1.1 * l, 0, 0.9 * l],
    [1.1 * l, 0, -0.9 * l],
    [0.5 * l, 0, 0.9 * l],
    [0.5 * l, 0, -0.9 * l],
    [-0.1 * l, 0, 0.9 * l],
    [-0.1 * l, 0, -0.9 * l],
    [1.1 * l, 0, 0],
  ]
    .map((q) => pr(q[0], q[1], q[2]))
    .filter(inView)
    .sort((a, b) => Math.hypot(b[0] - mid[0], b[1] - mid[1]) - Math.hypot(a[0] - mid[0], a[1] - mid[1]))[0];
  return LABELS.map(([, kind], j) => {
    const p = kind === 'plane' ? planeAt : pr(pts[j][0], pts[j][1], pts[j][2]);
    const ok = show[kind] && p && p[0] > 4 && p[0] < w - 20 && p[1] > 8 && p[1] < h - 4;
    return ok && p ? [Math.round(p[0] + 3), Math.round(p[1] - 14)] : null;
  });
}

/**
 * The strain point's ring (14 px, centred on `at`): its translate, or null when off the canvas.
 * @param {number[] | null} at
 * @param {number} w
 * @param {number} h
 */
export function ringPlace(at, w, h) {
  const ok = !!at && at[0] > 0 && at[1] > 0 && at[0] < w && at[1] < h;
  return at && ok ? [Math.round(at[0] - 7), Math.round(at[1] - 7)] : null;
}

/**
 * A sensor tag's translate: up and to the right of its first sensor `p`, kept inside the canvas
 * width for a `label` of that many characters.
 * @param {{ x: number, y: number }} p
 * @param {string} label
 * @param {number} w
 */
export function tagPlace(p, label, w) {
  return [Math.round(Math.min(w - 8 * label.length - 12, p.x + 5)), Math.round(Math.max(0, p.y - 20))];
}

const translate = (/** @type {number[]} */ p) => `translate(${p[0]}px, ${p[1]}px)`;

/** A span moved every frame while playing: its own compositor layer, so a move repaints nothing. */
function mover(/** @type {string} */ cls, /** @type {Record<string, any>} */ attrs = {}) {
  const e = el('span', { class: cls, ...attrs });
  e.style.willChange = 'transform';
  return e;
}

/** The overlay's elements and the functions that move them. */
export function createOverlays() {
  const overlay = el('div', { class: 'wl-w3-overlay', 'aria-hidden': 'true' });
  // The strain point (FE wings): a ring at its projected position on the drawn wing.
  const pointMark = mover('wl-w3-point', { hidden: true });
  overlay.append(pointMark);
  // The sensing panel's K best sensors (colour 6): a dot per sensor, a numbered tag per group of
  // sensors that sit closer on screen than a tag (see placeSensors).
  const sensorLayer = el('div', { class: 'wl-w3-sensors', 'data-sensors': '0', hidden: true });
  overlay.append(sensorLayer);
  const labelEls = LABELS.map(([t, kind, c]) => {
    // Hidden until the first frame places it (else every label sits at the canvas's corner).
    const e = mover(`wl-w3-label wl-w3-label-${kind}`, { text: t, hidden: true });
    e.style.color = c;
    overlay.append(e);
    return e;
  });
  const sensors = sensorMarks(sensorLayer);

  return {
    overlay,
    /** Moves the labels to `labelPlaces`' positions. */
    placeLabels(/** @type {(number[] | null)[]} */ places) {
      places.forEach((p, j) => {
        const e = labelEls[j];
        e.hidden = !p;
        if (p) e.style.transform = translate(p);
      });
    },
    /** Hides the strain point's ring. */
    hidePoint() {
      pointMark.hidden = true;
    },
    /** Puts the ring at `at` (CSS px; hidden off the canvas), titled with the point (mm). */
    placePoint(
      /** @type {number[] | null} */ at,
      /** @type {number} */ w,
      /** @type {number} */ h,
      /** @type {number[]} */ p,
    ) {
      const place = ringPlace(at, w, h);
      pointMark.hidden = !place;
      if (place) pointMark.style.transform = translate(place);
      const title = `strain point (${p[0]}, ${p[1]}) mm`;
      if (pointMark.title !== title) pointMark.title = title;
    },
    /** Where the ring is drawn (its centre, CSS px in the canvas), or null when hidden. */
    pointOnScreen() {
      if (pointMark.hidden) return null;
      const m = /translate\((-?\d+)px, (-?\d+)px\)/.exec(pointMark.style.transform);
      return m ? [Number(m[1]) + 7, Number(m[2]) + 7] : null;
    },
    ...sensors,
  };
}

/**
 * The sensor dots and tags in `layer`. place(pts, w, h, regroup) moves the dots every drawn frame;
 * which sensors share a numbered tag is decided again only when `regroup` (the text rate while
 * playing), after regroup(), or when the set changed. Moves only what moved a pixel.
 * @param {HTMLElement} layer
 */
function sensorMarks(layer) {
  /** @type {{ x: number, y: number, ranks: number[] }[] | null} */
  let groups = null;
  /** @type {HTMLElement[]} */
  const dots = [];
  /** @type {HTMLElement[]} */
  const tags = [];
  const hide = () => {
    if (!layer.hidden) {
      layer.hidden = true;
      layer.dataset.sensors = '0';
    }
    groups = null;
  };
  const placeDots = (
    /** @type {{ x: number, y: number, rank: number }[]} */ pts,
    /** @type {number} */ w,
    /** @type {number} */ h,
  ) => {
    while (dots.length < pts.length) {
      const d = mover('wl-w3-sdot');
      dots.push(d);
      layer.append(d);
    }
    pts.forEach((p, j) => {
      const d = dots[j];
      const ok = Number.isFinite(p.x) && Number.isFinite(p.y) && p.x >= 0 && p.y >= 0 && p.x <= w && p.y <= h;
      if (d.hidden !== !ok) d.hidden = !ok;
      if (d.dataset.rank !== String(p.rank)) d.dataset.rank = String(p.rank);
      const tf = ok ? `translate(${Math.round(p.x - 3)}px, ${Math.round(p.y - 3)}px)` : '';
      if (ok && d.style.transform !== tf) d.style.transform = tf;
    });
    for (let j = pts.length; j < dots.length; j++) dots[j].hidden = true;
  };
  const placeTags = (
    /** @type {typeof groups & {}} */ gs,
    /** @type {Map<number, { x: number, y: number }>} */ byRank,
    /** @type {number} */ w,
    /** @type {number} */ h,
  ) => {
    while (tags.length < gs.length) {
      const t = mover('wl-w3-stag');
      tags.push(t);
      layer.append(t);
    }
    gs.forEach((g, j) => {
      const t = tags[j];
      const p = byRank.get(g.ranks[0]);
      const label = groupLabel(g.ranks, 6);
      if (t.textContent !== label) {
        t.textContent = label;
        t.dataset.ranks = g.ranks.join(',');
        t.title = `sensor${g.ranks.length > 1 ? 's' : ''} ${label} of the greedy placement (1 = chosen first)`;
      }
      const ok = !!p && p.x >= 0 && p.y >= 0 && p.x <= w && p.y <= h;
      if (t.hidden !== !ok) t.hidden = !ok;
      if (!ok || !p) return;
      const tf = translate(tagPlace(p, label, w));
      if (t.style.transform !== tf) t.style.transform = tf;
    });
    for (let j = gs.length; j < tags.length; j++) tags[j].hidden = true;
  };
  return {
    /** Forgets the tags' grouping (a new map or colour): the next placeSensors groups afresh. */
    regroupSensors() {
      groups = null;
    },
    /**
     * Places the sensors at their screen points `pts` (sensorPoints in www/wing3d/picking.js) on a
     * w × h canvas; null or none hides the layer.
     */
    placeSensors(
      /** @type {{ x: number, y: number, rank: number }[] | null} */ pts,
      /** @type {number} */ w,
      /** @type {number} */ h,
      /** @type {boolean} */ regroup,
    ) {
      if (!pts || !pts.length) {
        hide();
        return;
      }
      placeDots(pts, w, h);
      const byRank = new Map(pts.map((p) => [p.rank, p]));
      if (
        regroup ||
        !groups ||
        groups.reduce((a, g) => a + g.ranks.length, 0) !== pts.length ||
        groups.some((g) => !byRank.has(g.ranks[0]))
      ) {
        groups = clusterMarkers(
          pts.filter((p) => Number.isFinite(p.x) && Number.isFinite(p.y)),
          22,
        );
      }
      placeTags(groups, byRank, w, h);
      if (layer.hidden) layer.hidden = false;
      layer.dataset.sensors = String(pts.length);
    },
  };
}
