// What the 3-D panel marks on the drawn wing (www/wing3d/marks.js), with stand-ins for the
// store, the overlays and the panel's getters: a click picks the strain point it is drawn at,
// only on an FE wing; the ring is hidden without a camera or for the paper mode set; the
// sensors are placed only under the detectability colour.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createWingMarks } from '../../www/wing3d/marks.js';
import { SENSE_COLOUR } from '../../www/wing3d/fields.js';
import * as S from '../../www/scene3d.js';
import { flatWing } from './wing_fixture.mjs';

// The shared flat wing (wing_fixture.mjs) with its strain point at (20, −10) mm.
function wing() {
  return { ...flatWing(), strain_point_mm: [20, -10] };
}

const result = {
  angles: { alpha: Float64Array.of(0, 0.3), beta: Float64Array.of(0, -0.2), gamma: Float64Array.of(0, 0.1) },
  analysis: {
    sim: { t: Float64Array.of(0, 0.001), sample_rate_hz: 1000, modes: [{ q: { total: Float64Array.of(0, 0.1) } }] },
  },
};

/** The marks with stand-ins; `calls` records what reached the overlays. */
function setup({ modes = 'fe', cam = S.defaultCamera(0.05), colour = 1, senseUp = null } = {}) {
  let state = { modes, result, strain_point: null };
  const calls = [];
  const store = {
    get: () => state,
    set: (patch) => {
      state = { ...state, ...patch };
    },
  };
  const overlays = {
    hidePoint: () => calls.push(['hidePoint']),
    placePoint: (at, w, h, p) => calls.push(['placePoint', at, w, h, p]),
    placeLabels: (places) => calls.push(['placeLabels', places]),
    placeSensors: (pts, w, h, regroup) => calls.push(['placeSensors', pts, w, h, regroup]),
  };
  const check = (on) => ({ checked: on });
  const dom = { status: { textContent: '' }, showAxes: check(true), showBody: check(false), showPlane: check(true) };
  const fe = wing();
  const marks = createWingMarks({
    store: /** @type {any} */ (store),
    rig: { cam },
    overlays: /** @type {any} */ (overlays),
    fields: { senseUp },
    dom: /** @type {any} */ (dom),
    fe: () => fe,
    cssSize: () => [640, 480],
    colour: () => colour,
    exaggeration: () => 2,
    tNow: () => 0.001,
  });
  return { marks, calls, dom, store, fe };
}

test('a click where a planform point is drawn picks that point as the strain point (mm)', () => {
  const { marks, store } = setup();
  const at = marks.drawnPoint(30, -12);
  assert.ok(at && Number.isFinite(at[0]) && Number.isFinite(at[1]), `${at}`);
  const mm = marks.pickAt(at[0], at[1]);
  assert.ok(mm && Math.abs(mm[0] - 30) < 0.01 && Math.abs(mm[1] + 12) < 0.01, `${mm}`);
  assert.deepEqual(store.get().strain_point, mm);
  assert.equal(marks.drawnPoint(80, -12), null, 'past the tip');
  // the pose at t = 0 is another drawing of the wing: the same point lands elsewhere
  const at0 = marks.drawnPoint(30, -12, 0);
  assert.ok(Math.hypot(at0[0] - at[0], at0[1] - at[1]) > 1);
});

test('on the paper mode set a click picks nothing and says why', () => {
  const { marks, store, dom } = setup({ modes: 'paper' });
  assert.equal(marks.pickAt(320, 240), null);
  assert.match(dom.status.textContent, /FE wing only/);
  assert.equal(store.get().strain_point, null);
});

test('the ring is placed at the drawn strain point, hidden for the paper modes or without a camera', () => {
  const fe = setup();
  fe.marks.placePoint();
  const [kind, at, w, h, p] = fe.calls[0];
  assert.equal(kind, 'placePoint');
  assert.deepEqual(at, fe.marks.drawnPoint(20, -10));
  assert.deepEqual([w, h, p], [640, 480, [20, -10]], 'the wing’s own point when none is chosen');
  fe.store.set({ strain_point: [40, -5] });
  fe.marks.placePoint();
  assert.deepEqual(fe.calls[1][4], [40, -5]);
  for (const o of [{ modes: 'paper' }, { cam: null }]) {
    const { marks, calls } = setup(o);
    marks.placePoint();
    assert.deepEqual(calls, [['hidePoint']], JSON.stringify(o));
  }
});

test('labels follow the camera; sensors are placed only under the detectability colour', () => {
  const ang = [0.3, -0.2, 0.1];
  const plain = setup();
  plain.marks.placeOverlays(ang, [0.1], 0.001, true);
  assert.deepEqual(
    plain.calls.map((c) => c[0]),
    ['placeLabels', 'placePoint', 'placeSensors'],
  );
  assert.deepEqual(plain.calls[2].slice(1), [null, 0, 0, true]);
  const senseUp = { sensors: [{ node: 54, rank: 1 }] };
  const sensing = setup({ colour: SENSE_COLOUR, senseUp });
  sensing.marks.placeOverlays(ang, [0.1], 0.001, false);
  const [, pts, w, h, regroup] = sensing.calls[2];
  assert.equal(pts.length, 1);
  assert.equal(pts[0].rank, 1);
  assert.deepEqual([w, h, regroup], [640, 480, false]);
  const noCam = setup({ colour: SENSE_COLOUR, senseUp, cam: null });
  noCam.marks.placeOverlays(ang, [0.1], 0.001, true);
  assert.deepEqual(
    noCam.calls,
    [['hidePoint'], ['placeSensors', null, 0, 0, true]],
    'no camera: no labels, no sensors',
  );
});
