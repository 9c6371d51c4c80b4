// Hostile URL queries (www/state.js parseQuery/parsePairs) and hostile postMessage payloads
// (www/embed-api.js checkEnvelope/paramPairs, the checks in front of the URL parser): random
// parameter names and values from a seeded PRNG — huge and non-finite numbers, every float
// syntax, repeated keys, unicode (emoji, lone surrogates, control and bidi characters), very long
// text, and for messages every JS type (BigInt, nested junk, huge arrays, cyclic objects, typed
// arrays, Maps). Checks: nothing throws; every value that is not taken is reported with the
// field's name (the key, shortened to 40 code points, never a lone surrogate or a control
// character) and never echoed; everything taken lies inside its range.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  parseQuery,
  parsePairs,
  defaults,
  NUMERIC,
  WING,
  ENUMS,
  PANELS,
  BODY_RATE,
  shortKey,
  MAX_PAIRS,
} from '../../www/state.js';
import { checkEnvelope, paramPairs, API_VERSION } from '../../www/embed-api.js';
import { prng } from './prng.mjs';

const KEYS = [
  ...NUMERIC.map((p) => p.key),
  ...WING.map((w) => w.key),
  ...ENUMS.map((e) => e.key),
  'panels',
  'embed',
  'exp',
  'outline',
  'planform',
  'body_rate',
  'body_axis',
];
const VALUES = [
  '',
  ' ',
  '0',
  '-0',
  '+1',
  '1e308',
  '1e-308',
  '1e999',
  '-1e999',
  'NaN',
  'Infinity',
  '-Infinity',
  '0x10',
  '1_000',
  '.5',
  '5.',
  '1e+2',
  '1E-2',
  '2.5e',
  '٣',
  '１',
  '0.1 ',
  '\t0.2',
  '1,2',
  'root',
  'fe',
  'paper',
  'z',
  'controls,numbers',
  '../../etc/passwd.csv',
  '//evil.example/x.json',
  'examples/planform-narrow.json',
  '<script>alert(1)</script>',
  '\u{1F98B}',
  '\uD800',
  '\u202Egamma',
  '\u0000',
  String(2 ** 53),
  String(Number.MAX_VALUE),
  '9'.repeat(400),
];

function randomKey(r) {
  const x = r();
  if (x < 0.6) return KEYS[Math.floor(r() * KEYS.length)];
  if (x < 0.7) return '\u{1F98B}'.repeat(1 + Math.floor(r() * 30)) + '\uD800';
  if (x < 0.8) return 'k'.repeat(1 + Math.floor(r() * 5000));
  if (x < 0.9)
    return ['__proto__', 'constructor', 'toString', 'hasOwnProperty', '', ' ', 'GAMMA0', 'gamma0 '][
      Math.floor(r() * 8)
    ];
  return String.fromCharCode(...Array.from({ length: 1 + Math.floor(r() * 10) }, () => Math.floor(r() * 0xffff)));
}

function randomValue(r) {
  const x = r();
  if (x < 0.5) return VALUES[Math.floor(r() * VALUES.length)];
  if (x < 0.8) return String((r() - 0.5) * 10 ** Math.floor(r() * 40 - 20));
  if (x < 0.9) return 'x'.repeat(Math.floor(r() * 1e5));
  return String.fromCharCode(...Array.from({ length: 1 + Math.floor(r() * 10) }, () => Math.floor(r() * 0xffff)));
}

/** Every accepted value lies in its range / among its choices. */
function assertInRange(state) {
  for (const p of [...NUMERIC, ...WING, BODY_RATE]) {
    const v = state[p.key];
    assert.ok(
      typeof v === 'number' && Number.isFinite(v) && v >= p.min && v <= p.max,
      `${p.key} = ${v} in [${p.min}, ${p.max}]`,
    );
  }
  for (const e of ENUMS) assert.ok(e.choices.includes(state[e.key]), `${e.key} = ${state[e.key]}`);
  assert.ok(Array.isArray(state.panels) && state.panels.every((p) => PANELS.includes(p)));
}

/** A rejected key is readable: no lone surrogate, no control character, at most 41 code points. */
function assertReadableKey(k) {
  assert.equal(typeof k, 'string');
  assert.ok(Array.from(k).length <= 41, `short key (${Array.from(k).length} code points)`);
  assert.ok(
    !/[\uD800-\uDBFF](?![\uDC00-\uDFFF])|(?<![\uD800-\uDBFF])[\uDC00-\uDFFF]/.test(k),
    `no lone surrogate in ${JSON.stringify(k)}`,
  );
  // biome-ignore lint/suspicious/noControlCharactersInRegex: the test looks for control characters on purpose
  assert.ok(!/[\u0000-\u001f\u007f-\u009f\u2028\u2029]/.test(k), `no control character in ${JSON.stringify(k)}`);
}

