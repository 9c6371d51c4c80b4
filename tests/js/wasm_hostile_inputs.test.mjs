// Every export of the REAL wasm module (www/pkg, as tests/js/wasm.test.mjs loads it) called with
// random arguments of every JS type — undefined, null, numbers (NaN, ±Infinity, −0, 2^53, …),
// strings (empty, unicode, lone surrogates, tens of millions of characters), booleans, symbols,
// BigInts, functions, plain and cyclic objects, objects with throwing getters, revoked proxies,
// arrays (nested junk, sparse with length 2^32 − 1), objects posing as arrays ({ length: 2e9 }),
// typed arrays of every kind and DataViews — mixed with valid arguments so the calls reach past
// the first check. A seeded PRNG picks them, so a failure names a reproducible call.
//
// What it checks, after every call:
//   * no trap: nothing throws a WebAssembly.RuntimeError (`unreachable`, `memory access out of
//     bounds`) — a refusal is an ordinary Error;
//   * the instance still answers: a cheap known call (`envelope` of a fixed series, and
//     `checkPlanform` of a square) gives the result it gave on the fresh instance;
//   * no leak: when a refused call grew the wasm memory, repeating it must not grow it again;
//   * nothing stalls: a refusal takes under 2 s, any call under 20 s;
//   * clear refusals: every thrown value is an Error whose message names the field in backticks
//     (the core's "invalid value for `field`: … (allowed: …)" form) or names the problem
//     explicitly (a geometry, a parse position, a cap).
// The counts are printed at the end (WASM_HOSTILE_CALLS overrides the number of calls).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { prng } from './prng.mjs';
import { smallWing } from './real_wasm.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
// WASM_HOSTILE_PKG: another build to try (e.g. one of an older commit, to see this test fail there).
const PKG = process.env.WASM_HOSTILE_PKG || path.join(ROOT, 'www', 'pkg');
const CALLS = Number(process.env.WASM_HOSTILE_CALLS || 2500);
const SEED = Number(process.env.WASM_HOSTILE_SEED || 20);
const TIME_BUDGET_MS = 40_000;

async function loadReal() {
  const glue = path.join(PKG, 'wingbeat.js');
  const bin = path.join(PKG, 'wingbeat_bg.wasm');
  assert.ok(
    fs.existsSync(glue) && fs.existsSync(bin),
    'www/pkg is missing: run `bash scripts/build-web.sh www` first (npm test does)',
  );
  const m = await import(new URL(`file://${glue}`).href);
  const exports = m.initSync({ module: fs.readFileSync(bin) });
  return { m, exports };
}

const TYPED = [
  Int8Array,
  Uint8Array,
  Uint8ClampedArray,
  Int16Array,
  Uint16Array,
  Int32Array,
  Uint32Array,
  Float32Array,
  Float64Array,
  BigInt64Array,
  BigUint64Array,
  ...(typeof Float16Array === 'function' ? [Float16Array] : []),
];

const NUMBERS = [
  0,
  -0,
  1,
  -1,
  0.5,
  1.5,
  2,
  3,
  7,
  64,
  65,
  1000,
  2 ** 31,
  2 ** 32,
  2 ** 53,
  -(2 ** 53),
  1e300,
  -1e300,
  5e-324,
  NaN,
  Infinity,
  -Infinity,
  1e-300,
  0.01,
  25,
  100,
  10000,
];

