// @ts-check
// The keyboard of a focused line plot (www/plot.js): ← → pan by a quarter of the window, + (or =)
// zooms in to its middle half, − (or _) out to twice its span, 0 (or Home) goes back. Pure.

/**
 * The x window after key `key` on a plot showing [min, max] of data spanning [lo, hi]: the new
 * window (never wider than the data, shifted back inside it), 'reset' for 0 or Home, or null
 * for a key the plot does not use.
 * @param {string} key a KeyboardEvent's key
 * @param {number} min
 * @param {number} max
 * @param {number} lo
 * @param {number} hi
 * @returns {[number, number] | 'reset' | null}
 */
export function keyWindow(key, min, max, lo, hi) {
  const span = max - min;
  /** @type {number[]} */
  let a;
  if (key === 'ArrowLeft') a = [min - 0.25 * span, max - 0.25 * span];
  else if (key === 'ArrowRight') a = [min + 0.25 * span, max + 0.25 * span];
  else if (key === '+' || key === '=') a = [min + 0.25 * span, max - 0.25 * span];
  else if (key === '-' || key === '_') a = [min - 0.5 * span, max + 0.5 * span];
  else if (key === '0' || key === 'Home') return 'reset';
  else return null;
  let [m0, m1] = a;
  const w = Math.min(m1 - m0, hi - lo);
  if (m0 < lo) {
    m0 = lo;
    m1 = lo + w;
  }
  if (m1 > hi) {
    m1 = hi;
    m0 = hi - w;
  }
  return [m0, m1];
}
