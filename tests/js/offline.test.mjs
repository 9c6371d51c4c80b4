// www/offline.js: the opt-outs (URL parameter, meta tag, localStorage) decided without a browser.
// Run: node --test tests/js/offline.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { offlineOptOut, OFFLINE_STORAGE_KEY } from '../../www/offline.js';

function store(init = {}) {
  const m = new Map(Object.entries(init));
  return {
    getItem: (k) => (m.has(k) ? m.get(k) : null),
    setItem: (k, v) => {
      m.set(k, String(v));
    },
    removeItem: (k) => {
      m.delete(k);
    },
    m,
  };
}

test('on by default; ?offline=0 turns it off and is remembered; ?offline=1 forgets it', () => {
  const s = store();
  assert.equal(offlineOptOut({ urls: ['http://127.0.0.1:8080/index.html?alpha0=0.5'], meta: null, storage: s }), '');
  assert.match(
    offlineOptOut({
      urls: ['http://127.0.0.1:8080/index.html?alpha0=0.5', 'http://127.0.0.1:8080/index.html?offline=0'],
      meta: null,
      storage: s,
    }),
    /offline=0/,
  );
  assert.equal(s.m.get(OFFLINE_STORAGE_KEY), 'off');
  assert.match(offlineOptOut({ urls: ['http://127.0.0.1:8080/'], meta: null, storage: s }), /localStorage/);
  assert.equal(offlineOptOut({ urls: ['http://127.0.0.1:8080/?offline=1'], meta: null, storage: s }), '');
  assert.equal(s.m.has(OFFLINE_STORAGE_KEY), false);
});

test('the host page meta tag turns it off; storage that throws is not fatal', () => {
  assert.match(offlineOptOut({ urls: ['https://x.example/'], meta: ' OFF ', storage: null }), /meta/);
  assert.equal(offlineOptOut({ urls: ['https://x.example/'], meta: 'on', storage: null }), '');
  const bad = {
    getItem() {
      throw new Error('denied');
    },
    setItem() {
      throw new Error('denied');
    },
    removeItem() {
      throw new Error('denied');
    },
  };
  assert.equal(offlineOptOut({ urls: ['https://x.example/'], meta: null, storage: bad }), '');
  assert.match(offlineOptOut({ urls: ['https://x.example/?offline=0'], meta: null, storage: bad }), /offline=0/);
  assert.equal(
    offlineOptOut({ urls: ['not a url'], meta: null, storage: store({ [OFFLINE_STORAGE_KEY]: 'off' }) }).length > 0,
    true,
  );
});
