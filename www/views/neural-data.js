// @ts-check
// The numbers of the "As a neuron sees it" panel (views/neural.js), from the wasm
// classifyRotation report (docs/sensing.md, "Classifying rotation"): the accuracy-against-sensors
// curves of one strain representation on a common x axis, the SSPOC sensor sets, and the rows
// of the comparison with the published study. Pure (no DOM); tests/js/neural_panel.test.mjs.
import { PUBLISHED, PUBLISHED_RANDOM, bestSparse, randomAt } from '../experiments/neural.js';

/**
 * @typedef {{ sensors: number, mean: number, sd: number, failed_fits: number }} RandomPoint
 * @typedef {{ kept_modes: number, sensors: number[], accuracy: number }} SparsePoint
 * @typedef {{ sensors: number[], d_prime: number, accuracy: number }} GreedyPoint
 * @typedef {{ all_sensors: number, sparse: SparsePoint[], random: RandomPoint[], greedy?: GreedyPoint[], s0: number }} Curves
 */

/** Which strain the panel shows: the encoder's output or the raw strain. */
export const STRAINS = Object.freeze([
  Object.freeze({ id: 'encoded', label: 'encoded, as a neuron fires' }),
  Object.freeze({ id: 'raw', label: 'raw strain' }),
]);

/**
 * The plot's columns for one representation: x the sensor counts that carry a point (random
 * sets, SSPOC sets, greedy d′ sets, the published random points), then per x the random mean,
 * mean ± sd, the SSPOC accuracy (the best set of that size), the all-sensor accuracy, the
 * published random mean (encoded only) and the greedy d′ set's accuracy; null where a series
 * has no point. Accuracies in %.
 * @param {Curves} c
 * @param {boolean} published whether the published points belong (encoded strain)
 * @returns {(number | null)[][]}
 */
export function curveColumns(c, published) {
  const xs = new Set();
  for (const r of c.random) xs.add(r.sensors);
  for (const s of c.sparse) xs.add(s.sensors.length);
  for (const g of c.greedy || []) xs.add(g.sensors.length);
  if (published) for (const p of PUBLISHED_RANDOM) xs.add(p.sensors);
  const x = [...xs].filter((v) => v >= 1).sort((a, b) => a - b);
  const pct = (/** @type {number} */ v) => Math.round(1e4 * v) / 100;
  const col = (/** @type {(n: number) => number | null} */ f) => x.map(f);
  /** @param {(r: RandomPoint) => number} f */
  const rndCol = (f) =>
    col((n) => {
      const r = c.random.find((q) => q.sensors === n);
      return r ? pct(f(r)) : null;
    });
  const sparseAt = (/** @type {number} */ n) => {
    /** @type {number | null} */
    let best = null;
    for (const s of c.sparse) if (s.sensors.length === n && (best === null || s.accuracy > best)) best = s.accuracy;
    return best === null ? null : pct(best);
  };
  return [
    x,
    rndCol((r) => r.mean),
    rndCol((r) => Math.min(1, r.mean + r.sd)),
    rndCol((r) => Math.max(0, r.mean - r.sd)),
    col(sparseAt),
    col(() => pct(c.all_sensors)),
    col((n) => {
      const p = published ? PUBLISHED_RANDOM.find((q) => q.sensors === n) : null;
      return p ? pct(p.mean) : null;
    }),
    col((n) => {
      const g = (c.greedy || []).find((q) => q.sensors.length === n);
      return g ? pct(g.accuracy) : null;
    }),
  ];
}

/**
 * The sensor sets the panel's chooser lists: SSPOC's, one per kept-mode count, then the
 * greedy d′ sets, one per size. `value` is "sspoc:<i>" or "greedy:<i>".
 * @param {Curves} c
 */
export function setChoices(c) {
  const n = (/** @type {number} */ k) => `${k} sensor${k === 1 ? '' : 's'}`;
  return [
    ...c.sparse.map((s, i) => ({
      value: `sspoc:${i}`,
      text: `SSPOC, ${s.kept_modes} modes kept: ${n(s.sensors.length)}, ${fmtPct(s.accuracy)}`,
    })),
    ...(c.greedy || []).map((g, i) => ({
      value: `greedy:${i}`,
      text: `greedy d′: ${n(g.sensors.length)}, ${fmtPct(g.accuracy)}`,
    })),
  ];
}

/**
 * The set a chooser value names, or null.
 * @param {Curves} c
 * @param {string} value
 * @returns {{ sensors: number[], accuracy: number } | null}
 */
export function setOf(c, value) {
  const [kind, i] = value.split(':');
  const list = kind === 'greedy' ? c.greedy || [] : kind === 'sspoc' ? c.sparse : [];
  return list[Number(i)] || null;
}

/**
 * @param {Curves} c
 * @param {number} k
 */
