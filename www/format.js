// @ts-check
// Number and unit formatting shared by the views and the exports. Pure (no DOM); unit-tested
// in tests/js/format.test.mjs.
//
// Labels are written with a light markup: `x_sub`, `x_{sub}`, `x^sup`, `x^{sup}` (e.g. "f_d",
// "γ_{xy}", "kg^½·m", "(…)^2/Hz"). `parseRich` splits such a label into runs that the DOM
// (www/dom.js `rich`) renders with <sub>/<sup> and canvases (www/export.js `drawRich`) with
// smaller, shifted glyphs; `plain` gives a caret-free Unicode version for places that only take
// text (aria-labels, tooltips). The CSV files keep their historical ASCII headers (`kg^½·m`).

/** Units. `label` is rich markup, `csv` the CSV header form (unchanged from earlier releases). */
export const UNITS = {
  q: { label: 'kg^½·m', csv: 'kg^½·m' },
  force: { label: 'kg^½·m/s^2', csv: 'kg^½·m/s²' },
  qpsd: { label: '(kg^½·m)^2/Hz', csv: '(kg^½·m)^2/Hz' },
  fpsd: { label: '(kg^½·m/s^2)^2/Hz', csv: '(kg^½·m/s²)^2/Hz' },
};

/** Explains "paper units" wherever they are used. */
export const PAPER_UNITS_NOTE =
  'Paper units: the paper’s Table 4 gives the modal force coefficients a_k in units that are not SI for mass-normalised modes, so absolute q, forces and strains of the paper mode set are on the paper’s own scale (about 10× below SI). Shares, spectra shapes, frequencies and beat periods do not depend on that scale. Choose the FE wing mode set for SI values.';

/** Significant-digit formatting; exponent form outside [1e-3, 1e5). */
export function fmt(v, digits = 4) {
  if (v == null || Number.isNaN(v)) return '—';
  if (!Number.isFinite(v)) return v > 0 ? '∞' : '−∞';
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a >= 1e5 || a < 1e-3) return v.toExponential(digits - 1);
  return Number(v.toPrecision(digits)).toString();
}

/** Like fmt, but exponents as "×10^k" markup (for rich text). */
export function fmtRich(v, digits = 3) {
  const s = fmt(v, digits);
  const m = /^(-?[\d.]+)e([+-]\d+)$/.exec(s);
  if (!m) return s;
  return `${m[1]}×10^{${Number(m[2])}}`.replace('-', '−');
}

const SUP = {
  0: '⁰',
  1: '¹',
  2: '²',
  3: '³',
  4: '⁴',
  5: '⁵',
  6: '⁶',
  7: '⁷',
  8: '⁸',
  9: '⁹',
  '-': '⁻',
  '−': '⁻',
  '+': '⁺',
  '½': '½',
};

/**
 * Splits rich markup into runs: [{ text, kind: 'normal' | 'sub' | 'sup' }]. `_` and `^` take
 * one character, or a {braced} group. A lone `_`/`^` at the end is kept as text.
 */
export function parseRich(s) {
  /** @type {{ text: string, kind: 'normal' | 'sub' | 'sup' }[]} */
  const runs = [];
  /** @param {string} text @param {'normal' | 'sub' | 'sup'} kind */
  const push = (text, kind) => {
    if (!text) return;
    const last = runs[runs.length - 1];
    if (last && last.kind === kind) last.text += text;
    else runs.push({ text, kind });
  };
  const str = String(s);
  let i = 0;
  while (i < str.length) {
    const c = str[i];
    if ((c === '_' || c === '^') && i + 1 < str.length) {
      const kind = c === '_' ? 'sub' : 'sup';
      if (str[i + 1] === '{') {
        const j = str.indexOf('}', i + 2);
        if (j > 0) {
          push(str.slice(i + 2, j), kind);
          i = j + 1;
          continue;
        }
      }
      // one code point
      const cp = String.fromCodePoint(/** @type {number} i + 1 < length */ (str.codePointAt(i + 1)));
      push(cp, kind);
      i += 1 + cp.length;
      continue;
    }
    push(c, 'normal');
    i++;
  }
  return runs;
}

/** Caret-free plain text: superscripts in Unicode where they exist; subscripts written inline. */
export function plain(s) {
  return parseRich(s)
    .map((r) => {
      if (r.kind === 'sup')
        return [...r.text].every((ch) => SUP[ch]) ? [...r.text].map((ch) => SUP[ch]).join('') : r.text;
      return r.text;
    })
    .join('');
}

/** Seconds with a sensible number of digits. */
export function fmtS(v, digits = 4) {
  return `${fmt(v, digits)} s`;
}

/** Percent with one decimal. */
export function pct(v) {
  return Number.isFinite(v) ? `${v.toFixed(1)} %` : '—';
}

/**
 * The message of a thrown value (an Error's message, a wasm error's text, anything else as text).
 * @param {unknown} e
 * @returns {string}
 */
export function errorText(e) {
  if (e instanceof Error) return e.message;
  if (e && typeof e === 'object' && 'message' in e) return String(e.message);
  return String(e);
}
