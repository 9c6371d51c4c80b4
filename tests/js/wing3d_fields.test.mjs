// The 3-D panel's words (www/wing3d/texts.js) and its per-node colours 5 and 6 (www/wing3d/fields.js):
// the playback speed, the status and deflection lines, which colour limit the renderer gets,
// and when a strain or detectability map is uploaded to a stand-in WingView.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as T from '../../www/wing3d/texts.js';
import * as F from '../../www/wing3d/fields.js';
import * as S from '../../www/scene3d.js';

/** A run at 25 Hz whose mode 0 beats every `period` s (null: no beat). */
const run = (period) => ({
  k: 0,
  analysis: {
    sim: {
      flap_freq_hz: 25,
      modes: [
        {
          freq_hz: 60,
          floquet: { beat_harmonic: 2, effective_freq_hz: 50.5, beat_period_s: period, stable: true, max_modulus: 1 },
        },
      ],
    },
  },
});

test('speeds: one flap per second, one beat in 4 s (a flap per second without a beat), or a fixed factor', () => {
  assert.equal(T.speedFactor('flap1', run(2)), 1 / 25);
  assert.equal(T.speedFactor('beat4', run(2)), 0.5);
  assert.equal(T.speedFactor('beat4', run(null)), 1 / 25);
  assert.equal(T.speedFactor('beat4', null), 1 / 25);
  assert.equal(T.speedFactor('0.005', run(2)), 0.005);
  assert.equal(T.timeLine(0.5125, run(2), 0.5), 't = 0.5125 s · flap 25 Hz shown at 12.5 Hz · one beat every 4 s');
  assert.equal(T.timeLine(0, null, 0.04), 't = 0.0000 s · flap 25 Hz shown at 1 Hz');
});

test('status and deflection lines: mm and share of the span for the FE wing, paper units otherwise', () => {
  assert.equal(
    T.statusLine('webgl2', 3142, [-0.7391, -0.4624, -0.1851], true, 0.01493, 1),
    'WebGL2 · 3142 triangles · α -0.739, β -0.462, γ -0.185 rad · true largest deflection 14.9 mm, drawn ×1',
  );
  assert.match(
    T.statusLine('webgpu', 10, [0, 0, 0], false, 0.5, 10),
    /^WebGPU · .*largest deflection 500 \(paper q units, not SI\), drawn ×10$/,
  );
  const nodes = Float64Array.of(0, 0, 0, 0.049, -0.01, 0);
  assert.equal(
    T.deflectionText(0.0197, true, nodes),
    'Largest deflection over the whole run: 19.7 mm (true scale, SI), about 40 % of the 49 mm span.',
  );
  assert.match(T.deflectionText(0.0197, false, nodes), /^Paper mode set: .*not mm/);
  assert.equal(T.deflectionText(null, true, nodes), '');
  assert.match(T.noteText(true, 'rect', 1653, 6), /\(rect; 1653 nodes\) with all 6 of its modes/);
  assert.match(
    T.summaryText(0.25, [0.1, 0.2, 0.3], 0.002, true, 0.01, 'legend'),
    /^Wing at t = 0\.2500 s: .*deflection now 2 mm, largest over the run 10\. legend$/,
  );
});

test('the colour limit: the map’s own (5), 1 for detectability (6), the run’s range (1–4), else none', () => {
  const ranges = { 1: 1e-4, 2: 0, 3: 2e-4, 4: 3e-4 };
  assert.equal(F.rangeLimit(5, ranges, 0.3), 0.3);
  assert.equal(F.rangeLimit(5, ranges, null), null);
  assert.equal(F.rangeLimit(6, ranges, 0.3), 1);
  assert.equal(F.rangeLimit(3, ranges, 0.3), 2e-4);
  assert.equal(F.rangeLimit(2, ranges, 0.3), null, 'a zero range is the renderer’s own');
  assert.equal(F.rangeLimit(1, null, 0.3), null);
  assert.equal(F.rangeLimit(0, ranges, 0.3), null);
});

