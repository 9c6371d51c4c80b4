// @ts-check
// The panels' redraws for a new live result, scheduled so that redrawing every panel is never
// one long task: each panel's `result` subscription runs in a task of its own (a MessageChannel
// message, not clamped like setTimeout), the panels on screen first, and a panel off the current
// screen does no work until it is shown. After the last redraw the element is told
// (`rendered`), which times the whole and fires `wl-rendered`. Used by www/lab.js only.

/** @typedef {import('../lab.js').LabState} LabState */
/** @typedef {{ name: string, fn: Function }} Redraw */

/**
 * @param {{
 *   store: import('../store.js').Store<LabState>,
 *   section: (name: string) => HTMLElement | undefined,
 *   live: () => boolean,
 *   rendered: (r: import('../engine.js').LiveResult, t1: number) => void,
 * }} host `section(name)` is a panel's section (hidden when off screen); `live()` says whether
 *   the element is still built; `rendered(r, t1)` runs once all panels show result `r`
 *   (published at time t1).
 */
export function createDraws({ store, section, live, rendered }) {
  /** Whether a new result's panel redraws are being run (one task each, see drain). */
  let drawing = false;
  /** @type {Redraw[]} */
  let queue = [];
  /** @type {Redraw[]} redraws skipped by hidden panels (see flush) */
  let stale = [];
  /** @type {MessageChannel | null} */
  let port = null;
  /** bumped by reset(): a redraw sequence of the old build stops */
  let gen = 0;
  /** @type {{ r: import('../engine.js').LiveResult, t1: number } | null} the result being drawn */
  let pending = null;

  /** Queues a panel's redraw for a new result (once per panel and function). */
  const defer = (/** @type {Redraw} */ entry) => {
    if (!queue.includes(entry)) queue.push(entry);
  };

  /** Each panel's place: 0 on screen, 1 off screen, 2 hidden (measured once per drain). */
  function ranker() {
    /** @type {Map<string, number>} */
    const rank = new Map();
    return (/** @type {string} */ n) => {
      let r = rank.get(n);
      if (r === undefined) {
        const sec = section(n);
        if (!sec || sec.hidden) r = 2;
        else {
          const b = sec.getBoundingClientRect();
          r = b.bottom > 0 && b.top < (window.innerHeight || 800) ? 0 : 1;
        }
        rank.set(n, r);
      }
      return r;
    };
  }

  /** Runs the queued redraws one task each, the panels on screen first; then `done`. */
  function drain(/** @type {() => void} */ done) {
    if (!port) port = new MessageChannel();
    const ch = port;
    // A measurement after each panel's redraw would force a layout every task: once per drain.
    const visible = ranker();
    const g = gen;
    const step = () => {
      if (!live() || g !== gen) return;
      if (!queue.length) {
        done();
        return;
      }
      // One panel per task, the most visible first (ties: the order they subscribed in).
      let best = 0,
        bestV = 3;
      for (let i = 0; i < queue.length; i++) {
        const v = visible(queue[i].name);
        if (v < bestV) {
          best = i;
          bestV = v;
        }
      }
      const [e] = queue.splice(best, 1);
      try {
        e.fn(store.get(), ['result']);
      } finally {
        ch.port1.onmessage = step;
        ch.port2.postMessage(0);
      }
    };
    step();
  }

  /** All panels show the newest result: tell the element. */
  function finish() {
    const p = pending;
    pending = null;
    if (p) rendered(p.r, p.t1);
  }

  const startDrain = () => {
    drawing = true;
    drain(() => {
      drawing = false;
      finish();
    });
  };

  return {
    /**
     * The store as panel `name` sees it: the same store, except that a subscription whose only
     * change is a new `result` is deferred (a task of its own, or until the panel is shown).
     * @param {string} name
     * @returns {import('../store.js').Store<LabState>}
     */
    viewStore(name) {
      return {
        get: store.get,
        set: store.set,
        subscribe: (keys, fn) => {
          if (keys === '*' || !keys.includes('result')) return store.subscribe(keys, fn);
          const entry = { name, fn };
          return store.subscribe(keys, (st, changed) => {
            const onlyResult = changed.length === 1 && changed[0] === 'result';
            // A panel off the current screen does no work for a new result until it is shown.
            const sec = section(name);
            if (onlyResult && sec && sec.hidden) {
              if (!stale.includes(entry)) stale.push(entry);
            } else if (drawing && onlyResult) defer(entry);
            else fn(st, changed);
          });
        },
      };
    },
    /** The newest live result: into the store (the views redraw, a panel per task). */
    publish(/** @type {import('../engine.js').LiveResult} */ r) {
      const t1 = performance.now();
      // A result arriving while the previous one's panels are still being drawn: the queue
      // keeps one entry per panel, each reads the newest result when it runs.
      const first = !drawing;
      drawing = true;
      pending = { r, t1: pending ? pending.t1 : t1 };
      store.set({ result: r, status: null });
      if (first) startDrain();
    },
    /** Redraws a panel that comes into view with the new results it skipped while hidden. */
    flush(/** @type {string} */ name) {
      const entries = stale.filter((e) => e.name === name);
      if (!entries.length) return;
      stale = stale.filter((e) => e.name !== name);
      for (const e of entries) defer(e);
      if (!drawing) startDrain();
    },
    /** Forgets everything queued (the element was removed); a drain under way stops. */
    reset() {
      drawing = false;
      queue = [];
      stale = [];
      pending = null;
      gen++;
    },
  };
}
