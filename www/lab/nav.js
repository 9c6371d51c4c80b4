// @ts-check
// The screen nav: a tablist above the panels' grid, one tab per screen of www/screens.js (arrow
// keys, Home and End move between the tabs, Enter or Space opens one), the line that says what
// the screen shown is for, and the grid's tabpanel roles. Shown only when every panel is on
// offer (an author's own `panels=` choice is one page without tabs). Used by www/lab.js.
import { el } from '../dom.js';
import { SCREENS } from '../screens.js';

/**
 * @param {{ id: (s: string) => string, labName: string, open: (screen: string) => void }} opts
 *   `id` makes the element's unique ids; `labName` names the tablist when several labs share a
 *   page; `open(screen)` is called when a tab is chosen.
 */
export function createNav({ id, labName, open }) {
  const list = el('div', {
    class: 'wl-screens',
    role: 'tablist',
    'aria-label': labName ? `Screens — ${labName}` : 'Screens of the lab',
  });
  const about = el('p', { class: 'wl-screen-about', id: id('screen-about') });
  /** @type {Record<string, HTMLButtonElement>} the tabs by screen id */
  const tabs = {};
  for (const sc of SCREENS) {
    const tab = /** @type {HTMLButtonElement} */ (
      el('button', {
        type: 'button',
        role: 'tab',
        class: 'wl-tab',
        id: id(`tab-${sc.id}`),
        'data-screen': sc.id,
        'aria-controls': id('screen'),
        'aria-selected': 'false',
        tabindex: '-1',
        text: sc.label,
        title: sc.about,
      })
    );
    tab.addEventListener('click', () => open(sc.id));
    tabs[sc.id] = tab;
    list.append(tab);
  }
  list.addEventListener('keydown', (e) => {
    const all = Object.values(tabs);
    const at = all.indexOf(/** @type {HTMLButtonElement} */ (e.target));
    if (at < 0) return;
    const to = {
      ArrowRight: at + 1,
      ArrowDown: at + 1,
      ArrowLeft: at - 1,
      ArrowUp: at - 1,
      Home: 0,
      End: all.length - 1,
    }[e.key];
    if (to === undefined) return;
    e.preventDefault();
    const next = all[(to + all.length) % all.length];
    for (const t of all) t.tabIndex = t === next ? 0 : -1;
    next.focus();
  });

  return {
    list,
    about,
    tabs,
    /**
     * Selects the tab of `screen` and says what it is for; with `chosen` false (an author's
     * panel choice) the nav and its line are hidden and the grid is no tabpanel.
     * @param {string} screen
     * @param {boolean} chosen
     * @param {HTMLElement | null} grid
     */
    select(screen, chosen, grid) {
      list.hidden = !chosen;
      about.hidden = !chosen;
      if (grid) {
        if (chosen) {
          grid.setAttribute('role', 'tabpanel');
          grid.setAttribute('aria-describedby', about.id);
        } else {
          grid.removeAttribute('role');
          grid.removeAttribute('aria-describedby');
        }
      }
      for (const sc of SCREENS) {
        const tab = tabs[sc.id];
        const on = sc.id === screen;
        tab.setAttribute('aria-selected', String(on));
        tab.tabIndex = on ? 0 : -1;
        if (on) {
          about.textContent = `${sc.label}: ${sc.about}.`;
          if (grid) {
            if (chosen) grid.setAttribute('aria-labelledby', tab.id);
            else grid.removeAttribute('aria-labelledby');
          }
        }
      }
    },
  };
}
