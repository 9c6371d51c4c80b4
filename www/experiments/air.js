// @ts-check
// The guided experiments of the wing in air (docs/model.md, "The wing in air"): the live run
// is in air on the FE wing, and a study runs the same case in a vacuum (study kind `analyze`
// with `params`: the live analysis of those parameters, in the study worker) so each
// prediction compares the two media from computed numbers. Pure (no DOM); part of
// www/experiments.js's EXPERIMENTS, tested with it in tests/js/experiments_air.test.mjs.
import { fmt } from './fmt.js';
import { measureBeat } from '../measure.js';

const sampleRate = (/** @type {any} */ a) => a.sim.sample_rate_hz || 1 / (a.sim.t[1] - a.sim.t[0]);

/**
 * The largest PSD value of `spec` within one bin of `f` Hz (a harmonic's peak).
 * @param {{ freq_hz: ArrayLike<number>, psd: ArrayLike<number> }} spec
 * @param {number} f
 */
export function psdNear(spec, f) {
  const df = spec.freq_hz[1] - spec.freq_hz[0];
  let best = 0;
  for (let i = 0; i < spec.freq_hz.length; i++)
    if (Math.abs(spec.freq_hz[i] - f) <= 1.01 * df && spec.psd[i] > best) best = spec.psd[i];
  return best;
}

/**
 * The 3ω/1ω amplitude ratio of mode k's total response: √(PSD near 3 f_d / PSD near f_d).
 * @param {any} a an Analysis
 * @param {number} k
 */
export function superharmonicRatio(a, k) {
  const fd = a.sim.flap_freq_hz;
  const sp = a.spectra[k].total;
  const p1 = psdNear(sp, fd);
  const p3 = psdNear(sp, 3 * fd);
  return { p1, p3, ratio: p1 > 0 ? Math.sqrt(p3 / p1) : null };
}

/** The same case in a vacuum, run by the study worker. */
const VACUUM = Object.freeze({ kind: 'analyze', params: Object.freeze({ air_density: 0 }) });

