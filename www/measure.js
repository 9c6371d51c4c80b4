// @ts-check
// Measurements on sampled responses, as the guided experiments (www/experiments.js) check their
// predictions with them: the peak |x|, a centred moving average, a beat's period and modulation
// from an envelope (like the core's analysis::beat), and a response's growth rate per second.
// Pure (no DOM); unit-tested in tests/js/experiments.test.mjs and tests/js/measure.test.mjs.

/** The largest |x[i]| (0 for an empty series). */
export function peakAbs(x) {
  let m = 0;
  for (let i = 0; i < x.length; i++) {
    const v = Math.abs(x[i]);
    if (v > m) m = v;
  }
  return m;
}

/** Centred moving average over `w` samples (shrinks at the ends), like analysis::beat. */
export function movingAverage(x, w) {
  const n = x.length;
  w = Math.max(1, w | 0);
  const pre = new Float64Array(n + 1);
  for (let i = 0; i < n; i++) pre[i + 1] = pre[i] + x[i];
  const out = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    const lo = Math.max(0, i - (w >> 1));
    const hi = Math.min(n, i + w - (w >> 1));
    out[i] = (pre[hi] - pre[lo]) / (hi - lo);
  }
  return out;
}

/**
 * Measures a beat from an envelope sampled at `fs` Hz, between fractions `from`…`to` of its
 * length, the way the core's `analysis::beat::measure` does: flap-average the envelope (one
 * flap period), then modulation index (max − min)/(max + min) over the window, kept one flap
 * period clear of the ends. The period is the mean spacing of upward crossings of the window's
 * mean (linear interpolation, hysteresis of 10 % of the swing), or null when fewer than two.
 */
export function measureBeat(env, fs, flapHz, from = 0, to = 1) {
  const n = env.length;
  const per = Math.max(1, Math.round(fs / flapHz));
  const avg = movingAverage(env, per);
  const a = Math.max(per, Math.floor(from * n));
  const b = Math.min(n - per, Math.floor(to * n));
  if (b <= a + 2) return { modulation_index: 0, period_s: null, crossings: 0 };
  let mx = -Infinity;
  let mn = Infinity;
  let sum = 0;
  for (let i = a; i < b; i++) {
    const v = avg[i];
    if (v > mx) mx = v;
    if (v < mn) mn = v;
    sum += v;
  }
  const modulation_index = mx + mn > 0 ? (mx - mn) / (mx + mn) : 0;
  const mean = sum / (b - a);
  const hyst = 0.1 * (mx - mn);
  const ups = [];
  let armed = false;
  for (let i = a + 1; i < b; i++) {
    if (avg[i] < mean - hyst) armed = true;
    if (armed && avg[i - 1] < mean && avg[i] >= mean) {
      const f = (mean - avg[i - 1]) / (avg[i] - avg[i - 1]);
      ups.push((i - 1 + f) / fs);
      armed = false;
    }
  }
  const period_s =
    ups.length >= 2 && mx - mn > 1e-12 * Math.max(Math.abs(mx), 1e-300)
      ? (ups[ups.length - 1] - ups[0]) / (ups.length - 1)
      : null;
  return { modulation_index, period_s, crossings: ups.length };
}

/**
 * Growth rate (1/s) of a response: least-squares slope of ln(peak |x|) per flap period over
 * fractions `from`…`to` of the run. A Floquet multiplier λ gives ln|λ|·f_d.
 */
export function growthRate(x, fs, flapHz, from = 0.5, to = 1) {
  const per = Math.max(2, Math.round(fs / flapHz));
  const n = x.length;
  const ts = [];
  const ls = [];
  for (let s = Math.floor(from * n); s + per <= Math.floor(to * n); s += per) {
    let m = 0;
    for (let i = s; i < s + per; i++) m = Math.max(m, Math.abs(x[i]));
    if (m > 0) {
      ts.push((s + per / 2) / fs);
      ls.push(Math.log(m));
    }
  }
  if (ts.length < 3) return null;
  const tm = ts.reduce((p, v) => p + v, 0) / ts.length;
  const lm = ls.reduce((p, v) => p + v, 0) / ls.length;
  let num = 0;
  let den = 0;
  for (let i = 0; i < ts.length; i++) {
    num += (ts[i] - tm) * (ls[i] - lm);
    den += (ts[i] - tm) ** 2;
  }
  return num / den;
}
