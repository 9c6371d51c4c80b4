// The line plot's parts (www/plot/): the keyboard's new x window (pan, zoom, reset, kept inside
// the data) and what is drawn over the lines, checked on a recording stand-in for the canvas: the
// bands clipped to the plot area, only the markers inside it, labels that would overlap put on
// further rows, the labelled bands' brackets. Run: node --test tests/js/plot_parts.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { keyWindow } from '../../www/plot/window.js';
import { fillBands, drawMarks } from '../../www/plot/marks.js';

test('keyWindow: arrows pan a quarter, + and − zoom about the middle, 0 and Home reset, other keys are not ours', () => {
  assert.deepEqual(keyWindow('ArrowRight', 2, 6, 0, 10), [3, 7]);
  assert.deepEqual(keyWindow('ArrowLeft', 2, 6, 0, 10), [1, 5]);
  assert.deepEqual(keyWindow('+', 2, 6, 0, 10), [3, 5]);
  assert.deepEqual(keyWindow('=', 2, 6, 0, 10), [3, 5]);
  assert.deepEqual(keyWindow('-', 3, 5, 0, 10), [2, 6]);
  assert.deepEqual(keyWindow('_', 3, 5, 0, 10), [2, 6]);
  assert.equal(keyWindow('0', 2, 6, 0, 10), 'reset');
  assert.equal(keyWindow('Home', 2, 6, 0, 10), 'reset');
  assert.equal(keyWindow('a', 2, 6, 0, 10), null);
  assert.equal(keyWindow('Enter', 2, 6, 0, 10), null);
});

test('keyWindow keeps the window inside the data and never wider than it', () => {
  assert.deepEqual(keyWindow('ArrowLeft', 0, 4, 0, 10), [0, 4], 'at the left end a pan left stays');
  assert.deepEqual(keyWindow('ArrowRight', 7, 10, 0, 10), [7, 10], 'at the right end a pan right stays');
  assert.deepEqual(keyWindow('-', 2, 8, 0, 10), [0, 10], 'zooming out past the data shows all of it');
  assert.deepEqual(keyWindow('ArrowRight', 5, 9, 0, 10), [6, 10], 'a pan that would leave is shifted back');
});

/** A stand-in for a 2-D context that records fills, strokes (as path points) and texts. */
function recorder() {
  const log = { fills: [], strokes: [], texts: [], dashes: [] };
  let path = [];
  const ctx = {
    fillStyle: '',
    strokeStyle: '',
    lineWidth: 1,
    font: '',
    textBaseline: '',
    textAlign: '',
    save() {},
    restore() {},
    translate(x, y) {
      ctx._at = [x, y];
    },
    rotate() {},
    setLineDash(d) {
      log.dashes.push(d);
    },
    beginPath() {
      path = [];
    },
    moveTo(x, y) {
      path.push([x, y]);
    },
    lineTo(x, y) {
      path.push([x, y]);
    },
    stroke() {
      log.strokes.push({ color: ctx.strokeStyle, path });
    },
    fillRect(x, y, w, h) {
      log.fills.push({ color: ctx.fillStyle, x, y, w, h });
    },
    fillText(text, x, y) {
      log.texts.push({ text, at: ctx._at, x, y, color: ctx.fillStyle });
    },
    // 6 px per character whatever the font.
    measureText: (t) => ({ width: 6 * t.length }),
    _at: [0, 0],
  };
  return { ctx, log };
}

/** A plot area 100…500 × 10…210 with x in canvas pixels = 100 + 40·value. */
function area(ctx) {
  return {
    ctx: /** @type {any} */ (ctx),
    bbox: { left: 100, top: 10, width: 400, height: 200 },
    valToPos: (v) => 100 + 40 * v,
  };
}

test('fillBands fills each band clipped to the plot area and skips the ones outside it', () => {
  const { ctx, log } = recorder();
  fillBands(area(ctx), [
    { x0: 1, x1: 2 },
    { x0: -5, x1: 1, fill: 'red' },
    { x0: 9, x1: 20 },
    { x0: 12, x1: 14 },
    { x0: 3, x1: 3 },
  ]);
  assert.deepEqual(log.fills, [
    { color: 'rgba(122,60,194,0.10)', x: 140, y: 10, w: 40, h: 200 },
    { color: 'red', x: 100, y: 10, w: 40, h: 200 },
    { color: 'rgba(122,60,194,0.10)', x: 460, y: 10, w: 40, h: 200 },
  ]);
});

test('drawMarks: a line per marker inside the area, overlapping labels on further rows, band brackets with labels', () => {
  const { ctx, log } = recorder();
  drawMarks(
    area(ctx),
    [
      { x: 1, label: 'f_1', color: 'blue' },
      { x: 1.4, label: 'long label', color: 'green', dash: [2, 3] },
      { x: 20, label: 'outside', color: 'black' },
      { x: 5, label: '', color: 'gray' },
    ],
    [
      { x0: 2, x1: 4, label: 'T', color: 'purple' },
      { x0: 6, x1: 7 },
    ],
    2,
  );
  const lines = log.strokes.filter((s) => s.path.length === 2);
  assert.deepEqual(
    lines.map((s) => [s.color, s.path[0][0]]),
    [
      ['blue', 140],
      ['green', 156],
      ['gray', 300],
    ],
    'the marker outside the area is not drawn',
  );
  assert.deepEqual(lines[0].path, [
    [140, 10],
    [140, 210],
  ]);
  assert.ok(
    log.dashes.some((d) => d.length === 2 && d[0] === 4 && d[1] === 6),
    'dashes scale with the pixel ratio',
  );
  const label = (t) => log.texts.find((x) => x.text === t);
  assert.ok(label('f') && label('long label') && label('T'));
  assert.equal(label('outside'), undefined);
  // "f_1" (f and a subscript 1) ends at 146 + 12 px, the gap is 8; "long label" starts at 162: a second row.
  assert.equal(label('f').at[1], 10 + 2 * 2);
  assert.equal(label('long label').at[1], 10 + 13 * 2 + 2 * 2);
  const bracket = log.strokes.find((s) => s.path.length === 4);
  assert.equal(bracket.color, 'purple');
  assert.deepEqual(
    bracket.path.map((p) => p[0]),
    [180, 180, 260, 260],
  );
  assert.equal(log.strokes.filter((s) => s.path.length === 4).length, 1, 'an unlabelled band has no bracket');
});
