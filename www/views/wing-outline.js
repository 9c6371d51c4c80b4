// @ts-check
// The Wing panel's outline editor (views/wing.js): the outline drawn as SVG (drag a point with a
// pointer), the selected point's number, x and y (exact values by keyboard), "Add point" /
// "Remove point", and the live check of the outline by the core (checkPlanform), which also
// gives the automatic element size. Edits the panel's draft (`form`); never the store.
import { el } from '../dom.js';
import { fmt, errorText } from '../format.js';
import { outlineBox, insertMidpoint, editedLabel } from '../wingform.js';

const NS = 'http://www.w3.org/2000/svg';

/**
 * @typedef {{ params: Record<string, number>, points: [number, number][] | null, outline: string, source: string, label: string, planform: string }} WingDraft
 * @typedef {{ draft: WingDraft, selected: number, dirty: boolean }} WingForm the draft, the selected point, whether the draft differs from the wing in use
 */

/**
 * @param {import('../lab.js').ViewContext} ctx
 * @param {WingForm} form
 * @param {{ say: (text: string, bad?: boolean) => void, onOwn: () => void, onChecked: () => void }} on
 *   `onOwn` when an outline becomes the user's own by an edit, `onChecked` after each check
 */
export function outlineEditor(ctx, form, on) {
  const { store, engine, id } = ctx;
  const svg = document.createElementNS(NS, 'svg');
  svg.setAttribute('class', 'wl-outline-svg');
  svg.setAttribute('role', 'img');
  svg.setAttribute('aria-labelledby', id('wing-svg-desc'));
  const svgDesc = el('p', { class: 'wl-sr', id: id('wing-svg-desc') });
  const poly = document.createElementNS(NS, 'polygon');
  poly.setAttribute('class', 'wl-outline-poly');
  svg.append(poly);
  const dots = document.createElementNS(NS, 'g');
  svg.append(dots);
  const toSvg = (p) => [p[0], -p[1]];

  /** A cross at the strain point of the wing in use (the chosen one, else the FE result's), when shown; its words. */
  const strainCross = (scale) => {
    const st = store.get();
    const sp = !form.dirty && st.modes === 'fe' && st.fe ? st.strain_point || st.fe.strain_point_mm : null;
    if (!sp) return '';
    const [x, y] = toSvg(sp);
    const r = 0.025 * scale;
    const cross = document.createElementNS(NS, 'path');
    cross.setAttribute('d', `M${x - r},${y - r}L${x + r},${y + r}M${x - r},${y + r}L${x + r},${y - r}`);
    cross.setAttribute('class', 'wl-outline-sp');
    cross.setAttribute('stroke-width', String(0.008 * scale));
    dots.append(cross);
    return ` The cross is the strain point (${fmt(sp[0], 4)}, ${fmt(sp[1], 4)}) mm.`;
  };

  const draw = () => {
    const pts = form.draft.points;
    dots.replaceChildren();
    if (!pts || !pts.length) {
      poly.setAttribute('points', '');
      svgDesc.textContent = 'No outline to draw (this wasm build does not list the built-in outlines).';
      check();
      syncPointInputs();
      return;
    }
    const { viewBox, w, h, scale } = outlineBox(pts);
    svg.setAttribute('viewBox', viewBox);
    poly.setAttribute('points', pts.map((p) => toSvg(p).join(',')).join(' '));
    poly.setAttribute('stroke-width', String(0.006 * scale));
    pts.forEach((p, i) => {
      const c = document.createElementNS(NS, 'circle');
      const [x, y] = toSvg(p);
      c.setAttribute('cx', String(x));
      c.setAttribute('cy', String(y));
      c.setAttribute('r', String((i === form.selected ? 0.022 : 0.014) * scale));
      c.setAttribute('class', i === form.selected ? 'wl-pt wl-pt-sel' : 'wl-pt');
      c.dataset.i = String(i);
      dots.append(c);
    });
    const spText = strainCross(scale);
    svgDesc.textContent = `Outline of ${pts.length} points, span ${fmt(w, 4)} mm, chord ${fmt(h, 4)} mm; point ${form.selected + 1} selected. Drag a point to move it, or use the point fields below.${spText}`;
    check();
    syncPointInputs();
  };

  // ---- dragging ----
  const svgPoint = (ev) => {
    const ctm = svg.getScreenCTM();
    if (!ctm) return null;
    const p = new DOMPoint(ev.clientX, ev.clientY).matrixTransform(ctm.inverse());
    return [Number(p.x.toFixed(3)), Number((-p.y).toFixed(3))];
  };
  let dragging = -1;
  svg.addEventListener('pointerdown', (ev) => {
    const t = /** @type {Element} */ (ev.target);
    if (!(t instanceof SVGCircleElement) || !form.draft.points) return;
    dragging = Number(t.dataset.i);
    form.selected = dragging;
    svg.setPointerCapture(ev.pointerId);
    ev.preventDefault();
    draw();
  });
  svg.addEventListener('pointermove', (ev) => {
    if (dragging < 0 || !form.draft.points) return;
    const p = svgPoint(ev);
    if (!p) return;
    form.draft.points[dragging] = /** @type {[number, number]} */ (p);
    edited();
  });
  const endDrag = () => {
    dragging = -1;
  };
  svg.addEventListener('pointerup', endDrag);
  svg.addEventListener('pointercancel', endDrag);

  // ---- the selected point by keyboard ----
  const idxIn = el('input', { type: 'number', id: id('wing-pt'), min: 1, step: 1, 'data-wing': 'point' });
  const xIn = el('input', { type: 'number', id: id('wing-x'), step: 0.1, 'data-wing': 'x' });
  const yIn = el('input', { type: 'number', id: id('wing-y'), step: 0.1, 'data-wing': 'y' });
  const syncPointInputs = () => {
    const pts = form.draft.points || [];
    idxIn.max = String(Math.max(1, pts.length));
    idxIn.value = String(form.selected + 1);
    const p = pts[form.selected];
    xIn.value = p ? String(p[0]) : '';
    yIn.value = p ? String(p[1]) : '';
  };
  idxIn.addEventListener('change', () => {
    const n = form.draft.points ? form.draft.points.length : 0;
    const v = Math.round(Number(idxIn.value));
    if (n && Number.isFinite(v)) form.selected = Math.min(n, Math.max(1, v)) - 1;
    draw();
  });
  for (const [inp, c] of /** @type {[HTMLInputElement, number][]} */ ([
    [xIn, 0],
    [yIn, 1],
  ])) {
    inp.addEventListener('change', () => {
      const v = Number(inp.value);
      if (!form.draft.points || inp.value.trim() === '' || !Number.isFinite(v)) {
        inp.setAttribute('aria-invalid', 'true');
        return;
      }
      inp.removeAttribute('aria-invalid');
      form.draft.points[form.selected][c] = v;
      edited();
    });
  }
  const addBtn = el('button', {
    type: 'button',
    text: 'Add point',
    'data-wing': 'add',
    title: 'Insert a point halfway to the next one',
  });
  addBtn.addEventListener('click', () => {
    const pts = form.draft.points;
    if (!pts) return;
    insertMidpoint(pts, form.selected);
    form.selected += 1;
    edited();
  });
  const delBtn = el('button', { type: 'button', text: 'Remove point', 'data-wing': 'remove' });
  delBtn.addEventListener('click', () => {
    const pts = form.draft.points;
    if (!pts || pts.length <= 3) return on.say('An outline needs at least 3 points.', true);
    pts.splice(form.selected, 1);
    form.selected = Math.min(form.selected, pts.length - 1);
    edited();
  });
  const edited = () => {
    const draft = form.draft;
    if (draft.source !== 'edited') {
      draft.source = 'edited';
      draft.label = editedLabel(draft.label);
      draft.planform = '';
      on.onOwn();
    }
    form.dirty = true;
    draw();
  };
  const pointsRow = el(
    'div',
    { class: 'wl-wing-pts' },
    el('span', { class: 'wl-pair' }, el('label', { for: id('wing-pt'), text: 'Point' }), idxIn),
    el('span', { class: 'wl-pair' }, el('label', { for: id('wing-x'), text: 'x (mm)' }), xIn),
    el('span', { class: 'wl-pair' }, el('label', { for: id('wing-y'), text: 'y (mm)' }), yIn),
    addBtn,
    delBtn,
  );

  // ---- the core's check ----
  const checkEl = el('p', { class: 'wl-note', role: 'status', 'data-wing': 'check' });
  let autoMesh = NaN;
  const check = () => {
    const pts = form.draft.points;
    if (!pts || !engine.ready) {
      checkEl.textContent = '';
      return;
    }
    let r;
    try {
      r = engine.checkPlanform(pts);
    } catch (e) {
      r = { ok: false, error: errorText(e) };
    }
    checkEl.classList.toggle('wl-bad', !r.ok);
    if (!r.ok) {
      checkEl.textContent = `Outline not valid: ${r.error}`;
      autoMesh = NaN;
    } else if (r.area_mm2 != null) {
      autoMesh = r.default_mesh_size_mm;
      checkEl.textContent = `Valid outline: area ${fmt(r.area_mm2, 4)} mm², span ${fmt(r.span_mm, 4)} mm, chord ${fmt(r.chord_mm, 4)} mm; automatic element size ${fmt(r.default_mesh_size_mm, 3)} mm.`;
    } else checkEl.textContent = '';
    on.onChecked();
  };

  return {
    svg,
    svgDesc,
    pointsRow,
    checkEl,
    draw,
    /** The automatic element size of the outline as last checked (mm), NaN when not valid. */
    autoMesh: () => autoMesh,
  };
}
