// Unit tests of the sensing panel's pure helpers (www/sensemap.js) and of the body-rate URL
// parameters (www/state.js BODY_RATE, BODY_AXIS). Run: node --test tests/js/sensemap.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  RATE_SLIDER,
  MAP_LO,
  MAP_HI,
  REL_DECADES,
  sliderOfRate,
  rateOfSlider,
  mapScale,
  deltaAt,
  curveData,
  sensorsFor,
  clusterMarkers,
  groupLabel,
  rateError,
  senseFe,
  peakAbs,
  spectrumWindow,
  curveSummary,
  legendWords,
  senseMapOf,
  senseCsvColumns,
} from '../../www/sensemap.js';
import { fmt } from '../../www/format.js';
import {
  BODY_RATE,
  BODY_AXIS,
  bodyRateVector,
  parseQuery,
  toQuery,
  defaults,
  paramsOf,
  PANELS,
  expectation,
} from '../../www/state.js';

test('rate slider: log10 |ω_b| both ways, sign kept, zero at the left end, range kept', () => {
  assert.equal(sliderOfRate(1), 0);
  assert.equal(sliderOfRate(-0.01), -2);
  assert.equal(sliderOfRate(0), RATE_SLIDER.min);
  assert.equal(sliderOfRate(1e6), RATE_SLIDER.max);
  assert.equal(rateOfSlider(0), 1);
  assert.equal(rateOfSlider(-3, -5), -0.001);
  assert.equal(rateOfSlider(Math.log10(0.5)), 0.5);
  assert.equal(rateOfSlider(99), BODY_RATE.max);
  for (let p = RATE_SLIDER.min; p <= RATE_SLIDER.max; p += RATE_SLIDER.step) {
    const r = rateOfSlider(p);
    assert.ok(r >= BODY_RATE.min && r <= BODY_RATE.max);
    assert.ok(Math.abs(sliderOfRate(r) - p) < 0.003, `${p} → ${r} → ${sliderOfRate(r)}`);
  }
});

test('map scale (absolute): fixed log scale, 0 for D ≤ 10^MAP_LO, zero or NaN; scaling D moves the colours', () => {
  const s = mapScale([0, 1e-9, 10 ** MAP_LO, 1, 10 ** MAP_HI, 1e9, NaN], 'absolute');
  assert.equal(s.max, 1e9);
  assert.equal(s.t(0), 0);
  assert.equal(s.t(NaN), 0);
  assert.equal(s.t(1e-9), 0);
  assert.equal(s.t(10 ** MAP_LO), 0);
  assert.equal(s.t(10 ** MAP_HI), 1);
  assert.equal(s.t(1e9), 1);
  assert.ok(Math.abs(s.t(1) - (0 - MAP_LO) / (MAP_HI - MAP_LO)) < 1e-12);
  // four times the rate: D × 16, visibly higher on the scale
  const a = mapScale([1e-3], 'absolute'),
    b = mapScale([16e-3], 'absolute');
  assert.ok(b.t(16e-3) - a.t(1e-3) > 0.1);
  assert.equal(mapScale(new Float64Array(4), 'absolute').max, 0);
});

test('map scale (relative, the default): REL_DECADES below the largest D, unchanged by scaling D', () => {
  const d = [0.12, 0.012, 0.0012, 1e-5, 0];
  const s = mapScale(d);
  assert.equal(s.mode, 'relative');
  assert.equal(s.t(0.12), 1);
  assert.ok(Math.abs(s.t(0.012) - (1 - 1 / REL_DECADES)) < 1e-12);
  assert.equal(s.t(1e-5), 0);
  assert.equal(s.t(0), 0);
  const k = mapScale(d.map((v) => 16 * v));
  for (const v of d) assert.ok(Math.abs(k.t(16 * v) - s.t(v)) < 1e-12);
  const z = mapScale([0, 0]);
  assert.equal(z.max, 0);
  assert.equal(z.t(0), 0);
  assert.equal(z.t(1), 0);
});

