// @ts-check
// The guided experiment of sensing as the published studies measure it (docs/sensing.md,
// "Classifying rotation"): the study worker runs wasm `classifyRotation` on the published plate
// (Mohren et al. 2018: 50 × 25 mm acrylic, flapping at 25 Hz, rotation 0 or 10 rad/s about its
// normal, seeded disturbances), encodes each sensor's strain as a neuron would and classifies
// rotation against none; the prediction reads the computed accuracies and sets them beside the
// published ones. Pure (no DOM); part of www/experiments.js's EXPERIMENTS, tested in
// tests/js/experiments_neural.test.mjs.
import { fmt } from './fmt.js';

/**
 * The study's request: the published setup on a 2 mm sensor grid (26 × 13 = 338 sensors, a
 * quarter of the published 1326, so the browser computes it in seconds), SSPOC at six kept-mode
 * counts and 30 random draws per count.
 */
export const NEURAL_REQUEST = Object.freeze({
  grid_step_mm: 2,
  seed: 1,
  options: Object.freeze({
    kept_modes: Object.freeze([5, 10, 15, 20, 25, 30]),
    random_counts: Object.freeze([1, 5, 10, 20, 30]),
    random_draws: 30,
  }),
});

/** Published (Mohren et al. 2018, Fig. 3; 1326 sensors, 100 runs): all sensors encoded and raw, 10 random sensors. */
export const PUBLISHED = Object.freeze({ encoded: 0.9, raw: 0.488, random10: 0.631 });

/** Published mean accuracy of random encoded sensor sets by size (Mohren et al. 2018, Fig. 3; docs/sensing.md). */
export const PUBLISHED_RANDOM = Object.freeze([
  Object.freeze({ sensors: 10, mean: 0.631 }),
  Object.freeze({ sensors: 20, mean: 0.814 }),
  Object.freeze({ sensors: 30, mean: 0.889 }),
]);

/** The study's request to the worker and its key in the page's study cache (www/lab/study-cache.js). */
export const NEURAL_STUDY = Object.freeze({ kind: 'classify', opts: NEURAL_REQUEST });

/**
 * The random-placement point with `n` sensors, or null.
 * @param {any} curves
 * @param {number} n
 */
export const randomAt = (curves, n) => curves.random.find((/** @type {any} */ p) => p.sensors === n) || null;

/**
 * The most accurate SSPOC set of at most `n` sensors, or null.
 * @param {any} curves
 * @param {number} n
 */
export function bestSparse(curves, n) {
  /** @type {{ sensors: number[], accuracy: number } | null} */
  let best = null;
  for (const p of curves.sparse) if (p.sensors.length <= n && (!best || p.accuracy > best.accuracy)) best = p;
  return best;
}

export const pct = (/** @type {number} */ x) => `${fmt(100 * x, 3)} %`;

export const NEURAL_EXPERIMENTS = [
  {
    id: 'neural-sensing',
    title: 'As a neuron sees it: rotation from strain (Mohren et al. 2018)',
    figure: 'beyond the paper',
    params: { modes: 'fe' },
    mode: 0,
    study: NEURAL_STUDY,
    look: 'The study worker flaps the published sensing plate (50 × 25 mm acrylic, 25 Hz) twice from rest, once still and once turning at 10 rad/s about its normal, with small random disturbances, and reads the spanwise strain at 338 points. Each reading is encoded as a neuron would (a spike-triggered-average filter, then a sigmoid), and a linear classifier learns from the first 90 % of the samples to tell turning from still; the last 10 % test it. Can raw strain do it? Can a few sensors? (The 3-D view keeps the lab’s own wing; the plate is computed apart.)',
    predict(/** @type {any} */ _a, /** @type {any} */ ctx = {}) {
      const r = ctx.study;
      if (!r || !r.report)
        return {
          lines: ['The published plate is computing in the study worker (a few seconds)…'],
          checks: [],
          values: {},
        };
      const rep = r.report;
      const e = rep.encoded;
      const w = rep.raw;
      const n = rep.sensors.length;
      const one = randomAt(e, 1);
      const ten = randomAt(e, 10);
      const sparse = bestSparse(e, 15);
      const lines = [
        `The plate's first modes: ${r.modes
          .slice(0, 3)
          .map((/** @type {any} */ m) => `${fmt(m.freq_hz, 3)} Hz (ζ ${fmt(m.zeta, 2)})`)
          .join(
            ', ',
          )}; it flaps at 25 Hz, above the first. ${rep.test_samples} test samples per class, chance is 50 %.`,
        `With all ${n} sensors, encoded strain tells turning from still in ${pct(e.all_sensors)} of the test samples; raw strain in ${pct(w.all_sensors)}: a snapshot of the strain cannot show the rotation, the encoder's memory of the last few milliseconds can. Published (1326 sensors): ${pct(PUBLISHED.encoded)} and ${pct(PUBLISHED.raw)}.`,
        `One random sensor: ${one ? pct(one.mean) : '—'}; ten random sensors: ${ten ? `${pct(ten.mean)} ± ${fmt(100 * ten.sd, 2)}` : '—'} (published ${pct(PUBLISHED.random10)}). The best sparse set SSPOC chose with at most 15 sensors: ${sparse ? `${sparse.sensors.length} sensors, ${pct(sparse.accuracy)}` : '—'}.`,
      ];
      const checks = [
        {
          id: 'raw-cannot',
          label: `Raw strain classifies near chance (${pct(w.all_sensors)} ≤ 60 %)`,
          holds: w.all_sensors <= 0.6,
          value: w.all_sensors,
          expected: 0.6,
        },
        {
          id: 'encoding-can',
          label: `Encoding lifts all-sensor accuracy by at least 20 points (${pct(e.all_sensors)} vs ${pct(w.all_sensors)})`,
          holds: e.all_sensors >= w.all_sensors + 0.2,
          value: e.all_sensors,
          expected: w.all_sensors + 0.2,
        },
        {
          id: 'one-sensor-chance',
          label: `One random sensor is near chance (${one ? pct(one.mean) : '—'} ≤ 55 %)`,
          holds: !!one && one.mean <= 0.55,
          value: one ? one.mean : null,
          expected: 0.55,
        },
      ];
      return {
        lines,
        checks,
        values: {
          encoded_all: e.all_sensors,
          raw_all: w.all_sensors,
          random1: one ? one.mean : null,
          random10: ten ? ten.mean : null,
          sparse_best: sparse ? sparse.accuracy : null,
        },
      };
    },
  },
];
