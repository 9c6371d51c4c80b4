// @ts-check
// Lab state <-> URL query / element attributes. Pure functions (no DOM), unit-tested in
// tests/js/state.test.mjs. The slider table NUMERIC mirrors the core's parameter table (wasm
// `parameters()`, src/params.rs; tests/js/wasm.test.mjs checks every field); the SimConfig is
// built by the core (wasm `applyOverrides`, called by www/engine.js from overridesOf()). Everything read from outside is validated here: a value that is not
// a plain decimal number inside its slider's range, or not one of an enum's choices, is dropped
// (the default is used) and reported by name so the page can show a notice (as text only).

import { SCREEN_IDS } from './screens.js';

/**
 * @typedef {{ key: 'alpha0' | 'beta0' | 'gamma0' | 'flap_hz' | 'zeta' | 'alpha_phase' | 'beta_phase' | 'gamma_phase' | 'duration' | 'air_density',
 *   label: string, sym: string, unit: string, min: number, max: number, step: number, def: number }} NumericParam
 * @typedef {{ key: 'modes' | 'mode' | 'detrend', label: string, choices: string[], def: string, disabled?: string[] }} EnumParam
 * @typedef {{ key: 'camber' | 'clamp' | 'e_pa' | 'rho' | 'nu' | 'thickness_um' | 'mesh_mm' | 'n_modes', core: string,
 *   label: string, unit: string, min: number, max: number, step: number, def: number }} WingParam
 */

/**
 * Numeric parameters: URL/attribute name, label, unit, slider range and default (the paper case).
 * @type {NumericParam[]}
 */
export const NUMERIC = [
  { key: 'alpha0', label: 'α_0, roll amplitude', sym: 'α_0', unit: 'rad', min: 0, max: 1.5, step: 0.01, def: 0.8 },
  { key: 'beta0', label: 'β_0, pitch amplitude', sym: 'β_0', unit: 'rad', min: 0, max: 1.0, step: 0.01, def: 0.5 },
  { key: 'gamma0', label: 'γ_0, yaw amplitude', sym: 'γ_0', unit: 'rad', min: 0, max: 0.5, step: 0.005, def: 0.2 },
  { key: 'flap_hz', label: 'Flap frequency f_d', sym: 'f_d', unit: 'Hz', min: 5, max: 60, step: 0.5, def: 25 },
  { key: 'zeta', label: 'ζ, modal damping ratio', sym: 'ζ', unit: '', min: 0, max: 0.1, step: 0.001, def: 0 },
  { key: 'alpha_phase', label: 'Phase of α', sym: 'φ_α', unit: 'rad', min: -3.14, max: 3.14, step: 0.01, def: 0 },
  { key: 'beta_phase', label: 'Phase of β', sym: 'φ_β', unit: 'rad', min: -3.14, max: 3.14, step: 0.01, def: 0 },
  { key: 'gamma_phase', label: 'Phase of γ', sym: 'φ_γ', unit: 'rad', min: -3.14, max: 3.14, step: 0.01, def: 0 },
  { key: 'duration', label: 'Duration', sym: 'T_{sim}', unit: 's', min: 0.2, max: 10, step: 0.1, def: 2 },
  {
    key: 'air_density',
    label: 'ρ_{air}, fluid density (0 = vacuum)',
    sym: 'ρ_{air}',
    unit: 'kg/m³',
    min: 0,
    max: 2,
    step: 0.01,
    def: 0,
  },
];

/**
 * The named media of the Parameters panel's medium control (www/views/medium.js), densities in
 * kg/m³: the core's table (src/aero/mod.rs MEDIA, wasm `media()`; tests/js/wasm.test.mjs holds
 * them equal). Any other density of the `air_density` slider is a custom medium.
 */
export const MEDIA = Object.freeze([
  Object.freeze({ name: 'vacuum', density_kg_m3: 0 }),
  Object.freeze({ name: 'helium', density_kg_m3: 0.18 }),
  Object.freeze({ name: 'air', density_kg_m3: 1.2 }),
]);

/**
 * Enumerated parameters. `disabled` choices are shown but not selectable (and rejected from URLs).
 * @type {EnumParam[]}
 */
