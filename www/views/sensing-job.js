// @ts-check
// The sensing panel's analysis (views/sensing.js): when to ask for one (SENSE_DELAY_MS after the
// last change, only while the panel is visible, one at a time: a change during a run asks again
// when it ends), the worker job `sense` (wasm senseRotation) with its progress, cancel and status
// words, and the last result with what it was computed for (the wing, the body rate, the picked
// point and the run's configuration).
import { fmt, errorText } from '../format.js';
import { bodyRateVector } from '../state.js';
import { senseFe } from '../sensemap.js';

/** Wait after the last change before a new analysis is asked for, ms. */
export const SENSE_DELAY_MS = 250;

/**
 * @param {import('../lab.js').ViewContext} ctx
 * @param {{ status: HTMLElement, prog: HTMLProgressElement, cancel: HTMLElement }} ui the controls' status line, progress bar and cancel button
 * @param {HTMLElement} box the map's box (data-state, data-ms, data-worker-ms)
 * @param {{ point: () => ([number, number] | null), visible: () => boolean, onResult: () => void }} hooks
 *   the picked point (null = the best sensor), whether the panel is on screen, and what to draw
 *   when a result arrives
 */
export function senseJob(ctx, ui, box, hooks) {
  const { store, engine } = ctx;
  const { status, prog, cancel } = ui;
  /** @type {any} the last wasm result (SensingResult) */
  let result = null;
  /** @type {{ fe: any, key: string } | null} what `result` was computed for */
  let resultFor = null;
  /** the run configuration (JSON) the result is for (published with sense_map, so the 3-D view can tell an outdated map) */
  let resultCfg = '';
  /** @type {{ id: number, key: string } | null} */
  let running = null;
  let dirty = false;
  /** @type {ReturnType<typeof setTimeout> | undefined} */
  let timer;

  /** What an analysis depends on: the body rate, the point and the config (kinematics, modes, run). */
  const keyOf = (s) => JSON.stringify({ w: bodyRateVector(s), p: hooks.point(), c: s.result ? s.result.cfg : null });

  /** Asks for a new analysis SENSE_DELAY_MS after the last change (one at a time). */
  function schedule() {
    clearTimeout(timer);
    timer = setTimeout(request, SENSE_DELAY_MS);
  }

  function request() {
    const s = store.get();
    const fe = senseFe(s);
    if (!fe || !hooks.visible() || !s.result) return;
    const cfg = s.result.cfg;
    const key = keyOf(s);
    if (result && resultFor && resultFor.fe === fe && resultFor.key === key) return;
    if (running) {
      dirty = true;
      return;
    }
    const w = bodyRateVector(s);
    const t0 = performance.now();
    /** @type {Record<string, unknown>} */
    const opts = {};
    const point = hooks.point();
    if (point) opts.point_mm = point;
    const job = engine.run(
      'sense',
      { cfg, fe: { nodes: fe.nodes, triangles: fe.triangles, strain_nodes: fe.strain_nodes }, body_rate: w, opts },
      (done, total) => {
        prog.max = total;
        prog.value = done;
      },
    );
    running = { id: job.id, key };
    dirty = false;
    box.dataset.state = 'computing';
    const rho = cfg.aero ? Number(cfg.aero.air_density_kg_m3) : 0;
    const medium = rho > 0 ? `in a fluid of ${fmt(rho, 3)} kg/m³` : 'in a vacuum';
    status.textContent = `Computing: two runs of the FE wing ${medium} (with and without ω_b), then ${fe.n_nodes} nodes × 3 strain components…`;
    prog.hidden = false;
    cancel.hidden = false;
    job.promise
      .then(
        ({ result: r, ms }) => {
          running = null;
          result = r;
          resultFor = { fe, key };
          resultCfg = JSON.stringify(cfg);
          const t1 = performance.now();
          hooks.onResult();
          const t2 = performance.now();
          box.dataset.ms = String(Math.round(t2 - t0));
          box.dataset.workerMs = String(Math.round(ms));
          status.textContent = `Done, ${medium}, in ${fmt((t2 - t0) / 1000, 2)} s (analysis ${fmt(ms / 1000, 2)} s in the worker, drawing ${fmt(t2 - t1, 2)} ms).${r.warnings.length ? ' Warnings: ' + r.warnings.join('; ') : ''}`;
        },
        (e) => {
          const why = errorText(e);
          box.dataset.state = why === 'cancelled' ? 'cancelled' : 'error';
          status.textContent = why === 'cancelled' ? 'Cancelled; change a setting to compute again.' : `Error: ${why}`;
        },
      )
      .finally(() => {
        running = null;
        prog.hidden = true;
        cancel.hidden = true;
        if (dirty) schedule();
      });
  }

  return {
    /** @returns {any} the last result (SensingResult), or null */
    get result() {
      return result;
    },
    /** The run configuration (JSON) of the last result. */
    get cfg() {
      return resultCfg;
    },
    /** Whether an analysis is running. */
    get running() {
      return !!running;
    },
    schedule,
    /** Whether there is no result for the FE wing in use. */
    stale() {
      const fe = senseFe(store.get());
      return !result || !resultFor || resultFor.fe !== fe || fe === null;
    },
    /** Whether the last result is for another wing than `fe`. */
    forOtherWing(/** @type {any} */ fe) {
      return !!(result && resultFor && resultFor.fe !== fe);
    },
    cancel() {
      if (running) engine.cancel(running.id);
    },
    destroy() {
      clearTimeout(timer);
    },
  };
}
