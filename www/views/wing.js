// @ts-check
// Wing panel: your own wing. Pick a built-in outline or load one from a file (the CLI's CSV
// `x_mm,y_mm` or JSON `[[x, y], …]`), edit it (drag points, add / remove, exact x and y by
// keyboard; checked live by the core's checkPlanform), set camber, clamp, material (with the
// paper's presets), element size (0 = automatic) and the number of modes (1–8), then "Compute
// modes": the solve runs in the worker with progress and Cancel while the wing in use stays.
// The same file input reads a `wingbeat modes` JSON document (import); "Export modes JSON"
// writes the wing in use in that format (for `wingbeat simulate --modes`).
// Reads and writes the store; calls ctx.engine for the wasm helpers (never wasm itself).
import { WING, OUTLINE_IDS, customWing } from '../state.js';
import { el, activeIn } from '../dom.js';
import { fmt, errorText } from '../format.js';
import { download } from '../export.js';

export const title = 'Wing';

/** The paper's two materials, used when the wasm build lacks materialPresets(). */
const FALLBACK_PRESETS = [
  { id: 'paper-frequencies', label: 'Paper, frequencies (E = 13.11 GPa)', e_pa: 1.311e10, rho: 860, nu: 0.3, thickness_um: 81 },
  { id: 'paper-as-printed', label: 'Paper, as printed (E = 10 MPa)', e_pa: 1e7, rho: 860, nu: 0.3, thickness_um: 81 },
];

/** How each wing parameter is shown: a display unit and scale (E in GPa), the input step. */
const SHOW = {
  camber: { unit: 'fraction of chord', scale: 1, step: 0.01 },
  clamp: { unit: 'mm, 0 = root edge', scale: 1, step: 0.1 },
  e_pa: { unit: 'GPa', scale: 1e-9, step: 0.01 },
  rho: { unit: 'kg/m³', scale: 1, step: 1 },
  nu: { unit: '', scale: 1, step: 0.01 },
  thickness_um: { unit: 'µm', scale: 1, step: 0.1 },
  mesh_mm: { unit: 'mm, 0 = automatic', scale: 1, step: 0.05 },
  n_modes: { unit: '', scale: 1, step: 1 },
};
const LABEL = {
  camber: 'Camber',
  clamp: 'Clamp strip',
  e_pa: 'Young’s modulus E',
  rho: 'Density ρ',
  nu: 'Poisson’s ratio ν',
  thickness_um: 'Thickness',
  mesh_mm: 'Element size',
  n_modes: 'Modes',
};

/** Rounds to ~12 significant digits (GPa ↔ Pa without 13.110000000000001). */
const clean = (v) => Number(Number(v).toPrecision(12));

/**
 * Whether a text is a `wingbeat modes` document (an object with `modes`) rather than an outline.
 * @param {string} text
 */
export function looksLikeModes(text) {
  const t = text.trimStart();
  if (!t.startsWith('{')) return false;
  try {
    const o = JSON.parse(t);
    return !!o && typeof o === 'object' && !Array.isArray(o) && 'modes' in o;
  } catch {
    return false;
  }
}

/** The name of the chosen strain point in exported modes documents (the CLI's --point name). */
export const CHOSEN_POINT = 'S';

/**
 * A `wingbeat modes` document that carries the strain point the lab shows: with a chosen point
 * (its modal strains per mode from modalStrainAt), that point first in every mode's `strains`,
 * named CHOSEN_POINT (`wingbeat simulate --modes` reports the first point's strain), the
 * document's own points after it. Without one, the document as it is.
 * @param {string} text the document (feModes' modes_json)
 * @param {{ eps_x: number, eps_y: number, gamma_xy: number }[] | null} strains per mode
 * @returns {string}
 */
export function modesDocument(text, strains) {
  if (!strains) return text;
  const doc = JSON.parse(text);
  doc.modes.forEach((m, k) => {
    const rest = (m.strains || []).filter((p) => p.point !== CHOSEN_POINT);
    m.strains = [{ point: CHOSEN_POINT, eps_x: strains[k].eps_x, eps_y: strains[k].eps_y, gamma_xy: strains[k].gamma_xy }, ...rest];
  });
  return JSON.stringify(doc);
}

