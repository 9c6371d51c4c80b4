// @ts-check
// Exports: CSV text, publishable figures (PNG at 2× and SVG from ONE drawing routine, with
// title, axes, legend swatches and the parameter line), downloads, and the label placement the
// live plots share. The drawing code talks to a small "painter" (canvas or SVG), so both files
// show the same figure. Pure except figurePNG/download (DOM); unit-tested in
// tests/js/export.test.mjs with the SVG painter.
import { parseRich, plain, fmt, fmtRich } from './format.js';

/** CSV text from named columns (header "name (unit)"), `#` comment lines first. */
export function toCSV(columns, comments = []) {
  const lines = comments.map((c) => `# ${c}`);
  lines.push(
    columns
      .map((c) => (c.unit ? `${c.name} (${c.unit})` : c.name))
      .map(csvCell)
      .join(','),
  );
  const n = Math.max(...columns.map((c) => c.values.length));
  for (let i = 0; i < n; i++) {
    lines.push(
      columns
        .map((c) => {
          const v = c.values[i];
          return v == null || Number.isNaN(v) ? '' : String(v);
        })
        .join(','),
    );
  }
  return lines.join('\n') + '\n';
}

export function csvCell(s) {
  return /[",\n]/.test(s) ? `"${s.replace(/"/g, '""')}"` : s;
}

/** Saves a Blob under `name` (browser only). */
export function download(name, blob) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 10000);
}

/** "Nice" tick values covering [lo, hi], about `count` of them. */
export function niceTicks(lo, hi, count = 6) {
  if (!Number.isFinite(lo) || !Number.isFinite(hi)) return [];
  if (hi < lo) [lo, hi] = [hi, lo];
  if (hi === lo) return [lo];
  const raw = (hi - lo) / Math.max(1, count);
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * mag).find((s) => s >= raw) || 10 * mag;
  const out = [];
  for (let v = Math.ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step)
    out.push(Math.abs(v) < step * 1e-9 ? 0 : Number(v.toPrecision(12)));
  return out;
}

/**
 * Greedy label rows so that no two labels overlap: items [{ x, width }] (pixels, x = label's
 * left edge) sorted or not; returns the row of each item (0, 1, …), at most `maxRows` rows
 * (labels that fit nowhere get row -1 and should be left out).
 */
export function placeLabels(items, { gap = 4, maxRows = 3 } = {}) {
  const order = items.map((_it, i) => i).sort((a, b) => items[a].x - items[b].x);
  const ends = [];
  const rows = new Array(items.length).fill(-1);
  for (const i of order) {
    const { x, width } = items[i];
    let r = 0;
    while (r < ends.length && ends[r] + gap > x) r++;
    if (r >= maxRows) continue;
    ends[r] = x + width;
    rows[i] = r;
  }
  return rows;
}

const FONT = 'system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';

function approxWidth(text, size) {
  return [...text].length * size * 0.56;
}

/**
 * The 2-D context of a canvas (throws where the browser gives none, e.g. out of memory).
 * @param {HTMLCanvasElement} c
 * @returns {CanvasRenderingContext2D}
 */
export function context2d(c) {
  const ctx = c.getContext('2d');
  if (!ctx) throw new Error('no 2-D canvas context');
  return ctx;
}

/**
 * Walks a flat polyline [x0, y0, x1, y1, …] for both painters: calls `to(x, y, drawing)` at each
 * finite point, with `drawing` false where the pen is lifted (the first point, and the first one
 * after a non-finite coordinate, which breaks the line).
 * @param {ArrayLike<number>} pts
 * @param {(x: number, y: number, drawing: boolean) => void} to
 */
function tracePolyline(pts, to) {
  let pen = false;
  for (let i = 0; i < pts.length; i += 2) {
    const x = pts[i],
      y = pts[i + 1];
    if (!Number.isFinite(x) || !Number.isFinite(y)) {
      pen = false;
      continue;
    }
    to(x, y, pen);
    pen = true;
  }
}

/** @typedef {(s: string, size: number) => number} MeasureFn text width in CSS px of rich markup at a font size */

/**
 * A painter over a CanvasRenderingContext2D (coordinates in CSS pixels; pre-scaled).
 * @param {CanvasRenderingContext2D} ctx
 */
export function canvasPainter(ctx) {
  const font = (size, weight = 'normal') => `${weight} ${size}px ${FONT}`;
  return {
    rect(x, y, w, h, fill, stroke) {
      if (fill) {
        ctx.fillStyle = fill;
        ctx.fillRect(x, y, w, h);
      }
      if (stroke) {
        ctx.strokeStyle = stroke;
        ctx.lineWidth = 1;
        ctx.strokeRect(x + 0.5, y + 0.5, w, h);
      }
    },
    line(pts, color, width = 1, dash = /** @type {number[] | null} */ (null), alpha = 1) {
      if (pts.length < 4) return;
      ctx.save();
      ctx.globalAlpha = alpha;
      ctx.strokeStyle = color;
      ctx.lineWidth = width;
      ctx.lineJoin = 'round';
      ctx.setLineDash(dash || []);
      ctx.beginPath();
      tracePolyline(pts, (x, y, drawing) => {
        if (drawing) ctx.lineTo(x, y);
        else ctx.moveTo(x, y);
      });
      ctx.stroke();
      ctx.restore();
    },
    /**
     * @param {number} x
     * @param {number} y
     * @param {string} s rich markup
     * @param {{ size?: number, weight?: string, color?: string, align?: 'left' | 'center' | 'right', baseline?: CanvasTextBaseline, rotate?: number }} [o]
     */
    text(
      x,
      y,
      s,
      { size = 12, weight = 'normal', color = '#222', align = 'left', baseline = 'alphabetic', rotate = 0 } = {},
    ) {
      ctx.save();
      ctx.translate(x, y);
      if (rotate) ctx.rotate(rotate);
      ctx.fillStyle = color;
      ctx.textBaseline = baseline;
      ctx.textAlign = 'left';
      const runs = parseRich(s);
      const w = this.measure(s, size, weight);
      let cx = align === 'center' ? -w / 2 : align === 'right' ? -w : 0;
      for (const r of runs) {
        const small = r.kind !== 'normal';
        ctx.font = font(small ? Math.round(size * 0.72) : size, weight);
        const dy = r.kind === 'sub' ? size * 0.28 : r.kind === 'sup' ? -size * 0.38 : 0;
        ctx.fillText(r.text, cx, dy);
        cx += ctx.measureText(r.text).width;
      }
      ctx.restore();
    },
    measure(s, size = 12, weight = 'normal') {
      let w = 0;
      for (const r of parseRich(s)) {
        ctx.font = font(r.kind !== 'normal' ? Math.round(size * 0.72) : size, weight);
        w += ctx.measureText(r.text).width;
      }
      return w;
    },
  };
}

const esc = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

/**
 * A painter that builds an SVG document; `toString()` returns it.
 * @param {number} width
 * @param {number} height
 * @param {MeasureFn | null} [measureFn]
 */
export function svgPainter(width, height, measureFn = null) {
  /** @type {string[]} */
  const parts = [];
  const measure = (s, size = 12) =>
    measureFn
      ? measureFn(s, size)
      : parseRich(s).reduce((w, r) => w + approxWidth(r.text, r.kind !== 'normal' ? size * 0.72 : size), 0);
  return {
    rect(x, y, w, h, fill, stroke) {
      parts.push(
        `<rect x="${x}" y="${y}" width="${w}" height="${h}" fill="${fill || 'none'}"${stroke ? ` stroke="${stroke}"` : ''}/>`,
      );
    },
    line(pts, color, width = 1, dash = /** @type {number[] | null} */ (null), alpha = 1) {
      let d = '';
      tracePolyline(pts, (x, y, drawing) => {
        d += `${drawing ? 'L' : 'M'}${x.toFixed(2)} ${y.toFixed(2)}`;
      });
      if (!d) return;
      parts.push(
        `<path d="${d}" fill="none" stroke="${color}" stroke-width="${width}"${dash ? ` stroke-dasharray="${dash.join(' ')}"` : ''}${alpha < 1 ? ` stroke-opacity="${alpha}"` : ''} stroke-linejoin="round"/>`,
      );
    },
    text(
      x,
      y,
      s,
      { size = 12, weight = 'normal', color = '#222', align = 'left', baseline = 'alphabetic', rotate = 0 } = {},
    ) {
      const anchor = align === 'center' ? 'middle' : align === 'right' ? 'end' : 'start';
      const base = baseline === 'top' ? 'hanging' : baseline === 'middle' ? 'middle' : 'auto';
      const spans = parseRich(s)
        .map((r) =>
          r.kind === 'normal'
            ? `<tspan>${esc(r.text)}</tspan>`
            : `<tspan baseline-shift="${r.kind === 'sub' ? 'sub' : 'super'}" font-size="${Math.round(size * 0.72)}">${esc(r.text)}</tspan>`,
        )
        .join('');
      const tr = rotate ? ` transform="rotate(${(rotate * 180) / Math.PI} ${x} ${y})"` : '';
      parts.push(
        `<text x="${x}" y="${y}" font-size="${size}" font-weight="${weight}" fill="${color}" text-anchor="${anchor}" dominant-baseline="${base}"${tr}>${spans}</text>`,
      );
    },
    measure,
    toString() {
      return `<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}" font-family='${FONT}'>\n${parts.join('\n')}\n</svg>\n`;
    },
  };
}

