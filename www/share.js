// @ts-check
// Large shared state in the URL fragment: `#s=<base64url(deflate-raw(JSON))>`. Short state (the
// sliders, the wing parameters, the built-in outline id) stays in the query (www/state.js); only
// what does not fit there comes here: an edited outline, a kinematics table, a strain point.
//
// Versions (the JSON's `v`; every version ever written stays readable):
//   v1  { v: 1, outline: [[x_mm, y_mm], …], outline_label, kin: { label, kinematics, csv }, strain_point }
//       (plain JSON numbers; written until 2026-11).
//   v2  { v: 2, o: { u, d }, ol, k: { l, f, a, b, g, c? }, p }  (written now; compact):
//       o  the outline as integers in units of 10^-u mm (u = OUTLINE_DECIMALS = 4), the first point
//          then the difference of each point from the one before: d = [x0, y0, dx1, dy1, …];
//       k  the kinematics: l label, f flap frequency (exact), a/b/g the three angles. A Fourier
//          angle is stored as it is (exact). A sampled angle is stored as the Fourier series the
//          core makes of it (src/kinematics.rs: the DFT of the N samples, truncated at
//          H = min(N/2, max_harmonic ?? 24)): { s: [N, H, e], c: [mean, s1, c1, …, sH, cH] } with
//          each coefficient an integer in units of 10^-e rad; it is read back as N samples of that
//          series with max_harmonic H, which give the core the same series (to the rounding).
//          c the CSV the table came from (only when the link stays short enough with it).
//       p  the strain point [x_mm, y_mm] (exact).
// decodeShare returns the v1 shape whatever version it read (`v` says which), so callers need
// not know the versions. shareLink picks the finest rounding that keeps the whole link within
// MAX_LINK characters, and says so plainly when even the coarsest does not fit.
// A sampled angle's series is the one DFT of www/fourier.js (the core's, see there).
// Uses the browser's CompressionStream / DecompressionStream (also in node ≥ 18). Pure apart
// from those streams; unit-tested in tests/js/share.test.mjs.

import { sampledSeries, seriesSamples } from './fourier.js';

/** The fragment version this lab writes. */
export const SHARE_VERSION = 2;
/** The fragment versions this lab reads. */
export const SHARE_VERSIONS_READ = [1, 2];
/** Longest fragment read (characters) and longest JSON accepted after inflating (bytes). */
export const MAX_FRAGMENT = 200000;
export const MAX_JSON = 2000000;
/** Longest link (whole URL) the lab writes without a warning: what e-mail, chat and LMS keep. */
export const MAX_LINK = 2000;
/** Outline points are stored in units of 10^-4 mm (0.1 µm; the built-in outlines' resolution). */
export const OUTLINE_DECIMALS = 4;
/** Decimals (of rad) tried for a sampled angle's Fourier coefficients, finest first. */
export const ANGLE_DECIMALS = [6, 5, 4];
const MAX_SAMPLES = 100000;
const MAX_HARMONIC = 256;
/** Short keys of v2; a state passed to encodeShare must not use them for anything else. */
const V2_KEYS = ['o', 'ol', 'k', 'p'];

/** @param {Uint8Array} bytes */
function toBase64url(bytes) {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(s).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

/** @param {string} text */
function fromBase64url(text) {
  if (!/^[A-Za-z0-9_-]*$/.test(text)) throw new Error('the share fragment is not base64url text');
  const b64 = text.replace(/-/g, '+').replace(/_/g, '/') + '==='.slice((text.length + 3) % 4);
  const bin = atob(b64);
  const out = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
  return out;
}

/**
 * @param {Uint8Array} bytes
 * @param {CompressionStream | DecompressionStream} stream
 */
async function pipe(bytes, stream, limit = Infinity) {
  const body = new Blob([/** @type {BlobPart} */ (bytes)]).stream().pipeThrough(stream);
  const reader = body.getReader();
  /** @type {Uint8Array[]} */
  const parts = [];
  let n = 0;
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    n += value.length;
    if (n > limit) {
      await reader.cancel();
      throw new Error(`the shared state is larger than ${limit} bytes`);
    }
    parts.push(value);
  }
  const out = new Uint8Array(n);
  let o = 0;
  for (const p of parts) {
    out.set(p, o);
    o += p.length;
  }
  return out;
}

// ---------- v2 packing (pure) ----------