/** One hostile value (`depth` bounds nesting). Each kind is labelled for the failure report. */
function hostile(r, depth = 0) {
  const pick = (xs) => xs[Math.floor(r() * xs.length)];
  const kinds = [
    () => ['undefined', undefined],
    () => ['null', null],
    () => {
      const n = pick(NUMBERS);
      return [`number ${Object.is(n, -0) ? '-0' : n}`, n];
    },
    () => {
      const n = (r() - 0.5) * 10 ** Math.floor(r() * 12);
      return [`number ${n}`, n];
    },
    () => ['boolean', r() < 0.5],
    () => ['symbol', Symbol('x')],
    () => ['bigint', pick([0n, 10n, 2n ** 64n, -1n])],
    () => ['function', () => 1],
    () => ['empty string', ''],
    () => {
      const s = pick([
        'csv',
        'json',
        'rms',
        'peak',
        'deg',
        'rad',
        '0',
        '1e308',
        'NaN',
        'null',
        '{}',
        '[]',
        '{"modes": []}',
        '[[0,0],[1,0],[1,1]]',
        'x_mm,y_mm\n0,0\n1,0\n1,1\n',
        't,alpha\n0,0\n0.01,1\n',
      ]);
      return [`string ${JSON.stringify(s)}`, s];
    },
    () => ['unicode string', '\u{1F98B}\uD800 wing \u0000 \u202E é' + '\uDFFF'.repeat(3)],
    () => {
      const n = pick([1e5, 1e6, 5e6, 4e7]);
      return [`string of ${n} characters`, 'x'.repeat(n)];
    },
    () => ['empty object', {}],
    () => ['object with junk keys', { a: 1, b: [1, 2], __proto__x: 'y', toString: 5 }],
    () => {
      const n = pick([2e9, 6e7, 2 ** 32 - 1, -1, NaN, 1.5, '5', 3]);
      return [`{ length: ${String(n)} }`, { length: n }];
    },
    () => ['{ 0: 1, length: 1 }', { 0: 1, length: 1 }],
    () => ['empty array', []],
    () => ['small numeric array', [1, 2, 3]],
    () => ['array of strings', ['1', '2', '3']],
    () => ['array of NaN', [NaN, Infinity]],
    () => [
      'outline-like array',
      [
        [0, 0],
        [10, 0],
        [10, -5],
        [0, -5],
      ],
    ],
    () => ['nested junk array', [[[[]]], { a: [null] }, 'x', 1]],
    () => {
      const a = [];
      a.length = 2 ** 32 - 1;
      return ['sparse array of length 2^32 - 1', a];
    },
    () => {
      const a = [];
      a.length = 6e7;
      return ['sparse array of length 6e7', a];
    },
    () => {
      const C = pick(TYPED);
      const n = Math.floor(r() * 20);
      const a = new C(n);
      return [`${C.name}(${n})`, a];
    },
    () => {
      const n = pick([0, 3, 64, 1e6, 3e6]);
      const a = new Float64Array(n).fill(pick([0, 1, NaN, Infinity, 1e300]));
      return [`Float64Array(${n}) filled`, a];
    },
    () => ['Uint32Array with big indices', new Uint32Array([0, 1, 4294967295])],
    () => ['DataView', new DataView(new ArrayBuffer(16))],
    () => ['ArrayBuffer', new ArrayBuffer(16)],
    () => [
      'cyclic object',
      (() => {
        const o = { a: 1 };
        o.self = o;
        return o;
      })(),
    ],
    () => [
      'object with throwing getter',
      {
        get length() {
          throw new Error('getter');
        },
        get x() {
          throw new Error('getter');
        },
      },
    ],
    () => [
      'array with throwing element getter',
      (() => {
        const a = [1, 2, 3];
        Object.defineProperty(a, 1, {
          get() {
            throw new Error('getter');
          },
        });
        return a;
      })(),
    ],
    () => [
      'revoked proxy',
      (() => {
        const p = Proxy.revocable([], {});
        p.revoke();
        return p.proxy;
      })(),
    ],
    () => [
      'proxy array that throws',
      new Proxy([1, 2, 3], {
        get() {
          throw new Error('trap');
        },
      }),
    ],
    () => ['fake Float64Array', Object.create(Float64Array.prototype)],
    () => [
      'typed array with a lying length',
      (() => {
        const a = new Float64Array(4);
        Object.defineProperty(a, 'length', { value: 2e9 });
        return a;
      })(),
    ],
    () => ['Date', new Date(0)],
    () => ['Map', new Map([[1, 2]])],
    () => [
      'object with toJSON',
      {
        toJSON() {
          return 'x'.repeat(1000);
        },
      },
    ],
    () => ['Object.create(null)', Object.create(null)],
  ];
  if (depth < 2) {
    kinds.push(() => {
      const [l, v] = hostile(r, depth + 1);
      return [`[${l}]`, [v]];
    });
    kinds.push(() => {
      const [l, v] = hostile(r, depth + 1);
      return [`{ k: ${l} }`, { duration_s: v, modes: v, planform_mm: v, stat: v }];
    });
  }
  return pick(kinds)();
}

