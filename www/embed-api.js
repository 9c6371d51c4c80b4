// @ts-check
// The lab's side of the iframe embedding (docs/embedding.md, section iframe). Started by
// main.js only when the page runs inside a frame. Two jobs:
//   - height: posts { type: 'wingbeat:height', version: 1, height } to the parent whenever the
//     content height changes (a ResizeObserver on <html> and <body>), so a few lines of host
//     script (embed-host.js) can size the iframe to the lab: no inner scrollbar.
//   - a small versioned request/reply API for the parent window:
//       wingbeat:set        { id, params }  → wingbeat:state (after the recompute) | wingbeat:error
//       wingbeat:get        { id }          → wingbeat:state
//       wingbeat:subscribe  { id }          → wingbeat:subscribed, then wingbeat:result after
//                                             every recompute (wl-rendered)
//       wingbeat:unsubscribe { id }         → wingbeat:unsubscribed
//     Every message carries version: 1; other versions and unknown wingbeat:* types get a
//     wingbeat:error reply. Messages whose type does not start with "wingbeat:" are not ours
//     and are ignored without a reply (other scripts on the host may post to the frame).
// Origins: only messages from window.parent are considered. With `parent_origin=` the lab talks
// to that origin only (messages from others are ignored, heights and replies go to it alone);
// without it the lab answers whichever origin its parent has, replying to that origin (not '*').
// That is safe because the API can do no more than the iframe's own URL could (set the same
// validated URL parameters) and reads only what the lab shows anyway.
// Parameters are validated by the URL parser (state.js parsePairs): the same ranges, the same
// messages. A set is all or nothing.

import { parsePairs, paramsOf, toQuery, shortKey, PANELS } from './state.js';
import { fmt } from './format.js';
import { experimentPatch } from './experiments.js';

export const API_VERSION = 1;
const PREFIX = 'wingbeat:';
/** Keys the URL knows but `wingbeat:set` does not take (with the reason, for the error). */
const NOT_SETTABLE = {
  embed: 'fixed by the iframe’s src (embed=1)',
  planform: 'a file is read only when the page loads: put planform= in the iframe’s src',
  parent_origin: 'fixed by the iframe’s src',
};
/** Keys that do not change the computation (no recompute to wait for). */
const VIEW_ONLY = ['panels', 'exp', 'screen'];
const MAX_KEYS = 40;
const SETTLE_TIMEOUT_MS = 30000;

/**
 * One mode's Floquet numbers as the API returns them.
 * @typedef {{ mode: number, freq_hz: number, f_eff_hz: number, max_modulus: number, stable: boolean,
 *   growth_rate_per_s: number, beat_period_s: number | null, beat_harmonic: number | null,
 *   beat_period_vs_2fd_s: number | null, shares_percent: { euler: number, centrifugal: number, coriolis: number },
 *   shown: { feff: string, mod: string, beat: string, stable: string } }} ModeResult
 */
/**
 * What `wingbeat:state` and `wingbeat:result` carry besides the parameters.
 * `error` is the problem the lab shows at the moment (e.g. an FE wing that could not be computed,
 * with the paper table's modes used meanwhile), or null.
 * @typedef {{ mode_set: string, selected_mode: number, modes: ModeResult[], summary: string, error: string | null, compute_ms: number }} Results
 */
/**
 * The element as this module uses it (the public hooks of <wing-lab>).
 * @typedef {HTMLElement & { store?: import('./store.js').Store<import('./lab.js').LabState>, state?: import('./state.js').Params, fe?: unknown, screen?: string }} LabElement
 */

/**
 * Starts posting heights and answering the parent. Returns a stop function (used by tests).
 * @param {HTMLElement} labEl the <wing-lab> element
 * @param {{ parentOrigin?: string | null, target?: Window }} [opts] parentOrigin: the only origin
 *   to talk to (null/undefined = whichever origin the parent has); target: the parent window.
 * @returns {() => void}
 */
