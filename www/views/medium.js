// @ts-check
// The medium control of the Parameters panel: vacuum (the paper), helium, air or a custom
// density. One state key owns it, `air_density` (kg/m³, www/state.js NUMERIC, the core's
// parameter table); the choice shown is derived from it, and "custom" opens the density
// slider under "More parameters". A fluid loads the wing point by point, so it needs the FE
// wing's mode shapes: choosing one switches the mode set to the FE wing, and says so.
import { MEDIA } from '../state.js';
import { el } from '../dom.js';
import { fmt } from '../format.js';

/** The medium a density is (a preset's name, or 'custom'). */
export function mediumOf(/** @type {number} */ rho) {
  const m = MEDIA.find((x) => x.density_kg_m3 === rho);
  return m ? m.name : 'custom';
}

const TEXT = {
  vacuum: 'Vacuum (the paper)',
  helium: 'Helium',
  air: 'Air',
};

/**
 * @param {{ store: import('../store.js').Store<any>, id: (s: string) => string,
 *   openMore: () => void }} deps `openMore` unfolds "More parameters" and focuses the density
 */
export function mediumControl({ store, id, openMore }) {
  const select = el('select', { id: id('medium'), 'data-key': 'medium' });
  for (const m of MEDIA) {
    const extra = m.density_kg_m3 > 0 ? `, ${fmt(m.density_kg_m3, 3)} kg/m³` : '';
    select.append(el('option', { value: m.name, text: `${TEXT[m.name] || m.name}${extra}` }));
  }
  select.append(el('option', { value: 'custom', text: 'Custom density…' }));
  const note = el('p', { class: 'wl-note', 'data-note': 'medium', hidden: true });
  select.addEventListener('change', () => {
    const s = store.get();
    if (select.value === 'custom') {
      openMore();
      return;
    }
    const m = MEDIA.find((x) => x.name === select.value);
    if (!m) return;
    /** @type {Record<string, unknown>} */
    const patch = { air_density: m.density_kg_m3 };
    if (m.density_kg_m3 > 0 && s.modes !== 'fe') patch.modes = 'fe';
    store.set(patch);
  });
  const element = el(
    'div',
    { class: 'wl-medium' },
    el(
      'div',
      { class: 'wl-row wl-select' },
      el('label', { for: id('medium'), text: 'Medium', title: 'The fluid around the wing' }),
      select,
    ),
    note,
  );
  /** Shows the state's medium; `switched` when a fluid moved the mode set to the FE wing. */
  const sync = (/** @type {any} */ s) => {
    const rho = Number(s.air_density);
    const name = mediumOf(rho);
    if (select.value !== name) select.value = name;
    note.hidden = !(rho > 0);
    note.textContent =
      rho > 0
        ? `ρ = ${fmt(rho, 3)} kg/m³: quasi-steady drag and added mass on the FE wing (a fluid acts on the mode shapes, which the paper’s table does not have)${s.modes === 'fe' ? '' : ' — choose Mode set: FE wing'}.`
        : '';
  };
  return { element, select, sync };
}
