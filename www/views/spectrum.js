// @ts-check
// Spectra panel (paper Fig. 4): Welch PSDs of the Euler, centrifugal and Coriolis forces, of
// the stiffness force S(t)·q_k and, in air, of the aerodynamic force (left axis), and of the
// total response (right axis), with markers at the flap harmonics n·f_d, the natural
// frequency f_k and the Floquet f_{eff}.
import { el, rich, isTouch } from '../dom.js';
import { fmt, UNITS, PAPER_UNITS_NOTE } from '../format.js';
import { linePlot, color, log10OrNull } from '../plot.js';
import { SAMPLE_RATE_HZ, toQuery, describe } from '../state.js';

export const title = 'Spectra of the force terms';

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, section } = ctx;
  let markers = [];
  const plot = linePlot(section, {
    name: 'spectrum',
    title: 'Spectra',
    ariaLabel:
      'Spectra plot: power spectral densities of the force terms and of the total response against frequency, log scale',
    xLabel: 'f',
    xUnit: 'Hz',
    yLabel: `force PSD (${UNITS.fpsd.label})`,
    y2Label: `response PSD (${UNITS.qpsd.label})`,
    log: { y: true, y2: true },
    series: [
      { label: 'Euler force', color: color('euler') },
      { label: 'Centrifugal force', color: color('centrifugal') },
      { label: 'Coriolis force', color: color('coriolis'), width: 1.6 },
      { label: 'Stiffness force S(t)·q', color: color('stiffness_force') },
      { label: 'Total response (right axis)', color: color('total'), scale: 'y2', dash: [4, 3] },
      { label: 'Aerodynamic force', color: color('aerodynamic'), width: 1.6 },
    ],
    markers: () => markers,
    height: 250,
  });
  section.append(
    el('p', {
      class: 'wl-note',
      rich: `Welch PSD, Hann window, 8192-sample segments, one-sided. Grey lines: multiples n·f_d of the flap frequency; blue dashed: natural frequency f_k; red: Floquet effective frequency f_{eff}. S(t) = α̇^2cos^2β + β̇^2 is the stiffness coefficient (1/s^2); the stiffness force S(t)·q is in force units. In a fluid (Parameters: Medium) the aerodynamic force F_A of the rigid motion (quasi-steady drag and added mass) joins them. ${isTouch() ? 'Touch the plot for values.' : 'Hover for values (legend); drag to zoom, double-click to reset.'}`,
    }),
  );
  const unitNote = el('p', { class: 'wl-note wl-units-note' });
  section.append(unitNote);

  const draw = (s) => {
    const r = s.result;
    if (!r) return;
    const a = r.analysis,
      k = r.k;
    const sp = a.spectra[k];
    const fd = a.sim.flap_freq_hz;
    const f = a.sim.modes[k].floquet;
    const fk = a.sim.modes[k].freq_hz;
    const fmax = Math.min(SAMPLE_RATE_HZ / 2, Math.max(8 * fd, 1.6 * fk, 1.2 * f.effective_freq_hz));
    const freq = sp.euler.freq_hz;
    let n = 0;
    while (n < freq.length && freq[n] <= fmax) n++;
    const pos = (arr) => {
      const out = new Array(n);
      for (let i = 0; i < n; i++) out[i] = log10OrNull(arr[i]);
      return out;
    };
    const stiff = sp.stiffness_force;
    const aero = sp.aerodynamic;
    plot.setData([
      Array.from(freq.subarray(0, n)),
      pos(sp.euler.psd),
      pos(sp.centrifugal.psd),
      pos(sp.coriolis.psd),
      pos(stiff.psd),
      pos(sp.total.psd),
      aero ? pos(aero.psd) : new Array(n).fill(null),
    ]);
    plot.setAvailable(5, !!aero);
    const marks = [];
    for (let j = 1; j * fd <= fmax; j++) marks.push({ x: j * fd, label: `${j}f_d`, color: '#8a8a8a' });
    marks.push({ x: fk, label: 'f_k', color: '#1f5fbf', dash: [5, 4] });
    if (Number.isFinite(f.effective_freq_hz))
      marks.push({ x: f.effective_freq_hz, label: 'f_{eff}', color: '#d62728', width: 1.5 });
    markers = marks;
    plot.redraw();
    const peakOf = (p) => {
      let b = 1;
      for (let i = 1; i < n; i++) if (p[i] > p[b]) b = i;
      return freq[b];
    };
    plot.setSummary(
      `Mode ${k + 1}, 0 to ${fmt(fmax, 3)} Hz. Largest non-DC peaks: Euler force at ${fmt(peakOf(sp.euler.psd), 4)} Hz, centrifugal at ${fmt(peakOf(sp.centrifugal.psd), 4)} Hz, Coriolis at ${fmt(peakOf(sp.coriolis.psd), 4)} Hz, stiffness force at ${fmt(peakOf(stiff.psd), 4)} Hz, ${aero ? `aerodynamic force at ${fmt(peakOf(aero.psd), 4)} Hz, ` : ''}total response at ${fmt(peakOf(sp.total.psd), 4)} Hz. ` +
        `Markers: flap harmonics every ${fmt(fd, 4)} Hz, natural frequency ${fmt(fk, 4)} Hz, Floquet effective frequency ${fmt(f.effective_freq_hz, 6)} Hz.`,
    );
    unitNote.replaceChildren(rich(s.modes === 'paper' ? PAPER_UNITS_NOTE : 'FE wing: SI units throughout.'));
  };
  const unsub = store.subscribe(['result'], draw);
  ctx.registerPlot('spectrum', plot);
  ctx.registerExport('spectrum', {
    csv: () => {
      const s = store.get();
      const sp = s.result && s.result.analysis.spectra[s.result.k];
      if (!s.result || !sp) return null;
      const pu = UNITS.fpsd.csv;
      return ctx.toCSV(
        [
          { name: 'f', unit: 'Hz', values: sp.euler.freq_hz },
          { name: 'psd_euler_force', unit: pu, values: sp.euler.psd },
          { name: 'psd_centrifugal_force', unit: pu, values: sp.centrifugal.psd },
          { name: 'psd_coriolis_force', unit: pu, values: sp.coriolis.psd },
          { name: 'psd_stiffness_force', unit: pu, values: sp.stiffness_force.psd },
          { name: 'psd_total_response', unit: UNITS.qpsd.csv, values: sp.total.psd },
          ...(sp.aerodynamic ? [{ name: 'psd_aerodynamic_force', unit: pu, values: sp.aerodynamic.psd }] : []),
        ],
        [
          `wingbeat lab; ${toQuery(s)}`,
          `mode ${s.result.k + 1}; Welch, Hann, 8192-sample segments, detrend ${s.detrend}; all bins up to Nyquist`,
        ],
      );
    },
    figure: () => {
      const s = store.get();
      if (!s.result) return null;
      const u = plot.u;
      return {
        title: `Spectra of the force terms, mode ${s.result.k + 1} (paper Fig. 4)`,
        params: describe(s),
        x: u.data[0],
        xRange: plot.xWindow(),
        xLabel: 'f (Hz)',
        yLabel: `force PSD (${UNITS.fpsd.label})`,
        y2Label: `response PSD (${UNITS.qpsd.label})`,
        log: { y: true, y2: true },
        series: plot.exportSeries(),
        markers,
        note:
          s.modes === 'paper'
            ? 'Paper units: Table 4 is not SI; spectral shapes and frequencies are unaffected.'
            : 'SI units.',
      };
    },
  });
  return {
    plot,
    destroy: () => {
      unsub();
      plot.destroy();
    },
  };
}
