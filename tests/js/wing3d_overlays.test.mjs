// What the 3-D panel draws over its canvas and under it (www/wing3d/overlays.js, legend.js): the
// label, ring and sensor-tag places, the colour bar's gradient and the legends' words.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as O from '../../www/wing3d/overlays.js';
import * as L from '../../www/wing3d/legend.js';
import * as S from '../../www/scene3d.js';

const ALL = { fixed: true, wing: true, body: true, plane: true };

test('labels sit 3 px right of and 14 px above their projected axis tips; switched-off kinds are hidden', () => {
  const span = 0.05;
  const cam = S.defaultCamera(span);
  const pr = S.projector(cam, 640, 480);
  const places = O.labelPlaces(cam, span, [0, 0, 0], 640, 480, ALL);
  assert.equal(places.length, O.LABELS.length);
  const at = (p) => {
    const s = pr(...p);
    return [Math.round(s[0] + 3), Math.round(s[1] - 14)];
  };
  assert.deepEqual(places[0], at([0.35 * span, 0, 0]), 'I');
  assert.deepEqual(places[2], at([0, 0, 0.35 * span]), 'K');
  assert.deepEqual(places[6], at([0, 0.6 * span, 0]), 'body axis');
  // the flapping frame's tips turn with α and β (not γ)
  const ang = [0.4, -0.3, 0.9];
  const turned = O.labelPlaces(cam, span, ang, 640, 480, ALL);
  assert.deepEqual(turned[3], at(S.rotate(0.4, -0.3, 0, [0.7 * span, 0, 0])), 'I″');
  assert.deepEqual(turned[0], places[0], 'the fixed frame does not move');
  const noWing = O.labelPlaces(cam, span, ang, 640, 480, { ...ALL, wing: false, plane: false });
  assert.deepEqual(
    noWing.map((p) => p === null),
    [false, false, false, true, true, true, false, true],
  );
  assert.ok(
    O.labelPlaces(cam, span, ang, 20, 20, ALL).every((p) => p === null),
    'nothing fits on a 20 px canvas',
  );
});

test('the stroke plane label goes to the on-screen plane corner farthest from the wing', () => {
  const span = 0.05;
  const cam = S.defaultCamera(span);
  const pr = S.projector(cam, 640, 480);
  const plane = O.labelPlaces(cam, span, [0, 0, 0], 640, 480, ALL)[7];
  const corners = [
    [1.1, 0, 0.9],
    [1.1, 0, -0.9],
    [0.5, 0, 0.9],
    [0.5, 0, -0.9],
    [-0.1, 0, 0.9],
    [-0.1, 0, -0.9],
    [1.1, 0, 0],
  ]
    .map((c) => pr(...c.map((v) => v * span)))
    .filter((p) => p[0] > 10 && p[0] < 550 && p[1] > 20 && p[1] < 470);
  const mid = pr(0.45 * span, -0.2 * span, 0);
  const far = corners.sort(
    (a, b) => Math.hypot(b[0] - mid[0], b[1] - mid[1]) - Math.hypot(a[0] - mid[0], a[1] - mid[1]),
  )[0];
  assert.deepEqual(plane, [Math.round(far[0] + 3), Math.round(far[1] - 14)]);
  assert.ok(corners.length >= 2, 'the choice was a real one');
});

test('the strain ring is centred on its point and hidden off the canvas; sensor tags stay inside', () => {
  assert.deepEqual(O.ringPlace([100.4, 50.6], 640, 480), [93, 44]);
  assert.equal(O.ringPlace([0, 10], 640, 480), null);
  assert.equal(O.ringPlace([640, 10], 640, 480), null);
  assert.equal(O.ringPlace(null, 640, 480), null);
  assert.deepEqual(O.tagPlace({ x: 100, y: 100 }, '2', 640), [105, 80]);
  assert.deepEqual(O.tagPlace({ x: 630, y: 10 }, '1–3', 640), [604, 0]); // 640 − 8·3 − 12
});

