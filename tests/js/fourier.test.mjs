// The lab's one JS copy of the sampled-angle DFT (www/fourier.js) against the core's
// (src/kinematics.rs `Angle::series`): the REAL wasm in node evaluates a config whose angles are
// sampled tables (wasm anglesAt), and the JS series of the same tables, evaluated at the same
// instants, must give the same angles to 1e-12 rad — with the default harmonic cap, an asked-for
// cap, an odd N and an even N at its Nyquist term. Also: the series of N samples with every
// harmonic gives the samples back. Needs www/pkg (scripts/build-web.sh www).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { sampledSeries, seriesSamples, DEFAULT_SAMPLED_MAX_HARMONIC } from '../../www/fourier.js';
import { prng } from './prng.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const PKG = path.join(ROOT, 'www', 'pkg');

async function loadReal() {
  const glue = path.join(PKG, 'wingbeat.js');
  assert.ok(fs.existsSync(glue), 'www/pkg is missing: run `bash scripts/build-web.sh www` first');
  const m = await import(new URL(`file://${glue}`).href);
  m.initSync({ module: fs.readFileSync(path.join(PKG, 'wingbeat_bg.wasm')) });
  return m;
}
const wbPromise = loadReal();

/** A measured-looking stroke: a few harmonics and deterministic noise, rad. */
function table(n, seed, amp) {
  const rnd = prng(seed);
  return Array.from({ length: n }, (_, j) => {
    const p = (2 * Math.PI * j) / n;
    return (
      amp * Math.sin(p + 0.2) + 0.2 * amp * Math.cos(3 * p) + 0.05 * amp * Math.sin(7 * p) + 0.02 * amp * (rnd() - 0.5)
    );
  });
}

for (const [what, n, cap] of [
  ['the default cap (N = 120: 24 of 60 harmonics)', 120, null],
  ['a cap asked for (N = 64, 5 harmonics)', 64, 5],
  ['an odd N with every harmonic (N = 31)', 31, 15],
  ['an even N up to its Nyquist term (N = 20, 10 harmonics)', 20, 10],
]) {
  test(`JS series of a sampled table = the core’s, evaluated by wasm anglesAt: ${what}`, async () => {
    const wb = await wbPromise;
    const fd = 25;
    const angle = (values) => ({ kind: 'sampled', values, max_harmonic: cap });
    const tabs = [table(n, 1, 0.7), table(n, 2, 0.4), table(n, 3, 0.15)];
    const cfg = {
      ...wb.defaultConfig(),
      kinematics: { flap_freq_hz: fd, alpha: angle(tabs[0]), beta: angle(tabs[1]), gamma: angle(tabs[2]) },
    };
    // 3N + 1 instants over one period: the table's own points and two between each pair
    const m = 3 * n;
    const times = Array.from({ length: m }, (_, j) => j / (m * fd));
    const core = wb.anglesAt(cfg, times);
    let worst = 0;
    tabs.forEach((v, c) => {
      const series = sampledSeries(v, cap);
      assert.equal((series.length - 1) / 2, Math.min(Math.floor(n / 2), cap ?? DEFAULT_SAMPLED_MAX_HARMONIC));
      const js = seriesSamples(series, m);
      for (let j = 0; j < m; j++) worst = Math.max(worst, Math.abs(js[j] - core[3 * j + c]));
    });
    assert.ok(worst < 1e-12, `largest difference ${worst} rad`);
  });
}

test('every harmonic kept: the series gives the N samples back (even and odd N)', () => {
  for (const n of [8, 9, 50]) {
    const v = table(n, 7, 1);
    const back = seriesSamples(sampledSeries(v, n), n);
    assert.equal(sampledSeries(v, n).length, 1 + 2 * Math.floor(n / 2));
    for (let j = 0; j < n; j++)
      assert.ok(Math.abs(back[j] - v[j]) < 1e-12, `N = ${n}, j = ${j}: ${back[j]} vs ${v[j]}`);
  }
});

test('a cap low-passes: one harmonic of a two-harmonic table leaves the second out', () => {
  const n = 40;
  const v = Array.from(
    { length: n },
    (_, j) => 0.3 + Math.sin((2 * Math.PI * j) / n) + 0.5 * Math.cos((4 * Math.PI * j) / n),
  );
  const s = sampledSeries(v, 1);
  assert.equal(s.length, 3);
  assert.ok(Math.abs(s[0] - 0.3) < 1e-12 && Math.abs(s[1] - 1) < 1e-12 && Math.abs(s[2]) < 1e-12, JSON.stringify(s));
  const two = sampledSeries(v, 2);
  assert.ok(Math.abs(two[4] - 0.5) < 1e-12 && Math.abs(two[3]) < 1e-12);
});
