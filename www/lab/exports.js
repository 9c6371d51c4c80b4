// @ts-check
// The panels' export buttons and what they download: CSV from the panel's own text, SVG and PNG
// (2×) figures from one drawing routine (www/export.js), a table or a drawn canvas as PNG with a
// title and the parameter line. Used by www/lab.js, which keeps each panel's registration.
import { el } from '../dom.js';
import { plain } from '../format.js';
import { download, figurePNG, figureSVG, tablePNG, canvasPainter, context2d } from '../export.js';

/** The figures' size in CSS pixels (PNG at 2×). */
export const FIG_W = 900,
  FIG_H = 560;

/** @typedef {import('../lab.js').ExportReg} ExportReg */
/** @typedef {{ name: string, kind: string, width?: number, height?: number, legend?: string[] }} ExportDone */

/**
 * A drawn canvas (the heat map) with title and parameter line, at 2×.
 * @param {string} title
 * @param {string} params
 * @param {HTMLCanvasElement} src
 * @returns {Promise<{ blob: Blob | null, width: number, height: number }>}
 */
function canvasPNG(title, params, src) {
  const w = Math.max(600, src.width + 32),
    h = src.height + 90;
  const c = document.createElement('canvas');
  c.width = 2 * w;
  c.height = 2 * h;
  const ctx = context2d(c);
  ctx.scale(2, 2);
  const p = canvasPainter(ctx);
  p.rect(0, 0, w, h, '#fff');
  p.text(16, 26, title, { size: 17, weight: 'bold', color: '#111' });
  p.text(16, 46, params.length > 130 ? params.slice(0, 127) + '…' : params, { size: 11, color: '#444' });
  ctx.drawImage(src, 16, 64);
  return new Promise((resolve) => c.toBlob((blob) => resolve({ blob, width: c.width, height: c.height }), 'image/png'));
}

/**
 * Downloads panel `name`'s export of `kind` (csv | png | svg); resolves to what was exported,
 * or undefined after a notice when the panel has nothing to export yet.
 * @param {ExportReg | undefined} reg the panel's registration
 * @param {string} name
 * @param {string} kind
 * @param {string} label the panel's title
 * @param {{ notice: (text: string) => void, describe: () => string }} lab
 * @returns {Promise<ExportDone | undefined>}
 */
export async function exportPanel(reg, name, kind, label, { notice, describe }) {
  const nothing = () => {
    notice(`Nothing to export yet for “${plain(label)}”: run it first.`);
    return undefined;
  };
  if (!reg) return nothing();
  if (kind === 'csv') {
    const text = reg.csv && reg.csv();
    if (!text) return nothing();
    download(`wingbeat-${name}.csv`, new Blob([text], { type: 'text/csv;charset=utf-8' }));
    return { name, kind };
  }
  const fig = reg.figure && reg.figure();
  if (kind === 'svg') {
    if (!fig) return nothing();
    const probe = canvasPainter(context2d(document.createElement('canvas')));
    download(
      `wingbeat-${name}.svg`,
      new Blob([figureSVG(fig, FIG_W, FIG_H, (s, size) => probe.measure(s, size))], { type: 'image/svg+xml' }),
    );
    return { name, kind };
  }
  let out;
  if (fig) out = await figurePNG(fig, FIG_W, FIG_H, 2);
  else if (reg.table && reg.table()) out = await tablePNG(plain(label), describe(), reg.table(), 2);
  else if (reg.canvas && reg.canvas())
    out = await canvasPNG(plain(label), describe(), /** @type {HTMLCanvasElement} */ (reg.canvas()));
  else return nothing();
  download(`wingbeat-${name}.png`, out.blob);
  return {
    name,
    kind,
    width: out.width,
    height: out.height,
    legend: fig ? fig.series.filter((s) => s.show !== false).map((s) => s.color) : [],
  };
}

/**
 * A panel's export buttons: one per kind, folded behind one "Export…" toggle on a focused
 * screen (style.css); the full page shows them all.
 * @param {string} name the panel
 * @param {string} label its title
 * @param {string[]} kinds
 * @param {(name: string, kind: string, label: string) => void} onExport
 */
export function exportButtons(name, label, kinds, onExport) {
  const box = el('span', { class: 'wl-export' });
  const toggle = el('button', {
    type: 'button',
    class: 'wl-export-toggle',
    'aria-expanded': 'false',
    'aria-label': `Export ${plain(label)}…`,
    text: 'Export…',
  });
  toggle.addEventListener('click', () => {
    const open = toggle.getAttribute('aria-expanded') !== 'true';
    toggle.setAttribute('aria-expanded', String(open));
    box.classList.toggle('wl-open', open);
  });
  box.append(toggle);
  for (const kind of kinds) {
    box.append(
      el('button', {
        type: 'button',
        text: kind.toUpperCase(),
        'data-export': kind,
        'data-target': name,
        'aria-label': `Export ${plain(label)} as ${kind.toUpperCase()}`,
        onclick: () => onExport(name, kind, label),
      }),
    );
  }
  return box;
}
