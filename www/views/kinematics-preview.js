// @ts-check
// The Kinematics panel's preview (views/kinematics.js): one flap period of the kinematics in use
// as an SVG, the core's periodic interpolant (wasm anglesAt) as lines and a measured table's
// samples as dots, with its legend and its words (www/kinform.js).
import { el } from '../dom.js';
import { fmt, errorText } from '../format.js';
import { ANGLES, SYM, previewBounds, previewWords } from '../kinform.js';

const COL = { alpha: '#1f6aa5', beta: '#b34700', gamma: '#1e7a1e' };
/** Points of the interpolant drawn per period. */
const PREVIEW_POINTS = 241;
const NS = 'http://www.w3.org/2000/svg';

/**
 * The preview's elements (`svg`, `legend`, `desc`) and `draw(s)`, which redraws it for the
 * store's state `s` (the custom kinematics, else the sliders').
 * @param {import('../lab.js').ViewContext} ctx
 */
export function kinematicsPreview(ctx) {
  const { engine, id } = ctx;
  const svg = document.createElementNS(NS, 'svg');
  svg.setAttribute('class', 'wl-kin-svg');
  svg.setAttribute('role', 'img');
  svg.setAttribute('aria-labelledby', id('kin-desc'));
  svg.setAttribute('viewBox', '0 0 400 160');
  svg.setAttribute('preserveAspectRatio', 'none');
  const desc = el('p', { class: 'wl-note', id: id('kin-desc'), 'data-kin': 'summary' });
  const legend = el(
    'p',
    { class: 'wl-kin-legend', 'aria-hidden': 'true' },
    ...ANGLES.map((a) => el('span', { style: `color:${COL[a]}`, text: `— ${SYM[a]}  ` })),
    el('span', { class: 'wl-kin-dots', text: '● measured samples', hidden: true }),
  );
  const draw = (s) => {
    svg.replaceChildren();
    if (!engine.ready) return;
    let kinematics;
    try {
      kinematics = s.kin ? s.kin.kinematics : engine.config(s).kinematics;
    } catch {
      return;
    }
    if (!kinematics) return;
    const T = 1 / kinematics.flap_freq_hz;
    const t = Float64Array.from({ length: PREVIEW_POINTS }, (_, i) => (i * T) / (PREVIEW_POINTS - 1));
    let ang;
    try {
      ang = engine.anglesAt({ ...engine.baseConfig, kinematics }, t);
    } catch (e) {
      desc.textContent = `No preview: ${errorText(e)}`;
      return;
    }
    const samp = s.kin && s.kin.samples;
    /** @type {HTMLElement} */ (legend.querySelector('.wl-kin-dots')).hidden = !samp;
    const bounds = previewBounds(ang, samp);
    const { lo, hi } = bounds;
    const X = (tt) => (400 * tt) / T,
      Y = (v) => 160 - (160 * (v - lo)) / (hi - lo);
    const zero = document.createElementNS(NS, 'line');
    zero.setAttribute('x1', '0');
    zero.setAttribute('x2', '400');
    zero.setAttribute('y1', String(Y(0)));
    zero.setAttribute('y2', String(Y(0)));
    zero.setAttribute('class', 'wl-kin-zero');
    svg.append(zero);
    for (const a of ANGLES) {
      const pl = document.createElementNS(NS, 'polyline');
      pl.setAttribute('points', Array.from(t, (tt, i) => `${X(tt).toFixed(2)},${Y(ang[a][i]).toFixed(2)}`).join(' '));
      pl.setAttribute('fill', 'none');
      pl.setAttribute('stroke', COL[a]);
      pl.setAttribute('stroke-width', '1.6');
      pl.setAttribute('vector-effect', 'non-scaling-stroke');
      svg.append(pl);
      if (samp) {
        const g = document.createElementNS(NS, 'g');
        g.setAttribute('fill', COL[a]);
        const n = samp.t.length;
        const stride = Math.max(1, Math.ceil(n / 400));
        for (let i = 0; i < n; i += stride) {
          const c = document.createElementNS(NS, 'circle');
          const tt = ((samp.t[i] % T) + T) % T;
          c.setAttribute('cx', X(tt).toFixed(2));
          c.setAttribute('cy', Y(samp[a][i]).toFixed(2));
          c.setAttribute('r', '1.8');
          g.append(c);
        }
        svg.append(g);
      }
    }
    desc.textContent = previewWords(kinematics.flap_freq_hz, ang, !!samp, bounds, fmt);
  };
  return { svg, legend, desc, draw };
}