test('random hostile URL queries: nothing throws, every refusal names its key, accepted values are in range', () => {
  const r = prng(2020);
  let refusals = 0;
  for (let i = 0; i < 3000; i++) {
    const n = Math.floor(r() * 12);
    // URLSearchParams encodes (a lone surrogate becomes U+FFFD, as in a real URL)
    const sp = new URLSearchParams();
    for (let j = 0; j < n; j++) {
      const k = randomKey(r);
      sp.append(k, randomValue(r));
      if (r() < 0.15) sp.append(k, randomValue(r)); // a repeated key
    }
    // malformed escapes, empty names, a lone-surrogate escape
    const extra = r() < 0.1 ? '&%E0%A4%A&&&=x&a=%&%ED%A0%80=1' : '';
    const q = '?' + sp.toString() + extra;
    const { state, rejected } = parseQuery(q);
    assertInRange(state);
    refusals += rejected.length;
    const params = new URLSearchParams(q);
    const seen = new Map();
    for (const [k] of params) seen.set(k, (seen.get(k) || 0) + 1);
    for (const rj of rejected) {
      assertReadableKey(rj.key);
      assert.ok(typeof rj.why === 'string' && rj.why.length > 0 && rj.why.length < 400, rj.why);
      assert.ok(!/<script|x{50}/.test(rj.why), 'the value is never echoed');
    }
    // every repeated key is reported as repeated, by name
    for (const [k, c] of seen) {
      if (c > 1 && !['', undefined].includes(k))
        assert.ok(
          rejected.some((rj) => rj.key === shortKey(k) && /more than once/.test(rj.why)),
          `repeated ${JSON.stringify(k.slice(0, 20))}`,
        );
    }
  }
  assert.ok(refusals > 1000, `the generator produces refusals (${refusals})`);
});

