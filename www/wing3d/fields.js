// @ts-check
// The 3-D panel's colours that are per-node fields rather than the renderer's own strain
// components: colour 5, the strain panel's whole-run strain map (store `strain_map`), and colour
// 6, the sensing panel's rotation-detectability map (store `sense_map`). Each is uploaded to the
// renderer once per map (WingView.setNodeField) with its colour limit; the colour limit of every
// colour goes to WingView.set_strain_range. Pure parts (which limit, why no map) are tested in
// tests/js/wing3d_fields.test.mjs.
import { errorText } from '../format.js';
import * as S from '../scene3d.js';
import { strainFieldOf, PEAK_DELAY_MS } from '../views/strain-map.js';

/** The colour option that shows the strain panel's whole-run map (the renderer's node field). */
export const FIELD_COLOUR = 5;
/** The colour option that shows the sensing panel's detectability map (drawn as the renderer's node field, mode 5). */
export const SENSE_COLOUR = 6;

/**
 * The limit for WingView.set_strain_range under colour `c`: the strain map's own limit (colour
 * 5), 1 for the detectability map (positions 0…1 on the sensing panel's scale), the run-wide
 * range of components 1–4, or null (the renderer's per-frame range / no colours).
 * @param {number} c
 * @param {Record<number, number> | null} ranges
 * @param {number | null} fieldLimit
 */
export function rangeLimit(c, ranges, fieldLimit) {
  return c === FIELD_COLOUR ? fieldLimit : c === SENSE_COLOUR ? 1 : c > 0 && ranges && ranges[c] > 0 ? ranges[c] : null;
}

/**
 * Why the detectability map `m` cannot be shown on the FE wing `fe` (null: it can).
 * @param {any} fe
 * @param {any} m store `sense_map`
 */
export function senseProblemOf(fe, m) {
  return !fe
    ? 'the FE wing is not ready yet'
    : !m
      ? 'no sensing result yet: open the Sensing panel (FE wing mode set) and wait for its map'
      : m.fe !== fe || m.n_nodes !== fe.n_nodes || m.field.length !== fe.nodes.length / 3
        ? 'the sensing result is for another wing: keep the Sensing panel on screen until it has recomputed'
        : null;
}

/**
 * The node fields of colours 5 and 6 for one panel.
 * @param {{ store: any, engine: any, view: () => any, fe: () => any, colour: () => number, draw: () => void }} o
 */
export function createFields({ store, engine, view, fe, colour, draw }) {
  let fieldKey = '';
  /** @type {string | null} */
  let fieldProblem = null;
  /** @type {ReturnType<typeof setTimeout> | undefined} */
  let fieldTimer;
  /** @type {any} */
  let fieldResult = null;
  let fieldLabel = '';
  /** @type {number | null} the map's colour limit (S.mapLimit, as on the strain panel's map) */
  let fieldLimit = null;
  /** @type {any} the sense_map uploaded last (null: none) */
  let senseUp = null;
  /** @type {string | null} why there is no detectability map to show */
  let senseProblem = null;
  /** the map shown is for other settings (kinematics, modes) than the run drawn */
  let senseStale = false;

  /**
   * Colour 5: the whole-run strain map of the strain panel, uploaded once per run and choice
   * with the limit S.mapLimit, as on the panel's planform map.
   */
  function applyField(force = false) {
    const s = store.get();
    const v = view(),
      w = fe();
    if (!v || !w || !s.result) return;
    const map = s.strain_map || S.DEFAULT_MAP;
    const key = `${map.component}/${map.stat}`;
    if (fieldKey === key && fieldResult === s.result) return;
    // A peak map is slow (see PEAK_DELAY_MS): made once the run stops changing, unless the
    // strain panel already made it; the previous map stays drawn meanwhile.
    if (s.modes === 'fe' && map.stat === 'peak' && !force && !S.cachedStrainMap(w, s.result, map)) {
      clearTimeout(fieldTimer);
      fieldTimer = setTimeout(() => {
        applyField(true);
        draw();
      }, PEAK_DELAY_MS);
      return;
    }
    fieldKey = key;
    fieldResult = s.result;
    const field = s.modes === 'fe' ? S.strainMap(w, s.result, map, strainFieldOf(engine)) : null;
    fieldProblem = field
      ? null
      : s.modes === 'fe'
        ? 'the wing and the run do not match yet'
        : 'the paper mode set has no whole-wing strain (choose the FE wing)';
    try {
      fieldLimit = field ? S.mapLimit(field) : null;
      v.setNodeField(field || new Float64Array(w.nodes.length / 3), fieldLimit);
    } catch (e) {
      fieldProblem = errorText(e);
    }
    fieldLabel = `${S.MAP_LABELS[map.stat]} of ${S.MAP_LABELS[map.component]}`;
  }

  /**
   * Colour 6: the detectability map (per node the position 0…1 on the sensing panel's log-D
   * colour scale), uploaded once per map with the limit 1 (0 → the colour map's grey middle,
   * 1 → its dark red end).
   */
  function applySense() {
    const v = view(),
      w = fe();
    if (!v || !w) return;
    const s = store.get();
    const m0 = s.sense_map || null;
    senseProblem = senseProblemOf(w, m0);
    senseStale = !senseProblem && !!m0 && !!s.result && m0.cfg_json !== JSON.stringify(s.result.cfg);
    const m = senseProblem ? null : m0;
    if (fieldKey === 'sense' && senseUp === m) return;
    fieldKey = 'sense';
    senseUp = m;
    try {
      v.setNodeField(m ? m.field : new Float64Array(w.nodes.length / 3), 1);
    } catch (e) {
      senseProblem = errorText(e);
    }
  }

  return {
    /** Uploads the chosen colour's field when it is 5 or 6, then sets the colour limit. */
    applyRange(/** @type {Record<number, number> | null} */ ranges) {
      const v = view();
      if (!v) return;
      const c = colour();
      if (c === FIELD_COLOUR) applyField();
      if (c === SENSE_COLOUR) applySense();
      v.set_strain_range(rangeLimit(c, ranges, fieldLimit));
    },
    /** Forgets the uploaded field: the next applyRange uploads again. */
    invalidate() {
      fieldKey = '';
    },
    /** The detectability map on the wing now (null: none). */
    get senseUp() {
      return senseUp;
    },
    /** What the legend says about the fields (www/wing3d/legend.js LegendInfo). */
    legendInfo() {
      return { sensing: colour() === SENSE_COLOUR, fieldProblem, fieldLabel, senseUp, senseProblem, senseStale };
    },
    destroy() {
      clearTimeout(fieldTimer);
    },
  };
}