test('deltaAt: Σ_k ε_k Δq_k per component, exactly zero for zero Δq', () => {
  const modal = [
    { eps_x: 2, eps_y: -1, gamma_xy: 0.5 },
    { eps_x: 1, eps_y: 3, gamma_xy: -2 },
  ];
  const dq = [Float64Array.of(1, 0, -1), Float64Array.of(0.5, 2, 0)];
  const d = deltaAt(modal, dq);
  assert.deepEqual(Array.from(d.eps_x), [2.5, 2, -2]);
  assert.deepEqual(Array.from(d.eps_y), [0.5, 6, 1]);
  assert.deepEqual(Array.from(d.gamma_xy), [-0.5, -4, -0.5]);
  const z = deltaAt(modal, [new Float64Array(5), new Float64Array(5)]);
  assert.ok([...z.eps_x, ...z.eps_y, ...z.gamma_xy].every((v) => v === 0 && !Object.is(v, -0)));
  assert.equal(deltaAt([], []).eps_x.length, 0);
});

test('curve data and the K for P_d ≥ 0.9', () => {
  const r = { pd: [0.2, 0.7, 0.95], d_prime: [1, 2, 4], d_prime_all: 8 };
  assert.deepEqual(curveData(r), [
    [1, 2, 3],
    [0.2, 0.7, 0.95],
    [0.125, 0.25, 0.5],
  ]);
  assert.deepEqual(curveData({ pd: [0.01], d_prime: [0], d_prime_all: 0 })[2], [null]);
  assert.equal(sensorsFor(r.pd), 3);
  assert.equal(sensorsFor(r.pd, 0.5), 2);
  assert.equal(sensorsFor([0.1, 0.2]), null);
});

test('body rate URL parameters: parsed in range, written only when not the default, vector per axis', () => {
  assert.ok(PANELS.includes('sensing'));
  const d = defaults();
  assert.equal(d.body_rate, BODY_RATE.def);
  assert.equal(d.body_axis, BODY_AXIS.def);
  assert.doesNotMatch(toQuery(d), /body_/);
  const { state, rejected } = parseQuery('?body_rate=-2.5&body_axis=x&panels=controls,sensing');
  assert.deepEqual(rejected, []);
  assert.equal(state.body_rate, -2.5);
  assert.equal(state.body_axis, 'x');
  assert.deepEqual(state.panels, ['controls', 'sensing']);
  assert.deepEqual(bodyRateVector(state), [-2.5, 0, 0]);
  assert.deepEqual(bodyRateVector({ body_rate: 3, body_axis: 'y' }), [0, 3, 0]);
  assert.deepEqual(bodyRateVector({}), [0, 0, BODY_RATE.def]);
  const q = new URLSearchParams(toQuery(state));
  assert.equal(q.get('body_rate'), '-2.5');
  assert.equal(q.get('body_axis'), 'x');
  const again = parseQuery(`?${toQuery(state)}`);
  assert.deepEqual(again.rejected, []);
  assert.deepEqual(paramsOf(again.state), paramsOf(state));
  for (const bad of [
    'body_rate=101',
    'body_rate=-100.5',
    'body_rate=abc',
    'body_rate=1e999',
    'body_axis=w',
    'body_axis=',
  ]) {
    const r = parseQuery(`?${bad}`);
    assert.equal(r.rejected.length, 1, bad);
    assert.equal(r.rejected[0].why, `expected ${expectation(bad.split('=')[0])}`);
  }
  assert.equal(parseQuery('?body_rate=100').state.body_rate, 100);
  assert.equal(parseQuery('?body_rate=0').state.body_rate, 0);
  assert.match(expectation('body_rate'), /\[-100, 100\] rad\/s/);
});