test('the colour bar gradient spans the stops’ own range, colours clamped to 0…255', () => {
  const g = L.gradientStops([0.25, 0, 0, 1, 0.5, 1, 1, 1, 0.75, 1.2, -0.1, 0.5]);
  assert.deepEqual(g, [
    [0, 'rgb(0,0,255)'],
    [0.5, 'rgb(255,255,255)'],
    [1, 'rgb(255,0,128)'],
  ]);
  assert.deepEqual(L.gradientStops([0.3, 0.5, 0.5, 0.5]), [[0, 'rgb(128,128,128)']]);
});

test('the strain legend names the component, its fixed range and its units', () => {
  const lg = { component: 'γ_xy', min: -5.66e-4, max: 5.66e-4 };
  assert.equal(L.strainLegendText(lg, true, null, ''), 'γ_xy: -5.66e-4 … 5.66e-4 strain (–), fixed for the whole run');
  assert.equal(
    L.strainLegendText(lg, false, null, ''),
    'γ_xy: -5.66e-4 … 5.66e-4 (FE strain × paper q: not physical), fixed for the whole run',
  );
  const field = { component: 'field', min: 0, max: 4.86e-4 };
  assert.equal(
    L.strainLegendText(field, true, null, 'RMS over the run of von Mises equivalent strain'),
    'RMS over the run of von Mises equivalent strain: 0 … 4.86e-4 strain (–), one map for the whole run (the hottest 10 % of the nodes saturate)',
  );
  assert.equal(
    L.strainLegendText(field, true, 'the wing and the run do not match yet', 'x'),
    'no strain map: the wing and the run do not match yet',
  );
});

test('the detectability legend gives the rotation, the scale and the sensors; or why there is no map', () => {
  assert.equal(
    L.senseLegendText(null, null, false),
    'No detectability map: no sensing result yet: open the Sensing panel.',
  );
  assert.equal(
    L.senseLegendText({}, 'the FE wing is not ready yet', false),
    'No detectability map: the FE wing is not ready yet.',
  );
  const m = { body_rate: [0, 2, 0], max: 0, mode: 'relative', lo: -2, hi: 0, sensors: [{}, {}, {}] };
  assert.match(L.senseLegendText(m, null, false), /ω_b = 2 rad\/s about body axis y\): D = 0 everywhere/);
  const rel = L.senseLegendText({ ...m, max: 12.5 }, null, false);
  assert.match(rel, /grey = D ≤ 0\.01 \(2 decade below the largest\), dark red = the largest, 12\.5/);
  assert.match(rel, /the 3 best sensors/);
  assert.doesNotMatch(rel, /earlier settings/);
  const abs = L.senseLegendText({ ...m, max: 12.5, mode: 'absolute', lo: -1, hi: 1 }, null, true);
  assert.match(abs, /grey = D ≤ 10\^\{-1\}, dark red = D ≥ 10\^\{1\}; largest on this wing 12\.5/);
  assert.match(abs, /This map is for earlier settings/);
});

test('the legend key changes with what the legend shows, and the sensing map only under colour 6', () => {
  const lg = { component: 'field', min: 0, max: 1 };
  const info = {
    sensing: false,
    fieldProblem: null,
    fieldLabel: 'a',
    senseUp: null,
    senseProblem: null,
    senseStale: false,
  };
  const k = L.legendKey(lg, true, info);
  assert.equal(L.legendKey(lg, true, { ...info, senseUp: { max: 3, mode: 'relative', sensors: [] } }), k);
  assert.notEqual(L.legendKey(lg, false, info), k);
  assert.notEqual(L.legendKey({ ...lg, max: 2 }, true, info), k);
  assert.notEqual(L.legendKey(lg, true, { ...info, fieldLabel: 'b' }), k);
  const s = { ...info, sensing: true, senseUp: { max: 3, mode: 'relative', sensors: [] } };
  assert.notEqual(L.legendKey(lg, true, { ...s, senseUp: { ...s.senseUp, max: 4 } }), L.legendKey(lg, true, s));
  assert.notEqual(L.legendKey(lg, true, { ...s, senseStale: true }), L.legendKey(lg, true, s));
});
