// Unit tests of the Wing panel's pure rules (www/wingform.js) and of reading a `wingbeat modes`
// document into the lab's FE wing (www/modesdoc.js). Run: node --test tests/js/wingform.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { WING } from '../../www/state.js';
import {
  SHOW,
  clean,
  readWingValue,
  matchingPreset,
  outlineBox,
  insertMidpoint,
  editedLabel,
  wingPatch,
} from '../../www/wingform.js';
import { looksLikeModes, feFromModesDocument } from '../../www/modesdoc.js';

const row = (key) => WING.find((w) => w.key === key);

test('every wing parameter has a display rule', () => {
  for (const w of WING) assert.ok(SHOW[w.key], w.key);
});

test('a typed wing value is read in the core’s unit (E typed in GPa), and refused with its range outside it', () => {
  const e = row('e_pa');
  assert.deepEqual(readWingValue(e, '13.11'), { value: 1.311e10 });
  const low = readWingValue(e, String((e.min * 1e-9) / 2));
  assert.ok(
    'error' in low && low.error.startsWith('Young’s modulus E: expected a number in [') && low.error.endsWith('GPa.'),
    JSON.stringify(low),
  );
  for (const bad of ['', ' ', 'x', String(e.max * 1e-9 * 2)]) assert.ok('error' in readWingValue(e, bad), bad);
  // the ends of the range are accepted
  assert.ok('value' in readWingValue(e, String(clean(e.min * 1e-9))));
  assert.ok('value' in readWingValue(e, String(clean(e.max * 1e-9))));
  const n = row('n_modes');
  assert.deepEqual(readWingValue(n, String(n.min)), { value: n.min });
  const frac = readWingValue(n, String(n.min + 0.5));
  assert.ok('error' in frac && frac.error.includes('a whole number'));
  const mesh = readWingValue(row('mesh_mm'), '-1');
  assert.ok(
    'error' in mesh && /mm\.$/.test(mesh.error) && !mesh.error.includes('automatic'),
    'the unit without its note',
  );
});

test('the preset that matches the material parameters, to 1e-9 relative; none for a custom material', () => {
  const PRESETS = [
    { id: 'a', label: 'A', e_pa: 1.311e10, rho: 860, nu: 0.3, thickness_um: 81 },
    { id: 'b', label: 'B', e_pa: 1e7, rho: 860, nu: 0.3, thickness_um: 81 },
  ];
  const p = PRESETS[0];
  const params = { e_pa: p.e_pa * (1 + 1e-12), rho: p.rho, nu: p.nu, thickness_um: p.thickness_um, camber: 0.3 };
  assert.equal(matchingPreset(PRESETS, params), p);
  assert.equal(matchingPreset(PRESETS, { ...params, rho: p.rho + 1 }), undefined);
  assert.equal(matchingPreset(PRESETS, { ...params, e_pa: PRESETS[1].e_pa }), PRESETS[1]);
});

test('the outline’s drawing box: bounds in SVG coordinates (y down) with a 6 % margin', () => {
  const b = outlineBox([
    [0, 0],
    [40, -2],
    [30, -20],
    [0, -12],
  ]);
  assert.equal(b.w, 40);
  assert.equal(b.h, 20);
  assert.equal(b.scale, 40);
  const [x, y, w, h] = b.viewBox.split(' ').map(Number);
  assert.ok(
    Math.abs(x + 2.4) < 1e-12 && Math.abs(y + 2.4) < 1e-12 && Math.abs(w - 44.8) < 1e-12 && Math.abs(h - 24.8) < 1e-12,
    b.viewBox,
  );
  // a degenerate outline still has a finite box
  assert.ok(
    outlineBox([
      [1, 1],
      [1, 1],
      [1, 1],
    ]).scale > 0,
  );
});

test('a point added halfway to the next one (the last wraps to the first), to 0.001 mm', () => {
  const pts = [
    [0, 0],
    [10, 0.0005],
    [10, -10],
  ];
  insertMidpoint(pts, 0);
  assert.deepEqual(pts[1], [5, 0]);
  assert.equal(pts.length, 4);
  insertMidpoint(pts, 3);
  assert.deepEqual(pts[4], [5, -5]);
});

