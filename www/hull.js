// @ts-check
// The convex hull of 2-D points (pure, no DOM): the stroke fit uses it for the planform's outline
// (www/scene3d.js) and the run-wide ranges for the modal trajectory (www/strainmap.js).

/**
 * Convex hull (monotone chain) of 2-D points given as two arrays; returns vertex indices.
 * Points strictly inside the polygon of the 16 directional extremes are dropped first
 * (Akl–Toussaint), so long trajectories sort only their outer points.
 */
export function hull2(xs, ys) {
  const n = xs.length;
  /** @type {number[] | null} */
  let cand = null;
  if (n > 64) {
    /** @type {number[]} */
    const ext = [];
    for (let d = 0; d < 16; d++) {
      const c = Math.cos((Math.PI * d) / 8),
        sn = Math.sin((Math.PI * d) / 8);
      let best = 0,
        bv = -Infinity;
      for (let i = 0; i < n; i++) {
        const v = c * xs[i] + sn * ys[i];
        if (v > bv) {
          bv = v;
          best = i;
        }
      }
      if (ext[ext.length - 1] !== best && ext[0] !== best) ext.push(best);
    }
    // ext is in angular order (counter-clockwise); keep points not strictly inside it
    if (ext.length >= 3) {
      /** @type {number[]} */
      const kept = [];
      cand = kept;
      const m = ext.length;
      for (let i = 0; i < n; i++) {
        let inside = true;
        for (let j = 0; j < m; j++) {
          const a = ext[j],
            b = ext[(j + 1) % m];
          if ((xs[b] - xs[a]) * (ys[i] - ys[a]) - (ys[b] - ys[a]) * (xs[i] - xs[a]) <= 0) {
            inside = false;
            break;
          }
        }
        if (!inside) kept.push(i);
      }
    }
  }
  const idx = (cand || Array.from({ length: n }, (_, i) => i)).sort((a, b) => xs[a] - xs[b] || ys[a] - ys[b]);
  const cross = (o, a, b) => (xs[a] - xs[o]) * (ys[b] - ys[o]) - (ys[a] - ys[o]) * (xs[b] - xs[o]);
  const lower = [],
    upper = [];
  for (const i of idx) {
    while (lower.length >= 2 && cross(lower[lower.length - 2], lower[lower.length - 1], i) <= 0) lower.pop();
    lower.push(i);
  }
  for (let j = idx.length - 1; j >= 0; j--) {
    const i = idx[j];
    while (upper.length >= 2 && cross(upper[upper.length - 2], upper[upper.length - 1], i) <= 0) upper.pop();
    upper.push(i);
  }
  upper.pop();
  lower.pop();
  const h = lower.concat(upper);
  return h.length ? h : idx.length ? [idx[0]] : n ? [0] : [];
}