export const ENUMS = [
  { key: 'modes', label: 'Mode set', choices: ['paper', 'fe'], def: 'paper' },
  { key: 'mode', label: 'Selected mode', choices: ['1', '2', '3', '4', '5', '6', '7', '8'], def: '1' },
  { key: 'detrend', label: 'PSD detrend', choices: ['none', 'mean', 'linear'], def: 'none' },
];

/** Panels that can be shown; `panels=` picks a subset (comma-separated). */
export const PANELS = [
  'controls',
  'numbers',
  'time',
  'spectrum',
  'strain',
  'studies',
  'wing3d',
  'report',
  'experiments',
  'resonance',
  'wing',
  'kinematics',
  'modeshape',
  'sensing',
  'neural',
];

/**
 * The body rotation that the sensing panel (www/views/sensing.js) detects: a constant body
 * angular velocity of `body_rate` rad/s about the body axis `body_axis` (x = I, roll; y = J,
 * pitch; z = K, yaw). The range is the core's for a constant component (src/params.rs
 * BODY_RATE_RANGES, `mean`; tests/sensing_lab.rs compares them); the sign is the direction.
 * Written to URLs only when they differ from the default. Only the sensing analysis uses it:
 * the live panels show the paper's fixed body.
 */
export const BODY_RATE = Object.freeze({
  key: 'body_rate',
  label: 'Body rotation rate ω_b',
  sym: 'ω_b',
  unit: 'rad/s',
  min: -100,
  max: 100,
  step: 0.001,
  def: 1,
});
/** The body axis of the rotation: choices and default. */
export const BODY_AXIS = Object.freeze({
  key: 'body_axis',
  label: 'Rotation axis (body axes)',
  choices: Object.freeze(['x', 'y', 'z']),
  def: 'z',
});
/** What each body axis is, for labels. */
export const BODY_AXIS_LABELS = Object.freeze({ x: 'x = I (roll)', y: 'y = J (pitch)', z: 'z = K (yaw)' });
/** The URL keys of the sensing panel. */
export const SENSING_KEYS = ['body_rate', 'body_axis'];

/**
 * The body rate vector [x, y, z] rad/s of a state (see BODY_RATE).
 * @param {{ body_rate?: number, body_axis?: string }} s
 * @returns {[number, number, number]}
 */
export function bodyRateVector(s) {
  const r = Number.isFinite(Number(s.body_rate)) ? Number(s.body_rate) : BODY_RATE.def;
  const i = Math.max(0, BODY_AXIS.choices.indexOf(s.body_axis || BODY_AXIS.def));
  /** @type {[number, number, number]} */
  const w = [0, 0, 0];
  w[i] = r;
  return w;
}

/** Guided experiments (www/experiments.js); `exp=<id>` opens one. */
export const EXPERIMENT_IDS = [
  'beat',
  'no-yaw',
  'damping',
  'yaw',
  'ic',
  'resonance',
  'instability',
  'sensing',
  'air-beat',
  'air-superharmonic',
  'neural-sensing',
];

/**
 * The lab's FE wing (wasm `feModes` input): the default synthetic outline, camber, clamp,
 * material and 1 mm elements, the same as `wingbeat modes`, so the lab and the CLI agree
 * (f1 = 62.49 Hz); two modes, like the paper table. About 1–3 s in a worker (1.25 mm would
 * take a third of that but put f1 at 63.8 Hz).
 */
export const FE_LAB_INPUT = Object.freeze({ n_modes: 2, mesh_size_mm: 1.0 });

/**
 * The wing's parameters (URL parameters too, written only when they differ from the default so
 * that short links stay short). `core` is the key of the core's table (wasm `wingParameters()`,
 * src/params.rs; tests/js/wing.test.mjs compares ranges with it when the wasm has it). The
 * ranges are the core's; the defaults are the lab's default FE wing (FE_LAB_INPUT: 2 modes,
 * where the core table has 4): the lab passes every key to `wingInput`, so its wing never
 * depends on the core's defaults. `clamp` is the basal strip width in mm, 0 = the root edge
 * (also written `clamp=root`); `mesh_mm` 0 = the core's automatic size from the planform, the
 * default as in `wingbeat modes` without --mesh-size-mm (1 mm on the default outline, 0.53 mm on
 * examples/planform-tapered.csv), so a loaded outline is meshed as the CLI meshes it.
 * @type {WingParam[]}
 */
