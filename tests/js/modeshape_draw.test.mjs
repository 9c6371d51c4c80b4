// The mode-shape viewer's drawing (www/views/modeshape-draw.js): the camera fitted to both
// extremes of the oscillation and the drawing scale, the back-to-front paint order, the two-sided
// shading, and what is painted for a mode (one fill per triangle, the dashed outline, the name).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { DRAWN_FRACTION, modeGeometry, backToFront, shadeOf, paintMode } from '../../www/views/modeshape-draw.js';
import * as S from '../../www/scene3d.js';

/** A 40 mm × 10 mm flat plate of two triangles (nodes in m), with one bending mode z ∝ x. */
function plate() {
  const nodes = [0, 0, 0, 0.04, 0, 0, 0.04, -0.01, 0, 0, -0.01, 0];
  return {
    nodes,
    triangles: [0, 1, 2, 0, 2, 3],
    shapes: [0, 2, 2, 0],
    n_modes: 1,
    kinds: ['spanwise bending'],
    freq_hz: [62.49],
  };
}

test('the deflection is scaled to DRAWN_FRACTION of the span and both extremes fit the canvas', () => {
  const fe = plate();
  const w = 600,
    h = 320;
  const g = modeGeometry(fe, 0, w, h);
  assert.equal(g.max, 2);
  assert.ok(Math.abs(g.scale - (DRAWN_FRACTION * 0.04) / 2) < 1e-15);
  const pr = S.projector(g.cam, w, h);
  for (const sgn of [-1, 1])
    for (let i = 0; i < 4; i++) {
      const p = pr(fe.nodes[3 * i], fe.nodes[3 * i + 1], sgn * g.scale * fe.shapes[i]);
      assert.ok(p, `node ${i} in front of the camera`);
      assert.ok(
        p[0] >= -1e-6 && p[0] <= w + 1e-6 && p[1] >= -1e-6 && p[1] <= h + 1e-6,
        `node ${i} (${sgn}) on the canvas`,
      );
    }
  const flat = modeGeometry({ ...fe, shapes: [0, 0, 0, 0] }, 0, w, h);
  assert.equal(flat.scale, 0, 'a zero shape is drawn flat, never scaled by 1/0');
  assert.ok(Number.isFinite(flat.cam.distance) && flat.cam.distance > 0);
});

test('triangles are painted farthest first', () => {
  const tri = [0, 1, 2, 1, 2, 3, 0, 0, 3];
  const depth = [1, 5, 5, 9];
  assert.deepEqual(Array.from(backToFront(tri, depth)), [1, 0, 2]); // depth sums 11, 19, 11; ties keep their order
  assert.deepEqual(Array.from(backToFront([], [])), []);
});

test('shading is two-sided: 1 facing the light (either side), 0.6 edge-on', () => {
  const pa = [0, 0, 0],
    pb = [1, 0, 0],
    pc = [0, 1, 0]; // normal along +z
  assert.ok(Math.abs(shadeOf(pa, pb, pc, [0, 0, 2], 2) - 1) < 1e-12);
  assert.ok(Math.abs(shadeOf(pa, pc, pb, [0, 0, 2], 2) - 1) < 1e-12, 'the back face too');
  assert.ok(Math.abs(shadeOf(pa, pb, pc, [3, 0, 0], 3) - 0.6) < 1e-12);
  assert.equal(shadeOf(pa, pa, pa, [0, 0, 1], 1), 0.6, 'a degenerate triangle is not NaN');
});

test('paintMode fills every triangle once, dashes the outline and names the mode', () => {
  const calls = [];
  const c2 = new Proxy(
    {},
    {
      get: (o, k) => (k in o ? o[k] : (...args) => calls.push([k, ...args])),
      set: (o, k, v) => {
        o[k] = v;
        return true;
      },
    },
  );
  const fe = plate();
  const g = modeGeometry(fe, 0, 300, 160);
  const stops = [0, 0, 0, 1, 1, 1, 0, 0];
  paintMode(/** @type {any} */ (c2), fe, 0, g, 90, stops, 300, 160);
  assert.equal(calls.filter((c) => c[0] === 'fill').length, 2);
  assert.deepEqual(
    calls.filter((c) => c[0] === 'setLineDash').map((c) => c[1]),
    [[3, 3], []],
  );
  const text = calls.find((c) => c[0] === 'fillText');
  assert.equal(text[1], 'mode 1: spanwise bending, 62.49 Hz');
  assert.match(c2.fillStyle, /^#222$/);
});
