// The element's first state (www/lab/url.js initialState) from its attributes and, with
// sync-url, the page's query string — which values win, what is rejected and why, the FE wing
// implied by a wing parameter, the selected mode kept within the mode set, a guided experiment's
// parameters and screen — and kinematics restored from a share fragment (kinFromShare).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { initialState, kinFromShare } from '../../www/lab/url.js';
import { defaults } from '../../www/state.js';

test('attributes set parameters; an invalid one is rejected with its key and the default kept', () => {
  const { params, rejected } = initialState({
    attrs: [
      ['gamma0', '0.1'],
      ['flap_hz', '9999'],
      ['class', 'x'],
      ['sync-url', ''],
    ],
    search: null,
  });
  assert.equal(params.gamma0, 0.1);
  assert.equal(params.flap_hz, defaults().flap_hz);
  assert.deepEqual(
    rejected.map((r) => r.key),
    ['flap_hz'],
  );
  assert.match(rejected[0].why, /\d/, 'the reason names the range');
});

test('with sync-url the query string wins over attributes; embed is not a parameter; without it the query is ignored', () => {
  const attrs = [
    ['gamma0', '0.1'],
    ['zeta', '0.01'],
  ];
  const s = initialState({ attrs, search: '?gamma0=0.2&embed=1&alpha0=nope' });
  assert.equal(s.params.gamma0, 0.2);
  assert.equal(s.params.zeta, 0.01);
  assert.equal(s.params.alpha0, defaults().alpha0);
  assert.deepEqual(
    s.rejected.map((r) => r.key),
    ['alpha0'],
  );
  const t = initialState({ attrs, search: null });
  assert.equal(t.params.gamma0, 0.1);
  assert.deepEqual(t.rejected, []);
});

test('a wing parameter or outline without a mode set means the FE wing; a given mode set is kept', () => {
  assert.equal(initialState({ attrs: [['camber', '0.05']], search: null }).params.modes, 'fe');
  assert.equal(initialState({ attrs: [], search: '?outline=broad' }).params.modes, 'fe');
  assert.equal(
    initialState({
      attrs: [
        ['camber', '0.05'],
        ['modes', 'paper'],
      ],
      search: null,
    }).params.modes,
    'paper',
  );
  // A rejected wing parameter does not switch the mode set.
  assert.equal(initialState({ attrs: [['camber', 'x']], search: null }).params.modes, 'paper');
});

test('the selected mode stays within the mode set (2 paper modes, n_modes FE modes)', () => {
  const paper = initialState({ attrs: [['mode', '3']], search: null });
  assert.equal(paper.params.mode, '1');
  assert.deepEqual(
    paper.rejected.map((r) => r.key),
    ['mode'],
  );
  assert.match(paper.rejected[0].why, /1 to 2 .*paper table/);
  const fe = initialState({
    attrs: [
      ['mode', '3'],
      ['modes', 'fe'],
      ['n_modes', '4'],
    ],
    search: null,
  });
  assert.equal(fe.params.mode, '3');
  assert.deepEqual(fe.rejected, []);
});

test('a guided experiment brings its parameters (values given with it win) and opens its screen unless one is given', () => {
  const a = initialState({ attrs: [['exp', 'damping']], search: null });
  assert.equal(a.params.zeta, 0.01);
  assert.equal(a.params.duration, 10);
  assert.equal(a.params.screen, 'beat');
  const b = initialState({
    attrs: [
      ['exp', 'damping'],
      ['zeta', '0.05'],
      ['screen', 'research'],
    ],
    search: null,
  });
  assert.equal(b.params.zeta, 0.05, 'the given value wins');
  assert.equal(b.params.screen, 'research');
  const c = initialState({ attrs: [['exp', 'yaw']], search: null });
  assert.equal(c.params.screen, 'research');
});

test('kinematics from a share fragment: the CSV read again by the core, or the config itself; bad input throws naming it', () => {
  const calls = [];
  const engine = /** @type {any} */ ({
    kinematicsFromCsv: (text, opts) => {
      calls.push([text, opts]);
      return { kinematics: { from: 'csv' }, samples: { t: [0] } };
    },
  });
  const csv = { text: 't,alpha\n0,1', units: 'deg', flap_hz: 25 };
  const k = kinFromShare({ label: 'x'.repeat(100), csv }, engine);
  assert.deepEqual(k.kinematics, { from: 'csv' });
  assert.equal(k.source, 'share');
  assert.equal(k.label.length, 80);
  assert.deepEqual(calls[0][1], { units: 'deg', flap_hz: 25, max_harmonic: undefined });
  const own = kinFromShare({ kinematics: { flap_freq_hz: 30 } }, engine);
  assert.deepEqual(own, {
    kinematics: { flap_freq_hz: 30 },
    source: 'share',
    label: 'shared kinematics',
    samples: null,
    csv: null,
  });
  assert.throws(() => kinFromShare(null, engine), /kin: expected an object/);
  assert.throws(() => kinFromShare({ label: 'y' }, engine), /kin\.kinematics/);
});
