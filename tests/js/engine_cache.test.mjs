// The engine's caches (www/engine/cache.js): the FE wings by input with the wanted wing and the
// wing in use kept apart, the LRU that bounds them, and the modal strains at a point computed
// once per wing and point — against a fake solver, no worker and no wasm.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createLru, createWings, createPointStrains, wingKey, FE_CACHE } from '../../www/engine/cache.js';

/** A solver whose jobs finish when the test says so. */
function fakeSolver() {
  const jobs = [];
  let id = 0;
  const solve = (input) => {
    let resolve, reject;
    const promise = new Promise((res, rej) => {
      resolve = res;
      reject = rej;
    });
    const job = { id: ++id, input, promise, finish: (r) => resolve({ result: r, ms: 1 }), fail: (e) => reject(e) };
    jobs.push(job);
    return job;
  };
  return { solve, jobs };
}

test('the LRU keeps the newest entries and refreshes an entry stored again', () => {
  const c = createLru(2);
  c.set('a', 1);
  c.set('b', 2);
  c.set('a', 3);
  c.set('c', 4);
  assert.equal(c.get('b'), undefined, 'b was the oldest');
  assert.equal(c.get('a'), 3);
  assert.equal(c.get('c'), 4);
  assert.equal(c.size, 2);
});

test('a wing being computed is one job; it is used when ready only if still wanted (or none is in use)', async () => {
  const { solve, jobs } = fakeSolver();
  const A = { n_modes: 2 },
    B = { n_modes: 3 };
  const w = createWings({ initial: A, solve });
  const pa = w.ensure();
  assert.equal(w.ensure(), pa, 'the same promise while computing');
  assert.equal(jobs.length, 1);
  assert.equal(w.fe, null);
  jobs[0].finish({ modes: ['a'] });
  const ra = await pa;
  assert.equal(w.fe, ra, 'the first wing is used at once');
  assert.equal(w.current, true);
  const jb = w.compute(B);
  assert.equal(w.compute(B), jb, 'one job per input');
  jobs[1].finish({ modes: ['b'] });
  const rb = await jb.promise;
  assert.equal(w.fe, ra, 'B is computed but not wanted: A stays in use');
  w.want(B);
  assert.equal(w.fe, rb);
  assert.equal(w.current, true);
  // Back to A: cached, no job.
  assert.equal(await w.ensure(A), ra);
  assert.equal(jobs.length, 2);
  // Wanting an uncomputed wing: the old one stays in use, and it is not current.
  w.want({ n_modes: 4 });
  assert.equal(w.fe, ra);
  assert.equal(w.current, false);
});

test('a failed computation is tried again on the next call; the wing in use stays', async () => {
  const { solve, jobs } = fakeSolver();
  const w = createWings({ initial: { n_modes: 2 }, solve });
  const p = w.ensure();
  jobs[0].fail(new Error('cancelled'));
  await assert.rejects(p, /cancelled/);
  await Promise.resolve();
  const p2 = w.ensure();
  assert.equal(jobs.length, 2, 'a new job');
  jobs[1].finish({ modes: [] });
  assert.deepEqual(await p2, { modes: [] });
});

test('only the last FE_CACHE wings are kept; imported modes are used at once under their key', async () => {
  const { solve, jobs } = fakeSolver();
  const w = createWings({ initial: { n_modes: 1 }, solve });
  const inputs = Array.from({ length: FE_CACHE + 1 }, (_, i) => ({ n_modes: i + 1 }));
  for (const [i, input] of inputs.entries()) {
    const j = w.compute(input);
    jobs[i].finish({ i });
    await j.promise;
  }
  assert.equal(jobs.length, FE_CACHE + 1);
  w.compute(inputs[0]);
  assert.equal(jobs.length, FE_CACHE + 2, 'the oldest wing was dropped: computed again');
  w.compute(inputs[FE_CACHE]);
  assert.equal(jobs.length, FE_CACHE + 2, 'the newest is kept');
  const imported = { modes: ['x'] };
  w.use(imported, 'import:x');
  assert.equal(w.fe, imported);
  assert.equal(w.current, true);
  assert.equal(wingKey({ imported: 'import:x' }), JSON.stringify({ imported: 'import:x' }));
  assert.equal(wingKey(undefined), 'null');
});

test('modal strains at a point: the modes carry them as point S, computed once per wing and point', () => {
  const calls = [];
  const modesAt = createPointStrains((fe, p) => {
    calls.push(p);
    return fe.modes.map((_, k) => ({ eps_x: k + p[0], eps_y: p[1], gamma_xy: 0 }));
  });
  const fe = {
    modes: [
      { name: 'a', strains: [{ point: 'P', eps_x: 9, eps_y: 9, gamma_xy: 9 }] },
      { name: 'b', strains: [] },
    ],
  };
  assert.equal(modesAt(fe, null), fe.modes, 'no point: the modes as they are');
  const m = modesAt(fe, [4, -2]);
  assert.deepEqual(
    m.map((x) => x.strains),
    [[{ point: 'S', eps_x: 4, eps_y: -2, gamma_xy: 0 }], [{ point: 'S', eps_x: 5, eps_y: -2, gamma_xy: 0 }]],
  );
  assert.equal(m[0].name, 'a');
  assert.equal(fe.modes[0].strains[0].point, 'P', 'the FE result itself is not changed');
  modesAt(fe, [4, -2]);
  assert.equal(calls.length, 1, 'once per wing and point');
  modesAt(fe, [5, -2]);
  modesAt({ modes: fe.modes }, [5, -2]);
  assert.equal(calls.length, 3, 'a new point or a new wing computes again');
});
