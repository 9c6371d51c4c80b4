// The messages between the engine and its workers (www/engine/protocol.js), which both
// www/engine/*.js and www/worker.js build and read: each message the worker writes is read back
// as what it says, the job kinds are the ones worker.js answers, and a result's typed arrays are
// listed once each for transfer.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import {
  JOB,
  JOB_KINDS,
  jobMessage,
  readRequest,
  readReply,
  readyMessage,
  progressMessage,
  resultMessage,
  errorMessage,
  wasmModuleMessage,
  wasmPendingMessage,
  transferList,
} from '../../www/engine/protocol.js';

test('what the worker writes is read back as what it says', () => {
  assert.deepEqual(readReply(readyMessage()), { type: 'ready' });
  assert.deepEqual(readReply(progressMessage(3, 2, 7)), { type: 'progress', id: 3, done: 2, total: 7 });
  const r = { a: new Float64Array(2) };
  assert.deepEqual(readReply(resultMessage(4, r, 12.5)), { type: 'result', id: 4, result: r, ms: 12.5 });
  assert.deepEqual(readReply(errorMessage(5, 'invalid value for `duration_s`')), {
    type: 'error',
    id: 5,
    error: 'invalid value for `duration_s`',
  });
  // An empty error message is still an error, not a result.
  assert.equal(readReply(errorMessage(6, '')).type, 'error');
  // A result that is null or 0 is a result.
  assert.deepEqual(readReply(resultMessage(7, 0, 1)), { type: 'result', id: 7, result: 0, ms: 1 });
  // Anything unreadable is an empty result for no job (the engine drops it: no job has id undefined).
  assert.deepEqual(readReply(null), { type: 'result', id: undefined, result: undefined, ms: undefined });
});

test('what the engine writes is read by the worker as the job and its inputs', () => {
  const m = jobMessage(9, JOB.sweep, { cfg: { duration_s: 1 }, opts: { points: 3 } });
  assert.deepEqual(m, { id: 9, kind: 'sweep', cfg: { duration_s: 1 }, opts: { points: 3 } });
  const got = readRequest(m);
  assert.ok(!('wasmModule' in got));
  assert.equal(got.id, 9);
  assert.equal(got.kind, 'sweep');
  assert.deepEqual(got.job.opts, { points: 3 });
  const mod = { fake: 'module' };
  // The page's compiled module names its build (the live worker gets the small live one);
  // anything but 'live' is the full build.
  assert.deepEqual(readRequest(wasmModuleMessage(/** @type {any} */ (mod))), { wasmModule: mod, variant: 'full' });
  assert.deepEqual(readRequest(wasmModuleMessage(/** @type {any} */ (mod), 'live')), {
    wasmModule: mod,
    variant: 'live',
  });
  assert.deepEqual(readRequest({ wasmModule: mod, variant: 'other' }), { wasmModule: mod, variant: 'full' });
  // "The module follows" and "it will not": only a strict true waits.
  assert.deepEqual(readRequest(wasmPendingMessage(true)), { wasmPending: true });
  assert.deepEqual(readRequest(wasmPendingMessage(false)), { wasmPending: false });
  assert.deepEqual(readRequest({ wasmPending: 'yes' }), { wasmPending: false });
  assert.deepEqual(readRequest(undefined), { id: undefined, kind: undefined, job: {} });
});

test('the job kinds are the jobs worker.js defines, each once', () => {
  assert.deepEqual([...JOB_KINDS].sort(), [
    'analyze',
    'classify',
    'damping',
    'fe',
    'icmap',
    'reproduce',
    'resonance',
    'sense',
    'sweep',
  ]);
  const src = fs.readFileSync(new URL('../../www/worker.js', import.meta.url), 'utf8');
  const defined = [...src.matchAll(/^ {2}\[JOB\.(\w+)\]\(/gm)].map((m) => m[1]).sort();
  assert.deepEqual(defined, [...JOB_KINDS].sort(), 'worker.js has one job per kind, keyed by JOB');
});

test('transferList: every typed array’s buffer once, found at any depth', () => {
  const shared = new Float64Array(4);
  const u = new Uint32Array(3);
  const res = {
    sim: { t: shared, q: [shared, new Float64Array(2)] },
    fe: { triangles: u, n: 3 },
    name: 'x',
    none: null,
  };
  const list = transferList(res);
  assert.equal(list.length, 3);
  assert.ok(list.includes(shared.buffer) && list.includes(u.buffer));
  assert.deepEqual(transferList({ a: 1, b: 'two', c: [null] }), []);
});
