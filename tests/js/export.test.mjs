// Exports (www/export.js): CSV text, tick and label placement, and the figure drawing routine
// through the SVG painter (the PNG uses the same routine on a canvas).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { toCSV, niceTicks, placeLabels, figureSVG, drawFigure, svgPainter } from '../../www/export.js';

test('toCSV: comments, header with units, empty cells for NaN', () => {
  const t = toCSV(
    [
      { name: 't', unit: 's', values: [0, 1] },
      { name: 'q', unit: 'kg^½·m', values: [1, NaN] },
    ],
    ['case'],
  );
  assert.equal(t, '# case\nt (s),q (kg^½·m)\n0,1\n1,\n');
});

test('niceTicks covers the range with round steps', () => {
  assert.deepEqual(niceTicks(0, 1, 5), [0, 0.2, 0.4, 0.6, 0.8, 1]);
  assert.deepEqual(niceTicks(-26, -20, 6), [-26, -25, -24, -23, -22, -21, -20]);
  assert.deepEqual(niceTicks(3, 3), [3]);
});

test('placeLabels never lets two labels in a row overlap', () => {
  const items = [
    { x: 100, width: 30 },
    { x: 110, width: 20 },
    { x: 125, width: 25 },
    { x: 200, width: 10 },
  ];
  const rows = placeLabels(items, { gap: 4, maxRows: 3 });
  assert.deepEqual(rows, [0, 1, 2, 0]);
  for (let i = 0; i < items.length; i++)
    for (let j = 0; j < items.length; j++) {
      if (i === j || rows[i] !== rows[j] || rows[i] < 0) continue;
      const [a, b] = items[i].x < items[j].x ? [items[i], items[j]] : [items[j], items[i]];
      assert.ok(a.x + a.width + 4 <= b.x);
    }
  assert.equal(
    placeLabels(
      [
        { x: 0, width: 50 },
        { x: 1, width: 50 },
      ],
      { maxRows: 1 },
    )[1],
    -1,
  );
});

test('a figure has title, parameter line, axis titles with real superscripts, and a legend with swatches', () => {
  const x = Float64Array.from({ length: 1000 }, (_, i) => i / 1000);
  const fig = {
    title: 'Responses of mode 1',
    params: 'α_0 = 0.8 rad, f_d = 25 Hz',
    x,
    xRange: [0.1, 0.4],
    xLabel: 't (s)',
    yLabel: 'q (kg^½·m)',
    series: [
      { label: 'Coriolis response', color: '#2ca02c', y: Float64Array.from(x, (v) => Math.sin(60 * v)) },
      { label: 'Total', color: '#222222', y: Float64Array.from(x, (v) => Math.cos(50 * v)), show: false },
    ],
    bands: [{ x0: 0.2, x1: 0.297, label: 'T_{beat} = 0.097 s' }],
    markers: [{ x: 0.3, label: '3-D t', color: '#7a3cc2' }],
  };
  const svg = figureSVG(fig, 900, 560);
  assert.match(svg, /^<\?xml/);
  assert.match(svg, /Responses of mode 1/);
  assert.match(svg, /baseline-shift="super"[^>]*>½</);
  assert.match(svg, /baseline-shift="sub"[^>]*>beat</);
  assert.ok(!svg.includes('kg^'));
  assert.match(svg, /<rect[^>]*fill="#2ca02c"/); // legend swatch
  assert.ok(!svg.includes('>Total<'), 'hidden series are left out of the legend');
  const p = svgPainter(900, 560);
  const layout = drawFigure(p, fig, 900, 560);
  assert.equal(layout.legend.length, 1);
  assert.ok(layout.plot.width > 600 && layout.plot.height > 250);
});