export const AIR_EXPERIMENTS = [
  {
    id: 'air-beat',
    title: 'Does the beat survive in air?',
    figure: 'beyond the paper',
    params: { modes: 'fe', air_density: 1.2, zeta: 0 },
    mode: 0,
    study: VACUUM,
    look: 'The FE wing flaps as in the paper case, now in air (1.2 kg/m³). Look at the responses plot: is there still a swelling and fading Coriolis envelope (red)? Then set the Medium back to vacuum and compare.',
    predict(/** @type {any} */ a, /** @type {any} */ ctx = {}) {
      const k = ctx.mode ?? 0;
      const m = a.sim.modes[k];
      const fd = a.sim.flap_freq_hz;
      const fs = sampleRate(a);
      const dur = a.sim.t[a.sim.t.length - 1];
      const air = m.air;
      if (!air) return { lines: ['This run is not in a fluid: choose Air as the medium.'], checks: [], values: {} };
      const tau = air.decay_time_s;
      const beat = m.floquet.beat_period_s;
      const lines = [
        `In air the added mass lowers mode ${k + 1} from ${fmt(m.freq_hz, 4)} Hz to ${fmt(air.still_air_freq_hz, 4)} Hz (still air), and the drag damps its free vibration: cycle-averaged ζ_a = ${fmt(air.aero_damping_ratio, 3)}, Floquet decay rate σ = ${fmt(air.decay_rate_per_s, 3)} 1/s, time constant τ = ${fmt(tau, 3)} s. The beat is that free vibration drifting against the forced one (period ${beat == null ? '— (none)' : fmt(beat, 3) + ' s'}), so it can live only about τ.`,
      ];
      const air2 = measureBeat(a.envelope[k], fs, fd, 0.25, 1);
      /** @type {any[]} */
      const checks = [
        {
          id: 'decays-within-a-beat',
          label: `Floquet: the free vibration decays within one beat period (τ ${fmt(tau, 3)} s < T_{beat} ${fmt(beat, 3)} s)`,
          holds: tau != null && beat != null && tau < beat,
          value: tau,
          expected: beat,
        },
      ];
      const v = ctx.study;
      if (v && v.sim && v.envelope && v.envelope[k]) {
        const vac = measureBeat(v.envelope[k], fs, fd, 0.25, 1);
        const vm = v.sim.modes[k];
        lines.push(
          `Measured after the first quarter of the ${fmt(dur, 3)} s run, the Coriolis envelope's modulation (max − min)/(max + min) is ${fmt(vac.modulation_index, 3)} in a vacuum (beat period ${fmt(vm.floquet.beat_period_s, 3)} s, f_{eff} ${fmt(vm.floquet.effective_freq_hz, 4)} Hz) and ${fmt(air2.modulation_index, 3)} in air.`,
        );
        checks.push({
          id: 'beat-gone',
          label: `Envelope modulation in air at most a tenth of the vacuum's (${fmt(air2.modulation_index, 3)} vs ${fmt(vac.modulation_index, 3)})`,
          holds: air2.modulation_index <= 0.1 * vac.modulation_index,
          value: air2.modulation_index,
          expected: 0.1 * vac.modulation_index,
        });
      } else lines.push('The same case in a vacuum is computing…');
      return { lines, checks, values: { tau, beat, modulation_air: air2.modulation_index } };
    },
  },
  {
    id: 'air-superharmonic',
    title: 'The 3ω superharmonic: vacuum vs air',
    figure: 'beyond the paper',
    params: { modes: 'fe', air_density: 1.2, flap_hz: 20.5, zeta: 0.02, duration: 4 },
    mode: 0,
    study: VACUUM,
    look: 'The FE wing flaps at 20.5 Hz, about a third of its first natural frequency, so the third flap harmonic 3f_d sits near mode 1. Read the numbers below and the Floquet table’s air rows, then open the Forces tab: in the spectra panel compare the total response’s peak at 3f_d with the one at f_d, in air, and again after switching the Medium to vacuum.',
    predict(/** @type {any} */ a, /** @type {any} */ ctx = {}) {
      const k = ctx.mode ?? 0;
      const fd = a.sim.flap_freq_hz;
      const m = a.sim.modes[k];
      const inAir = superharmonicRatio(a, k);
      const lines = [
        `Flapping at f_d = ${fmt(fd, 4)} Hz puts 3f_d = ${fmt(3 * fd, 4)} Hz near mode ${k + 1} (${fmt(m.freq_hz, 4)} Hz in a vacuum${m.air ? `, ${fmt(m.air.still_air_freq_hz, 4)} Hz in still air` : ''}): the inertial forces and the time-varying centrifugal softening have a 3f_d part, which this mode amplifies. In air its aerodynamic damping (ζ_a = ${m.air ? fmt(m.air.aero_damping_ratio, 3) : '—'}) should hold that resonance down, while the 1f_d response (driven by the aerodynamic force too) does not drop. In air the 3f_d/1f_d amplitude ratio of the total response is ${fmt(inAir.ratio, 3)}.`,
      ];
      /** @type {any[]} */
      const checks = [];
      const v = ctx.study;
      if (v && v.sim && v.spectra && v.spectra[k]) {
        const vac = superharmonicRatio(v, k);
        lines.push(
          `In a vacuum the same ratio is ${fmt(vac.ratio, 3)}: air ${inAir.ratio != null && vac.ratio != null && inAir.ratio < vac.ratio ? `suppresses the superharmonic ${fmt(vac.ratio / inAir.ratio, 3)}-fold relative to 1f_d` : 'does not suppress the superharmonic here'}; the 1f_d response changes ×${fmt(Math.sqrt(inAir.p1 / vac.p1), 3)} and the 3f_d response ×${fmt(Math.sqrt(inAir.p3 / vac.p3), 3)}. (J. Vib. Acoust. 142:021012, 2020, measured this in kind on a flexible flapping wing; they give no numbers for this wing.)`,
        );
        checks.push(
          {
            id: 'superharmonic-suppressed',
            label: `3f_d/1f_d amplitude ratio lower in air than in a vacuum (${fmt(inAir.ratio, 3)} vs ${fmt(vac.ratio, 3)})`,
            holds: inAir.ratio != null && vac.ratio != null && inAir.ratio < vac.ratio,
            value: inAir.ratio,
            expected: vac.ratio,
          },
          {
            id: 'third-harmonic-falls',
            label: `The 3f_d response itself falls in air (×${fmt(Math.sqrt(inAir.p3 / vac.p3), 3)})`,
            holds: inAir.p3 < vac.p3,
            value: Math.sqrt(inAir.p3 / vac.p3),
            expected: 1,
          },
        );
      } else lines.push('The same case in a vacuum is computing…');
      return { lines, checks, values: { ratio_air: inAir.ratio } };
    },
  },
];
