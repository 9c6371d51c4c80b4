// The lab's screens (www/screens.js): every panel is on a focused screen, the full page has them
// all, an author's panels= choice is shown exactly, screen= is validated by the URL parser with
// a named reason, and every guided experiment opens a screen that shows the experiment and the
// study it points to.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  SCREENS,
  SCREEN_IDS,
  DEFAULT_SCREEN,
  EXPERIMENT_SCREEN,
  screenPanels,
  resolveScreen,
  screenOfPanel,
} from '../../www/screens.js';
import { PANELS, EXPERIMENT_IDS, parseQuery, parsePairs, toQuery, defaults, paramsOf } from '../../www/state.js';
import { EXPERIMENTS } from '../../www/experiments.js';

test('every screen lists known panels; every panel is on some focused screen; full has all', () => {
  for (const s of SCREENS) {
    if (s.panels) for (const p of s.panels) assert.ok(PANELS.includes(p), `${s.id}: unknown panel ${p}`);
  }
  for (const p of PANELS) assert.notEqual(screenOfPanel(p, PANELS), 'full', `${p} is only on the full page`);
  assert.deepEqual(screenPanels('full', PANELS), PANELS);
  assert.ok(SCREEN_IDS.includes(DEFAULT_SCREEN));
  assert.deepEqual(screenPanels('nope', PANELS), []);
});

test('focused screens are small: at most 5 panels each', () => {
  for (const s of SCREENS) if (s.panels) assert.ok(s.panels.length <= 5, `${s.id}: ${s.panels.length} panels`);
});

test("resolveScreen: default, wanted, and an author's panels= choice shown exactly", () => {
  const all = PANELS;
  assert.equal(resolveScreen('', all, all).id, DEFAULT_SCREEN);
  assert.deepEqual(resolveScreen('', all, all).offered, SCREEN_IDS);
  const f = resolveScreen('forces', all, all);
  assert.equal(f.id, 'forces');
  assert.deepEqual(f.shown, screenPanels('forces', all));
  // A choice one screen holds: that screen, exactly the chosen panels.
  const c = resolveScreen('', ['controls', 'numbers', 'spectrum'], all);
  assert.equal(c.id, 'forces');
  assert.deepEqual(c.shown.slice().sort(), ['controls', 'numbers', 'spectrum']);
  // A choice no single screen holds: the full page with exactly those panels.
  const m = resolveScreen('', ['controls', 'experiments', 'sensing'], all);
  assert.deepEqual(m.shown.slice().sort(), ['controls', 'experiments', 'sensing']);
  // A wanted screen holding none of the chosen panels falls back like no screen.
  const n = resolveScreen('beat', ['numbers'], all);
  assert.deepEqual(n.shown, ['numbers']);
  assert.ok(!n.offered.includes('beat'));
  // A wanted screen with a choice: its chosen panels only.
  assert.deepEqual(resolveScreen('beat', ['controls', 'numbers', 'spectrum'], all).shown, ['controls']);
});

test('screen= is parsed and written like the other URL parameters; unknown values are named', () => {
  assert.equal(parseQuery('?screen=wing').state.screen, 'wing');
  const bad = parseQuery('?screen=Forces');
  assert.equal(bad.state.screen, undefined);
  assert.deepEqual(bad.rejected, [{ key: 'screen', why: `expected one of ${SCREEN_IDS.join(', ')}` }]);
  assert.equal(parsePairs([['screen', 'x'.repeat(500)]]).rejected[0].key, 'screen');
  assert.match(toQuery({ ...defaults(), screen: 'research' }), /(^|&)screen=research(&|$)/);
  assert.doesNotMatch(toQuery(defaults()), /screen=/);
  // Not a parameter default: resetting the parameters (defaults()) keeps the screen.
  assert.ok(!('screen' in defaults()));
  assert.equal(paramsOf({ ...defaults(), screen: 'sensing' }).screen, 'sensing');
});

test('every guided experiment opens a screen that shows the experiment and what it points to', () => {
  assert.deepEqual(Object.keys(EXPERIMENT_SCREEN).sort(), EXPERIMENT_IDS.slice().sort());
  for (const e of EXPERIMENTS) {
    const id = EXPERIMENT_SCREEN[e.id];
    assert.ok(SCREEN_IDS.includes(id), `${e.id}: ${id}`);
    const shown = screenPanels(id, PANELS);
    assert.ok(shown.includes('experiments'), `${e.id}: the experiment's text is on ${id}`);
    if (e.study) {
      // Its "Go to" button opens the study's screen, which shows the experiment's text too.
      const target = e.study.kind === 'resonance' ? 'resonance' : 'studies';
      const there = screenPanels(screenOfPanel(target, PANELS), PANELS);
      assert.ok(there.includes(target) && there.includes('experiments'), `${e.id}: ${target} with the experiment`);
    }
  }
  assert.ok(screenPanels(EXPERIMENT_SCREEN.sensing, PANELS).includes('sensing'));
  for (const id of ['beat', 'no-yaw', 'damping', 'resonance', 'instability'])
    assert.ok(screenPanels(EXPERIMENT_SCREEN[id], PANELS).includes('time'), `${id} talks about the responses plot`);
});