/** @param {unknown} v */
const isObj = (v) => !!v && typeof v === 'object' && !Array.isArray(v);

/**
 * An outline as delta-coded integers of 10^-u mm, or null when a value is too large for exact
 * integers (then the plain points are stored).
 * @param {[number, number][]} pts
 */
export function packOutline(pts, u = OUTLINE_DECIMALS) {
  const k = 10 ** u;
  /** @type {number[]} */
  const d = [];
  let px = 0,
    py = 0;
  for (const p of pts) {
    const x = Math.round(p[0] * k),
      y = Math.round(p[1] * k);
    if (!Number.isSafeInteger(x) || !Number.isSafeInteger(y) || Math.abs(x) > 2 ** 48 || Math.abs(y) > 2 ** 48)
      return null;
    d.push(x - px, y - py);
    px = x;
    py = y;
  }
  return { u, d };
}

/**
 * @param {unknown} o
 * @returns {[number, number][]}
 */
export function unpackOutline(o) {
  if (!isObj(o)) throw new Error('o: expected { u, d }');
  const { u, d } = /** @type {{ u: unknown, d: unknown }} */ (o);
  if (!Number.isInteger(u) || /** @type {number} */ (u) < 0 || /** @type {number} */ (u) > 9)
    throw new Error('o.u: expected an integer 0 to 9');
  if (!Array.isArray(d) || d.length % 2 || d.length < 6 || d.length > 4000)
    throw new Error('o.d: expected 3 to 2000 points as integer pairs');
  const k = 10 ** /** @type {number} */ (u);
  /** @type {[number, number][]} */
  const pts = [];
  let x = 0,
    y = 0;
  for (let i = 0; i < d.length; i += 2) {
    if (!Number.isSafeInteger(d[i]) || !Number.isSafeInteger(d[i + 1])) throw new Error(`o.d[${i}]: expected integers`);
    x += d[i];
    y += d[i + 1];
    pts.push([x / k, y / k]);
  }
  return pts;
}

/**
 * One angle for v2: a sampled angle as its quantised series, anything else unchanged.
 * @param {any} a
 * @param {number} e decimals of rad
 */
function packAngle(a, e) {
  if (
    !isObj(a) ||
    a.kind !== 'sampled' ||
    !Array.isArray(a.values) ||
    a.values.length < 3 ||
    a.values.length > MAX_SAMPLES
  )
    return a;
  if (!a.values.every((/** @type {unknown} */ v) => typeof v === 'number' && Number.isFinite(v))) return a;
  const mh = a.max_harmonic == null ? null : Number(a.max_harmonic);
  if (mh != null && !(Number.isInteger(mh) && mh >= 0 && mh <= MAX_HARMONIC)) return a;
  const series = sampledSeries(a.values, mh);
  const k = 10 ** e;
  return { s: [a.values.length, (series.length - 1) / 2, e], c: series.map((v) => Math.round(v * k)) };
}

/**
 * @param {any} a
 * @param {string} field
 */
function unpackAngle(a, field) {
  if (!isObj(a) || !('s' in a)) return a;
  const s = a.s,
    c = a.c;
  if (!Array.isArray(s) || s.length !== 3 || !s.every(Number.isInteger))
    throw new Error(`${field}.s: expected [N, H, e] integers`);
  const [n, h, e] = s;
  if (n < 3 || n > MAX_SAMPLES || h < 0 || h > Math.min(Math.floor(n / 2), MAX_HARMONIC) || e < 0 || e > 9)
    throw new Error(`${field}.s: N, H or e out of range`);
  if (!Array.isArray(c) || c.length !== 1 + 2 * h || !c.every(Number.isSafeInteger))
    throw new Error(`${field}.c: expected ${1 + 2 * h} integers`);
  const k = 10 ** e;
  return {
    kind: 'sampled',
    values: seriesSamples(
      c.map((v) => v / k),
      n,
    ),
    max_harmonic: h,
  };
}

/**
 * The state (v1 shape) as a v2 object.
 * @param {Record<string, any>} state
 * @param {{ angleDecimals?: number, csv?: boolean }} opts
 */
