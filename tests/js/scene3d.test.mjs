// Pure 3-D maths (www/scene3d.js): the camera mirror, the stroke fit, the run-wide strain range.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as S from '../../www/scene3d.js';
import { prng } from './prng.mjs';
import { flatWing } from './wing_fixture.mjs';

// The shared flat wing (wing_fixture.mjs), its triangles named `tris` here.
function wing() {
  const { nodes, triangles } = flatWing();
  return { nodes, tris: triangles };
}

test('the default camera projects its target to the image centre; orbit/zoom mirror the renderer', () => {
  const cam = S.defaultCamera(0.05);
  const p = S.projector(cam, 640, 480)(...cam.target);
  assert.ok(Math.abs(p[0] - 320) < 1e-9 && Math.abs(p[1] - 240) < 1e-9);
  const c2 = S.orbit(cam, 100, -20);
  assert.ok(Math.abs(c2.yaw - (cam.yaw - 0.8)) < 1e-12);
  assert.ok(Math.abs(c2.pitch - (cam.pitch - 0.16)) < 1e-12);
  assert.equal(S.orbit(cam, 0, 1e6).pitch, Math.PI / 2 - 0.01);
  assert.ok(Math.abs(S.zoom(cam, 2).distance - 2 * cam.distance) < 1e-15);
  assert.equal(S.key(cam, 'x'), null);
  // moveTo gives the orbit/zoom that reproduce a target camera
  const to = { ...cam, yaw: -1.5, pitch: 0.4, distance: 0.2 };
  const m = S.moveTo(cam, to);
  const got = S.zoom(S.orbit(cam, m.dx, m.dy), m.zoom);
  for (const k of ['yaw', 'pitch', 'distance']) assert.ok(Math.abs(got[k] - to[k]) < 1e-12, k);
});

test('rotate is R_x(α)·R_y(β)·R_z(γ) (the renderer’s wing rotation)', () => {
  const r = S.rotate(0, 0, Math.PI / 2, [1, 0, 0]);
  assert.ok(Math.abs(r[0]) < 1e-12 && Math.abs(r[1] - 1) < 1e-12);
  const b = S.rotate(0, Math.PI / 2, 0, [1, 0, 0]);
  assert.ok(Math.abs(b[2] + 1) < 1e-12);
  const a = S.rotate(Math.PI / 2, 0, 0, [0, 1, 0]);
  assert.ok(Math.abs(a[2] - 1) < 1e-12);
});

test('fitDistance keeps every pose of a stroke inside the image; bestView covers more than the default', () => {
  const { nodes, tris } = wing();
  const poses = [];
  for (let j = 0; j < 24; j++) {
    const ph = (2 * Math.PI * j) / 24;
    poses.push([0.8 * Math.sin(ph), 0.5 * Math.sin(ph), 0.2 * Math.sin(ph)]);
  }
  const span = S.spanOf(nodes);
  const pts = S.posePoints(nodes, poses);
  const cam = S.defaultCamera(span);
  const d = S.fitDistance(cam, pts, 640, 480, 0.05);
  const bb = S.bbox({ ...cam, distance: d }, pts, 640, 480);
  assert.ok(
    bb[0] >= 0.05 * 640 - 1e-6 &&
      bb[2] <= 0.95 * 640 + 1e-6 &&
      bb[1] >= 0.05 * 480 - 1e-6 &&
      bb[3] <= 0.95 * 480 + 1e-6,
    `${bb}`,
  );
  // tight: slightly closer and something leaves the margin
  const bb2 = S.bbox({ ...cam, distance: d * 0.97 }, pts, 640, 480);
  assert.ok(bb2[0] < 0.05 * 640 || bb2[2] > 0.95 * 640 || bb2[1] < 0.05 * 480 || bb2[3] > 0.95 * 480);
  const best = S.bestView(span, nodes, tris, poses, 640, 480);
  const dflt =
    poses.reduce(
      (s, p) => s + S.projectedArea({ ...cam, distance: cam.distance * 1.35 }, nodes, tris, p, 640, 480),
      0,
    ) /
    poses.length /
    (640 * 480);
  assert.ok(best.coverage > dflt, `${best.coverage} vs ${dflt}`);
  const bb3 = S.bbox(best.camera, pts, 640, 480);
  assert.ok(bb3[0] >= 0 && bb3[2] <= 640 && bb3[1] >= 0 && bb3[3] <= 480);
});

