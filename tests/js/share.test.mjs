// The share fragment (www/share.js): deflate-raw + base64url, the compact v2 packing (outline as
// delta-coded 0.1 µm integers, sampled angles as the core's Fourier series), reading v1 links,
// the 2000-character link budget and the reasons given when a fragment cannot be restored.
// Run: node --test tests/js/share.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  encodeShare,
  decodeShare,
  fragmentValue,
  checkPoints,
  shareLink,
  packOutline,
  unpackOutline,
  SHARE_VERSION,
  MAX_LINK,
  MAX_FRAGMENT,
} from '../../www/share.js';
import { sampledSeries, DEFAULT_SAMPLED_MAX_HARMONIC } from '../../www/fourier.js';
import { defaults, toQuery } from '../../www/state.js';
import { prng } from './prng.mjs';

/** Deterministic pseudo-random numbers in [0, 1) (tests/js/prng.mjs). */
const rng = (seed = 7) => prng(seed);
const sig6 = (/** @type {number} */ v) => Number(v.toPrecision(6));

// The default planform's outline (wasm planforms(), id manduca: 39 points at 4 decimals).
const MANDUCA_39 = [
  [0, -4],
  [0.3341, -5.1203],
  [1.3275, -8.1783],
  [2.9529, -12.3924],
  [5.1661, -16.8053],
  [7.9066, -20.5984],
  [11.0998, -23.275],
  [14.6585, -24.6783],
  [18.4856, -24.8982],
  [22.4768, -24.1476],
  [26.5232, -22.6655],
  [30.5144, -20.5984],
  [34.3415, -18.1653],
  [37.9002, -15.5017],
  [41.0934, -12.716],
  [43.8339, -9.9163],
  [46.0471, -7.2088],
  [47.6725, -4.7014],
  [48.6659, -2.5024],
  [49, -0.7209],
  [48.6659, 0.5519],
  [47.6725, 1.4136],
  [46.0471, 1.9311],
  [43.8339, 2.1793],
  [41.0934, 2.2386],
  [37.9002, 2.1946],
  [34.3415, 2.1248],
  [30.5144, 2.0736],
  [26.5232, 2.0259],
  [22.4768, 1.9545],
  [18.4856, 1.8431],
  [14.6585, 1.688],
  [11.0998, 1.4881],
  [7.9066, 1.2441],
  [5.1661, 0.9585],
  [2.9529, 0.6348],
  [1.3275, 0.2778],
  [0.3341, -0.1138],
  [0, -0.3],
];

/** The outline after dragging: every point moved by a pointer (full-precision floats). */
function draggedOutline(r = rng(3)) {
  return MANDUCA_39.map(([x, y]) => /** @type {[number, number]} */ ([x + (r() - 0.5) * 3, y + (r() - 0.5) * 3]));
}

/** A measured-looking one-period table: N samples × 3 angles at 6 significant digits, with noise. */
function measuredKin(n = 200, noise = 0.02, r = rng(11)) {
  const ang = (/** @type {number} */ a, /** @type {number} */ ph) =>
    Array.from({ length: n }, (_, i) =>
      sig6(a * Math.sin((2 * Math.PI * i) / n + ph) + 0.1 * Math.sin((6 * Math.PI * i) / n) + noise * (r() - 0.5)),
    );
  return {
    flap_freq_hz: 25,
    alpha: { kind: 'sampled', values: ang(0.8, 0), max_harmonic: null },
    beta: { kind: 'sampled', values: ang(0.5, 1), max_harmonic: null },
    gamma: { kind: 'sampled', values: ang(0.2, 2), max_harmonic: null },
  };
}

/** The longest query the lab writes for the sliders (every wing parameter changed too). */
function longQuery() {
  const s = /** @type {any} */ (defaults());
  Object.assign(s, {
    alpha0: 0.75,
    beta0: 0.45,
    gamma0: 0.185,
    flap_hz: 27.5,
    zeta: 0.025,
    alpha_phase: -1.57,
    beta_phase: 1.57,
    gamma_phase: 3.14,
    duration: 4.5,
    modes: 'fe',
    mode: '2',
    detrend: 'linear',
  });
  Object.assign(s, {
    camber: 0.11,
    clamp: 1.5,
    e_pa: 1.2e10,
    rho: 950,
    nu: 0.35,
    thickness_um: 75.5,
    mesh_mm: 0.75,
    n_modes: 4,
    panels: ['controls', 'numbers', 'time', 'spectrum', 'wing', 'kinematics'],
  });
  return toQuery(s);
}
const BASE = `https://course.example.org/biomechanics/week-5/wingbeat/index.html?${longQuery()}`;

