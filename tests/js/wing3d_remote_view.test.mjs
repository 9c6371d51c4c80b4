// The 3-D view drawn by a worker, the page's side (www/wing3d/remote-view.js) and the messages
// (www/wing3d/render-protocol.js): against the shared stand-in worker (fake_worker.mjs), answered as
// www/render-worker.js would. Latest-wins frames, legends to the frame that asked,
// the camera kept as the renderer keeps it, refusals at once, a failed start; and the
// renderer's own fit (WingView.fitCamera) in the real wasm against the page's mirror.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { RemoteWingView, canRenderInWorker } from '../../www/wing3d/remote-view.js';
import { CALLS, readToWorker, readFromWorker } from '../../www/wing3d/render-protocol.js';
import * as S from '../../www/scene3d.js';
import { loadReal } from './real_wasm.mjs';
import { fakeWorker } from './fake_worker.mjs';

/** The draw messages posted to a stand-in worker (fake_worker.mjs, shared with the engine tests). */
const draws = (w) => w.posted.filter((m) => m.op === 'draw');

const WING = {
  nodes: Float64Array.of(0, 0, 0, 0.04, 0, 0, 0.04, -0.01, 0, 0, -0.01, 0),
  triangles: Uint32Array.of(0, 1, 2, 0, 2, 3),
  shapes: Float64Array.of(0, 1, 1, 0),
  strain_nodes: new Float64Array(0),
};
const canvas = (w = 640, h = 480) => ({ width: w, height: h, transferControlToOffscreen: () => ({ offscreen: true }) });
const CAM = [0.02, -0.01, 0, -1.95, 0.8, 0.084];

/** A started RemoteWingView on a fake worker, and the worker. */
async function started(o = {}) {
  const worker = fakeWorker();
  const p = RemoteWingView.create(canvas(), WING, {
    worker,
    module: /** @type {any} */ ({}),
    fitCamera: o.fitCamera || ((c) => c),
    ...o,
  });
  assert.equal(worker.posted[0].op, 'init');
  worker.reply({ op: 'ready', backend: 'webgl2', triangles: 2, camera: CAM });
  const view = await p;
  return { view, worker };
}

test('create hands the canvas over and answers with the worker view', async () => {
  const { view, worker } = await started();
  const init = worker.posted[0];
  assert.deepEqual(init.canvas, { offscreen: true });
  assert.equal(init.nodes, WING.nodes, 'the wing goes with init');
  assert.equal(view.backend(), 'webgl2');
  assert.equal(view.triangles(), 2);
  assert.deepEqual(view.camera(), CAM);
});

test('a failed start rejects with the worker reason and ends the worker', async () => {
  const worker = fakeWorker();
  const p = RemoteWingView.create(canvas(), WING, { worker, module: /** @type {any} */ ({}), fitCamera: (c) => c });
  worker.reply({ op: 'failed', message: 'this browser offers neither WebGPU nor WebGL2' });
  await assert.rejects(p, /neither WebGPU nor WebGL2/);
  assert.ok(worker.terminated);
});

test('a worker that never answers is given up after the timeout', async () => {
  const worker = fakeWorker();
  const p = RemoteWingView.create(canvas(), WING, {
    worker,
    module: /** @type {any} */ ({}),
    fitCamera: (c) => c,
    timeoutMs: 20,
  });
  await assert.rejects(p, /did not start within 0.02 s/);
  assert.ok(worker.terminated);
});

test('frames are latest-wins: one draw in flight, the newest pose sent next, none queued', async () => {
  const { view, worker } = await started();
  view.setPose(0.1, 0, 0, [1]);
  view.render();
  assert.equal(draws(worker).length, 1, 'the first frame goes at once');
  for (let i = 2; i <= 10; i++) {
    view.setPose(0.1 * i, 0, 0, [i]);
    view.render();
  }
  assert.equal(draws(worker).length, 1, 'nothing more while the first is in flight');
  worker.reply({ op: 'drawn', seq: 1, legend: null, stops: null, error: null });
  const d = draws(worker);
  assert.equal(d.length, 2);
  assert.deepEqual(d[1].pose, [1.0, 0, 0], 'the newest pose, not the second');
  assert.deepEqual(Array.from(d[1].q), [10]);
  assert.equal(d[1].frame, null);
  worker.reply({ op: 'drawn', seq: 2, legend: null, stops: null, error: null });
  assert.equal(draws(worker).length, 2, 'nothing new: nothing sent');
  assert.equal(view.drawn, 2);
});