test('hull2 and extremeStates: extremes of linear functions over the run are hull vertices', () => {
  const n = 5000;
  const q1 = Float64Array.from({ length: n }, (_, i) => Math.sin(i / 37));
  const q2 = Float64Array.from({ length: n }, (_, i) => 0.3 * Math.cos(i / 11));
  const states = S.extremeStates([q1, q2]);
  assert.ok(states.length < 400);
  for (const [a, b] of [
    [1, 0],
    [0.3, -2],
    [-1, 1],
  ]) {
    let brute = 0;
    for (let i = 0; i < n; i++) brute = Math.max(brute, Math.abs(a * q1[i] + b * q2[i]));
    const hull = Math.max(...states.map(([x, y]) => Math.abs(a * x + b * y)));
    assert.ok(Math.abs(brute - hull) < 1e-12);
  }
});

test('strainRanges: one fixed range per component from the run’s extremes (robust over nodes)', () => {
  const nNodes = 100;
  const strain = new Float64Array(2 * nNodes * 3);
  for (let i = 0; i < nNodes; i++) {
    strain[i * 3] = i / 100; // mode 0 ε_x grows along the nodes
    strain[(nNodes + i) * 3 + 2] = 1; // mode 1 γ_xy uniform
  }
  strain[99 * 3] = 1000; // a clamp-corner singularity: ignored by the robust quantile
  const q1 = Float64Array.from({ length: 1000 }, (_, i) => 2 * Math.sin(i / 10));
  const q2 = Float64Array.from({ length: 1000 }, (_, i) => 0.5 * Math.cos(i / 7));
  const r = S.strainRanges(strain, nNodes, [q1, q2], 0.98);
  assert.ok(
    Math.abs(S.strainRanges(strain, nNodes, [q1, q2])[1] - (0.89 * r[1]) / 0.97) < 1e-9,
    'default quantile 0.9',
  );
  let m1 = 0,
    m2 = 0;
  for (let i = 0; i < 1000; i++) {
    m1 = Math.max(m1, Math.abs(q1[i]));
    m2 = Math.max(m2, Math.abs(q2[i]));
  }
  assert.ok(Math.abs(r[1] - 0.97 * m1) < 1e-9, `${r[1]}`);
  assert.equal(r[2], 0);
  assert.ok(Math.abs(r[3] - m2) < 1e-9);
  assert.ok(r[4] >= r[1] && r[4] >= r[3] / Math.SQRT2 - 1e-12);
  const shapes = new Float64Array(2 * nNodes).fill(0.001);
  const dmax = S.maxDeflection(shapes, nNodes, [q1, q2]);
  let brute = 0;
  for (let i = 0; i < 1000; i++) brute = Math.max(brute, Math.abs(0.001 * (q1[i] + q2[i])));
  assert.ok(Math.abs(dmax - brute) < 1e-15);
});

test("statesAt / strainRangesAt / maxDeflectionAt: given sample indices (the core's extreme_samples) give the same ranges", () => {
  const nNodes = 50;
  const strain = Float64Array.from({ length: 2 * nNodes * 3 }, (_, j) => Math.sin(j * 0.7));
  const shapes = Float64Array.from({ length: 2 * nNodes }, (_, j) => 1e-3 * Math.cos(j * 0.3));
  const q1 = Float64Array.from({ length: 3000 }, (_, i) => 2 * Math.sin(i / 10));
  const q2 = Float64Array.from({ length: 3000 }, (_, i) => 0.5 * Math.cos(i / 7) + 0.1 * Math.sin(i / 300));
  const idx = S.hull2(q1, q2).sort((a, b) => a - b);
  const states = S.statesAt([q1, q2], Uint32Array.from([...idx, 99999]));
  assert.equal(states.length, idx.length, 'an index past the end is skipped');
  assert.deepEqual(S.strainRangesAt(strain, nNodes, states), S.strainRanges(strain, nNodes, [q1, q2]));
  assert.equal(S.maxDeflectionAt(shapes, nNodes, states), S.maxDeflection(shapes, nNodes, [q1, q2]));
  assert.equal(S.maxDeflectionAt(shapes, nNodes, []), 0, 'no states: 0, not NaN');
  assert.deepEqual(S.strainRangesAt(strain, nNodes, []), { 1: 0, 2: 0, 3: 0, 4: 0 });
});