export const WING = [
  { key: 'camber', core: 'camber', label: 'Camber (rise / chord)', unit: '', min: 0, max: 0.5, step: 0.01, def: 0.13 },
  {
    key: 'clamp',
    core: 'clamp_mm',
    label: 'Clamp strip width (0 = root edge)',
    unit: 'mm',
    min: 0,
    max: 1000,
    step: 0.1,
    def: 0,
  },
  { key: 'e_pa', core: 'e_pa', label: 'Young’s modulus E', unit: 'Pa', min: 1e5, max: 1e12, step: 1e5, def: 1.311e10 },
  { key: 'rho', core: 'rho', label: 'Density ρ', unit: 'kg/m³', min: 10, max: 20000, step: 1, def: 860 },
  { key: 'nu', core: 'nu', label: 'Poisson’s ratio ν', unit: '', min: 0, max: 0.49, step: 0.01, def: 0.3 },
  { key: 'thickness_um', core: 'thickness_um', label: 'Thickness', unit: 'µm', min: 1, max: 10000, step: 0.1, def: 81 },
  {
    key: 'mesh_mm',
    core: 'mesh_mm',
    label: 'Element size (0 = automatic)',
    unit: 'mm',
    min: 0,
    max: 100,
    step: 0.05,
    def: 0,
  },
  { key: 'n_modes', core: 'n_modes', label: 'Number of modes', unit: '', min: 1, max: 8, step: 1, def: 2 },
];

/** Built-in outline ids (wasm `planforms()`); `outline=<id>` picks one. */
export const OUTLINE_IDS = ['manduca', 'slender', 'broad', 'rect'];

/** Output sample rate of the live simulation, Hz (fixed). */
export const SAMPLE_RATE_HZ = 10000;

const NUMBER_RE = /^[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d{1,3})?$/;

/**
 * The lab's URL parameters (one store property each).
 * @typedef {{
 *   alpha0: number, beta0: number, gamma0: number, flap_hz: number, zeta: number,
 *   alpha_phase: number, beta_phase: number, gamma_phase: number, duration: number, air_density: number,
 *   modes: 'paper' | 'fe', mode: string, detrend: 'none' | 'mean' | 'linear', panels: string[], exp: string, embed?: boolean,
 *   camber: number, clamp: number, e_pa: number, rho: number, nu: number, thickness_um: number, mesh_mm: number, n_modes: number,
 *   outline: string, planform: string, body_rate: number, body_axis: 'x' | 'y' | 'z',
 *   screen?: string,
 * }} Params
 * `screen`: the screen wanted (www/screens.js; '' or absent = the lab's choice). Not in
 * defaults(): a reset of the parameters keeps the screen, like the panel choice.
 */

/** @returns {Params} */
export function defaults() {
  /** @type {Record<string, unknown>} */
  const s = {};
  for (const p of NUMERIC) s[p.key] = p.def;
  for (const e of ENUMS) s[e.key] = e.def;
  for (const w of WING) s[w.key] = w.def;
  s.outline = 'manduca';
  s.planform = '';
  s.body_rate = BODY_RATE.def;
  s.body_axis = BODY_AXIS.def;
  s.panels = PANELS.slice();
  s.exp = '';
  return /** @type {Params} */ (s);
}

/**
 * Parses one numeric value; returns a number or null when not a plain in-range decimal. The
 * range check is the core's (`check_range` in src/error.rs: finite and min <= v <= max, no
 * tolerance), so a value accepted here is never refused by `applyOverrides`/`wingInput`
 * (`zeta=-1e-13` used to pass here and fail there); tests/clear_errors_and_url_ranges.rs runs this file
 * against the core's tables.
 * @param {NumericParam} p
 * @param {unknown} raw
 */
