// The lab's live recompute (www/lab/live.js) with a stand-in engine: several parameter changes in
// one task make one request, nothing is asked while the share fragment is restored, only results
// of a live element are published, the FE wing is computed when the FE mode set needs it (the
// selected mode and a strain point off the new wing fall back), and a wing that cannot be built
// or computed is said in the error line. wingPoints picks the outline of the wing wanted.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createLive, wingPoints } from '../../www/lab/live.js';
import { createStore } from '../../www/store.js';
import { defaults } from '../../www/state.js';

const PLANFORMS = [
  {
    id: 'manduca',
    points_mm: [
      [0, 0],
      [1, 0],
      [1, 1],
    ],
  },
  {
    id: 'drosophila',
    points_mm: [
      [0, 0],
      [2, 0],
      [2, 3],
    ],
  },
];

test('wingPoints: an own outline wins, a built-in one is found by id, the default is null, an unknown id names `outline`', () => {
  const own = /** @type {[number, number][]} */ ([
    [0, 0],
    [5, 0],
    [5, 5],
  ]);
  const wing = /** @type {any} */ ({ points: own });
  assert.equal(
    wingPoints({ wing, outline: 'drosophila' }, () => PLANFORMS),
    own,
  );
  assert.deepEqual(
    wingPoints({ wing: null, outline: 'drosophila' }, () => PLANFORMS),
    PLANFORMS[1].points_mm,
  );
  let asked = 0;
  const count = () => {
    asked++;
    return PLANFORMS;
  };
  assert.equal(wingPoints({ wing: null, outline: 'manduca' }, count), null);
  assert.equal(wingPoints({ wing: null, outline: '' }, count), null);
  assert.equal(asked, 0, 'the default outline needs no look-up');
  assert.throws(() => wingPoints({ wing: null, outline: 'bee' }, () => PLANFORMS), /^Error: outline: .*"bee"/);
});

/** A stand-in engine: records requests and wings; results and FE wings come when the test says. */
function fakeEngine(over = {}) {
  const e = {
    ready: true,
    fe: /** @type {any} */ (null),
    wingCurrent: false,
    requests: /** @type {any[]} */ ([]),
    wings: /** @type {any[]} */ ([]),
    /** @type {((v: any) => void)[]} */
    answers: [],
    fePromise: /** @type {Promise<any> | null} */ (null),
    feCalls: 0,
    requestLive(p) {
      e.requests.push(p);
      return new Promise((res) => e.answers.push(res));
    },
    planforms: () => PLANFORMS,
    wingInput: (p, points) => ({ e_gpa: p.e_gpa, points }),
    setWing(w) {
      e.wings.push(w);
    },
    ensureFe() {
      e.feCalls++;
      return /** @type {Promise<any>} */ (e.fePromise);
    },
    modalStrainAt(_pt) {},
    ...over,
  };
  return e;
}

function setup({ engine = fakeEngine(), state = {}, alive = () => true } = {}) {
  const store = createStore({ ...defaults(), fe: null, status: null, wing: null, strain_point: null, ...state });
  const log = { errors: /** @type {string[]} */ ([]), notices: /** @type {string[]} */ ([]), published: [] };
  const live = createLive({
    store: /** @type {any} */ (store),
    engine: /** @type {any} */ (engine),
    alive,
    error: (t) => log.errors.push(t),
    notice: (t) => log.notices.push(t),
    publish: (r) => log.published.push(r),
  });
  return { store, engine, live, log };
}

const tick = () => new Promise((r) => setTimeout(r, 0));

test('several schedule() calls in one task make one request; its result is published after the error line is cleared', async () => {
  const { engine, live, log } = setup();
  live.schedule();
  live.schedule();
  live.schedule();
  assert.equal(engine.requests.length, 0, 'nothing before the end of the task');
  await tick();
  assert.equal(engine.requests.length, 1);
  engine.answers[0]({ compute_ms: 1 });
  await tick();
  assert.deepEqual(log.published, [{ compute_ms: 1 }]);
  assert.deepEqual(log.errors, [''], 'no wing error: the error line is hidden');
  live.schedule();
  await tick();
  assert.equal(engine.requests.length, 2, 'a later task asks again');
});

test('a superseded (null) result, and any result once the element is gone, is not published', async () => {
  let on = true;
  const { engine, live, log } = setup({ alive: () => on });
  live.render();
  live.render();
  engine.answers[0](null);
  on = false;
  engine.answers[1]({ compute_ms: 2 });
  await tick();
  assert.deepEqual(log.published, []);
  live.schedule();
  await tick();
  assert.equal(engine.requests.length, 2, 'a schedule() after removal asks nothing');
});

