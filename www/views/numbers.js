// @ts-check
// Floquet & contributions panel: every mode's natural and effective frequencies, beat periods,
// multipliers, stability and force-term shares, as a table (its own text alternative). In a
// fluid, rows for what the air does (the aerodynamic share, the still-air frequency, the
// aerodynamic damping, the free vibration's decay time and the beat's fate) appear.
import { el, rich } from '../dom.js';
import { fmt, UNITS } from '../format.js';
import { toQuery } from '../state.js';

export const title = 'Floquet & contributions';

/**
 * The largest |q| over the run of mode k's response `key`: the core's value (Analysis.peaks),
 * else (an analysis without it) a scan of the samples.
 * @param {any} a an Analysis
 * @param {number} k
 * @param {'euler' | 'centrifugal' | 'coriolis' | 'total'} key
 */
export function peakOf(a, k, key) {
  const p = a.peaks && a.peaks.q[k];
  if (p) return p[key];
  let peak = 0;
  for (const v of a.sim.modes[k].q[key]) peak = Math.max(peak, Math.abs(v));
  return peak;
}

/**
 * The beat's fate in a fluid, short: whether the free vibration (time constant `tau`, s)
 * outlives one beat period (s). The core's sentence (ModeAir.beat) says the same at length.
 * @param {number | null} tau
 * @param {number | null} beat
 */
export function beatFate(tau, beat) {
  if (beat == null) return 'no beat';
  if (tau == null) return 'does not fade';
  if (tau < beat) return `gone within one beat (τ ${fmt(tau, 2)} s < ${fmt(beat, 2)} s)`;
  return `fades over ${fmt(tau / beat, 2)} beats (τ ${fmt(tau, 2)} s)`;
}

export const ROWS = [
  ['freq', 'Natural frequency f_k (Hz)'],
  ['feff', 'Floquet effective frequency (Hz)'],
  ['favg', 'Averaged-stiffness estimate (Hz)'],
  ['beat2', 'Beat period vs 2 f_d (s)'],
  ['beat', 'Beat period vs nearest n·f_d (s)'],
  ['mult', 'Floquet multipliers λ (per flap period)'],
  ['mod', 'max |λ|'],
  ['stable', 'Stability'],
  ['euler', 'Euler share (%)'],
  ['centrifugal', 'Centrifugal share (%)'],
  ['coriolis', 'Coriolis share (%)'],
  ['aero', 'Aerodynamic share (%)'],
  ['sum', 'Sum of shares (%)'],
  ['peak', `Peak |q| total (${UNITS.q.label})`],
  ['still', 'Still-air frequency (Hz, added mass)'],
  ['zeta_a', 'Aerodynamic damping ratio ζ_a (cycle average)'],
  ['decay', 'Free vibration decay time 1/σ (s)'],
  ['fate', 'The beat in this fluid'],
];

