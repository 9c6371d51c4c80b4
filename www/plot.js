// Plot helpers around uPlot (vendor/uPlot.esm.js, copied from node_modules by the build):
// line plots with units, frequency markers, CSV and PNG export, and a canvas heat map.
import uPlot from './vendor/uPlot.esm.js';

export { uPlot };

const COLORS = {
  euler: '#1f77b4',
  centrifugal: '#ff7f0e',
  coriolis: '#2ca02c',
  stiffness: '#9467bd',
  total: '#222222',
  free: '#8c564b',
  envelope: '#d62728',
  eps_x: '#1f77b4',
  eps_y: '#ff7f0e',
  gamma_xy: '#2ca02c',
};
export function color(name) {
  return COLORS[name] || '#555';
}

export function fmt(v, digits = 4) {
  if (v == null || Number.isNaN(v)) return '—';
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a >= 1e5 || a < 1e-3) return v.toExponential(digits - 1);
  return Number(v.toPrecision(digits)).toString();
}

/**
 * Log axes are drawn as log10(value) on a linear scale with "1e k" tick labels: uPlot's own log
 * scales only cover about 1e-16…1e16 and loop for ever below that, while the paper preset's
 * response PSDs sit near 1e-26. Callers pass log10 data for such series (see `log10OrNull`).
 */
export function log10OrNull(v) {
  return v > 0 && Number.isFinite(v) ? Math.log10(v) : null;
}

/** Limits a log10 scale to at most 14 decades below its maximum, on whole decades. */
function logRange(u, min, max) {
  if (min == null || max == null || !Number.isFinite(max)) return [-12, 0];
  const hi = Math.ceil(max + 1e-9);
  let lo = Math.floor(Math.max(min, hi - 14));
  if (lo >= hi) lo = hi - 1;
  return [lo, hi];
}

/**
 * Creates a uPlot line chart in `el`.
 * spec: { xLabel, xUnit, series: [{ label, unit, color, scale, dash }], yScales: { y: {label, unit, log} }, markers: () => [{x, label, color, dash}] }
 */
export function linePlot(el, spec) {
  const width = Math.max(280, el.clientWidth || 600);
  const axes = [
    { label: `${spec.xLabel} (${spec.xUnit})`, stroke: '#333', grid: { stroke: '#e5e5e5' } },
  ];
  const scales = { x: { time: false } };
  if (spec.xRange) scales.x.range = spec.xRange;
  for (const [key, s] of Object.entries(spec.yScales)) {
    scales[key] = s.log ? { range: logRange } : {};
    if (s.range) scales[key].range = s.range;
    axes.push({
      scale: key,
      label: `${s.label} (${s.unit})`,
      side: s.side ?? 3,
      stroke: '#333',
      grid: { show: key === 'y', stroke: '#e5e5e5' },
      size: 70,
      values: s.log ? (u, vals) => vals.map((v) => (Number.isInteger(v) ? `1e${v}` : '')) : (u, vals) => vals.map((v) => fmt(v, 2)),
      incrs: s.log ? [1, 2, 3, 5, 10] : undefined,
    });
  }
  const series = [
    { label: `${spec.xLabel} (${spec.xUnit})`, value: (u, v) => (v == null ? '—' : `${fmt(v, 5)} ${spec.xUnit}`) },
    ...spec.series.map((s) => ({
      label: s.label,
      stroke: s.color,
      width: s.width ?? 1.25,
      dash: s.dash,
      scale: s.scale || 'y',
      points: { show: false },
      value: (u, v) => (v == null ? '—' : `${fmt(spec.yScales[s.scale || 'y'].log ? 10 ** v : v, 4)} ${s.unit}`),
    })),
  ];
  const opts = {
    width,
    height: spec.height || 240,
    scales,
    axes,
    series,
    cursor: { drag: { x: true, y: false }, points: { show: false } },
    legend: { live: true },
    hooks: {
      draw: [
        (u) => {
          if (!spec.markers) return;
          const ctx = u.ctx;
          const { left, top, width: w, height: h } = u.bbox;
          ctx.save();
          ctx.font = `${Math.round(10 * devicePixelRatio)}px sans-serif`;
          ctx.textBaseline = 'top';
          for (const m of spec.markers()) {
            const x = u.valToPos(m.x, 'x', true);
            if (!(x >= left && x <= left + w)) continue;
            ctx.strokeStyle = m.color || '#999';
            ctx.lineWidth = devicePixelRatio;
            ctx.setLineDash(m.dash ? m.dash.map((d) => d * devicePixelRatio) : []);
            ctx.beginPath();
            ctx.moveTo(x, top);
            ctx.lineTo(x, top + h);
            ctx.stroke();
            if (m.label) {
              ctx.fillStyle = m.color || '#666';
              ctx.fillText(m.label, x + 2 * devicePixelRatio, top + (m.row || 0) * 12 * devicePixelRatio + 2);
            }
          }
          ctx.restore();
        },
      ],
    },
  };
  const u = new uPlot(opts, [[0], ...spec.series.map(() => [null])], el);
  return u;
}