test('hull2 with the interior filter equals the plain hull; outline holds every node', () => {
  const n = 3000;
  const xs = Float64Array.from({ length: n }, (_, i) => Math.sin(i * 0.37) * (1 + 0.3 * Math.sin(i * 0.011)));
  const ys = Float64Array.from({ length: n }, (_, i) => Math.cos(i * 0.23) * 0.5);
  const h = S.hull2(xs, ys);
  // every point is inside or on the hull polygon
  for (let i = 0; i < n; i += 7) {
    for (let j = 0; j < h.length; j++) {
      const a = h[j],
        b = h[(j + 1) % h.length];
      assert.ok((xs[b] - xs[a]) * (ys[i] - ys[a]) - (ys[b] - ys[a]) * (xs[i] - xs[a]) >= -1e-12);
    }
  }
  const small = S.hull2(xs.slice(0, 50), ys.slice(0, 50));
  assert.ok(small.length >= 3);
  // outline: bbox of all nodes at any pose equals that of the outline with the camber lift
  const nodes = [];
  for (let i = 0; i <= 20; i++)
    for (let j = 0; j <= 8; j++) nodes.push(0.0025 * i, -0.003 * j * (1 - i / 25), 0.002 * Math.sin((Math.PI * j) / 8));
  const N = Float64Array.from(nodes);
  const ol = S.outline(N);
  assert.ok(ol.nodes.length / 3 < 40);
  const cam = { ...S.defaultCamera(0.05), pitch: 0.6 };
  const poses = [
    [0.5, 0.3, 0.1],
    [-0.7, -0.4, 0],
  ];
  const all = S.bbox(cam, S.posePoints(N, poses), 640, 480);
  const few = S.bbox(cam, S.posePoints(ol.nodes, poses, { lift: ol.zmax }), 640, 480);
  assert.ok(few[0] <= all[0] + 1e-9 && few[1] <= all[1] + 1e-9 && few[2] >= all[2] - 1e-9 && few[3] >= all[3] - 1e-9);
});

// ---------- strain maps, picking and the colour map (mode viewer, strain panel) ----------

/** Deterministic pseudo-random numbers in [−1, 1) (tests/js/prng.mjs). */
function rng(seed) {
  const u = prng(seed);
  return () => 2 * u() - 1;
}

test('strainMapJs: RMS equals the sample RMS for every component; peak bounds every sample', () => {
  const { nodes } = wing();
  const n = nodes.length / 3,
    m = 3,
    nT = 500;
  const r = rng(7);
  const sn = Float64Array.from({ length: 3 * n * m }, () => 1e-3 * r());
  const qs = Array.from({ length: m }, (_, k) =>
    Float64Array.from({ length: nT }, (_, t) => Math.sin(0.05 * (k + 1) * t + k) + 0.3 * r()),
  );
  const at = (i, t) => {
    const e = [0, 0, 0];
    for (let k = 0; k < m; k++) for (let c = 0; c < 3; c++) e[c] += sn[(k * n + i) * 3 + c] * qs[k][t];
    return e;
  };
  const value = {
    eps_x: (e) => e[0],
    eps_y: (e) => e[1],
    gamma_xy: (e) => e[2],
    von_mises: (e) => S.vonMisesStrain(e[0], e[1], e[2]),
  };
  for (const component of S.MAP_COMPONENTS) {
    const rms = S.strainMapJs(sn, n, qs, { component, stat: 'rms' });
    const peak = S.strainMapJs(sn, n, qs, { component, stat: 'peak' });
    for (const i of [0, 7, n - 1]) {
      let ms = 0,
        pk = 0;
      for (let t = 0; t < nT; t++) {
        const v = value[component](at(i, t));
        ms += v * v;
        pk = Math.max(pk, Math.abs(v));
      }
      assert.ok(Math.abs(rms[i] - Math.sqrt(ms / nT)) <= 1e-12 + 1e-9 * rms[i], `${component} rms node ${i}`);
      // every sample visited here (500 < maxSamples): exact
      assert.ok(Math.abs(peak[i] - pk) <= 1e-15 + 1e-12 * pk, `${component} peak node ${i}: ${peak[i]} vs ${pk}`);
    }
  }
  // von Mises of a pure shear γ: √¾·|γ|; of uniaxial ε: |ε|
  assert.ok(Math.abs(S.vonMisesStrain(0, 0, 2e-3) - Math.sqrt(0.75) * 2e-3) < 1e-15);
  assert.ok(Math.abs(S.vonMisesStrain(1e-3, 0, 0) - 1e-3) < 1e-15);
});

