// @ts-check
// Paper claims check: reproduce() in the worker, every claim with what wingbeat computes.
import { el } from '../dom.js';
import { errorText } from '../format.js';

export const title = 'Paper claims check';

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { section, engine } = ctx;
  const btn = el('button', { type: 'button', class: 'wl-run', text: 'Check the paper’s claims', 'data-run': 'report' });
  const prog = el('progress', { class: 'wl-progress', hidden: true, 'aria-label': 'report progress' });
  const status = el('span', { class: 'wl-status', role: 'status' });
  const out = el('div', { class: 'wl-report-out' });
  btn.addEventListener('click', () => {
    btn.disabled = true;
    prog.hidden = false;
    status.textContent = 'computing…';
    engine
      .run('reproduce')
      .promise.then(({ result: r, ms }) => {
        out.replaceChildren();
        const t = el('table', { class: 'wl-reporttable' });
        t.append(
          el(
            'thead',
            {},
            el(
              'tr',
              {},
              ...['Claim', '§', 'Paper says', 'wingbeat computes', 'Verdict'].map((h) =>
                el('th', { scope: 'col', text: h }),
              ),
            ),
          ),
        );
        const tb = el('tbody');
        for (const c of r.claims) {
          tb.append(
            el(
              'tr',
              { class: `wl-v-${c.verdict}` },
              el('td', { text: c.id }),
              el('td', { text: c.section }),
              el('td', { text: c.paper_says }),
              el('td', { text: c.computed }),
              el('td', { text: c.verdict }),
            ),
          );
        }
        t.append(tb);
        out.append(t);
        const s = r.summary;
        status.textContent = `${s.holds} hold, ${s.partly} partly, ${s.fails} fail, ${s.input} inputs (${ms.toFixed(0)} ms, worker)`;
        ctx.emit('wl-study', { kind: 'reproduce' });
      })
      .catch((e) => {
        status.textContent = `Error: ${errorText(e)}`;
      })
      .finally(() => {
        btn.disabled = false;
        prog.hidden = true;
      });
  });
  section.append(
    el('div', { class: 'wl-study-controls' }, btn, prog, status),
    el('p', {
      class: 'wl-note',
      text: 'The paper preset as printed, zero initial conditions; every verdict is computed.',
    }),
    out,
  );
  return { destroy() {} };
}
