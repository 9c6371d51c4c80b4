// @ts-check
// The sensing panel's controls (views/sensing.js): rotation axis, the rate as a number and on a
// log slider, the number of sensors K, the map's colour scale, the status row with progress and
// Cancel, and the box that offers the FE wing when the paper's modes are chosen. The axis and the
// rate go straight to the store (body_axis, body_rate); K, the scale and Cancel call back.
import { el } from '../dom.js';
import { fmt } from '../format.js';
import { BODY_RATE, BODY_AXIS, BODY_AXIS_LABELS } from '../state.js';
import { RATE_SLIDER, REL_DECADES, sliderOfRate, rateOfSlider, rateError } from '../sensemap.js';

/**
 * @param {import('../lab.js').ViewContext} ctx
 * @param {{ onK: () => void, onScale: () => void, onCancel: () => void }} on
 */
export function sensingControls(ctx, on) {
  const { store, section, uid } = ctx;
  const axis = el('select', { id: `${uid}-sense-axis` });
  for (const a of BODY_AXIS.choices)
    axis.append(el('option', { value: a, text: /** @type {any} */ (BODY_AXIS_LABELS)[a] }));
  const rateNum = el('input', {
    type: 'number',
    id: `${uid}-sense-rate`,
    min: BODY_RATE.min,
    max: BODY_RATE.max,
    step: 'any',
    'aria-describedby': `${uid}-sense-rate-help`,
  });
  const rateRange = el('input', {
    type: 'range',
    id: `${uid}-sense-log`,
    min: RATE_SLIDER.min,
    max: RATE_SLIDER.max,
    step: RATE_SLIDER.step,
    'aria-label': 'Body rotation rate, logarithmic slider (|ω_b| from 0.0001 to 100 rad/s)',
  });
  const kRange = el('input', { type: 'range', id: `${uid}-sense-k`, min: 1, max: 30, step: 1, value: 5 });
  const kOut = el('output', { for: kRange.id, text: '5' });
  const scaleSel = el(
    'select',
    { id: `${uid}-sense-scale` },
    el('option', {
      value: 'relative',
      text: `relative: ${REL_DECADES} decade${REL_DECADES === 1 ? '' : 's'} below this map’s largest D`,
    }),
    el('option', { value: 'absolute', text: `absolute: D from 10⁻⁶ to 10² on every map` }),
  );
  const field = (label, id, ...inputs) =>
    el('span', { class: 'wl-sense-field' }, el('label', { for: id, rich: label }), ...inputs);
  const controls = el(
    'div',
    { class: 'wl-sense-controls' },
    field('rotation axis', axis.id, axis),
    field('ω_b (rad/s)', rateNum.id, rateNum),
    el('span', { class: 'wl-sense-field wl-sense-log' }, rateRange),
    field('sensors K', kRange.id, kRange, kOut),
    field('colour scale', scaleSel.id, scaleSel),
  );
  const rateHelp = el('p', {
    class: 'wl-note',
    id: `${uid}-sense-rate-help`,
    text: `Rate from ${BODY_RATE.min} to ${BODY_RATE.max} rad/s (the sign turns the rotation around); the slider moves |ω_b| on a log scale. Hawkmoths turn at a few rad/s.`,
  });
  const status = el('p', { class: 'wl-sense-status', 'aria-live': 'polite' });
  const prog = el('progress', {
    class: 'wl-progress',
    max: 1,
    value: 0,
    hidden: true,
    'aria-label': 'sensing analysis progress',
  });
  const cancel = el('button', { type: 'button', class: 'wl-cancel', text: 'Cancel', hidden: true });
  const statusRow = el('div', { class: 'wl-study-controls' }, status, prog, cancel);
  const needFe = el('div', { class: 'wl-sense-needfe' });
  const useFe = el('button', { type: 'button', text: 'Use the FE wing' });
  useFe.addEventListener('click', () => ctx.setParams({ modes: 'fe' }));
  needFe.append(
    el('p', {
      rich: 'Sensing needs strain over the whole wing, which only the FE wing has: the paper’s modes (Table 6) give strain at one point P only. Switch the mode set to the FE wing (or your own wing) to see where rotation shows up.',
    }),
    useFe,
  );

  /** The store's axis and rate into the fields (not the number while it is being typed in). */
  function sync() {
    const s = store.get();
    axis.value = s.body_axis;
    const root = /** @type {any} */ (section.getRootNode());
    if (!root || root.activeElement !== rateNum) rateNum.value = String(s.body_rate);
    rateRange.value = String(sliderOfRate(s.body_rate));
    rateRange.setAttribute('aria-valuetext', `${fmt(Math.abs(s.body_rate), 3)} rad/s`);
  }

  axis.addEventListener('change', () => store.set({ body_axis: /** @type {any} */ (axis.value) }));
  rateNum.addEventListener('change', () => {
    const bad = rateError(rateNum.value);
    if (bad) {
      rateNum.setAttribute('aria-invalid', 'true');
      status.textContent = bad;
      return;
    }
    rateNum.removeAttribute('aria-invalid');
    store.set({ body_rate: Number(rateNum.value) });
  });
  rateRange.addEventListener('input', () => {
    const s = store.get();
    store.set({ body_rate: rateOfSlider(Number(rateRange.value), s.body_rate < 0 ? -1 : 1) });
  });
  kRange.addEventListener('input', () => {
    kOut.textContent = kRange.value;
    on.onK();
  });
  scaleSel.addEventListener('change', () => on.onScale());
  cancel.addEventListener('click', () => on.onCancel());

  return {
    controls,
    rateHelp,
    statusRow,
    status,
    prog,
    cancel,
    needFe,
    sync,
    /** The K slider's value. */
    k: () => Number(kRange.value),
    /** The colour scale chosen. */
    scaleMode: () => /** @type {'relative' | 'absolute'} */ (scaleSel.value),
  };
}
