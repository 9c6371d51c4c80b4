// Number, unit and label formatting (www/format.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { fmt, parseRich, plain, UNITS, fmtRich } from '../../www/format.js';

test('fmt keeps the numbers the lab has always shown', () => {
  assert.equal(fmt(60.30639396854428, 6), '60.3064');
  assert.equal(fmt(62.5, 4), '62.5');
  assert.equal(fmt(0), '0');
  assert.equal(fmt(null), '—');
  assert.equal(fmt(1.5e-6, 3), '1.50e-6');
  assert.equal(fmt(Infinity), '∞');
});

test('rich markup: subscripts, superscripts, braces; no caret survives plain()', () => {
  assert.deepEqual(parseRich('f_d'), [
    { text: 'f', kind: 'normal' },
    { text: 'd', kind: 'sub' },
  ]);
  assert.deepEqual(parseRich('γ_{xy} x'), [
    { text: 'γ', kind: 'normal' },
    { text: 'xy', kind: 'sub' },
    { text: ' x', kind: 'normal' },
  ]);
  assert.deepEqual(
    parseRich('kg^½·m').map((r) => r.kind),
    ['normal', 'sup', 'normal'],
  );
  assert.equal(plain(UNITS.q.label), 'kg½·m');
  assert.equal(plain(UNITS.fpsd.label), '(kg½·m/s²)²/Hz');
  assert.equal(plain('10^{-26}'), '10⁻²⁶');
  for (const u of Object.values(UNITS)) assert.ok(!plain(u.label).includes('^'));
  assert.equal(fmtRich(1.5e-6, 2), '1.5×10^{−6}');
});

test('CSV units keep their historical ASCII form', () => {
  assert.equal(UNITS.q.csv, 'kg^½·m');
  assert.equal(UNITS.fpsd.csv, '(kg^½·m/s²)^2/Hz');
});