export function parseNumber(p, raw) {
  if (typeof raw !== 'string' || raw.length > 32 || !NUMBER_RE.test(raw.trim())) return null;
  const v = Number(raw.trim());
  if (!Number.isFinite(v) || !(v >= p.min && v <= p.max)) return null;
  return v;
}

/**
 * @param {EnumParam} e
 * @param {unknown} raw
 */
function parseEnum(e, raw) {
  if (typeof raw !== 'string') return null;
  const v = raw.trim();
  if (!e.choices.includes(v) || (e.disabled || []).includes(v)) return null;
  return v;
}

/** @param {unknown} raw */
function parsePanels(raw) {
  if (typeof raw !== 'string' || raw.length > 200) return null;
  const list = raw
    .split(',')
    .map((s) => s.trim())
    .filter(Boolean);
  if (list.length === 0 || !list.every((p) => PANELS.includes(p))) return null;
  return PANELS.filter((p) => list.includes(p));
}

/** Why a parameter was rejected, for the notice (never echoes the value). */
export function expectation(key) {
  const p = NUMERIC.find((q) => q.key === key);
  if (p) return `a number in [${p.min}, ${p.max}]${p.unit ? ' ' + p.unit : ''}`;
  const e = ENUMS.find((q) => q.key === key);
  if (e) return `one of ${e.choices.filter((c) => !(e.disabled || []).includes(c)).join(', ')}`;
  if (key === 'panels') return `a comma-separated list of ${PANELS.join(', ')}`;
  if (key === 'embed') return '0 or 1';
  if (key === 'exp') return `one of ${EXPERIMENT_IDS.join(', ')}`;
  if (key === 'screen') return `one of ${SCREEN_IDS.join(', ')}`;
  const w = WING.find((q) => q.key === key);
  if (w)
    return `${key === 'clamp' ? '"root" or ' : ''}a number in [${w.min}, ${w.max}]${w.unit ? ' ' + w.unit : ''}${key === 'n_modes' ? ' (a whole number)' : ''}`;
  if (key === 'outline') return `one of ${OUTLINE_IDS.join(', ')}`;
  if (key === 'body_rate') return `a number in [${BODY_RATE.min}, ${BODY_RATE.max}] ${BODY_RATE.unit}`;
  if (key === 'body_axis') return `one of ${BODY_AXIS.choices.join(', ')}`;
  if (key === 'planform')
    return 'a relative same-origin path to a .csv or .json outline (no scheme, no //, at most 200 characters)';
  return 'a known parameter';
}

/** Most name/value pairs read from one query, attribute list or message; the rest are reported. */
export const MAX_PAIRS = 200;

/**
 * A name for notices and error replies: at most 40 code points (a truncated emoji leaves no
 * lone surrogate); control characters and lone surrogates shown as U+FFFD. Never throws.
 * @param {unknown} key
 */
export function shortKey(key) {
  if (typeof key !== 'string') return `(a ${typeof key} as a name)`;
  const cps = Array.from(key.slice(0, 82)).slice(0, 41);
  // control characters and lone surrogates (a name cut from a malformed escape) as U+FFFD
  const text = cps
    .slice(0, 40)
    .join('')
    // biome-ignore lint/suspicious/noControlCharactersInRegex: control characters are what this replaces
    .replace(/[\u0000-\u001f\u007f-\u009f\u2028\u2029\uD800-\uDFFF]/gu, '\uFFFD');
  return cps.length > 40 ? text + '…' : text;
}

/**
 * Reads state from name/value pairs (URLSearchParams or element attributes).
 * Returns { state, rejected: [{ key, why }] }; `key` is shortened by shortKey (40 characters).
 * Unknown names are rejected too, except those in `ignore`; so is a name given more than once, a
 * name or value that is not a string, and every pair after the first MAX_PAIRS. Never throws.
 * @param {Iterable<[string, string]> | string[][]} pairs
 * @param {string[]} [ignore]
 * @returns {{ state: Params, rejected: { key: string, why: string }[] }}
 */