test('set_frame resolves to the legend of the draw that carried it; merged frames keep the newest settings', async () => {
  const { view, worker } = await started();
  view.setPose(0, 0, 0, [0]);
  view.render();
  const a = view.set_frame(0.2, 0, 0, [1], 10, 4);
  const b = view.set_frame(0.3, 0, 0, [2], 20, 1);
  view.setPose(0.4, 0, 0, [3]);
  view.render();
  worker.reply({ op: 'drawn', seq: 1, legend: null, stops: null, error: null });
  const d = draws(worker)[1];
  assert.deepEqual(d.frame, [20, 1], 'the newest exaggeration and colour');
  assert.deepEqual(d.pose, [0.4, 0, 0], 'with the newest pose');
  const legend = { component: 'ε_x', max_deflection_m: 1e-4 };
  worker.reply({ op: 'drawn', seq: 2, legend, stops: [0, 1, 0, 0], error: null });
  assert.equal(await a, legend);
  assert.equal(await b, legend);
  assert.deepEqual(view.legend_stops(), [0, 1, 0, 0]);
});

test('a failed draw resolves null, reports, and the next frame still goes', async () => {
  const errors = [];
  const { view, worker } = await started({ onError: (m) => errors.push(m) });
  const p = view.set_frame(0, 0, 0, [0], 1, 0);
  view.render();
  view.setPose(0.5, 0, 0, [0]);
  view.render();
  worker.reply({ op: 'drawn', seq: 1, legend: null, stops: null, error: 'device lost' });
  assert.equal(await p, null);
  assert.deepEqual(errors, ['render: device lost']);
  assert.equal(draws(worker).length, 2);
  worker.reply({ op: 'error', name: 'setNodeField', message: 'bad' });
  assert.deepEqual(errors.at(-1), 'setNodeField: bad');
});

test('the camera is kept as the renderer keeps it, and every change is sent', async () => {
  const { view, worker } = await started();
  view.orbit(30, -10);
  const m = S.orbit(
    { ...S.defaultCamera(1), target: CAM.slice(0, 3), yaw: CAM[3], pitch: CAM[4], distance: CAM[5] },
    30,
    -10,
  );
  assert.ok(Math.abs(view.camera()[3] - m.yaw) < 1e-12 && Math.abs(view.camera()[4] - m.pitch) < 1e-12);
  view.zoom(2);
  assert.ok(Math.abs(view.camera()[5] - 2 * CAM[5]) < 1e-12);
  assert.equal(view.key('ArrowLeft'), true);
  assert.equal(view.key('q'), false, 'a key the renderer ignores');
  view.setCamera(0, 0, 0, 7, 3, 0.1);
  assert.ok(Math.abs(view.camera()[3] - (7 % (2 * Math.PI))) < 1e-12, 'yaw modulo 2π');
  assert.ok(Math.abs(view.camera()[4] - (Math.PI / 2 - 0.01)) < 1e-12, 'pitch within its limit');
  assert.throws(() => view.setCamera(0, 0, 0, 0, 0, 0), /distance > 0/);
  assert.throws(() => view.setCamera(Number.NaN, 0, 0, 0, 0, 1), /finite/);
  const calls = worker.posted.filter((x) => x.op === 'call').map((x) => x.name);
  assert.deepEqual(calls, ['orbit', 'zoom', 'key', 'setCamera'], 'refused calls are not sent');
});

test('fitPoints runs the renderer fit on the page with the canvas aspect and sends its camera', async () => {
  const seen = [];
  const fitted = [1, 2, 3, 0.5, 0.6, 0.7];
  const { view, worker } = await started({
    fitCamera: (c, xyz, margin, aspect) => {
      seen.push({ c: c.slice(), n: xyz.length, margin, aspect });
      return Float64Array.from(fitted);
    },
  });
  view.resize(800, 400);
  const out = view.fitPoints(new Float32Array(9), 0.04);
  assert.deepEqual(out, fitted);
  assert.deepEqual(seen, [{ c: CAM, n: 9, margin: 0.04, aspect: 2 }]);
  assert.deepEqual(view.camera(), fitted);
  const last = worker.posted.at(-1);
  assert.deepEqual([last.name, last.args], ['setCamera', fitted]);
});

