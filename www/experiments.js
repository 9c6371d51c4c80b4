// @ts-check
// Guided experiments: one-click parameter sets, each with what to look at and what the model
// predicts, the prediction computed from the live analysis (never canned numbers). Pure module
// (no DOM), unit-tested in tests/js/experiments.test.mjs against synthetic fixtures.
//
// An experiment is { id, title, figure, params, mode, study, look, predict(analysis, ctx) }:
//   params   URL parameters (www/state.js names) applied on top of the paper defaults;
//   study    an optional worker study whose numbers the prediction uses:
//            { kind: 'sweep' | 'icmap' | 'resonance', opts } (ctx.study holds its result);
//   predict  returns { lines: [sentence], checks: [{ id, label, holds, value, expected }],
//            values: { … } } from a wasm `analyze` result (a.sim, a.envelope) and ctx:
//            { study?, mode? } (mode: 0-based index of the selected mode).
// The numbers in `params` for the resonance and instability experiments were picked from the
// wasm `resonanceMap` of the paper case (see docs/lab.md), not guessed; their predictions are
// still recomputed from whatever the analysis returns.

import { defaults, toQuery, NUMERIC, ENUMS } from './state.js';
import { UNITS, errorText } from './format.js';
import { peakAbs, measureBeat, growthRate } from './measure.js';
import { fmt } from './experiments/fmt.js';
import { AIR_EXPERIMENTS } from './experiments/air.js';
import { NEURAL_EXPERIMENTS } from './experiments/neural.js';

export { fmt };

const sampleRate = (a) => a.sim.sample_rate_hz || 1 / (a.sim.t[1] - a.sim.t[0]);
const relErr = (x, ref) => Math.abs(x - ref) / Math.abs(ref);

/** The mode with the largest Floquet |multiplier| (the least stable one). */
export function leastStableMode(a) {
  let k = 0;
  a.sim.modes.forEach((m, j) => {
    if (m.floquet.max_modulus > a.sim.modes[k].floquet.max_modulus) k = j;
  });
  return k;
}

/** Beat of mode k's Coriolis response against 2 f_d: the Floquet prediction and the measurement. */
function coriolisBeat(a, k) {
  const m = a.sim.modes[k];
  const fd = a.sim.flap_freq_hz;
  const feff = m.floquet.effective_freq_hz;
  const predicted = 1 / Math.abs(feff - 2 * fd);
  const env = a.envelope && a.envelope[k];
  const meas = env ? measureBeat(env, sampleRate(a), fd, 0, 1) : { period_s: null, modulation_index: 0 };
  return { fd, feff, predicted, measured: meas.period_s, modulation: meas.modulation_index };
}

function beatLines(b, duration) {
  return (
    `f_{eff} = ${fmt(b.feff, 4)} Hz and the Coriolis force drives at 2 f_d = ${fmt(2 * b.fd, 4)} Hz, so the envelope should repeat every ` +
    `T_{beat} = 1/|${fmt(b.feff, 4)} − ${fmt(2 * b.fd, 4)}| = ${fmt(b.predicted, 3)} s (${fmt(duration / b.predicted, 3)} beats in the ${fmt(duration, 3)} s run).`
  );
}

function beatCheck(b, tol) {
  const holds = b.measured != null && relErr(b.measured, b.predicted) <= tol;
  return {
    id: 'beat-period',
    label:
      b.measured == null
        ? 'Beat period measured from the envelope: no full beat in this run'
        : `Beat period measured from the envelope: ${fmt(b.measured, 4)} s (Floquet ${fmt(b.predicted, 4)} s, ${fmt(100 * relErr(b.measured, b.predicted), 2)} % apart; allowed ${fmt(100 * tol, 2)} %)`,
    holds,
    value: b.measured,
    expected: b.predicted,
  };
}

const modeName = (a, k) => `mode ${k + 1} (f_${k + 1} = ${fmt(a.sim.modes[k].freq_hz, 4)} Hz)`;