/** Keeps a plot at its container's width. */
export function autoWidth(u, el) {
  const ro = new ResizeObserver(() => {
    const w = Math.max(280, el.clientWidth);
    if (Math.abs(w - u.width) > 2) u.setSize({ width: w, height: u.height });
  });
  ro.observe(el);
  return ro;
}

/**
 * Min/max decimation onto a shared x grid: each bucket contributes two x positions (its start
 * and middle) and, for every series, its min and max there. Keeps peaks; series stay aligned.
 */
export function decimate(x, ys, buckets) {
  const n = x.length;
  if (n <= 2 * buckets) return [Array.from(x), ...ys.map((y) => Array.from(y))];
  const xo = new Float64Array(2 * buckets);
  const yo = ys.map(() => new Float64Array(2 * buckets));
  for (let b = 0; b < buckets; b++) {
    const lo = Math.floor((b * n) / buckets);
    const hi = Math.max(lo + 1, Math.floor(((b + 1) * n) / buckets));
    xo[2 * b] = x[lo];
    xo[2 * b + 1] = x[Math.min(n - 1, (lo + hi) >> 1)];
    ys.forEach((y, k) => {
      let mn = y[lo];
      let mx = y[lo];
      let imn = lo;
      let imx = lo;
      for (let i = lo + 1; i < hi; i++) {
        const v = y[i];
        if (v < mn) { mn = v; imn = i; }
        if (v > mx) { mx = v; imx = i; }
      }
      yo[k][2 * b] = imn <= imx ? mn : mx;
      yo[k][2 * b + 1] = imn <= imx ? mx : mn;
    });
  }
  return [xo, ...yo];
}

/** CSV text from named columns (header "name (unit)"), with `#` comment lines first. */
export function toCSV(columns, comments = []) {
  const lines = comments.map((c) => `# ${c}`);
  lines.push(columns.map((c) => (c.unit ? `${c.name} (${c.unit})` : c.name)).map(csvCell).join(','));
  const n = Math.max(...columns.map((c) => c.values.length));
  for (let i = 0; i < n; i++) {
    lines.push(columns.map((c) => { const v = c.values[i]; return v == null || Number.isNaN(v) ? '' : String(v); }).join(','));
  }
  return lines.join('\n') + '\n';
}

