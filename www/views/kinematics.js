// @ts-check
// Kinematics panel: measured strokes (CSV) and hand-edited means and harmonics. (First
// version: the panel's skeleton; the controls follow.)
import { el } from '../dom.js';

export const title = 'Kinematics';

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  ctx.section.append(el('p', { class: 'wl-note', text: 'Your own kinematics: the controls follow.' }));
  return { destroy() {} };
}