export function startEmbedApi(labEl, opts = {}) {
  const lab = /** @type {LabElement} */ (labEl);
  const parent = opts.target || window.parent;
  if (!parent || parent === window) return () => {};
  const pinned = opts.parentOrigin || null;
  /** Origins that subscribed to results ('*' stands for an opaque one). */
  const subscribers = new Set();
  const cleanups = /** @type {(() => void)[]} */ ([]);

  /**
   * @param {Record<string, unknown>} msg
   * @param {string} origin the receiver's origin ('*' when it is opaque)
   */
  const post = (msg, origin) => {
    try {
      parent.postMessage({ ...msg, version: API_VERSION }, origin);
    } catch {
      // A parent that navigated away, or an origin postMessage does not accept: nothing to do.
    }
  };
  /** Where unsolicited messages (height, ready) go: the pinned origin, else any parent. */
  const broadcastOrigin = pinned || '*';

  // ---------- height ----------
  let lastHeight = -1;
  const measure = () => {
    const html = document.documentElement;
    // The <html> box is as tall as the content (height: auto); scrollHeight would never shrink
    // below the frame's own height. Body margins are 0 in embed mode (page.css).
    const h = Math.ceil(
      Math.max(
        html.getBoundingClientRect().height,
        document.body ? document.body.getBoundingClientRect().bottom + window.scrollY : 0,
      ),
    );
    if (h > 0 && h !== lastHeight) {
      lastHeight = h;
      post({ type: `${PREFIX}height`, height: h }, broadcastOrigin);
    }
  };
  if (typeof ResizeObserver === 'function') {
    const ro = new ResizeObserver(() => measure());
    ro.observe(document.documentElement);
    if (document.body) ro.observe(document.body);
    cleanups.push(() => ro.disconnect());
  }
  addEventListener('load', measure);
  cleanups.push(() => removeEventListener('load', measure));
  measure();

  // ---------- results ----------
  const store = () => lab.store;

  /** @returns {Results | null} */
  const results = () => {
    const st = store();
    const r = st && st.get().result;
    if (!r) return null;
    const a = r.analysis;
    /** @type {ModeResult[]} */
    const modes = a.sim.modes.map((m, k) => {
      const f = m.floquet;
      const c = m.contribution_percent;
      return {
        mode: k + 1,
        freq_hz: m.freq_hz,
        f_eff_hz: f.effective_freq_hz,
        max_modulus: f.max_modulus,
        stable: f.stable,
        growth_rate_per_s: f.growth_rate_per_s,
        beat_period_s: f.beat_period_s ?? null,
        beat_harmonic: f.beat_harmonic ?? null,
        beat_period_vs_2fd_s: f.beat_period_vs_2fd_s ?? null,
        shares_percent: { euler: c.euler, centrifugal: c.centrifugal, coriolis: c.coriolis },
        // The same text as the lab's "Floquet & contributions" table (views/numbers.js).
        shown: {
          feff: fmt(f.effective_freq_hz, 6),
          mod: fmt(f.max_modulus, 8),
          beat: f.beat_period_s == null ? '— (none)' : `${fmt(f.beat_period_s, 4)} (n = ${f.beat_harmonic})`,
          stable: f.stable
            ? `stable (growth ${fmt(f.growth_rate_per_s, 2)} 1/s)`
            : `UNSTABLE (growth ${fmt(f.growth_rate_per_s, 3)} 1/s)`,
        },
      };
    });
    const sel = modes[r.k];
    // The mode set the numbers come from: FE only when an FE wing exists (when it could not be
    // computed the lab uses the paper table's modes meanwhile, and says so in `error`).
    const modeSet = r.params.modes === 'fe' && lab.fe ? 'fe' : 'paper';
    const summary = sel
      ? `Mode ${sel.mode} of ${modes.length} (${modeSet === 'fe' ? 'FE wing' : 'paper table'}): Floquet effective frequency ${sel.shown.feff} Hz, max |λ| ${sel.shown.mod}, ${sel.stable ? 'stable' : 'UNSTABLE'}, beat period ${sel.beat_period_s == null ? 'none' : fmt(sel.beat_period_s, 4) + ' s'}.`
      : '';
    const shownError = (lab.shadowRoot || lab).querySelector('.wl-error:not([hidden])');
    const error = shownError && shownError.textContent ? shownError.textContent : null;
    return { mode_set: modeSet, selected_mode: r.k + 1, modes, summary, error, compute_ms: r.compute_ms };
  };

  /** The lab's URL parameters as plain JSON (panels as a list, screen: the screen shown). */
  const params = () => {
    const st = store();
    const p = st ? paramsOf(st.get()) : lab.state;
    return p ? { ...p, panels: [...p.panels], screen: lab.screen || p.screen || '' } : null;
  };

  /** A key of the parameters that decide the computation (panels and exp left out). */
  const computeKey = (/** @type {import('./state.js').Params} */ p) =>
    toQuery({ ...p, panels: PANELS.slice(), exp: '', screen: '' });

  /** Whether the latest result belongs to the current parameters. */
  const current = () => {
    const st = store();
    if (!st) return false;
    const s = st.get();
    return !!s.result && computeKey(s.result.params) === computeKey(paramsOf(s));
  };

  /** Resolves once the result matches the parameters (or rejects after a timeout). */
  const settled = () =>
    new Promise((resolve, reject) => {
      if (current()) return resolve(undefined);
      const done = () => {
        if (!current()) return;
        clearTimeout(timer);
        lab.removeEventListener('wl-rendered', done);
        resolve(undefined);
      };
      const timer = setTimeout(() => {
        lab.removeEventListener('wl-rendered', done);
        const err = (lab.shadowRoot || lab).querySelector('.wl-error:not([hidden])');
        reject(new Error(err && err.textContent ? err.textContent : `no result within ${SETTLE_TIMEOUT_MS / 1000} s`));
      }, SETTLE_TIMEOUT_MS);
      lab.addEventListener('wl-rendered', done);
    });

  const stateMsg = (/** @type {string} */ type, /** @type {unknown} */ id) => ({
    type: `${PREFIX}${type}`,
    id,
    params: params(),
    results: results(),
  });

  // After every recompute: results to the subscribers.
  const onRendered = () => {
    if (!subscribers.size || !current()) return;
    const msg = stateMsg('result', null);
    delete msg.id;
    for (const o of subscribers) post(msg, o);
  };
  lab.addEventListener('wl-rendered', onRendered);
  cleanups.push(() => lab.removeEventListener('wl-rendered', onRendered));

  // ---------- requests ----------

  /**
   * Validates a `params` object with the URL parser. Returns the patch, or the errors.
   * @param {unknown} raw
   * @returns {{ patch: Record<string, unknown>, errors: { field: string, message: string }[] }}
   */
  const validate = (raw) => {
    /** @type {{ field: string, message: string }[]} */
    const errors = [];
    /** @type {Record<string, unknown>} */
    const patch = {};
    const checked = paramPairs(raw);
    if (checked.fatal) return { patch, errors: checked.errors };
    errors.push(...checked.errors);
    const pairs = checked.pairs;
    const parsed = parsePairs(pairs);
    for (const r of parsed.rejected) errors.push({ field: r.key, message: `${r.key}: ${r.why}` });
    const into = /** @type {Record<string, unknown>} */ (/** @type {unknown} */ (parsed.state));
    for (const [key] of pairs) if (!parsed.rejected.some((r) => r.key === short(key))) patch[key] = into[key];
    // exp opens a guided experiment with its parameters, as its chip does (values set with it win).
    if (typeof patch.exp === 'string' && patch.exp)
      Object.assign(patch, experimentPatch(patch.exp, Object.keys(patch)));
    // The selected mode must exist in the mode set it will be used with.
    if ('mode' in patch || 'modes' in patch) {
      const st = store();
      const s = st ? st.get() : null;
      const modesSet = /** @type {string} */ ('modes' in patch ? patch.modes : s ? s.modes : 'paper');
      const n =
        modesSet === 'fe'
          ? s && s.fe
            ? s.fe.modes.length
            : Number('n_modes' in patch ? patch.n_modes : s ? s.n_modes : 2)
          : 2;
      const mode = Number('mode' in patch ? patch.mode : s ? s.mode : 1);
      if (mode > n)
        errors.push({
          field: 'mode',
          message: `mode: expected 1 to ${n} (the modes of the ${modesSet === 'fe' ? 'FE wing' : 'paper table'})`,
        });
    }
    return { patch, errors };
  };

  /**
   * @param {MessageEvent} e
   */
  const onMessage = async (e) => {
    if (e.source !== parent) return;
    if (pinned && e.origin !== pinned) return;
    const d = e.data;
    if (!d || typeof d !== 'object' || typeof d.type !== 'string' || !d.type.startsWith(PREFIX)) return;
    // Reply to the sender's origin; an opaque one ("null": a sandboxed host) can only be '*',
    // which still reaches nothing but our parent window.
    const to = e.origin && e.origin !== 'null' ? e.origin : '*';
    const env = checkEnvelope(d);
    const id = env.id;
    const fail = (
      /** @type {string} */ code,
      /** @type {string} */ message,
      /** @type {Record<string, unknown>} */ more = {},
    ) => post({ type: `${PREFIX}error`, id, request: shortKey(d.type), code, message, ...more }, to);
    if (env.error) return fail(env.error.code, env.error.message, { field: env.error.field, ...env.error.more });
    const st = store();
    switch (d.type) {
      case `${PREFIX}get`:
        if (!st) return fail('not-ready', 'the lab has not started yet');
        try {
          await settled();
        } catch (err) {
          return fail(
            'no-result',
            `no result for the current parameters: ${err instanceof Error ? err.message : String(err)}`,
          );
        }
        return post(stateMsg('state', id), to);
      case `${PREFIX}set`: {
        if (!st) return fail('not-ready', 'the lab has not started yet');
        const { patch, errors } = validate(d.params);
        if (errors.length) {
          return fail('bad-params', errors.map((x) => x.message).join('; '), { field: errors[0].field, errors });
        }
        const changed = st.set(/** @type {any} */ (patch));
        // Wait for the recompute the change started (or one still running from before).
        if (changed.some((k) => !VIEW_ONLY.includes(k)) || !current()) {
          try {
            await settled();
          } catch (err) {
            return fail(
              'no-result',
              `the parameters were set but gave no result: ${err instanceof Error ? err.message : String(err)}`,
            );
          }
        }
        return post(stateMsg('state', id), to);
      }
      case `${PREFIX}subscribe`:
        subscribers.add(to);
        post({ type: `${PREFIX}subscribed`, id }, to);
        if (current()) {
          const msg = stateMsg('result', null);
          delete msg.id;
          post(msg, to);
        }
        return;
      case `${PREFIX}unsubscribe`:
        subscribers.delete(to);
        return post({ type: `${PREFIX}unsubscribed`, id }, to);
      default:
        return fail(
          'unknown-type',
          `type: unknown message type ${JSON.stringify(String(d.type).slice(0, 40))}; this lab knows ${['set', 'get', 'subscribe', 'unsubscribe'].map((t) => PREFIX + t).join(', ')}`,
        );
    }
  };
  addEventListener('message', onMessage);
  cleanups.push(() => removeEventListener('message', onMessage));

  // Tell the parent the API is listening (with the parameter names it accepts).
  post({ type: `${PREFIX}ready`, params: params(), accepts: acceptedKeys() }, broadcastOrigin);

  return () => {
    for (const f of cleanups) f();
  };
}

