// @ts-check
// Large shared state in the URL fragment: `#s=<base64url(deflate-raw(JSON))>`, where the JSON
// is versioned `{ v: 1, … }` (the edited outline, the kinematics table, the strain point).
// Short state stays in the query (www/state.js); only what does not fit there comes here.
// Uses the browser's CompressionStream / DecompressionStream (also in node ≥ 18). Pure apart
// from those streams; unit-tested in tests/js/share.test.mjs.

/** The fragment version this lab writes and reads. */
export const SHARE_VERSION = 1;
/** Longest fragment read (characters) and longest JSON accepted after inflating (bytes). */
export const MAX_FRAGMENT = 200000;
export const MAX_JSON = 2000000;

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
  for (const p of parts) { out.set(p, o); o += p.length; }
  return out;
}

/**
 * Encodes a state object as the fragment value (without `#s=`).
 * @param {Record<string, unknown>} state
 */
export async function encodeShare(state) {
  const json = JSON.stringify({ v: SHARE_VERSION, ...state });
  const packed = await pipe(new TextEncoder().encode(json), new CompressionStream('deflate-raw'));
  return toBase64url(packed);
}

/**
 * Decodes a fragment value back into the state object; throws an Error saying why it cannot be
 * restored (not base64url, not deflate-raw, not JSON, wrong version, too large).
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
  if (!obj || typeof obj !== 'object' || Array.isArray(obj)) throw new Error('the share fragment does not hold an object');
  if (obj.v !== SHARE_VERSION) throw new Error(`the share fragment has version ${JSON.stringify(obj.v)}; this lab reads version ${SHARE_VERSION}`);
  return obj;
}

/** The `s` value of a location.hash such as `#s=…` (else null). */
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
  if (!Array.isArray(pts) || pts.length < 3 || pts.length > 2000) throw new Error(`${field}: expected 3 to 2000 points [x_mm, y_mm]`);
  return pts.map((p, i) => {
    if (!Array.isArray(p) || p.length !== 2 || !p.every((v) => typeof v === 'number' && Number.isFinite(v))) throw new Error(`${field}[${i}]: expected [x_mm, y_mm] finite numbers`);
    return /** @type {[number, number]} */ ([p[0], p[1]]);
  });
}