const logLabel = (v) => `10^{${String(v).replace('-', '−')}}`;

/**
 * Draws a figure with painter `p` in a width × height box (CSS pixels).
 * fig: { title, params, note, xLabel, yLabel, y2Label, x, series: [{ label, color, y, scale:
 *   'y'|'y2', dash, width, show }], xRange, log: { y, y2 } (series hold log10 values),
 *   markers: [{ x, label, color, dash }], bands: [{ x0, x1, label, color }], legendTitle }
 * Returns the layout { plot: {left, top, width, height}, legend: [{ label, color, x, y, size }] }.
 */
export function drawFigure(p, fig, width, height) {
  p.rect(0, 0, width, height, '#ffffff');
  let y = 26;
  p.text(16, y, fig.title || '', { size: 17, weight: 'bold', color: '#111' });
  y += 20;
  // Parameter line(s), wrapped.
  const paramLines = wrap(p, fig.params || '', width - 32, 12);
  for (const l of paramLines) {
    p.text(16, y, l, { size: 12, color: '#444' });
    y += 16;
  }
  const visible = fig.series.filter((s) => s.show !== false);
  const inLegend = visible.filter((s) => s.legend !== false);
  // Legend block at the bottom: swatch + label, wrapped in rows.
  const sw = 14;
  const legendItems = [];
  let lx = 16,
    rowsH = 0;
  const legendW = width - 32;
  const itemW = inLegend.map((s) => sw + 6 + p.measure(s.label, 12) + 18);
  let row = 0;
  inLegend.forEach((s, i) => {
    if (lx + itemW[i] > 16 + legendW && lx > 16) {
      row++;
      lx = 16;
    }
    legendItems.push({ s, x: lx, row });
    lx += itemW[i];
  });
  rowsH = inLegend.length ? (row + 1) * 22 : 0;
  const noteLines = fig.note ? wrap(p, fig.note, width - 32, 11) : [];
  const bottom = height - rowsH - 12 - noteLines.length * 15;
  const hasY2 = fig.series.some((s) => s.scale === 'y2');
  const plot = { left: 78, top: y + 22, width: width - 78 - (hasY2 ? 78 : 24), height: 0 };
  plot.height = Math.max(60, bottom - 44 - plot.top);
  // Axis titles (horizontal, above each y axis: never clipped, never rotated).
  p.text(plot.left - 70, plot.top - 10, fig.yLabel || '', { size: 12, color: '#222' });
  if (hasY2)
    p.text(plot.left + plot.width + 70, plot.top - 10, fig.y2Label || '', { size: 12, color: '#222', align: 'right' });
  p.text(plot.left + plot.width, plot.top + plot.height + 36, fig.xLabel || '', {
    size: 12,
    color: '#222',
    align: 'right',
  });
  // Scales.
  const x = fig.x;
  let [x0, x1] = fig.xRange || [x[0], x[x.length - 1]];
  if (!(x1 > x0)) x1 = x0 + 1;
  const i0 = lowerBound(x, x0),
    i1 = Math.min(x.length, lowerBound(x, x1) + 1);
  const range = (scale) => {
    let lo = Infinity,
      hi = -Infinity;
    for (const s of visible) {
      if ((s.scale || 'y') !== scale) continue;
      for (let i = i0; i < i1; i++) {
        const v = s.y[i];
        if (v == null || !Number.isFinite(v)) continue;
        if (v < lo) lo = v;
        if (v > hi) hi = v;
      }
    }
    if (!Number.isFinite(lo)) return [0, 1];
    if (fig.log && fig.log[scale]) {
      hi = Math.ceil(hi + 1e-9);
      lo = Math.floor(Math.max(lo, hi - 14));
      return [lo, Math.max(hi, lo + 1)];
    }
    if (hi === lo) {
      hi += Math.abs(hi) || 1;
      lo -= Math.abs(lo) || 1;
    }
    const pad = 0.05 * (hi - lo);
    return [lo - pad, hi + pad];
  };
  const ys = { y: range('y'), y2: hasY2 ? range('y2') : null };
  const X = (v) => plot.left + ((v - x0) / (x1 - x0)) * plot.width;
  const Y = (v, sc = 'y') => plot.top + plot.height - ((v - ys[sc][0]) / (ys[sc][1] - ys[sc][0])) * plot.height;
  // Bands (e.g. the marked beat) under everything.
  for (const b of fig.bands || []) {
    const bx0 = Math.max(plot.left, X(b.x0)),
      bx1 = Math.min(plot.left + plot.width, X(b.x1));
    if (bx1 > bx0) p.rect(bx0, plot.top, bx1 - bx0, plot.height, b.fill || 'rgba(122,60,194,0.10)');
  }
  // Grid, ticks, labels.
  p.rect(plot.left, plot.top, plot.width, plot.height, null, '#999');
  for (const v of niceTicks(x0, x1, Math.max(3, Math.round(plot.width / 110)))) {
    const px = X(v);
    p.line([px, plot.top, px, plot.top + plot.height], '#e6e6e6', 1);
    p.text(px, plot.top + plot.height + 16, fmt(v, 4), { size: 11, align: 'center', color: '#333' });
  }
  for (const sc of hasY2 ? ['y', 'y2'] : ['y']) {
    const [lo, hi] = ys[sc];
    const log = fig.log && fig.log[sc];
    const ticks = log
      ? niceTicks(lo, hi, 6).filter(Number.isInteger)
      : niceTicks(lo, hi, Math.max(3, Math.round(plot.height / 60)));
    for (const v of ticks) {
      const py = Y(v, sc);
      if (sc === 'y') p.line([plot.left, py, plot.left + plot.width, py], '#e6e6e6', 1);
      const label = log ? logLabel(v) : fmtRich(v, 3);
      if (sc === 'y') p.text(plot.left - 6, py + 4, label, { size: 11, align: 'right', color: '#333' });
      else p.text(plot.left + plot.width + 6, py + 4, label, { size: 11, color: '#333' });
    }
  }
  // Series (min/max per pixel column keeps the envelope of dense data).
  for (const s of visible) {
    const sc = s.scale || 'y';
    const pts = [];
    const cols = Math.max(1, Math.round(plot.width * 2));
    const step = Math.max(1, Math.floor((i1 - i0) / cols));
    for (let i = i0; i < i1; i += step) {
      let mn = Infinity,
        mx = -Infinity,
        imn = i,
        imx = i;
      for (let j = i; j < Math.min(i1, i + step); j++) {
        const v = s.y[j];
        if (v == null || !Number.isFinite(v)) continue;
        if (v < mn) {
          mn = v;
          imn = j;
        }
        if (v > mx) {
          mx = v;
          imx = j;
        }
      }
      if (!Number.isFinite(mn)) {
        pts.push(NaN, NaN);
        continue;
      }
      const first = imn <= imx ? mn : mx,
        second = imn <= imx ? mx : mn;
      pts.push(
        X(x[Math.min(imn, imx)]),
        clampY(Y(first, sc), plot),
        X(x[Math.max(imn, imx)]),
        clampY(Y(second, sc), plot),
      );
    }
    p.line(pts, s.color, s.width || 1.3, s.dash || null);
  }
  // Markers with non-overlapping labels.
  const marks = (fig.markers || []).filter((m) => m.x >= x0 && m.x <= x1);
  const rows = placeLabels(marks.map((m) => ({ x: X(m.x) + 3, width: p.measure(m.label || '', 11) })));
  marks.forEach((m, i) => {
    const px = X(m.x);
    p.line([px, plot.top, px, plot.top + plot.height], m.color || '#888', 1, m.dash || null);
    if (m.label && rows[i] >= 0)
      p.text(px + 3, plot.top + 13 + rows[i] * 14, m.label, { size: 11, color: m.color || '#555' });
  });
  for (const b of fig.bands || []) {
    if (!b.label) continue;
    const bx0 = X(b.x0),
      bx1 = X(b.x1);
    const by = plot.top + plot.height - 12;
    p.line([bx0, by - 5, bx0, by, bx1, by, bx1, by - 5], b.color || '#7a3cc2', 1.5);
    p.text((bx0 + bx1) / 2, by - 8, b.label, {
      size: 12,
      weight: 'bold',
      align: 'center',
      color: b.color || '#7a3cc2',
    });
  }
  // Legend.
  const legend = [];
  const ly = height - rowsH - 6 - noteLines.length * 15;
  for (const { s, x: ix, row: r } of legendItems) {
    const yy = ly + r * 22;
    p.rect(ix, yy, sw, sw, s.color);
    p.text(ix + sw + 6, yy + 11, s.label, { size: 12, color: '#222' });
    legend.push({ label: s.label, color: s.color, x: ix, y: yy, size: sw });
  }
  let ny = height - noteLines.length * 15 + 4;
  for (const l of noteLines) {
    p.text(16, ny, l, { size: 11, color: '#555' });
    ny += 15;
  }
  return { plot, legend };
}

