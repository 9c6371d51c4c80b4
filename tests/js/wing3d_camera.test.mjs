// The 3-D panel's camera (www/wing3d/camera.js) and canvas sizing (www/wing3d/canvas.js): the
// fit's lift and refit key, click versus drag, the wheel, and the camera rig against a stand-in
// WingView that records what the renderer was told.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as C from '../../www/wing3d/camera.js';
import { canvasSize, MAX_BACKING_PX } from '../../www/wing3d/canvas.js';
import * as S from '../../www/scene3d.js';
import { flatWing as wing } from './wing_fixture.mjs';

/** A stand-in WingView: keeps a camera, applies orbit/zoom/key as the renderer does, logs calls. */
function fakeView(span) {
  let cam = S.defaultCamera(span);
  const calls = { setCamera: 0, fitPoints: 0, orbit: [], zoom: [] };
  const asArray = (c) => Float64Array.of(...c.target, c.yaw, c.pitch, c.distance);
  return {
    calls,
    get cam() {
      return cam;
    },
    setCamera(tx, ty, tz, yaw, pitch, distance) {
      calls.setCamera++;
      cam = { ...cam, target: [tx, ty, tz], yaw, pitch, distance };
    },
    // the renderer's fit moves its camera: same direction, the stroke fitted by distance (here: the page's own fitDistance)
    fitPoints(pts, margin) {
      calls.fitPoints++;
      cam = { ...cam, distance: S.fitDistance(cam, pts, 640, 480, margin / 2) };
      return asArray(cam);
    },
    orbit(dx, dy) {
      calls.orbit.push([dx, dy]);
      cam = S.orbit(cam, dx, dy);
    },
    zoom(f) {
      calls.zoom.push(f);
      cam = S.zoom(cam, f);
    },
    key(k) {
      const c = S.key(cam, k);
      if (c) cam = c;
      return !!c;
    },
  };
}

test('fitLift frames the drawn deflection, at most two spans (also when it overflows)', () => {
  assert.equal(C.fitLift(0.01, 3, 0.05), 0.03);
  assert.equal(C.fitLift(0.01, 20, 0.05), 0.1);
  assert.equal(C.fitLift(null, 1000, 0.05), 0);
  assert.equal(C.fitLift(1e42, 1e300, 0.05), 0.1, 'an infinite drawn deflection frames two spans');
});

test('refitKey changes with the stroke, the canvas and the lift by an eighth of a decade, not less', () => {
  const s = { alpha0: 1, beta0: 0.2, gamma0: 0, alpha_phase: 0, beta_phase: 1.5, gamma_phase: 0 };
  assert.equal(C.refitKey(s, 640, 480, 0.02), '1/0.2/0/0/1.5/0/640x480/-14'); // 8·log10(0.02) = −13.6
  assert.equal(C.refitKey(s, 640, 480, 0.0202), C.refitKey(s, 640, 480, 0.02));
  assert.notEqual(C.refitKey(s, 640, 480, 0.03), C.refitKey(s, 640, 480, 0.02)); // −12.2
  assert.notEqual(C.refitKey(s, 641, 480, 0.02), C.refitKey(s, 640, 480, 0.02));
  assert.notEqual(C.refitKey({ ...s, beta_phase: 1.4 }, 640, 480, 0.02), C.refitKey(s, 640, 480, 0.02));
  assert.match(C.refitKey(s, 640, 480, 0), /\/-99$/);
});

test('a pointer up within 4 px of its down is a click; the wheel zooms out for positive deltaY', () => {
  assert.equal(C.isClick([10, 10], 12, 13), true); // 3.6 px
  assert.equal(C.isClick([10, 10], 13, 13), false); // 4.2 px
  assert.equal(C.isClick(null, 10, 10), false);
  assert.equal(C.wheelZoom(100), 1.1);
  assert.equal(C.wheelZoom(-3), 1 / 1.1);
  const c = C.cameraFromRenderer([1, 2, 3, 0.5, 0.4, 0.2], 0.7);
  assert.deepEqual(c, { target: [1, 2, 3], yaw: 0.5, pitch: 0.4, distance: 0.2, fov: 0.7 });
});