/** An FE wing of 4 nodes with one mode, a run of it, and a stand-in WingView that logs uploads. */
function setting(colour) {
  const fe = {
    nodes: new Float64Array(12),
    n_nodes: 4,
    strain_nodes: Float64Array.from({ length: 12 }, (_, j) => (j % 3 === 0 ? j + 1 : 0)),
    shapes: new Float64Array(4),
  };
  const result = { cfg: { a: 1 }, analysis: { sim: { modes: [{ q: { total: Float64Array.of(1, -2, 0.5) } }] } } };
  const sense = {
    fe,
    n_nodes: 4,
    field: Float64Array.of(0, 0.5, 1, 0.25),
    cfg_json: JSON.stringify(result.cfg),
    sensors: [],
  };
  let state = { modes: 'fe', result, sense_map: sense, strain_map: { component: 'eps_x', stat: 'rms' } };
  const store = {
    get: () => state,
    set: (p) => {
      state = { ...state, ...p };
    },
  };
  const uploads = [],
    limits = [];
  const view = {
    setNodeField: (f, lim) => uploads.push([Array.from(f), lim]),
    set_strain_range: (l) => limits.push(l),
  };
  const c = { colour };
  const fields = F.createFields({
    store,
    engine: {},
    view: () => view,
    fe: () => fe,
    colour: () => c.colour,
    draw() {},
  });
  return { fe, result, sense, store, uploads, limits, fields, c };
}

test('colour 6 uploads the detectability map once per map, limit 1; a map for another wing is refused by name', () => {
  const s = setting(6);
  s.fields.applyRange(null);
  s.fields.applyRange(null);
  assert.deepEqual(s.uploads, [[[0, 0.5, 1, 0.25], 1]]);
  assert.deepEqual(s.limits, [1, 1]);
  assert.equal(s.fields.senseUp, s.sense);
  assert.equal(s.fields.legendInfo().senseStale, false);
  s.store.set({ result: { ...s.result, cfg: { a: 2 } } });
  s.fields.applyRange(null);
  assert.equal(s.uploads.length, 1, 'the same map: not uploaded again');
  assert.equal(s.fields.legendInfo().senseStale, true, 'the map is for other settings');
  s.fields.invalidate();
  s.fields.applyRange(null);
  assert.equal(s.uploads.length, 2);
  s.store.set({ sense_map: { ...s.sense, n_nodes: 5 } });
  s.fields.applyRange(null);
  assert.deepEqual(s.uploads[2], [[0, 0, 0, 0], 1]);
  assert.match(s.fields.legendInfo().senseProblem, /for another wing/);
  assert.equal(F.senseProblemOf(null, s.sense), 'the FE wing is not ready yet');
  assert.match(F.senseProblemOf(s.fe, null), /^no sensing result yet/);
  assert.equal(F.senseProblemOf(s.fe, s.sense), null);
});

test('colour 5 uploads the run’s strain map with the strain panel’s limit; the paper mode set has none', () => {
  const s = setting(5);
  s.fields.applyRange(null);
  // ε_x per unit q at nodes 0…3: 1, 4, 7, 10; RMS of q over the run = √((1 + 4 + 0.25)/3)
  const rms = Math.sqrt(5.25 / 3);
  const want = [1, 4, 7, 10].map((e) => e * rms);
  assert.equal(s.uploads.length, 1);
  s.uploads[0][0].forEach((v, i) => {
    assert.ok(Math.abs(v - want[i]) < 1e-12, `node ${i}`);
  });
  assert.equal(s.uploads[0][1], S.mapLimit(Float64Array.from(want)));
  assert.equal(s.limits[0], s.uploads[0][1]);
  assert.equal(s.fields.legendInfo().fieldLabel, 'RMS over the run of ε_x, spanwise strain');
  s.fields.applyRange(null);
  assert.equal(s.uploads.length, 1, 'same run and choice: not uploaded again');
  s.store.set({ modes: 'paper', result: { ...s.result } });
  s.fields.applyRange(null);
  assert.deepEqual(s.uploads[1], [[0, 0, 0, 0], null]);
  assert.match(s.fields.legendInfo().fieldProblem, /paper mode set has no whole-wing strain/);
  s.fields.destroy();
});

test('run ranges: the colour limit and the largest deflection over the run, or over the core’s listed samples', () => {
  const { fe, result } = setting(1);
  fe.shapes = Float64Array.of(0.1, 0.2, 0.3, 0.4);
  // ε_x per unit q at nodes 0…3: 1, 4, 7, 10; q over the run: 1, −2, 0.5
  const all = S.runRanges(fe, result.analysis, 1000);
  assert.equal(all.ranges[1], 20); // max_t |ε_x q| = 2, 8, 14, 20: the 90 % quantile of 4 nodes is the largest
  assert.equal(all.ranges[2], 0);
  assert.equal(all.deflection, 0.8);
  const listed = S.runRanges(fe, { ...result.analysis, extreme_samples: Uint32Array.of(0, 2) }, 1000);
  assert.equal(listed.ranges[1], 10, 'sample 1 (q = −2) not listed, not seen');
  assert.equal(listed.deflection, 0.4);
});