export const EXPERIMENTS = [
  {
    id: 'beat',
    title: 'The Coriolis beat (paper case)',
    figure: 'Fig. 5',
    params: {},
    mode: 0,
    look: 'Look at the Coriolis response (green) on the responses plot and its envelope (red): the amplitude swells and fades regularly — the beat; the shading marks one beat period.',
    predict(a, ctx = {}) {
      const k = ctx.mode ?? 0;
      const b = coriolisBeat(a, k);
      const dur = a.sim.t[a.sim.t.length - 1];
      const lines = [`Floquet theory, ${modeName(a, k)}: the flapping softens the wing, ` + beatLines(b, dur)];
      const checks = [beatCheck(b, 0.02)];
      return { lines, checks, values: { feff: b.feff, fd: b.fd, predicted_s: b.predicted, measured_s: b.measured } };
    },
  },
  {
    id: 'no-yaw',
    title: 'No yaw: no Coriolis force, no beat',
    figure: 'Eq. 13',
    params: { gamma0: 0 },
    mode: 0,
    look: 'Look at the Coriolis response and its envelope on the responses plot: both lie flat on zero; the wing still bends (Euler and centrifugal responses).',
    predict(a, ctx = {}) {
      const k = ctx.mode ?? 0;
      const gamma0 = ctx.state ? ctx.state.gamma0 : null;
      const peaks = a.sim.modes.map((m) => peakAbs(m.q.coriolis));
      const envPeak = a.envelope && a.envelope[k] ? peakAbs(a.envelope[k]) : 0;
      const shares = a.sim.modes.map((m) => m.contribution_percent.coriolis);
      const c = a.sim.modes[k].contribution_percent;
      const lines = [
        `The Coriolis force is −2 γ̇ Ω·a_k: with ${gamma0 == null ? 'no yaw' : `γ_0 = ${fmt(gamma0, 3)} rad`} the yaw rate γ̇ is zero at every instant, so the force, its response and its envelope are exactly zero — measured max |q_{Coriolis}| = ${peaks.map((p) => fmt(p, 3)).join(' and ')} (modes ${peaks.map((_, j) => j + 1).join(', ')}), Coriolis share ${shares.map((s) => fmt(s, 3)).join(' / ')} %.`,
        `What is left is the Euler (${fmt(c.euler, 3)} %) and centrifugal (${fmt(c.centrifugal, 3)} %) response of ${modeName(a, k)}: no Coriolis beat, so nothing here could tell the insect that its body turned.`,
      ];
      const checks = [
        {
          id: 'coriolis-zero',
          label: `Coriolis response identically zero in every mode (max |q| = ${peaks.map((p) => fmt(p, 3)).join(', ')})`,
          holds: peaks.every((p) => p === 0),
          value: Math.max(...peaks),
          expected: 0,
        },
        {
          id: 'envelope-zero',
          label: `Coriolis envelope identically zero (max ${fmt(envPeak, 3)})`,
          holds: envPeak === 0,
          value: envPeak,
          expected: 0,
        },
      ];
      return { lines, checks, values: { coriolis_peak: Math.max(...peaks), envelope_peak: envPeak } };
    },
  },
  {
    id: 'damping',
    title: 'Damping removes the beat',
    figure: 'Fig. 8',
    params: { zeta: 0.01, duration: 10 },
    mode: 0,
    look: 'Look at the overview of the whole run under the responses plot: the envelope (red) swings strongly at first, then settles to a steady amplitude as the free vibration dies out. The responses panel gives the decay time and greys the part of the run where the beat is gone.',
    predict(a, ctx = {}) {
      const k = ctx.mode ?? 0;
      const m = a.sim.modes[k];
      const fs = sampleRate(a);
      const fd = a.sim.flap_freq_hz;
      const zeta = m.zeta;
      const omega = 2 * Math.PI * m.freq_hz;
      const tau = 1 / (zeta * omega);
      const dur = a.sim.t[a.sim.t.length - 1];
      const env = a.envelope[k];
      const early = measureBeat(env, fs, fd, 0, 0.1);
      const late = measureBeat(env, fs, fd, 0.8, 1);
      const ratio = late.modulation_index > 0 ? early.modulation_index / late.modulation_index : Infinity;
      const decay = Math.exp((-0.7 * dur) / tau);
      const lines = [
        `With ζ = ${fmt(zeta, 3)} the free vibration at f_{eff} = ${fmt(m.floquet.effective_freq_hz, 4)} Hz decays as exp(−ζ ω_${k + 1} t), time constant 1/(ζ·2π·${fmt(m.freq_hz, 4)} Hz) = ${fmt(tau, 3)} s; by the last fifth of the ${fmt(dur, 3)} s run it is down to ${fmt(decay, 2)} of its start, so the beat should vanish and only the forced vibration at 2 f_d = ${fmt(2 * fd, 4)} Hz stay.`,
        `Envelope modulation index (max − min)/(max + min): ${fmt(early.modulation_index, 3)} in the first tenth, ${fmt(late.modulation_index, 2)} in the last fifth — ${Number.isFinite(ratio) ? fmt(ratio, 3) + '×' : 'infinitely'} lower.`,
      ];
      const checks = [
        {
          id: 'modulation-drop',
          label: `Beat modulation falls at least 10× (measured ${Number.isFinite(ratio) ? fmt(ratio, 3) : '∞'}×)`,
          holds: ratio >= 10,
          value: ratio,
          expected: 10,
        },
        {
          id: 'stable',
          label: `Floquet: stable, growth rate ${fmt(m.floquet.growth_rate_per_s, 3)} 1/s (−ζω = ${fmt(-zeta * omega, 3)} 1/s)`,
          holds: m.floquet.stable && m.floquet.growth_rate_per_s < 0,
          value: m.floquet.growth_rate_per_s,
          expected: -zeta * omega,
        },
      ];
      return { lines, checks, values: { early: early.modulation_index, late: late.modulation_index, ratio, tau } };
    },
  },
  {
    id: 'yaw',
    title: 'Yaw amplitude and the Coriolis share',
    figure: 'Fig. 6',
    params: { gamma0: 0.1 },
    mode: 0,
    study: { kind: 'sweep', opts: { param: 'gamma0', from: 0, to: 0.3, points: 7 } },
    look: 'Compare the Coriolis response with the paper case (γ_0 = 0.2 rad): half the yaw, half the Coriolis response. The sweep study (Studies → Contribution vs parameter) draws the whole curve.',
    predict(a, ctx = {}) {
      const k = ctx.mode ?? 0;
      const m = a.sim.modes[k];
      const g = ctx.state ? ctx.state.gamma0 : null;
      const peak = peakAbs(m.q.coriolis);
      const lines = [
        `The Coriolis force −2 γ̇ Ω·a_k is proportional to γ_0, and so is its response (here peak |q_{C}| = ${fmt(peak, 3)}${g ? `, i.e. ${fmt(peak / g, 4)} per rad of γ_0` : ''}); the Euler and centrifugal forces depend on γ only through small terms. So the Coriolis share should rise with γ_0: ${fmt(m.contribution_percent.coriolis, 3)} % at γ_0 = ${g == null ? '?' : fmt(g, 3)} rad for ${modeName(a, k)}.`,
      ];
      const checks = [];
      const s = ctx.study;
      if (s && s.values && s.modes) {
        const sm = s.modes[k];
        const cor = Array.from(sm.coriolis);
        const vals = Array.from(s.values);
        lines.push(
          `The sweep over γ_0 = ${fmt(vals[0], 3)} … ${fmt(vals[vals.length - 1], 3)} rad gives the Coriolis share ${cor.map((v) => fmt(v, 3)).join(', ')} %.`,
        );
        let rising = true;
        for (let i = 1; i < cor.length; i++) if (!(cor[i] >= cor[i - 1] - 1e-9)) rising = false;
        checks.push({
          id: 'share-rises',
          label: `Coriolis share rises with γ_0 over the sweep (${fmt(cor[0], 3)} → ${fmt(cor[cor.length - 1], 3)} %)`,
          holds: rising && cor[cor.length - 1] > cor[0],
          value: cor[cor.length - 1] - cor[0],
          expected: 0,
        });
        if (g != null) {
          const j = vals.findIndex((v) => Math.abs(v - g) < 1e-9);
          if (j >= 0) {
            checks.push({
              id: 'share-matches',
              label: `Sweep at γ_0 = ${fmt(g, 3)} rad equals this run (${fmt(cor[j], 6)} vs ${fmt(m.contribution_percent.coriolis, 6)} %)`,
              holds: Math.abs(cor[j] - m.contribution_percent.coriolis) < 1e-6,
              value: cor[j],
              expected: m.contribution_percent.coriolis,
            });
          }
        }
      } else {
        lines.push('The γ_0 sweep is computing in the worker…');
      }
      return { lines, checks, values: { coriolis_share: m.contribution_percent.coriolis, coriolis_peak: peak } };
    },
  },
  {
    id: 'ic',
    title: 'Initial conditions',
    figure: 'Fig. 7',
    params: {},
    mode: 0,
    study: { kind: 'icmap', opts: { n_q: 41, n_qdot: 41, attribution: 'forced' } },
    look: 'Initial conditions only add a free vibration at f_{eff}; the forced responses stay the same. The initial-condition map (Studies → Initial-condition map) shows how the Coriolis share moves with them.',
    predict(a, ctx = {}) {
      const k = ctx.mode ?? 0;
      const m = a.sim.modes[k];
      const rest = m.contribution_percent.coriolis;
      const lines = [
        `Starting from rest, the Coriolis share of ${modeName(a, k)} is ${fmt(rest, 4)} %. A start (q_0, q̇_0) adds a free vibration at f_{eff} = ${fmt(m.floquet.effective_freq_hz, 4)} Hz to the total but leaves the forced Coriolis response unchanged, so the share moves with the initial conditions.`,
      ];
      const checks = [];
      const r = ctx.study;
      if (r && r.coriolis_percent) {
        lines.push(
          `Over ${r.n_q}×${r.n_qdot} starts spanning the forced response’s own range (q_0 from ${fmt(r.q0[0], 3)} to ${fmt(r.q0[r.q0.length - 1], 3)} ${UNITS.q.label}, “${r.attribution}” attribution) the share runs from ${fmt(r.min_percent, 3)} % to ${fmt(r.max_percent, 3)} %; ${fmt(100 * r.fraction_above_60, 3)} % of the starts give more than 60 % (the paper: most of them).`,
        );
        checks.push({
          id: 'rest-inside',
          label: `The share from rest (${fmt(rest, 4)} %) lies inside the map’s range ${fmt(r.min_percent, 3)}–${fmt(r.max_percent, 3)} %`,
          holds: rest >= r.min_percent - 1e-9 && rest <= r.max_percent + 1e-9,
          value: rest,
          expected: [r.min_percent, r.max_percent],
        });
      } else {
        lines.push('The initial-condition map is computing in the worker…');
      }
      return { lines, checks, values: { rest } };
    },
  },
  {
    id: 'resonance',
    title: 'Flapping near a natural frequency (resonance)',
    figure: 'resonance map',
    params: { flap_hz: 29, duration: 4 },
    mode: 0,
    study: { kind: 'resonance', opts: { from_hz: 5, to_hz: 60, points: 221 } },
    look: 'Look at the Coriolis envelope (red): the beats are far slower and larger than in the paper case, because twice the flap frequency sits close to the wing’s effective natural frequency.',
    predict(a, ctx = {}) {
      const k = ctx.mode ?? 0;
      const m = a.sim.modes[k];
      const b = coriolisBeat(a, k);
      const dur = a.sim.t[a.sim.t.length - 1];
      const n = Math.max(1, Math.round(b.feff / b.fd));
      const lines = [
        `f_d = ${fmt(b.fd, 4)} Hz is close to f_{eff}/2 (f_${k + 1}/2 = ${fmt(m.freq_hz / 2, 4)} Hz unsoftened): the Coriolis force’s line at 2 f_d sits ${fmt(Math.abs(b.feff - 2 * b.fd), 3)} Hz from the effective natural frequency. ` +
          beatLines(b, dur),
        `The nearer n·f_d comes to f_{eff}, the longer and larger the beat; at f_{eff} = n·f_d exactly the response would grow without bound (here n = ${n}: ${n}·f_d = ${fmt(n * b.fd, 4)} Hz). Max |λ| = ${fmt(m.floquet.max_modulus, 6)}: ${m.floquet.stable ? 'still stable' : 'unstable'}.`,
      ];
      const checks = [
        beatCheck(b, 0.03),
        {
          id: 'stable',
          label: `Still Floquet-stable (max |λ| = ${fmt(m.floquet.max_modulus, 8)})`,
          holds: m.floquet.max_modulus <= 1 + 1e-9,
          value: m.floquet.max_modulus,
          expected: 1,
        },
      ];
      const r = ctx.study;
      if (r && r.flap_hz && r.modes) lines.push(resonanceSummary(r).sentence);
      return { lines, checks, values: { feff: b.feff, predicted_s: b.predicted, measured_s: b.measured } };
    },
  },
  {
    id: 'instability',
    title: 'A parametric instability',
    figure: 'resonance map',
    params: { alpha0: 0.87, flap_hz: 29.5, duration: 4 },
    mode: 0,
    study: { kind: 'resonance', opts: { from_hz: 5, to_hz: 60, points: 221 } },
    look: 'Look at the total response: instead of beating, it grows flap after flap (0.5 Hz and a little more roll away from the resonance experiment). The stiffness ω_k² − (α̇²cos²β + β̇²) pulses at 2 f_d, and at this flap frequency the pulsing pumps energy into the mode (parametric resonance, like a child pumping a swing).',
    predict(a, ctx = {}) {
      const k = leastStableMode(a);
      const m = a.sim.modes[k];
      const f = m.floquet;
      const fd = a.sim.flap_freq_hz;
      const dur = a.sim.t[a.sim.t.length - 1];
      const sigma = Math.log(f.max_modulus) * fd;
      const measured = growthRate(m.q.total, sampleRate(a), fd, 0.5, 1);
      const ratio = f.effective_freq_hz / fd;
      const lines = [
        `Floquet, ${modeName(a, k)}: max |λ| = ${fmt(f.max_modulus, 6)} per flap period ${f.max_modulus > 1 ? '> 1' : '≤ 1'}, so a disturbance is multiplied by ${fmt(f.max_modulus, 4)} every 1/f_d = ${fmt(1000 / fd, 4)} ms: growth rate σ = f_d·ln|λ| = ${fmt(sigma, 4)} 1/s, ×${fmt(Math.exp(sigma * dur), 3)} over the ${fmt(dur, 3)} s run.`,
        `Here f_{eff}/f_d = ${fmt(ratio, 4)}: the mode sits in an instability tongue near f_{eff} = ${Math.round(ratio)}·f_d. Measured from the peaks of q_{total} over the second half of the run: σ = ${fmt(measured, 4)} 1/s.`,
      ];
      const checks = [
        {
          id: 'unstable',
          label: `max |λ| = ${fmt(f.max_modulus, 8)} > 1 (unstable)`,
          holds: f.max_modulus > 1 && !f.stable,
          value: f.max_modulus,
          expected: 1,
        },
        {
          id: 'growth',
          label: `Response grows at the Floquet rate (measured ${fmt(measured, 4)} 1/s vs ${fmt(sigma, 4)} 1/s, within 15 %)`,
          holds: measured != null && relErr(measured, sigma) <= 0.15,
          value: measured,
          expected: sigma,
        },
      ];
      const r = ctx.study;
      if (r && r.flap_hz && r.modes) lines.push(resonanceSummary(r).sentence);
      return { lines, checks, values: { max_modulus: f.max_modulus, sigma, measured, mode: k } };
    },
  },
  {
    id: 'sensing',
    title: 'Sensing body rotation through wing strain',
    figure: 'sensing panel',
    params: { modes: 'fe' },
    mode: 0,
    look: 'Open the “Sensing body rotation” panel (FE wing). Set the rotation rate to 0.001 rad/s about z (yaw) and watch the detection curve: how many strain sensors does it take to reach P_d = 0.9? Then raise the rate ten-fold: D grows a hundred-fold and one sensor suffices. Where are the best sensors: at the root or the tip, and which strain component (ε_x bending, γ_xy twist)?',
    predict(a, ctx = {}) {
      const k = ctx.mode ?? 0;
      const m = a.sim.modes[k];
      const fd = a.sim.flap_freq_hz;
      const cor = m.contribution_percent.coriolis;
      const lines = [
        `The model predicts that a body rotation ω_b adds Coriolis and centrifugal forcing to every mode of the flapping wing: the frame's rate becomes Ω = R^T ω_b + Ω_{wing}, so the rotation-induced strain Δε grows in proportion to ω_b for small rates and its detectability D = E_Δ/(ρ^2E_F + σ^2) with ω_b^2. Without rotation the ${modeName(a, k)} already carries a Coriolis share of ${fmt(cor, 3)} % of its response at f_d = ${fmt(fd, 4)} Hz (from the yaw of the stroke); the rotation signal rides on these same forces, so it appears at the flap harmonics n·f_d and near the modes' natural frequencies.`,
      ];
      const checks = [
        {
          id: 'coriolis-present',
          label: `The flapping wing already feels a Coriolis force (share ${fmt(cor, 3)} % > 0), the channel through which body rotation reaches the strain`,
          holds: cor > 0,
          value: cor,
          expected: 0,
        },
      ];
      return { lines, checks, values: { coriolis_percent: cor } };
    },
  },
  ...AIR_EXPERIMENTS,
  ...NEURAL_EXPERIMENTS,
];

