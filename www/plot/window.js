// @ts-check
// A line plot's x window (www/plot.js and the panels that move it): kept inside the data, and
// moved by the keyboard of a focused plot: ← → pan by a quarter of the window, + (or =) zooms in
// to its middle half, − (or _) out to twice its span, 0 (or Home) goes back. Pure.

/**
 * The window [a, b] kept inside the data [lo, hi]: never wider than the data, and shifted back
 * inside it (its width kept) where it sticks out.
 * @param {number[]} w [a, b]
 * @param {number} lo
 * @param {number} hi
 * @returns {[number, number]}
 */
export function clampWindow([a, b], lo, hi) {
  const span = Math.min(b - a, hi - lo);
  if (a < lo) {
    a = lo;
    b = lo + span;
  }
  if (b > hi) {
    b = hi;
    a = hi - span;
  }
  return [a, b];
}

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
  return clampWindow(a, lo, hi);
}
