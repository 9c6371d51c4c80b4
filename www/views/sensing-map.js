// @ts-check
// The sensing panel's planform map (views/sensing.js): its box (canvas, legend, words, the
// 3-D button, the sensor list) and the drawing on it: the numbered sensor markers (sensors closer
// than a marker share one label) and the colour legend. The planform's fill and the ring at the
// picked point are www/planform.js.
import { el } from '../dom.js';
import { viridis } from '../plot.js';
import { context2d } from '../export.js';
import { clusterMarkers, groupLabel } from '../sensemap.js';

/**
 * The K best sensors as numbered discs (last drawn on top: the best). Sensors closer than a
 * marker's size share one label ("1,2,4"), drawn at the first one; each sensor's exact place is
 * a small dark dot. Returns the groups drawn.
 * @param {CanvasRenderingContext2D} c2
 * @param {{ x: number, y: number, rank: number }[]} marks canvas px, in rank order
 */
export function drawSensorMarkers(c2, marks) {
  c2.font = 'bold 10px system-ui, sans-serif';
  c2.textAlign = 'center';
  c2.textBaseline = 'middle';
  for (const m of marks) {
    c2.fillStyle = '#111';
    c2.beginPath();
    c2.arc(m.x, m.y, 2, 0, 2 * Math.PI);
    c2.fill();
  }
  const groups = clusterMarkers(marks, 16);
  for (let j = groups.length - 1; j >= 0; j--) {
    const g = groups[j];
    const label = groupLabel(g.ranks);
    const w = Math.max(16, c2.measureText(label).width + 8);
    // the label sits up and to the right of the first sensor of its group, joined by a line
    const lx = g.x + 6 + w / 2,
      ly = g.y - 12;
    c2.strokeStyle = '#111';
    c2.lineWidth = 1;
    c2.beginPath();
    c2.moveTo(g.x, g.y);
    c2.lineTo(lx - w / 2, ly);
    c2.stroke();
    c2.fillStyle = '#fff';
    c2.lineWidth = 1.5;
    c2.beginPath();
    c2.roundRect(lx - w / 2, ly - 8, w, 16, 8);
    c2.fill();
    c2.stroke();
    c2.fillStyle = '#111';
    c2.fillText(label, lx, ly + 0.5);
  }
  return groups;
}

/**
 * The legend strip: viridis from left to right.
 * @param {HTMLCanvasElement} legend
 */
export function drawViridisLegend(legend) {
  const lc = context2d(legend);
  for (let i = 0; i < legend.width; i++) {
    const rgb = viridis(i / (legend.width - 1));
    lc.fillStyle = `rgb(${rgb[0]},${rgb[1]},${rgb[2]})`;
    lc.fillRect(i, 0, 1, legend.height);
  }
}

/**
 * The map's box: heading with the export buttons, the canvas, the legend row, the picked point's
 * words, the "Show on the 3-D wing" button and the list of chosen sensors.
 * @param {import('../lab.js').ViewContext} ctx
 * @param {boolean} touch
 */
export function sensingMapBox(ctx, touch) {
  const mapId = `${ctx.uid}-sensemap`;
  const canvas = el('canvas', {
    class: 'wl-smap-canvas wl-sense-canvas',
    id: mapId,
    tabindex: '0',
    role: 'img',
    width: 600,
    height: 300,
    'aria-label': `Planform map of the wing coloured by how detectable the body rotation is in strain, with the best sensors numbered; ${touch ? 'tap' : 'click'} a point, or use the arrow keys here, to plot the rotation-induced strain there.`,
    'aria-describedby': `${mapId}-text`,
  });
  const legend = el('canvas', { class: 'wl-smap-legend', width: 240, height: 12, 'aria-hidden': 'true' });
  const legendText = el('span', { class: 'wl-smap-legend-text' });
  const pointText = el('p', { class: 'wl-smap-point', id: `${mapId}-text`, 'aria-live': 'polite' });
  // the map and the sensors on the 3-D wing (store `sense_map`; views/wing3d.js colour 6)
  const show3d = el('button', { type: 'button', class: 'wl-small', text: 'Show on the 3-D wing', 'data-show3d': '' });
  show3d.disabled = true;
  const sensorList = el('ol', {
    class: 'wl-sense-list',
    'aria-label': 'The best sensors, in the order the greedy placement chose them',
  });
  const box = el(
    'div',
    { class: 'wl-smap wl-sense-map', 'data-sensemap': '' },
    el(
      'div',
      { class: 'wl-smap-head' },
      el('h3', { class: 'wl-smap-title', text: 'Where rotation shows up: detectability per point' }),
      ctx.exportButtons('sensing', 'Sensing map and sensors', ['csv', 'png']),
    ),
    canvas,
    el('div', { class: 'wl-smap-legendrow' }, legend, legendText),
    pointText,
    el(
      'p',
      { class: 'wl-note wl-sense-3d' },
      show3d,
      ' this map (the same log-D scale) and the K sensors on the flapping 3-D wing.',
    ),
    el('details', { class: 'wl-sense-details' }, el('summary', { text: 'The chosen sensors' }), sensorList),
  );
  return { box, canvas, legend, legendText, pointText, show3d, sensorList };
}