/** @param {string} key */
function short(key) {
  return shortKey(key);
}

/** Longest request id echoed back (characters). */
const MAX_ID_CHARS = 200;
/** Longest parameter value read from a message (characters); every valid one is far shorter. */
const MAX_VALUE_CHARS = 1000;

/**
 * What a value is, for error messages (never its text).
 * @param {unknown} v
 */
function kindOf(v) {
  if (v === null) return 'null';
  if (typeof v === 'number') return Number.isFinite(v) ? 'a number' : `the number ${String(v)}`;
  if (typeof v === 'string') return `text of ${v.length} characters`;
  if (Array.isArray(v)) return `a list of ${v.length} items`;
  if (ArrayBuffer.isView(v)) return 'a typed array';
  if (typeof v === 'object') return 'an object';
  return `a ${typeof v}`;
}

/**
 * Checks the envelope of a message whose type starts with "wingbeat:" (the caller has checked
 * that): `version` must be API_VERSION and `id`, when given, a finite number or a string of at
 * most MAX_ID_CHARS characters. Returns the id to echo (null when absent or refused) and the
 * error to reply with (null when the envelope is fine), naming the field. Never throws, whatever
 * the message holds (BigInts, cyclic objects, huge strings).
 * @param {any} d
 * @returns {{ id: string | number | null, error: null | { code: string, field: string, message: string, more: Record<string, unknown> } }}
 */