test('markers closer than the radius share a label; every rank appears once', () => {
  const m = [
    { x: 0, y: 0, rank: 1 },
    { x: 5, y: 0, rank: 2 },
    { x: 100, y: 0, rank: 3 },
    { x: 0, y: 9, rank: 4 },
    { x: 103, y: 3, rank: 5 },
  ];
  const g = clusterMarkers(m, 12);
  assert.deepEqual(
    g.map((q) => q.ranks),
    [
      [1, 2, 4],
      [3, 5],
    ],
  );
  assert.deepEqual([g[0].x, g[0].y, g[1].x], [0, 0, 100]);
  assert.deepEqual(
    g.flatMap((q) => q.ranks).sort((a, b) => a - b),
    [1, 2, 3, 4, 5],
  );
  assert.equal(clusterMarkers([], 10).length, 0);
  assert.equal(groupLabel([1, 2, 4]), '1,2,4');
  assert.equal(groupLabel([1, 2, 3, 4, 5, 6]), '1,2,3,4 +2');
  assert.equal(groupLabel([7]), '7');
});

test('rate field: empty, non-numeric and out-of-range text is refused with the range; in-range rates pass', () => {
  for (const t of ['', '  ', 'abc', 'NaN', String(BODY_RATE.max * 2), String(BODY_RATE.min * 2)]) {
    const e = rateError(t);
    assert.ok(e && e.includes(`[${BODY_RATE.min}, ${BODY_RATE.max}]`), `${JSON.stringify(t)} → ${e}`);
  }
  for (const t of ['0', '0.05', '-3', String(BODY_RATE.max), String(BODY_RATE.min)])
    assert.equal(rateError(t), null, t);
});

test('the FE wing for sensing: only with the FE mode set and a live result of that wing’s mode count', () => {
  const fe = { n_modes: 3 };
  const result = (n) => ({ analysis: { sim: { modes: new Array(n).fill({}) } } });
  assert.equal(senseFe({ modes: 'fe', fe, result: result(3) }), fe);
  assert.equal(senseFe({ modes: 'fe', fe, result: result(2) }), null, 'a result of the previous wing');
  assert.equal(senseFe({ modes: 'paper', fe, result: result(3) }), null);
  assert.equal(senseFe({ modes: 'fe', fe: null, result: result(3) }), null);
  assert.equal(senseFe({ modes: 'fe', fe, result: null }), null);
});

test('peak |v| of a series, 0 when empty', () => {
  assert.equal(peakAbs([]), 0);
  assert.equal(peakAbs([1, -3, 2]), 3);
  assert.equal(peakAbs(new Float64Array([-1e-9, 5e-10])), 1e-9);
});

test('spectrum window: bins up to min(Nyquist, 10 f_d), a marker at every multiple of f_d inside it', () => {
  const freq = Array.from({ length: 600 }, (_, i) => i);
  const a = spectrumWindow({ flap_freq_hz: 25, sample_rate_hz: 10000 }, freq);
  assert.equal(a.fmax, 250);
  assert.equal(a.n, 251);
  assert.deepEqual(
    a.marks.map((m) => m.x),
    [25, 50, 75, 100, 125, 150, 175, 200, 225, 250],
  );
  assert.equal(a.marks[2].label, '3f_d');
  const b = spectrumWindow({ flap_freq_hz: 25, sample_rate_hz: 120 }, freq);
  assert.equal(b.fmax, 60);
  assert.equal(b.n, 61);
  assert.deepEqual(
    b.marks.map((m) => m.x),
    [25, 50],
  );
});

