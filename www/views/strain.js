// @ts-check
// Strain panel (paper Fig. 9, and beyond it): ε_x, ε_y, γ_xy over time at the strain point,
// Σ_k ε_k q_k(t) over every mode; for an FE wing also a planform map of the whole wing coloured
// by the RMS or peak of a chosen strain component over the run, on which a click (or the arrow
// keys) chooses the strain point: views/strain-map.js. The 3-D view can show the same map.
import { el, rich, isTouch } from '../dom.js';
import { fmt, PAPER_UNITS_NOTE } from '../format.js';
import { decimate } from '../decimate.js';
import { linePlot, color } from '../plot.js';
import { toQuery, describe } from '../state.js';
import { strainMapView, strainPointOf as pointOf } from './strain-map.js';

export const title = 'Strain where you point (paper Fig. 9)';

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, section } = ctx;
  const touch = isTouch();
  const plot = linePlot(section, {
    name: 'strain',
    title: 'Strain at the strain point',
    ariaLabel: 'Strain plot: normal strains ε_x, ε_y and shear strain γ_xy at the strain point over time',
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

  // ---- the whole-wing map (views/strain-map.js) ----
  const map = strainMapView(ctx, touch);
  section.append(map.box);
  const unit = (s) => (s.modes === 'fe' ? 'strain (–)' : 'paper units');

  const draw = (s) => {
    const r = s.result;
    if (!r) return;
    const a = r.analysis;
    const st = a.sim.strain;
    const [px, py] = pointOf(s);
    note.replaceChildren(
      rich(
        s.modes === 'fe'
          ? `Σ_k ε_k q_k(t) over all ${a.sim.modes.length} modes at the strain point (${fmt(px, 3)}, ${fmt(py, 3)}) mm, from the FE modal strain fields (top surface, dimensionless, SI).`
          : `Σ_k ε_k q_k(t) with the Table 6 modal strains at P (both modes). ${PAPER_UNITS_NOTE}`,
      ),
    );
    plot.setYLabel(s.modes === 'fe' ? 'strain (–)' : 'strain (paper units)');
    if (!st) {
      plot.setData([[0], [null], [null], [null]]);
      plot.setSummary('No strain at this point for this mode set.');
    } else {
      const w = plot.u.bbox ? plot.u.bbox.width / (globalThis.devicePixelRatio || 1) : 600;
      plot.setData(decimate(a.sim.t, [st.eps_x, st.eps_y, st.gamma_xy], Math.min(1500, Math.max(200, Math.round(w)))));
      // The core's run-wide peaks (Analysis.peaks.strain); a scan only for an analysis without them.
      const sp = a.peaks && a.peaks.strain;
      const pk = (/** @type {'eps_x' | 'eps_y' | 'gamma_xy'} */ c) => {
        if (sp) return sp[c];
        let p = 0;
        for (const v of st[c]) p = Math.max(p, Math.abs(v));
        return p;
      };
      plot.setSummary(
        `Peak |strain| at the strain point over the run (${unit(s)}): ε_x ${fmt(pk('eps_x'), 3)}, ε_y ${fmt(pk('eps_y'), 3)}, γ_xy ${fmt(pk('gamma_xy'), 3)}.`,
      );
    }
    map.draw();
  };
  const unsubs = [
    store.subscribe(['result'], draw),
    store.subscribe(['fe', 'strain_map', 'strain_point', 'modes'], () => map.draw()),
  ];
  map.draw();
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
        [
          `wingbeat lab; ${toQuery(s)}`,
          s.modes === 'fe'
            ? `strain at the strain point (x, y) = (${pointOf(s).join(', ')}) mm`
            : `strain at point ${st.point}`,
        ],
      );
    },
    figure: () => {
      const s = store.get();
      const st = s.result && s.result.analysis.sim.strain;
      if (!st) return null;
      return {
        title: 'Strain at the strain point (paper Fig. 9)',
        params: describe(s),
        x: s.result.analysis.sim.t,
        xRange: plot.xWindow(),
        xLabel: 't (s)',
        yLabel: s.modes === 'fe' ? 'strain (–)' : 'strain (paper units)',
        series: [
          { label: 'ε_x', color: color('eps_x'), y: st.eps_x, show: plot.u.series[1].show },
          { label: 'ε_y', color: color('eps_y'), y: st.eps_y, show: plot.u.series[2].show },
          { label: 'γ_{xy}', color: color('gamma_xy'), y: st.gamma_xy, show: plot.u.series[3].show },
        ],
        note: s.modes === 'paper' ? 'Paper units: Table 4/6 data are not SI.' : 'Dimensionless (SI).',
      };
    },
  });
  return {
    plot,
    get field() {
      return map.field;
    },
    choose: map.choose,
    destroy: () => {
      for (const f of unsubs) f();
      map.destroy();
      plot.destroy();
    },
  };
}
