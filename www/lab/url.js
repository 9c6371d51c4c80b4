// @ts-check
// The element's state and the page's URL: the first state from the attributes and (with
// `sync-url`) the query string; what the URL carries beyond the query (a `planform=` file and
// the `#s=` share fragment), restored once the wasm has loaded; and the writes back (the query
// at most every 250 ms while sliders move, never in the key press's own task; the fragment once
// the state settles). Used by www/lab.js; `initialState` is pure and tested in
// tests/js/lab_url.test.mjs.
import { NUMERIC, ENUMS, WING, parsePairs, parseQuery, toQuery } from '../state.js';
import { shareLink, decodeShare, fragmentValue, checkPoints } from '../share.js';
import { experimentPatch } from '../experiments.js';
import { EXPERIMENT_SCREEN } from '../screens.js';
import { errorText } from '../format.js';

/** @typedef {import('../lab.js').LabState} LabState */
/** @typedef {import('../lab.js').KinState} KinState */

/** Attributes that are not lab parameters. */
export const NOT_PARAMS = [
  'id',
  'class',
  'style',
  'sync-url',
  'embed',
  'layout',
  'hidden',
  'title',
  'lang',
  'dir',
  'slot',
  'part',
  'tabindex',
  'nonce',
  'role',
  'inert',
  'translate',
  'is',
];
/** The keys that decide which wing is wanted. */
export const WING_KEYS = [...WING.map((w) => w.key), 'outline', 'planform', 'wing'];
/** Parameter attributes that apply live when changed after connection (planform= needs a fetch: not live). */
export const LIVE_ATTRS = [
  ...NUMERIC.map((p) => p.key),
  ...ENUMS.map((e) => e.key),
  ...WING.map((w) => w.key),
  'outline',
  'panels',
  'exp',
  'screen',
];

/**
 * The first state of an element: its attributes, then (with sync-url) the query string's
 * accepted values; a guided experiment's parameters (values given with it win); the FE wing
 * when a wing parameter, outline or planform file is given without a mode set; the selected
 * mode within the mode set; the experiment's screen unless one is given.
 * @param {{ attrs: [string, string][], search: string | null }} from `attrs`: the element's
 *   attributes less aria-* and data-*; `search`: the page's query string with sync-url, else null
 * @returns {{ params: import('../state.js').Params, rejected: { key: string, why: string }[] }}
 */
export function initialState({ attrs, search }) {
  const fromAttrs = parsePairs(attrs, NOT_PARAMS);
  const params = fromAttrs.state;
  const rejected = [...fromAttrs.rejected];
  const given = new Set(attrs.map((a) => a[0]));
  if (search != null) {
    const q = parseQuery(search);
    for (const [k] of new URLSearchParams(search)) {
      given.add(k);
      if (k === 'embed') continue;
      if (!q.rejected.some((r) => r.key === k) && k in q.state) params[k] = q.state[k];
    }
    rejected.push(...q.rejected.filter((r) => r.key !== 'embed'));
  }
  const accepted = (/** @type {string} */ k) => !rejected.some((r) => r.key === k);
  // A guided experiment (exp= attribute or URL) brings its parameters, as its chip does; values
  // given with it (and accepted) win.
  if (params.exp) Object.assign(params, experimentPatch(params.exp, [...given].filter(accepted)));
  // A wing parameter, outline or planform file given without a mode set means the FE wing.
  if (!given.has('modes') && WING_KEYS.some((k) => given.has(k) && accepted(k))) params.modes = 'fe';
  // So does a fluid (air_density above 0): air acts on the FE wing's mode shapes.
  if (!given.has('modes') && given.has('air_density') && accepted('air_density') && params.air_density > 0)
    params.modes = 'fe';
  const nModes = params.modes === 'fe' ? params.n_modes : 2;
  if (Number(params.mode) > nModes) {
    rejected.push({
      key: 'mode',
      why: `expected 1 to ${nModes} (the modes of the ${params.modes === 'fe' ? 'FE wing' : 'paper table'})`,
    });
    params.mode = '1';
  }
  // A guided experiment opens the screen that shows what it talks about (screen= wins).
  if (params.exp && !params.screen) params.screen = EXPERIMENT_SCREEN[params.exp] || '';
  return { params, rejected };
}

/**
 * Kinematics from a share fragment: the CSV again (same core function) or the config itself.
 * @param {any} k the fragment's `kin`
 * @param {ReturnType<typeof import('../engine.js').createEngine>} engine
 * @returns {KinState}
 */
export function kinFromShare(k, engine) {
  if (!k || typeof k !== 'object') throw new Error('kin: expected an object');
  const label = String(k.label || 'shared kinematics').slice(0, 80);
  if (k.csv && typeof k.csv.text === 'string') {
    const r = engine.kinematicsFromCsv(k.csv.text, {
      units: k.csv.units,
      flap_hz: k.csv.flap_hz,
      max_harmonic: k.csv.max_harmonic,
    });
    return { kinematics: k.kinematics || r.kinematics, source: 'share', label, samples: r.samples, csv: k.csv };
  }
  if (!k.kinematics || typeof k.kinematics !== 'object')
    throw new Error('kin.kinematics: expected the core’s Kinematics object');
  // Checked by the core on the first computation (applyOverrides validates the config).
  return { kinematics: k.kinematics, source: 'share', label, samples: null, csv: null };
}

