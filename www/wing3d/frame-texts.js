// @ts-check
// The words of a drawn frame of the 3-D panel (www/wing3d/panel.js): the status line, the
// exaggeration, the run's largest deflection, the colour legend, the note on the mode set and the
// screen-reader summary, from the frame's legend (WingView.set_frame's, or the worker's answer
// when the view draws in a worker). What each says is texts.js; this writes them.
import { rich } from '../dom.js';
import { fmt } from '../format.js';
import * as T from './texts.js';

/** Sets `e`'s text only when it differs (an unchanged text costs no layout or paint). */
export function setText(/** @type {HTMLElement} */ e, /** @type {string} */ t) {
  if (e.textContent !== t) e.textContent = t;
}

/**
 * @param {import('./panel.js').Wing3dPanel} p
 * @param {any} lg the frame's legend
 * @param {number[]} ang [α, β, γ] rad
 * @param {number} ex exaggeration
 * @param {number} t s
 * @param {number} nModes
 */
export function writeFrameTexts(p, lg, ang, ex, t, nModes) {
  const s = p.store.get();
  const { dom } = p;
  const view = p.view;
  const fe = /** @type {any} */ (p.fe);
  const isFe = s.modes === 'fe';
  const d = lg.max_deflection_m;
  dom.box.dataset.modes = String(nModes);
  setText(dom.exagText, `×${fmt(ex, 3)}`);
  dom.exag.setAttribute('aria-valuetext', `deflection drawn ${fmt(ex, 3)} times true scale`);
  setText(dom.status, T.statusLine(view.backend(), view.triangles(), ang, isFe, d, ex));
  const deflText = T.deflectionText(p.runDeflection, isFe, fe.nodes);
  if (dom.defl.dataset.text !== deflText) {
    dom.defl.dataset.text = deflText;
    if (isFe) dom.defl.textContent = deflText;
    else dom.defl.replaceChildren(rich(deflText));
  }
  p.drawLegend(lg, isFe, () => view.legend_stops(), p.fields.legendInfo());
  const wingName = s.wing && s.wing.label ? s.wing.label : 'synthetic Manduca-like outline, not digitised';
  const noteText = T.noteText(isFe, wingName, fe.n_nodes, nModes);
  if (dom.note.dataset.text !== noteText) {
    dom.note.dataset.text = noteText;
    dom.note.replaceChildren(rich(noteText));
  }
  setText(dom.summary, T.summaryText(t, ang, d, isFe, p.runDeflection, dom.legendText.textContent || ''));
}
