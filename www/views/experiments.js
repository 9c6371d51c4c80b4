// Guided experiments panel: one link per experiment (a shareable URL: every parameter plus
// exp=<id>), and for the active one what to look at and what the model predicts, recomputed
// from each new analysis (www/experiments.js), with the numeric checks shown as ✓ / ✗.
//
// host:
//   state() → the lab state;  analysis() → the latest wasm `analyze` result (or null)
//   apply(state) → sets the lab state (recomputes, rewrites the URL)
//   config() → the current SimConfig
//   job(kind, payload, onProgress) → { promise, cancel }   the engine's worker jobs
//   href(query) → an absolute URL for a query string (the page's own, or index.html's)
//   show?(panel)                                         scrolls a panel into view
// Returns { box, select(id, {apply}), refresh(), active() }.
import { EXPERIMENTS, experiment, experimentState, experimentQuery, predict } from '../experiments.js';

function el(tag, props = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) {
    if (k === 'class') e.className = v;
    else if (k === 'text') e.textContent = v;
    else if (k.startsWith('aria-') || k.startsWith('data-') || k === 'role' || k === 'for' || k === 'hidden') {
      if (v !== false && v != null) e.setAttribute(k, v === true ? '' : v);
    } else e[k] = v;
  }
  for (const c of children) if (c != null) e.append(c);
  return e;
}

/** Key of the inputs a study result depends on (the study is rerun when they change). */
const studyKey = (id, cfg) => `${id}|${JSON.stringify(cfg)}`;

export function mountExperiments(box, host) {
  box.classList.add('wl-experiments');
  const list = el('ul', { class: 'wl-exp-list', role: 'list' });
  const links = new Map();
  for (const e of EXPERIMENTS) {
    const a = el('a', {
      class: 'wl-exp-link',
      href: host.href(experimentQuery(e.id)),
      'data-exp': e.id,
      text: e.title,
    });
    a.append(el('span', { class: 'wl-exp-fig', text: ` (${e.figure})` }));
    a.addEventListener('click', (ev) => {
      if (ev.button !== 0 || ev.ctrlKey || ev.metaKey || ev.shiftKey || ev.altKey) return; // new tab etc.
      ev.preventDefault();
      select(e.id, { apply: true });
    });
    links.set(e.id, a);
    list.append(el('li', {}, a));
  }
  const detail = el('div', { class: 'wl-exp-detail', 'aria-live': 'polite' });
  const intro = el('p', { class: 'wl-note', text: 'Each experiment sets the parameters for one effect of the model and says what to look for. Its prediction is computed from the current results and checked against the simulation; the links can be shared.' });
  box.append(intro, list, detail);

  let activeId = null;
  const studies = new Map(); // key -> { result } | { pending }

  function select(id, { apply = false } = {}) {
    const e = experiment(id);
    activeId = e ? e.id : null;
    for (const [k, a] of links) {
      if (k === activeId) a.setAttribute('aria-current', 'true');
      else a.removeAttribute('aria-current');
    }
    if (e && apply) host.apply(experimentState(e.id, host.state().panels), e.id);
    refresh();
  }

  function ensureStudy(e) {
    if (!e.study) return null;
    const cfg = host.config();
    const key = studyKey(e.id, cfg);
    const have = studies.get(key);
    if (have) return have.result || null;
    const entry = { pending: true, result: null };
    studies.set(key, entry);
    const opts = { ...e.study.opts };
    if (e.study.kind === 'icmap') opts.mode = Number(host.state().mode) - 1;
    let payload;
    if (e.study.kind === 'resonance') payload = { cfg, opts };
    else payload = { cfg, opts };
    const job = host.job(e.study.kind, payload, () => {});
    job.promise.then(
      (r) => {
        entry.result = r;
        entry.pending = false;
        if (activeId === e.id) refresh();
      },
      (err) => {
        entry.pending = false;
        entry.error = String(err && err.message ? err.message : err);
        if (activeId === e.id) refresh();
      },
    );
    return null;
  }

  function refresh() {
    const e = activeId ? experiment(activeId) : null;
    if (!e) {
      detail.replaceChildren();
      box.dataset.exp = '';
      return;
    }
    box.dataset.exp = e.id;
    const a = host.analysis();
    const state = host.state();
    const study = ensureStudy(e);
    const cfg = e.study ? studies.get(studyKey(e.id, host.config())) : null;
    const head = el('h3', { class: 'wl-exp-title', text: `${e.title}` });
    const url = host.href(experimentQuery(e.id));
    const copy = el('button', { type: 'button', class: 'wl-exp-copy', text: 'Copy link', 'aria-label': `Copy the link to the experiment “${e.title}”` });
    copy.addEventListener('click', async () => {
      try {
        await navigator.clipboard.writeText(url);
        copy.textContent = 'Link copied';
      } catch {
        copy.textContent = 'Copy failed: use the link above';
      }
      setTimeout(() => { copy.textContent = 'Copy link'; }, 2000);
    });
    const parts = [el('div', { class: 'wl-head' }, head, copy), el('p', { class: 'wl-exp-look', text: e.look })];
    if (!a) {
      parts.push(el('p', { class: 'wl-note', text: 'Computing…' }));
    } else {
      const p = predict(e.id, a, { mode: Number(state.mode) - 1, state, study });
      const pred = el('div', { class: 'wl-exp-predict', 'data-exp-predict': e.id });
      pred.append(el('p', { class: 'wl-exp-label', text: 'The model predicts:' }));
      for (const line of p.lines) pred.append(el('p', { class: 'wl-exp-line', text: line }));
      if (cfg && cfg.error) pred.append(el('p', { class: 'wl-error', text: `The study failed: ${cfg.error}` }));
      if (p.checks.length) {
        const ul = el('ul', { class: 'wl-exp-checks', 'aria-label': 'Checks of the prediction against the simulation' });
        for (const c of p.checks) {
          ul.append(el('li', { class: c.holds ? 'wl-ok' : 'wl-bad', 'data-check': c.id, 'data-holds': String(c.holds) },
            el('span', { class: 'wl-exp-mark', 'aria-hidden': 'true', text: c.holds ? '✓' : '✗' }),
            el('span', { text: `${c.holds ? 'Holds' : 'Does not hold'}: ${c.label}` })));
        }
        pred.append(ul);
      }
      parts.push(pred);
      box.dataset.checks = p.checks.map((c) => `${c.id}:${c.holds ? 1 : 0}`).join(',');
      box.dataset.values = JSON.stringify(p.values, (k, v) => (typeof v === 'number' && !Number.isFinite(v) ? String(v) : v));
    }
    if (e.study && host.show) {
      const target = e.study.kind === 'resonance' ? 'resonance' : 'studies';
      const go = el('button', { type: 'button', class: 'wl-exp-go', text: e.study.kind === 'resonance' ? 'Open the resonance map' : e.study.kind === 'sweep' ? 'Open the sweep study' : 'Open the initial-condition map' });
      go.addEventListener('click', () => host.show(target, e.study));
      parts.push(go);
    }
    detail.replaceChildren(...parts);
    box.dispatchEvent(new CustomEvent('wl-experiment', { bubbles: true, detail: { id: e.id } }));
  }

  return { box, select, refresh, active: () => activeId };
}
