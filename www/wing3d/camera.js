// @ts-check
// The 3-D panel's camera: the renderer's camera (WingView) and its mirror here (www/scene3d.js
// Camera) kept in step, fitted to the whole stroke until the user orbits or zooms, and driven by
// drag, wheel and keys. The pure parts (the lift to frame, when to refit, a click versus a drag,
// a renderer camera read back) are tested in tests/js/wing3d_camera.test.mjs, and so is the rig
// with a stand-in WingView.
import * as S from '../scene3d.js';

/** Margin of the camera fit, as a fraction of the half-width and half-height (2 % of each side). */
export const FIT_MARGIN = 0.04;
/** A pointer that comes up within this many CSS px of where it went down is a click, not a drag. */
export const CLICK_PX = 4;
/** Zoom factor per wheel notch (out for a positive deltaY). */
export const WHEEL_ZOOM = 1.1;

/**
 * The mirror of a camera returned by the renderer ([tx, ty, tz, yaw, pitch, distance]).
 * @param {ArrayLike<number>} c
 * @param {number} fov
 * @returns {S.Camera}
 */
export function cameraFromRenderer(c, fov) {
  return { target: [c[0], c[1], c[2]], yaw: c[3], pitch: c[4], distance: c[5], fov };
}

/**
 * `count` poses [α, β, γ] spread over one flap period of a run (the stroke to fit), or null
 * before a run with angles.
 * @param {any} result LiveResult
 */
export function strokePoses(result, count = 32) {
  if (!result || !result.angles) return null;
  const { alpha, beta, gamma } = result.angles;
  const a = result.analysis;
  return S.flapSamples(alpha.length, a.sim.sample_rate_hz, a.sim.flap_freq_hz, count).map((i) => [
    alpha[i],
    beta[i],
    gamma[i],
  ]);
}

/**
 * How far (m) the fit lets the wing move off its plane: the drawn deflection (true ×
 * exaggeration), at most two spans. (In a parametric instability the response grows every flap:
 * ~1e42 m after 2 s at f_d = 54.5 Hz.)
 * @param {number | null} runDeflection m
 * @param {number} exaggeration
 * @param {number} span m
 */
export function fitLift(runDeflection, exaggeration, span) {
  const drawn = (runDeflection || 0) * exaggeration;
  return Number.isFinite(drawn) ? Math.min(drawn, 2 * span) : 2 * span;
}

/**
 * What the fitted camera depends on: the stroke (amplitudes and phases), the canvas size and the
 * drawn deflection `lift` (m) to an eighth of a decade. The camera is refitted when it changes.
 * @param {Record<string, any>} s store state
 * @param {number} width
 * @param {number} height
 * @param {number} lift
 */
export function refitKey(s, width, height, lift) {
  const liftKey = lift > 0 ? Math.round(Math.log10(lift) * 8) : -99;
  return `${s.alpha0}/${s.beta0}/${s.gamma0}/${s.alpha_phase}/${s.beta_phase}/${s.gamma_phase}/${width}x${height}/${liftKey}`;
}

/**
 * Whether a pointer that went down at `down` and came up at (x, y) is a click.
 * @param {number[] | null} down
 * @param {number} x
 * @param {number} y
 */
export function isClick(down, x, y) {
  return !!down && Math.hypot(x - down[0], y - down[1]) < CLICK_PX;
}

/** The zoom factor of a wheel event's deltaY. */
export function wheelZoom(/** @type {number} */ deltaY) {
  return deltaY > 0 ? WHEEL_ZOOM : 1 / WHEEL_ZOOM;
}

/**
 * The camera of one panel. `view()` is the current WingView (null while there is none).
 * cam is the mirror; `user` is set once the user moved the camera (fits then leave it alone);
 * `fitKey` is '' until the first fit, then refitKey's value of the last fit.
 * @param {() => any} view
 */
