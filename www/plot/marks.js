// @ts-check
// What a line plot (www/plot.js) draws over uPlot's own canvas: shaded bands behind the lines,
// and on top the vertical markers with labels that never overlap (export.js placeLabels, up to
// three rows) and the bands' labelled brackets. Canvas pixels are CSS pixels × `r` (the DPR).
import { placeLabels, canvasPainter } from '../export.js';

/** @typedef {import('../plot.js').Marker} Marker */
/** @typedef {import('../plot.js').Band} Band */
/**
 * The part of a uPlot the drawing needs.
 * @typedef {{ ctx: CanvasRenderingContext2D, bbox: { left: number, top: number, width: number, height: number },
 *   valToPos: (v: number, scale: string, canvasPixels?: boolean) => number }} PlotArea
 */

/**
 * Fills the bands (x0 … x1, clipped to the plot area) behind the lines (uPlot's drawClear).
 * @param {PlotArea} u
 * @param {Band[]} bands
 */
export function fillBands(u, bands) {
  const ctx = u.ctx;
  const { top, height: h, left, width: w } = u.bbox;
  for (const b of bands) {
    const x0 = Math.max(left, u.valToPos(b.x0, 'x', true)),
      x1 = Math.min(left + w, u.valToPos(b.x1, 'x', true));
    if (!(x1 > x0)) continue;
    ctx.fillStyle = b.fill || 'rgba(122,60,194,0.10)';
    ctx.fillRect(x0, top, x1 - x0, h);
  }
}

/**
 * Draws the markers inside the plot area (a line each, its label in the first free row) and the
 * labelled bands' brackets and labels (uPlot's draw).
 * @param {PlotArea} u
 * @param {Marker[]} markers
 * @param {Band[]} bands
 * @param {number} r device pixels per CSS pixel
 */
export function drawMarks(u, markers, bands, r) {
  const ctx = u.ctx;
  const { left, top, width: w, height: h } = u.bbox;
  ctx.save();
  ctx.font = `${Math.round(11 * r)}px system-ui, sans-serif`;
  ctx.textBaseline = 'top';
  ctx.textAlign = 'left';
  const marks = markers
    .map((m) => ({ ...m, px: u.valToPos(m.x, 'x', true) }))
    .filter((m) => m.px >= left && m.px <= left + w);
  const pt = canvasPainter(ctx);
  const rows = placeLabels(
    marks.map((m) => ({ x: m.px + 3 * r, width: m.label ? pt.measure(m.label, 11 * r) : 0 })),
    { gap: 4 * r, maxRows: 3 },
  );
  marks.forEach((m, i) => {
    ctx.strokeStyle = m.color || '#999';
    ctx.lineWidth = (m.width || 1) * r;
    ctx.setLineDash(m.dash ? m.dash.map((d) => d * r) : []);
    ctx.beginPath();
    ctx.moveTo(m.px, top);
    ctx.lineTo(m.px, top + h);
    ctx.stroke();
    if (m.label && rows[i] >= 0) {
      const tw = pt.measure(m.label, 11 * r);
      const y = top + rows[i] * 13 * r + 2 * r;
      ctx.fillStyle = 'rgba(255,255,255,0.8)';
      ctx.fillRect(m.px + 2 * r, y - r, tw + 2 * r, 13 * r);
      pt.text(m.px + 3 * r, y, m.label, { size: 11 * r, color: m.color || '#666', baseline: 'top' });
    }
  });
  ctx.setLineDash([]);
  for (const b of bands) {
    if (!b.label) continue;
    const x0 = u.valToPos(b.x0, 'x', true),
      x1 = u.valToPos(b.x1, 'x', true);
    if (x1 < left || x0 > left + w) continue;
    const y = top + h - 10 * r;
    ctx.strokeStyle = b.color || '#7a3cc2';
    ctx.lineWidth = 2 * r;
    ctx.beginPath();
    ctx.moveTo(x0, y - 6 * r);
    ctx.lineTo(x0, y);
    ctx.lineTo(x1, y);
    ctx.lineTo(x1, y - 6 * r);
    ctx.stroke();
    const tw = pt.measure(b.label, 12 * r, 'bold');
    const cx = Math.min(left + w - tw / 2 - 2, Math.max(left + tw / 2 + 2, (x0 + x1) / 2));
    ctx.fillStyle = 'rgba(255,255,255,0.85)';
    ctx.fillRect(cx - tw / 2 - 3 * r, y - 24 * r, tw + 6 * r, 17 * r);
    pt.text(cx - tw / 2, y - 10 * r, b.label, { size: 12 * r, weight: 'bold', color: b.color || '#7a3cc2' });
  }
  ctx.restore();
}
