// The 3-D panel's play loop (www/wing3d/frame-loop.js): the time step, the ≈ 30 fps gate on a slow
// machine, and the loop itself on a stand-in clock: it advances at the chosen speed, wraps at the
// run's end, hands its time to the store at most every 100 ms, and stops or pauses with a reason.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as F from '../../www/wing3d/frame-loop.js';

test('advanceTime moves by real time × speed and wraps past the end of the run', () => {
  assert.ok(Math.abs(F.advanceTime(0.1, 500, 0.01, 2) - 0.105) < 1e-15);
  assert.equal(F.advanceTime(1.999, 1000, 0.01, 2), 0);
  assert.equal(F.advanceTime(1.99, 1000, 0.01, 2), 2, 'the end itself is still shown');
});

test('the frame gate draws every frame at 60 Hz and ≤ 1 per 30 ms once frames come slower than 24 ms', () => {
  const fast = F.frameGate();
  let drawn = 0;
  for (let t = 1000; t < 2000; t += 16) drawn += fast.due(t) ? 1 : 0;
  assert.equal(drawn, 63);
  assert.equal(fast.mean, 16);
  const slow = F.frameGate();
  assert.equal(slow.due(1000), true);
  assert.equal(slow.due(1040), true); // first interval: mean 40 ms
  assert.equal(slow.mean, 40);
  assert.equal(slow.due(1060), false, '20 ms after the last drawn frame');
  assert.equal(slow.due(1070), true, '30 ms after');
  assert.ok(Math.abs(slow.mean - 39) < 1e-12); // 0.9 · 40 + 0.1 · 30
});

/** A store, a box, a clock and a document for the loop, and a way to run animation frames. */
function rig({ playing = true, t3d = 0.5 } = {}) {
  let state = { playing, t3d };
  const sets = [];
  const store = {
    get: () => state,
    set: (p) => {
      sets.push(p);
      state = { ...state, ...p };
    },
  };
  const box = { dataset: {} };
  let queue = [];
  let nextId = 1;
  let clock = 0;
  const listeners = {};
  const doc = {
    hidden: false,
    addEventListener: (k, f) => {
      listeners[k] = f;
    },
    removeEventListener: (k) => {
      delete listeners[k];
    },
  };
  const env = {
    raf: (f) => {
      const id = nextId++;
      queue.push({ id, f });
      return id;
    },
    caf: (id) => {
      queue = queue.filter((q) => q.id !== id);
    },
    now: () => clock,
    doc,
  };
  const drawn = [];
  const loop = F.createFrameLoop({
    box,
    store,
    ready: () => true,
    draw: (t) => drawn.push(t),
    speed: () => 0.01,
    duration: () => 2,
    env,
  });
  /** Runs the pending animation frames every `dt` ms until `until`. */
  const run = (until, dt = 16) => {
    while (clock + dt <= until && queue.length) {
      clock += dt;
      const q = queue;
      queue = [];
      for (const { f } of q) f(clock);
    }
  };
  return { loop, store, sets, box, doc, listeners, drawn, run, pending: () => queue.length };
}

test('the loop plays at the chosen speed and hands its time to the store every 100 ms or more', () => {
  const r = rig();
  r.loop.start();
  assert.equal(r.box.dataset.loop, 'running');
  assert.equal(r.loop.t, 0.5);
  r.run(1008); // 63 frames of 16 ms
  assert.equal(r.drawn.length, 63);
  assert.ok(Math.abs(r.loop.t - (0.5 + 1.008 * 0.01)) < 1e-12, `t ${r.loop.t}`);
  const pushes = r.sets.filter((p) => 't3d' in p);
  assert.equal(pushes.length, 9); // at 112, 224, …, 1008 ms: every 7th frame, the first ≥ 100 ms after 0
  assert.equal(r.loop.lastPush, 1008);
  assert.equal(r.store.get().t3d, r.loop.t);
  assert.equal(r.loop.pushing, false);
});

test('the loop stops when playing ends and pauses in a hidden tab, leaving its instant in the store', () => {
  const r = rig();
  r.loop.start();
  r.run(50);
  r.doc.hidden = true;
  r.run(66);
  assert.equal(r.box.dataset.loop, 'paused-hidden');
  assert.equal(r.pending(), 0, 'no frame asked for while hidden');
  assert.equal(r.loop.t, null);
  assert.ok(Math.abs(r.store.get().t3d - (0.5 + 0.048 * 0.01)) < 1e-12, 'the last instant drawn (3 frames) stays');
  // visible again: the visibility handler restarts it
  r.loop.watch(/** @type {any} */ ({}));
  r.doc.hidden = false;
  r.listeners.visibilitychange();
  assert.equal(r.box.dataset.loop, 'running');
  r.store.set({ playing: false });
  r.run(200);
  assert.equal(r.box.dataset.loop, 'stopped');
  r.loop.destroy();
  assert.equal(r.listeners.visibilitychange, undefined);
});

test('the loop does not start without a view or while not playing', () => {
  const r = rig({ playing: false });
  r.loop.start();
  assert.equal(r.pending(), 0);
  assert.equal(r.box.dataset.loop, undefined);
  const box = { dataset: {} };
  const none = F.createFrameLoop({
    box,
    store: { get: () => ({ playing: true }), set() {} },
    ready: () => false,
    draw() {},
    speed: () => 1,
    duration: () => 1,
    env: {
      raf: () => 1,
      caf() {},
      now: () => 0,
      doc: { hidden: false, addEventListener() {}, removeEventListener() {} },
    },
  });
  none.start();
  assert.equal(box.dataset.loop, undefined);
});