export function experiment(id) {
  return EXPERIMENTS.find((e) => e.id === id) || null;
}

/** The full lab state of an experiment: the paper defaults plus its parameters (panels kept). */
/**
 * @param {string} id
 * @param {string[]} [panels]
 * @returns {import('./state.js').Params | null}
 */
export function experimentState(id, panels) {
  const e = experiment(id);
  if (!e) return null;
  const s = defaults();
  /** @type {Record<string, unknown>} */
  const into = s;
  for (const [k, v] of Object.entries(e.params)) into[k] = v;
  if (!('mode' in e.params)) s.mode = (e.mode ?? 0) === 1 ? '2' : '1';
  if (panels) s.panels = panels.slice();
  return s;
}

/**
 * The parameters an experiment sets: every slider and enum of www/state.js (on the paper
 * defaults) except the mode set, which stays as it is unless the experiment names one (the
 * sensing experiment asks for the FE wing).
 */
const EXPERIMENT_KEYS = [...NUMERIC.map((p) => p.key), ...ENUMS.filter((e) => e.key !== 'modes').map((e) => e.key)];

/**
 * What opening an experiment changes: `exp` and the experiment's parameters (experimentState),
 * except the keys in `given` — values stated with it in the same URL, attribute set or message,
 * which win over the experiment's. The ONE definition every entry point applies: a chip
 * (views/experiments.js), `?exp=` in the URL and `<wing-lab exp=…>` (lab.js), and the message
 * API's `set({ exp })` (embed-api.js). Null for an unknown id.
 * @param {string} id
 * @param {Iterable<string>} [given]
 * @returns {Record<string, unknown> | null}
 */
