// The live requests (www/engine/requests.js): what a recompute asks for, and the newest-wins
// queue in front of the live worker — one request in flight and one waiting, a newer request
// supersedes the waiting one and makes the one in flight stale, a request waits for a starting
// worker (up to a limit, then the main thread computes), and the main thread computes when the
// worker has failed — against a fake worker and a fake main-thread compute.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { liveAsk, liveOverrides, createLiveQueue, STROKE_KEYS, LIVE_SEGMENT_LEN } from '../../www/engine/requests.js';
import { defaults } from '../../www/state.js';
import { fakeWorker } from './fake_worker.mjs';

/** A queue whose main-thread compute returns 'here:<tag>' and whose worker results are 'worker:<result>'. */
function queue({ start, startWait } = {}) {
  const made = [];
  const hereCalls = [];
  const q = createLiveQueue({
    start:
      start ||
      (() => {
        const w = fakeWorker();
        made.push(w);
        return w;
      }),
    here: (ask) => {
      hereCalls.push(ask.cfg.tag);
      if (ask.cfg.tag === 'bad') throw new Error('rejected here');
      return `here:${ask.cfg.tag}`;
    },
    fromWorker: (ask, result, ms) => `worker:${result}:${ms}:${ask.cfg.tag}`,
    startWait,
  });
  const ask = (tag) => q.request(liveAsk({ ...defaults(), mode: '2', detrend: 'mean' }, { tag }));
  return { q, made, hereCalls, ask };
}

test('what a recompute asks for: the mode index, the spectra options, the overrides', () => {
  const a = liveAsk({ ...defaults(), mode: '3', detrend: 'linear' }, { c: 1 });
  assert.equal(a.k, 2);
  assert.deepEqual(a.opts, { detrend: 'linear', segment_len: LIVE_SEGMENT_LEN });
  assert.deepEqual(a.cfg, { c: 1 });
  assert.equal(a.run, a.cfg, 'wasm gets the config itself unless a wing is attached');
  const w = liveAsk(defaults(), { c: 1 }, { c: 1, wing: {} });
  assert.deepEqual(w.cfg, { c: 1 }, 'the result keeps the plain config');
  assert.deepEqual(w.run, { c: 1, wing: {} });
  const all = liveOverrides(defaults(), false);
  assert.ok(STROKE_KEYS.every((k) => k in all));
  const kin = liveOverrides({ ...defaults(), zeta: 0.03 }, true);
  assert.deepEqual(
    Object.keys(kin).sort(),
    ['air_density', 'duration', 'zeta'],
    'custom kinematics: only ζ, the duration and the medium apply',
  );
  assert.equal(kin.zeta, 0.03);
});

test('the first request is computed here without a worker; later ones wait for the worker to be ready', async () => {
  const { q, made, hereCalls, ask } = queue();
  assert.equal(await ask('a'), 'here:a');
  assert.equal(made.length, 0, 'a lab only looked at never starts the live worker');
  // The second request starts the worker and waits for it (nothing computed on the page).
  const b = ask('b');
  assert.equal(made.length, 1);
  assert.equal(q.inWorker, false);
  assert.equal(made[0].posted.length, 0);
  // A third one made meanwhile supersedes it.
  const c = ask('c');
  assert.equal(await b, null);
  made[0].reply({ ready: true });
  assert.equal(q.inWorker, true);
  assert.equal(made[0].posted.length, 1, 'the newest waiting request goes to the worker once it is ready');
  assert.deepEqual(made[0].posted[0], {
    id: 3,
    kind: 'analyze',
    cfg: { tag: 'c' },
    opts: { detrend: 'mean', segment_len: LIVE_SEGMENT_LEN },
    k: 1,
  });
  made[0].reply({ id: 3, progress: [1, 2] });
  made[0].reply({ id: 3, result: 'R', ms: 4 });
  assert.equal(await c, 'worker:R:4:c');
  assert.deepEqual(hereCalls, ['a']);
  assert.deepEqual(q.stats, { posted: 1, superseded: 1, stale: 0, sync: 1 });
});