/** Valid arguments per export, so that a call with one hostile argument gets past the others. */
function validArgs(wb) {
  const cfg = { ...wb.defaultConfig(), duration_s: 0.02, sample_rate_hz: 2000 };
  const square = [
    [0, 0],
    [10, 0],
    [10, -5],
    [0, -5],
  ];
  const fe = smallWing(wb, 0.01);
  const nModes = fe.n_modes;
  const series = new Float64Array(256).map((_, i) => Math.sin(i / 5));
  const qs = Array.from({ length: nModes }, () => series.slice(0, 64));
  const feCfg = { ...cfg, modes: fe.modes };
  const body = { nodes: fe.nodes, triangles: fe.triangles, strain_nodes: fe.strain_nodes };
  return {
    fe,
    valid: {
      version: [],
      planforms: [],
      wingParameters: [],
      materialPresets: [],
      defaultConfig: [],
      limits: [],
      parameters: [],
      media: [],
      bodyRateRanges: [],
      reproduceText: [],
      reproduce: [],
      parsePlanform: ['x_mm,y_mm\n0,0\n10,0\n10,-5\n0,-5\n', 'csv'],
      checkPlanform: [square],
      wingInput: [{ camber: 0.1 }, square],
      modalStrainAt: [body.nodes, body.triangles, body.strain_nodes, nModes, [5, -3]],
      strainField: [body.strain_nodes, nModes, qs, { stat: 'rms' }],
      modesFromJson: ['{"modes": [{"name": "m", "freq_hz": 50, "a": [[0,0],[0,0],[0,0]], "b": [0,0,0]}]}'],
      validateConfig: [cfg],
      simulate: [cfg],
      forceSeries: [cfg],
      anglesAt: [cfg, [0, 0.001, 0.002]],
      applyOverrides: [cfg, { gamma0: 0.1 }],
      kinematicsFromCsv: ['t,alpha\n0,0\n0.01,10\n0.02,0\n0.03,-10\n', { units: 'deg', flap_hz: 25 }],
      psd: [series, 1000, { segment_len: 64 }, 25],
      envelope: [series],
      spectra: [cfg, { segment_len: 32 }, 0],
      analyze: [cfg, { segment_len: 32 }, 0],
      sweep: [cfg, { param: 'gamma0', from: 0, to: 0.2, points: 2 }, () => {}],
      icMap: [cfg, { n_q: 2, n_qdot: 2 }],
      resonanceMap: [cfg, { from_hz: 20, to_hz: 30, points: 2 }, () => {}],
      feModes: [
        {
          planform_mm: [
            [0, 0],
            [0, -8],
            [30, -8],
            [30, 0],
          ],
          n_modes: 1,
          mesh_size_mm: 6,
        },
        0.01,
        undefined,
      ],
      senseRotation: [
        feCfg,
        body.nodes,
        body.triangles,
        body.strain_nodes,
        [0, 0, 1],
        { k_max: 2, samples_per_sensor: 8 },
        undefined,
      ],
      classifyRotation: [
        {
          n_modes: 1,
          mesh_size_mm: 5,
          grid_step_mm: 10,
          options: { duration_s: 0.3, discard_s: 0.1, rank: 5, kept_modes: [1], random_counts: [1], random_draws: 1 },
        },
        undefined,
      ],
    },
  };
}

