// The planform map (www/planform.js), shared by the strain and sensing panels: its frame, the
// picked point's ring and the redraw on a change of the box's width.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { planformFrame, KEY_STEP_MM, onPlanform, pointOnWing, drawRing, watchWidth } from '../../www/planform.js';

test('a planform fills the width, keeps its aspect and maps mm to pixels inside the margins', () => {
  // A 40 mm × 10 mm rectangle (nodes in m), drawn 400 px wide with 10 px margins.
  const nodes = [0, -0.01, 0, 0.04, -0.01, 0, 0.04, 0, 0, 0, 0, 0];
  const { cssW, cssH, frame } = planformFrame(nodes, 400, 10);
  assert.equal(cssW, 400);
  assert.equal(cssH, Math.round(10 * (380 / 40) + 20)); // 115 px: the aspect kept
  const px = (x) => (x - frame.x0) * frame.k,
    py = (y) => (frame.y1 - y) * frame.k;
  assert.ok(Math.abs(px(0) - 10) < 1e-9 && Math.abs(px(40) - 390) < 1e-9, 'span fills the width inside the margins');
  assert.ok(py(0) >= 10 - 1e-9 && py(-10) <= cssH - 10 + 1e-9, 'chord inside the height');
  assert.ok(py(0) < py(-10), 'leading edge (y = 0) above the trailing edge');
});

test('the width is clamped to 200…720 px and a very deep planform to 360 px high', () => {
  const tall = [0, 0, 0, 0.001, 0, 0, 0, -0.05, 0];
  assert.equal(planformFrame(tall, 50, 10).cssW, 200);
  const r = planformFrame(tall, 5000, 10);
  assert.equal(r.cssW, 720);
  assert.equal(r.cssH, 360);
  assert.ok((r.frame.y1 - -50) * r.frame.k <= 360 - 10 + 1e-9, 'the whole chord fits');
  assert.equal(KEY_STEP_MM, 0.5);
});

test('no nodes gives a finite frame, never NaN', () => {
  const { cssW, cssH, frame } = planformFrame([], 300, 10);
  for (const v of [cssW, cssH, frame.x0, frame.y1, frame.k]) assert.ok(Number.isFinite(v));
});

test('onPlanform: a point (mm) is on the wing inside its triangles or on their edges, off it elsewhere', () => {
  // A 40 mm × 10 mm rectangle of two triangles (nodes in m), chord toward −y.
  const nodes = [0, 0, 0, 0.04, 0, 0, 0.04, -0.01, 0, 0, -0.01, 0];
  const tris = [0, 1, 2, 0, 2, 3];
  assert.equal(onPlanform(nodes, tris, 20, -5), true);
  assert.equal(onPlanform(nodes, tris, 1, -9), true, 'in the second triangle');
  assert.equal(onPlanform(nodes, tris, 40, 0), true, 'a corner');
  assert.equal(onPlanform(nodes, tris, 20, 1), false, 'ahead of the leading edge');
  assert.equal(onPlanform(nodes, tris, 41, -5), false, 'beyond the tip');
  assert.equal(onPlanform(nodes, [0, 1, 2], 1, -9), false, 'only the triangles count, not the nodes’ hull');
  assert.equal(onPlanform([], [], 0, 0), false);
});

test('pointOnWing: a point on the wing rounded to 0.001 mm; off the wing null, and the note says why', () => {
  const fe = { nodes: [0, 0, 0, 0.04, 0, 0, 0.04, -0.01, 0, 0, -0.01, 0], triangles: [0, 1, 2, 0, 2, 3] };
  const note = { textContent: 'before' };
  assert.deepEqual(pointOnWing(fe, 20.12345, -5.00049, note), [20.123, -5]);
  assert.equal(note.textContent, 'before', 'a point on the wing leaves the note alone');
  assert.equal(pointOnWing(fe, 41, -5, note), null);
  assert.match(note.textContent, /^\(41, -5\) mm is outside the wing/);
});

test('drawRing strokes a dark 3 px circle, then the light 1.5 px one, both at the radius', () => {
  const log = [];
  const c2 = {
    set lineWidth(v) {
      log.push(['lineWidth', v]);
    },
    set strokeStyle(v) {
      log.push(['strokeStyle', v]);
    },
    beginPath: () => log.push(['beginPath']),
    arc: (...a) => log.push(['arc', ...a]),
    stroke: () => log.push(['stroke']),
  };
  drawRing(/** @type {any} */ (c2), 12, 34, 6, '#fff');
  const ring = (w, colour) => [
    ['lineWidth', w],
    ['strokeStyle', colour],
    ['beginPath'],
    ['arc', 12, 34, 6, 0, 2 * Math.PI],
    ['stroke'],
  ];
  assert.deepEqual(log, [...ring(3, '#111'), ...ring(1.5, '#fff')]);
});

test('watchWidth redraws when the box width changes by more than 4 px, and stops on disconnect', () => {
  const had = globalThis.ResizeObserver;
  /** @type {any} */
  let made = null;
  globalThis.ResizeObserver = /** @type {any} */ (
    class {
      constructor(cb) {
        this.cb = cb;
        this.watching = null;
        made = this;
      }
      observe(b) {
        this.watching = b;
      }
      disconnect() {
        this.watching = null;
      }
    }
  );
  try {
    const box = { clientWidth: 0 };
    let draws = 0;
    const w = watchWidth(/** @type {any} */ (box), () => draws++);
    assert.equal(made.watching, box);
    const resize = (px) => {
      box.clientWidth = px;
      made.cb();
    };
    resize(0); // not laid out yet
    assert.equal(draws, 0);
    resize(300);
    assert.equal(draws, 1);
    resize(304); // within 4 px of the last drawn width
    assert.equal(draws, 1);
    resize(305);
    assert.equal(draws, 2);
    w.disconnect();
    assert.equal(made.watching, null);
  } finally {
    globalThis.ResizeObserver = had;
  }
  // without ResizeObserver (node): nothing to watch, disconnect is harmless
  const w = watchWidth(/** @type {any} */ ({ clientWidth: 10 }), () => assert.fail('no redraw'));
  w.disconnect();
});