function greedyCell(c, k) {
  const g = (c.greedy || []).find((q) => q.sensors.length === k);
  return g ? fmtPct(g.accuracy) : '—';
}

/** @param {number} v a fraction */
export function fmtPct(v) {
  return `${(100 * v).toFixed(1)} %`;
}

/**
 * The comparison table: [what, encoded here, raw here, published] (published: encoded unless
 * said). `n` is the number of sensors of the run.
 * @param {{ encoded: Curves, raw: Curves, sensors: number[][] }} rep
 * @returns {string[][]}
 */
export function comparisonRows(rep) {
  const n = rep.sensors.length;
  const cell = (/** @type {any} */ p, /** @type {'mean' | 'accuracy'} */ k) => (p ? fmtPct(p[k]) : '—');
  const rnd = (/** @type {number} */ k) => [
    `${k} random sensor${k === 1 ? '' : 's'} (mean)`,
    cell(randomAt(rep.encoded, k), 'mean'),
    cell(randomAt(rep.raw, k), 'mean'),
  ];
  const best = bestSparse(rep.encoded, 15);
  const bestRaw = bestSparse(rep.raw, 15);
  const pub10 = PUBLISHED_RANDOM.find((p) => p.sensors === 10);
  const pub30 = PUBLISHED_RANDOM.find((p) => p.sensors === 30);
  return [
    [
      `all ${n} sensors`,
      fmtPct(rep.encoded.all_sensors),
      fmtPct(rep.raw.all_sensors),
      `${fmtPct(PUBLISHED.encoded)} encoded, ${fmtPct(PUBLISHED.raw)} raw (1326 sensors)`,
    ],
    [...rnd(1), '50 % (chance)'],
    [...rnd(10), pub10 ? fmtPct(pub10.mean) : '—'],
    [...rnd(30), pub30 ? fmtPct(pub30.mean) : '—'],
    ['greedy d′ set of 10 sensors', greedyCell(rep.encoded, 10), greedyCell(rep.raw, 10), '—'],
    [
      'best SSPOC set of at most 15 sensors',
      best ? `${fmtPct(best.accuracy)} (${best.sensors.length} sensors)` : '—',
      bestRaw ? `${fmtPct(bestRaw.accuracy)} (${bestRaw.sensors.length} sensors)` : '—',
      'about 85 % with 7–13 sensors',
    ],
  ];
}

/**
 * Where a sensor set sits on the plate, in words for a screen reader: "12 sensors; nearest the
 * root at x = 2 mm, farthest at x = 50 mm; 5 within 10 mm of the root".
 * @param {number[]} idx sensor indices
 * @param {number[][]} positions every sensor's [x, y] in mm
 */
export function sensorWords(idx, positions) {
  if (!idx.length) return 'no sensors';
  const xs = idx.map((i) => positions[i][0]);
  const near = xs.filter((x) => x <= 10).length;
  return `${idx.length} sensor${idx.length === 1 ? '' : 's'}; nearest the root at x = ${Math.min(...xs)} mm, farthest at x = ${Math.max(...xs)} mm; ${near} within 10 mm of the root`;
}

/**
 * What the plot shows, in words computed from the report: the all-sensor accuracy, and for
 * encoded strain the best SSPOC set of at most 15 sensors against random sets of about its
 * size (the nearest random size) and against all sensors.
 * @param {{ encoded: Curves, raw: Curves, sensors: number[][] }} rep
 * @param {string} which 'encoded' or 'raw'
 */
export function neuralWords(rep, which) {
  const n = rep.sensors.length;
  const c = which === 'raw' ? rep.raw : rep.encoded;
  if (which === 'raw')
    return `Raw strain: ${fmtPct(c.all_sensors)} with all ${n} sensors — chance. At one instant, the strain of a turning plate and a still one look alike; the neuron’s memory of the last milliseconds is what tells them apart.`;
  const head = `Encoded, all ${n} sensors tell turning from still in ${fmtPct(c.all_sensors)} of the test samples; random sets climb with their size.`;
  const best = bestSparse(c, 15);
  if (!best || !c.random.length) return head;
  const k = best.sensors.length;
  const near = c.random.reduce((a, r) => (Math.abs(r.sensors - k) < Math.abs(a.sensors - k) ? r : a));
  const vsRandom =
    best.accuracy > near.mean + near.sd
      ? 'better than'
      : best.accuracy < near.mean - near.sd
        ? 'worse than'
        : 'within one sd of';
  const tail =
    best.accuracy >= c.all_sensors - 0.02
      ? ' and as well as all sensors, as in the paper.'
      : ', but falls short of all sensors, where in the paper about 10 SSPOC sensors came close to them (docs/sensing.md says what we know of why).';
  return `${head} The best SSPOC set of at most 15 sensors (${k} sensors, ${fmtPct(best.accuracy)}) does ${vsRandom} random sets of ${near.sensors} (${fmtPct(near.mean)})${tail}`;
}
