// @ts-check
// Mode-shape viewer: one mode of the FE wing animated alone (φ_k · sin ωt), with its natural
// frequency f_k, kind (bending / torsion …) and modal participation a_k. (First version: the
// panel's skeleton; the drawing follows.)
import { el } from '../dom.js';

export const title = 'Mode shapes';

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { section } = ctx;
  const status = el('p', { class: 'wl-note', role: 'status', text: 'The mode shapes appear once the FE wing is computed.' });
  section.append(status);
  return { destroy() {} };
}
