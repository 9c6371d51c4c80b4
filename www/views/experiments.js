// @ts-check
// Guided experiments panel: one link per experiment (a shareable URL: every parameter plus
// exp=<id>), and for the active one what to look at and what the model predicts, recomputed
// from every new analysis by www/experiments.js, with its numeric checks shown as ✓ / ✗.
// Experiments that need a study (γ_0 sweep, initial-condition map) run it through the engine's
// worker; the prediction fills in when it arrives. Reads the store; writes only `exp` and the
// experiment's parameters (ctx.setParams).
import { WWW } from '../base.js';
import { el } from '../dom.js';
import { plain, errorText } from '../format.js';
import { LIVE_SEGMENT_LEN } from '../engine/requests.js';
import { SCREENS, EXPERIMENT_SCREEN } from '../screens.js';
import { EXPERIMENTS, experiment, experimentPatch, experimentQuery, predict } from '../experiments.js';
import { study, studyKey, watchStudy } from '../lab/study-cache.js';

export const title = 'Guided experiments';

/** An absolute link to the lab page (index.html next to lab.js) with `query`. */
export function experimentHref(id) {
  return new URL(`index.html?${experimentQuery(id)}`, WWW).href;
}

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, section, engine } = ctx;
  section.append(
    el('p', {
      class: 'wl-note wl-exp-intro',
      text: 'Each experiment sets the parameters for one effect of the model and says what to look for. The prediction is computed from the current results and checked against the simulation; it stays live if you move the sliders. Every link can be shared.',
    }),
  );
  const list = el('ul', { class: 'wl-exp-list' });
  const links = new Map();
  for (const e of EXPERIMENTS) {
    const a = el(
      'a',
      { class: 'wl-exp-link', href: experimentHref(e.id), 'data-exp': e.id },
      el('span', { rich: e.title }),
      el('span', { class: 'wl-exp-fig', text: `· ${e.figure}` }),
    );
    a.addEventListener('click', (ev) => {
      if (ev.button !== 0 || ev.ctrlKey || ev.metaKey || ev.shiftKey || ev.altKey) return; // new tab / window
      ev.preventDefault();
      choose(e.id);
    });
    links.set(e.id, a);
    list.append(el('li', {}, a));
  }
  const detail = el('div', { class: 'wl-exp-detail' });
  const live = el('div', { class: 'wl-sr', 'aria-live': 'polite' });
  // On a focused screen only its own experiments are listed (www/screens.js); the rest are named.
  const elsewhere = el('p', { class: 'wl-note wl-exp-elsewhere', hidden: true });
  section.append(list, elsewhere, detail, live);

  /** The study keys this panel listens to (www/lab/study-cache.js) and how to stop. */
  const watched = new Set();
  /** @type {(() => void)[]} */
  const unwatch = [];
  let lastAnnounced = '';

  /** Applies an experiment: exp=id and its parameters (experimentPatch: the same as its URL). */
  function choose(id) {
    const patch = experimentPatch(id);
    if (!patch) return;
    ctx.setParams(patch);
    refresh();
  }

  function studyFor(e, restart = false) {
    if (!e.study) return null;
    const s = store.get();
    // `analyze`: the live analysis of the same state with the study's `params` (another
    // medium), in the study worker; the other kinds take the live config and their `opts`.
    const compare = e.study.kind === 'analyze';
    let cfg;
    try {
      cfg = engine.config(compare ? { ...s, ...e.study.params } : s);
    } catch (err) {
      return { result: null, error: errorText(err) };
    }
    const opts = compare ? { detrend: s.detrend, segment_len: LIVE_SEGMENT_LEN } : { ...e.study.opts };
    if (e.study.kind === 'icmap') opts.mode = Number(s.mode) - 1;
    const key = studyKey(e.study.kind, opts, cfg);
    const entry = study(engine, e.study.kind, compare ? { cfg, opts, k: Number(s.mode) - 1 } : { cfg, opts }, key, {
      restart,
    });
    if (!watched.has(key)) {
      watched.add(key);
      unwatch.push(watchStudy(key, () => refresh()));
    }
    return entry;
  }

  function refresh() {
    const s = store.get();
    const e = s.exp ? experiment(s.exp) : null;
    for (const [k, a] of links) {
      if (e && k === e.id) a.setAttribute('aria-current', 'true');
      else a.removeAttribute('aria-current');
    }
    section.dataset.exp = e ? e.id : '';
    if (!e) {
      detail.replaceChildren(el('p', { class: 'wl-note', text: 'Choose an experiment above.' }));
      return;
    }
    const a = s.result && s.result.analysis;
    const entry = a ? studyFor(e) : null;
    /** @type {HTMLElement[]} */
    const parts = [el('h3', { class: 'wl-exp-title', rich: e.title }), el('p', { class: 'wl-exp-look', rich: e.look })];
    if (!a) parts.push(el('p', { class: 'wl-note', text: 'Computing…' }));
    else {
      const p = predict(e.id, a, { mode: Number(s.mode) - 1, state: s, study: entry && entry.result });
      const pred = el('div', { class: 'wl-exp-predict', 'data-exp-predict': e.id });
      pred.append(el('p', { class: 'wl-exp-label', text: 'The model predicts' }));
      for (const line of p.lines) pred.append(el('p', { class: 'wl-exp-line', rich: line }));
      if (entry && entry.error) pred.append(el('p', { class: 'wl-error', text: `The study failed: ${entry.error}` }));
      if (entry && 'cancelled' in entry && entry.cancelled && !entry.result) {
        const again = el('button', { type: 'button', class: 'wl-run', text: 'Run the study again' });
        again.addEventListener('click', () => {
          studyFor(e, true);
          refresh();
        });
        pred.append(el('p', { class: 'wl-note', text: 'The study was cancelled. ' }, again));
      }
      if (p.checks.length) {
        const ul = el('ul', {
          class: 'wl-exp-checks',
          'aria-label': 'Checks of the prediction against the simulation',
        });
        for (const c of p.checks) {
          ul.append(
            el(
              'li',
              { class: c.holds ? 'wl-ok' : 'wl-bad', 'data-check': c.id, 'data-holds': String(c.holds) },
              el('span', { class: 'wl-exp-mark', 'aria-hidden': 'true', text: c.holds ? '✓' : '✗' }),
              el('span', { rich: `${c.holds ? 'Holds' : 'Does not hold'}: ${c.label}` }),
            ),
          );
        }
        pred.append(ul);
      }
      parts.push(pred);
      section.dataset.checks = p.checks.map((c) => `${c.id}:${c.holds ? 1 : 0}`).join(',');
      section.dataset.values = JSON.stringify(p.values, (_k, v) =>
        typeof v === 'number' && !Number.isFinite(v) ? String(v) : v,
      );
      const say = `${plain(e.title)}: ${p.checks.length ? p.checks.map((c) => (c.holds ? 'holds' : 'does not hold')).join(', ') : 'computing'}`;
      if (say !== lastAnnounced) {
        live.textContent = say;
        lastAnnounced = say;
      }
    }
    if (e.study && e.study.kind !== 'analyze' && e.study.kind !== 'classify') {
      const target = e.study.kind === 'resonance' ? 'resonance' : 'studies';
      const label = {
        resonance: 'Go to the resonance map',
        sweep: 'Go to the sweep study (Fig. 6)',
        icmap: 'Go to the initial-condition map (Fig. 7)',
      }[e.study.kind];
      const go = el('button', { type: 'button', class: 'wl-exp-go', text: label });
      go.addEventListener('click', () => {
        const sec = section.parentElement && section.parentElement.querySelector(`[data-panel="${target}"]`);
        if (!sec) return;
        ctx.showPanel(target); // its screen, when the panel is on another one
        sec.scrollIntoView({ behavior: 'smooth', block: 'start' });
        /** @type {HTMLElement | null} */
        const study = sec.querySelector(`[data-study="${e.study.kind === 'resonance' ? 'resonance' : e.study.kind}"]`);
        /** @type {HTMLButtonElement | null} */
        const run = study && study.querySelector('button[data-run]');
        if (study && run) {
          run.focus({ preventScroll: true });
          const out = study.querySelector('.wl-study-out');
          if (!study.dataset.done && !(out && out.childElementCount) && !run.disabled) run.click(); // show it computed, not empty
        }
      });
      parts.push(go);
    }
    detail.replaceChildren(...parts);
    ctx.emit('wl-experiment', { id: e.id });
  }

  const unsub = store.subscribe(['exp', 'result'], refresh);
  refresh();
  return {
    /**
     * Lists the experiments of a screen (all on the full page) and says where the others are.
     * @param {string} screenId
     */
    setScreen(screenId) {
      const other = new Set();
      for (const [k, a] of links) {
        const home = EXPERIMENT_SCREEN[/** @type {keyof typeof EXPERIMENT_SCREEN} */ (k)];
        const here = screenId === 'full' || home === screenId;
        /** @type {HTMLElement} */ (a.parentElement).hidden = !here;
        if (!here) other.add(home);
      }
      const names = SCREENS.filter((sc) => other.has(sc.id)).map((sc) => `“${sc.label}”`);
      elsewhere.hidden = names.length === 0;
      elsewhere.textContent = names.length
        ? `More experiments on the ${names.join(', ').replace(/, ([^,]*)$/, ' and $1')} screen${names.length > 1 ? 's' : ''}.`
        : '';
    },
    choose,
    refresh,
    destroy() {
      unsub();
      for (const f of unwatch) f();
    },
  };
}
