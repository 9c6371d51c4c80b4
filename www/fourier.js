// @ts-check
// The Fourier series of a sampled periodic angle, in JavaScript: the same direct DFT as the core's
// (src/kinematics.rs `Angle::series`: mean, then sine and cosine coefficients of harmonics 1…H,
// H = min(N/2, max_harmonic ?? DEFAULT_SAMPLED_MAX_HARMONIC), the Nyquist term at half weight),
// and its inverse on N points. The one JS copy, used by the share links (www/share.js), which
// store a measured stroke as its series. Why a copy: share links are encoded and decoded by pure
// JS — decoded when the page opens, before the wasm has loaded, and unit-tested without it — and
// the core does not export the series by itself. tests/js/fourier.test.mjs holds it to the core's
// numbers (the angles the real wasm evaluates from a sampled table, to 1e-12 rad).

/** The core's default harmonic cap for sampled angles (src/kinematics.rs DEFAULT_SAMPLED_MAX_HARMONIC;
 * tests/js/wasm.test.mjs checks it against wasm limits().default_sampled_max_harmonic). */
export const DEFAULT_SAMPLED_MAX_HARMONIC = 24;

/**
 * The Fourier series the core makes of N samples over one period (src/kinematics.rs
 * `Angle::series`): [mean, s1, c1, …, sH, cH] with H = min(N/2, maxHarmonic ??
 * DEFAULT_SAMPLED_MAX_HARMONIC).
 * @param {ArrayLike<number>} values
 * @param {number | null | undefined} maxHarmonic
 */
export function sampledSeries(values, maxHarmonic) {
  const n = values.length;
  let mean = 0;
  for (let j = 0; j < n; j++) mean += values[j];
  mean /= n;
  const hmax = Math.min(Math.floor(n / 2), maxHarmonic ?? DEFAULT_SAMPLED_MAX_HARMONIC);
  const out = [mean];
  for (let h = 1; h <= hmax; h++) {
    let cs = 0,
      sn = 0;
    for (let j = 0; j < n; j++) {
      const th = (2 * Math.PI * ((h * j) % n)) / n;
      cs += values[j] * Math.cos(th);
      sn += values[j] * Math.sin(th);
    }
    const w = n % 2 === 0 && h === n / 2 ? 1 / n : 2 / n;
    out.push(w * sn, w * cs);
  }
  return out;
}

/**
 * N samples over one period of the series [mean, s1, c1, …] (t_j = j T / N).
 * @param {number[]} series
 * @param {number} n
 */
export function seriesSamples(series, n) {
  const hmax = (series.length - 1) / 2;
  const out = new Array(n);
  for (let j = 0; j < n; j++) {
    let v = series[0];
    for (let h = 1; h <= hmax; h++) {
      const th = (2 * Math.PI * ((h * j) % n)) / n;
      v += series[2 * h - 1] * Math.sin(th) + series[2 * h] * Math.cos(th);
    }
    out[j] = v;
  }
  return out;
}
