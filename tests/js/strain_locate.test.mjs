// Finding where a modes document's strain point is (www/modesdoc.js locateStrainPoint): the
// modal strain at a point is the barycentric interpolation of its triangle's nodal strains, so
// strains interpolated at a known point of a small synthetic mesh must lead back to that point;
// strains that no triangle gives must not be placed anywhere. Run: node --test tests/js/strain_locate.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { locateStrainPoint, modesDocument, CHOSEN_POINT } from '../../www/modesdoc.js';

// A 2 × 1 mm rectangle of two triangles (nodes in m, a little camber in z), two modes.
const nodes = Float64Array.from([0, 0, 0, 2e-3, 0, 1e-5, 2e-3, -1e-3, 2e-5, 0, -1e-3, 0]);
const triangles = Uint32Array.from([0, 1, 2, 0, 2, 3]);
const nn = 4,
  nm = 2;
const strainNodes = Float64Array.from({ length: nm * nn * 3 }, (_, i) => Math.sin(1.7 * i + 0.3) * (1 + (i % 5)));
const at = (tri, l) =>
  Array.from({ length: nm }, (_, k) => {
    const e = [0, 0, 0];
    tri.forEach((node, c) => {
      for (let j = 0; j < 3; j++) e[j] += l[c] * strainNodes[(k * nn + node) * 3 + j];
    });
    return { eps_x: e[0], eps_y: e[1], gamma_xy: e[2] };
  });

test('strains interpolated at a point lead back to that point (mm)', () => {
  // Point in the second triangle (0, 2, 3) with weights 0.2, 0.5, 0.3.
  const l = [0.2, 0.5, 0.3];
  const want = [0, 2, 3].reduce(
    (p, node, c) => [p[0] + 1e3 * l[c] * nodes[3 * node], p[1] + 1e3 * l[c] * nodes[3 * node + 1]],
    [0, 0],
  );
  const got = locateStrainPoint(nodes, triangles, strainNodes, at([0, 2, 3], l));
  assert.ok(got && Math.hypot(got[0] - want[0], got[1] - want[1]) < 1e-6, `${got} vs ${want}`);
});

test('strains that no triangle gives are not placed', () => {
  const t = at([0, 1, 2], [0.3, 0.3, 0.4]).map((s) => ({ ...s, eps_x: s.eps_x + 5 }));
  assert.equal(locateStrainPoint(nodes, triangles, strainNodes, t), null);
  assert.equal(locateStrainPoint(nodes, triangles, strainNodes, []), null);
});

test('an export puts the chosen point first in every mode and keeps the others', () => {
  const doc = JSON.stringify({
    modes: [{ freq_hz: 1, a: [1, 0], strains: [{ point: 'P', eps_x: 1, eps_y: 2, gamma_xy: 3 }] }],
  });
  const out = JSON.parse(modesDocument(doc, [{ eps_x: 4, eps_y: 5, gamma_xy: 6 }]));
  assert.deepEqual(
    out.modes[0].strains.map((p) => p.point),
    [CHOSEN_POINT, 'P'],
  );
  assert.equal(out.modes[0].strains[0].eps_x, 4);
  assert.equal(modesDocument(doc, null), doc);
});
