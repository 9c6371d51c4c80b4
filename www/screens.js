// @ts-check
// The lab's screens (as in PhET sims): a few focused pages, each a set of panels, instead of one
// long page. This table is the ONE definition of them: www/state.js parses and validates
// `screen=` (URL, attribute, iframe API) against SCREEN_IDS, www/lab.js builds the screen nav and
// shows a screen's panels, and a guided experiment opens the screen of EXPERIMENT_SCREEN. Pure
// module (no DOM, no imports), unit-tested in tests/js/screens.test.mjs.
//
// A panel may sit on several screens (the sliders do); `full` is every panel, the page as it was
// before the screens, for researchers. `panels=` (the author's choice of panels) still works: a
// screen then shows only the chosen panels it holds, and without `screen=` the lab opens the
// first screen that holds every chosen panel (the full page when none does), so a page that
// asked for `panels=controls,numbers,spectrum` shows exactly those three, as before.

/**
 * @typedef {{ id: string, label: string, panels: readonly string[] | null, about: string }} Screen
 * `panels`: the panels of the screen in no particular order (the lab's LAYOUT orders them);
 * null = every panel (the full page). `about`: one line for the nav's description.
 */

/** @type {readonly Screen[]} */
export const SCREENS = Object.freeze(
  [
    {
      id: 'beat',
      label: 'The beat',
      panels: ['wing3d', 'controls', 'time', 'experiments'],
      about: 'the flapping wing in 3-D, the main sliders and the responses with their beat',
    },
    {
      id: 'forces',
      label: 'Forces',
      panels: ['controls', 'kinematics', 'spectrum', 'numbers'],
      about: 'the stroke that drives the wing, the spectra of the force terms and each force’s share of the response',
    },
    {
      id: 'wing',
      label: 'Your wing',
      panels: ['wing', 'modeshape', 'strain'],
      about: 'your own wing outline and material, its mode shapes and the strain',
    },
    {
      id: 'sensing',
      label: 'Sensing',
      panels: ['wing3d', 'sensing', 'neural', 'experiments'],
      about: 'sensing a body rotation with strain sensors on the wing, and as a neuron sees it',
    },
    {
      id: 'research',
      label: 'Research',
      panels: ['studies', 'resonance', 'numbers', 'report', 'experiments'],
      about: 'the paper’s studies (Figs. 6–8), the resonance map and the paper’s claims checked',
    },
    { id: 'full', label: 'Full page', panels: null, about: 'every panel on one long page, as for research' },
  ].map((s) => Object.freeze({ ...s, panels: s.panels ? Object.freeze(s.panels.slice()) : null })),
);

/** Screen ids, in nav order (`screen=` takes one of them). */
export const SCREEN_IDS = Object.freeze(SCREENS.map((s) => s.id));

/** The screen the lab opens when nothing asks for another. */
export const DEFAULT_SCREEN = 'beat';

/**
 * The screen that shows what each guided experiment (www/experiments.js) talks about: the
 * responses plot for most, the study for the yaw sweep (Fig. 6) and the initial-condition map
 * (Fig. 7); an experiment's study's "Go to" button (views/experiments.js) opens the screen
 * of the study's panel (screenOfPanel), which holds the experiment's text too.
 */
export const EXPERIMENT_SCREEN = Object.freeze({
  beat: 'beat',
  'no-yaw': 'beat',
  damping: 'beat',
  yaw: 'research',
  ic: 'research',
  resonance: 'beat',
  instability: 'beat',
  sensing: 'sensing',
  'air-beat': 'beat',
  'air-superharmonic': 'research',
  'neural-sensing': 'sensing',
});

/**
 * A screen by id, or undefined.
 * @param {string} id
 */
export function screen(id) {
  return SCREENS.find((s) => s.id === id);
}

/**
 * The panels a screen holds among `all` (in the order of `all`).
 * @param {string} id
 * @param {readonly string[]} all every panel there is, in order
 * @returns {string[]}
 */
export function screenPanels(id, all) {
  const s = screen(id);
  if (!s) return [];
  const own = s.panels;
  return own ? all.filter((p) => own.includes(p)) : all.slice();
}

/**
 * Which screen to show and its panels, from the wanted screen ('' = not given) and the panels
 * the author chose (`panels=`; every panel by default).
 *   - a wanted screen that holds at least one chosen panel: that screen, its chosen panels;
 *   - else (none wanted, or one holding none of the chosen panels): with every panel chosen,
 *     DEFAULT_SCREEN; with a choice, the first screen that holds all chosen panels (the full
 *     page when no screen does), so exactly the chosen panels are shown;
 *   - `offered`: the screens worth a place in the nav (those holding a chosen panel).
 * @param {string} wanted
 * @param {readonly string[]} chosen
 * @param {readonly string[]} all every panel there is, in order
 * @returns {{ id: string, shown: string[], offered: string[] }}
 */
export function resolveScreen(wanted, chosen, all) {
  const pick = (/** @type {string} */ id) => screenPanels(id, all).filter((p) => chosen.includes(p));
  const offered = SCREEN_IDS.filter((id) => pick(id).length > 0);
  if (wanted && screen(wanted) && pick(wanted).length) return { id: wanted, shown: pick(wanted), offered };
  const everything = all.every((p) => chosen.includes(p));
  if (everything) return { id: DEFAULT_SCREEN, shown: pick(DEFAULT_SCREEN), offered };
  const holder = SCREEN_IDS.find((id) => chosen.every((p) => screenPanels(id, all).includes(p))) || 'full';
  return { id: holder, shown: pick(holder), offered };
}

/**
 * The screen that shows a panel (the first one holding it; the full page for none).
 * @param {string} panel
 * @param {readonly string[]} all
 */
export function screenOfPanel(panel, all) {
  return SCREEN_IDS.find((id) => id !== 'full' && screenPanels(id, all).includes(panel)) || 'full';
}