export function experimentPatch(id, given = []) {
  const e = experiment(id);
  const s = experimentState(id);
  if (!e || !s) return null;
  const keep = new Set(given);
  /** @type {Record<string, unknown>} */
  const from = s;
  /** @type {Record<string, unknown>} */
  const patch = { exp: id };
  for (const k of new Set([...EXPERIMENT_KEYS, ...Object.keys(e.params)])) if (!keep.has(k)) patch[k] = from[k];
  return patch;
}

/** The experiment's shareable query string (no leading '?'): every parameter plus exp=<id>. */
export function experimentQuery(id, extra = {}) {
  const s = experimentState(id);
  if (!s) return null;
  return toQuery(s, { ...extra, exp: id });
}

/** Runs an experiment's prediction; never throws (a failure becomes a line of text). */
export function predict(id, analysis, ctx = {}) {
  const e = experiment(id);
  if (!e) return { lines: [`Unknown experiment ${String(id).slice(0, 40)}`], checks: [], values: {} };
  try {
    return e.predict(analysis, ctx);
  } catch (err) {
    return { lines: [`The prediction could not be computed: ${errorText(err)}`], checks: [], values: {} };
  }
}

// ---------- resonance map summaries (text alternative and experiment sentences) ----------

/** Intervals [from, to] of x where flag[i] is true (consecutive grid points joined). */
export function bands(x, flag) {
  const out = [];
  let start = -1;
  for (let i = 0; i < x.length; i++) {
    if (flag[i] && start < 0) start = i;
    if ((!flag[i] || i === x.length - 1) && start >= 0) {
      const end = flag[i] ? i : i - 1;
      out.push([x[start], x[end]]);
      start = -1;
    }
  }
  return out;
}

