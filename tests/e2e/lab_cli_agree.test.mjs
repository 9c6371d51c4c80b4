// The lab and the CLI give the same numbers for the same inputs, and exports carry what is shown:
//   - every example outline in www/examples (planform-*), loaded into the wing panel with the
//     lab's defaults and computed, is meshed as `wingbeat modes --planform FILE` meshes it: the
//     automatic element size, the node count and f1 (exactly, where the mesher repeats itself;
//     see below for the one outline where it does not);
//   - after a click on the strain map moves the strain point, "Export modes JSON" carries that
//     point (first in every mode's strains), so `wingbeat simulate --modes` reports the strain
//     the lab shows, and importing the file into a fresh lab shows the same strain with the
//     cross at the same point (found from the strains on the mesh).
//   node --test --test-concurrency=1 tests/e2e/lab_cli_agree.test.mjs   (after scripts/build-web.sh www;
//   builds target/debug/wingbeat with cargo when it is missing)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { execFileSync, spawnSync } from 'node:child_process';
import { setup, openPage, waitRenders, ROOT, OUT } from './helpers.mjs';

const EX = path.join(ROOT, 'www', 'examples');
const OUTLINES = fs
  .readdirSync(EX)
  .filter((f) => /^planform-.*\.(csv|json)$/.test(f))
  .sort();
const BIN = path.join(process.env.CARGO_TARGET_DIR || path.join(ROOT, 'target'), 'debug', 'wingbeat');

let env;
before(async () => {
  if (!fs.existsSync(BIN)) execFileSync('cargo', ['build', '--bin', 'wingbeat'], { cwd: ROOT, stdio: 'inherit' });
  env = await setup();
  fs.mkdirSync(OUT, { recursive: true });
});
after(async () => {
  if (env) await env.close();
});

/** `wingbeat modes` on a file: its JSON and the mesh line it prints on stderr. */
function cliModes(file, ...args) {
  const r = spawnSync(BIN, ['modes', '--planform', file, ...args], { cwd: ROOT, maxBuffer: 1 << 30 });
  assert.equal(r.status, 0, String(r.stderr));
  const doc = JSON.parse(String(r.stdout));
  return { nodes: doc.nodes.length, f1: doc.freq_hz[0], mesh: doc.mesh_size_mm, doc };
}
const W_IN = (k) => `[data-wing="${k}"]`;
const W = (k) => `wing-lab ${W_IN(k)}`;

/** Waits for the wing panel's computation to end; returns its status text. */
async function computed(page, timeout = 120000) {
  await page.waitForFunction(
    (s) => /Computed|could not|Imported/.test(__wl.q(s)?.textContent || '') && __wl.q('[data-wing="cancel"]').hidden,
    W_IN('status'),
    { timeout },
  );
  return page.textContent(W('status'));
}

test('every example outline: the lab meshes and solves it as `wingbeat modes --planform` does', async () => {
  assert.ok(OUTLINES.length >= 2, `example outlines: ${OUTLINES}`);
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  await page.goto(`${env.url}?modes=fe&screen=wing`);
  await page.waitForFunction(() => document.querySelector('wing-lab').fe, null, { timeout: 60000 });
  const rows = [];
  for (const name of OUTLINES) {
    const file = path.join(EX, name);
    await page.setInputFiles(W('file'), file);
    await page.waitForFunction((s) => /Outline read/.test(__wl.q(s)?.textContent || ''), W_IN('status'));
    // The element size field shows what will be used: automatic (0), with the size next to it.
    const field = await page.inputValue(W('mesh_mm'));
    const auto = await page.textContent(W('auto-mesh'));
    await page.click(W('compute'));
    assert.match(await computed(page), /^Computed/, name);
    await page.waitForFunction(() => {
      const l = document.querySelector('wing-lab');
      return l.store.get().wing && l.fe && l.store.get().fe === l.fe;
    });
    const lab = await page.evaluate(() => {
      const fe = document.querySelector('wing-lab').fe;
      return { nodes: fe.n_nodes, f1: fe.freq_hz[0], mesh: fe.mesh_size_mm };
    });
    // The CLI's mesher is repeatable on most outlines, not on outlines with several boundary
    // points at one angle from its start (the straight tapered edges: docs/fem.md, "Known open
    // bug — repeatability"; natively the order changes from run to run, in wasm it does not).
    const runs = [cliModes(file, '--n-modes', '2'), cliModes(file, '--n-modes', '2'), cliModes(file, '--n-modes', '2')];
    const repeatable = runs.every((r) => r.nodes === runs[0].nodes && r.f1 === runs[0].f1);
    const cli = runs[0];
    rows.push({
      name,
      field,
      auto,
      lab,
      cli: runs.map((r) => ({ nodes: r.nodes, f1: r.f1, mesh: r.mesh })),
      repeatable,
    });
    assert.equal(field, '0', `${name}: the field says automatic`);
    assert.equal(lab.mesh, cli.mesh, `${name}: the same (automatic) element size`);
    assert.ok(auto.includes(String(Number(cli.mesh.toPrecision(3)))), `${name}: "${auto}" names ${cli.mesh} mm`);
    if (repeatable) {
      assert.equal(lab.nodes, cli.nodes, `${name}: node count`);
      assert.ok(Math.abs(lab.f1 - cli.f1) <= 1e-9 * cli.f1, `${name}: f1 ${lab.f1} vs ${cli.f1}`);
    } else {
      // Within the mesher's own spread (measured 1585–1634 nodes, f1 ±0.05 % for the tapered
      // outline); the old lab (1 mm kept for a loaded outline: 479 nodes, 823.9 Hz) is far outside.
      const med = runs.map((r) => r.nodes).sort((a, b) => a - b)[1];
      assert.ok(
        Math.abs(lab.nodes - med) <= 0.04 * med,
        `${name}: ${lab.nodes} nodes vs the CLI's ${runs.map((r) => r.nodes)}`,
      );
      assert.ok(
        Math.abs(lab.f1 - cli.f1) <= 1e-3 * cli.f1,
        `${name}: f1 ${lab.f1} vs the CLI's ${runs.map((r) => r.f1)}`,
      );
    }
  }
  fs.writeFileSync(path.join(OUT, 'lab-cli-outlines.json'), JSON.stringify(rows, null, 1));
  assert.deepEqual(problems, []);
  await context.close();
});