/** Whether a thrown value is a clear refusal: an Error naming the field or the problem. */
function clear(e) {
  if (!(e instanceof Error) || typeof e.message !== 'string') return false;
  const m = e.message;
  return (
    /`[^`]+`/.test(m) ||
    /^(could not parse|invalid geometry|rendering failed|non-finite result|.* did not converge)/.test(m)
  );
}

test('every wasm export refuses hostile arguments by name, without trapping, dying or leaking', async (t) => {
  const { m: wb, exports } = await loadReal();
  const memory = exports.memory;
  const probeSeries = new Float64Array([3, 1, 4, 1, 5, 9, 2, 6]);
  const probeEnvelope = Array.from(wb.envelope(probeSeries)).join(',');
  const alive = () => {
    try {
      const e = Array.from(wb.envelope(probeSeries)).join(',');
      const ok =
        e === probeEnvelope &&
        wb.checkPlanform([
          [0, 0],
          [10, 0],
          [10, -5],
          [0, -5],
        ]).ok === true;
      return ok;
    } catch {
      return false;
    }
  };
  assert.ok(alive(), 'the probe call works on a fresh instance');

  const { valid } = validArgs(wb);
  // Every exported function, found at run time (a new export is fuzzed without editing this list).
  const skip = new Set(['default', 'initSync', 'start']);
  const fns = Object.keys(wb).filter(
    (k) => typeof wb[k] === 'function' && !skip.has(k) && !k.startsWith('__') && !/^[A-Z]/.test(k),
  );
  const classes = Object.keys(wb).filter((k) => typeof wb[k] === 'function' && /^[A-Z]/.test(k));
  const missing = fns.filter((k) => !(k in valid));
  assert.deepEqual(missing, [], 'every export has valid arguments in this test (add them for a new export)');
  // The class statics (WingView.create, createFromArrays, createSynthetic, colourMap): node has no
  // canvas, so these are called for their argument checks only (instances need a browser).
  /** @type {{ name: string, call: (...a: unknown[]) => unknown, arity: number, valid: unknown[] }[]} */
  const targets = fns.map((k) => ({
    name: k,
    call: (...a) => wb[k](...a),
    arity: Math.max(wb[k].length, valid[k].length),
    valid: valid[k],
  }));
  for (const c of classes) {
    for (const s of Object.getOwnPropertyNames(wb[c])) {
      if (['length', 'name', 'prototype', '__wrap'].includes(s) || typeof wb[c][s] !== 'function') continue;
      const f = wb[c][s];
      targets.push({ name: `${c}.${s}`, call: (...a) => f.apply(wb[c], a), arity: Math.max(f.length, 1), valid: [] });
    }
  }
  t.diagnostic(`${targets.length} exports: ${targets.map((x) => x.name).join(', ')}`);

  const r = prng(SEED);
  const counts = { calls: 0, returned: 0, refused: 0, traps: 0, dead: 0, leaks: 0, unclear: 0, slow: 0 };
  /** @type {string[]} */
  const problems = [];
  const started = Date.now();
  const describeCall = (name, labels) => `${name}(${labels.join(', ')})`;

  const invoke = async (target, args) => {
    try {
      let v = target.call(...args);
      if (v && typeof v.then === 'function') v = await v;
      return { ok: true, v };
    } catch (e) {
      return { ok: false, e };
    }
  };

  // Exports that run for seconds with their defaults (the paper report; the published
  // classification, about 10 s) are called once.
  const once = new Set(['reproduce', 'reproduceText', 'classifyRotation']);
  for (let i = 0; i < CALLS && Date.now() - started < TIME_BUDGET_MS; i++) {
    const target = targets[Math.floor(r() * targets.length)];
    if (once.has(target.name)) {
      if (target.done) continue;
      target.done = true;
    }
    const n = target.arity + (r() < 0.1 ? 1 : 0);
    const labels = [];
    const args = [];
    // Mostly one hostile argument among valid ones (reaches deep checks), sometimes all hostile.
    const allHostile = r() < 0.25 || target.valid.length === 0;
    const which = Math.floor(r() * n);
    for (let j = 0; j < n; j++) {
      if (!allHostile && j !== which && j < target.valid.length) {
        args.push(target.valid[j]);
        labels.push('valid');
      } else {
        const [l, v] = hostile(r);
        args.push(v);
        labels.push(l);
      }
    }
    const before = memory.buffer.byteLength;
    const t0 = Date.now();
    const res = await invoke(target, args);
    const took = Date.now() - t0;
    counts.calls++;
    const what = describeCall(target.name, labels);
    // A refusal is quick; a call that computes (feModes of the default wing) may take seconds,
    // within the core's work budgets; nothing may hang.
    if ((!res.ok && took > 2000) || (took > 20000 && !once.has(target.name))) {
      counts.slow++;
      problems.push(`SLOW ${what}: ${(took / 1000).toFixed(1)} s`);
    }
    if (res.ok) {
      counts.returned++;
    } else {
      counts.refused++;
      if (res.e instanceof WebAssembly.RuntimeError) {
        counts.traps++;
        problems.push(`TRAP ${what}: ${res.e.message}`);
      } else if (!clear(res.e)) {
        counts.unclear++;
        problems.push(
          `UNCLEAR ${what}: ${res.e instanceof Error ? `${res.e.name}: ${res.e.message}` : `threw ${typeof res.e}`}`.slice(
            0,
            400,
          ),
        );
      }
    }
    if (!alive()) {
      counts.dead++;
      problems.push(`DEAD after ${what}`);
      break; // nothing more can be learned from a dead instance
    }
    const grew = memory.buffer.byteLength - before;
    if (!res.ok && grew > 0) {
      // A refused call that grew memory: the same call again must not grow it further.
      const b2 = memory.buffer.byteLength;
      await invoke(target, args);
      await invoke(target, args);
      const grewAgain = memory.buffer.byteLength - b2;
      if (grewAgain > 0) {
        counts.leaks++;
        problems.push(
          `LEAK ${what}: +${(grew / 2 ** 20).toFixed(1)} MiB, then +${(grewAgain / 2 ** 20).toFixed(1)} MiB over two repeats`,
        );
      }
    }
  }
  const ms = Date.now() - started;
  t.diagnostic(
    `seed ${SEED}: ${counts.calls} calls in ${(ms / 1000).toFixed(1)} s — ${counts.returned} returned, ${counts.refused} refused; ` +
      `traps ${counts.traps}, dead instances ${counts.dead}, leaks ${counts.leaks}, unclear errors ${counts.unclear}, slow (refusal > 2 s or any call > 20 s) ${counts.slow}; ` +
      `wasm memory ${(memory.buffer.byteLength / 2 ** 20).toFixed(0)} MiB`,
  );
  for (const p of problems.slice(0, 40)) t.diagnostic(p);
  assert.ok(counts.calls >= Math.min(CALLS, 500), `at least 500 calls ran (${counts.calls})`);
  assert.deepEqual(
    { traps: counts.traps, dead: counts.dead, leaks: counts.leaks, unclear: counts.unclear, slow: counts.slow },
    { traps: 0, dead: 0, leaks: 0, unclear: 0, slow: 0 },
    problems.slice(0, 20).join('\n'),
  );
});

test('text arguments refuse non-strings by name (parsePlanform(12345, "csv") used to trap)', async () => {
  const { m: wb } = await loadReal();
  for (const [f, args, field] of [
    ['parsePlanform', [12345, 'csv'], 'parsePlanform.text'],
    ['parsePlanform', ['0,0\n1,0\n1,1\n', 7], 'parsePlanform.format'],
    ['modesFromJson', [{ modes: [] }], 'modesFromJson.text'],
    ['kinematicsFromCsv', [null, { units: 'deg', flap_hz: 25 }], 'kinematicsFromCsv.text'],
  ]) {
    assert.throws(
      () => wb[f](...args),
      (e) => e instanceof Error && !(e instanceof WebAssembly.RuntimeError) && e.message.includes(`\`${field}\``),
      `${f}: names ${field}`,
    );
  }
});