/** The rows shown only in a fluid (hidden in a vacuum). */
const AIR_ROWS = new Set(['aero', 'still', 'zeta_a', 'decay', 'fate']);

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, section } = ctx;
  const table = el('table', { class: 'wl-numtable' });
  const caption = el('caption', {
    class: 'wl-sr',
    text: 'Floquet analysis and force-term shares of every mode for the current parameters',
  });
  const headRow = el('tr');
  const tbody = el('tbody');
  table.append(caption, el('thead', {}, headRow), tbody);
  // The table scrolls sideways on its own when there are more modes than fit (8 at most).
  // Named after its section (which carries the lab's name when a page has several labs), so
  // each lab's region is a distinct landmark.
  const scroller = el(
    'div',
    {
      class: 'wl-numscroll',
      role: 'region',
      tabindex: '0',
      'aria-label': `${section.getAttribute('aria-label') || 'Floquet and contributions'}: table, scrolls sideways for many modes`,
    },
    table,
  );
  section.append(
    scroller,
    el('p', {
      class: 'wl-note',
      rich: 'Shares are 100·Σq_{term}^2/Σq_{total}^2 (paper §4.1). They need not sum to 100 % because the partial responses are not orthogonal (cross terms). One column per mode of the current mode set; the selected mode is highlighted.',
    }),
  );
  /** @type {Record<string, HTMLTableCellElement>} */
  const cells = {};
  /** @type {HTMLTableCellElement[][]} cells by [row][mode], for the selection mark */
  let cols = [];
  /** @type {HTMLTableRowElement[]} the rows of the air (hidden in a vacuum) */
  let airRows = [];
  let nModes = 0;

  /** Rebuilds header and body for `n` modes (only when the count changes). */
  const layout = (n) => {
    if (n === nModes) return;
    nModes = n;
    for (const k of Object.keys(cells)) delete cells[k];
    cols = Array.from({ length: n }, () => []);
    airRows = [];
    headRow.replaceChildren(
      el('th', { scope: 'col', text: 'Quantity' }),
      ...Array.from({ length: n }, (_, k) => {
        const th = el('th', { scope: 'col', text: `Mode ${k + 1}`, 'data-mode': String(k + 1) });
        cols[k].push(th);
        return th;
      }),
    );
    tbody.replaceChildren(
      ...ROWS.map(([key, label]) => {
        const tr = el('tr', { 'data-row': key }, el('th', { scope: 'row' }, rich(label)));
        if (AIR_ROWS.has(key)) airRows.push(tr);
        for (let k = 0; k < n; k++) {
          const td = el('td', { 'data-field': `${key}-${k}`, text: '—' });
          cells[`${key}-${k}`] = td;
          cols[k].push(td);
          tr.append(td);
        }
        return tr;
      }),
    );
  };
  layout(2);

  const draw = (s) => {
    if (!s.result) return;
    const a = s.result.analysis;
    layout(a.sim.modes.length);
    const set = (key, k, text) => {
      if (cells[`${key}-${k}`]) cells[`${key}-${k}`].textContent = text;
    };
    a.sim.modes.forEach((m, k) => {
      const f = m.floquet;
      const c = m.contribution_percent;
      set('freq', k, fmt(m.freq_hz, 4));
      set('feff', k, fmt(f.effective_freq_hz, 6));
      set('favg', k, fmt(f.averaged_freq_hz, 6));
      set('beat2', k, f.beat_period_vs_2fd_s == null ? '— (none)' : fmt(f.beat_period_vs_2fd_s, 4));
      set('beat', k, f.beat_period_s == null ? '— (none)' : `${fmt(f.beat_period_s, 4)} (n = ${f.beat_harmonic})`);
      set(
        'mult',
        k,
        f.multipliers.map(([re, im]) => `${fmt(re, 4)}${im >= 0 ? ' + ' : ' − '}${fmt(Math.abs(im), 4)}i`).join(', '),
      );
      set('mod', k, fmt(f.max_modulus, 8));
      set(
        'stable',
        k,
        f.stable
          ? `stable (growth ${fmt(f.growth_rate_per_s, 2)} 1/s)`
          : `UNSTABLE (growth ${fmt(f.growth_rate_per_s, 3)} 1/s)`,
      );
      set('euler', k, fmt(c.euler, 4));
      set('centrifugal', k, fmt(c.centrifugal, 4));
      set('coriolis', k, fmt(c.coriolis, 4));
      set('aero', k, c.aerodynamic == null ? '— (vacuum)' : fmt(c.aerodynamic, 4));
      set('sum', k, fmt(c.euler + c.centrifugal + c.coriolis + (c.aerodynamic || 0), 4));
      const air = m.air;
      set('still', k, air ? fmt(air.still_air_freq_hz, 5) : '— (vacuum)');
      set('zeta_a', k, air ? fmt(air.aero_damping_ratio, 3) : '— (vacuum)');
      set('decay', k, air ? (air.decay_time_s == null ? '— (no decay)' : fmt(air.decay_time_s, 3)) : '— (vacuum)');
      set('fate', k, air ? beatFate(air.decay_time_s, f.beat_period_s) : '— (vacuum)');
      const fc = cells[`fate-${k}`];
      if (fc) fc.title = air ? air.beat : '';
      // The core's run-wide peak (Analysis.peaks): no scan of every sample on the page's thread.
      set('peak', k, fmt(peakOf(a, k, 'total'), 4));
    });
    cols.forEach((col, k) => {
      for (const c of col) c.classList.toggle('wl-selmode', k === s.result.k);
    });
    const inAir = !!a.sim.air;
    for (const tr of airRows) tr.hidden = !inAir;
    table.dataset.selected = String(s.result.k + 1);
    table.dataset.modes = String(nModes);
  };
  const unsub = store.subscribe(['result'], draw);
  const header = () => ['Quantity', ...Array.from({ length: nModes }, (_, k) => `Mode ${k + 1}`)];
  const rows = () =>
    ROWS.filter(([key]) => !AIR_ROWS.has(key) || !airRows.some((r) => r.hidden)).map(([key, label]) => [
      label,
      ...Array.from({ length: nModes }, (_, k) => cells[`${key}-${k}`].textContent || ''),
    ]);
  ctx.registerExport('numbers', {
    csv: () => {
      const s = store.get();
      if (!s.result) return null;
      const case_ = `wingbeat lab; ${toQuery(s)}`;
      return (
        [
          '# ' + case_,
          header()
            .map((h) => h.toLowerCase())
            .join(','),
          ...rows().map((r) => r.map((c) => `"${c.replace(/"/g, '""')}"`).join(',')),
        ].join('\n') + '\n'
      );
    },
    table: () => (store.get().result ? [header(), ...rows()] : null),
  });
  return { cells, destroy: unsub };
}