test('round trip of an outline and a kinematics table (v2, written now)', async () => {
  assert.equal(SHARE_VERSION, 2);
  const outline = Array.from({ length: 200 }, (_, i) => [Math.cos(i / 30) * 20 + 20, Math.sin(i / 30) * 5 - 5]);
  const kin = { label: 'k', kinematics: measuredKin(64, 0), csv: null };
  const s = await encodeShare({ outline, kin, strain_point: [21.25, -3.5], outline_label: 'mine' });
  assert.match(s, /^[A-Za-z0-9_-]+$/);
  assert.ok(s.length < JSON.stringify({ outline, kin }).length / 4, 'compact');
  const back = await decodeShare(s);
  assert.equal(back.v, 2);
  assert.equal(back.outline_label, 'mine');
  assert.deepEqual(back.strain_point, [21.25, -3.5]);
  assert.equal(back.outline.length, 200);
  for (let i = 0; i < 200; i++)
    for (const c of [0, 1])
      assert.ok(Math.abs(back.outline[i][c] - outline[i][c]) <= 0.5e-4 + 1e-12, 'outline rounded to 0.1 µm');
  assert.equal(back.kin.label, 'k');
  assert.equal(back.kin.kinematics.flap_freq_hz, 25);
});

test('outline points with at most 4 decimals (the built-in outlines, typed values) are exact', async () => {
  const back = await decodeShare(await encodeShare({ outline: MANDUCA_39 }));
  assert.deepEqual(back.outline, MANDUCA_39);
  assert.deepEqual(unpackOutline(packOutline(/** @type {any} */ (MANDUCA_39))), MANDUCA_39);
  // A value too large for exact integers is stored as it is.
  const huge = [
    [0, 0],
    [1e200, 0],
    [0, 1],
  ];
  assert.deepEqual((await decodeShare(await encodeShare({ outline: huge }))).outline, huge);
});

test('a sampled angle comes back as the same Fourier series the core makes of it (to the rounding)', async () => {
  const k = measuredKin(200, 0.02);
  k.beta.max_harmonic = /** @type {any} */ (12);
  for (const e of [6, 5, 4]) {
    const back = await decodeShare(
      await encodeShare({ kin: { label: 'm', kinematics: k, csv: null } }, { angleDecimals: e }),
    );
    for (const a of /** @type {const} */ (['alpha', 'beta', 'gamma'])) {
      const ang = back.kin.kinematics[a];
      assert.equal(ang.kind, 'sampled');
      assert.equal(ang.values.length, 200, 'same number of samples');
      const want = sampledSeries(k[a].values, k[a].max_harmonic);
      assert.equal(ang.max_harmonic, (want.length - 1) / 2);
      assert.equal(ang.max_harmonic, a === 'beta' ? 12 : DEFAULT_SAMPLED_MAX_HARMONIC);
      const got = sampledSeries(ang.values, ang.max_harmonic);
      assert.equal(got.length, want.length);
      const worst = Math.max(...got.map((v, i) => Math.abs(v - want[i])));
      assert.ok(worst <= 0.5 * 10 ** -e + 1e-12, `${a} at 1e-${e} rad: worst coefficient error ${worst}`);
    }
  }
  // Fourier angles and the flap frequency are exact.
  const f = {
    flap_freq_hz: 27.123456789,
    alpha: {
      kind: 'fourier',
      mean: 0.0123456789,
      harmonics: [
        { n: 1, amplitude: 0.812345678901, phase: 0.1 },
        { n: 3, amplitude: 0.05, phase: -1.234567 },
      ],
    },
    beta: { kind: 'fourier', harmonics: [] },
    gamma: { kind: 'fourier', mean: 0 },
  };
  const back = await decodeShare(await encodeShare({ kin: { label: 'f', kinematics: f, csv: null } }));
  assert.deepEqual(back.kin.kinematics, f);
});

