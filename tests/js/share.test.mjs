// The share fragment (www/share.js): deflate-raw + base64url round trip, versioning and the
// reasons given when a fragment cannot be restored. Run: node --test tests/js/share.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { encodeShare, decodeShare, fragmentValue, checkPoints, SHARE_VERSION } from '../../www/share.js';

test('round trip of an outline and a kinematics table', async () => {
  const outline = Array.from({ length: 200 }, (_, i) => [Math.cos(i / 30) * 20 + 20, Math.sin(i / 30) * 5 - 5]);
  const kin = { flap_freq_hz: 25, alpha: { kind: 'sampled', values: Array.from({ length: 64 }, (_, i) => Math.sin(i / 10)) } };
  const s = await encodeShare({ outline, kin });
  assert.match(s, /^[A-Za-z0-9_-]+$/);
  assert.ok(s.length < JSON.stringify({ outline, kin }).length, 'compressed');
  const back = await decodeShare(s);
  assert.equal(back.v, SHARE_VERSION);
  assert.deepEqual(back.outline, outline);
  assert.deepEqual(back.kin, kin);
});

test('a damaged, foreign or future fragment is refused with a reason', async () => {
  const good = await encodeShare({ a: 1 });
  await assert.rejects(decodeShare(good.slice(0, good.length - 4)), /compressed state|JSON/);
  await assert.rejects(decodeShare('not base64!'), /base64url/);
  await assert.rejects(decodeShare('AAAA'), /compressed state|JSON/);
  const future = await encodeShare({ a: 1 });
  const obj = await decodeShare(future);
  assert.equal(obj.a, 1);
  // version 2 written by hand
  const cs = new Blob([JSON.stringify({ v: 2 })]).stream().pipeThrough(new CompressionStream('deflate-raw'));
  const bytes = new Uint8Array(await new Response(cs).arrayBuffer());
  const b64 = Buffer.from(bytes).toString('base64url');
  await assert.rejects(decodeShare(b64), /version 2/);
});

test('fragmentValue and checkPoints', () => {
  assert.equal(fragmentValue('#s=abc-_'), 'abc-_');
  assert.equal(fragmentValue('#x=abc'), null);
  assert.equal(fragmentValue(''), null);
  assert.deepEqual(checkPoints([[0, 0], [1, 0], [1, 1]]), [[0, 0], [1, 0], [1, 1]]);
  assert.throws(() => checkPoints([[0, 0], [1, 0]]), /outline: expected 3/);
  assert.throws(() => checkPoints([[0, 0], [1, 0], [1, 'x']]), /outline\[2\]/);
});