function csvCell(s) {
  return /[",\n]/.test(s) ? `"${s.replace(/"/g, '""')}"` : s;
}

export function download(name, blob) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 10000);
}

/** A PNG of a panel: its title, then its canvases stacked (plot canvases are the real pixels). */
export async function panelPNG(title, canvases, textLines = []) {
  const dpr = 1;
  const w = Math.max(400, ...canvases.map((c) => c.width));
  const h = 30 + canvases.reduce((s, c) => s + c.height + 8, 0) + textLines.length * 18 + 10;
  const out = document.createElement('canvas');
  out.width = w * dpr;
  out.height = h * dpr;
  const ctx = out.getContext('2d');
  ctx.fillStyle = '#fff';
  ctx.fillRect(0, 0, w, h);
  ctx.fillStyle = '#111';
  ctx.font = 'bold 15px sans-serif';
  ctx.fillText(title, 10, 20);
  let y = 30;
  for (const c of canvases) {
    ctx.drawImage(c, 0, y);
    y += c.height + 8;
  }
  ctx.font = '13px sans-serif';
  for (const line of textLines) {
    y += 18;
    ctx.fillText(line, 10, y);
  }
  return new Promise((resolve) => out.toBlob(resolve, 'image/png'));
}

// A perceptually ordered colour map (viridis, 9 stops, linear in between).
const VIRIDIS = [
  [68, 1, 84], [71, 44, 122], [59, 81, 139], [44, 113, 142], [33, 144, 141],
  [39, 173, 129], [92, 200, 99], [170, 220, 50], [253, 231, 37],
];
export function viridis(t) {
  const x = Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0)) * (VIRIDIS.length - 1);
  const i = Math.min(VIRIDIS.length - 2, Math.floor(x));
  const f = x - i;
  return VIRIDIS[i].map((c, k) => Math.round(c + f * (VIRIDIS[i + 1][k] - c)));
}

/**
 * Draws a heat map with axes and a colour bar onto `canvas`.
 * m: { nx, ny, x: Float64Array, y: Float64Array, z: Float64Array (row-major, y outer), zmin, zmax,
 *      xLabel, yLabel, zLabel }
 */
export function drawHeatmap(canvas, m) {
  const W = canvas.width;
  const H = canvas.height;
  const ctx = canvas.getContext('2d');
  ctx.fillStyle = '#fff';
  ctx.fillRect(0, 0, W, H);
  const L = 78, R = 90, T = 12, B = 46;
  const pw = W - L - R;
  const ph = H - T - B;
  const img = ctx.createImageData(m.nx, m.ny);
  const span = m.zmax - m.zmin || 1;
  for (let j = 0; j < m.ny; j++) {
    for (let i = 0; i < m.nx; i++) {
      const v = m.z[j * m.nx + i];
      const [r, g, b] = viridis((v - m.zmin) / span);
      const o = ((m.ny - 1 - j) * m.nx + i) * 4; // q̇0 grows upward
      img.data[o] = r; img.data[o + 1] = g; img.data[o + 2] = b; img.data[o + 3] = 255;
    }
  }
  const tmp = document.createElement('canvas');
  tmp.width = m.nx;
  tmp.height = m.ny;
  tmp.getContext('2d').putImageData(img, 0, 0);
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(tmp, L, T, pw, ph);
  ctx.strokeStyle = '#333';
  ctx.strokeRect(L, T, pw, ph);
  ctx.fillStyle = '#222';
  ctx.font = '11px sans-serif';
  ctx.textAlign = 'center';
  for (let k = 0; k <= 4; k++) {
    const xv = m.x[0] + ((m.x[m.x.length - 1] - m.x[0]) * k) / 4;
    ctx.fillText(fmt(xv, 3), L + (pw * k) / 4, T + ph + 14);
    const yv = m.y[0] + ((m.y[m.y.length - 1] - m.y[0]) * k) / 4;
    ctx.textAlign = 'right';
    ctx.fillText(fmt(yv, 3), L - 4, T + ph - (ph * k) / 4 + 4);
    ctx.textAlign = 'center';
  }
  ctx.fillText(m.xLabel, L + pw / 2, H - 12);
  ctx.save();
  ctx.translate(14, T + ph / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.fillText(m.yLabel, 0, 0);
  ctx.restore();
  // colour bar
  const cx = W - R + 16;
  for (let y = 0; y < ph; y++) {
    const [r, g, b] = viridis(1 - y / ph);
    ctx.fillStyle = `rgb(${r},${g},${b})`;
    ctx.fillRect(cx, T + y, 16, 1);
  }
  ctx.strokeRect(cx, T, 16, ph);
  ctx.fillStyle = '#222';
  ctx.textAlign = 'left';
  ctx.fillText(fmt(m.zmax, 3), cx + 20, T + 8);
  ctx.fillText(fmt(m.zmin, 3), cx + 20, T + ph);
  ctx.save();
  ctx.translate(W - 8, T + ph / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.textAlign = 'center';
  ctx.fillText(m.zLabel, 0, 0);
  ctx.restore();
}