/**
 * Where on an FE wing a point's modal strains were taken (mm), found from the strains
 * themselves: the modal strain at a point is the linear (barycentric) interpolation of the
 * nodal strains of the triangle that holds it (analysis::strain::interpolate_strain), so the
 * triangle whose nodal strains reproduce `target` (least squares over every mode and component,
 * relative residual ≤ 1e-7, barycentric weights in [0, 1]) gives the point. Null when no
 * triangle does (e.g. strains not from this mesh). Used on import: a modes document names its
 * strain points but does not say where they are.
 * @param {ArrayLike<number>} nodes flat [x, y, z] per node, m
 * @param {ArrayLike<number>} triangles flat node indices
 * @param {ArrayLike<number>} strainNodes flat [mode][node][ε_x, ε_y, γ_xy]
 * @param {{ eps_x: number, eps_y: number, gamma_xy: number }[]} target per mode
 * @returns {[number, number] | null}
 */
export function locateStrainPoint(nodes, triangles, strainNodes, target) {
  const nn = nodes.length / 3;
  const nm = target.length;
  if (!nm || strainNodes.length !== nm * nn * 3) return null;
  const tv = target.flatMap((t) => [t.eps_x, t.eps_y, t.gamma_xy]);
  const scale = Math.max(...tv.map(Math.abs));
  if (!(scale > 0) || !tv.every(Number.isFinite)) return null;
  const sv = (node, j) => strainNodes[(Math.floor(j / 3) * nn + node) * 3 + (j % 3)];
  /** @type {number[] | null} */
  let best = null;
  let bestRes = Infinity;
  for (let t = 0; t + 2 < triangles.length; t += 3) {
    const a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
    let uu = 0, uv = 0, vv = 0, ur = 0, vr = 0;
    for (let j = 0; j < tv.length; j++) {
      const s0 = sv(a, j), u = sv(b, j) - s0, v = sv(c, j) - s0, r = tv[j] - s0;
      uu += u * u; uv += u * v; vv += v * v; ur += u * r; vr += v * r;
    }
    const det = uu * vv - uv * uv;
    if (!(Math.abs(det) > 1e-300)) continue;
    const l1 = (vv * ur - uv * vr) / det, l2 = (uu * vr - uv * ur) / det, l0 = 1 - l1 - l2;
    const tol = 1e-9;
    if (l0 < -tol || l1 < -tol || l2 < -tol) continue;
    let res = 0;
    for (let j = 0; j < tv.length; j++) {
      const e = sv(a, j) * l0 + sv(b, j) * l1 + sv(c, j) * l2 - tv[j];
      res += e * e;
    }
    res = Math.sqrt(res) / scale;
    if (res < bestRes) {
      bestRes = res;
      best = [0, 1].map((k) => 1e3 * (l0 * nodes[3 * a + k] + l1 * nodes[3 * b + k] + l2 * nodes[3 * c + k]));
    }
  }
  if (!best || !(bestRes <= 1e-7)) return null;
  // Chosen points are kept to 0.001 mm; the solve returns them to about 1e-9 mm.
  return [Number(best[0].toFixed(6)), Number(best[1].toFixed(6))];
}

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, engine, section, id } = ctx;

  // ---------- the draft: what the form shows, applied by "Compute modes" ----------
  /** @type {{ params: Record<string, number>, points: [number, number][] | null, outline: string, source: string, label: string, planform: string }} */
  const draft = { params: {}, points: null, outline: 'manduca', source: 'builtin', label: '', planform: '' };
  let dirty = false;
  let selected = 0;

  const builtins = () => {
    const list = engine.ready ? engine.planforms() : [];
    return list.length ? list : [{ id: 'manduca', label: 'Manduca-like (synthetic, default)', note: '', points_mm: null }];
  };

  const fromStore = () => {
    const s = store.get();
    for (const w of WING) draft.params[w.key] = s[w.key];
    draft.outline = s.outline || 'manduca';
    draft.planform = s.planform || '';
    if (s.wing && s.wing.points) {
      draft.points = s.wing.points.map((p) => [p[0], p[1]]);
      draft.source = s.wing.source;
      draft.label = s.wing.label;
    } else {
      const b = builtins().find((p) => p.id === draft.outline);
      draft.points = b && b.points_mm ? b.points_mm.map((p) => [p[0], p[1]]) : null;
      draft.source = 'builtin';
      draft.label = b ? b.label : draft.outline;
    }
    selected = Math.min(selected, draft.points ? draft.points.length - 1 : 0);
    dirty = false;
  };

  // ---------- outline source ----------
  const outlineSel = el('select', { id: id('wing-outline'), 'data-wing': 'outline' });
  const fillOutlines = () => {
    const cur = outlineSel.value;
    outlineSel.replaceChildren();
    for (const b of builtins()) outlineSel.append(el('option', { value: b.id, text: b.label }));
    outlineSel.append(el('option', { value: 'own', text: 'Own outline (file, link or edited)', disabled: true }));
    outlineSel.value = cur || draft.outline;
  };
  outlineSel.addEventListener('change', () => {
    const b = builtins().find((p) => p.id === outlineSel.value);
    if (!b) return;
    draft.outline = b.id;
    draft.points = b.points_mm ? b.points_mm.map((p) => [p[0], p[1]]) : null;
    draft.source = 'builtin';
    draft.label = b.label;
    draft.planform = '';
    selected = 0;
    dirty = true;
    drawOutline();
  });
  const fileIn = el('input', { type: 'file', id: id('wing-file'), accept: '.csv,.json,.txt,text/csv,application/json', 'data-wing': 'file' });
  fileIn.addEventListener('change', async () => {
    const f = fileIn.files && fileIn.files[0];
    if (!f) return;
    try {
      if (f.size > 20e6) throw new Error(`${f.name} is larger than 20 MB`);
      const text = await f.text();
      if (looksLikeModes(text)) importModes(text, f.name);
      else {
        const format = /\.json$/i.test(f.name) || text.trimStart().startsWith('[') ? 'json' : 'csv';
        const pts = engine.parsePlanform(text, format);
        draft.points = pts.map((p) => [p[0], p[1]]);
        draft.source = 'file';
        draft.label = f.name.slice(0, 80);
        draft.planform = '';
        selected = 0;
        dirty = true;
        outlineSel.value = 'own';
        drawOutline();
        say(`Outline read from ${draft.label}: ${pts.length} points. Set the parameters and press “Compute modes”.`);
      }
    } catch (e) {
      say(`Could not read ${f.name}: ${errorText(e)}`, true);
    }
    fileIn.value = '';
  });

  // ---------- outline editor (SVG; drag with a pointer, exact values by keyboard) ----------
  const NS = 'http://www.w3.org/2000/svg';
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
  let scale = 1;
  const toSvg = (p) => [p[0], -p[1]];
  const drawOutline = () => {
    const pts = draft.points;
    dots.replaceChildren();
    if (!pts || !pts.length) {
      poly.setAttribute('points', '');
      svgDesc.textContent = 'No outline to draw (this wasm build does not list the built-in outlines).';
      check();
      syncPointInputs();
      return;
    }
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    for (const p of pts) {
      const [x, y] = toSvg(p);
      x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y);
    }
    const w = Math.max(x1 - x0, 1e-6), h = Math.max(y1 - y0, 1e-6);
    const m = 0.06 * Math.max(w, h);
    svg.setAttribute('viewBox', `${x0 - m} ${y0 - m} ${w + 2 * m} ${h + 2 * m}`);
    scale = Math.max(w, h);
    poly.setAttribute('points', pts.map((p) => toSvg(p).join(',')).join(' '));
    poly.setAttribute('stroke-width', String(0.006 * scale));
    pts.forEach((p, i) => {
      const c = document.createElementNS(NS, 'circle');
      const [x, y] = toSvg(p);
      c.setAttribute('cx', String(x));
      c.setAttribute('cy', String(y));
      c.setAttribute('r', String((i === selected ? 0.022 : 0.014) * scale));
      c.setAttribute('class', i === selected ? 'wl-pt wl-pt-sel' : 'wl-pt');
      c.dataset.i = String(i);
      dots.append(c);
    });
    // The strain point of the wing in use (the chosen one, else the FE result's), when shown.
    const st = store.get();
    const sp = !dirty && st.modes === 'fe' && st.fe ? st.strain_point || st.fe.strain_point_mm : null;
    let spText = '';
    if (sp) {
      const [x, y] = toSvg(sp);
      const r = 0.025 * scale;
      const cross = document.createElementNS(NS, 'path');
      cross.setAttribute('d', `M${x - r},${y - r}L${x + r},${y + r}M${x - r},${y + r}L${x + r},${y - r}`);
      cross.setAttribute('class', 'wl-outline-sp');
      cross.setAttribute('stroke-width', String(0.008 * scale));
      dots.append(cross);
      spText = ` The cross is the strain point (${fmt(sp[0], 4)}, ${fmt(sp[1], 4)}) mm.`;
    }
    svgDesc.textContent = `Outline of ${pts.length} points, span ${fmt(w, 4)} mm, chord ${fmt(h, 4)} mm; point ${selected + 1} selected. Drag a point to move it, or use the point fields below.${spText}`;
    check();
    syncPointInputs();
  };
  const svgPoint = (ev) => {
    const ctm = svg.getScreenCTM();
    if (!ctm) return null;
    const p = new DOMPoint(ev.clientX, ev.clientY).matrixTransform(ctm.inverse());
    return [Number(p.x.toFixed(3)), Number((-p.y).toFixed(3))];
  };
  let dragging = -1;
  svg.addEventListener('pointerdown', (ev) => {
    const t = /** @type {Element} */ (ev.target);
    if (!(t instanceof SVGCircleElement) || !draft.points) return;
    dragging = Number(t.dataset.i);
    selected = dragging;
    svg.setPointerCapture(ev.pointerId);
    ev.preventDefault();
    drawOutline();
  });
  svg.addEventListener('pointermove', (ev) => {
    if (dragging < 0 || !draft.points) return;
    const p = svgPoint(ev);
    if (!p) return;
    draft.points[dragging] = /** @type {[number, number]} */ (p);
    edited();
  });
  const endDrag = () => { dragging = -1; };
  svg.addEventListener('pointerup', endDrag);
  svg.addEventListener('pointercancel', endDrag);

  const idxIn = el('input', { type: 'number', id: id('wing-pt'), min: 1, step: 1, 'data-wing': 'point' });
  const xIn = el('input', { type: 'number', id: id('wing-x'), step: 0.1, 'data-wing': 'x' });
  const yIn = el('input', { type: 'number', id: id('wing-y'), step: 0.1, 'data-wing': 'y' });
  const syncPointInputs = () => {
    const pts = draft.points || [];
    idxIn.max = String(Math.max(1, pts.length));
    idxIn.value = String(selected + 1);
    const p = pts[selected];
    xIn.value = p ? String(p[0]) : '';
    yIn.value = p ? String(p[1]) : '';
  };
  idxIn.addEventListener('change', () => {
    const n = draft.points ? draft.points.length : 0;
    const v = Math.round(Number(idxIn.value));
    if (n && Number.isFinite(v)) selected = Math.min(n, Math.max(1, v)) - 1;
    drawOutline();
  });
  for (const [inp, c] of /** @type {[HTMLInputElement, number][]} */ ([[xIn, 0], [yIn, 1]])) {
    inp.addEventListener('change', () => {
      const v = Number(inp.value);
      if (!draft.points || inp.value.trim() === '' || !Number.isFinite(v)) {
        inp.setAttribute('aria-invalid', 'true');
        return;
      }
      inp.removeAttribute('aria-invalid');
      draft.points[selected][c] = v;
      edited();
    });
  }
  const addBtn = el('button', { type: 'button', text: 'Add point', 'data-wing': 'add', title: 'Insert a point halfway to the next one' });
  addBtn.addEventListener('click', () => {
    const pts = draft.points;
    if (!pts) return;
    const a = pts[selected], b = pts[(selected + 1) % pts.length];
    pts.splice(selected + 1, 0, [Number(((a[0] + b[0]) / 2).toFixed(3)), Number(((a[1] + b[1]) / 2).toFixed(3))]);
    selected += 1;
    edited();
  });
  const delBtn = el('button', { type: 'button', text: 'Remove point', 'data-wing': 'remove' });
  delBtn.addEventListener('click', () => {
    const pts = draft.points;
    if (!pts || pts.length <= 3) return say('An outline needs at least 3 points.', true);
    pts.splice(selected, 1);
    selected = Math.min(selected, pts.length - 1);
    edited();
  });
  const edited = () => {
    if (draft.source !== 'edited') {
      draft.source = 'edited';
      draft.label = draft.label && !/^edited/.test(draft.label) ? `edited ${draft.label}`.slice(0, 80) : draft.label || 'edited outline';
      draft.planform = '';
      outlineSel.value = 'own';
    }
    dirty = true;
    drawOutline();
  };
  const checkEl = el('p', { class: 'wl-note', role: 'status', 'data-wing': 'check' });
  let autoMesh = NaN;
  const check = () => {
    const pts = draft.points;
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
    showAuto();
  };

  // ---------- parameters ----------
  const presets = () => {
    const p = engine.ready ? engine.materialPresets() : [];
    return p.length ? p : FALLBACK_PRESETS;
  };
  const presetSel = el('select', { id: id('wing-preset'), 'data-wing': 'preset' });
  const fillPresets = () => {
    presetSel.replaceChildren(el('option', { value: '', text: 'Custom (as set below)' }));
    for (const p of presets()) presetSel.append(el('option', { value: p.id, text: p.label }));
    matchPreset();
  };
  const matchPreset = () => {
    const m = presets().find((p) => ['e_pa', 'rho', 'nu', 'thickness_um'].every((k) => Math.abs(p[k] - draft.params[k]) <= 1e-9 * Math.abs(p[k])));
    presetSel.value = m ? m.id : '';
  };
  presetSel.addEventListener('change', () => {
    const p = presets().find((q) => q.id === presetSel.value);
    if (!p) return;
    for (const k of ['e_pa', 'rho', 'nu', 'thickness_um']) draft.params[k] = p[k];
    dirty = true;
    syncParams();
  });
  /** @type {Record<string, HTMLInputElement>} */
  const inputs = {};
  const autoEl = el('span', { class: 'wl-unit wl-auto', 'data-wing': 'auto-mesh' });
  const showAuto = () => {
    const fe = store.get().fe;
    const a = Number.isFinite(autoMesh) ? autoMesh : null;
    autoEl.textContent = a != null ? `: ${fmt(a, 3)} mm` : fe && store.get().modes === 'fe' && draft.params.mesh_mm === 0 ? `: ${fmt(fe.mesh_size_mm, 3)} mm in use` : '';
  };
  const rows = WING.map((w) => {
    const sh = SHOW[w.key];
    const inp = el('input', {
      type: 'number', id: id(`wing-${w.key}`), 'data-wing': w.key,
      min: clean(w.min * sh.scale), max: clean(w.max * sh.scale), step: sh.step,
    });
    inputs[w.key] = inp;
    inp.addEventListener('change', () => {
      const v = Number(inp.value) / sh.scale;
      const ok = inp.value.trim() !== '' && Number.isFinite(v) && v >= w.min - 1e-12 && v <= w.max + 1e-12 && (w.key !== 'n_modes' || Number.isInteger(v));
      if (!ok) {
        inp.setAttribute('aria-invalid', 'true');
        say(`${LABEL[w.key]}: expected ${w.key === 'n_modes' ? 'a whole number' : 'a number'} in [${clean(w.min * sh.scale)}, ${clean(w.max * sh.scale)}]${sh.unit ? ' ' + sh.unit.replace(/,.*$/, '') : ''}.`, true);
        return;
      }
      inp.removeAttribute('aria-invalid');
      draft.params[w.key] = clean(v);
      dirty = true;
      matchPreset();
      showAuto();
    });
    return el('div', { class: 'wl-wing-field' },
      el('label', { for: id(`wing-${w.key}`) }, LABEL[w.key], sh.unit ? el('span', { class: 'wl-unit' }, ` (${sh.unit}`, w.key === 'mesh_mm' ? autoEl : '', ')') : null),
      inp);
  });
  const syncParams = () => {
    for (const w of WING) {
      const inp = inputs[w.key];
      if (activeIn(inp) !== inp) inp.value = String(clean(draft.params[w.key] * SHOW[w.key].scale));
      inp.removeAttribute('aria-invalid');
    }
    matchPreset();
    showAuto();
  };

  // ---------- compute, cancel, export ----------
  const computeBtn = el('button', { type: 'button', class: 'wl-primary', text: 'Compute modes', 'data-wing': 'compute' });
  const cancelBtn = el('button', { type: 'button', text: 'Cancel', 'data-wing': 'cancel', hidden: true });
  const progress = el('progress', { 'aria-label': 'Computing the wing’s modes', hidden: true });
  const statusEl = el('p', { class: 'wl-note', role: 'status', 'data-wing': 'status' });
  const exportBtn = el('button', { type: 'button', text: 'Export modes JSON', 'data-wing': 'export', title: 'The wing in use as a `wingbeat modes` document (for wingbeat simulate --modes)' });
  const resetBtn = el('button', { type: 'button', text: 'Default wing', 'data-wing': 'reset' });
  const inUse = el('div', { class: 'wl-wing-inuse', 'data-wing': 'in-use' });
  /** @type {{ id: number, t0: number, timer: ReturnType<typeof setInterval> } | null} */
  let job = null;
  const say = (text, bad = false) => {
    statusEl.textContent = text;
    statusEl.classList.toggle('wl-bad', bad);
    statusEl.setAttribute('role', bad ? 'alert' : 'status');
  };
  const busy = (on) => {
    progress.hidden = !on;
    cancelBtn.hidden = !on;
    computeBtn.disabled = on;
  };
  const compute = () => {
    if (job) return;
    /** @type {any} */
    const p = { ...store.get(), ...draft.params, outline: draft.outline, planform: draft.planform };
    const own = draft.source !== 'builtin' && draft.points;
    let input;
    try {
      input = engine.wingInput(p, own ? draft.points : draft.outline !== 'manduca' ? draft.points : null);
    } catch (e) {
      say(`The wing is not valid: ${errorText(e)}`, true);
      return;
    }
    const t0 = performance.now();
    const j = engine.computeWing(input, () => {});
    if (!j.id) return apply(p, own, input);
    busy(true);
    const timer = setInterval(() => say(`Computing ${p.n_modes} modes in the worker… ${((performance.now() - t0) / 1000).toFixed(1)} s (the wing in use stays until this one is ready)`), 250);
    job = { id: j.id, t0, timer };
    say(`Computing ${p.n_modes} modes in the worker…`);
    ctx.emit('wl-wing', { state: 'started' });
    j.promise.then(
      (r) => {
        clearInterval(timer);
        job = null;
        busy(false);
        apply(p, own, input);
        say(`Computed in ${((performance.now() - t0) / 1000).toFixed(1)} s: ${r.n_nodes} nodes, element size ${fmt(r.mesh_size_mm, 3)} mm.`);
        ctx.emit('wl-wing', { state: 'done' });
      },
      (e) => {
        clearInterval(timer);
        job = null;
        busy(false);
        const msg = errorText(e);
        if (msg === 'cancelled') say('Cancelled. The wing in use is unchanged.');
        else say(`The wing could not be computed: ${msg}. The wing in use is unchanged.`, true);
        ctx.emit('wl-wing', { state: msg === 'cancelled' ? 'cancelled' : 'failed', error: msg });
      },
    );
  };
  /** Makes the draft the wing in use (the store follows; the engine has the result cached). */
  const apply = (p, own, input) => {
    /** @type {Record<string, any>} */
    const patch = { modes: 'fe', outline: draft.outline, planform: draft.source === 'url' ? draft.planform : '' };
    for (const w of WING) patch[w.key] = p[w.key];
    patch.wing = own ? { input, source: draft.source, label: draft.label, outline: 'own', points: draft.points && draft.points.map((q) => [q[0], q[1]]) } : null;
    if (own) patch.outline = draft.outline;
    dirty = false;
    store.set(patch);
  };
  computeBtn.addEventListener('click', compute);
  cancelBtn.addEventListener('click', () => {
    if (job) engine.cancel(job.id);
  });
  exportBtn.addEventListener('click', () => {
    const s = store.get();
    const fe = s.fe;
    if (!fe || s.modes !== 'fe') return say('No FE wing in use yet: choose the FE wing mode set or compute a wing first.', true);
    const raw = /** @type {any} */ (fe).modes_json;
    if (typeof raw !== 'string') return say('This wasm build does not produce the modes document: rebuild www/pkg.', true);
    // A chosen strain point goes with the modes, first (the one simulate --modes reports).
    let json;
    try {
      json = modesDocument(raw, s.strain_point ? engine.modalStrainAt(s.strain_point) : null);
    } catch (e) {
      return say(`Could not export the modes: ${errorText(e)}`, true);
    }
    download('wingbeat-modes.json', new Blob([json], { type: 'application/json' }));
    const sp = s.strain_point;
    say(`Exported ${fe.modes.length} modes as wingbeat-modes.json${sp ? `, with the chosen strain point ${CHOSEN_POINT} = (${fmt(sp[0], 4)}, ${fmt(sp[1], 4)}) mm first` : ''} (use it with: wingbeat simulate --modes wingbeat-modes.json).`);
    ctx.emit('wl-wing', { state: 'exported' });
  });
  resetBtn.addEventListener('click', () => {
    /** @type {Record<string, any>} */
    const patch = { wing: null, outline: 'manduca', planform: '' };
    for (const w of WING) patch[w.key] = w.def;
    store.set(patch);
    fromStore();
    fillOutlines();
    syncParams();
    drawOutline();
  });

  /** A `wingbeat modes` document → the wing in use (mesh and modes as computed by the CLI). */
  const importModes = (text, name) => {
    const r = engine.modesFromJson(text);
    const f = r.fe;
    if (!f || !f.nodes) throw new Error('the document has no FE mesh (nodes, triangles, shapes); the lab needs the full `wingbeat modes` output');
    const F = (a) => (a instanceof Float64Array ? a : Float64Array.from(a));
    /** @type {any} */
    const fe = {
      ...f,
      modes: r.modes,
      nodes: F(f.nodes),
      triangles: f.triangles instanceof Uint32Array ? f.triangles : Uint32Array.from(f.triangles),
      shapes: F(f.shapes),
      strain_nodes: F(f.strain_nodes),
      freq_hz: F(f.freq_hz || r.modes.map((m) => m.freq_hz)),
      kinds: f.kinds || r.modes.map((m) => m.name || ''),
      n_modes: r.modes.length,
      n_nodes: f.n_nodes || f.nodes.length / 3,
      modes_json: text,
      imported: true,
    };
    // Where the document's first strain point is (the one the lab and simulate use): found from
    // its modal strains on this mesh, so the cross on the maps sits where it was.
    const s0 = r.modes.every((m) => m.strains && m.strains[0]) ? r.modes.map((m) => m.strains[0]) : null;
    const point = s0 ? locateStrainPoint(fe.nodes, fe.triangles, fe.strain_nodes, s0) : null;
    if (point) fe.strain_point_mm = point;
    engine.useFe(fe, `import:${name}:${text.length}`);
    store.set({ modes: 'fe', wing: { input: null, source: 'import', label: name.slice(0, 80), outline: 'file', points: null }, fe, mode: '1', strain_point: null });
    say(`Imported ${r.modes.length} modes from ${name}.`);
    ctx.emit('wl-wing', { state: 'imported' });
  };

  const describeInUse = (s) => {
    inUse.replaceChildren();
    if (s.modes !== 'fe') {
      inUse.append(el('p', { class: 'wl-note', text: 'In use: the paper table’s two modes (paper units). Compute a wing (or choose the FE wing mode set under Parameters) to use FE modes.' }));
      return;
    }
    const fe = s.fe;
    if (!fe) {
      inUse.append(el('p', { class: 'wl-note', text: 'The FE wing is being computed…' }));
      return;
    }
    const src = s.wing ? `${s.wing.label} (${s.wing.source === 'import' ? 'imported modes' : 'own outline'})` : customWing(s) ? `${(builtins().find((b) => b.id === s.outline) || { label: s.outline }).label}` : 'the default synthetic Manduca-like wing';
    inUse.append(el('p', { class: 'wl-note', text: `In use: ${src}; ${fe.modes.length} modes, ${fe.n_nodes} nodes, element size ${fmt(fe.mesh_size_mm, 3)} mm${s.strain_point ? `, chosen strain point (${fmt(s.strain_point[0], 4)}, ${fmt(s.strain_point[1], 4)}) mm` : ''}${fe.strain_point_mm ? `, ${s.strain_point ? 'the wing’s own ' : ''}strain point (${fmt(fe.strain_point_mm[0], 4)}, ${fmt(fe.strain_point_mm[1], 4)}) mm` : ''}.` }));
    const ol = el('ol', { class: 'wl-wing-freqs', 'aria-label': 'Natural frequencies of the wing in use' });
    fe.modes.forEach((m, k) => ol.append(el('li', { 'data-field': `wing-freq-${k}`, text: `${fmt(m.freq_hz, 4)} Hz${fe.kinds && fe.kinds[k] ? ` (${fe.kinds[k]})` : ''}` })));
    inUse.append(ol);
  };

  // One column in reading order (tab order = visual order): source, drawing, point editing,
  // the parameters as a grid filled row by row, the actions, the wing in use.
  section.append(
    el('div', { class: 'wl-wing-src' },
      el('div', { class: 'wl-wing-field' }, el('label', { for: id('wing-outline'), text: 'Outline' }), outlineSel),
      el('div', { class: 'wl-wing-field' }, el('label', { for: id('wing-file'), text: 'Load a file (outline or modes JSON)' }), fileIn)),
    el('p', { class: 'wl-note', text: 'Outline files: CSV with a header x_mm,y_mm (or i,x_mm,y_mm; # comments) or JSON [[x, y], …], in mm, x spanwise from the root (root edge on x = 0), chord toward −y. A `wingbeat modes` JSON document imports its modes.' }),
    svg,
    svgDesc,
    el('div', { class: 'wl-wing-pts' },
      el('span', { class: 'wl-pair' }, el('label', { for: id('wing-pt'), text: 'Point' }), idxIn),
      el('span', { class: 'wl-pair' }, el('label', { for: id('wing-x'), text: 'x (mm)' }), xIn),
      el('span', { class: 'wl-pair' }, el('label', { for: id('wing-y'), text: 'y (mm)' }), yIn),
      addBtn, delBtn),
    checkEl,
    el('div', { class: 'wl-wing-params' },
      el('div', { class: 'wl-wing-field' }, el('label', { for: id('wing-preset'), text: 'Material preset' }), presetSel),
      ...rows),
    el('div', { class: 'wl-wing-actions' }, computeBtn, cancelBtn, progress, exportBtn, resetBtn),
    statusEl,
    inUse,
  );

  const unsub = [
    store.subscribe([...WING.map((w) => w.key), 'outline', 'planform', 'wing'], () => {
      if (dirty || job) return;
      fromStore();
      fillOutlines();
      if (draft.source !== 'builtin') outlineSel.value = 'own';
      syncParams();
      drawOutline();
    }),
    store.subscribe(['fe', 'modes', 'wing', 'outline', 'strain_point'], (s) => { describeInUse(s); showAuto(); }),
    store.subscribe(['fe', 'strain_point', 'modes'], () => { if (!dirty) drawOutline(); }),
  ];
  const init = () => {
    fromStore();
    fillOutlines();
    fillPresets();
    if (draft.source !== 'builtin') outlineSel.value = 'own';
    syncParams();
    drawOutline();
    describeInUse(store.get());
  };
  init();
  // The built-in outlines and presets come from the wasm: refresh once it has loaded.
  const whenReady = setInterval(() => {
    if (!engine.ready) return;
    clearInterval(whenReady);
    if (!dirty) init();
  }, 100);
  return {
    compute,
    get draft() { return draft; },
    destroy() {
      clearInterval(whenReady);
      if (job) clearInterval(job.timer);
      unsub.forEach((f) => f());
    },
  };
}
