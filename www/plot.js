// @ts-check
// Live line plots around uPlot (vendor/uPlot.esm.js, copied from node_modules by the build):
// rich axis titles in HTML (sub/superscripts, never clipped), a keyboard-reachable legend of
// toggle buttons with live values, frequency/time markers whose labels never overlap, shaded
// bands, an accessible name and a text alternative for the canvas, and `figure()` — the same
// plot as an export figure (www/export.js) with title, legend and parameter line.
// Its parts are in plot/: window.js (the x window kept inside the data, the keyboard's pan and
// zoom), marks.js (bands, markers and their labels drawn over the lines).
import uPlot from './vendor/uPlot.esm.js';
import { el, rich, srOnly } from './dom.js';
import { fmt, fmtRich, plain } from './format.js';
import { context2d } from './export.js';
import { keyWindow } from './plot/window.js';
import { fillBands, drawMarks } from './plot/marks.js';
import { liveMarker } from './plot/live-marker.js';

export { uPlot };

const COLORS = {
  euler: '#1f77b4',
  centrifugal: '#ff7f0e',
  coriolis: '#2ca02c',
  stiffness_force: '#9467bd',
  aerodynamic: '#0f7c8c',
  total: '#222222',
  free: '#8c564b',
  envelope: '#d62728',
  eps_x: '#1f77b4',
  eps_y: '#ff7f0e',
  gamma_xy: '#2ca02c',
  cursor: '#7a3cc2',
};
export function color(name) {
  return COLORS[name] || '#555';
}

/** Log axes are drawn as log10(value) on a linear scale (uPlot's log scales stop near 1e-16). */
export function log10OrNull(v) {
  return v > 0 && Number.isFinite(v) ? Math.log10(v) : null;
}

/**
 * @param {uPlot} _u
 * @param {number | null} min
 * @param {number | null} max
 * @returns {uPlot.Range.MinMax}
 */
function logRange(_u, min, max) {
  if (min == null || max == null || !Number.isFinite(max)) return [-12, 0];
  const hi = Math.ceil(max + 1e-9);
  let lo = Math.floor(Math.max(min, hi - 14));
  if (lo >= hi) lo = hi - 1;
  return [lo, hi];
}

let plotIds = 0;

/**
 * @typedef {{ label: string, unit?: string, color: string, scale?: 'y' | 'y2', dash?: number[],
 *   width?: number, legend?: boolean, show?: boolean, with?: number[], points?: boolean, span?: boolean }} SeriesSpec
 * @typedef {{ x: number, label: string, color: string, dash?: number[], width?: number }} Marker
 * @typedef {{ x0: number, x1: number, label?: string, color?: string, fill?: string }} Band
 * @typedef {{
 *   name: string, title?: string, xLabel: string, xUnit: string, yLabel?: string, y2Label?: string,
 *   series: SeriesSpec[], log?: { y?: boolean, y2?: boolean }, height?: number,
 *   markers?: () => Marker[], bands?: () => Band[], ariaLabel?: string, keys?: boolean,
 *   live?: import('./plot/live-marker.js').LiveMarkerSpec,
 *   cursor?: uPlot.Cursor, hooks?: uPlot.Hooks.Arrays,
 *   onReset?: () => void, onUser?: (what: string) => void, onToggle?: (i: number, show: boolean) => void,
 * }} PlotSpec
 */

/**
 * A line plot in `parent`: markers at x positions with labels, shaded bands, a keyboard
 * (← → pan, + − zoom, 0 reset when `keys` is not false), legend toggle buttons.
 * @param {HTMLElement} parent
 * @param {PlotSpec} spec
 */
