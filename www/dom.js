// @ts-check
// DOM helpers for the lab's views: element creation, rich-text labels (sub/superscripts from
// www/format.js markup), the stylesheet loader, input-kind detection and visually hidden text.
import { parseRich } from './format.js';

const HERE = new URL('.', import.meta.url);

/**
 * el('button', { class: 'x', text: 'Run', onclick, 'aria-label': '…' }, ...children).
 * `text` sets textContent; `rich` renders markup with <sub>/<sup>; aria-*, data-*, role, for,
 * hidden, tabindex are attributes (false/null omit them); everything else is a property.
 * @template {keyof HTMLElementTagNameMap} K
 * @param {K} tag
 * @param {Record<string, any>} [props] values of any kind: properties, handlers, attributes
 * @param {...(Node | string | null | undefined | false)} children
 * @returns {HTMLElementTagNameMap[K]}
 */
export function el(tag, props = {}, ...children) {
  const e = document.createElement(tag);
  const asProps = /** @type {Record<string, unknown>} */ (/** @type {unknown} */ (e));
  for (const [k, v] of Object.entries(props)) {
    if (k === 'class') e.className = v;
    else if (k === 'text') e.textContent = v;
    else if (k === 'rich') e.append(rich(v));
    else if (k === 'style' && typeof v === 'string') e.style.cssText = v;
    else if (k.startsWith('aria-') || k.startsWith('data-') || ['role', 'for', 'hidden', 'tabindex', 'title', 'scope', 'colspan'].includes(k)) {
      if (v !== false && v != null) e.setAttribute(k, v === true ? '' : String(v));
    } else asProps[k] = v;
  }
  for (const c of children) if (c != null && c !== false) e.append(c);
  return e;
}

/**
 * A DocumentFragment for rich markup ("f_d", "kg^½·m"): text nodes and <sub>/<sup>.
 * @param {string} s
 */
export function rich(s) {
  const f = document.createDocumentFragment();
  for (const r of parseRich(s)) {
    if (r.kind === 'normal') f.append(r.text);
    else f.append(el(/** @type {'sub' | 'sup'} */ (r.kind), { text: r.text }));
  }
  return f;
}

/**
 * Replaces an element's content by rich markup.
 * @param {Element} node
 * @param {string} s
 */
export function setRich(node, s) {
  node.replaceChildren(rich(s));
}

/** Text only for assistive technology (visually hidden). */
/**
 * @param {keyof HTMLElementTagNameMap} [tag]
 * @param {Record<string, any>} [props]
 */
export function srOnly(tag = 'p', props = {}) {
  return el(tag, { ...props, class: `wl-sr ${props.class || ''}`.trim() });
}

/** True on devices whose main pointer is coarse (touch): views say "tap" instead of "hover". */
export function isTouch() {
  return typeof matchMedia === 'function' && matchMedia('(pointer: coarse)').matches;
}

/** Adds the lab's stylesheets once per document. */
export function ensureStyles() {
  for (const href of ['vendor/uPlot.min.css', 'style.css']) {
    const url = new URL(href, HERE).href;
    if (![...document.querySelectorAll('link[rel=stylesheet]')].some((l) => /** @type {HTMLLinkElement} */ (l).href === url)) {
      document.head.append(el('link', { rel: 'stylesheet', href: url }));
    }
  }
}

/** A labelled <select> from [value, text] pairs. */
export function select(id, options, value, props = {}) {
  const s = el('select', { id, ...props });
  for (const [v, t] of options) s.append(el('option', { value: v, text: t }));
  if (value != null) s.value = value;
  return s;
}
