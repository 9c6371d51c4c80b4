// @ts-check
// The 3-D panel's elements, built once: the box with the canvas and its overlay, the summary and
// status lines, and the controls (play, speed, time, exaggeration, colour, colour bar, which
// scene lines to show, "Fit view", the scene legend, the note and the deflection sentence).
// Handlers come from wing3d/panel.js; nothing here holds state.
import { el } from '../dom.js';
import { SPEEDS } from './texts.js';
import { sceneLegendList } from './legend.js';

export const COLOURS = [
  ['0', 'none (shading only)'],
  ['1', 'ε_x, spanwise strain'],
  ['2', 'ε_y, chordwise strain'],
  ['3', 'γ_xy, shear strain'],
  ['4', '|ε|, strain magnitude'],
  ['5', 'whole-run strain map (strain panel’s choice)'],
  ['6', 'rotation detectability (sensing panel)'],
];

/**
 * The 3-D canvas (a new wing gets a fresh one), described by the summary `summaryId`.
 * @param {string} summaryId
 * @param {boolean} touch
 * @returns {HTMLCanvasElement}
 */
export function makeCanvas(summaryId, touch) {
  return el('canvas', {
    class: 'wl-w3-canvas',
    tabindex: '0',
    role: 'img',
    'aria-label': `3-D view of the flexing wing. ${touch ? 'Drag to orbit, pinch or use the buttons to zoom; tap the wing to choose the strain point.' : 'Drag, or use the arrow keys, to orbit; wheel or + and − to zoom; Space plays or pauses; click the wing to choose the strain point.'}`,
    'aria-describedby': summaryId,
    width: 640,
    height: 480,
  });
}

/**
 * A canvas as makeCanvas's, with a drawing buffer of `w` × `h` device px (640 × 480 when 0) and
 * the CSS height `cssHeight`: a new view is made on it before it replaces the panel's canvas.
 * @param {string} summaryId
 * @param {boolean} touch
 * @param {number} w
 * @param {number} h
 * @param {string} cssHeight
 */
export function sizedCanvas(summaryId, touch, w, h, cssHeight) {
  const c = /** @type {HTMLCanvasElement} */ (makeCanvas(summaryId, touch));
  c.width = w || 640;
  c.height = h || 480;
  c.style.height = cssHeight;
  return c;
}

/**
 * The panel when there is no 3-D view: the reason in the box (and the rest of the lab works),
 * the summary says it, the controls hidden.
 * @param {{ box: HTMLElement, summary: HTMLElement, status: HTMLElement, controls: HTMLElement, options: HTMLElement }} dom
 * @param {string} why
 */
export function showUnavailable(dom, why) {
  const { box, summary, status, controls, options } = dom;
  box.dataset.state = 'unavailable';
  box.replaceChildren(
    el('p', {
      class: 'wl-w3-fallback',
      text: `3-D view unavailable: ${why}. Everything else in the lab works without it.`,
    }),
  );
  summary.textContent = `3-D view unavailable: ${why}.`;
  status.textContent = '';
  controls.hidden = true;
  options.hidden = true;
}

/**
 * The panel's elements. `overlay` goes over the canvas; `on` holds the controls' handlers.
 * @param {string} uid
 * @param {boolean} touch
 * @param {HTMLElement} overlay
 * @param {{ play: () => void, speed: () => void, time: (t: number) => void, exag: () => void, colour: () => void, scene: () => void, fit: () => void }} on
 */
export function buildPanel(uid, touch, overlay, on) {
  const box = el('div', { class: 'wl-wing3d-box', 'data-wing3d': '', 'data-state': 'loading', 'data-loop': 'stopped' });
  // One 3-D view per lab and every lab renders into its own shadow root, so the id is unique
  // in its tree (tests and host scripts reach it as lab.shadowRoot.getElementById('wing3d')).
  box.id = 'wing3d';
  const summaryId = `${uid}-w3-sum`;
  const canvas = makeCanvas(summaryId, touch);
  const stage = el('div', { class: 'wl-w3-stage' }, canvas, overlay);
  box.append(stage);
  const summary = el('p', {
    class: 'wl-sr',
    id: summaryId,
    text: 'The 3-D view of the wing is starting: it shows the wing flapping and bending at the instant chosen with the time slider.',
  });
  const status = el('p', { class: 'wl-w3-status', role: 'status', text: 'Starting the 3-D view…' });
  return { box, summaryId, canvas, stage, summary, status, ...buildControls(uid, on) };
}