export function linePlot(parent, spec) {
  const id = `wl-plot-${++plotIds}`;
  const box = el('div', { class: 'wl-plot', 'data-plot': spec.name });
  const ytitle = el('span', { class: 'wl-ytitle', rich: spec.yLabel || '' });
  const titles = el(
    'div',
    { class: 'wl-axis-titles' },
    ytitle,
    spec.y2Label ? el('span', { class: 'wl-y2title', rich: spec.y2Label }) : null,
  );
  const stage = el('div', { class: 'wl-uplot' });
  const xtitle = el('div', { class: 'wl-xtitle', rich: `${spec.xLabel} (${spec.xUnit})` });
  const summary = srOnly('p', { id: `${id}-sum` });
  box.append(titles, stage, xtitle);
  parent.append(box);
  const width = Math.max(260, box.clientWidth || 600);
  const dpr = () => (typeof devicePixelRatio === 'number' ? devicePixelRatio : 1);
  /** @type {uPlot.Axis[]} */
  const axes = [
    { stroke: '#333', grid: { stroke: '#ececec' }, size: 34, values: (_u, vals) => vals.map((v) => fmt(v, 4)) },
  ];
  /** @type {Record<string, uPlot.Scale>} */
  const scales = { x: { time: false } };
  const hasY2 = spec.series.some((s) => s.scale === 'y2');
  for (const key of hasY2 ? ['y', 'y2'] : ['y']) {
    const log = spec.log && spec.log[key];
    scales[key] = log ? { range: logRange } : {};
    axes.push({
      scale: key,
      side: key === 'y2' ? 1 : 3,
      stroke: '#333',
      grid: { show: key === 'y', stroke: '#ececec' },
      // wide enough for the longest tick label (e.g. "−2.5×10⁻⁶"), so nothing is clipped
      size: (self, vals) => {
        if (!vals || !vals.length) return 40;
        const r = dpr();
        self.ctx.font = `${Math.round(11 * r)}px system-ui, sans-serif`;
        return Math.ceil(Math.max(...vals.map((v) => self.ctx.measureText(String(v)).width)) / r) + 16;
      },
      font: '11px system-ui, sans-serif',
      values: log
        ? (_u, vals) => vals.map((v) => (Number.isInteger(v) ? plain(`10^{${v}}`.replace('-', '−')) : ''))
        : (_u, vals) => vals.map((v) => plain(fmtRich(v, 2))),
      incrs: log ? [1, 2, 3, 5, 10] : undefined,
    });
  }
  /** @type {uPlot.Series[]} */
  const series = [
    {},
    ...spec.series.map((s) => ({
      label: plain(s.label),
      stroke: s.color,
      width: s.width ?? 1.25,
      dash: s.dash,
      scale: s.scale || 'y',
      // `points`: markers only (a scatter, e.g. one accuracy per sensor set), no line.
      points: s.points ? { show: true, size: 11, width: 1.5, fill: s.color, stroke: '#fff' } : { show: false },
      ...(s.points ? { paths: () => null } : {}),
      // `span`: a line through the points it has, across the x values it has none for.
      ...(s.span ? { spanGaps: true } : {}),
      show: s.show !== false,
    })),
  ];
  // Legend: toggle buttons with live values (keyboard-reachable; uPlot's own legend is off).
  const legend = el('div', {
    class: 'wl-legend',
    role: 'group',
    'aria-label': `${plain(spec.title || spec.name)}: series shown (press to hide or show)`,
  });
  /** @type {(HTMLElement | null)[]} */
  const values = [];
  /** @type {(HTMLButtonElement | null)[]} */
  const buttons = [];
  spec.series.forEach((s, i) => {
    if (s.legend === false) {
      values.push(null);
      buttons.push(null);
      return;
    }
    const val = el('span', { class: 'wl-legend-val' });
    const b = el(
      'button',
      {
        type: 'button',
        class: 'wl-legend-item',
        'aria-pressed': String(s.show !== false),
        'data-series': String(i + 1),
      },
      el('span', { class: 'wl-swatch', style: `background:${s.color}`, 'aria-hidden': 'true' }),
      el('span', { class: 'wl-legend-label', rich: s.label }),
      val,
    );
    b.addEventListener('click', () => {
      const show = !u.series[i + 1].show;
      u.setSeries(i + 1, { show });
      b.setAttribute('aria-pressed', String(show));
      for (const j of s.with || []) u.setSeries(j + 1, { show });
      if (spec.onToggle) spec.onToggle(i, show);
    });
    values.push(val);
    buttons.push(b);
    legend.append(b);
  });
  const xval = el('span', { class: 'wl-legend-x', 'aria-hidden': 'true' });
  legend.append(xval);
  box.append(legend, summary);

  /** @type {uPlot.Options & { hooks: uPlot.Hooks.Arrays, cursor: uPlot.Cursor }} */
  const opts = {
    width,
    height: spec.height || 220,
    scales,
    axes,
    series,
    legend: { show: false },
    cursor: { drag: { x: true, y: false, setScale: true }, points: { show: false } },
    padding: [8, 6, 0, 0],
    hooks: {
      drawClear: [
        (u) => {
          if (spec.bands) fillBands(u, spec.bands());
        },
      ],
      draw: [
        (u) => {
          drawMarks(u, spec.markers ? spec.markers() : [], spec.bands ? spec.bands() : [], dpr());
          if (live) live.place();
        },
      ],
      setCursor: [
        (u) => {
          const i = u.cursor.idx;
          xval.textContent =
            i == null ? '' : `${spec.xLabel.replace(/_/g, '')} = ${fmt(u.data[0][i], 5)} ${spec.xUnit}`;
          spec.series.forEach((s, k) => {
            const v = values[k];
            if (!v) return;
            const y = i == null ? null : u.data[k + 1][i];
            v.textContent =
              y == null || !Number.isFinite(y) ? '' : ` ${fmt(spec.log && spec.log[s.scale || 'y'] ? 10 ** y : y, 3)}`;
          });
        },
      ],
    },
  };
  if (spec.cursor) opts.cursor = { ...opts.cursor, ...spec.cursor };
  for (const [name, fns] of Object.entries(spec.hooks || {})) opts.hooks[name] = [...(opts.hooks[name] || []), ...fns];
  if (spec.series.every((s) => s.legend === false)) legend.hidden = true;
  /** @type {ReturnType<typeof liveMarker> | null} */
  let live = null;
  const u = new uPlot(opts, [[0], ...spec.series.map(() => [null])], stage);
  // `live`: a marker moved every frame without repainting the plot (www/plot/live-marker.js).
  if (spec.live) live = liveMarker(u, spec.live);
  // Accessible name and text alternative of the canvas.
  u.ctx.canvas.setAttribute('role', 'img');
  u.ctx.canvas.setAttribute('aria-label', plain(spec.ariaLabel || spec.title || spec.name));
  u.ctx.canvas.setAttribute('aria-describedby', summary.id);
  if (spec.keys !== false) {
    u.over.tabIndex = 0;
    u.over.setAttribute('role', 'group');
    u.over.setAttribute(
      'aria-label',
      `${plain(spec.ariaLabel || spec.name)}. Keys: left and right arrows pan, plus and minus zoom, 0 resets.`,
    );
    u.over.setAttribute('aria-describedby', summary.id);
    u.over.addEventListener('keydown', (e) => {
      const x = u.scales.x;
      if (x.min == null || x.max == null) return;
      const data = u.data[0];
      const lo = data[0],
        hi = data[data.length - 1];
      const next = keyWindow(e.key, x.min, x.max, lo, hi);
      if (!next) return;
      e.preventDefault();
      if (next === 'reset') {
        if (spec.onUser) spec.onUser('reset');
        if (spec.onReset) spec.onReset();
        else u.setScale('x', { min: lo, max: hi });
        return;
      }
      if (spec.onUser) spec.onUser('key');
      u.setScale('x', { min: next[0], max: next[1] });
    });
  }
  const onUser = spec.onUser;
  if (onUser) {
    u.over.addEventListener('dblclick', () => onUser('dblclick'));
    opts.hooks.setSelect = [...(opts.hooks.setSelect || [])];
  }
  /** @type {ResizeObserver | null} */
  let ro = null;
  if (typeof ResizeObserver === 'function') {
    ro = new ResizeObserver(() => {
      const w = Math.max(260, Math.floor(stage.clientWidth));
      if (Math.abs(w - u.width) > 2) u.setSize({ width: w, height: u.height });
    });
    ro.observe(stage);
  }
  return {
    u,
    box,
    legend,
    buttons,
    /** New data; keeps `keepX` ([min, max]) as the x window when given. */
    /**
     * @param {uPlot.AlignedData} data
     * @param {number[] | null} [keepX]
     */
    setData(data, keepX = null) {
      if (keepX && u.data[0].length > 1) {
        // One commit: new data in the given window (y re-ranges over it), no detour through
        // the whole run (which would build every path at full resolution first).
        u.setData(data, false);
        u.setScale('x', { min: keepX[0], max: keepX[1] });
      } else {
        u.setData(data);
        // uPlot commits setData in a microtask (auto-ranging x to the data); the window goes after it.
        if (keepX) queueMicrotask(() => u.setScale('x', { min: keepX[0], max: keepX[1] }));
      }
    },
    setHeight(h) {
      if (Math.abs(h - u.height) > 2) u.setSize({ width: u.width, height: h });
    },
    setYLabel(markup) {
      ytitle.replaceChildren(rich(markup));
    },
    /**
     * Whether series `i` (0-based, as in spec.series) exists for the current data: an absent
     * one (e.g. the aerodynamic force in a vacuum) is not drawn and has no legend button; when
     * it comes back it is drawn unless its button was switched off.
     * @param {number} i
     * @param {boolean} on
     */
    setAvailable(i, on) {
      const b = buttons[i];
      if (b) {
        b.hidden = !on;
        b.style.display = on ? '' : 'none'; // the legend's own display rule outranks `hidden`
      }
      const pressed = !b || b.getAttribute('aria-pressed') !== 'false';
      if (u.series[i + 1].show !== (on && pressed)) u.setSeries(i + 1, { show: on && pressed });
    },
    setSummary(text) {
      summary.textContent = text;
    },
    redraw() {
      u.redraw(false, false);
    },
    /**
     * Moves the spec's `live` marker to `x` (null hides it); no repaint.
     * @param {number | null} x
     */
    setLive(x) {
      if (live) live.set(x);
    },
    /** The visible series for an export figure (full data of the current x window). */
    exportSeries(data = u.data) {
      return spec.series.map((s, i) => ({
        label: s.label,
        color: s.color,
        dash: s.dash,
        width: (s.width ?? 1.25) + 0.2,
        scale: s.scale || 'y',
        y: data[i + 1],
        show: u.series[i + 1].show,
        legend: s.legend !== false,
      }));
    },
    xWindow() {
      return [u.scales.x.min, u.scales.x.max];
    },
    destroy() {
      if (ro) ro.disconnect();
      u.destroy();
    },
  };
}