test('array arguments are length-checked before any copy ({ length: 2e9 } is refused, memory unchanged)', async () => {
  const { m: wb, exports } = await loadReal();
  const before = exports.memory.buffer.byteLength;
  for (let i = 0; i < 5; i++) {
    assert.throws(() => wb.modalStrainAt({ length: 2e9 }, [0, 1, 2], [0, 0, 0], 1, [0, 0]), /`nodes`/);
    assert.throws(() => wb.strainField({ length: 6e7 }, 1, [[1]], { stat: 'rms' }), /`strain_nodes`/);
    assert.throws(
      () => wb.senseRotation(wb.defaultConfig(), [0, 0, 0], [0, 0, 0], [0, 0, 0], { length: 6e7 }),
      /`body_rate`/,
    );
    const a = [];
    a.length = 2 ** 32 - 1;
    assert.throws(() => wb.psd(a, 100), /`psd.series`/);
  }
  assert.equal(exports.memory.buffer.byteLength, before, 'refused calls allocate nothing in wasm memory');
});

test('numbers are never coerced: "3", true and [5] are refused where a number is expected', async () => {
  const { m: wb } = await loadReal();
  const s = new Float64Array([1, 2, 3, 4, 5, 6]);
  for (const bad of ['3', true, [5], null]) {
    assert.throws(() => wb.modalStrainAt([], [], [], bad, [0, 0]), /`n_modes`/, String(bad));
    assert.throws(() => wb.psd(s, bad), /`psd\.sample_rate_hz`/, String(bad));
  }
  assert.throws(() => wb.envelope(['1', '2']), /`envelope\.series\[0\]`/);
  assert.throws(
    () => wb.sweep(wb.defaultConfig(), { param: 'gamma0', from: 0, to: 0.1, points: 2 }, 'not a function'),
    /`progress`/,
  );
});

test('a geometry the mesher cannot take is refused by checkPlanform and feModes alike', async () => {
  const { m: wb } = await loadReal();
  const outline = [
    [0, 0],
    [0, -5],
    [30, -5],
    [30, 0],
    [1e-300, 0],
  ];
  const check = wb.checkPlanform(outline);
  let feError = null;
  try {
    wb.feModes({ planform_mm: outline, n_modes: 1, mesh_size_mm: 3 }, 0, undefined);
  } catch (e) {
    feError = e;
  }
  assert.ok(!(feError instanceof WebAssembly.RuntimeError), `feModes must not trap: ${feError}`);
  assert.equal(check.ok, false, 'checkPlanform refuses the outline');
  assert.ok(feError instanceof Error, 'feModes refuses it too');
  assert.equal(feError.message, check.error, 'with the same message');
});