test('a v1 link written by the earlier lab still decodes to its state', async () => {
  // Written by www/share.js v1 (encodeShare before the v2 packing), saved here unchanged.
  const V1 =
    'fZFdasQwDISvUuZZMba7KcV36AmMCdpE25h1nDQ_S-mSuxe37FJK6YsQjPTNIF1xgTOEcVtTzALnvabqEMgbrWqqjFW2DuQPmiqjS1MrY2uqbCBvNRlVh3BfbxIfJcFBurhK9_DCudtarlI8CwjnmOGuuA0Nwss2S6fa5fKtysBrbJcydEo8NadZ3pr-A87WBE5Tz0U6x9zBYeFhStKBcOG0yQLntTJUYmv1TFo9UqWVLeUpEAZ-b3qehzHHFi5vKe2Eo6w_kadxm6PMoJItw2nCbaXgr8hfxyrGcd06gStumHpeBM4ou4ed8MrD8C9VafMH2P4C2ztY72HfCeVMt-DLOnPMzTTGvMJ5a8uznsP-CQ';
  const st = await decodeShare(V1);
  assert.deepEqual(st, {
    v: 1,
    outline: [
      [0, -4],
      [10.5, -12.25],
      [40, -10],
      [45.125, -2],
      [20, 1.5],
    ],
    outline_label: 'edited Manduca-like',
    kin: {
      label: 'measured.csv',
      kinematics: {
        flap_freq_hz: 25,
        alpha: { kind: 'sampled', values: [0.1, 0.5, 0.8, 0.3, -0.2, -0.6], max_harmonic: null },
        beta: { kind: 'fourier', mean: 0, harmonics: [{ n: 1, amplitude: 0.5, phase: 1.2 }] },
        gamma: { kind: 'fourier', mean: 0.01, harmonics: [{ n: 2, amplitude: 0.2, phase: 0 }] },
      },
      csv: null,
    },
    strain_point: [22.5, -8],
  });
  assert.deepEqual(checkPoints(st.outline), st.outline);
});

test('the default-size state makes a link of at most 2000 characters (measured)', async (t) => {
  const state = {
    outline: draggedOutline(),
    outline_label: 'edited Manduca-like (synthetic, default)',
    kin: { label: 'high-speed-video-run-03.csv', kinematics: measuredKin(200, 0.02), csv: null },
    strain_point: [24.123456789, -10.987654321],
  };
  const r = await shareLink(state, BASE);
  t.diagnostic(
    `base ${BASE.length} chars; fragment ${r.hash.length}; link ${r.length}; angles at 1e-${r.angleDecimals} rad`,
  );
  assert.equal(r.message, '');
  assert.ok(r.length <= MAX_LINK, `link ${r.length} > ${MAX_LINK}`);
  assert.equal(r.length, BASE.length + r.hash.length);
  const back = await decodeShare(/** @type {string} */ (fragmentValue(r.hash)));
  assert.equal(back.outline.length, 39);
  assert.deepEqual(back.strain_point, state.strain_point);
  // Noise-free 6-digit tables and the outline alone fit at the finest rounding.
  const smooth = await shareLink({ ...state, kin: { label: 's', kinematics: measuredKin(200, 0), csv: null } }, BASE);
  t.diagnostic(`noise-free table: link ${smooth.length}, angles at 1e-${smooth.angleDecimals} rad`);
  assert.equal(smooth.angleDecimals, 6);
  const only = await shareLink({ outline: draggedOutline() }, BASE);
  t.diagnostic(`dragged 39-point outline only: link ${only.length}`);
  assert.ok(only.hash.length <= 450);
  // Noisier tables fall back to coarser rounding, then say so.
  const noisy = await shareLink({ ...state, kin: { label: 'n', kinematics: measuredKin(200, 0.1), csv: null } }, BASE);
  t.diagnostic(
    `noise 0.1 rad: link ${noisy.length}, angles at 1e-${noisy.angleDecimals} rad, message ${noisy.message ? 'yes' : 'no'}`,
  );
  assert.ok(noisy.length <= MAX_LINK || noisy.message);
});

