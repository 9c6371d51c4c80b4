// @ts-check
// Strain panel (paper Fig. 9): ε_x, ε_y, γ_xy at the point P, Σ_k ε_k q_k(t).
import { el, rich } from '../dom.js';
import { fmt, PAPER_UNITS_NOTE } from '../format.js';
import { decimate } from '../decimate.js';
import { linePlot, color } from '../plot.js';
import { toQuery, describe } from '../state.js';

export const title = 'Strain at the point P (paper Fig. 9)';

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, section } = ctx;
  const plot = linePlot(section, {
    name: 'strain',
    title: 'Strain at P',
    ariaLabel: 'Strain plot: normal strains ε_x, ε_y and shear strain γ_xy at the point P over time',
    xLabel: 't',
    xUnit: 's',
    yLabel: 'strain',
    series: [
      { label: 'ε_x', color: color('eps_x') },
      { label: 'ε_y', color: color('eps_y') },
      { label: 'γ_{xy}', color: color('gamma_xy') },
    ],
    height: 200,
  });
  const note = el('p', { class: 'wl-note' });
  section.append(note);
  const unit = (s) => (s.modes === 'fe' ? 'strain (–)' : 'paper units');
  const draw = (s) => {
    const r = s.result;
    if (!r) return;
    const a = r.analysis;
    note.replaceChildren(rich(s.modes === 'fe'
      ? 'Σ_k ε_k q_k(t) at P = (3, −6) mm from the FE modal strain fields (top surface, dimensionless, SI).'
      : `Σ_k ε_k q_k(t) with the Table 6 modal strains at P (both modes). ${PAPER_UNITS_NOTE}`));
    plot.setYLabel(`strain (${unit(s)})`);
    const st = a.sim.strain;
    if (!st) {
      plot.setData([[0], [null], [null], [null]]);
      return;
    }
    const w = plot.u.bbox ? plot.u.bbox.width / (globalThis.devicePixelRatio || 1) : 600;
    plot.setData(decimate(a.sim.t, [st.eps_x, st.eps_y, st.gamma_xy], Math.min(1500, Math.max(200, Math.round(w)))));
    const pk = (y) => { let p = 0; for (const v of y) p = Math.max(p, Math.abs(v)); return p; };
    plot.setSummary(`Peak |strain| at P over the run (${unit(s)}): ε_x ${fmt(pk(st.eps_x), 3)}, ε_y ${fmt(pk(st.eps_y), 3)}, γ_xy ${fmt(pk(st.gamma_xy), 3)}.`);
  };
  const unsub = store.subscribe(['result'], draw);
  ctx.registerPlot('strain', plot);
  ctx.registerExport('strain', {
    csv: () => {
      const s = store.get();
      const st = s.result && s.result.analysis.sim.strain;
      if (!st) return null;
      const a = s.result.analysis;
      return ctx.toCSV(
        [
          { name: 't', unit: 's', values: a.sim.t },
          { name: 'eps_x', unit: unit(s), values: st.eps_x },
          { name: 'eps_y', unit: unit(s), values: st.eps_y },
          { name: 'gamma_xy', unit: unit(s), values: st.gamma_xy },
        ],
        [`wingbeat lab; ${toQuery(s)}`, `strain at point ${st.point}`],
      );
    },
    figure: () => {
      const s = store.get();
      const st = s.result && s.result.analysis.sim.strain;
      if (!st) return null;
      return {
        title: 'Strain at the point P (paper Fig. 9)',
        params: describe(s),
        x: s.result.analysis.sim.t,
        xRange: plot.xWindow(),
        xLabel: 't (s)',
        yLabel: `strain (${unit(s)})`,
        series: [
          { label: 'ε_x', color: color('eps_x'), y: st.eps_x, show: plot.u.series[1].show },
          { label: 'ε_y', color: color('eps_y'), y: st.eps_y, show: plot.u.series[2].show },
          { label: 'γ_{xy}', color: color('gamma_xy'), y: st.gamma_xy, show: plot.u.series[3].show },
        ],
        note: s.modes === 'paper' ? 'Paper units: Table 4/6 data are not SI.' : 'Dimensionless (SI).',
      };
    },
  });
  return { plot, destroy: () => { unsub(); plot.destroy(); } };
}
