// @ts-check
// The published sensing plate (50 mm span × 25 mm chord, root clamped on the left) drawn on a
// canvas for the "As a neuron sees it" panel (views/neural.js): every sensor of the run as a
// small grey dot, a chosen set as numbered orange discs (1 = the strongest weight), the root's
// clamp hatched. Positions in wingbeat's frame: x 0…50 mm spanwise, y 0…−25 mm chordwise.

/** Span and chord of the plate, mm. */
export const PLATE_MM = Object.freeze({ span: 50, chord: 25 });

/** Colour of a chosen sensor (the lab's accent orange). */
export const CHOSEN = '#e66100';

/**
 * Draws the plate, the grid and the set `chosen` (indices into `positions`) into `canvas`,
 * sized to `cssWidth` CSS px (the height follows the plate's aspect).
 * @param {HTMLCanvasElement} canvas
 * @param {number[][]} positions every sensor's [x, y], mm
 * @param {number[]} chosen
 * @param {number} cssWidth
 */
export function drawPlate(canvas, positions, chosen, cssWidth) {
  const dpr = typeof devicePixelRatio === 'number' ? devicePixelRatio : 1;
  const pad = 26;
  const w = Math.max(200, Math.min(640, cssWidth));
  const scale = (w - 2 * pad) / PLATE_MM.span;
  const h = Math.round(PLATE_MM.chord * scale + 2 * pad);
  canvas.style.width = `${w}px`;
  canvas.style.height = `${h}px`;
  canvas.width = Math.round(w * dpr);
  canvas.height = Math.round(h * dpr);
  const ctx = canvas.getContext('2d');
  if (!ctx) return;
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.clearRect(0, 0, w, h);
  const px = (/** @type {number} */ x) => pad + x * scale;
  const py = (/** @type {number} */ y) => pad - y * scale;
  ctx.fillStyle = '#eef3f8';
  ctx.strokeStyle = '#345';
  ctx.lineWidth = 1.5;
  ctx.fillRect(px(0), py(0), PLATE_MM.span * scale, PLATE_MM.chord * scale);
  ctx.strokeRect(px(0), py(0), PLATE_MM.span * scale, PLATE_MM.chord * scale);
  // The clamped root: a hatched strip left of x = 0.
  ctx.strokeStyle = '#666';
  ctx.lineWidth = 1;
  for (let k = 0; k <= PLATE_MM.chord * scale; k += 6) {
    ctx.beginPath();
    ctx.moveTo(px(0) - 8, py(0) + k + 6);
    ctx.lineTo(px(0), py(0) + k);
    ctx.stroke();
  }
  ctx.fillStyle = '#333';
  ctx.font = '11px system-ui, sans-serif';
  ctx.textBaseline = 'bottom';
  ctx.fillText('root (clamped)', px(0), py(0) - 4);
  ctx.textAlign = 'right';
  ctx.fillText('tip, 50 mm', px(PLATE_MM.span), py(0) - 4);
  ctx.textAlign = 'left';
  ctx.textBaseline = 'top';
  ctx.fillText('chord 25 mm ↓', px(0), py(-PLATE_MM.chord) + 4);
  ctx.fillStyle = '#9aa5b1';
  for (const [x, y] of positions) {
    ctx.beginPath();
    ctx.arc(px(x), py(y), 1.4, 0, 2 * Math.PI);
    ctx.fill();
  }
  const r = Math.max(5, Math.min(8, scale * 1.2));
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.font = `bold ${Math.round(r * 1.25)}px system-ui, sans-serif`;
  chosen.forEach((i, rank) => {
    const p = positions[i];
    if (!p) return;
    ctx.fillStyle = CHOSEN;
    ctx.beginPath();
    ctx.arc(px(p[0]), py(p[1]), r, 0, 2 * Math.PI);
    ctx.fill();
    if (rank < 9) {
      ctx.fillStyle = '#fff';
      ctx.fillText(String(rank + 1), px(p[0]), py(p[1]) + 0.5);
    }
  });
}
