// @ts-check
// Responses panel (paper Fig. 5) — the beat made visible: the partial and total responses of
// the selected mode in a window of about three beats (full resolution), the beat period marked
// (shaded from an envelope maximum to the next, T_{beat} = 1/|f_{eff} − n·f_d| from the Floquet
// numbers), an overview of the whole run to move the window, the force-term shares, a hint
// line (mouse, keyboard or touch wording) and a click-to-pose link to the 3-D wing. The beat's
// words and the shares list are written by views/time-words.js, the marks (beat band, repeats,
// the band where a damped beat is gone) come from views/time-marks.js, and the overview strip is
// views/time-overview.js.
import { el, isTouch } from '../dom.js';
import { fmt, plain, UNITS } from '../format.js';
import { decimate } from '../decimate.js';
import { beatInfo, beatWindow, beatFate, shares, smooth } from '../beat.js';
import { linePlot, color } from '../plot.js';
import { peakOf } from './numbers.js';
import { toQuery, describe } from '../state.js';
import { writeBeat, writeShares } from './time-words.js';
import { beatBand, beatRepeats, goneBands } from './time-marks.js';
import { timeOverview } from './time-overview.js';
import { clampWindow } from '../plot/window.js';

export const title = 'Responses and the beat (paper Fig. 5)';

