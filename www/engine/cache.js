// @ts-check
// The engine's caches: the FE wings by input (the last few, so switching back is instant), which
// wing is wanted and which is in use (the old one stays until the new one is ready), and the
// modes' modal strains at the chosen point (once per wing and point). Pure given the solver and
// the strain function it is handed; tested in tests/js/engine_cache.test.mjs.

/** @typedef {import('../pkg/wingbeat.js').FemInput} FemInput */
/** @typedef {import('../pkg/wingbeat.js').FeModesResult & { modes_json?: string, max_nodes?: number, imported?: boolean }} FeModesResult */
/** A wing wanted: its FemInput, or the key of imported modes. */
/** @typedef {FemInput | { imported: string }} WingWanted */

/** How many FE results are kept (each is a few MB of typed arrays at most). */
export const FE_CACHE = 4;

/** The key under which an FE result is kept: its input (and strain point request). */
export const wingKey = (/** @type {unknown} */ input) => JSON.stringify(input || null);

/**
 * A map that keeps its `size` most recently stored entries.
 * @template V
 * @param {number} size
 */
export function createLru(size) {
  /** @type {Map<string, V>} */
  const map = new Map();
  return {
    get: (/** @type {string} */ key) => map.get(key),
    /** Stores `value` as the newest entry; the oldest go beyond `size`. */
    set(/** @type {string} */ key, /** @type {V} */ value) {
      map.delete(key);
      map.set(key, value);
      while (map.size > size) map.delete(/** @type {string} */ (map.keys().next().value));
    },
    get size() {
      return map.size;
    },
  };
}

/**
 * The wings: wanted, in use, computed (by key) and being computed.
 * @param {{ initial: FemInput, solve: (input: FemInput, onProgress?: (done: number, total: number) => void) => { id: number, promise: Promise<{ result: any }> }, size?: number }} deps
 *   `initial` is the wing wanted at first; `solve` computes one (a worker job).
 */
export function createWings({ initial, solve, size = FE_CACHE }) {
  /** @type {WingWanted} */
  let wanted = initial;
  /** @type {ReturnType<typeof createLru<FeModesResult>>} */
  const done = createLru(size);
  /** @type {Map<string, { id: number, promise: Promise<FeModesResult> }>} */
  const pending = new Map();
  /** @type {FeModesResult | null} the wing in use (the last one ready that was wanted) */
  let inUse = null;

  const wings = {
    /** The wing in use, or null before the first one is ready. */
    get fe() {
      return inUse;
    },
    /** Whether the wing in use is the one wanted. */
    get current() {
      return !!inUse && done.get(wingKey(wanted)) === inUse;
    },
    /** Makes `input` the wing wanted; when it is computed already it is in use at once. */
    want(/** @type {FemInput} */ input) {
      wanted = input;
      const r = done.get(wingKey(input));
      if (r) inUse = r;
    },
    /**
     * Computes a wing (or returns the one computed or being computed); once ready it becomes
     * the wing in use when it is still wanted, or when there is none yet.
     * @param {FemInput} input
     * @param {(done: number, total: number) => void} [onProgress]
     * @returns {{ id: number, promise: Promise<FeModesResult> }}
     */
    compute(input, onProgress) {
      const key = wingKey(input);
      const have = done.get(key);
      if (have) {
        wanted = input;
        inUse = have;
        return { id: 0, promise: Promise.resolve(have) };
      }
      const pend = pending.get(key);
      if (pend) return pend;
      const job = solve(input, onProgress);
      const promise = job.promise.then(({ result }) => {
        const r = /** @type {FeModesResult} */ (result);
        done.set(key, r);
        if (wingKey(wanted) === key || !inUse) inUse = r;
        return r;
      });
      const entry = { id: job.id, promise };
      pending.set(key, entry);
      const settle = () => {
        if (pending.get(key) === entry) pending.delete(key);
      };
      promise.then(settle, settle);
      return entry;
    },
    /** Uses an already computed or imported FE result as the wing in use (modes JSON import). */
    use(/** @type {FeModesResult} */ r, /** @type {string} */ key) {
      done.set(key, r);
      wanted = { imported: key };
      done.set(wingKey(wanted), r);
      inUse = r;
    },
    /**
     * The wing wanted (`input`, else the one set last), computed once; resolves at once when it
     * is ready. A rejected computation is tried again on the next call.
     * @param {FemInput} [input]
     * @returns {Promise<FeModesResult>}
     */
    ensure(input) {
      if (input) wings.want(input);
      const r = done.get(wingKey(wanted));
      if (r) {
        inUse = r;
        return Promise.resolve(r);
      }
      return wings.compute(/** @type {FemInput} */ (wanted)).promise;
    },
  };
  return wings;
}

/** @typedef {{ eps_x: number, eps_y: number, gamma_xy: number }} PointStrain */

/**
 * The modes of a wing with their modal strains at a point (mm) instead of the FE result's own
 * point, computed once per wing and point.
 * @param {(fe: FeModesResult, point: [number, number]) => PointStrain[]} strainsAt the modal
 *   strains of every mode at a point (wasm modalStrainAt)
 */
export function createPointStrains(strainsAt) {
  /** @type {{ fe: FeModesResult, key: string, strains: PointStrain[] } | null} */
  let memo = null;
  /**
   * @param {FeModesResult} fe
   * @param {[number, number] | null} point null: the modes as they are
   */
  return function modesAt(fe, point) {
    if (!point) return fe.modes;
    const key = `${point[0]},${point[1]}`;
    if (!memo || memo.fe !== fe || memo.key !== key) memo = { fe, key, strains: strainsAt(fe, [point[0], point[1]]) };
    const st = memo.strains;
    return fe.modes.map((m, k) => ({
      ...m,
      strains: [{ point: 'S', eps_x: st[k].eps_x, eps_y: st[k].eps_y, gamma_xy: st[k].gamma_xy }],
    }));
  };
}

/**
 * `cfg` with the wing `fe`'s mesh and mode shapes attached as `cfg.wing` when `cfg` is in a
 * fluid (aero.air_density_kg_m3 > 0) and its modes are that wing's; else `cfg` itself. The
 * wing travels beside the JSON config (typed arrays, copied to a worker with the message) and
 * is never part of an export.
 * @param {import('../pkg/wingbeat.js').SimConfig} cfg
 * @param {FeModesResult | null} fe
 * @returns {import('../pkg/wingbeat.js').SimConfig}
 */
export function withWing(cfg, fe) {
  const rho = cfg && cfg.aero ? Number(cfg.aero.air_density_kg_m3) : 0;
  if (!(rho > 0) || !fe || !cfg.modes || cfg.modes.length !== fe.modes.length) return cfg;
  return { ...cfg, wing: { nodes: fe.nodes, triangles: fe.triangles, shapes: fe.shapes } };
}

/** Why a fluid cannot run on the paper's table modes (the message names `air_density`). */
export function noWingInFluid(/** @type {number} */ rho) {
  return `air_density = ${rho} kg/m³ needs the FE wing's mode shapes (a fluid loads the wing point by point; the paper's table has frequencies only): choose Mode set: FE wing, or the vacuum`;
}