test('strainMap: the engine’s field when it fits, the JS map otherwise; null for a mismatched run', () => {
  const { nodes, tris } = wing();
  const n = nodes.length / 3;
  const fe = {
    nodes: Float64Array.from(nodes),
    triangles: Uint32Array.from(tris),
    strain_nodes: new Float64Array(3 * n * 2).fill(1e-3),
    n_modes: 2,
  };
  const mk = (m) => ({
    analysis: {
      sim: { modes: Array.from({ length: m }, () => ({ q: { total: Float64Array.from([1, -1, 1, -1]) } })) },
    },
  });
  const res = mk(2);
  const fromEngine = S.strainMap(fe, res, { component: 'eps_x', stat: 'rms' }, () => new Float64Array(n).fill(42));
  assert.equal(fromEngine[0], 42);
  // wrong length from the engine (another wing): the JS map is used
  const js = S.strainMap(fe, mk(2), { component: 'eps_x', stat: 'rms' }, () => new Float64Array(3));
  assert.ok(Math.abs(js[0] - 2e-3) < 1e-15, String(js[0]));
  assert.equal(S.strainMap(fe, mk(3), { component: 'eps_x', stat: 'rms' }), null);
});

test('pick: the planform point under a screen position, front-most triangle, null off the wing', () => {
  const { nodes, tris } = wing();
  const n = nodes.length / 3;
  const top = { xy: new Float64Array(2 * n), depth: new Float64Array(n) };
  for (let i = 0; i < n; i++) {
    top.xy[2 * i] = nodes[3 * i] * 1e3;
    top.xy[2 * i + 1] = nodes[3 * i + 1] * 1e3;
  }
  const h = S.pick(nodes, tris, top, 23.3, -7.1);
  assert.ok(h && Math.abs(h.x - 0.0233) < 1e-12 && Math.abs(h.y + 0.0071) < 1e-12);
  assert.ok(Math.abs(h.w.reduce((a, b) => a + b, 0) - 1) < 1e-12);
  assert.equal(S.pick(nodes, tris, top, 60, -5), null);
  // Seen through the camera at a pose: the picked point projects back under the cursor.
  const cam = S.defaultCamera(0.05);
  const proj = S.projectNodes(nodes, null, [], 1, [0.3, -0.2, 0.1], cam, 640, 480);
  const p = S.rotate(0.3, -0.2, 0.1, [0.02, -0.012, 0]);
  const at = S.projector(cam, 640, 480)(p[0], p[1], p[2]);
  const hit = S.pick(nodes, tris, proj, at[0], at[1]);
  assert.ok(hit && Math.hypot(hit.x - 0.02, hit.y + 0.012) < 2e-4, JSON.stringify(hit));
});