/**
 * Flap frequencies where f_{eff} of a mode crosses n·f_d (n = 1..nMax): the resonances
 * (linear interpolation between grid points; NaN values skipped, and with `stable` given, only
 * between two stable points).
 */
/**
 * @param {ArrayLike<number>} fd
 * @param {ArrayLike<number>} feff
 * @param {number} [nMax]
 * @param {ArrayLike<boolean | number> | null} [stable]
 */
export function resonanceCrossings(fd, feff, nMax = 4, stable = null) {
  const out = [];
  const ok = (i) => Number.isFinite(feff[i]) && (!stable || stable[i]);
  for (let n = 1; n <= nMax; n++) {
    for (let i = 1; i < fd.length; i++) {
      // Inside an unstable band f_eff locks onto n·f_d: those are bands, not crossings.
      if (!ok(i - 1) || !ok(i)) continue;
      const g0 = feff[i - 1] - n * fd[i - 1];
      const g1 = feff[i] - n * fd[i];
      const last = i === fd.length - 1 && g1 === 0;
      if (g0 === 0 || g0 * g1 < 0 || last) {
        const t = g0 === 0 ? 0 : last ? 1 : g0 / (g0 - g1);
        out.push({ n, flap_hz: fd[i - 1] + t * (fd[i] - fd[i - 1]) });
      }
    }
  }
  return out.sort((p, q) => p.flap_hz - q.flap_hz);
}