export function createCameraRig(view) {
  const rig = {
    /** @type {S.Camera | null} mirror of the renderer's camera */
    cam: null,
    user: false,
    fitKey: '',
    /** The renderer's initial camera for a new wing of span `span`; fits allowed again. */
    reset(/** @type {number} */ span) {
      rig.cam = S.defaultCamera(span);
      rig.user = false;
      rig.fitKey = '';
    },
    /** Sets the renderer's camera to `to` (and the mirror). */
    move(/** @type {S.Camera} */ to) {
      const v = view();
      if (!v) return;
      v.setCamera(to.target[0], to.target[1], to.target[2], to.yaw, to.pitch, to.distance);
      rig.cam = to;
    },
    /** The mirror of the renderer's camera as WingView returned it. */
    mirror(/** @type {ArrayLike<number>} */ c) {
      return cameraFromRenderer(c, rig.cam ? rig.cam.fov : S.defaultCamera(0.05).fov);
    },
    /**
     * Fits the camera to the whole stroke with the renderer's own fit (WingView.fitPoints: the
     * target centres the stroke, the distance is the smallest that keeps every pose inside): from
     * each of a few view directions when `search` (or before the first fit), keeping the most
     * wing on screen; else from the current direction. Nothing once the user moved the camera.
     * Returns the wing's share of the canvas when a search ran.
     * @param {boolean} search
     * @param {any} fe FeModesResult
     * @param {number[][] | null} poses strokePoses
     * @param {number} lift fitLift
     * @param {number} width canvas backing store
     * @param {number} height
     * @returns {number | null}
     */
    fit(search, fe, poses, lift, width, height) {
      const v = view();
      if (!v || !fe || rig.user || !poses) return null;
      const span = S.spanOf(fe.nodes);
      const ol = S.outline(fe.nodes);
      const pts = Float32Array.from(S.posePoints(ol.nodes, poses, { lift: lift + ol.zmax }));
      /** @type {number | null} */
      let coverage = null;
      if (search || !rig.fitKey) {
        const fitFrom = (/** @type {S.Camera} */ c) => {
          rig.move(c);
          return rig.mirror(v.fitPoints(pts, FIT_MARGIN));
        };
        const best = S.bestView(span, fe.nodes, fe.triangles, poses, width, height, { lift, fit: fitFrom });
        if (!best) return null;
        rig.move(best.camera);
        coverage = best.coverage;
      } else {
        rig.cam = rig.mirror(v.fitPoints(pts, FIT_MARGIN));
      }
      rig.fitKey = 'fitted';
      return coverage;
    },
    /** A drag by (dx, dy) CSS px. */
    orbit(/** @type {number} */ dx, /** @type {number} */ dy) {
      const v = view();
      if (!v) return;
      v.orbit(dx, dy);
      if (rig.cam) rig.cam = S.orbit(rig.cam, dx, dy);
      rig.user = true;
    },
    /** A zoom by `f` (distance × f). */
    zoom(/** @type {number} */ f) {
      const v = view();
      if (!v) return;
      v.zoom(f);
      rig.cam = S.zoom(rig.cam, f);
      rig.user = true;
    },
    /** A key; true when the renderer used it (the camera moved). */
    key(/** @type {string} */ k) {
      const v = view();
      if (!v || !v.key(k)) return false;
      rig.cam = S.key(rig.cam, k) || rig.cam;
      rig.user = true;
      return true;
    },
  };
  return rig;
}

/**
 * Drag to orbit, wheel to zoom, arrows and + − to move the camera, Space to play or pause, and a
 * click (not a drag) to pick, on `canvas`. `moved` redraws after a camera move.
 * @param {HTMLCanvasElement} canvas
 * @param {ReturnType<typeof createCameraRig>} rig
 * @param {{ view: () => any, moved: () => void, click: (x: number, y: number) => void, togglePlay: () => void }} on
 */
export function bindCamera(canvas, rig, on) {
  /** @type {number[] | null} */
  let last = null;
  /** @type {number[] | null} where the pointer went down (a click: up within CLICK_PX of it) */
  let down = null;
  canvas.addEventListener('pointerdown', (e) => {
    last = [e.clientX, e.clientY];
    down = last;
    canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointerup', (e) => {
    if (isClick(down, e.clientX, e.clientY)) {
      const b = canvas.getBoundingClientRect();
      on.click(e.clientX - b.left, e.clientY - b.top);
    }
    down = null;
  });
  canvas.addEventListener('pointermove', (e) => {
    if (!last || !on.view()) return;
    rig.orbit(e.clientX - last[0], e.clientY - last[1]);
    last = [e.clientX, e.clientY];
    on.moved();
  });
  const end = () => {
    last = null;
  };
  canvas.addEventListener('pointerup', end);
  canvas.addEventListener('pointercancel', end);
  canvas.addEventListener(
    'wheel',
    (e) => {
      if (!on.view()) return;
      e.preventDefault();
      rig.zoom(wheelZoom(e.deltaY));
      on.moved();
    },
    { passive: false },
  );
  canvas.addEventListener('keydown', (e) => {
    if (!on.view()) return;
    if (e.key === ' ') {
      e.preventDefault();
      on.togglePlay();
    } else if (rig.key(e.key)) {
      e.preventDefault();
      on.moved();
    }
  });
}