test('colourAt: interpolates the renderer’s stops, clamps, and maps NaN to the middle', () => {
  const stops = [0, 0, 0, 1, 0.5, 1, 1, 1, 1, 1, 0, 0];
  assert.deepEqual(S.colourAt(stops, 0), [0, 0, 255]);
  assert.deepEqual(S.colourAt(stops, 0.25), [128, 128, 255]);
  assert.deepEqual(S.colourAt(stops, 2), [255, 0, 0]);
  assert.deepEqual(S.colourAt(stops, NaN), [255, 255, 255]);
  assert.deepEqual(S.colourAt([], 0.3), [128, 128, 128]);
});

test('backingSize: CSS size × devicePixelRatio, the ratio capped, the area capped keeping the aspect', () => {
  assert.deepEqual(S.backingSize(543, 424, 1, 2, 2e6), { width: 543, height: 424, scale: 1 });
  assert.deepEqual(S.backingSize(390, 281, 3, 2, 2e6), { width: 780, height: 562, scale: 2 });
  const big = S.backingSize(1243, 520, 2, 2, 2e6);
  assert.ok(big.width * big.height <= 2e6 && big.width * big.height > 1.99e6, JSON.stringify(big));
  assert.ok(Math.abs(big.width / big.height - 1243 / 520) < 0.01);
  assert.deepEqual(S.backingSize(100, 50, NaN, 2, 2e6), { width: 100, height: 50, scale: 1 });
});

test('strainRangesAt and maxDeflectionAt: the same numbers as a strain sum per node and state, for 6 modes', async () => {
  const { strainRangesAt, maxDeflectionAt, RANGE_QUANTILE } = await import('../../www/strainmap.js');
  // a seeded wing: 57 nodes, 6 modes, 240 states of mixed signs and scales
  let seed = 12345;
  const rnd = () => {
    seed = (seed * 1103515245 + 12345) % 2147483648;
    return seed / 2147483648 - 0.5;
  };
  const n = 57,
    m = 6;
  const strainNodes = Float64Array.from({ length: 3 * n * m }, () => rnd() * 1e-3);
  const shapes = Float64Array.from({ length: n * m }, () => rnd());
  const states = Array.from({ length: 240 }, (_, s) =>
    Array.from({ length: m }, (_, k) => rnd() * 10 ** (k - (s % 3))),
  );
  // the reference: each node and state summed on its own, the magnitude by its square root
  const mx = [0, 1, 2, 3].map(() => new Float64Array(n));
  let defl = 0;
  for (let i = 0; i < n; i++)
    for (const q of states) {
      const e = [0, 0, 0];
      let w = 0;
      for (let k = 0; k < m; k++) {
        for (let c = 0; c < 3; c++) e[c] += strainNodes[(k * n + i) * 3 + c] * q[k];
        w += shapes[k * n + i] * q[k];
      }
      const mag = Math.sqrt(e[0] * e[0] + e[1] * e[1] + 0.5 * e[2] * e[2]);
      [Math.abs(e[0]), Math.abs(e[1]), Math.abs(e[2]), mag].forEach((v, c) => {
        if (v > mx[c][i]) mx[c][i] = v;
      });
      defl = Math.max(defl, Math.abs(w));
    }
  const quantile = (a) => {
    const s = Array.from(a).sort((x, y) => x - y);
    return s;
  };
  const got = strainRangesAt(strainNodes, n, states, RANGE_QUANTILE);
  // the robust maximum picks a node's value: each limit is exactly one of the reference maxima
  for (let c = 0; c < 4; c++) assert.ok(quantile(mx[c]).includes(got[c + 1]), `component ${c + 1}: ${got[c + 1]}`);
  // and the same one the reference picks with every node's maximum exact
  const all = strainRangesAt(strainNodes, n, states, 1);
  for (let c = 0; c < 4; c++) assert.equal(all[c + 1], Math.max(...mx[c]));
  assert.equal(maxDeflectionAt(shapes, n, states), defl);
  // first m modes only when the states carry more values than the wing has modes
  const wide = states.map((q) => [...q, 5, -7]);
  assert.deepEqual(strainRangesAt(strainNodes, n, wide, RANGE_QUANTILE), got);
  assert.equal(maxDeflectionAt(shapes, n, wide), defl);
});
