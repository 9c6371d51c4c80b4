// @ts-check
// The beat, made explicit (pure; unit-tested in tests/js/beat.test.mjs): the Floquet beat of
// the selected mode, T_beat = 1 / |f_eff − n·f_d| with the harmonic n nearest f_eff, the
// default window of the responses plot (about three beats, starting on an envelope maximum),
// and the force-term shares. All numbers come from the analysis; nothing is canned.

/** @typedef {import('./pkg/wingbeat.js').Analysis} Analysis */

/**
 * @typedef {{ fEff: number, n: number, fd: number, fHarm: number | null, diff: number | null,
 *   period: number | null, stable: boolean, maxModulus: number, fk: number }} BeatInfo
 */

/**
 * The beat of mode k of an analysis. `period` is the Floquet `beat_period_s` itself (null when
 * there is no beat).
 * @param {Analysis} a
 * @param {number} k
 * @returns {BeatInfo}
 */
export function beatInfo(a, k) {
  const m = a.sim.modes[k];
  const f = m.floquet;
  const fd = a.sim.flap_freq_hz;
  const n = f.beat_harmonic;
  const fEff = f.effective_freq_hz;
  const period = f.beat_period_s == null || !Number.isFinite(f.beat_period_s) ? null : f.beat_period_s;
  const fHarm = n == null ? null : n * fd;
  const diff = fHarm == null ? null : Math.abs(fEff - fHarm);
  return { fEff, n, fd, fHarm, diff, period, stable: f.stable, maxModulus: f.max_modulus, fk: m.freq_hz };
}

/**
 * Index of the largest value of y on [i0, i1).
 * @param {ArrayLike<number>} y
 * @param {number} i0
 * @param {number} i1
 */
function argmax(y, i0, i1) {
  let best = Math.max(0, i0);
  for (let i = best + 1; i < Math.min(y.length, i1); i++) if (y[i] > y[best]) best = i;
  return best;
}

/**
 * The responses plot's opening window: [x0, x1] spanning about three beats, and the marked
 * beat [tA, tB] with tB = tA + T_beat, tA an envelope maximum after the first beat. Without a
 * beat (or when three beats do not fit) the whole run. `measured` is the time from tA to the
 * next envelope maximum (≈ T_beat).
 * @param {ArrayLike<number>} t
 * @param {ArrayLike<number> | null} env
 * @param {number | null} period
 * @param {{ beats?: number }} [o]
 * @returns {{ x0: number, x1: number, mark: [number, number] | null, measured: number | null }}
 */
export function beatWindow(t, env, period, { beats = 3 } = {}) {
  const n = t.length;
  const t0 = t[0],
    t1 = t[n - 1];
  const dur = t1 - t0;
  if (!period || !(period > 0) || period * (beats + 1) > dur || !env || env.length !== n) {
    return { x0: t0, x1: t1, mark: null, measured: null };
  }
  const dt = dur / (n - 1);
  const idx = (/** @type {number} */ tt) => Math.round((tt - t0) / dt);
  // The envelope maximum within the second beat: the beat has built up, and a full window follows.
  const a = argmax(env, idx(t0 + period), idx(t0 + 2 * period));
  const tA = t[a];
  const b = argmax(env, idx(tA + 0.5 * period), idx(tA + 1.5 * period));
  const x0 = Math.max(t0, tA - 0.5 * period);
  const x1 = Math.min(t1, x0 + beats * period);
  return { x0, x1, mark: [tA, tA + period], measured: t[b] - tA };
}

/**
 * Force-term shares (paper §4.1) of mode k: [{ key, label, value }].
 * @param {Analysis} a
 * @param {number} k
 */
export function shares(a, k) {
  const c = a.sim.modes[k].contribution_percent;
  return [
    { key: 'euler', label: 'Euler', value: c.euler },
    { key: 'centrifugal', label: 'Centrifugal', value: c.centrifugal },
    { key: 'coriolis', label: 'Coriolis', value: c.coriolis },
  ];
}

/**
 * A display envelope: `env` averaged over a sliding window of `width` samples (one flap
 * period), centred, so the ripple at the flap frequency and its harmonics cancels and the
 * beat's swell and fade remain. The raw envelope stays what the CSV exports.
 * @param {ArrayLike<number>} env
 * @param {number} width
 */
export function smooth(env, width) {
  const n = env.length;
  const w = Math.max(1, Math.round(width));
  if (w <= 1 || n === 0) return Float64Array.from(env);
  const c = new Float64Array(n + 1);
  for (let i = 0; i < n; i++) c[i + 1] = c[i] + env[i];
  const out = new Float64Array(n);
  const h = Math.floor(w / 2);
  for (let i = 0; i < n; i++) {
    const a = Math.max(0, i - h),
      b = Math.min(n, i - h + w);
    out[i] = (c[b] - c[a]) / (b - a);
  }
  return out;
}

/**
 * @typedef {{ kind: 'none' | 'steady' | 'decays' | 'gone', tau: number | null, goneAt: number | null, floor: number }} BeatFate
 */

/**
 * What becomes of the beat over a run of `duration` s. The beat is the free vibration (at
 * f_eff) drifting against the forced one; with damping the free vibration decays as
 * exp(−t/τ), τ = −1/σ from the Floquet growth rate σ (−ζω for a damped mode), and the beat's
 * swing with it. `goneAt` = τ·ln(1/floor) is when that swing is down to `floor` (5 %: 3.0 τ) of
 * its start. Kinds: `none` (no beat period), `steady` (undamped, unstable, or τ too long for the
 * beat to fade within the run), `decays` (it fades within the run, after at least one beat),
 * `gone` (it fades within one beat period: nothing to see).
 * @param {BeatInfo} info
 * @param {number} growthRate Floquet growth rate σ of the mode, 1/s
 * @param {number} duration s
 * @param {{ floor?: number }} [o]
 * @returns {BeatFate}
 */
export function beatFate(info, growthRate, duration, { floor = 0.05 } = {}) {
  if (info.period == null) return { kind: 'none', tau: null, goneAt: null, floor };
  if (!info.stable || !(growthRate < 0) || !Number.isFinite(growthRate))
    return { kind: 'steady', tau: null, goneAt: null, floor };
  const tau = -1 / growthRate;
  const goneAt = tau * Math.log(1 / floor);
  if (goneAt <= info.period) return { kind: 'gone', tau, goneAt, floor };
  if (goneAt < duration) return { kind: 'decays', tau, goneAt, floor };
  return { kind: 'steady', tau, goneAt, floor };
}

/**
 * The swing of an envelope between times a and b (s): modulation index (max − min)/(max + min)
 * of `env` (already averaged over a flap) sampled at `t`; 0 for an empty window.
 * @param {ArrayLike<number>} t
 * @param {ArrayLike<number>} env
 * @param {number} a
 * @param {number} b
 */
export function modulation(t, env, a, b) {
  let mx = -Infinity,
    mn = Infinity;
  for (let i = 0; i < t.length; i++) {
    if (t[i] < a || t[i] > b) continue;
    if (env[i] > mx) mx = env[i];
    if (env[i] < mn) mn = env[i];
  }
  return mx + mn > 0 && Number.isFinite(mx) ? (mx - mn) / (mx + mn) : 0;
}