/** A canvas heat map with axes and a colour bar (the initial-condition map). */
const VIRIDIS = [
  [68, 1, 84],
  [71, 44, 122],
  [59, 81, 139],
  [44, 113, 142],
  [33, 144, 141],
  [39, 173, 129],
  [92, 200, 99],
  [170, 220, 50],
  [253, 231, 37],
];
export function viridis(t) {
  const x = Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0)) * (VIRIDIS.length - 1);
  const i = Math.min(VIRIDIS.length - 2, Math.floor(x));
  const f = x - i;
  return VIRIDIS[i].map((c, k) => Math.round(c + f * (VIRIDIS[i + 1][k] - c)));
}

export function drawHeatmap(canvas, m) {
  const W = canvas.width;
  const H = canvas.height;
  const ctx = context2d(canvas);
  ctx.fillStyle = '#fff';
  ctx.fillRect(0, 0, W, H);
  const L = 78,
    R = 90,
    T = 12,
    B = 46;
  const pw = W - L - R;
  const ph = H - T - B;
  const img = ctx.createImageData(m.nx, m.ny);
  const span = m.zmax - m.zmin || 1;
  for (let j = 0; j < m.ny; j++) {
    for (let i = 0; i < m.nx; i++) {
      const v = m.z[j * m.nx + i];
      const [r, g, b] = viridis((v - m.zmin) / span);
      const o = ((m.ny - 1 - j) * m.nx + i) * 4;
      img.data[o] = r;
      img.data[o + 1] = g;
      img.data[o + 2] = b;
      img.data[o + 3] = 255;
    }
  }
  const tmp = document.createElement('canvas');
  tmp.width = m.nx;
  tmp.height = m.ny;
  context2d(tmp).putImageData(img, 0, 0);
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
  ctx.fillText(plain(m.xLabel), L + pw / 2, H - 12);
  ctx.save();
  ctx.translate(14, T + ph / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.fillText(plain(m.yLabel), 0, 0);
  ctx.restore();
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
  ctx.fillText(plain(m.zLabel), 0, 0);
  ctx.restore();
}

export { rich };