/**
 * A plain-text summary of a resonanceMap result (1-D: no alpha0 axis, or the row of a given
 * alpha0 index): per mode, the unstable bands of f_d, the largest |multiplier| and where, and
 * the flap frequencies where f_{eff} = n·f_d. Returns { modes: [...], sentence }.
 */
export function resonanceSummary(r, row = 0) {
  const nx = r.flap_hz.length;
  const fd = Array.from(r.flap_hz);
  const modes = r.modes.map((m, k) => {
    const sl = (arr) => Array.from(arr).slice(row * nx, row * nx + nx);
    const feff = sl(m.effective_freq_hz);
    const mod = sl(m.max_modulus);
    const stable = sl(m.stable);
    const unstable = bands(
      fd,
      stable.map((s) => !s),
    );
    let im = 0;
    for (let i = 1; i < nx; i++) if (mod[i] > mod[im]) im = i;
    return {
      mode: k + 1,
      freq_hz: m.freq_hz,
      unstable,
      max_modulus: mod[im],
      max_at_hz: fd[im],
      resonances: resonanceCrossings(fd, feff, 4, stable.map(Boolean)),
    };
  });
  const parts = modes.map((m) => {
    const u = m.unstable.length
      ? `unstable for f_d in ${m.unstable.map(([a, b]) => (a === b ? `${fmt(a, 4)}` : `${fmt(a, 4)}–${fmt(b, 4)}`)).join(', ')} Hz (largest |λ| ${fmt(m.max_modulus, 5)} at ${fmt(m.max_at_hz, 4)} Hz)`
      : `stable over the whole range (largest |λ| ${fmt(m.max_modulus, 6)})`;
    const res = m.resonances.length
      ? `; f_{eff} = n·f_d at ${m.resonances.map((c) => `${fmt(c.flap_hz, 4)} Hz (n = ${c.n})`).join(', ')}`
      : '; f_{eff} meets no n·f_d line (n ≤ 4)';
    return `mode ${m.mode} (f = ${fmt(m.freq_hz, 4)} Hz): ${u}${res}`;
  });
  const range = `f_d = ${fmt(fd[0], 4)}–${fmt(fd[nx - 1], 4)} Hz`;
  return { modes, sentence: `Resonance map, ${range}: ${parts.join('; ')}.` };
}