test('refusals come at once, as the view refuses them: field length, canvas size', async () => {
  const { view, worker } = await started();
  const before = worker.posted.length;
  assert.throws(() => view.setNodeField(new Float64Array(3), 1), /one per node, 4/);
  for (const [w, h] of [
    [0, 10],
    [10.5, 10],
    [40000, 10],
    [Number.NaN, 1],
  ])
    assert.throws(() => view.resize(w, h), /integers in \[1, 32768\]/);
  assert.equal(worker.posted.length, before, 'nothing sent');
  view.setNodeField([1, 2, 3, 4], null);
  assert.ok(worker.posted.at(-1).args[0] instanceof Float64Array);
});

test('free ends the worker and sends nothing after', async () => {
  const { view, worker } = await started();
  view.free();
  assert.equal(worker.posted.at(-1).op, 'free');
  const n = worker.posted.length;
  view.setPose(0, 0, 0, []);
  view.render();
  view.orbit(1, 1);
  assert.equal(worker.posted.length, n);
});

test('the protocol readers take what the other side writes and nothing else', () => {
  const mod = new WebAssembly.Module(Uint8Array.of(0, 97, 115, 109, 1, 0, 0, 0));
  assert.ok(readToWorker({ op: 'init', module: mod, canvas: {} }));
  assert.equal(readToWorker({ op: 'init', module: {}, canvas: {} }), null, 'not a module');
  assert.ok(readToWorker({ op: 'draw', seq: 1, frame: null, pose: [0, 0, 0], q: new Float64Array(1) }));
  assert.equal(readToWorker({ op: 'draw', seq: 1, pose: [0, 0], q: new Float64Array(1) }), null);
  assert.equal(readToWorker({ op: 'draw', seq: 1, pose: [0, 0, 0], q: [1] }), null, 'q as typed array');
  for (const name of CALLS) assert.ok(readToWorker({ op: 'call', name, args: [] }));
  for (const name of ['free', 'render', 'constructor', '__proto__', 'set_frame'])
    assert.equal(readToWorker({ op: 'call', name, args: [] }), null, name);
  assert.equal(readToWorker(null), null);
  assert.equal(readToWorker({ op: 'eval' }), null);
  assert.ok(readFromWorker({ op: 'ready', backend: 'webgpu', triangles: 1, camera: CAM }));
  assert.equal(readFromWorker({ op: 'ready', backend: 'webgpu', camera: [1] }), null);
  assert.ok(readFromWorker({ op: 'drawn', seq: 3 }));
  assert.equal(readFromWorker({ op: 'drawn', seq: 'x' }), null);
  assert.equal(readFromWorker({ op: 'error', name: 'x' }), null);
});

test('canRenderInWorker needs OffscreenCanvas, Worker and transferControlToOffscreen', () => {
  const ok = typeof OffscreenCanvas === 'function' && typeof Worker === 'function';
  assert.equal(canRenderInWorker(/** @type {any} */ (canvas())), ok);
  assert.equal(canRenderInWorker(/** @type {any} */ ({ width: 1, height: 1 })), false);
});

