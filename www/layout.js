// @ts-check
// The lab's grid, from the element's own width and the panels shown (pure; unit-tested in
// tests/js/layout.test.mjs). www/lab.js writes the result into the shadow root's grid as
// inline `grid-template-columns` / `grid-template-areas` and gives each panel `grid-area:
// <name>`, so no panel subset ever leaves empty cells.
//
//   mode    narrow (< 720 px, the `embed` attribute, or layout="narrow"): one column, DOM order
//           medium (720–1099 px) and wide (≥ 1100 px): two or three columns
//   full set (or any set that has the first row: wide = wing3d, controls, time; medium =
//           wing3d, controls): the designed template below; a missing panel's cells go to its
//           neighbour in the same row, a row with none of its panels left is dropped
//   any other subset: the sliders (controls, 250 px) as a sidebar beside the other panels —
//           on the right when the 3-D wing is shown (it comes first, as in the template), else
//           on the left; wide packs the other panels two per row, the broad ones (experiments,
//           wing, studies, resonance, report, sensing, neural) and a lone last one span both columns; the
//           3-D wing pairs with the guided experiments (the sensing screen).

export const WIDE_AT = 1100;
export const MEDIUM_AT = 720;
/** The width of the sliders' column in the two- and three-column layouts. */
export const SIDEBAR = '250px';
const FR = 'minmax(0, 1fr)';

/** @typedef {'wide' | 'medium' | 'narrow'} LayoutMode */
/** @typedef {{ columns: string[], rows: string[][] }} Grid */

/** The designed layouts for the full lab (DOM order = tab order = visual order). */
export const TEMPLATES = {
  wide: {
    columns: ['minmax(0, 1.3fr)', SIDEBAR, FR],
    rows: [
      ['wing3d', 'controls', 'time'],
      ['experiments', 'experiments', 'experiments'],
      ['wing', 'wing', 'kinematics'],
      ['spectrum', 'spectrum', 'numbers'],
      ['modeshape', 'strain', 'strain'],
      ['sensing', 'sensing', 'sensing'],
      ['neural', 'neural', 'neural'],
      ['studies', 'studies', 'studies'],
      ['resonance', 'resonance', 'resonance'],
      ['report', 'report', 'report'],
    ],
  },
  medium: {
    columns: [FR, SIDEBAR],
    rows: [
      ['wing3d', 'controls'],
      ['time', 'time'],
      ['experiments', 'experiments'],
      ['wing', 'wing'],
      ['kinematics', 'kinematics'],
      ['spectrum', 'spectrum'],
      ['numbers', 'numbers'],
      ['modeshape', 'modeshape'],
      ['strain', 'strain'],
      ['sensing', 'sensing'],
      ['neural', 'neural'],
      ['studies', 'studies'],
      ['resonance', 'resonance'],
      ['report', 'report'],
    ],
  },
};

/** Panels that take a whole row of the main area in the sidebar layout. */
export const BROAD = ['experiments', 'wing', 'studies', 'resonance', 'report', 'sensing', 'neural'];

/**
 * The layout mode: `forced` (the `layout` attribute) wins, then `embed` (compact, one column),
 * then the element's width.
 * @param {number} width the element's own width (CSS px)
 * @param {{ embed?: boolean, forced?: string | null }} [opts]
 * @returns {LayoutMode}
 */
export function layoutMode(width, opts = {}) {
  if (opts.forced === 'wide' || opts.forced === 'medium' || opts.forced === 'narrow') return opts.forced;
  if (opts.embed) return 'narrow';
  return width >= WIDE_AT ? 'wide' : width >= MEDIUM_AT ? 'medium' : 'narrow';
}

/**
 * The grid for the panels shown (`visible`, in DOM order) in a layout mode: its column sizes and
 * its rows of area names (each row as long as `columns`; every visible panel's area is a
 * rectangle; no cell is empty).
 * @param {string[]} visible
 * @param {LayoutMode} mode
 * @returns {Grid}
 */
export function gridLayout(visible, mode) {
  if (mode === 'narrow' || visible.length <= 1) return { columns: [FR], rows: visible.map((p) => [p]) };
  const t = TEMPLATES[mode];
  if (t.rows[0].every((p) => visible.includes(p))) {
    const rows = [];
    for (const row of t.rows) {
      if (!row.some((p) => visible.includes(p))) continue;
      rows.push(fillRow(row, visible));
    }
    // A visible panel that the template does not place (none today) goes in a row of its own.
    for (const p of visible) if (!rows.some((r) => r.includes(p))) rows.push(t.columns.map(() => p));
    return { columns: t.columns.slice(), rows };
  }
  return sidebarLayout(visible, mode);
}

/** A template row with each hidden panel's cells given to the nearest visible one (left first). */
function fillRow(row, visible) {
  return row.map((p, i) => {
    if (visible.includes(p)) return p;
    for (let j = i - 1; j >= 0; j--) if (visible.includes(row[j])) return row[j];
    for (let j = i + 1; j < row.length; j++) if (visible.includes(row[j])) return row[j];
    return p;
  });
}

/**
 * @param {string[]} visible
 * @param {'wide' | 'medium'} mode
 * @returns {Grid}
 */
function sidebarLayout(visible, mode) {
  const side = visible.includes('controls');
  const main = visible.filter((p) => p !== 'controls');
  const cols = mode === 'wide' ? 2 : 1;
  /** @type {string[][]} the main area's rows */
  const rows = [];
  for (let i = 0; i < main.length; i++) {
    const p = main[i];
    const next = main[i + 1];
    // Two narrow panels share a row; so do the 3-D wing and the guided experiments (text that
    // reads well at half width; the sensing screen: wing3d, experiments, sensing).
    const pair = next && ((!BROAD.includes(p) && !BROAD.includes(next)) || (p === 'wing3d' && next === 'experiments'));
    if (cols === 2 && pair) {
      rows.push([p, next]);
      i++;
    } else rows.push(Array(cols).fill(p));
  }
  if (!side) {
    return { columns: Array(cols).fill(FR), rows };
  }
  if (rows.length === 0) return { columns: [FR], rows: [['controls']] };
  const right = main.includes('wing3d');
  return {
    columns: right ? [...Array(cols).fill(FR), SIDEBAR] : [SIDEBAR, ...Array(cols).fill(FR)],
    rows: rows.map((r) => (right ? [...r, 'controls'] : ['controls', ...r])),
  };
}

/**
 * The CSS value of `grid-template-areas` for a grid's rows.
 * @param {string[][]} rows
 */
export function areasCss(rows) {
  return rows.map((r) => `"${r.join(' ')}"`).join(' ');
}
