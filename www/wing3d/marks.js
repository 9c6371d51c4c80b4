// @ts-check
// What the 3-D panel marks on the drawn wing, and the one thing a click on it picks: the axis
// and plane labels, the strain point's ring, the sensing panel's sensors (colour 6), and the
// strain point chosen by a click (FE wings only). The geometry is picking.js's (pointer ↔ wing)
// and overlays.js's (the elements); this module asks the panel, through getters, for the wing,
// the camera, the instant and the exaggeration shown. Tested with stand-ins in
// tests/js/wing3d_marks.test.mjs.
import * as S from '../scene3d.js';
import * as P from './picking.js';
import { labelPlaces } from './overlays.js';
import { SENSE_COLOUR } from './fields.js';

/**
 * @param {{
 *   store: import('../lab.js').ViewContext['store'],
 *   rig: { cam: S.Camera | null },
 *   overlays: ReturnType<typeof import('./overlays.js').createOverlays>,
 *   fields: { senseUp: any },
 *   dom: { status: HTMLElement, showAxes: HTMLInputElement, showBody: HTMLInputElement, showPlane: HTMLInputElement },
 *   fe: () => any,
 *   cssSize: () => number[],
 *   colour: () => number,
 *   exaggeration: () => number,
 *   tNow: () => number,
 * }} deps
 */
export function createWingMarks(deps) {
  const { store, rig, overlays, fields, dom, cssSize } = deps;
  const planformHit = P.planformHits();

  /** The drawn wing's nodes on screen at the instant shown (CSS pixels), for picking and the point mark. */
  function screenNodes(/** @type {number} */ t = deps.tNow()) {
    const [w, h] = cssSize();
    return P.screenNodes(deps.fe(), store.get().result, rig.cam, t, deps.exaggeration(), w, h);
  }

  /**
   * Where the planform point (x, y) mm is drawn now (CSS px in the canvas): its triangle of the
   * flat planform gives barycentric weights, applied to the drawn (cambered, deflected, rotated,
   * projected) nodes. Null when the point is off the wing or behind the eye.
   */
  function drawnPoint(
    /** @type {number} */ xmm,
    /** @type {number} */ ymm,
    /** @type {number | undefined} */ t = undefined,
  ) {
    const fe = deps.fe();
    if (!fe) return null;
    const sn = screenNodes(t);
    if (!sn) return null;
    const hit = planformHit(fe, xmm, ymm);
    return hit ? P.drawnAt(hit, sn.proj) : null;
  }

  /** Places the strain-point ring over the drawn wing (hidden for the paper mode set). */
  function placePoint(/** @type {number | undefined} */ t = undefined) {
    const s = store.get();
    const fe = deps.fe();
    const p = s.strain_point || (fe && fe.strain_point_mm);
    if (!fe || !p || s.modes !== 'fe' || !rig.cam) {
      overlays.hidePoint();
      return;
    }
    const [cw, ch] = cssSize();
    overlays.placePoint(drawnPoint(p[0], p[1], t), cw, ch, p);
  }

  return {
    screenNodes,
    drawnPoint,
    placePoint,

    /** The labels, the strain point's ring and the sensors for the frame just drawn. */
    placeOverlays(
      /** @type {number[]} */ ang,
      /** @type {ArrayLike<number>} */ q,
      /** @type {number} */ t,
      /** @type {boolean} */ regroup,
    ) {
      const fe = deps.fe();
      if (rig.cam && fe) {
        const [w, h] = cssSize();
        const show = {
          fixed: dom.showAxes.checked,
          wing: dom.showAxes.checked,
          body: dom.showBody.checked,
          plane: dom.showPlane.checked,
        };
        overlays.placeLabels(labelPlaces(rig.cam, S.spanOf(fe.nodes), ang, w, h, show));
      }
      placePoint(t);
      const m = deps.colour() === SENSE_COLOUR && rig.cam ? fields.senseUp : null;
      if (!m || !fe || !m.sensors.length) {
        overlays.placeSensors(null, 0, 0, regroup);
        return;
      }
      const [w, h] = cssSize();
      overlays.placeSensors(
        P.sensorPoints(fe, m.sensors, ang, q, deps.exaggeration(), /** @type {S.Camera} */ (rig.cam), w, h),
        w,
        h,
        regroup,
      );
    },

    /**
     * A click on the drawn wing at (x, y) CSS pixels: the front-most triangle there gives the
     * planform point (undeformed x, y), which becomes the strain point (mm). FE wings only.
     */
    pickAt(/** @type {number} */ x, /** @type {number} */ y) {
      const fe = deps.fe();
      if (!fe || store.get().modes !== 'fe') {
        dom.status.textContent =
          'The strain point can be chosen on an FE wing only (the paper’s strains exist only at P).';
        return null;
      }
      const sn = screenNodes();
      if (!sn) return null;
      const mm = P.strainPointAt(fe, sn.proj, x, y);
      if (!mm) return null;
      store.set({ strain_point: mm });
      return mm;
    },
  };
}