test('an edited outline’s label', () => {
  assert.equal(editedLabel('wing.csv'), 'edited wing.csv');
  assert.equal(editedLabel('edited wing.csv'), 'edited wing.csv');
  assert.equal(editedLabel(''), 'edited outline');
  assert.equal(editedLabel('x'.repeat(100)).length, 80);
});

test('a modes document is told from an outline file', () => {
  assert.equal(looksLikeModes('  {"modes": []}'), true);
  assert.equal(looksLikeModes('[[0, 0], [1, 0], [1, 1]]'), false);
  assert.equal(looksLikeModes('x_mm,y_mm\n0,0'), false);
  assert.equal(looksLikeModes('{"outline": 1}'), false);
  assert.equal(looksLikeModes('{not json'), false);
});

test('a read modes document becomes the lab’s FE wing: typed arrays, per-mode fields, its strain point located', () => {
  // one triangle, one mode; nodal strains (ε_x, ε_y, γ_xy) differ per node, so a point's strains
  // lead back to it: the centroid's strains are the mean of the nodes'
  const nodes = [0, 0, 0, 0.01, 0, 0, 0, -0.01, 0];
  const sn = [1, 0, 0, 0, 2, 0, 0, 0, 3];
  const strains = [{ point: 'P', eps_x: 1 / 3, eps_y: 2 / 3, gamma_xy: 1 }];
  const r = {
    modes: [{ name: 'bending', freq_hz: 20, strains }],
    fe: { nodes, triangles: [0, 1, 2], shapes: [0, 0, 1, 0, 0, 1, 0, 0, 1], strain_nodes: sn },
  };
  const fe = feFromModesDocument(r, '{"modes":[]}');
  assert.ok(
    fe.nodes instanceof Float64Array &&
      fe.triangles instanceof Uint32Array &&
      fe.shapes instanceof Float64Array &&
      fe.strain_nodes instanceof Float64Array,
  );
  assert.deepEqual(Array.from(fe.freq_hz), [20]);
  assert.deepEqual(fe.kinds, ['bending']);
  assert.equal(fe.n_modes, 1);
  assert.equal(fe.n_nodes, 3);
  assert.equal(fe.imported, true);
  assert.equal(fe.modes_json, '{"modes":[]}');
  assert.ok(
    Math.abs(fe.strain_point_mm[0] - 10 / 3) < 1e-6 && Math.abs(fe.strain_point_mm[1] + 10 / 3) < 1e-6,
    JSON.stringify(fe.strain_point_mm),
  );
  // no strains: no point; no mesh: refused
  assert.equal(feFromModesDocument({ ...r, modes: [{ freq_hz: 20 }] }, '').strain_point_mm, undefined);
  assert.throws(() => feFromModesDocument({ modes: r.modes, fe: null }, ''), /no FE mesh/);
});

test('the patch that makes the draft the wing in use: FE modes, its parameters, an own outline with a copy of its points', () => {
  const p = Object.fromEntries(WING.map((w, k) => [w.key, k + 0.5]));
  const builtin = { outline: 'bee', planform: 'x', source: 'builtin', label: 'Bee', points: [[1, 2]] };
  const a = wingPatch(builtin, { ...p, flap_hz: 99 }, false, { any: 1 });
  assert.equal(a.modes, 'fe');
  assert.equal(a.outline, 'bee');
  assert.equal(a.planform, '', 'the planform text is kept only for an outline from a link');
  assert.equal(a.wing, null, 'a built-in outline needs no wing record');
  for (const w of WING) assert.equal(a[w.key], p[w.key], w.key);
  assert.ok(!('flap_hz' in a), 'only the wing parameters');
  const points = [
    [0, 0],
    [30, -5],
  ];
  const link = { outline: 'manduca', planform: '0,0;30,-5', source: 'url', label: 'from a link', points };
  const input = { planform: 'checked' };
  const b = wingPatch(link, p, true, input);
  assert.equal(b.planform, '0,0;30,-5');
  assert.deepEqual(b.wing, { input, source: 'url', label: 'from a link', outline: 'own', points });
  assert.notEqual(b.wing.points, points, 'a copy: later edits of the draft leave the wing in use alone');
  assert.notEqual(b.wing.points[1], points[1]);
});