export function checkEnvelope(d) {
  const rawId = d.id;
  const idOk =
    rawId === undefined ||
    rawId === null ||
    (typeof rawId === 'number' && Number.isFinite(rawId)) ||
    (typeof rawId === 'string' && rawId.length <= MAX_ID_CHARS);
  const id = idOk && rawId !== undefined ? rawId : null;
  if (d.version !== API_VERSION) {
    const v = d.version;
    const got =
      typeof v === 'number' || typeof v === 'boolean'
        ? String(v)
        : typeof v === 'string'
          ? JSON.stringify(shortKey(v))
          : v === undefined
            ? 'none'
            : kindOf(v);
    return {
      id,
      error: {
        code: 'bad-version',
        field: 'version',
        message: `version: this lab speaks version ${API_VERSION} of the wingbeat message API; got ${got}`,
        more: { supported: [API_VERSION] },
      },
    };
  }
  if (!idOk) {
    return {
      id: null,
      error: {
        code: 'bad-id',
        field: 'id',
        message: `id: expected a finite number or a string of at most ${MAX_ID_CHARS} characters; got ${kindOf(rawId)}`,
        more: {},
      },
    };
  }
  return { id, error: null };
}

/**
 * The `params` of a wingbeat:set message as name/value text pairs for the URL parser, with an
 * error per refused entry, naming it: `params` must be a plain object of 1 to MAX_KEYS entries;
 * each value a finite number, a string of at most MAX_VALUE_CHARS characters, or (panels) a list
 * of panel names; names the URL fixes (NOT_SETTABLE) are refused. `fatal` when `params` itself
 * is unusable. Never throws.
 * @param {unknown} raw
 * @returns {{ pairs: [string, string][], errors: { field: string, message: string }[], fatal: boolean }}
 */
