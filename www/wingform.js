// @ts-check
// The Wing panel's form, pure (views/wing.js and its pieces): how each wing parameter is shown
// (unit, scale, step, label), reading a typed value back with its range check, the material
// preset that matches the parameters, and the outline edits (the drawing's box, a point added
// halfway to the next one, the label of an edited outline) and the store patch that makes the
// draft the wing in use. No DOM; unit-tested in tests/js/wingform.test.mjs.
import { WING } from './state.js';

/** The parameters a material preset sets. */
export const MATERIAL_KEYS = ['e_pa', 'rho', 'nu', 'thickness_um'];

/** How each wing parameter is shown: a display unit and scale (E in GPa), the input step. */
export const SHOW = {
  camber: { unit: 'fraction of chord', scale: 1, step: 0.01 },
  clamp: { unit: 'mm, 0 = root edge', scale: 1, step: 0.1 },
  e_pa: { unit: 'GPa', scale: 1e-9, step: 0.01 },
  rho: { unit: 'kg/m³', scale: 1, step: 1 },
  nu: { unit: '', scale: 1, step: 0.01 },
  thickness_um: { unit: 'µm', scale: 1, step: 0.1 },
  mesh_mm: { unit: 'mm, 0 = automatic', scale: 1, step: 0.05 },
  n_modes: { unit: '', scale: 1, step: 1 },
};
export const LABEL = {
  camber: 'Camber',
  clamp: 'Clamp strip',
  e_pa: 'Young’s modulus E',
  rho: 'Density ρ',
  nu: 'Poisson’s ratio ν',
  thickness_um: 'Thickness',
  mesh_mm: 'Element size',
  n_modes: 'Modes',
};

/** Rounds to ~12 significant digits (GPa ↔ Pa without 13.110000000000001). */
export const clean = (v) => Number(Number(v).toPrecision(12));

/**
 * A typed value of wing parameter `w` (in its display unit) in the core's unit, or the
 * complaint naming the parameter and its range (display unit).
 * @param {{ key: string, min: number, max: number }} w a row of state.js WING
 * @param {string} text
 * @returns {{ value: number } | { error: string }}
 */
export function readWingValue(w, text) {
  const sh = SHOW[w.key];
  const v = Number(text) / sh.scale;
  const ok =
    text.trim() !== '' &&
    Number.isFinite(v) &&
    v >= w.min - 1e-12 &&
    v <= w.max + 1e-12 &&
    (w.key !== 'n_modes' || Number.isInteger(v));
  if (ok) return { value: clean(v) };
  return {
    error: `${LABEL[w.key]}: expected ${w.key === 'n_modes' ? 'a whole number' : 'a number'} in [${clean(w.min * sh.scale)}, ${clean(w.max * sh.scale)}]${sh.unit ? ' ' + sh.unit.replace(/,.*$/, '') : ''}.`,
  };
}

/**
 * The first preset whose material parameters all equal `params` (to 1e-9 relative), or undefined.
 * @template {{ id: string }} P
 * @param {P[]} presets
 * @param {Record<string, number>} params
 * @returns {P | undefined}
 */
export const matchingPreset = (presets, params) =>
  presets.find((p) => MATERIAL_KEYS.every((k) => Math.abs(p[k] - params[k]) <= 1e-9 * Math.abs(p[k])));

/**
 * The outline drawing's box in SVG coordinates (x right, y down: y_svg = −y_mm): the points'
 * bounds with a 6 % margin as a viewBox, the span and chord (mm, at least 1e-6), and `scale`,
 * the larger of the two (marker sizes are fractions of it).
 * @param {[number, number][]} pts mm
 */
export function outlineBox(pts) {
  let x0 = Infinity,
    x1 = -Infinity,
    y0 = Infinity,
    y1 = -Infinity;
  for (const p of pts) {
    const x = p[0],
      y = -p[1];
    x0 = Math.min(x0, x);
    x1 = Math.max(x1, x);
    y0 = Math.min(y0, y);
    y1 = Math.max(y1, y);
  }
  const w = Math.max(x1 - x0, 1e-6),
    h = Math.max(y1 - y0, 1e-6);
  const m = 0.06 * Math.max(w, h);
  return { viewBox: `${x0 - m} ${y0 - m} ${w + 2 * m} ${h + 2 * m}`, w, h, scale: Math.max(w, h) };
}

/**
 * Inserts, after point `i`, the point halfway to the next one (the last point's next is the
 * first), rounded to 0.001 mm. Changes `pts`.
 * @param {[number, number][]} pts
 * @param {number} i
 */
export function insertMidpoint(pts, i) {
  const a = pts[i],
    b = pts[(i + 1) % pts.length];
  pts.splice(i + 1, 0, [Number(((a[0] + b[0]) / 2).toFixed(3)), Number(((a[1] + b[1]) / 2).toFixed(3))]);
}

/**
 * The label of an outline once it is edited: "edited <label>" (at most 80 characters), the label
 * as it is when it already says so, or "edited outline" when there was none.
 * @param {string} label
 */
export const editedLabel = (label) =>
  label && !/^edited/.test(label) ? `edited ${label}`.slice(0, 80) : label || 'edited outline';

/**
 * The store patch that makes the draft the wing in use (the FE mode set): the wing parameters
 * from `p`, the outline, the planform text kept only for an outline from a link, and for an own
 * outline (`own`) the wing record with its checked `input` and a copy of the points.
 * @param {{ outline: string, planform: string, source: string, label: string, points: number[][] | null }} draft
 * @param {Record<string, any>} p the parameters as computed (store and draft)
 * @param {any} own truthy for an own outline
 * @param {any} input the core's checked wing input
 * @returns {Record<string, any>}
 */
export function wingPatch(draft, p, own, input) {
  /** @type {Record<string, any>} */
  const patch = { modes: 'fe', outline: draft.outline, planform: draft.source === 'url' ? draft.planform : '' };
  for (const w of WING) patch[w.key] = p[w.key];
  patch.wing = own
    ? {
        input,
        source: draft.source,
        label: draft.label,
        outline: 'own',
        points: draft.points && draft.points.map((q) => [q[0], q[1]]),
      }
    : null;
  return patch;
}
