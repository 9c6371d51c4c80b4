// The scanner behind scripts/code-shape.mjs (the size limits of ARCHITECTURE.md): it must find
// every function with its true length, see closures, and not be fooled by braces in strings,
// chars, raw strings or comments.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { jsFunctions, rustFunctions } from '../../scripts/code-shape.mjs';

test('rust functions are measured from the fn line to the closing brace', () => {
  const src = [
    'fn a() {', // 1
    '    let s = "}}} {";', // 2
    "    let c = '}';", // 3
    '    let r = r#"} { }"#;', // 4
    '    // } a comment brace', // 5
    '    /* { nested /* } */ } */', // 6
    '    if x { y } else { z }', // 7
    '}', // 8
    'pub(crate) fn b<T: Fn() -> u8>(x: T) -> Vec<u8> where T: Copy {', // 9
    '    vec![x()]', // 10
    '}', // 11
    'trait T { fn decl(&self); fn with_body(&self) -> u8 { 1 } }', // 12
    "fn lifetimes<'a>(x: &'a str) -> &'a str {", // 13
    '    x', // 14
    '}', // 15
  ].join('\n');
  const fns = rustFunctions(src);
  assert.deepEqual(
    fns.map((f) => [f.name, f.line + 1, f.lines]),
    [
      ['a', 1, 8],
      ['b', 9, 3],
      ['with_body', 12, 1],
      ['lifetimes', 13, 3],
    ],
  );
});

test('javascript functions: lengths, names, and closures (a function holding another)', () => {
  const src = [
    'export function outer() {', // 1
    '  const inner = () => {', // 2
    '    return 1;', // 3
    '  };', // 4
    '  return inner;', // 5
    '}', // 6
    '// long: a reason', // 7
    'const flat = function () {', // 8
    '  return "{";', // 9
    '};', // 10
    'const obj = { method() { return 2; } };', // 11
  ].join('\n');
  const fns = jsFunctions(src);
  const byName = Object.fromEntries(fns.map((f) => [f.name, f]));
  assert.equal(byName.outer.lines, 6);
  assert.equal(byName.outer.closure, true);
  assert.equal(byName.inner.lines, 3);
  assert.equal(byName.inner.closure, false);
  assert.equal(byName.flat.line + 1, 8);
  assert.equal(byName.flat.lines, 3);
  assert.equal(byName.method.lines, 1);
  assert.equal(fns.length, 4);
});