/**
 * The controls under the view.
 * @param {string} uid
 * @param {Parameters<typeof buildPanel>[3]} on
 */
function buildControls(uid, on) {
  const playBtn = el('button', {
    type: 'button',
    class: 'wl-w3-play',
    text: 'Play',
    'aria-pressed': 'false',
    onclick: on.play,
  });
  const speed = el('select', { id: `${uid}-w3-speed`, 'aria-label': 'Playback speed' });
  for (const [v, t] of SPEEDS) speed.append(el('option', { value: v, text: t }));
  speed.value = 'beat4';
  speed.addEventListener('change', on.speed);
  const time = el('input', {
    type: 'range',
    id: `${uid}-w3-time`,
    min: 0,
    max: 2,
    step: 0.0001,
    value: 0.505,
    'aria-label': 'Simulated time t, in s',
  });
  time.addEventListener('input', () => on.time(Number(time.value)));
  const timeText = el('span', { class: 'wl-w3-time', 'aria-live': 'off' });
  const exag = el('input', {
    type: 'range',
    id: `${uid}-w3-exag`,
    min: 0,
    max: 3,
    step: 0.05,
    value: 1,
    'aria-label': 'Deflection exaggeration, as a power of ten',
  });
  exag.addEventListener('input', on.exag);
  const exagText = el('span', { class: 'wl-w3-exag' });
  const colour = el('select', { id: `${uid}-w3-colour`, 'aria-label': 'Colour the wing by' });
  for (const [v, t] of COLOURS) colour.append(el('option', { value: v, text: t }));
  colour.value = '3';
  colour.addEventListener('change', on.colour);
  const legend = el('canvas', { class: 'wl-w3-legend', width: 240, height: 14, 'aria-hidden': 'true' });
  const legendText = el('span', { class: 'wl-w3-legend-text' });
  const showAxes = el('input', { type: 'checkbox', id: `${uid}-w3-axes`, checked: true });
  const showBody = el('input', { type: 'checkbox', id: `${uid}-w3-body`, checked: true });
  const showPlane = el('input', { type: 'checkbox', id: `${uid}-w3-plane`, checked: true });
  for (const c of [showAxes, showBody, showPlane]) c.addEventListener('change', on.scene);
  const resetBtn = el('button', {
    type: 'button',
    class: 'wl-small',
    text: 'Fit view',
    title: 'Camera back to the view that fits the whole stroke',
    onclick: on.fit,
  });
  const row = (label, id, ...inputs) =>
    el('div', { class: 'wl-w3-row' }, el('label', { for: id, text: label }), ...inputs);
  const options = el(
    'details',
    { class: 'wl-w3-options', open: true },
    el('summary', { text: 'View options: exaggeration, colour, what the lines are' }),
    el(
      'div',
      { class: 'wl-w3-optrows' },
      row('exaggeration', exag.id, exag, exagText),
      row('colour', colour.id, colour),
      el('div', { class: 'wl-w3-row wl-w3-legendrow' }, legend, legendText),
    ),
    el(
      'div',
      { class: 'wl-w3-row' },
      el('label', { class: 'wl-check' }, showPlane, ' stroke plane'),
      el('label', { class: 'wl-check' }, showBody, ' body axis'),
      el('label', { class: 'wl-check' }, showAxes, ' frames I, J, K and I″, J″, K″'),
      resetBtn,
    ),
    sceneLegendList(),
  );
  const controls = el(
    'div',
    { class: 'wl-w3-controls' },
    el('div', { class: 'wl-w3-row' }, playBtn, el('label', { for: speed.id, text: 'speed' }), speed),
    row('time', time.id, time, timeText),
    options,
  );
  const defl = el('p', { class: 'wl-w3-defl' });
  const note = el('p', { class: 'wl-note' });
  options.append(note);
  return {
    playBtn,
    speed,
    time,
    timeText,
    exag,
    exagText,
    colour,
    legend,
    legendText,
    showAxes,
    showBody,
    showPlane,
    options,
    controls,
    defl,
    note,
  };
}
