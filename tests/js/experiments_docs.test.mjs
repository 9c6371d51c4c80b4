// The guided experiments as the docs list them: docs/embedding.md's `exp` row names exactly the
// experiments of www/experiments.js (the list one entry point's docs left one out of), and the
// URL parser accepts exactly those ids. Run: node --test tests/js/experiments_docs.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { EXPERIMENTS, experimentPatch } from '../../www/experiments.js';
import { EXPERIMENT_IDS } from '../../www/state.js';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const ids = EXPERIMENTS.map((e) => e.id);

test('the URL parser accepts exactly the experiments that are defined', () => {
  assert.deepEqual([...EXPERIMENT_IDS].sort(), [...ids].sort());
});

test("docs/embedding.md's exp row lists every experiment and nothing else", () => {
  const md = fs.readFileSync(path.join(ROOT, 'docs', 'embedding.md'), 'utf8');
  const row = md.split('\n').find((l) => l.startsWith('| `exp` |'));
  assert.ok(row, 'an `exp` row in the attribute table');
  const cell = row.split(' | ')[1];
  // The ids are the code spans before the first parenthesis (what follows names files and values).
  const listed = [...cell.split('(')[0].matchAll(/`([a-z-]+)`/g)].map((m) => m[1]);
  assert.deepEqual(listed, ids);
});

test('every experiment has one patch: its settings, with values given alongside kept', () => {
  for (const id of ids) {
    const p = experimentPatch(id);
    assert.ok(p, id);
    assert.equal(p.exp, id);
    const e = EXPERIMENTS.find((x) => x.id === id);
    for (const [k, v] of Object.entries(e.params)) assert.equal(p[k], v, `${id}: ${k}`);
  }
  const damping = experimentPatch('damping', ['zeta']);
  assert.equal('zeta' in damping, false, 'a value given with exp= is not replaced');
  assert.equal(damping.duration, 10);
  assert.equal('modes' in experimentPatch('beat'), false, 'the mode set is kept unless the experiment names it');
  assert.equal(experimentPatch('sensing').modes, 'fe');
  assert.equal(experimentPatch('nope'), null);
});