test('the CSV goes in only while the link stays short, never cut', async () => {
  const csv = { text: 't,alpha,beta,gamma\n0,1,2,3\n0.01,2,3,4\n0.02,3,4,5\n', units: 'deg', flap_hz: 25 };
  const kin = { label: 'small.csv', kinematics: measuredKin(48, 0), csv };
  const r = await shareLink({ kin }, BASE);
  assert.equal(r.csv, true);
  assert.deepEqual((await decodeShare(/** @type {string} */ (fragmentValue(r.hash)))).kin.csv, csv);
  const big = {
    ...csv,
    text: Array.from(
      { length: 400 },
      (_, i) => `${i / 1000},${sig6(Math.sin(i) * 40)},${sig6(Math.cos(i) * 20)},${sig6(Math.sin(2 * i))}`,
    ).join('\n'),
  };
  const r2 = await shareLink({ kin: { ...kin, csv: big } }, BASE);
  assert.equal(r2.csv, false);
  assert.ok(r2.length <= MAX_LINK);
  assert.equal((await decodeShare(/** @type {string} */ (fragmentValue(r2.hash)))).kin.csv, null);
});

test('a link over the limit is written whole with a plain message; a huge one is refused with a reason', async () => {
  const r = rng(5);
  const outline = Array.from({ length: 2000 }, () => [r() * 50, r() * 30 - 25]);
  /** @type {string[]} */
  const told = [];
  const long = await shareLink({ outline }, BASE, (m) => told.push(m));
  assert.deepEqual(told, [long.message]);
  assert.ok(long.length > MAX_LINK);
  assert.match(
    long.message,
    /This link is \d+ characters long \(it carries an outline of 2000 points\); links over 2000 characters may be cut short/,
  );
  const back = await decodeShare(/** @type {string} */ (fragmentValue(long.hash)));
  assert.equal(back.outline.length, 2000, 'not truncated');
  const junk = Array.from({ length: 240000 }, () => String.fromCharCode(33 + Math.floor(r() * 90))).join('');
  const huge = await shareLink({ kin: { label: 'x', kinematics: measuredKin(10, 0), csv: null }, note: junk }, BASE);
  assert.equal(huge.hash, '');
  assert.match(huge.message, new RegExp(`cannot carry .*at most ${MAX_FRAGMENT}`));
  assert.deepEqual(await shareLink({}, BASE), {
    hash: '',
    length: BASE.length,
    angleDecimals: null,
    csv: false,
    message: '',
  });
});

test('a damaged, foreign or future fragment is refused with a reason', async () => {
  const good = await encodeShare({ a: 1 });
  assert.equal((await decodeShare(good)).a, 1);
  await assert.rejects(decodeShare(good.slice(0, good.length - 4)), /compressed state|JSON/);
  await assert.rejects(decodeShare('not base64!'), /base64url/);
  await assert.rejects(decodeShare('AAAA'), /compressed state|JSON/);
  /** @param {unknown} obj */
  const raw = async (obj) => {
    const cs = new Blob([JSON.stringify(obj)]).stream().pipeThrough(new CompressionStream('deflate-raw'));
    return Buffer.from(new Uint8Array(await new Response(cs).arrayBuffer())).toString('base64url');
  };
  await assert.rejects(decodeShare(await raw({ v: 3 })), /version 3; this lab reads versions 1 and 2/);
  await assert.rejects(decodeShare(await raw({ v: 2, o: { u: 4, d: [1, 2, 3] } })), /o\.d/);
  await assert.rejects(decodeShare(await raw({ v: 2, k: { f: 25, a: { s: [10, 9, 5], c: [0] } } })), /k\.a\.s/);
  await assert.rejects(
    decodeShare(await raw({ v: 2, k: { f: 25, a: { s: [10, 2, 5], c: [0, 1] } } })),
    /k\.a\.c: expected 5 integers/,
  );
  await assert.rejects(decodeShare(await raw({ v: 2, k: { a: 1 } })), /k\.f/);
  await assert.rejects(encodeShare({ o: 1 }), /reserved/);
});

test('fragmentValue and checkPoints', () => {
  assert.equal(fragmentValue('#s=abc-_'), 'abc-_');
  assert.equal(fragmentValue('#x=abc'), null);
  assert.equal(fragmentValue(''), null);
  assert.deepEqual(
    checkPoints([
      [0, 0],
      [1, 0],
      [1, 1],
    ]),
    [
      [0, 0],
      [1, 0],
      [1, 1],
    ],
  );
  assert.throws(
    () =>
      checkPoints([
        [0, 0],
        [1, 0],
      ]),
    /outline: expected 3/,
  );
  assert.throws(
    () =>
      checkPoints([
        [0, 0],
        [1, 0],
        [1, 'x'],
      ]),
    /outline\[2\]/,
  );
});
