// @ts-check
// The responses panel's overview strip (views/time.js): the whole run (total response and
// envelope, decimated) with the window the responses plot shows shaded; a drag across it or a
// click on it moves that window.
import { linePlot, color } from '../plot.js';

/**
 * @param {HTMLElement} section
 * @param {{
 *   bands: () => import('../plot.js').Band[],
 *   shown: () => number[] | null,
 *   move: (w: number[]) => void,
 * }} o `bands()` are drawn under the window's shade; `shown()` is the window shown [t0, t1]
 *   (s); `move(w)` is called with the window the user picks.
 */
export function timeOverview(section, { bands, shown, move }) {
  const ov = linePlot(section, {
    name: 'time-overview',
    title: 'Whole run',
    ariaLabel:
      'Overview of the whole run (total response and envelope); the shaded window is what the responses plot shows',
    xLabel: 't',
    xUnit: 's',
    yLabel: '',
    series: [
      { label: 'Total', color: '#8a8a8a', width: 1, legend: false },
      { label: 'Envelope', color: color('envelope'), width: 1.6, legend: false },
    ],
    height: 150,
    keys: false,
    bands: () => {
      const win = shown();
      return [...bands(), ...(win ? [{ x0: win[0], x1: win[1], fill: 'rgba(31,95,191,0.18)' }] : [])];
    },
    cursor: { drag: { x: true, y: false, setScale: false } },
    hooks: {
      setSelect: [
        (u) => {
          const px = u.select.width;
          const a = u.posToVal(u.select.left, 'x');
          const b = u.posToVal(u.select.left + px, 'x');
          u.setSelect({ left: 0, width: 0, top: 0, height: 0 }, false);
          if (!(b > a) || px < 3 || b - a < 1e-4) return;
          move([a, b]);
        },
      ],
    },
  });
  ov.box.classList.add('wl-overview');
  // A click on the overview centres the window there.
  /** @type {number[] | null} */
  let odown = null;
  ov.u.over.addEventListener('pointerdown', (e) => {
    odown = [e.clientX, e.offsetX];
  });
  ov.u.over.addEventListener('pointerup', (e) => {
    const win = shown();
    if (odown && Math.abs(e.clientX - odown[0]) < 4 && win) {
      const c = ov.u.posToVal(e.offsetX, 'x');
      const w = win[1] - win[0];
      move([c - w / 2, c + w / 2]);
    }
    odown = null;
  });
  return ov;
}
