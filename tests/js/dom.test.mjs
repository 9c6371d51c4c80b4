// DOM helpers (www/dom.js) against a minimal fake document: attributes vs properties, rich
// labels as <sub>/<sup>, touch detection, the focused element inside a shadow root.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';

class FakeNode {
  constructor(tag) {
    this.tagName = tag.toUpperCase();
    this.attrs = {};
    this.children = [];
    this.textContent = '';
  }
  setAttribute(k, v) {
    this.attrs[k] = String(v);
  }
  getAttribute(k) {
    return this.attrs[k] ?? null;
  }
  append(...cs) {
    for (const c of cs) this.children.push(...(c instanceof FakeFragment ? c.children : [c]));
  }
  replaceChildren(...cs) {
    this.children = [];
    this.append(...cs);
  }
}
class FakeFragment extends FakeNode {}

let dom;
before(async () => {
  globalThis.document = {
    createElement: (t) => new FakeNode(t),
    createDocumentFragment: () => new FakeFragment('#fragment'),
    querySelectorAll: () => [],
    head: new FakeNode('head'),
  };
  globalThis.matchMedia = (q) => ({ matches: q === '(pointer: coarse)' && globalThis.__coarse === true });
  dom = await import('../../www/dom.js');
});

const text = (n) => (typeof n === 'string' ? n : n.textContent + n.children.map(text).join(''));

test('el: class, text, aria/data/role as attributes, false/null omitted, other keys as properties', () => {
  const click = () => {};
  const b = dom.el(
    'button',
    {
      class: 'x y',
      text: 'Run',
      'aria-pressed': false,
      'data-k': 3,
      role: 'img',
      hidden: true,
      onclick: click,
      type: 'button',
    },
    'tail',
    null,
  );
  assert.equal(b.className, 'x y');
  assert.equal(b.textContent, 'Run');
  assert.equal(b.getAttribute('aria-pressed'), null);
  assert.equal(b.getAttribute('data-k'), '3');
  assert.equal(b.getAttribute('role'), 'img');
  assert.equal(b.getAttribute('hidden'), '');
  assert.equal(b.onclick, click);
  assert.equal(b.type, 'button');
  assert.deepEqual(b.children, ['tail']);
});

test('rich: markup becomes text and <sub>/<sup> elements, no caret left', () => {
  const f = dom.rich('q (kg^½·m), f_d, γ_{xy}');
  const kinds = f.children.map((c) => (typeof c === 'string' ? 'text' : c.tagName));
  assert.deepEqual(kinds, ['text', 'SUP', 'text', 'SUB', 'text', 'SUB']);
  assert.equal(f.children.map(text).join(''), 'q (kg½·m), fd, γxy');
  const p = dom.el('p', { rich: 'T_{beat}' });
  assert.equal(p.children[1].tagName, 'SUB');
  assert.equal(p.children[1].textContent, 'beat');
});

test('srOnly, select, isTouch', () => {
  assert.equal(dom.srOnly('p', { id: 'a' }).className, 'wl-sr');
  const s = dom.select(
    'id1',
    [
      ['1', 'one'],
      ['2', 'two'],
    ],
    '2',
  );
  assert.equal(s.children.length, 2);
  assert.equal(s.value, '2');
  globalThis.__coarse = false;
  assert.equal(dom.isTouch(), false);
  globalThis.__coarse = true;
  assert.equal(dom.isTouch(), true);
});

test('activeIn: the focused element of the tree holding a node (shadow root or document)', () => {
  const inner = new FakeNode('input');
  const shadow = { activeElement: inner };
  const node = new FakeNode('div');
  node.getRootNode = () => shadow;
  assert.equal(dom.activeIn(node), inner);
  const page = new FakeNode('button');
  globalThis.document.activeElement = page;
  const loose = new FakeNode('span');
  loose.getRootNode = () => loose; // not in a document: falls back to document.activeElement
  assert.equal(dom.activeIn(loose), page);
});
