// @ts-check
// The live recompute: one request per task after parameter changes (engine.requestLive; only the
// newest result is published), the wing wanted (from the wing parameters and outline), the FE
// wing computed in a worker when the FE mode set needs it, and the work that must finish before
// the first computation (the `planform=` file, the `#s=` fragment). Used by www/lab.js, which
// makes one per connection.
import { paramsOf } from '../state.js';
import { errorText } from '../format.js';

/** @typedef {import('./types.js').LabState} LabState */

/**
 * The outline of the wing wanted (mm), or null for the core's default: an own outline (file,
 * editor, planform= URL, share fragment) first, then a built-in one by id.
 * @param {Readonly<Pick<LabState, 'wing' | 'outline'>>} s
 * @param {() => { id: string, points_mm: [number, number][] }[]} planforms the core's built-in outlines
 * @returns {[number, number][] | null}
 */
export function wingPoints(s, planforms) {
  if (s.wing && s.wing.points) return s.wing.points;
  if (s.outline && s.outline !== 'manduca') {
    const b = planforms().find((p) => p.id === s.outline);
    if (!b) throw new Error(`outline: no built-in outline "${s.outline}" in this wasm build`);
    return b.points_mm;
  }
  return null;
}

/**
 * @param {{
 *   store: import('../store.js').Store<LabState>,
 *   engine: ReturnType<typeof import('../engine.js').createEngine>,
 *   alive: () => boolean,
 *   error: (text: string) => void,
 *   notice: (text: string) => void,
 *   publish: (r: import('../engine.js').LiveResult) => void,
 * }} host `alive()` says whether the element is still built with this engine; `error(text)`
 *   shows (or with '' hides) the lab's error line; `publish(r)` hands a newest result to the
 *   panels' redraws.
 */
export function createLive({ store, engine, alive, error, notice, publish }) {
  /** -1 while a recompute is queued for the end of the task, else 0 */
  let raf = 0;
  /** Work that must finish before the first computation (planform= file, #s= fragment). */
  let pending = 0;
  /** Why the wanted wing cannot be built ('' = it can). */
  let wingError = '';
  let feRunning = false;

  /**
   * Recomputes once the current task's parameter changes are in (a microtask: several set()
   * calls in one handler make one request). The request goes to the engine's live worker
   * (engine.requestLive), so the paint after a key press only shows the slider's new value;
   * the panels redraw when the newest result arrives, and superseded results are dropped.
   */
  function schedule() {
    if (raf) return;
    raf = -1;
    queueMicrotask(() => {
      if (raf !== -1) return;
      raf = 0;
      if (alive()) render();
    });
  }

  /** Tells the engine which wing is wanted (from the wing parameters and outline). */
  function wantWing() {
    if (!engine.ready || pending) return;
    const s = store.get();
    if (s.wing && s.wing.source === 'import') return;
    try {
      engine.setWing(
        engine.wingInput(
          paramsOf(s),
          wingPoints(s, () => engine.planforms()),
        ),
      );
      wingError = '';
      // Already computed (cached, or just computed by the wing panel): use it now.
      if (engine.wingCurrent && s.fe !== engine.fe) {
        feReady(/** @type {import('../engine.js').FeModesResult} */ (engine.fe));
      }
    } catch (e) {
      wingError = `The wing is not valid: ${errorText(e)}`;
      error(wingError);
    }
  }

  /** Starts the FE wing wanted when the FE mode set needs it; true while the first one computes. */
  function ensureWing() {
    const s = store.get();
    if (s.modes !== 'fe' || engine.wingCurrent || wingError) return false;
    const first = !engine.fe;
    if (first) store.set({ status: 'computing the FE wing’s modes in a worker…' });
    if (!feRunning) {
      feRunning = true;
      engine.ensureFe().then(
        (fe) => {
          feRunning = false;
          feReady(fe);
        },
        (e) => {
          feRunning = false;
          // The lab stays usable: the previous wing (or, with none yet, the paper table's
          // modes) goes on, with the reason shown until the wing changes.
          wingError = `The FE wing could not be computed: ${errorText(e).replace(/\.?$/, '.')}${engine.fe ? ' The previous wing stays in use.' : ' Showing the paper table’s modes meanwhile.'}`;
          error(wingError);
          schedule();
        },
      );
    }
    return first;
  }

  /** One live recompute: the newest result is published when it arrives (superseded ones are not). */
  function render() {
    if (!engine.ready || pending) return;
    if (ensureWing()) return;
    /** @type {Promise<import('../engine.js').LiveResult | null>} */
    let req;
    try {
      req = engine.requestLive(paramsOf(store.get()));
    } catch (e) {
      error(`Computation rejected: ${errorText(e)}`);
      return;
    }
    req.then(
      (r) => {
        if (r && alive()) {
          error(wingError);
          publish(r);
        }
      },
      (e) => {
        if (alive()) error(`Computation rejected: ${errorText(e)}`);
      },
    );
  }

  /** A wing became ready: publish it, keep the selected mode within 1..N, recompute. */
  function feReady(/** @type {import('../engine.js').FeModesResult} */ fe) {
    const s = store.get();
    /** @type {Partial<LabState>} */
    const patch = { fe };
    if (Number(s.mode) > fe.modes.length) patch.mode = '1';
    // A chosen strain point that is not on the new wing falls back to the wing's own point.
    if (s.strain_point) {
      try {
        engine.modalStrainAt(s.strain_point);
      } catch {
        patch.strain_point = null;
        notice(
          `The chosen strain point (${s.strain_point.join(', ')}) mm is not on this wing; using the wing's own strain point.`,
        );
      }
    }
    store.set(patch);
    schedule();
  }

  return {
    schedule,
    render,
    wantWing,
    /**
     * Runs `work` (the planform= file, the #s= fragment) with wing and computation held back
     * until it settles; what it sets in the store meanwhile is picked up by the next render().
     * @param {() => Promise<unknown>} work
     */
    async holding(work) {
      pending++;
      try {
        await work();
      } finally {
        pending--;
      }
    },
    /** Drops a queued recompute (the element is being removed). */
    reset() {
      raf = 0;
    },
  };
}
