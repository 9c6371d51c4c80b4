// @ts-check
// Min/max decimation of several series onto a shared x grid: the one implementation, used by
// the plots (www/plot.js, views) and by the worker (www/worker.js). Pure; unit-tested in
// tests/js/decimate.test.mjs.
//
// Each bucket contributes two x positions (its start and its middle) and, for every series,
// its min and max there, in the order they occur, so peaks survive and the series stay aligned.
// Series no longer than 2·buckets are copied unchanged. Always returns Float64Arrays.

/**
 * @param {ArrayLike<number>} x
 * @param {ArrayLike<number>[]} ys
 * @param {number} buckets
 * @returns {Float64Array[]} [x, ...ys]
 */
export function decimate(x, ys, buckets) {
  const n = x.length;
  const b = Math.max(1, Math.floor(buckets));
  if (n <= 2 * b) return [Float64Array.from(x), ...ys.map((y) => Float64Array.from(y))];
  const xo = new Float64Array(2 * b);
  const yo = ys.map(() => new Float64Array(2 * b));
  for (let j = 0; j < b; j++) {
    const lo = Math.floor((j * n) / b);
    const hi = Math.max(lo + 1, Math.floor(((j + 1) * n) / b));
    xo[2 * j] = x[lo];
    xo[2 * j + 1] = x[Math.min(n - 1, (lo + hi) >> 1)];
    for (let k = 0; k < ys.length; k++) {
      const y = ys[k];
      let mn = y[lo],
        mx = y[lo],
        imn = lo,
        imx = lo;
      for (let i = lo + 1; i < hi; i++) {
        const v = y[i];
        if (v < mn) {
          mn = v;
          imn = i;
        }
        if (v > mx) {
          mx = v;
          imx = i;
        }
      }
      yo[k][2 * j] = imn <= imx ? mn : mx;
      yo[k][2 * j + 1] = imn <= imx ? mx : mn;
    }
  }
  return [xo, ...yo];
}
