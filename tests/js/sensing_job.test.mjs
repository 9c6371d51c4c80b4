// The sensing panel's analysis job (www/views/sensing-job.js) with a fake store and engine: it
// asks once SENSE_DELAY_MS after the last change and only while visible, never twice for the
// same input, once more when something changed during a run, and says how a run ended.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { senseJob, SENSE_DELAY_MS } from '../../www/views/sensing-job.js';

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const settle = () => sleep(SENSE_DELAY_MS + 60);

function harness({ visible = true } = {}) {
  const fe = { n_modes: 2, n_nodes: 4, nodes: [1], triangles: [2], strain_nodes: [3] };
  let state = {
    modes: 'fe',
    fe,
    body_rate: 1,
    body_axis: 'z',
    result: { cfg: { n: 1 }, analysis: { sim: { modes: [{}, {}] } } },
  };
  const runs = [];
  const cancelled = [];
  const engine = {
    run(kind, input, progress) {
      let resolve, reject;
      const promise = new Promise((a, b) => {
        resolve = a;
        reject = b;
      });
      const job = { id: runs.length + 1, kind, input, progress, resolve, reject, promise };
      runs.push(job);
      return job;
    },
    cancel: (id) => cancelled.push(id),
  };
  const store = { get: () => state };
  const ui = { status: { textContent: '' }, prog: { hidden: true, max: 0, value: 0 }, cancel: { hidden: true } };
  const box = { dataset: {} };
  let point = null;
  let drawn = 0;
  const job = senseJob(/** @type {any} */ ({ store, engine }), /** @type {any} */ (ui), /** @type {any} */ (box), {
    point: () => point,
    visible: () => visible,
    onResult: () => drawn++,
  });
  return {
    job,
    runs,
    cancelled,
    ui,
    box,
    fe,
    set: (patch) => {
      state = { ...state, ...patch };
    },
    pick: (p) => {
      point = p;
    },
    drawn: () => drawn,
  };
}

const answer = (n = 4) => ({ result: { n_nodes: n, warnings: [] }, ms: 12 });

test('one request SENSE_DELAY_MS after the last change, with the body rate, the wing and the point', async () => {
  const h = harness();
  h.job.schedule();
  h.job.schedule();
  await sleep(SENSE_DELAY_MS / 2);
  assert.equal(h.runs.length, 0, 'nothing before the delay');
  h.pick([3, -6]);
  await settle();
  assert.equal(h.runs.length, 1, 'the two changes ask once');
  const r = h.runs[0];
  assert.equal(r.kind, 'sense');
  assert.deepEqual(r.input.body_rate, [0, 0, 1]);
  assert.deepEqual(r.input.fe, { nodes: [1], triangles: [2], strain_nodes: [3] });
  assert.deepEqual(r.input.opts, { point_mm: [3, -6] });
  assert.equal(h.box.dataset.state, 'computing');
  assert.equal(h.ui.prog.hidden, false);
  assert.equal(h.ui.cancel.hidden, false);
  assert.equal(h.job.running, true);
  r.progress(3, 8);
  assert.equal(h.ui.prog.value, 3);
  assert.equal(h.ui.prog.max, 8);
  r.resolve(answer());
  await sleep(0);
  assert.equal(h.job.running, false);
  assert.equal(h.drawn(), 1);
  assert.equal(h.job.result.n_nodes, 4);
  assert.equal(h.job.cfg, JSON.stringify({ n: 1 }));
  assert.match(h.ui.status.textContent, /^Done, in a vacuum, in .* \(analysis 0\.012 s in the worker/);
  assert.equal(h.box.dataset.workerMs, '12');
  assert.equal(h.ui.prog.hidden, true);
  assert.equal(h.job.stale(), false);
  assert.equal(h.job.forOtherWing(h.fe), false);
  assert.equal(h.job.forOtherWing({}), true);
  h.job.schedule();
  await settle();
  assert.equal(h.runs.length, 1, 'the same input is not analysed again');
  h.job.destroy();
});

test('a change during a run asks again when it ends; cancel reaches the engine only while running', async () => {
  const h = harness();
  h.job.cancel();
  assert.deepEqual(h.cancelled, []);
  h.job.schedule();
  await settle();
  assert.equal(h.runs.length, 1);
  h.set({ body_rate: 2 });
  h.job.schedule();
  await settle();
  assert.equal(h.runs.length, 1, 'one at a time');
  h.job.cancel();
  assert.deepEqual(h.cancelled, [1]);
  h.runs[0].reject(new Error('cancelled'));
  await sleep(0);
  assert.equal(h.box.dataset.state, 'cancelled');
  assert.match(h.ui.status.textContent, /^Cancelled; change a setting/);
  await settle();
  assert.equal(h.runs.length, 2, 'the change made during the run is analysed');
  assert.deepEqual(h.runs[1].input.body_rate, [0, 0, 2]);
  h.runs[1].reject(new Error('out of memory'));
  await sleep(0);
  assert.equal(h.box.dataset.state, 'error');
  assert.equal(h.ui.status.textContent, 'Error: out of memory');
  assert.equal(h.job.result, null);
  assert.equal(h.job.stale(), true);
  h.job.destroy();
});

test('nothing is asked while hidden, without an FE wing for the run, or after destroy', async () => {
  const hidden = harness({ visible: false });
  hidden.job.schedule();
  await settle();
  assert.equal(hidden.runs.length, 0);
  const paper = harness();
  paper.set({ modes: 'paper' });
  paper.job.schedule();
  await settle();
  assert.equal(paper.runs.length, 0);
  const gone = harness();
  gone.job.schedule();
  gone.job.destroy();
  await settle();
  assert.equal(gone.runs.length, 0);
});