test('detection summary: P_d and d′ at K, the K for P_d ≥ 0.9, or why there is nothing to detect', () => {
  const r = {
    pd: [0.2, 0.6, 0.95, 0.99],
    d_prime: [1, 2, 3, 4],
    d_prime_all: 5,
    pd_all: 0.999,
    n_nodes: 10,
    k_for_90_percent: 4,
  };
  const t = curveSummary(r, 2, fmt);
  assert.match(t, /With K = 2 sensors, P_d = 0\.6 \(d′ = 2\)/);
  assert.match(t, /all 30 candidates together/);
  assert.match(t, /P_d ≥ 0\.9 from K = 3\./);
  assert.match(t, /90 % of the all-sensor d′ needs K = 4\./);
  assert.match(curveSummary({ ...r, pd: [0.1, 0.2] }, 1, fmt), /P_d stays below 0\.9 up to K = 2\./);
  assert.match(curveSummary({ ...r, d_prime_all: 0 }, 2, fmt), /nothing to detect/);
});

test('legend words follow the scale: zero map, absolute range, relative range from the largest D', () => {
  assert.deepEqual(legendWords(mapScale([0, 0]), fmt), ['D = 0 everywhere: no rotation, so nothing to detect']);
  const abs = legendWords(mapScale([0.5], 'absolute'), fmt);
  assert.equal(abs.length, 2);
  assert.ok(abs[0].includes(`10^{${MAP_LO}}`) && abs[0].includes(`10^{${MAP_HI}}`) && abs[0].includes('0.5'));
  const rel = legendWords(mapScale([2, 0.5]), fmt);
  assert.ok(
    rel[0].startsWith(`detectability D, log scale from ${fmt(2 / 10 ** REL_DECADES, 3)} (and below) to 2,`),
    rel[0],
  );
});

test('the published map: colour position per node from the scale, the first K sensors labelled by rank', () => {
  const fe = { n_nodes: 3 };
  const result = {
    d_best: [1e-3, 1e-2, 1e-1],
    body_rate: new Float64Array([0, 0, 0.5]),
    sensors: [
      { rank: 1, node: 2, component: 'eps_x', x_mm: 10, y_mm: -2, d: 0.1 },
      { rank: 2, node: 1, component: 'eps_y', x_mm: 5, y_mm: -1, d: 0.01 },
    ],
  };
  const scale = mapScale(result.d_best, 'relative');
  const m = senseMapOf(fe, result, scale, 1, '{"c":1}', 4);
  assert.deepEqual(
    Array.from(m.field),
    result.d_best.map((v) => scale.t(v)),
  );
  assert.equal(m.field[2], 1);
  assert.equal(m.field[0], 0);
  assert.deepEqual(m.body_rate, [0, 0, 0.5]);
  assert.equal(m.sensors.length, 1);
  assert.deepEqual(m.sensors[0], { rank: 1, node: 2, component: 'eps_x', x_mm: 10, y_mm: -2, label: '1' });
  assert.equal(m.mode, 'relative');
  assert.equal(m.cfg_json, '{"c":1}');
  assert.equal(m.show, 4);
  assert.equal(m.fe, fe);
});

test('sensing CSV columns: node position in mm, D per component de-interleaved, first rank per node', () => {
  const fe = { nodes: [0.001, -0.002, 0, 0.003, 0.004, 0] };
  const result = {
    n_nodes: 2,
    d: [1, 2, 3, 4, 5, 6],
    d_best: [3, 6],
    sensors: [
      { node: 1, rank: 1 },
      { node: 1, rank: 3 },
      { node: 0, rank: 2 },
    ],
  };
  const cols = senseCsvColumns(fe, result);
  const by = Object.fromEntries(cols.map((c) => [c.name, Array.from(c.values)]));
  assert.deepEqual(
    cols.map((c) => c.name),
    ['x', 'y', 'D_eps_x', 'D_eps_y', 'D_gamma_xy', 'D_best', 'sensor_rank'],
  );
  assert.deepEqual(by.x, [1, 3]);
  assert.deepEqual(by.y, [-2, 4]);
  assert.deepEqual(by.D_eps_x, [1, 4]);
  assert.deepEqual(by.D_eps_y, [2, 5]);
  assert.deepEqual(by.D_gamma_xy, [3, 6]);
  assert.deepEqual(by.sensor_rank, [2, 1]);
});
