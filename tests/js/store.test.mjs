// Unit tests of the lab's observable store (www/store.js). Run: node --test tests/js
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createStore } from '../../www/store.js';

test('get returns the initial state; set merges and reports changed keys', () => {
  const s = createStore({ a: 1, b: 2 });
  assert.deepEqual(s.get(), { a: 1, b: 2 });
  assert.deepEqual(s.set({ a: 1, b: 3, c: 4 }), ['b', 'c']);
  assert.deepEqual(s.get(), { a: 1, b: 3, c: 4 });
  assert.ok(Object.isFrozen(s.get()));
});

test('subscribers run only for their keys, once per set, with the changed keys', () => {
  const s = createStore({ a: 1, b: 2 });
  const calls = [];
  s.subscribe(['a'], (st, ch) => calls.push(['a', st.a, ch]));
  s.subscribe(['b', 'c'], (st, ch) => calls.push(['bc', st.b, ch]));
  s.subscribe('*', (_st, ch) => calls.push(['*', ch]));
  s.set({ a: 5 });
  s.set({ b: 2 }); // unchanged: nobody runs
  s.set({ b: 7, c: 1 });
  assert.deepEqual(calls, [
    ['a', 5, ['a']],
    ['*', ['a']],
    ['bc', 7, ['b', 'c']],
    ['*', ['b', 'c']],
  ]);
});

test('unsubscribe stops notifications; NaN and -0 compare with Object.is', () => {
  const s = createStore({ x: NaN });
  let n = 0;
  const off = s.subscribe(['x'], () => n++);
  assert.deepEqual(s.set({ x: NaN }), []);
  s.set({ x: 0 });
  s.set({ x: -0 });
  assert.equal(n, 2);
  off();
  s.set({ x: 1 });
  assert.equal(n, 2);
});

test('a subscriber may set other keys (nested notifications); runaway loops are stopped', () => {
  const s = createStore({ p: 1, derived: null });
  s.subscribe(['p'], (st) => s.set({ derived: st.p * 2 }));
  const seen = [];
  s.subscribe(['derived'], (st) => seen.push(st.derived));
  s.set({ p: 4 });
  assert.equal(s.get().derived, 8);
  assert.deepEqual(seen, [8]);
  const loop = createStore({ n: 0 });
  loop.subscribe(['n'], (st) => loop.set({ n: st.n + 1 }));
  assert.throws(() => loop.set({ n: 1 }), /recursion/);
});
