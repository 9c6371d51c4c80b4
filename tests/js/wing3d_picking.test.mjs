// Pointer ↔ wing for the 3-D panel (www/wing3d/picking.js): the sample drawn at a time, the
// strain point under a click, where a planform point is drawn, and where the sensors are drawn.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as P from '../../www/wing3d/picking.js';
import * as S from '../../www/scene3d.js';
import { flatWing as wing } from './wing_fixture.mjs';

/** Screen positions of a top view: x → 10 px per mm right, y → 10 px per mm down (y < 0 on the wing). */
function topView(nodes) {
  const n = nodes.length / 3;
  const xy = new Float64Array(2 * n);
  for (let i = 0; i < n; i++) {
    xy[2 * i] = nodes[3 * i] * 1e4;
    xy[2 * i + 1] = -nodes[3 * i + 1] * 1e4;
  }
  return { xy, depth: new Float64Array(n).fill(1) };
}

test('sampleIndex is the nearest sample, clamped to the run', () => {
  const sim = { t: new Float64Array(101), sample_rate_hz: 1000 };
  assert.equal(P.sampleIndex(sim, 0.0504), 50);
  assert.equal(P.sampleIndex(sim, 0.0506), 51);
  assert.equal(P.sampleIndex(sim, 1), 100);
  assert.equal(P.sampleIndex(sim, -1), 0);
});

test('a click on the drawn wing gives the planform point under it in mm; off the wing, none', () => {
  const fe = wing();
  const proj = topView(fe.nodes);
  assert.deepEqual(P.strainPointAt(fe, proj, 250, 100), [25, -10]);
  assert.deepEqual(P.strainPointAt(fe, proj, 123.4567, 45.5), [12.346, -4.55]); // rounded to µm
  assert.equal(P.strainPointAt(fe, proj, 250, 210), null, 'beyond the trailing edge');
  assert.equal(P.strainPointAt(fe, proj, -1, 100), null, 'behind the root');
});

test('a planform point is drawn at its barycentric place among the drawn nodes (cached per wing and point)', () => {
  const fe = wing();
  const hits = P.planformHits();
  const hit = hits(fe, 12.3, -4.5);
  assert.ok(hit);
  assert.equal(hits(fe, 12.3, -4.5), hit, 'the same point again is the cached answer');
  assert.ok(Math.abs(hit.w[0] + hit.w[1] + hit.w[2] - 1) < 1e-12);
  // any affine screen map is reproduced exactly by the weights
  const n = fe.nodes.length / 3;
  const xy = new Float64Array(2 * n);
  for (let i = 0; i < n; i++) {
    xy[2 * i] = 1000 * fe.nodes[3 * i] + 5;
    xy[2 * i + 1] = 2000 * fe.nodes[3 * i + 1] + 300;
  }
  const at = P.drawnAt(hit, { xy });
  assert.ok(Math.abs(at[0] - 17.3) < 1e-9 && Math.abs(at[1] - 291) < 1e-9, `${at}`);
  assert.equal(hits(fe, 60, -5), null, 'past the tip');
  xy.fill(NaN);
  assert.equal(P.drawnAt(hit, { xy }), null, 'behind the eye');
});

test('screenNodes and sensorPoints draw nodes where projectNodes does (pose, deflection, camera)', () => {
  const fe = wing();
  const n = fe.nodes.length / 3;
  const alpha = Float64Array.of(0, 0.3, 0.6),
    beta = Float64Array.of(0, -0.2, -0.4),
    gamma = Float64Array.of(0, 0.1, 0.2);
  const result = {
    angles: { alpha, beta, gamma },
    analysis: {
      sim: {
        t: Float64Array.of(0, 0.001, 0.002),
        sample_rate_hz: 1000,
        modes: [{ q: { total: Float64Array.of(0, 0.2, 0.4) } }],
      },
    },
  };
  const cam = S.defaultCamera(0.05);
  assert.equal(P.screenNodes(fe, result, null, 0.001, 1, 640, 480), null, 'no camera yet');
  assert.equal(P.screenNodes(fe, { analysis: result.analysis }, cam, 0.001, 1, 640, 480), null, 'no angles yet');
  const sn = P.screenNodes(fe, result, cam, 0.0011, 3, 640, 480);
  assert.deepEqual(sn.ang, [0.3, -0.2, 0.1]);
  assert.deepEqual(sn.q, [0.2]);
  const ref = S.projectNodes(fe.nodes, fe.shapes, [0.2], 3, [0.3, -0.2, 0.1], cam, 640, 480);
  assert.deepEqual(sn.proj.xy, ref.xy);
  const tip = n - 1; // (0.05, −0.02): deflected by 3 · 0.05 · 0.2 = 0.03 m
  const pts = P.sensorPoints(
    fe,
    [
      { node: tip, rank: 1 },
      { node: 0, rank: 2 },
    ],
    sn.ang,
    sn.q,
    3,
    cam,
    640,
    480,
  );
  assert.deepEqual(
    pts.map((p) => p.rank),
    [1, 2],
  );
  assert.ok(Math.abs(pts[0].x - ref.xy[2 * tip]) < 1e-9 && Math.abs(pts[0].y - ref.xy[2 * tip + 1]) < 1e-9);
  assert.ok(Math.abs(pts[1].x - ref.xy[0]) < 1e-9 && Math.abs(pts[1].y - ref.xy[1]) < 1e-9);
  const flat = P.sensorPoints(fe, [{ node: tip, rank: 1 }], sn.ang, sn.q, 0, cam, 640, 480)[0];
  assert.ok(Math.hypot(flat.x - pts[0].x, flat.y - pts[0].y) > 5, 'the deflection moves the sensor on screen');
  // a camera at x = 10 mm looking toward −x: the tip (x = 50 mm) is behind the eye, the root in front
  const near = { target: [0, 0, 0], yaw: 0, pitch: 0, distance: 0.01, fov: cam.fov };
  const [tipPt, rootPt] = P.sensorPoints(
    fe,
    [
      { node: tip, rank: 1 },
      { node: 0, rank: 2 },
    ],
    [0, 0, 0],
    [0],
    0,
    near,
    640,
    480,
  );
  assert.ok(Number.isNaN(tipPt.x) && Number.isNaN(tipPt.y));
  assert.ok(Math.abs(rootPt.x - 320) < 1e-9 && Math.abs(rootPt.y - 240) < 1e-9, 'the target is drawn at the centre');
});
