// @ts-check
// DOM helpers for the lab's views: element creation, rich-text labels (sub/superscripts from
// www/format.js markup), the shadow root's stylesheets, the focused element inside a shadow
// root, input-kind detection and visually hidden text.
import { parseRich } from './format.js';
import { WWW as HERE } from './base.js';

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
    else if (
      k.startsWith('aria-') ||
      k.startsWith('data-') ||
      ['role', 'for', 'hidden', 'tabindex', 'title', 'scope', 'colspan'].includes(k)
    ) {
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

/** @type {CSSStyleSheet | null} the shadow roots' shared base sheet (made once) */
let baseSheet = null;
/** The element's stylesheets, relative to this file (so they load from the lab's origin). */
export const STYLESHEETS = ['vendor/uPlot.min.css', 'style.css'];

/**
 * Puts the lab's stylesheets into a shadow root as <link> elements (url()s in them resolve
 * against their own URL, on the lab's host), after a tiny base sheet (adopted, so no inline
 * <style> for a page's CSP to refuse) that makes the host a block and keeps `.wl-root`
 * invisible until both have loaded, so the first paint is never unstyled. Resolves when they
 * have loaded or failed.
 * @param {ShadowRoot} root
 * @returns {Promise<void>}
 */
export function shadowStyles(root) {
  const BASE =
    ':host { display: block; } :host([hidden]) { display: none; } .wl-root[data-css=loading] { visibility: hidden; }';
  // A constructed sheet (CSSOM) is not an inline <style>, so a page's CSP needs no 'unsafe-inline'.
  if (
    !baseSheet &&
    typeof CSSStyleSheet === 'function' &&
    'replaceSync' in CSSStyleSheet.prototype &&
    'adoptedStyleSheets' in root
  ) {
    baseSheet = new CSSStyleSheet();
    baseSheet.replaceSync(BASE);
  }
  if (baseSheet) root.adoptedStyleSheets = [baseSheet];
  else root.append(el('style', { text: BASE }));
  return Promise.all(
    STYLESHEETS.map(
      (href) =>
        new Promise((resolve) => {
          const link = el('link', { rel: 'stylesheet', href: new URL(href, HERE).href });
          link.addEventListener('load', resolve, { once: true });
          link.addEventListener('error', resolve, { once: true });
          root.append(link);
        }),
    ),
  ).then(() => undefined);
}

/**
 * The focused element within the tree that holds `node` (its shadow root or the document):
 * inside a shadow root `document.activeElement` is only the host.
 * @param {Node} node
 * @returns {Element | null}
 */
export function activeIn(node) {
  const r = /** @type {Document | ShadowRoot} */ (node.getRootNode());
  return r && 'activeElement' in r ? r.activeElement : document.activeElement;
}

/** A labelled <select> from [value, text] pairs. */
export function select(id, options, value, props = {}) {
  const s = el('select', { id, ...props });
  for (const [v, t] of options) s.append(el('option', { value: v, text: t }));
  if (value != null) s.value = value;
  return s;
}