test('a worker slow to start: past the wait the newest request is computed here, and so are later ones until it is ready', async () => {
  const { q, made, hereCalls, ask } = queue({ startWait: 20 });
  await ask('a');
  const b = ask('b');
  assert.equal(made[0].posted.length, 0);
  assert.equal(await b, 'here:b', 'computed here once the wait ran out');
  assert.equal(await ask('c'), 'here:c', 'still starting: computed here at once');
  made[0].reply({ ready: true });
  const d = ask('d');
  assert.equal(made[0].posted.length, 1, 'ready: requests go to the worker again');
  made[0].reply({ id: 4, result: 'R', ms: 1 });
  assert.equal(await d, 'worker:R:1:d');
  assert.deepEqual(hereCalls, ['a', 'b', 'c']);
  assert.deepEqual(q.stats, { posted: 1, superseded: 0, stale: 0, sync: 3 });
});

test('a worker that fails while a request waits for it: the request is computed here', async () => {
  const { made, hereCalls, ask } = queue();
  await ask('a');
  const b = ask('b');
  made[0].onerror({ message: 'no wasm' });
  assert.equal(await b, 'here:b');
  assert.deepEqual(hereCalls, ['a', 'b']);
});

test('newest wins: the waiting request is superseded, the stale result dropped, the newest posted next', async () => {
  const { q, made, ask } = queue();
  q.warm();
  made[0].reply({ ready: true });
  const a = ask('a'),
    b = ask('b'),
    c = ask('c');
  assert.equal(made[0].posted.length, 1, 'one in flight');
  assert.equal(await b, null, 'superseded while waiting');
  made[0].reply({ id: 999, result: 'other', ms: 1 });
  assert.equal(made[0].posted.length, 1, 'a reply for another id changes nothing');
  made[0].reply({ id: made[0].posted[0].id, result: 'A', ms: 1 });
  assert.equal(await a, null, 'stale: a newer request came meanwhile');
  assert.equal(made[0].posted.length, 2);
  assert.equal(made[0].posted[1].cfg.tag, 'c');
  made[0].reply({ id: made[0].posted[1].id, error: 'invalid value for `duration_s`' });
  await assert.rejects(c, /duration_s/);
  assert.deepEqual(q.stats, { posted: 2, superseded: 1, stale: 1, sync: 0 });
});

test('a failing worker: the newest request is computed here, the older one resolves null, no new worker', async () => {
  const { q, made, ask, hereCalls } = queue();
  q.warm();
  made[0].reply({ ready: true });
  const a = ask('a'),
    b = ask('b');
  made[0].onerror({ message: 'boom' });
  assert.equal(await a, null);
  assert.equal(await b, 'here:b');
  assert.equal(made[0].terminated, true);
  assert.equal(await ask('c'), 'here:c');
  await assert.rejects(ask('bad'), /rejected here/);
  assert.equal(made.length, 1);
  assert.deepEqual(hereCalls, ['b', 'c', 'bad']);
  assert.equal(q.inWorker, false);
});

test('without workers everything is computed here; dispose resolves what is pending to null', async () => {
  const { q, ask } = queue({
    start: () => {
      throw new Error('no Worker');
    },
  });
  q.warm();
  assert.equal(await ask('a'), 'here:a');
  assert.equal(await ask('b'), 'here:b');
  const { q: q2, made, ask: ask2 } = queue();
  q2.warm();
  made[0].reply({ ready: true });
  const x = ask2('x'),
    y = ask2('y');
  q2.dispose();
  assert.equal(await x, null);
  assert.equal(await y, null);
  assert.equal(made[0].terminated, true);
  assert.equal(q2.inWorker, false);
  assert.equal(q.inWorker, false);
});

test('dispose while a request waits for the starting worker: it resolves to null and nothing is computed', async () => {
  const { q, made, hereCalls, ask } = queue({ startWait: 20 });
  await ask('a');
  const b = ask('b');
  q.dispose();
  assert.equal(await b, null);
  await new Promise((r) => setTimeout(r, 40));
  assert.deepEqual(hereCalls, ['a'], 'the wait was stopped with the queue');
  assert.equal(made[0].terminated, true);
});