test("a strain point moved by a click travels in the exported modes JSON: the CLI and a re-import show the lab's strain", async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  await page.goto(`${env.url}?modes=fe&duration=1&screen=wing`);
  await page.waitForFunction(
    () => {
      const l = document.querySelector('wing-lab');
      return l.fe && l.analysis && l.analysis.sim.strain;
    },
    null,
    { timeout: 60000 },
  );
  const p0 = await page.evaluate(() => document.querySelector('wing-lab').fe.strain_point_mm);
  // Click the strain map well away from P = (3, −6) mm.
  // The strain panel's map (the sensing panel's map shares the class).
  const map = page.locator('wing-lab canvas.wl-smap-canvas[id$="-smap"]');
  await map.scrollIntoViewIfNeeded();
  await page.waitForFunction(() => __wl.q('[data-smap]')?.dataset.state === 'ready', null, { timeout: 30000 });
  const box = await map.boundingBox();
  const n0 = Number(await page.evaluate(() => document.querySelector('wing-lab').dataset.renders));
  await page.mouse.click(box.x + box.width * 0.45, box.y + box.height * 0.3);
  await page.waitForFunction((p) => {
    const s = document.querySelector('wing-lab').store.get();
    return s.strain_point && (s.strain_point[0] !== p[0] || s.strain_point[1] !== p[1]);
  }, p0);
  await waitRenders(page, n0 + 1);
  const shown = await page.evaluate(() => {
    const l = document.querySelector('wing-lab');
    const st = l.analysis.sim.strain;
    return { point: l.store.get().strain_point, eps_x: [...st.eps_x], gamma_xy: [...st.gamma_xy] };
  });
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click(W('export'))]);
  const file = path.join(OUT, 'lab-cli-strain-modes.json');
  await dl.saveAs(file);
  const doc = JSON.parse(fs.readFileSync(file, 'utf8'));
  assert.deepEqual(
    doc.modes.map((m) => m.strains.map((p) => p.point)),
    doc.modes.map(() => ['S', 'P']),
    'the chosen point first (simulate reports it), P after it',
  );
  const sim = JSON.parse(
    execFileSync(BIN, ['simulate', '--modes', file, '--duration', '1', '--sample-rate', '10000'], {
      cwd: ROOT,
      maxBuffer: 1 << 30,
      stdio: ['ignore', 'pipe', 'ignore'],
    }).toString(),
  );
  const worst = (a, b) => {
    let w = 0,
      s = 0;
    for (let i = 0; i < a.length; i++) {
      w = Math.max(w, Math.abs(a[i] - b[i]));
      s = Math.max(s, Math.abs(b[i]));
    }
    return w / s;
  };
  assert.equal(sim.strain.point, 'S');
  assert.equal(sim.strain.eps_x.length, shown.eps_x.length);
  assert.ok(worst(shown.eps_x, sim.strain.eps_x) <= 1e-9, `ε_x lab vs CLI: ${worst(shown.eps_x, sim.strain.eps_x)}`);
  assert.ok(
    worst(shown.gamma_xy, sim.strain.gamma_xy) <= 1e-9,
    `γ_xy lab vs CLI: ${worst(shown.gamma_xy, sim.strain.gamma_xy)}`,
  );
  // Re-import into a fresh lab: the same strain, the cross at the same point.
  const o = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  await o.page.goto(`${env.url}?duration=1&screen=wing`);
  await waitRenders(o.page, 1);
  await o.page.setInputFiles(W('file'), file);
  assert.match(await computed(o.page), /^Imported/);
  await o.page.waitForFunction(
    () => {
      const l = document.querySelector('wing-lab');
      return (
        l.analysis &&
        l.analysis.sim.strain &&
        l.store.get().modes === 'fe' &&
        l.store.get().result.params.modes === 'fe'
      );
    },
    null,
    { timeout: 60000 },
  );
  const again = await o.page.evaluate(() => {
    const l = document.querySelector('wing-lab');
    return { point: l.fe.strain_point_mm, eps_x: [...l.analysis.sim.strain.eps_x] };
  });
  assert.ok(
    again.point && Math.hypot(again.point[0] - shown.point[0], again.point[1] - shown.point[1]) < 1e-6,
    `re-import: the cross at ${again.point}, chosen ${shown.point}`,
  );
  assert.ok(worst(again.eps_x, shown.eps_x) <= 1e-12, 're-import: the same strain');
  assert.deepEqual(problems, []);
  assert.deepEqual(o.problems, []);
  await o.context.close();
  await context.close();
});