test('reset() drops a queued recompute', async () => {
  const { engine, live } = setup();
  live.schedule();
  live.reset();
  await tick();
  assert.equal(engine.requests.length, 0);
});

test('while holding() work is in flight neither the wing nor a recompute is asked for; afterwards both are', async () => {
  const { engine, live } = setup();
  /** @type {() => void} */
  let finish = () => {};
  const held = live.holding(() => new Promise((r) => (finish = () => r(undefined))));
  live.render();
  live.wantWing();
  assert.equal(engine.requests.length, 0);
  assert.equal(engine.wings.length, 0);
  finish();
  await held;
  live.wantWing();
  live.render();
  assert.equal(engine.wings.length, 1);
  assert.equal(engine.requests.length, 1);
  // A failing restore still releases the hold.
  await assert.rejects(
    live.holding(() => Promise.reject(new Error('bad fragment'))),
    /bad fragment/,
  );
  live.render();
  assert.equal(engine.requests.length, 2);
});

test('a request the engine rejects at once is said in the error line', () => {
  const engine = fakeEngine({
    requestLive() {
      throw new Error('flap_hz: 0 is outside 1..200');
    },
  });
  const { live, log } = setup({ engine });
  live.render();
  assert.deepEqual(log.errors, ['Computation rejected: flap_hz: 0 is outside 1..200']);
});

test('FE modes: the first FE wing is computed before any request; the mode and a strain point off the wing fall back', async () => {
  let resolveFe = (_v) => {};
  const engine = fakeEngine({
    fePromise: new Promise((r) => (resolveFe = r)),
    modalStrainAt() {
      throw new Error('not on the mesh');
    },
  });
  const { store, live, log } = setup({ engine, state: { modes: 'fe', mode: '5', strain_point: [10, 3] } });
  live.render();
  live.render();
  assert.equal(engine.requests.length, 0, 'no request while the first FE wing computes');
  assert.equal(engine.feCalls, 1, 'one FE computation at a time');
  assert.match(String(store.get().status), /FE wing/);
  const fe = { modes: [{}, {}, {}] };
  engine.fe = fe;
  engine.wingCurrent = true;
  resolveFe(fe);
  await tick();
  const s = store.get();
  assert.equal(s.fe, fe);
  assert.equal(s.mode, '1', 'mode 5 of 3 goes back to mode 1');
  assert.equal(s.strain_point, null);
  assert.match(log.notices[0], /\(10, 3\) mm is not on this wing/);
  assert.equal(engine.requests.length, 1, 'the new wing is computed with');
});

test('an FE wing that cannot be computed is said (the paper modes meanwhile) and the lab computes on', async () => {
  const engine = fakeEngine({ fePromise: Promise.reject(new Error('mesh too fine')) });
  const { live, log } = setup({ engine, state: { modes: 'fe' } });
  live.render();
  await tick();
  await tick();
  assert.deepEqual(log.errors, [
    'The FE wing could not be computed: mesh too fine. Showing the paper table’s modes meanwhile.',
  ]);
  assert.equal(engine.requests.length, 1, 'the recompute after the failure asks for a result');
  engine.answers[0]({ compute_ms: 3 });
  await tick();
  assert.equal(log.errors.at(-1), log.errors[0], 'the reason stays shown with the new result');
  assert.equal(log.published.length, 1);
});

test('wantWing: the wing wanted goes to the engine; a wing that cannot be built is said; an imported wing is left alone', () => {
  const { engine, live, log, store } = setup({ state: { outline: 'drosophila' } });
  live.wantWing();
  assert.deepEqual(engine.wings.at(-1).points, PLANFORMS[1].points_mm);
  store.set({ outline: 'bee' });
  live.wantWing();
  assert.equal(engine.wings.length, 1);
  assert.match(log.errors[0], /^The wing is not valid: .*outline/);
  store.set({ wing: /** @type {any} */ ({ source: 'import', points: null }) });
  live.wantWing();
  assert.equal(engine.wings.length, 1);
});

test('wantWing: a wing already computed (cached) is published at once', () => {
  const fe = { modes: [{}, {}] };
  const engine = fakeEngine({ wingCurrent: true, fe });
  const { store, live } = setup({ engine });
  live.wantWing();
  assert.equal(store.get().fe, fe);
});