function packV2(state, { angleDecimals = ANGLE_DECIMALS[0], csv = true } = {}) {
  /** @type {Record<string, any>} */
  const out = { v: 2 };
  for (const [key, val] of Object.entries(state)) {
    if (key === 'v') continue;
    if (V2_KEYS.includes(key)) throw new Error(`encodeShare: the key "${key}" is reserved`);
    if (key === 'outline' && Array.isArray(val)) {
      const o = packOutline(/** @type {[number, number][]} */ (val));
      if (o) out.o = o;
      else out.outline = val;
    } else if (key === 'outline_label') out.ol = val;
    else if (key === 'strain_point') out.p = val;
    else if (key === 'kin' && isObj(val) && isObj(val.kinematics) && typeof val.kinematics.flap_freq_hz === 'number') {
      const kk = val.kinematics;
      /** @type {Record<string, any>} */
      const k = {
        l: val.label,
        f: kk.flap_freq_hz,
        a: packAngle(kk.alpha, angleDecimals),
        b: packAngle(kk.beta, angleDecimals),
        g: packAngle(kk.gamma, angleDecimals),
      };
      if (csv && val.csv) k.c = val.csv;
      out.k = k;
    } else out[key] = val;
  }
  return out;
}

/**
 * A v2 object back in the v1 shape.
 * @param {Record<string, any>} obj
 */
function unpackV2(obj) {
  /** @type {Record<string, any>} */
  const out = { v: 2 };
  for (const [key, val] of Object.entries(obj)) {
    if (key === 'v') continue;
    if (key === 'o') out.outline = unpackOutline(val);
    else if (key === 'ol') out.outline_label = val;
    else if (key === 'p') out.strain_point = val;
    else if (key === 'k') {
      if (!isObj(val)) throw new Error('k: expected an object');
      if (typeof val.f !== 'number') throw new Error('k.f: expected the flap frequency (Hz)');
      out.kin = {
        label: val.l,
        kinematics: {
          flap_freq_hz: val.f,
          alpha: unpackAngle(val.a, 'k.a'),
          beta: unpackAngle(val.b, 'k.b'),
          gamma: unpackAngle(val.g, 'k.g'),
        },
        csv: val.c ?? null,
      };
    } else out[key] = val;
  }
  return out;
}

// ---------- encode / decode ----------

/**
 * Encodes a state object (v1 shape: outline, outline_label, kin, strain_point, others as they
 * are) as the fragment value (without `#s=`), version SHARE_VERSION.
 * `angleDecimals`: rounding of a sampled angle's series (10^-e rad); `csv: false` leaves out the
 * kinematics' CSV text.
 * @param {Record<string, unknown>} state
 * @param {{ angleDecimals?: number, csv?: boolean }} [opts]
 */
export async function encodeShare(state, opts = {}) {
  const json = JSON.stringify(packV2(state, opts));
  const packed = await pipe(new TextEncoder().encode(json), new CompressionStream('deflate-raw'));
  return toBase64url(packed);
}

/**
 * Decodes a fragment value (any version in SHARE_VERSIONS_READ) into the state object in the v1
 * shape, `v` the version read; throws an Error saying why it cannot be restored (not base64url,
 * not deflate-raw, not JSON, unknown version, malformed field, too large).
 * @param {string} text
 * @returns {Promise<Record<string, any>>}
 */
export async function decodeShare(text) {
  if (text.length > MAX_FRAGMENT) throw new Error(`the share fragment is longer than ${MAX_FRAGMENT} characters`);
  const bytes = fromBase64url(text);
  let raw;
  try {
    raw = await pipe(bytes, new DecompressionStream('deflate-raw'), MAX_JSON);
  } catch (e) {
    if (e instanceof Error && /larger than/.test(e.message)) throw e;
    throw new Error('the share fragment is not compressed state (it may have been cut short when copied)');
  }
  let obj;
  try {
    obj = JSON.parse(new TextDecoder().decode(raw));
  } catch {
    throw new Error('the share fragment does not hold JSON');
  }
  if (!obj || typeof obj !== 'object' || Array.isArray(obj))
    throw new Error('the share fragment does not hold an object');
  if (obj.v === 1) return obj;
  if (obj.v === 2) return unpackV2(obj);
  throw new Error(
    `the share fragment has version ${JSON.stringify(obj.v)}; this lab reads versions ${SHARE_VERSIONS_READ.join(' and ')} (a newer lab wrote it?)`,
  );
}

