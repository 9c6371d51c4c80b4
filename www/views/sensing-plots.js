// @ts-check
// The sensing panel's three plots (views/sensing.js), each under its heading: Δε(t) at the
// picked point, its spectrum with the multiples of the flap frequency marked, and the detection
// probability against the number of sensors K with its summary as a note below.
import { el, rich } from '../dom.js';
import { fmt } from '../format.js';
import { decimate } from '../decimate.js';
import { linePlot, color, log10OrNull } from '../plot.js';
import { curveData, peakAbs, spectrumWindow, curveSummary } from '../sensemap.js';

const STRAIN_SERIES = () => [
  { label: 'Δε_x', color: color('eps_x') },
  { label: 'Δε_y', color: color('eps_y') },
  { label: 'Δγ_{xy}', color: color('gamma_xy') },
];

/**
 * Appends the headings, plots and the curve's note to `body`.
 * @param {HTMLElement} body
 */
export function sensingPlots(body) {
  const heading = (text) => body.append(el('h3', { class: 'wl-smap-title wl-sense-h', rich: text }));
  heading('Rotation-induced strain Δε at the picked point');
  const seriesPlot = linePlot(body, {
    name: 'sensing-series',
    title: 'Rotation-induced strain at the picked point',
    ariaLabel: 'Plot of the rotation-induced strain Δε_x, Δε_y and Δγ_xy at the picked point over time',
    xLabel: 't',
    xUnit: 's',
    yLabel: 'Δε (–)',
    series: STRAIN_SERIES(),
    height: 180,
  });
  let specMarkers = [];
  heading('Its spectrum: where in frequency the rotation shows up');
  const specPlot = linePlot(body, {
    name: 'sensing-spectrum',
    title: 'Spectrum of the rotation-induced strain',
    ariaLabel: 'Power spectral density of the rotation-induced strain components at the picked point, log scale',
    xLabel: 'f',
    xUnit: 'Hz',
    yLabel: 'PSD of Δε (1/Hz)',
    log: { y: true },
    series: STRAIN_SERIES(),
    markers: () => specMarkers,
    height: 180,
  });
  let kMarkers = [];
  heading('How many sensors does it take? Detection against K');
  const curvePlot = linePlot(body, {
    name: 'sensing-curve',
    title: 'Detection against the number of sensors',
    ariaLabel:
      'Plot of the detection probability and of the share of the all-sensor detection index against the number of sensors K',
    xLabel: 'sensors K',
    xUnit: 'count',
    yLabel: 'P_d, share of d′_{all}',
    series: [
      { label: 'P_d (1 % false alarms)', color: '#1f5fbf', width: 2 },
      { label: 'd′ / d′_{all}', color: '#d62728', dash: [4, 3] },
    ],
    markers: () => kMarkers,
    keys: false,
    height: 180,
  });
  const curveNote = el('p', { class: 'wl-note' });
  body.append(curveNote);

  /**
   * Δε(t) and (when given) its spectrum; returns the peak |Δε| over the three components.
   * @param {any} result the wasm SensingResult
   * @param {{ delta: any, spectrum: any }} sr the series at the point in use
   */
  function showSeries(result, sr) {
    const d = sr.delta;
    const w = seriesPlot.u.bbox ? seriesPlot.u.bbox.width / (globalThis.devicePixelRatio || 1) : 600;
    seriesPlot.setData(
      decimate(result.t, [d.eps_x, d.eps_y, d.gamma_xy], Math.min(1500, Math.max(200, Math.round(w)))),
    );
    const peak = Math.max(peakAbs(d.eps_x), peakAbs(d.eps_y), peakAbs(d.gamma_xy));
    seriesPlot.setSummary(
      `Peak |Δε| at the point: ε_x ${fmt(peakAbs(d.eps_x), 3)}, ε_y ${fmt(peakAbs(d.eps_y), 3)}, γ_xy ${fmt(peakAbs(d.gamma_xy), 3)} (dimensionless).`,
    );
    if (sr.spectrum) {
      const sp = sr.spectrum;
      const freq = sp.eps_x.freq_hz;
      const { fmax, n, marks } = spectrumWindow(result, freq);
      const pos = (arr) => Array.from(arr.subarray(0, n), (v) => log10OrNull(v));
      specPlot.setData([Array.from(freq.subarray(0, n)), pos(sp.eps_x.psd), pos(sp.eps_y.psd), pos(sp.gamma_xy.psd)]);
      specMarkers = marks;
      specPlot.redraw();
      const top = sp.eps_x.peaks && sp.eps_x.peaks[0];
      specPlot.setSummary(
        peak > 0
          ? `Welch PSD of Δε at the point up to ${fmt(fmax, 3)} Hz; grey lines: multiples of the flap frequency ${fmt(result.flap_freq_hz, 3)} Hz.${top ? ` Strongest Δε_x peak at ${fmt(top.freq_hz, 4)} Hz.` : ''}`
          : 'Δε is zero: no body rotation, no spectrum.',
      );
    } else {
      specPlot.setSummary('Spectrum: updating for the picked point…');
    }
    return peak;
  }

  /**
   * The detection curve with a marker at K, and its summary.
   * @param {any} result
   * @param {number} K
   */
  function showCurve(result, K) {
    const [k, pd, share] = curveData(result);
    curvePlot.setData([k, pd, share]);
    kMarkers = K ? [{ x: K, label: `K = ${K}`, color: '#555', dash: [3, 3] }] : [];
    curvePlot.redraw();
    const text = curveSummary(result, K, fmt);
    curvePlot.setSummary(text);
    curveNote.replaceChildren(rich(text));
  }

  return {
    seriesPlot,
    specPlot,
    curvePlot,
    showSeries,
    showCurve,
    destroy() {
      seriesPlot.destroy();
      specPlot.destroy();
      curvePlot.destroy();
    },
  };
}