export function parsePairs(pairs, ignore = []) {
  const state = defaults();
  /** @type {Record<string, unknown>} */
  const into = state;
  /** @type {{ key: string, why: string }[]} */
  const rejected = [];
  const seen = new Set();
  let count = 0;
  for (const pair of pairs) {
    if (++count > MAX_PAIRS) {
      rejected.push({ key: '(query)', why: `more than ${MAX_PAIRS} parameters: the rest were not read` });
      break;
    }
    const [rawKey, raw] = Array.isArray(pair) ? pair : [undefined, undefined];
    if (typeof rawKey !== 'string') {
      rejected.push({ key: shortKey(rawKey), why: 'a parameter name must be text' });
      continue;
    }
    const key = rawKey;
    if (ignore.includes(key)) continue;
    const short = shortKey(key);
    if (typeof raw !== 'string') {
      rejected.push({ key: short, why: `expected text: ${expectation(key)}` });
      continue;
    }
    if (seen.has(key)) {
      rejected.push({ key: short, why: 'given more than once' });
      continue;
    }
    seen.add(key);
    const p = NUMERIC.find((q) => q.key === key);
    const e = ENUMS.find((q) => q.key === key);
    /** @type {number | string | string[] | boolean | null} */
    let v = null;
    if (p) v = parseNumber(p, raw);
    else if (e) v = parseEnum(e, raw);
    else if (key === 'panels') v = parsePanels(raw);
    else if (key === 'embed') v = raw === '0' || raw === '1' ? raw === '1' : null;
    else if (key === 'exp') v = EXPERIMENT_IDS.includes(raw.trim()) ? raw.trim() : null;
    else if (key === 'screen') v = SCREEN_IDS.includes(String(raw).trim()) ? String(raw).trim() : null;
    else if (WING.some((q) => q.key === key))
      v = parseWing(/** @type {WingParam} */ (WING.find((q) => q.key === key)), raw);
    else if (key === 'outline') v = OUTLINE_IDS.includes(raw.trim()) ? raw.trim() : null;
    else if (key === 'planform') v = safePlanformPath(raw);
    else if (key === 'body_rate') v = parseNumber(/** @type {any} */ (BODY_RATE), raw);
    else if (key === 'body_axis') v = BODY_AXIS.choices.includes(raw.trim()) ? raw.trim() : null;
    else {
      rejected.push({ key: short, why: 'unknown parameter' });
      continue;
    }
    if (v === null) rejected.push({ key: short, why: `expected ${expectation(key)}` });
    else into[key] = v;
  }
  return { state, rejected };
}

/**
 * One wing parameter from text: a plain decimal in range (`clamp` also takes `root` = 0;
 * `n_modes` must be whole). Returns null when invalid.
 * @param {WingParam} w
 * @param {unknown} raw
 */
export function parseWing(w, raw) {
  if (w.key === 'clamp' && typeof raw === 'string' && raw.trim() === 'root') return 0;
  const v = parseNumber(/** @type {any} */ (w), raw);
  if (v === null) return null;
  if (w.key === 'n_modes' && !Number.isInteger(v)) return null;
  return v;
}

/**
 * A `planform=` value if it is a safe relative same-origin path (letters, digits, `._-/`, no
 * scheme, no leading `//` or `/`, no `..`, ending in .csv or .json); else null.
 * @param {unknown} raw
 */
export function safePlanformPath(raw) {
  if (typeof raw !== 'string') return null;
  const v = raw.trim();
  if (!v || v.length > 200) return null;
  if (!/^[A-Za-z0-9._\-/]+$/.test(v) || v.startsWith('/') || v.split('/').includes('..')) return null;
  if (!/\.(csv|json)$/i.test(v)) return null;
  return v;
}

/** Whether the wing differs from the lab's default FE wing (any wing parameter, outline or file). */
export function customWing(state) {
  return WING.some((w) => state[w.key] !== w.def) || state.outline !== 'manduca' || !!state.planform;
}

/**
 * Parses a query string such as location.search.
 * @param {string} search
 */
export function parseQuery(search) {
  let params;
  try {
    params = new URLSearchParams(search);
  } catch {
    return { state: defaults(), rejected: [{ key: '(query)', why: 'not a valid query string' }] };
  }
  return parsePairs(params.entries());
}

/**
 * Serialises state to a query string (no leading '?'); all parameters, shortest exact decimals.
 * @param {Params} state
 * @param {Record<string, string>} [extra]
 */