/**
 * The `#s=` fragment for a state and the link it makes with `base` (the URL without its
 * fragment): the finest rounding whose whole link is at most MAX_LINK characters, trying
 *   the CSV text included (if any) with the angle series at 10^-6 rad, then without the CSV at
 *   10^-6, 10^-5 and 10^-4 rad.
 * When even the last is longer than MAX_LINK the fragment is still written (it works when the
 * link is pasted whole) and `message` says so plainly; when the fragment would be longer than
 * MAX_FRAGMENT (a reader refuses it) no fragment is written and `message` says why. An empty
 * state gives hash ''. Never truncates. `onMessage` (optional) is called with `message` when
 * there is one (the lab shows it as a notice).
 * @param {Record<string, unknown>} state
 * @param {string} base
 * @param {(message: string) => void} [onMessage]
 * @returns {Promise<{ hash: string, length: number, angleDecimals: number | null, csv: boolean, message: string }>}
 */
export async function shareLink(state, base, onMessage) {
  const r = await linkFor(state, base);
  if (r.message && onMessage) onMessage(r.message);
  return r;
}

/**
 * @param {Record<string, unknown>} state
 * @param {string} base
 */
async function linkFor(state, base) {
  const keys = Object.keys(state).filter((k) => state[k] != null);
  if (!keys.length) return { hash: '', length: base.length, angleDecimals: null, csv: false, message: '' };
  const kin = /** @type {any} */ (state.kin);
  const hasCsv = !!(kin && kin.csv);
  const sampled = !!(
    kin &&
    kin.kinematics &&
    ['alpha', 'beta', 'gamma'].some((a) => kin.kinematics[a] && kin.kinematics[a].kind === 'sampled')
  );
  /** @type {{ angleDecimals: number, csv: boolean }[]} */
  const tries = [];
  if (hasCsv) tries.push({ angleDecimals: ANGLE_DECIMALS[0], csv: true });
  for (const e of sampled ? ANGLE_DECIMALS : ANGLE_DECIMALS.slice(0, 1)) tries.push({ angleDecimals: e, csv: false });
  let last = { hash: '', length: 0, angleDecimals: /** @type {number | null} */ (null), csv: false, message: '' };
  for (const t of tries) {
    const hash = `#s=${await encodeShare(state, t)}`;
    last = {
      hash,
      length: base.length + hash.length,
      angleDecimals: sampled ? t.angleDecimals : null,
      csv: t.csv,
      message: '',
    };
    if (last.length <= MAX_LINK) return last;
  }
  const what =
    [
      state.outline ? `an outline of ${/** @type {unknown[]} */ (state.outline).length} points` : '',
      kin ? 'a kinematics table' : '',
    ]
      .filter(Boolean)
      .join(' and ') || 'the shared state';
  if (last.hash.length - 3 > MAX_FRAGMENT) {
    return {
      hash: '',
      length: base.length,
      angleDecimals: null,
      csv: false,
      message: `The link cannot carry ${what}: it would be ${last.length} characters, and the lab reads at most ${MAX_FRAGMENT}. The link holds the slider settings only; export the outline or kinematics as a file to share them.`,
    };
  }
  last.message = `This link is ${last.length} characters long (it carries ${what}); links over ${MAX_LINK} characters may be cut short by e-mail, chat or a learning platform. It works when copied whole; to be safe, share the outline or kinematics as a file.`;
  return last;
}

/**
 * The `s` value of a location.hash such as `#s=…` (else null).
 * @param {string} hash
 */
export function fragmentValue(hash) {
  const m = /^#?s=([A-Za-z0-9_-]*)$/.exec(hash || '');
  return m ? m[1] : null;
}

/**
 * Checks an outline from a share fragment: an array of 3..2000 [x, y] finite numbers (mm).
 * Returns the points or throws naming the field.
 * @param {unknown} pts
 * @returns {[number, number][]}
 */
export function checkPoints(pts, field = 'outline') {
  if (!Array.isArray(pts) || pts.length < 3 || pts.length > 2000)
    throw new Error(`${field}: expected 3 to 2000 points [x_mm, y_mm]`);
  return pts.map((p, i) => {
    if (!Array.isArray(p) || p.length !== 2 || !p.every((v) => typeof v === 'number' && Number.isFinite(v)))
      throw new Error(`${field}[${i}]: expected [x_mm, y_mm] finite numbers`);
    return /** @type {[number, number]} */ ([p[0], p[1]]);
  });
}
