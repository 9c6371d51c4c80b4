// @ts-check
// The 3-D panel's words (pure, no DOM): the playback speed, the time line, the status line, the
// deflection sentence, the note under the options and the screen-reader summary. wing3d/panel.js
// puts them on the page; tests/js/wing3d_fields.test.mjs checks them.
import { fmt } from '../format.js';
import { beatInfo } from '../beat.js';
import { spanOf } from '../scene3d.js';

/** The playback speeds: a speed's value is a slow-motion factor, or a named rule. */
export const SPEEDS = [
  ['beat4', 'one beat in 4 s'],
  ['flap1', 'one flap per second'],
  ['0.002', '1/500 of real time'],
  ['0.005', '1/200 of real time'],
  ['0.01', '1/100 of real time'],
  ['0.02', '1/50 of real time'],
  ['0.05', '1/20 of real time'],
];

/**
 * Simulated seconds per real second for the speed choice `value` and the run `result` (null: none
 * yet, 25 Hz assumed): 'flap1' one flap per second, 'beat4' one beat in 4 s (one flap per second
 * when the run has no beat), else the number itself.
 * @param {string} value
 * @param {any} result LiveResult or null
 */
export function speedFactor(value, result) {
  const fd = result ? result.analysis.sim.flap_freq_hz : 25;
  if (value === 'flap1') return 1 / fd;
  if (value === 'beat4') {
    const b = result ? beatInfo(result.analysis, result.k) : null;
    return b && b.period ? b.period / 4 : 1 / fd;
  }
  return Number(value);
}

/**
 * The line next to the time slider: the instant, the flap frequency as shown and the beat's period
 * as shown, at slow-motion factor `f`.
 * @param {number} t
 * @param {any} result
 * @param {number} f
 */
export function timeLine(t, result, f) {
  const fd = result ? result.analysis.sim.flap_freq_hz : 25;
  const b = result ? beatInfo(result.analysis, result.k) : null;
  return (
    `t = ${t.toFixed(4)} s · flap ${fmt(fd, 3)} Hz shown at ${fmt(fd * f, 3)} Hz` +
    (b && b.period ? ` · one beat every ${fmt(b.period / f, 3)} s` : '')
  );
}

/**
 * The status line of a drawn frame.
 * @param {string} backend 'webgpu' or 'webgl2'
 * @param {number} triangles
 * @param {number[]} ang [α, β, γ] rad
 * @param {boolean} isFe the FE wing mode set (SI) rather than the paper's
 * @param {number} d largest deflection now (m, or paper units)
 * @param {number} ex exaggeration
 */
export function statusLine(backend, triangles, ang, isFe, d, ex) {
  return (
    `${backend === 'webgpu' ? 'WebGPU' : 'WebGL2'} · ${triangles} triangles · ` +
    `α ${ang[0].toFixed(3)}, β ${ang[1].toFixed(3)}, γ ${ang[2].toFixed(3)} rad · ` +
    (isFe
      ? `true largest deflection ${fmt(d * 1e3, 3)} mm, drawn ×${fmt(ex, 3)}`
      : `largest deflection ${fmt(d * 1e3, 3)} (paper q units, not SI), drawn ×${fmt(ex, 3)}`)
  );
}

/**
 * The sentence on the largest deflection over the run ('' before the first run): in mm and as a
 * share of the span for the FE wing, a warning about paper units otherwise (rich text).
 * @param {number | null} runDeflection m
 * @param {boolean} isFe
 * @param {ArrayLike<number>} nodes the FE wing's flat x, y, z
 */
export function deflectionText(runDeflection, isFe, nodes) {
  if (runDeflection == null) return '';
  const span = spanOf(nodes);
  return isFe
    ? `Largest deflection over the whole run: ${fmt(runDeflection * 1e3, 3)} mm (true scale, SI), about ${fmt((100 * runDeflection) / span, 2)} % of the ${fmt(span * 1e3, 3)} mm span.`
    : `Paper mode set: Table 4’s a_k are not SI, so these deflections are in paper units (≈ 10× below SI), not mm; choose the FE wing mode set for millimetres.`;
}

/**
 * The note under the view options: what is drawn (rich text).
 * @param {boolean} isFe
 * @param {string} wingName
 * @param {number} nNodes
 * @param {number} nModes
 */
export function noteText(isFe, wingName, nNodes, nModes) {
  return isFe
    ? `The shell-FE wing (${wingName}; ${nNodes} nodes) with all ${nModes} of its modes driven by the simulated q_k(t): deflection Σ_k φ_k q_k(t); strain per the FE modal strain fields (dimensionless, true scale). Click the wing to choose the strain point (ring).`
    : `Paper mode set: the paper's q_k(t) (Table 4 units, not SI) drawn on the shell-FE wing's first ${nModes} mode shapes, so shapes and timing are right and magnitudes are not physical. Choose the FE wing mode set for SI deflection and strain.`;
}

/**
 * The screen-reader summary of a drawn frame, ending with the legend's words.
 * @param {number} t
 * @param {number[]} ang
 * @param {number} d deflection now
 * @param {boolean} isFe
 * @param {number | null} runDeflection
 * @param {string} legend
 */
export function summaryText(t, ang, d, isFe, runDeflection, legend) {
  return `Wing at t = ${t.toFixed(4)} s: roll α ${ang[0].toFixed(3)}, pitch β ${ang[1].toFixed(3)}, yaw γ ${ang[2].toFixed(3)} rad; deflection now ${fmt(d * 1e3, 3)} ${isFe ? 'mm' : 'paper units'}, largest over the run ${fmt((runDeflection || 0) * 1e3, 3)}. ${legend}`;
}
