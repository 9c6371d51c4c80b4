// @ts-check
// What the responses plots (views/time.js) mark: the beat period shaded from an envelope maximum
// to the next, its repeats as dotted lines, and the grey band where a damped beat has died out.
// Pure; unit-tested in tests/js/time_marks.test.mjs.
import { fmt } from '../format.js';

/** @typedef {import('../plot.js').Band} Band */

const decaying = (/** @type {import('../beat.js').BeatFate | null} */ fate) => !!fate && fate.kind === 'decays';

/**
 * The shaded beat [mark0, mark1] labelled with its period (and "decaying" for a damped beat).
 * @param {number[]} mark [start, end] of the beat marked (s)
 * @param {number | null} period T_beat (s)
 * @param {import('../beat.js').BeatFate | null} fate
 * @returns {Band}
 */
export function beatBand(mark, period, fate) {
  return {
    x0: mark[0],
    x1: mark[1],
    label: `T_{beat} = ${fmt(period, 4)} s${decaying(fate) ? ' (decaying)' : ''}`,
    color: '#7a3cc2',
    fill: 'rgba(122,60,194,0.12)',
  };
}

/**
 * The grey band from where a decaying beat is gone to the end of the run `tEnd`; none for a beat
 * that does not decay away, or without a run (tEnd null).
 * @param {import('../beat.js').BeatFate | null} fate
 * @param {number | null} tEnd
 * @returns {Band[]}
 */
export function goneBands(fate, tEnd) {
  if (!fate || fate.kind !== 'decays' || fate.goneAt == null || tEnd == null) return [];
  return [
    {
      x0: fate.goneAt,
      x1: tEnd,
      label: `beat gone (< ${fmt(100 * fate.floor, 2)} %)`,
      color: '#555',
      fill: 'rgba(90,90,90,0.13)',
    },
  ];
}

/**
 * Where the beat marked from `mark0` repeats (mark0 + j·period, |j| ≤ 40, the marked beat's own
 * two ends left out) inside the window [x0, x1], up to where a decaying beat is gone.
 * @param {number} mark0
 * @param {number} period
 * @param {number | null | undefined} x0
 * @param {number | null | undefined} x1
 * @param {import('../beat.js').BeatFate | null} fate
 * @returns {number[]}
 */
export function beatRepeats(mark0, period, x0, x1, fate) {
  const out = [];
  for (let j = -40; j <= 40; j++) {
    const x = mark0 + j * period;
    const alive = !fate || fate.kind !== 'decays' || fate.goneAt == null || x <= fate.goneAt;
    if (j !== 0 && j !== 1 && alive && x0 != null && x1 != null && x >= x0 && x <= x1) out.push(x);
  }
  return out;
}
