// @ts-check
// The lab's observable state (the "model" of a PhET-style model/view split): one flat object
// of properties — the URL parameters of www/state.js plus derived ones such as `result` (the
// latest analysis), `fe` (the FE wing), `t3d` (the instant shown by the 3-D view) — with
// get / set(patch) / subscribe(keys, fn). Views subscribe to the keys they draw; nothing else
// reaches into them. Pure (no DOM); unit-tested in tests/js/store.test.mjs.

/**
 * @template {object} T
 * @typedef {{
 *   get(): Readonly<T>,
 *   set(patch: Partial<T>): string[],
 *   subscribe(keys: string[] | '*', fn: (state: Readonly<T>, changed: string[]) => void): () => void,
 * }} Store
 */

/**
 * @template {object} T
 * @param {T} initial
 * @returns {Store<T>}
 */
export function createStore(initial) {
  /** @type {Readonly<T>} */
  let state = Object.freeze({ ...initial });
  /** @type {Set<{ keys: string[] | '*', fn: (state: Readonly<T>, changed: string[]) => void }>} */
  const subs = new Set();
  let depth = 0;
  return {
    /** The current state (a frozen snapshot; never mutate it). */
    get() {
      return state;
    },
    /**
     * Applies `patch` (a shallow merge). Subscribers whose keys changed (by Object.is) are
     * called once, synchronously, with (state, changedKeys). Returns the changed keys.
     * A subscriber may call set() again; such nested changes notify as well.
     */
    set(patch) {
      /** @type {string[]} */
      const changed = [];
      /** @type {Record<string, unknown>} */
      const next = { ...state };
      /** @type {Record<string, unknown>} */
      const cur = state;
      for (const [k, v] of Object.entries(patch || {})) {
        if (!Object.is(cur[k], v)) {
          next[k] = v;
          changed.push(k);
        }
      }
      if (!changed.length) return changed;
      state = /** @type {Readonly<T>} */ (Object.freeze(next));
      if (++depth > 50) {
        depth = 0;
        throw new Error('store: set() recursion deeper than 50 (a subscriber keeps changing state)');
      }
      try {
        for (const s of [...subs]) {
          if (!subs.has(s)) continue;
          if (s.keys === '*' || changed.some((k) => s.keys.includes(k))) s.fn(state, changed);
        }
      } finally {
        depth--;
      }
      return changed;
    },
    /** Calls fn(state, changedKeys) whenever one of `keys` changes ('*': any). Returns unsubscribe. */
    subscribe(keys, fn) {
      const s = { keys: keys === '*' ? /** @type {'*'} */ ('*') : [...keys], fn };
      subs.add(s);
      return () => subs.delete(s);
    },
  };
}