/**
 * The URL's side of one element with sync-url.
 * @param {{
 *   store: import('../store.js').Store<LabState>,
 *   engine: ReturnType<typeof import('../engine.js').createEngine>,
 *   notice: (text: string) => void,
 *   params: () => import('../state.js').Params,
 * }} lab
 */
export function createUrlSync({ store, engine, notice, params }) {
  /** @type {ReturnType<typeof setTimeout> | undefined} */
  let fragTimer;
  /** @type {ReturnType<typeof setTimeout> | 0} */
  let urlTimer = 0;
  let urlWritten = -1e9;

  /** A `planform=` file: relative same-origin URL only (state.js checked the text), CSV or JSON. */
  async function fetchPlanform(/** @type {string} */ path) {
    const url = new URL(path, location.href);
    if (url.origin !== location.origin) throw new Error('only same-origin files can be loaded');
    const res = await fetch(url, { credentials: 'same-origin' });
    if (!res.ok) throw new Error(`HTTP ${res.status}`);
    const text = await res.text();
    if (text.length > 1e6) throw new Error('the file is larger than 1 MB');
    return engine.parsePlanform(text, /\.json$/i.test(path) ? 'json' : 'csv');
  }

  /** The `#s=` fragment's outline, kinematics and strain point, as a patch of the state. */
  async function fromFragment(/** @type {string} */ frag) {
    const st = await decodeShare(frag);
    /** @type {Partial<LabState>} */
    const patch = {};
    if (st.outline) {
      const points = checkPoints(st.outline);
      patch.wing = {
        input: null,
        source: 'share',
        label: typeof st.outline_label === 'string' ? st.outline_label.slice(0, 80) : 'shared outline',
        outline: 'shared',
        points,
      };
      patch.planform = '';
    }
    if (st.kin) patch.kin = kinFromShare(st.kin, engine);
    if (st.strain_point)
      patch.strain_point = /** @type {[number, number]} */ (
        checkPoints([st.strain_point, st.strain_point, st.strain_point], 'strain_point')[0]
      );
    return patch;
  }

  async function writeFragment() {
    const s = store.get();
    /** @type {Record<string, unknown>} */
    const st = {};
    if (s.wing && s.wing.points && s.wing.source !== 'url' && s.wing.source !== 'import') {
      st.outline = s.wing.points;
      st.outline_label = s.wing.label;
    }
    if (s.kin) {
      const csv = s.kin.csv && s.kin.csv.text.length <= 20000 ? s.kin.csv : null;
      st.kin = { label: s.kin.label, kinematics: s.kin.kinematics, csv };
    }
    if (s.strain_point) st.strain_point = s.strain_point;
    let hash = '';
    if (Object.keys(st).length) {
      try {
        // The finest rounding that keeps the whole link within 2000 characters; a notice if not.
        hash = (await shareLink(st, location.href.split('#')[0], notice)).hash;
      } catch {
        hash = '';
      }
    }
    if (hash !== location.hash && !(hash === '' && !location.hash)) {
      history.replaceState(null, '', `${location.pathname}${location.search}${hash}`);
    }
  }

  return {
    /**
     * Restores what the URL carries beyond the query: a `planform=` file (same origin,
     * relative) and the `#s=` fragment (outline, kinematics, strain point). Each failure is a
     * notice; the lab then goes on with the defaults for that part.
     */
    async restore() {
      const notes = [];
      const s = store.get();
      if (s.planform) {
        try {
          const points = await fetchPlanform(s.planform);
          store.set({ wing: { input: null, source: 'url', label: s.planform, outline: 'file', points } });
        } catch (e) {
          notes.push(
            `The planform file “${s.planform}” could not be used (${errorText(e)}); using the built-in outline.`,
          );
          store.set({ planform: '' });
        }
      }
      const frag = fragmentValue(location.hash);
      if (frag) {
        try {
          store.set(await fromFragment(frag));
        } catch (e) {
          notes.push(
            `The shared wing/kinematics in the link (#s=…) could not be restored: ${errorText(e)}. The lab uses its defaults for them.`,
          );
        }
      }
      if (notes.length) notice(notes.join(' '));
    },
    /** Writes the `#s=` fragment (own outline, kinematics, strain point) after the state settles. */
    scheduleFragment() {
      clearTimeout(fragTimer);
      fragTimer = setTimeout(writeFragment, 300);
    },
    /** Query-string writes: at most one per 250 ms while sliders move (Chromium throttles more). */
    scheduleQuery() {
      const write = () => {
        urlTimer = 0;
        urlWritten = performance.now();
        /** @type {Record<string, string>} */
        const extra = new URLSearchParams(location.search).get('embed') === '1' ? { embed: '1' } : {};
        history.replaceState(null, '', `${location.pathname}?${toQuery(params(), extra)}${location.hash}`);
      };
      if (urlTimer) return;
      const since = performance.now() - urlWritten;
      // Never in the key press's own task: history.replaceState costs ~10 ms in Chromium, which
      // would delay the paint of the slider's new value.
      urlTimer = setTimeout(write, Math.max(20, 250 - since));
    },
  };
}
