// @ts-check
// What the lab (and its tests) see of a mounted 3-D panel (www/wing3d/panel.js): starting it,
// its view, time and camera, picking, and the hooks the end-to-end tests wait on.

/**
 * The panel's public face.
 * @param {import('./panel.js').Wing3dPanel} p
 */
export function panelApi(p) {
  return {
    startWhenVisible: () => p.startWhenVisible(),
    start: () => p.start(),
    get view() {
      return p.view;
    },
    get t() {
      return p.tNow();
    },
    get camera() {
      return p.rig.cam;
    },
    get ranges() {
      return p.ranges;
    },
    get frames() {
      return p.frames;
    },
    get fe() {
      return p.fe;
    },
    pickAt: (/** @type {number} */ x, /** @type {number} */ y) => p.marks.pickAt(x, y),
    /**
     * Resolves once every frame asked for is on screen: the view's making done (a new wing's),
     * drawn by the worker (when it draws) and two animation frames more for the compositor
     * (tests screenshot after it).
     */
    async settled() {
      await p.making;
      const v = p.view;
      if (v && typeof v.idle === 'function') await v.idle();
      await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    },
    /** Where the strain point is drawn (CSS px in the canvas), or null when hidden. */
    pointOnScreen: () => p.overlays.pointOnScreen(),
    /** CSS px of the planform point (x, y) mm on the drawn wing at the current instant (tests). */
    screenOf: (/** @type {number} */ x, /** @type {number} */ y, /** @type {number | undefined} */ t = undefined) =>
      p.marks.drawnPoint(x, y, t),
    setTime(/** @type {number} */ t) {
      const r = p.store.get().result;
      const dur = r ? r.analysis.sim.t[r.analysis.sim.t.length - 1] : 2;
      p.store.set({ playing: false, t3d: Math.min(dur, Math.max(0, Number.isFinite(t) ? t : 0)) });
    },
    setPlaying(/** @type {boolean} */ on) {
      p.store.set({ playing: !!on });
    },
    setLayout: (/** @type {string} */ mode) => p.setLayout(mode),
    setScreen: (/** @type {string} */ screen) => p.setScreen(screen),
    destroy: () => p.destroy(),
  };
}