export function toQuery(state, extra = {}) {
  const q = new URLSearchParams();
  for (const p of NUMERIC) q.set(p.key, String(state[p.key]));
  for (const e of ENUMS) q.set(e.key, String(state[e.key]));
  for (const w of WING) {
    const v = state[w.key];
    if (v !== undefined && v !== w.def) q.set(w.key, w.key === 'clamp' && v === 0 ? 'root' : String(v));
  }
  if (state.outline && state.outline !== 'manduca') q.set('outline', state.outline);
  if (state.planform) q.set('planform', state.planform);
  if (state.body_rate !== undefined && state.body_rate !== BODY_RATE.def) q.set('body_rate', String(state.body_rate));
  if (state.body_axis && state.body_axis !== BODY_AXIS.def) q.set('body_axis', state.body_axis);
  if (state.panels && state.panels.length !== PANELS.length) q.set('panels', state.panels.join(','));
  if (state.exp) q.set('exp', state.exp);
  if (state.screen) q.set('screen', state.screen);
  for (const [k, v] of Object.entries(extra)) q.set(k, v);
  return q.toString();
}

/** Rounds a slider value to its step grid (avoids 0.30000000000000004 in URLs). */
/**
 * @param {NumericParam} p
 * @param {number} v
 */
export function snap(p, v) {
  const k = Math.round((v - p.min) / p.step);
  const s = p.min + k * p.step;
  const digits = Math.max(0, -Math.floor(Math.log10(p.step)) + 1);
  return Math.min(p.max, Math.max(p.min, Number(s.toFixed(digits))));
}

/**
 * The named overrides of a state for wasm `applyOverrides(base, overrides)`: the value of every
 * numeric parameter, by key. What each key means (γ0 is the first-harmonic amplitude of the yaw
 * angle, ζ applies to every mode, …) is decided by the core (src/params.rs), not here.
 * @param {Params} state
 * @returns {import('./pkg/wingbeat.js').Overrides}
 */
export function overridesOf(state) {
  /** @type {import('./pkg/wingbeat.js').Overrides} */
  const o = {};
  for (const p of NUMERIC) o[p.key] = Number(state[p.key]);
  return o;
}

/** The five parameters the lab shows first (the rest follow under "More parameters"). */
export const MAIN_KEYS = ['alpha0', 'beta0', 'gamma0', 'flap_hz', 'zeta'];

/**
 * Just the URL parameters of a store state (drops derived keys such as `result`).
 * @param {Params} s
 * @returns {Params}
 */
export function paramsOf(s) {
  /** @type {Record<string, unknown>} */
  const out = {};
  for (const p of NUMERIC) out[p.key] = s[p.key];
  for (const e of ENUMS) out[e.key] = s[e.key];
  for (const w of WING) out[w.key] = s[w.key];
  out.outline = s.outline;
  out.planform = s.planform;
  out.body_rate = s.body_rate === undefined ? BODY_RATE.def : s.body_rate;
  out.body_axis = s.body_axis || BODY_AXIS.def;
  out.panels = s.panels;
  out.exp = s.exp || '';
  out.screen = s.screen || '';
  return /** @type {Params} */ (out);
}

/**
 * A one-line, human-readable parameter set for figures and exports (rich markup).
 * @param {Params} s
 */
export function describe(s) {
  const modes = s.modes === 'fe' ? 'FE wing modes (SI)' : 'paper table modes (paper units)';
  return (
    `α_0 = ${s.alpha0} rad, β_0 = ${s.beta0} rad, γ_0 = ${s.gamma0} rad, f_d = ${s.flap_hz} Hz, ζ = ${s.zeta}, ` +
    `phases φ_α = ${s.alpha_phase}, φ_β = ${s.beta_phase}, φ_γ = ${s.gamma_phase} rad, ${s.duration} s at ${SAMPLE_RATE_HZ / 1000} kHz; ` +
    `mode ${s.mode}, ${modes}, ${Number(s.air_density) > 0 ? `in a fluid of ${s.air_density} kg/m³` : 'in a vacuum'} — wingbeat lab`
  );
}