test('strokePoses samples one flap period of the run', () => {
  const n = 400;
  const alpha = Float64Array.from({ length: n }, (_, i) => i),
    beta = alpha.map((v) => -v),
    gamma = alpha.map((v) => 2 * v);
  const result = { angles: { alpha, beta, gamma }, analysis: { sim: { sample_rate_hz: 1000, flap_freq_hz: 25 } } };
  const ps = C.strokePoses(result, 32);
  assert.equal(ps.length, 32);
  assert.deepEqual(ps[0], [0, -0, 0]);
  assert.deepEqual(ps[4], [5, -5, 10]); // 4 · 40/32 = 5 samples in
  assert.deepEqual(ps[31], [39, -39, 78]); // round(38.75): the last sample of the 40-sample period
  assert.equal(C.strokePoses({ analysis: result.analysis }), null);
});

test('the camera rig mirrors the renderer: user moves stick, fits search once and then keep the direction', () => {
  const w = wing();
  const v = fakeView(0.05);
  const rig = C.createCameraRig(() => v);
  rig.reset(0.05);
  assert.deepEqual(rig.cam, S.defaultCamera(0.05));
  const poses = [0, 1, 2, 3].map((j) => [0.6 * Math.sin(j), 0.3 * Math.sin(j), 0]);
  const coverage = rig.fit(false, w, poses, 0, 640, 480); // first fit: searches though not asked to
  assert.ok(coverage > 0.01 && coverage < 1, `coverage ${coverage}`);
  assert.equal(rig.fitKey, 'fitted');
  assert.equal(v.calls.setCamera, 22, 'one move per direction tried (7 × 3) and one to the best');
  for (const k of ['yaw', 'pitch', 'distance']) assert.ok(Math.abs(rig.cam[k] - v.cam[k]) < 1e-12, k);
  // the second fit keeps the direction: one renderer fit, no camera set
  const before = { ...rig.cam };
  assert.equal(rig.fit(false, w, poses, 0.05, 640, 480), null);
  assert.equal(v.calls.setCamera, 22);
  assert.equal(v.calls.fitPoints, 22);
  assert.equal(rig.cam.yaw, before.yaw);
  assert.ok(rig.cam.distance > before.distance, 'a lift of a span needs the camera farther away');
  // drag, wheel and keys move both cameras the same way and stop the fits
  rig.orbit(100, -20);
  assert.deepEqual(v.calls.orbit, [[100, -20]]);
  assert.ok(Math.abs(rig.cam.yaw - (before.yaw - 0.8)) < 1e-12);
  assert.equal(rig.user, true);
  rig.zoom(1.1);
  assert.ok(Math.abs(rig.cam.distance - v.cam.distance) < 1e-15);
  assert.equal(rig.key('x'), false);
  assert.equal(rig.key('+'), true);
  assert.ok(Math.abs(rig.cam.distance - v.cam.distance) < 1e-15);
  const moved = { ...rig.cam };
  assert.equal(rig.fit(true, w, poses, 0, 640, 480), null);
  assert.deepEqual(rig.cam, moved, 'no fit after the user moved the camera');
  // without a view nothing moves
  const none = C.createCameraRig(() => null);
  none.reset(0.05);
  none.orbit(10, 10);
  assert.equal(none.user, false);
});

test('canvasSize: aspect by width, height capped, backing store = CSS × DPR within the pixel cap', () => {
  assert.deepEqual(canvasSize(0, 1), { cssW: 640, cssH: 499, width: 640, height: 499 });
  assert.deepEqual(canvasSize(400, 3), { cssW: 400, cssH: 288, width: 800, height: 576 }); // DPR capped at 2
  assert.deepEqual(canvasSize(100, 1), { cssW: 160, cssH: 140, width: 160, height: 140 });
  const big = canvasSize(2000, 2);
  assert.deepEqual(big, { cssW: 2000, cssH: 520, width: 2773, height: 721 });
  assert.ok(big.width * big.height <= MAX_BACKING_PX);
});
