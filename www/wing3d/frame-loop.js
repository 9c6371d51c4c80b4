// @ts-check
// The 3-D panel's play loop: one requestAnimationFrame chain that advances the simulated time at
// the chosen speed, draws, and hands the time to the store (the responses plot's cursor, the
// time slider) at most every PUSH_MS. It runs only while the panel is on screen and the tab
// visible, and on a slow machine draws ≈ 30 frames per second. The time step and the frame
// gate are pure (tests/js/wing3d_frame_loop.test.mjs, which also runs the loop on a stand-in
// clock).

/** While playing, the time goes to the store (responses plot cursor, time slider) at most this often (ms). */
export const PUSH_MS = 100;
/**
 * When the frames delivered while playing come slower than SLOW_FRAME_MS apart on average (a
 * software rasteriser, a busy machine), the wing is drawn at most every CAPPED_FRAME_MS (≈ 30 fps),
 * leaving the rest of each 60 Hz period to the sliders and the compositor.
 */
export const SLOW_FRAME_MS = 24;
export const CAPPED_FRAME_MS = 30;

/**
 * The simulated time after `dtMs` real milliseconds at `speed` simulated seconds per second,
 * back to 0 past the run's end `dur`.
 * @param {number} t
 * @param {number} dtMs
 * @param {number} speed
 * @param {number} dur
 */
export function advanceTime(t, dtMs, speed, dur) {
  const next = t + (dtMs / 1000) * speed;
  return next > dur ? 0 : next;
}

/**
 * The frame gate: due(now) says whether to draw the animation frame at `now` (ms). It keeps a
 * running mean of the interval between drawn frames and, while that is above SLOW_FRAME_MS,
 * lets a frame through only CAPPED_FRAME_MS after the last one.
 */
export function frameGate() {
  let lastDraw = 0;
  let avg = 0;
  return {
    due(/** @type {number} */ now) {
      if (avg > SLOW_FRAME_MS && now - lastDraw < CAPPED_FRAME_MS) return false;
      if (lastDraw) avg = avg ? 0.9 * avg + 0.1 * (now - lastDraw) : now - lastDraw;
      lastDraw = now;
      return true;
    },
    get mean() {
      return avg;
    },
  };
}

/**
 * The play loop of one panel. `ready()` says whether there is a view to draw into; `draw(t)`
 * draws the instant t; `speed()` is the slow-motion factor;
 * `duration()` the run's end (s); `box.dataset.loop` says running | stopped | paused-hidden |
 * paused-offscreen. `env` replaces the browser's clock and document (tests).
 * @param {{ box: HTMLElement, store: any, ready: () => boolean, draw: (t: number) => void, speed: () => number, duration: () => number,
 *   env?: { raf: (f: (now: number) => void) => number, caf: (id: number) => void, now: () => number, doc: { hidden: boolean, addEventListener: Function, removeEventListener: Function } } }} o
 */
export function createFrameLoop({ box, store, ready, draw, speed, duration, env }) {
  const raf = env ? env.raf : (/** @type {(now: number) => void} */ f) => requestAnimationFrame(f);
  const caf = env ? env.caf : (/** @type {number} */ id) => cancelAnimationFrame(id);
  const clock = env ? env.now : () => performance.now();
  const doc = env ? env.doc : document;
  let id = 0;
  /** @type {number | null} the instant drawn while playing (s); reaches the store every PUSH_MS */
  let playT = null;
  let pushing = false;
  let lastPush = 0;
  /** on screen (IntersectionObserver); the loop pauses while off screen or the tab is hidden */
  let onScreen = true;
  /** @type {IntersectionObserver | null} */
  let vis = null;

  const pausedState = () => (doc.hidden ? 'paused-hidden' : 'paused-offscreen');

  /** Ends the loop; the instant it showed goes to the store (the cursor, the time slider). */
  function stop(/** @type {string} */ why) {
    if (id) caf(id);
    id = 0;
    box.dataset.loop = why;
    if (playT != null) {
      const t = playT;
      playT = null;
      if (store.get().t3d !== t) store.set({ t3d: t });
    }
  }

  /** Starts the loop when playing, on screen and visible (else says why it is paused). */
  function start() {
    if (!ready() || id || !store.get().playing) return;
    if (!onScreen || doc.hidden) {
      stop(pausedState());
      return;
    }
    box.dataset.loop = 'running';
    playT = store.get().t3d ?? 0;
    let prev = clock();
    const gate = frameGate();
    const step = (/** @type {number} */ now) => {
      id = 0;
      if (!store.get().playing) {
        stop('stopped');
        return;
      }
      if (!onScreen || doc.hidden) {
        stop(pausedState());
        return;
      }
      id = raf(step);
      if (!gate.due(now)) return;
      const t = advanceTime(playT ?? 0, now - prev, speed(), duration());
      prev = now;
      playT = t;
      draw(t);
      if (now - lastPush >= PUSH_MS) {
        lastPush = now;
        pushing = true;
        try {
          store.set({ t3d: t });
        } finally {
          pushing = false;
        }
      }
    };
    id = raf(step);
  }

  function onVisibility() {
    if (!doc.hidden) start();
  }

  return {
    start,
    stop,
    /** The instant being played (null when not playing). */
    get t() {
      return playT;
    },
    /** A time set from outside while playing becomes the loop's time (so a pause keeps it). */
    set t(/** @type {number | null} */ t) {
      playT = t;
    },
    /** True while the loop itself is handing its time to the store. */
    get pushing() {
      return pushing;
    },
    /** When the loop last handed its time to the store (ms, the frame clock). */
    get lastPush() {
      return lastPush;
    },
    /** Pauses the loop off screen (IntersectionObserver on `target`) and in a hidden tab; resumes when seen. */
    watch(/** @type {Element} */ target) {
      if (typeof IntersectionObserver === 'function') {
        vis = new IntersectionObserver((entries) => {
          onScreen = entries[entries.length - 1].isIntersecting;
          if (onScreen) start();
        });
        vis.observe(target);
      }
      doc.addEventListener('visibilitychange', onVisibility);
    },
    destroy() {
      if (vis) vis.disconnect();
      doc.removeEventListener('visibilitychange', onVisibility);
      if (id) caf(id);
    },
  };
}