export function paramPairs(raw) {
  /** @type {{ field: string, message: string }[]} */
  const errors = [];
  /** @type {[string, string][]} */
  const pairs = [];
  const proto = raw && typeof raw === 'object' ? Object.getPrototypeOf(raw) : undefined;
  if (!raw || typeof raw !== 'object' || (proto !== Object.prototype && proto !== null)) {
    return {
      pairs,
      errors: [
        { field: 'params', message: `params: expected an object such as { "gamma0": 0.1 }; got ${kindOf(raw)}` },
      ],
      fatal: true,
    };
  }
  let n = 0;
  for (const k in raw) if (Object.hasOwn(raw, k) && ++n > MAX_KEYS) break;
  if (n === 0 || n > MAX_KEYS) {
    return {
      pairs,
      errors: [
        {
          field: 'params',
          message: `params: expected 1 to ${MAX_KEYS} parameters; got ${n > MAX_KEYS ? 'more' : 'none'}`,
        },
      ],
      fatal: true,
    };
  }
  const obj = /** @type {Record<string, unknown>} */ (raw);
  for (const key of Object.keys(obj)) {
    const v = obj[key];
    const field = short(key);
    if (Object.hasOwn(NOT_SETTABLE, key)) {
      errors.push({
        field,
        message: `${field}: not settable by message (${NOT_SETTABLE[/** @type {keyof typeof NOT_SETTABLE} */ (key)]})`,
      });
    } else if (typeof v === 'number' && Number.isFinite(v)) {
      pairs.push([key, String(v)]);
    } else if (typeof v === 'string' && v.length <= MAX_VALUE_CHARS) {
      pairs.push([key, v]);
    } else if (
      key === 'panels' &&
      Array.isArray(v) &&
      v.length <= 2 * PANELS.length &&
      v.every((x) => typeof x === 'string' && x.length <= 40)
    ) {
      pairs.push([key, v.join(',')]);
    } else {
      const want =
        typeof v === 'number'
          ? 'a finite number'
          : typeof v === 'string'
            ? `text of at most ${MAX_VALUE_CHARS} characters`
            : `a number or a string${key === 'panels' ? ` (or a list of at most ${2 * PANELS.length} panel names)` : ''}`;
      errors.push({ field, message: `${field}: expected ${want}; got ${kindOf(v)}` });
    }
  }
  return { pairs, errors, fatal: false };
}

/** The parameter names `wingbeat:set` takes (for the ready message and the docs). */
function acceptedKeys() {
  const q = parsePairs([]).state;
  return Object.keys(q).filter((k) => !(k in NOT_SETTABLE));
}