test('URL values at and beyond the edges of every range, in every float syntax', () => {
  for (const p of [...NUMERIC, ...WING.filter((w) => w.key !== 'n_modes')]) {
    for (const [text, ok] of [
      [String(p.min), true],
      [String(p.max), true],
      [`${p.max}e0`, true],
      [`+${p.max}`, true],
      [String(p.max * (1 + 1e-12) + (p.max === 0 ? 1e-9 : 0)), false],
      [String(p.min - Math.max(Math.abs(p.min) * 1e-12, 1e-9)), false],
      ['1e999', false],
      ['-1e999', false],
      ['NaN', false],
      ['Infinity', false],
      ['0x1', false],
      ['1e9999', false],
    ]) {
      const { state, rejected } = parsePairs([[p.key, text]]);
      if (ok) {
        assert.deepEqual(rejected, [], `${p.key}=${text}`);
        assert.equal(state[p.key], Number(text));
      } else {
        assert.equal(rejected.length, 1, `${p.key}=${text} refused`);
        assert.equal(rejected[0].key, p.key);
        assert.match(rejected[0].why, /a number in \[/, 'names the range');
      }
    }
  }
});

test('names and values that are not text are refused by name, and the pair count is bounded', () => {
  const { rejected } = parsePairs(
    /** @type {any} */ ([
      [Symbol('s'), '1'],
      ['gamma0', 0.1],
      [
        'alpha0',
        {
          toString() {
            throw new Error('x');
          },
        },
      ],
      'junk',
      [1n, 2n],
    ]),
  );
  assert.equal(rejected.length, 5);
  assert.match(rejected[1].why, /expected text/);
  assert.equal(rejected[1].key, 'gamma0');
  const many = Array.from({ length: MAX_PAIRS + 50 }, (_, i) => [`k${i}`, '1']);
  const r2 = parsePairs(many);
  assert.equal(r2.rejected.length, MAX_PAIRS + 1, 'the first MAX_PAIRS are read, then one notice');
  assert.match(r2.rejected.at(-1).why, /more than 200 parameters/);
});

test('shortKey keeps whole code points and hides control characters', () => {
  assert.equal(shortKey('gamma0'), 'gamma0');
  const k = shortKey('\u{1F98B}'.repeat(50));
  assert.equal(Array.from(k).length, 41);
  assertReadableKey(k);
  assertReadableKey(shortKey('a\u0000b\u2028c'));
  assert.equal(shortKey(undefined), '(a undefined as a name)');
});

/** A random hostile message value (structured-clone-able, as postMessage delivers). */
function hostileValue(r, depth = 0) {
  const kinds = [
    () => undefined,
    () => null,
    () => NaN,
    () => Infinity,
    () => -0,
    () => 2 ** 53,
    () => 1e308,
    () => (r() - 0.5) * 100,
    () => true,
    () => 10n,
    () => '',
    () => randomValue(r),
    () => 'x'.repeat(2e6),
    () => [],
    () => new Array(1e6).fill('controls'),
    () => ['controls', 'numbers'],
    () => [1, 2],
    () => new Float64Array(8),
    () => new Map([['gamma0', 0.1]]),
    () => new Date(0),
    () => ({}),
    () => {
      const o = { a: 1 };
      o.self = o;
      return o;
    },
    () => Object.create(null),
  ];
  if (depth < 2)
    kinds.push(
      () => ({ gamma0: hostileValue(r, depth + 1), nested: [hostileValue(r, depth + 1)] }),
      () => [hostileValue(r, depth + 1)],
    );
  return kinds[Math.floor(r() * kinds.length)]();
}

test('random hostile postMessage payloads: nothing throws, every refusal names its field', () => {
  const r = prng(4242);
  let errors = 0;
  for (let i = 0; i < 3000; i++) {
    const d = {
      type: 'wingbeat:set',
      version: r() < 0.8 ? API_VERSION : hostileValue(r),
      id: r() < 0.7 ? i : hostileValue(r),
    };
    const env = checkEnvelope(d);
    if (env.error) {
      errors++;
      assert.ok(['version', 'id'].includes(env.error.field), env.error.field);
      assert.ok(env.error.message.startsWith(`${env.error.field}: `), env.error.message);
      assert.ok(env.error.message.length < 300, 'short message');
      continue;
    }
    assert.ok(env.id === null || typeof env.id === 'number' || (typeof env.id === 'string' && env.id.length <= 200));
    /** @type {any} */
    let params;
    if (r() < 0.3) params = hostileValue(r);
    else {
      params = {};
      const n = Math.floor(r() * 8);
      for (let j = 0; j < n; j++) params[randomKey(r)] = r() < 0.5 ? randomValue(r) : hostileValue(r);
    }
    const { pairs, errors: errs } = paramPairs(params);
    for (const e of errs) {
      assertReadableKey(e.field);
      assert.ok(e.message.startsWith(`${e.field}: `), e.message);
      assert.ok(e.message.length < 400, 'short message');
    }
    for (const [k, v] of pairs) assert.ok(typeof k === 'string' && typeof v === 'string' && v.length <= 1000);
    const parsed = parsePairs(pairs);
    assertInRange(parsed.state);
    for (const rj of parsed.rejected) assertReadableKey(rj.key);
    errors += errs.length;
  }
  assert.ok(errors > 500, `the generator produces refusals (${errors})`);
});

test('message envelopes and params that used to throw or mislead are refused by field', () => {
  // a BigInt or cyclic version made JSON.stringify throw inside the message handler
  for (const v of [
    10n,
    (() => {
      const o = {};
      o.o = o;
      return o;
    })(),
    Symbol.for('x').description,
    undefined,
  ]) {
    const env = checkEnvelope({ type: 'wingbeat:get', version: v });
    assert.equal(env.error.field, 'version');
    assert.match(env.error.message, /^version: this lab speaks version 1/);
  }
  assert.equal(checkEnvelope({ type: 'wingbeat:get', version: 1, id: 'x'.repeat(5000) }).error.field, 'id');
  assert.equal(checkEnvelope({ type: 'wingbeat:get', version: 1, id: 7 }).error, null);
  // names inherited from Object.prototype are unknown parameters, not "not settable"
  const p = paramPairs(JSON.parse('{"toString": 1, "constructor": "x", "__proto__": 2, "gamma0": 0.1}'));
  assert.deepEqual(p.errors, []);
  const parsed = parsePairs(p.pairs);
  assert.deepEqual(
    parsed.rejected.map((x) => [x.key, x.why]),
    [
      ['toString', 'unknown parameter'],
      ['constructor', 'unknown parameter'],
      ['__proto__', 'unknown parameter'],
    ],
  );
  assert.equal(parsed.state.gamma0, 0.1);
  // a non-finite number is "expected a finite number", not "expected a number"
  const nan = paramPairs({ gamma0: NaN, alpha0: Infinity, embed: 1 });
  assert.deepEqual(
    nan.errors.map((e) => e.field),
    ['gamma0', 'alpha0', 'embed'],
  );
  assert.match(nan.errors[0].message, /^gamma0: expected a finite number; got the number NaN/);
  // huge lists and non-plain objects
  assert.equal(paramPairs({ panels: new Array(1e6).fill('controls') }).errors[0].field, 'panels');
  for (const bad of [new Map([['gamma0', 0.1]]), [1, 2], new Float64Array(2), null, 'gamma0=0.1', {}]) {
    const r = paramPairs(bad);
    assert.equal(r.fatal, true);
    assert.equal(r.errors[0].field, 'params');
  }
  assert.equal(
    paramPairs(Object.fromEntries(Array.from({ length: 41 }, (_, i) => [`k${i}`, 1]))).errors[0].field,
    'params',
  );
  assert.deepEqual(paramPairs({ gamma0: 0.1, panels: ['controls', 'numbers'] }), {
    pairs: [
      ['gamma0', '0.1'],
      ['panels', 'controls,numbers'],
    ],
    errors: [],
    fatal: false,
  });
  assert.ok(defaults());
});
