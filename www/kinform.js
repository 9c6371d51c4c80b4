// @ts-check
// Pure helpers of the Kinematics panel (www/views/kinematics.js): the angles' names, the editor's
// Fourier form of a core Angle, the kinematics the hand editor makes (a measured table keeps its
// samples and gets the edits added on its own grid), the preview's vertical range and words, and
// the "in use" line. No DOM; unit-tested in tests/js/kinform.test.mjs.

export const ANGLES = /** @type {const} */ (['alpha', 'beta', 'gamma']);
export const SYM = Object.freeze({ alpha: 'α (roll)', beta: 'β (pitch)', gamma: 'γ (yaw)' });

/** @typedef {{ n: number, amplitude: number, phase: number }} Harmonic */
/** @typedef {{ mean: number, harmonics: Harmonic[] }} EditAngle */

/**
 * A Fourier angle for the editor: mean and harmonics (rad), from any core Angle (a sampled one
 * has no harmonics to edit: its mean offset only).
 * @param {any} a
 * @returns {EditAngle}
 */
export function fourierOf(a) {
  if (a && a.kind === 'fourier')
    return {
      mean: a.mean || 0,
      harmonics: (a.harmonics || []).map((h) => ({ n: h.n, amplitude: h.amplitude, phase: h.phase || 0 })),
    };
  return { mean: 0, harmonics: [] };
}

/**
 * The order of a harmonic added to `harmonics`: one above the highest there (1 when none).
 * @param {Harmonic[]} harmonics
 */
export function nextHarmonicOrder(harmonics) {
  return harmonics.reduce((m, h) => Math.max(m, h.n), 0) + 1;
}

/**
 * The core Kinematics the editor describes: per angle, a Fourier angle (mean and harmonics), or
 * for a measured table (`sampled[a]`) the table with the mean offset and the harmonics added on
 * its own grid t_j = j T / N, so the core's interpolant carries them.
 * @param {Record<string, EditAngle>} edit
 * @param {Record<string, any>} sampled
 * @param {number} flapHz
 */
export function editedKinematics(edit, sampled, flapHz) {
  /** @type {any} */
  const k = { flap_freq_hz: flapHz };
  for (const a of ANGLES) {
    if (sampled[a]) {
      const e = edit[a];
      const n = sampled[a].values.length;
      k[a] = {
        ...sampled[a],
        values: sampled[a].values.map(
          (v, j) =>
            v +
            e.mean +
            e.harmonics.reduce((acc, h) => acc + h.amplitude * Math.sin((2 * Math.PI * h.n * j) / n + h.phase), 0),
        ),
      };
    } else
      k[a] = {
        kind: 'fourier',
        mean: edit[a].mean,
        harmonics: edit[a].harmonics.map((h) => ({ n: h.n, amplitude: h.amplitude, phase: h.phase })),
      };
  }
  return k;
}

/**
 * The label of edited kinematics: "edited <the label in use>" (never "edited edited …"), or
 * "edited kinematics" when the sliders' were in use.
 * @param {{ label: string } | null | undefined} prev
 */
export function editedLabel(prev) {
  return prev ? `edited ${prev.label}`.replace(/^(edited )+/, 'edited ') : 'edited kinematics';
}

/**
 * The smallest and the largest value of `arr` ([Infinity, -Infinity] when empty).
 * @param {Iterable<number>} arr
 */
export function valueRange(arr) {
  let a = Infinity,
    b = -Infinity;
  for (const v of arr) {
    a = Math.min(a, v);
    b = Math.max(b, v);
  }
  return [a, b];
}

/**
 * The preview's vertical range: every angle of the interpolant `ang` and of the samples `samp`
 * (when given), widened to ±1 rad when flat, with 8 % of the range added on each side.
 * @param {Record<string, ArrayLike<number>>} ang
 * @param {Record<string, ArrayLike<number>> | null | undefined} samp
 */
export function previewBounds(ang, samp) {
  let lo = Infinity,
    hi = -Infinity;
  for (const src of samp ? [ang, samp] : [ang])
    for (const a of ANGLES) {
      const [mn, mx] = valueRange(Array.from(src[a]));
      lo = Math.min(lo, mn);
      hi = Math.max(hi, mx);
    }
  if (!(hi > lo)) {
    lo -= 1;
    hi += 1;
  }
  const pad = 0.08 * (hi - lo);
  return { lo: lo - pad, hi: hi + pad };
}

/**
 * The preview's text description: the period shown, each angle's range, the vertical range.
 * @param {number} flapHz
 * @param {Record<string, ArrayLike<number>>} ang
 * @param {boolean} withSamples
 * @param {{ lo: number, hi: number }} bounds
 * @param {(v: number, digits: number) => string} fmt
 */
export function previewWords(flapHz, ang, withSamples, bounds, fmt) {
  const T = 1 / flapHz;
  return (
    `One flap period (${fmt(T * 1e3, 4)} ms at ${fmt(flapHz, 4)} Hz) of the kinematics in use${withSamples ? ', measured samples as dots and the core’s periodic interpolant as lines' : ''}: ` +
    ANGLES.map((a) => {
      const [mn, mx] = valueRange(Array.from(ang[a]));
      return `${SYM[a]} from ${fmt(mn, 3)} to ${fmt(mx, 3)} rad`;
    }).join('; ') +
    `. Vertical range ${fmt(bounds.lo, 3)} to ${fmt(bounds.hi, 3)} rad.`
  );
}

/**
 * The "In use:" line: the sliders' kinematics, or the custom ones with where they came from.
 * @param {{ label: string, source: string, kinematics: { flap_freq_hz: number } } | null} k the store's `kin`
 * @param {(v: number, digits: number) => string} fmt
 */
export function inUseWords(k, fmt) {
  return !k
    ? 'In use: the sliders’ kinematics (first harmonics α0, β0, γ0 with their phases, at f_d).'
    : `In use: ${k.label} (${k.source === 'csv' ? 'measured table' : k.source === 'edited' ? 'edited by hand' : 'from the shared link'}, ${fmt(k.kinematics.flap_freq_hz, 4)} Hz). The Parameters panel’s amplitudes, phases and f_d do not apply; ζ and the duration do.`;
}