function clampY(v, plot) {
  return Math.min(plot.top + plot.height, Math.max(plot.top, v));
}

function lowerBound(x, v) {
  let lo = 0,
    hi = x.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (x[mid] < v) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

/** Word-wraps plain text to lines no wider than `max` pixels. */
export function wrap(p, text, max, size = 12) {
  const words = String(text).split(/\s+/).filter(Boolean);
  const lines = [];
  let cur = '';
  for (const w of words) {
    const next = cur ? `${cur} ${w}` : w;
    if (cur && p.measure(next, size) > max) {
      lines.push(cur);
      cur = w;
    } else cur = next;
  }
  if (cur) lines.push(cur);
  return lines;
}

/**
 * The figure as SVG text (width × height CSS px).
 * @param {any} fig a figure description (see drawFigure)
 * @param {number} [width]
 * @param {number} [height]
 * @param {MeasureFn | null} [measureFn]
 */
export function figureSVG(fig, width = 900, height = 560, measureFn = null) {
  const p = svgPainter(width, height, measureFn);
  drawFigure(p, fig, width, height);
  return p.toString();
}

/** The figure as a PNG Blob at `scale`× (browser only). Resolves to { blob, width, height }. */
export function figurePNG(fig, width = 900, height = 560, scale = 2) {
  const c = document.createElement('canvas');
  c.width = Math.round(width * scale);
  c.height = Math.round(height * scale);
  const ctx = context2d(c);
  ctx.scale(scale, scale);
  drawFigure(canvasPainter(ctx), fig, width, height);
  return new Promise((resolve) => c.toBlob((blob) => resolve({ blob, width: c.width, height: c.height }), 'image/png'));
}

/**
 * A text-only figure (tables): title, parameter line, then rows of cells, at `scale`×.
 * rows: [[cell, …], …]; the first row is the header.
 */
export function tablePNG(title, params, rows, scale = 2) {
  const probe = canvasPainter(context2d(document.createElement('canvas')));
  const cols = rows[0].length;
  const widths = Array.from(
    { length: cols },
    (_, j) => Math.max(...rows.map((r) => probe.measure(plain(String(r[j])), 12))) + 18,
  );
  const width = Math.max(520, 32 + widths.reduce((a, b) => a + b, 0));
  const paramLines = wrap(probe, params, width - 32, 12);
  const height = 60 + paramLines.length * 16 + rows.length * 20 + 10;
  const c = document.createElement('canvas');
  c.width = width * scale;
  c.height = height * scale;
  const ctx = context2d(c);
  ctx.scale(scale, scale);
  const p = canvasPainter(ctx);
  p.rect(0, 0, width, height, '#fff');
  p.text(16, 26, title, { size: 17, weight: 'bold', color: '#111' });
  let y = 46;
  for (const l of paramLines) {
    p.text(16, y, l, { size: 12, color: '#444' });
    y += 16;
  }
  y += 8;
  rows.forEach((r, i) => {
    let x = 16;
    r.forEach((cell, j) => {
      p.text(x, y, String(cell), { size: 12, weight: i === 0 ? 'bold' : 'normal', color: '#222' });
      x += widths[j];
    });
    y += 20;
  });
  return new Promise((resolve) => c.toBlob((blob) => resolve({ blob, width: c.width, height: c.height }), 'image/png'));
}