test('WingView.fitCamera (the real wasm, no GPU) frames every point and matches the page mirror', async () => {
  const wb = await loadReal();
  const cam = [0.025, -0.01, 0, -1.95, 0.8, 0.3];
  // a flat 50 × 20 mm wing at three poses
  const pts = S.posePoints(Float64Array.of(0, 0, 0, 0.05, 0, 0, 0.05, -0.02, 0, 0, -0.02, 0), [
    [0, 0, 0],
    [0.8, 0.3, 0.1],
    [-0.8, -0.3, -0.1],
  ]);
  const [W, H] = [800, 600];
  const out = Array.from(wb.WingView.fitCamera(cam, Float32Array.from(pts), 0.04, W / H));
  assert.equal(out.length, 6);
  assert.ok(Math.abs(out[3] - cam[3]) < 1e-6 && Math.abs(out[4] - cam[4]) < 1e-6, 'direction kept');
  const c = { target: out.slice(0, 3), yaw: out[3], pitch: out[4], distance: out[5], fov: S.defaultCamera(1).fov };
  const b = S.bbox(c, pts, W, H);
  assert.ok(b, 'every point in front of the eye');
  // inside with the margin (4 % of each half-side = 2 % of the side), and touching it on one axis
  const m = [b[0] / W, 1 - b[2] / W, b[1] / H, 1 - b[3] / H];
  for (const x of m) assert.ok(x >= 0.02 - 1e-4, `margin ${x}`);
  assert.ok(Math.min(...m) < 0.02 + 1e-3, `tight: ${m}`);
  // centred: equal margins left/right or top/bottom on the tight axis
  assert.ok(Math.abs(m[0] - m[1]) < 2e-3 || Math.abs(m[2] - m[3]) < 2e-3, `centred: ${m}`);
  // hostile inputs, refused by name
  assert.throws(() => wb.WingView.fitCamera([1, 2, 3], pts, 0.04, 1), /camera/);
  assert.throws(() => wb.WingView.fitCamera([0, 0, 0, 0, 0, 0], pts, 0.04, 1), /camera/);
  assert.throws(() => wb.WingView.fitCamera([0, 0, 0, 0, 0, Number.NaN], pts, 0.04, 1), /camera/);
  assert.throws(() => wb.WingView.fitCamera(cam, pts, 0.04, 0), /aspect/);
  assert.throws(() => wb.WingView.fitCamera(cam, pts, 0.9, 1), /margin/);
  assert.throws(() => wb.WingView.fitCamera(cam, [1, 2], 0.04, 1), /triples/);
  assert.throws(() => wb.WingView.fitCamera(cam, [Number.NaN, 0, 0], 0.04, 1), /no finite point/);
});

test('runRanges asks the worker for the run ranges over flat states; idle waits for the answer and what it asks for', async () => {
  const { view, worker } = await started();
  const Q = Float64Array.of(1, 2, 3, 4);
  const p = view.runRanges({ Q, S: 2, m: 2 });
  const m = worker.posted.at(-1);
  assert.deepEqual([m.op, m.S, m.m, Array.from(m.Q)], ['ranges', 2, 2, [1, 2, 3, 4]]);
  assert.ok(readToWorker(m), 'the worker reads it');
  let idle = false;
  const done = view.idle().then(() => {
    idle = true;
  });
  await new Promise((r) => setTimeout(r, 5));
  assert.equal(idle, false, 'not idle while the ranges are awaited');
  // the answer's handler asks for a frame: idle waits for that frame too
  p.then(() => {
    view.setPose(0, 0, 0, [0]);
    view.render();
  });
  worker.reply({ op: 'ranges', seq: m.seq, ranges: { 1: 1e-4, 2: 2e-4, 3: 3e-4, 4: 4e-4 }, deflection: 1e-3 });
  assert.deepEqual(await p, { ranges: { 1: 1e-4, 2: 2e-4, 3: 3e-4, 4: 4e-4 }, deflection: 1e-3 });
  await new Promise((r) => setTimeout(r, 5));
  assert.equal(idle, false, 'the frame asked for is still in flight');
  const d = draws(worker).at(-1);
  worker.reply({ op: 'drawn', seq: d.seq, legend: null, stops: null, error: null });
  await done;
  assert.equal(idle, true);
  // a worker that could not work them out: null; a freed view answers null at once
  const p2 = view.runRanges({ Q: new Float64Array(0), S: 0, m: 2 });
  worker.reply({ op: 'ranges', seq: worker.posted.at(-1).seq, ranges: null, deflection: 0 });
  assert.equal(await p2, null);
  view.free();
  assert.equal(await view.runRanges({ Q: new Float64Array(0), S: 0, m: 0 }), null);
  assert.equal(readToWorker({ op: 'ranges', seq: 1, Q: new Float64Array(3), S: 2, m: 2 }), null, 'length checked');
});
