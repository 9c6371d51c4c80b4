// @ts-check
// Wing panel: your own wing (outline, camber, clamp, material, mesh, number of modes), solved
// in the worker. (First version: the panel's skeleton; the controls follow.)
import { el } from '../dom.js';

export const title = 'Wing';

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  ctx.section.append(el('p', { class: 'wl-note', text: 'Your own wing: the controls follow.' }));
  return { destroy() {} };
}