const Q = UNITS.q.label;

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, section } = ctx;
  const touch = isTouch();
  const beatBox = el('div', { class: 'wl-beat', 'aria-live': 'polite' });
  const hint = el('p', {
    class: 'wl-hint',
    text: touch
      ? 'Drag across the plot to zoom in, double-tap for the whole run; drag on the strip below to move the window; tap a curve’s name to hide it; tap the plot to show that instant in the 3-D wing.'
      : 'Drag across the plot to zoom in, double-click for the whole run; drag on the strip below to move the window; click a curve’s name to hide it; click the plot to show that instant in the 3-D wing. Keys on the focused plot: ← → pan, + − zoom, 0 back to three beats.',
  });
  section.append(beatBox, hint);
  /** @type {import('../beat.js').BeatInfo | null} */
  let beat = null;
  /** @type {ReturnType<typeof beatWindow> | null} */
  let bw = null;
  /** @type {import('../beat.js').BeatFate | null} what becomes of the beat over the run */
  let fate = null;
  /** The grey band where a damped beat has died out (both plots). */
  const goneBand = () => {
    const r = store.get().result;
    const t = r ? r.analysis.sim.t : null;
    return goneBands(fate, t ? t[t.length - 1] : null);
  };
  /** @type {number[] | null} window shown [t0, t1] (s) */
  let win = null;
  let userWin = false;
  /** @type {import('../lab.js').Plot | null} made after the main plot, whose hooks redraw it */
  let overview = null;
  const main = linePlot(section, {
    name: 'time',
    title: 'Responses',
    ariaLabel:
      'Responses plot: partial responses to the Euler, centrifugal and Coriolis forces, the total response and the Coriolis envelope over time',
    xLabel: 't',
    xUnit: 's',
    yLabel: `q (${Q})`,
    series: [
      { label: 'Euler response', color: color('euler'), width: 1 },
      { label: 'Centrifugal response', color: color('centrifugal'), width: 1 },
      { label: 'Coriolis response', color: color('coriolis'), width: 1.6 },
      { label: 'Total', color: color('total'), width: 1.2 },
      { label: 'Coriolis envelope ± (one-flap average)', color: color('envelope'), width: 2, with: [5] },
      { label: '−envelope', color: color('envelope'), width: 2, legend: false },
    ],
    height: 230,
    bands: () => [
      ...(bw && bw.mark && beat && beat.period != null ? [beatBand(bw.mark, beat.period, fate)] : []),
      ...goneBand(),
    ],
    markers: () => {
      /** @type {import('../plot.js').Marker[]} */
      const out = [];
      if (bw && bw.mark && beat && beat.period != null) {
        const [x0, x1] = main.xWindow();
        for (const x of beatRepeats(bw.mark[0], beat.period, x0, x1, fate))
          out.push({ x, label: '', color: 'rgba(122,60,194,0.5)', dash: [2, 3] });
      }
      return out;
    },
    // The 3-D view's instant: moved every frame while it plays, without repainting the lines.
    live: { label: '3-D t', color: color('cursor'), width: 1.5 },
    onReset: () => resetWindow(),
    onUser: (what) => {
      if (what !== 'reset') userWin = true;
    },
    hooks: {
      // a drag across the plot zooms (uPlot sets the scale itself): the user's window from now on
      setSelect: [
        (u) => {
          if (u.select.width > 2) userWin = true;
        },
      ],
      setScale: [
        (u, key) => {
          if (key !== 'x' || u.scales.x.min == null || u.scales.x.max == null) return;
          win = [u.scales.x.min, u.scales.x.max];
          if (overview) overview.redraw();
        },
      ],
    },
  });
  // Click (not drag) on the plot: show that instant in the 3-D wing.
  /** @type {number[] | null} */
  let down = null;
  main.u.over.addEventListener('pointerdown', (e) => {
    down = [e.clientX, e.clientY];
  });
  main.u.over.addEventListener('pointerup', (e) => {
    if (down && Math.hypot(e.clientX - down[0], e.clientY - down[1]) < 4) {
      const t = main.u.posToVal(e.offsetX, 'x');
      if (Number.isFinite(t)) store.set({ t3d: Math.max(0, t), playing: false });
    }
    down = null;
  });
  main.box.title = touch ? 'Tap to show this instant in the 3-D wing' : 'Click to show this instant in the 3-D wing';

  const ov = timeOverview(section, {
    bands: goneBand,
    shown: () => win,
    move: (w) => {
      userWin = true;
      setWindow(w);
    },
  });
  overview = ov;

  const btnBeats = el('button', {
    type: 'button',
    class: 'wl-small',
    text: 'Three beats',
    onclick: () => resetWindow(),
  });
  const btnAll = el('button', {
    type: 'button',
    class: 'wl-small',
    text: 'Whole run',
    onclick: () => {
      userWin = true;
      setWindow(null);
    },
  });
  const sharesBox = el('div', { class: 'wl-shares' });
  section.append(el('div', { class: 'wl-timebar' }, btnBeats, btnAll), sharesBox);

  function fullRange() {
    const r = store.get().result;
    if (!r) return [0, 1];
    const t = r.analysis.sim.t;
    return [t[0], t[t.length - 1]];
  }
  /** @param {number[] | null} w */
  function setWindow(w) {
    const [lo, hi] = fullRange();
    const [a, b] = clampWindow(w || [lo, hi], lo, hi);
    main.u.setScale('x', { min: a, max: b });
    win = [a, b];
    if (overview) overview.redraw();
  }
  function resetWindow() {
    userWin = false;
    if (bw) setWindow([bw.x0, bw.x1]);
  }

  let beatSig = '';
  let sharesSig = '';
  /**
   * @param {import('../pkg/wingbeat.js').Analysis} a
   * @param {number} k
   * @param {import('../lab.js').LabState} s
   */
  function drawBeat(a, k, s) {
    const b = beat;
    if (!b) return;
    const f = fate || { kind: 'steady', tau: null, goneAt: null, floor: 0.05 };
    const t = a.sim.t;
    const sig = `${k}|${b.period}|${b.fEff}|${b.n}|${b.fd}|${b.stable}|${b.maxModulus}|${s.gamma0 === 0}|${f.kind}|${f.tau}|${t[t.length - 1]}`;
    if (sig === beatSig) return; // unchanged text: no DOM churn (and no repeated live-region announcement)
    beatSig = sig;
    writeBeat(beatBox, a, k, s, b, /** @type {import('../beat.js').BeatFate} */ (f));
  }

  function drawShares(a, k) {
    const sig = `${k}|${shares(a, k)
      .map((x) => fmt(x.value, 3))
      .join()}`;
    if (sig === sharesSig) return;
    sharesSig = sig;
    writeShares(sharesBox, a, k);
  }

  const draw = (s) => {
    const r = s.result;
    if (!r) return;
    const a = r.analysis;
    const k = r.k;
    const m = a.sim.modes[k];
    // The core's envelope, averaged over one flap period for display (its flap-rate ripple hides the beat).
    const env = smooth(a.envelope[k], a.sim.sample_rate_hz / a.sim.flap_freq_hz);
    const neg = new Float64Array(env.length);
    for (let i = 0; i < env.length; i++) neg[i] = -env[i];
    beat = beatInfo(a, k);
    const [lo, hi] = [a.sim.t[0], a.sim.t[a.sim.t.length - 1]];
    fate = beatFate(beat, m.floquet.growth_rate_per_s, hi - lo);
    bw = beatWindow(a.sim.t, env, fate.kind === 'gone' ? null : beat.period);
    // A damped beat: the marked beat only where the beat still is.
    if (fate.kind === 'decays' && bw.mark && fate.goneAt != null && bw.mark[1] > fate.goneAt)
      bw = { ...bw, mark: null };
    let w = userWin && win ? [Math.max(lo, win[0]), Math.min(hi, win[1])] : [bw.x0, bw.x1];
    if (!(w[1] > w[0])) w = [bw.x0, bw.x1];
    main.setData([a.sim.t, m.q.euler, m.q.centrifugal, m.q.coriolis, m.q.total, env, neg], w);
    win = w;
    ov.setData(decimate(a.sim.t, [m.q.total, env], Math.max(200, Math.min(800, Math.round(ov.u.width || 400)))));
    drawBeat(a, k, s);
    drawShares(a, k);
    const peak = (y) => {
      let p = 0;
      for (const v of y) p = Math.max(p, Math.abs(v));
      return p;
    };
    // The responses' peaks are the core's (Analysis.peaks); only the smoothed envelope is scanned here.
    main.setSummary(
      `Mode ${k + 1}, window ${fmt(w[0], 4)} to ${fmt(w[1], 4)} s of a ${fmt(hi, 3)} s run. Peak |q| (${plain(Q)}): total ${fmt(peakOf(a, k, 'total'), 3)}, Euler ${fmt(peakOf(a, k, 'euler'), 3)}, centrifugal ${fmt(peakOf(a, k, 'centrifugal'), 3)}, Coriolis ${fmt(peakOf(a, k, 'coriolis'), 3)}; largest Coriolis envelope ${fmt(peak(env), 3)}. ` +
        (beat.period == null || fate.kind === 'gone'
          ? 'No beat.'
          : `Beat period ${fmt(beat.period, 4)} s${bw.mark ? `, marked from ${fmt(bw.mark[0], 4)} s` : ''}${fate.kind === 'decays' && fate.goneAt != null ? `; the beat decays (τ = ${fmt(/** @type {number} */ (fate.tau), 3)} s) and is gone after ${fmt(fate.goneAt, 3)} s` : ''}.`),
    );
    ov.setSummary(
      `Whole run 0 to ${fmt(hi, 3)} s; the window shown above is ${fmt(w[0], 4)} to ${fmt(w[1], 4)} s.${fate.kind === 'decays' && fate.goneAt != null ? ` Grey from ${fmt(fate.goneAt, 3)} s: the beat is gone.` : ''}`,
    );
  };
  const unsub = [store.subscribe(['result'], draw), store.subscribe(['t3d'], (s) => main.setLive(s.t3d ?? null))];
  main.setLive(store.get().t3d ?? null);

  ctx.registerPlot('time', main);
  ctx.registerExport('time', {
    csv: () => {
      const s = store.get();
      if (!s.result) return null;
      const a = s.result.analysis,
        k = s.result.k,
        m = a.sim.modes[k];
      return ctx.toCSV(
        [
          { name: 't', unit: 's', values: a.sim.t },
          { name: 'euler_response', unit: UNITS.q.csv, values: m.q.euler },
          { name: 'centrifugal_response', unit: UNITS.q.csv, values: m.q.centrifugal },
          { name: 'coriolis_response', unit: UNITS.q.csv, values: m.q.coriolis },
          { name: 'total_response', unit: UNITS.q.csv, values: m.q.total },
          { name: 'coriolis_envelope', unit: UNITS.q.csv, values: a.envelope[k] },
        ],
        [`wingbeat lab; ${toQuery(s)}`, `mode ${k + 1}: ${m.name}; full resolution (the plot is min/max-decimated)`],
      );
    },
    figure: () => {
      const s = store.get();
      if (!s.result) return null;
      const a = s.result.analysis;
      return {
        title: `Responses of mode ${s.result.k + 1} and the beat (paper Fig. 5)`,
        params: describe(s),
        x: a.sim.t,
        xRange: main.xWindow(),
        xLabel: 't (s)',
        yLabel: `q (${Q})`,
        series: main.exportSeries(),
        bands: [...(bw && bw.mark && beat ? [beatBand(bw.mark, beat.period, fate)] : []), ...goneBand()],
        note:
          beat && beat.period != null
            ? `T_{beat} = 1/|f_{eff} − n·f_d| = 1/|${fmt(beat.fEff, 6)} − ${beat.n}×${fmt(beat.fd, 4)}| Hz = ${fmt(beat.period, 4)} s (Floquet). ` +
              (s.modes === 'paper' ? 'q in paper units (Table 4 is not SI).' : 'q in SI.')
            : '',
      };
    },
  });
  return {
    main,
    overview: ov,
    resetWindow,
    destroy: () => {
      for (const f of unsub) f();
      main.destroy();
      ov.destroy();
    },
  };
}
