// @ts-check
// One result per study request for the whole page. The guided experiments (views/experiments.js)
// and a panel that shows the same study (views/neural.js shows the neural-sensing experiment's
// classification) both ask here, so the study runs once and both say the same numbers. An entry
// keeps the progress and the listeners to tell when it changes; a study cancelled from outside
// (another study's Cancel ends the worker, www/engine/jobs.js) is forgotten so that the next
// request runs it again, one cancelled here by its own Cancel stays cancelled until asked again.
import { errorText } from '../format.js';

/**
 * @typedef {{ result: any, error: string | null, done: number, total: number, id: number,
 *   cancelled: boolean, listeners: Set<() => void> }} StudyEntry
 */

/** @type {Map<string, StudyEntry>} */
const entries = new Map();

/**
 * The entry for `key`, starting the study (engine.run(kind, payload)) when there is none or the
 * last was cancelled and `restart` is set.
 * @param {{ run: (kind: string, payload?: any, onProgress?: (d: number, t: number) => void) => { id: number, promise: Promise<{ result: any }> } }} engine
 * @param {string} kind
 * @param {Record<string, any>} payload
 * @param {string} key what the result depends on
 * @param {{ restart?: boolean }} [opts]
 * @returns {StudyEntry}
 */
export function study(engine, kind, payload, key, opts = {}) {
  const old = entries.get(key);
  // id 0: only watched so far (watchStudy), never started.
  if (old && old.id !== 0 && !(old.cancelled && opts.restart)) return old;
  /** @type {StudyEntry} */
  const e = {
    result: null,
    error: null,
    done: 0,
    total: 0,
    id: 0,
    cancelled: false,
    listeners: old ? old.listeners : new Set(),
  };
  entries.set(key, e);
  const notify = () => {
    for (const f of [...e.listeners]) f();
  };
  const job = engine.run(kind, payload, (done, total) => {
    e.done = done;
    e.total = total;
    notify();
  });
  e.id = job.id;
  job.promise.then(
    ({ result }) => {
      e.result = result;
      notify();
    },
    (err) => {
      const text = errorText(err);
      if (text === 'cancelled' && !e.cancelled && entries.get(key) === e) entries.delete(key);
      else if (text !== 'cancelled') e.error = text;
      notify();
    },
  );
  notify();
  return e;
}

/**
 * The entry for `key` if its study was started (null otherwise); starts nothing.
 * @param {string} key
 */
export function peekStudy(key) {
  const e = entries.get(key);
  return e && e.id !== 0 ? e : null;
}

/**
 * Calls `fn` whenever the entry for `key` changes (progress, result, error, cancel); returns
 * the unsubscribe function. Works before the study is first asked for.
 * @param {string} key
 * @param {() => void} fn
 */
export function watchStudy(key, fn) {
  let e = entries.get(key);
  if (!e) {
    e = { result: null, error: null, done: 0, total: 0, id: 0, cancelled: false, listeners: new Set() };
    entries.set(key, e);
  }
  e.listeners.add(fn);
  const listeners = e.listeners;
  return () => listeners.delete(fn);
}

/**
 * Cancels the running study of `key` (the worker ends; www/engine/jobs.js) and keeps it
 * cancelled until asked for with `restart`.
 * @param {{ cancel: (id: number) => unknown }} engine
 * @param {string} key
 */
export function cancelStudy(engine, key) {
  const e = entries.get(key);
  if (!e || e.id === 0 || e.result || e.error || e.cancelled) return;
  e.cancelled = true;
  engine.cancel(e.id);
  for (const f of [...e.listeners]) f();
}

/**
 * The key of a study request: its kind, options and the live configuration it runs on; the
 * classification (`classify`) runs on its own plate and kinematics, so the lab's configuration
 * is not part of its key.
 * @param {string} kind
 * @param {unknown} opts
 * @param {unknown} [cfg]
 */
export function studyKey(kind, opts, cfg) {
  return kind === 'classify'
    ? `${kind}|${JSON.stringify(opts)}`
    : `${kind}|${JSON.stringify(opts)}|${JSON.stringify(cfg)}`;
}
