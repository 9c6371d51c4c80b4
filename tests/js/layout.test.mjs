// The lab's grid (www/layout.js): every visible panel gets one rectangle, no cell is empty,
// the full set keeps the designed templates, subsets fill the width. LAYOUT is the lab's own
// panel list (www/lab/panels.js), so a panel of state.js missing from it fails here.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { layoutMode, gridLayout, areasCss, TEMPLATES, WIDE_AT, MEDIUM_AT } from '../../www/layout.js';
import { PANELS } from '../../www/state.js';
import { LAYOUT } from '../../www/lab/panels.js';
import { prng } from './prng.mjs';

/** Every visible panel occupies a rectangle; every cell holds a visible panel. */
function checkGrid(g, visible) {
  for (const r of g.rows) assert.equal(r.length, g.columns.length, JSON.stringify(g));
  const cells = new Map();
  g.rows.forEach((r, y) => {
    r.forEach((p, x) => {
      assert.ok(visible.includes(p), `cell ${p} not visible`);
      if (!cells.has(p)) cells.set(p, []);
      cells.get(p).push([x, y]);
    });
  });
  for (const p of visible) {
    const c = cells.get(p);
    assert.ok(c, `${p} placed`);
    const xs = c.map((v) => v[0]),
      ys = c.map((v) => v[1]);
    const w = Math.max(...xs) - Math.min(...xs) + 1,
      h = Math.max(...ys) - Math.min(...ys) + 1;
    assert.equal(w * h, c.length, `${p} is a rectangle in ${areasCss(g.rows)}`);
  }
}

test('layout mode: width, embed, forced', () => {
  assert.equal(layoutMode(WIDE_AT), 'wide');
  assert.equal(layoutMode(WIDE_AT - 1), 'medium');
  assert.equal(layoutMode(MEDIUM_AT), 'medium');
  assert.equal(layoutMode(MEDIUM_AT - 1), 'narrow');
  assert.equal(layoutMode(1400, { embed: true }), 'narrow');
  assert.equal(layoutMode(600, { forced: 'wide' }), 'wide');
  assert.equal(layoutMode(600, { forced: 'bogus' }), 'narrow');
});

test('the templates name every panel of state.js once per row set', () => {
  for (const t of Object.values(TEMPLATES)) assert.deepEqual([...new Set(t.rows.flat())].sort(), [...PANELS].sort());
  assert.deepEqual([...LAYOUT].sort(), [...PANELS].sort());
});

test('full set: the designed templates', () => {
  assert.deepEqual(gridLayout(LAYOUT, 'wide').rows, TEMPLATES.wide.rows);
  assert.deepEqual(gridLayout(LAYOUT, 'medium').rows, TEMPLATES.medium.rows);
  assert.deepEqual(
    gridLayout(LAYOUT, 'narrow').rows,
    LAYOUT.map((p) => [p]),
  );
});

test('subsets never leave empty cells', () => {
  // every subset of a handful of panels, and a few random larger ones
  const some = ['wing3d', 'controls', 'time', 'spectrum', 'numbers', 'studies', 'report'];
  for (let m = 1; m < 1 << some.length; m++) {
    const vis = LAYOUT.filter((p) => some.includes(p) && (m >> some.indexOf(p)) & 1);
    for (const mode of ['wide', 'medium', 'narrow']) checkGrid(gridLayout(vis, /** @type {any} */ (mode)), vis);
  }
  const rnd = prng(7);
  for (let k = 0; k < 300; k++) {
    const vis = LAYOUT.filter(() => rnd() < 0.6);
    if (!vis.length) continue;
    for (const mode of ['wide', 'medium', 'narrow']) checkGrid(gridLayout(vis, /** @type {any} */ (mode)), vis);
  }
});

test('controls, numbers, spectrum: sliders beside the plots', () => {
  const vis = ['controls', 'spectrum', 'numbers'];
  assert.equal(areasCss(gridLayout(vis, 'medium').rows), '"controls spectrum" "controls numbers"');
  assert.equal(areasCss(gridLayout(vis, 'wide').rows), '"controls spectrum numbers"');
  assert.equal(gridLayout(vis, 'medium').columns[0], '250px');
  // with the 3-D wing first, the sliders go on its right (as in the full layout)
  assert.equal(areasCss(gridLayout(['wing3d', 'controls', 'spectrum'], 'wide').rows), '"wing3d spectrum controls"');
  // The sensing screen (no sliders): the 3-D wing beside the experiments, the sensing panel below.
  assert.equal(
    areasCss(gridLayout(['wing3d', 'experiments', 'sensing'], 'wide').rows),
    '"wing3d experiments" "sensing sensing"',
  );
  assert.equal(
    areasCss(gridLayout(['wing3d', 'experiments', 'sensing'], 'medium').rows),
    '"wing3d" "experiments" "sensing"',
  );
  assert.equal(
    areasCss(gridLayout(['wing3d', 'controls', 'spectrum'], 'medium').rows),
    '"wing3d controls" "spectrum spectrum"',
  );
});
