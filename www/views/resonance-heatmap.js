// @ts-check
// The resonance map's heat map (α0 as a second axis): the largest |multiplier| over all modes as
// an image on (f_d, α0), the f_eff = n·f_d crossings as dots and a colour bar. The values come
// from views/resonance-data.js; this module only paints.
import { plain } from '../format.js';
import { viridis } from '../plot.js';
import { context2d } from '../export.js';
import { fmt } from '../experiments.js';
import { MODE_COLORS, heatmapField, heatmapCrossings } from './resonance-data.js';

/**
 * Heat map of the largest |multiplier| over all modes on (f_d, α0), with the f_eff = n·f_d
 * resonance curves of each mode drawn over it and a colour bar. Pixel-exact, DPR-aware.
 */
export function drawResonanceHeatmap(canvas, r) {
  const cssW = canvas.clientWidth || 640;
  const cssH = Math.round(Math.min(420, Math.max(260, cssW * 0.55)));
  const dpr = devicePixelRatio || 1;
  canvas.width = Math.round(cssW * dpr);
  canvas.height = Math.round(cssH * dpr);
  canvas.style.height = `${cssH}px`;
  const ctx = context2d(canvas);
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.fillStyle = '#fff';
  ctx.fillRect(0, 0, cssW, cssH);
  const L = 64,
    R = 96,
    T = 10,
    B = 44;
  const pw = cssW - L - R;
  const ph = cssH - T - B;
  const nx = r.flap_hz.length;
  const ny = r.alpha0.length;
  const { z, zmin, zmax } = heatmapField(r);
  const img = ctx.createImageData(nx, ny);
  for (let j = 0; j < ny; j++) {
    for (let i = 0; i < nx; i++) {
      const v = z[j * nx + i];
      const [cr, cg, cb] = Number.isFinite(v) ? viridis((v - zmin) / (zmax - zmin)) : [200, 200, 200];
      const o = ((ny - 1 - j) * nx + i) * 4;
      img.data[o] = cr;
      img.data[o + 1] = cg;
      img.data[o + 2] = cb;
      img.data[o + 3] = 255;
    }
  }
  const tmp = document.createElement('canvas');
  tmp.width = nx;
  tmp.height = ny;
  context2d(tmp).putImageData(img, 0, 0);
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(tmp, L, T, pw, ph);
  const f0 = r.flap_hz[0],
    f1 = r.flap_hz[nx - 1];
  const a0 = r.alpha0[0],
    a1 = r.alpha0[ny - 1];
  const X = (f) => L + ((f - f0) / (f1 - f0 || 1)) * pw;
  const Y = (a) => T + ph - ((a - a0) / (a1 - a0 || 1)) * ph;
  // Resonance curves: where each mode's f_eff crosses n·f_d, row by row.
  ctx.save();
  ctx.beginPath();
  ctx.rect(L, T, pw, ph);
  ctx.clip();
  heatmapCrossings(r).forEach((perN, k) => {
    ctx.strokeStyle = '#fff';
    ctx.fillStyle = MODE_COLORS[k % MODE_COLORS.length];
    for (const { points } of perN) {
      for (const [f, a] of points) {
        ctx.beginPath();
        ctx.arc(X(f), Y(a), 2.5, 0, 2 * Math.PI);
        ctx.fill();
        ctx.lineWidth = 0.8;
        ctx.stroke();
      }
    }
  });
  ctx.restore();
  ctx.strokeStyle = '#333';
  ctx.lineWidth = 1;
  ctx.strokeRect(L, T, pw, ph);
  ctx.fillStyle = '#222';
  ctx.font = '11px system-ui, sans-serif';
  ctx.textAlign = 'center';
  for (let k = 0; k <= 5; k++) {
    const f = f0 + ((f1 - f0) * k) / 5;
    ctx.fillText(plain(fmt(f, 3)), X(f), T + ph + 14);
  }
  ctx.textAlign = 'right';
  for (let k = 0; k <= 4; k++) {
    const a = a0 + ((a1 - a0) * k) / 4;
    ctx.fillText(plain(fmt(a, 3)), L - 4, Y(a) + 4);
  }
  ctx.textAlign = 'center';
  ctx.fillText('flap frequency fd (Hz)', L + pw / 2, cssH - 10);
  ctx.save();
  ctx.translate(14, T + ph / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.fillText('roll amplitude α0 (rad)', 0, 0);
  ctx.restore();
  const cx = cssW - R + 14;
  for (let y = 0; y < ph; y++) {
    const [cr, cg, cb] = viridis(1 - y / ph);
    ctx.fillStyle = `rgb(${cr},${cg},${cb})`;
    ctx.fillRect(cx, T + y, 14, 1);
  }
  ctx.strokeRect(cx, T, 14, ph);
  ctx.fillStyle = '#222';
  ctx.textAlign = 'left';
  ctx.fillText(plain(fmt(zmax, 5)), cx + 18, T + 9);
  ctx.fillText(plain(fmt(zmin, 5)), cx + 18, T + ph);
  ctx.save();
  ctx.translate(cssW - 8, T + ph / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.fillText('largest |λ| (–)', 0, 0);
  ctx.restore();
  return { zmin, zmax };
}
