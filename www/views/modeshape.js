// @ts-check
// Mode-shape viewer: one mode of the FE wing alone, animated as φ_k(x, y)·sin(2π t / T) (a slow
// stand-in for its natural frequency), with its natural frequency f_k, kind (bending, torsion …)
// and first-moment vector a_k = ∫ φ_k dm (what couples it to the flapping forces, Eq. 13).
// Drawn in 2-D on a canvas (no GPU needed) from the FE mesh: the wing seen obliquely with the
// renderer's camera mirror and rotation (www/scene3d.js), triangles painted back to front,
// coloured by the out-of-plane displacement with the renderer's colour map (WingView.colourMap).
// The deflection is scaled so the largest |φ_k| is 15 % of the span: shapes only, not
// amplitudes (a mass-normalised mode has no physical size).
import { el, rich } from '../dom.js';
import { fmt, errorText } from '../format.js';
import * as S from '../scene3d.js';
import { context2d } from '../export.js';

export const title = 'Mode shapes';

/** Period of the drawn oscillation, s (every mode alike: the shape matters, not its speed). */
const ANIM_PERIOD_S = 2;
/** The largest drawn deflection, as a fraction of the span. */
const DRAWN_FRACTION = 0.15;

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { store, section, engine, uid } = ctx;
  const reduced = typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;
  const pick = el('select', { id: `${uid}-ms-mode` });
  const playBtn = el('button', { type: 'button', class: 'wl-ms-play', 'aria-pressed': 'false', text: 'Animate' });
  const phase = el('input', { type: 'range', id: `${uid}-ms-phase`, min: 0, max: 360, step: 5, value: 90 });
  const phaseText = el('span', { class: 'wl-ms-phase-text' });
  const canvas = el('canvas', {
    class: 'wl-ms-canvas',
    width: 600,
    height: 320,
    role: 'img',
    'aria-label': 'Mode shape drawing',
    'aria-describedby': `${uid}-ms-info`,
  });
  // The numbers beside the drawing (f_k, kind, a_k) are its text description.
  const info = el('dl', { class: 'wl-ms-info', id: `${uid}-ms-info`, 'aria-live': 'polite' });
  const note = el('p', { class: 'wl-note' });
  const computeBtn = el('button', { type: 'button', class: 'wl-small', text: 'Compute the FE wing’s modes' });
  const empty = el('p', { class: 'wl-ms-empty' }, 'The mode shapes need an FE wing (mesh and shapes). ', computeBtn);
  const controls = el(
    'div',
    { class: 'wl-ms-controls' },
    el('span', { class: 'wl-ms-field' }, el('label', { for: pick.id, text: 'mode' }), pick),
    playBtn,
    el('span', { class: 'wl-ms-field' }, el('label', { for: phase.id, text: 'phase' }), phase, phaseText),
  );
  const box = el('div', { class: 'wl-ms', 'data-modeshape': '', 'data-state': 'empty' }, controls, canvas, info, note);
  section.append(empty, box);

  /** @type {any} FeModesResult */
  let fe = null;
  let k = 0;
  let playing = false;
  let raf = 0;
  let t0 = 0;
  let visible = true;
  /** @type {{ cam: S.Camera, scale: number, max: number } | null} per mode */
  let geom = null;

  computeBtn.addEventListener('click', () => {
    computeBtn.disabled = true;
    computeBtn.textContent = 'Computing…';
    engine.ensureFe().then(
      (r) => store.set({ fe: r }),
      (e) => {
        computeBtn.disabled = false;
        computeBtn.textContent = `Failed (${errorText(e)}): try again`;
      },
    );
  });
  pick.addEventListener('change', () => {
    k = Number(pick.value);
    geom = null;
    describe();
    draw();
  });
  phase.addEventListener('input', () => {
    setPlaying(false);
    draw();
  });
  playBtn.addEventListener('click', () => setPlaying(!playing));

  function setPlaying(on) {
    playing = !!on && !!fe;
    playBtn.textContent = playing ? 'Pause' : 'Animate';
    playBtn.setAttribute('aria-pressed', String(playing));
    if (playing && !raf) {
      t0 = performance.now() - (Number(phase.value) / 360) * ANIM_PERIOD_S * 1000;
      const step = (now) => {
        if (!playing) {
          raf = 0;
          return;
        }
        if (visible) {
          const deg = (((now - t0) / 1000 / ANIM_PERIOD_S) * 360) % 360;
          phase.value = String(Math.round(deg / 5) * 5);
          draw(deg);
        }
        raf = requestAnimationFrame(step);
      };
      raf = requestAnimationFrame(step);
    }
  }

  /** Per mode: the camera (the renderer's default view, fitted) and the drawing scale. */
  function geometry(w, h) {
    const n = fe.nodes.length / 3;
    const span = S.spanOf(fe.nodes);
    let max = 0;
    for (let i = 0; i < n; i++) max = Math.max(max, Math.abs(fe.shapes[k * n + i]));
    const scale = max > 0 ? (DRAWN_FRACTION * span) / max : 0;
    const base = S.defaultCamera(span);
    const cam = { ...base, yaw: -1.45, pitch: 0.62 };
    // Fit: the wing at both extremes of the oscillation inside the canvas with a margin,
    // looking at the middle of their bounding box.
    const pts = [];
    const stride = Math.max(1, Math.floor(n / 400));
    for (const sgn of [-1, 1]) {
      for (let i = 0; i < n; i += stride) {
        pts.push(fe.nodes[3 * i], fe.nodes[3 * i + 1], fe.nodes[3 * i + 2] + sgn * scale * fe.shapes[k * n + i]);
      }
    }
    const lo = [Infinity, Infinity, Infinity],
      hi = [-Infinity, -Infinity, -Infinity];
    for (let j = 0; j < pts.length; j += 3) {
      for (let c = 0; c < 3; c++) {
        lo[c] = Math.min(lo[c], pts[j + c]);
        hi[c] = Math.max(hi[c], pts[j + c]);
      }
    }
    cam.target = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])];
    cam.distance = S.fitDistance(cam, pts, w, h, 0.04);
    return { cam, scale, max };
  }

  function describe() {
    if (!fe) return;
    const a = fe.modes && fe.modes[k] ? fe.modes[k].a : fe.a ? fe.a[k] : null;
    const items = [
      ['mode', `${k + 1} of ${fe.n_modes}`],
      ['natural frequency f_k', `${fmt(fe.freq_hz[k], 5)} Hz`],
      ['kind', fe.kinds[k] || '—'],
      ['a_k = ∫ φ_k dm (x, y)', a ? `(${fmt(a[0], 4)}, ${fmt(a[1], 4)}) kg^½·m` : '—'],
      ['|a_k|', a ? `${fmt(Math.hypot(a[0], a[1]), 4)} kg^½·m` : '—'],
    ];
    info.replaceChildren(
      ...items.flatMap(([d, v]) => [el('dt', {}, rich(d)), el('dd', { 'data-ms': d.split(' ')[0] }, rich(v))]),
    );
    box.dataset.freq = String(fe.freq_hz[k]);
    box.dataset.mode = String(k + 1);
    canvas.setAttribute(
      'aria-label',
      `Mode ${k + 1} of the FE wing alone: ${fe.kinds[k] || 'mode'} at ${fmt(fe.freq_hz[k], 5)} Hz, drawn ${playing ? 'oscillating' : 'at one phase'} (deflection exaggerated to 15 % of the span; colour: displacement, blue down, red up).`,
    );
  }

  /** Draws mode k at phase `deg` (degrees; the slider's value when omitted). */
  function draw(deg = Number(phase.value)) {
    phaseText.textContent = `${Math.round(deg)}°`;
    phase.setAttribute(
      'aria-valuetext',
      `${Math.round(deg)} degrees, deflection ${fmt(Math.sin((deg * Math.PI) / 180), 2)} of its largest`,
    );
    if (!fe) return;
    const cssW = Math.max(200, Math.min(760, box.clientWidth || 600));
    const cssH = Math.round(Math.max(160, Math.min(380, cssW * 0.55)));
    const dpr = Math.min(2, globalThis.devicePixelRatio || 1);
    canvas.style.width = `${cssW}px`;
    canvas.style.height = `${cssH}px`;
    const W = Math.round(cssW * dpr),
      H = Math.round(cssH * dpr);
    if (canvas.width !== W || canvas.height !== H) {
      canvas.width = W;
      canvas.height = H;
      geom = null;
    }
    if (!geom) geom = geometry(cssW, cssH);
    const c2 = context2d(canvas);
    c2.setTransform(dpr, 0, 0, dpr, 0, 0);
    c2.fillStyle = '#fafbfd';
    c2.fillRect(0, 0, cssW, cssH);
    const n = fe.nodes.length / 3;
    const amp = Math.sin((deg * Math.PI) / 180);
    const q = new Float64Array(fe.n_modes);
    q[k] = amp * geom.scale;
    const proj = S.projectNodes(fe.nodes, fe.shapes, q, 1, [0, 0, 0], geom.cam, cssW, cssH);
    const tri = fe.triangles;
    const nt = tri.length / 3;
    const order = new Uint32Array(nt);
    const depth = new Float64Array(nt);
    for (let t = 0; t < nt; t++) {
      order[t] = t;
      depth[t] = proj.depth[tri[3 * t]] + proj.depth[tri[3 * t + 1]] + proj.depth[tri[3 * t + 2]];
    }
    order.sort((a, b) => depth[b] - depth[a]);
    const R = engine.renderer;
    const stops = R ? R.colourMap() : null;
    const max = geom.max || 1;
    // Two-sided diffuse shading from a light above and behind the viewer's right shoulder, so
    // bending and twist read as shape, not only as colour.
    const e = S.eye(geom.cam);
    const L = [
      e[0] - geom.cam.target[0] + 0.3 * S.spanOf(fe.nodes),
      e[1] - geom.cam.target[1],
      e[2] - geom.cam.target[2] + 0.5 * S.spanOf(fe.nodes),
    ];
    const ll = Math.hypot(...L);
    const P = (i) => [fe.nodes[3 * i], fe.nodes[3 * i + 1], fe.nodes[3 * i + 2] + q[k] * fe.shapes[k * n + i]];
    for (const t of order) {
      const a = tri[3 * t],
        b = tri[3 * t + 1],
        c = tri[3 * t + 2];
      const w = (fe.shapes[k * n + a] + fe.shapes[k * n + b] + fe.shapes[k * n + c]) / 3;
      const rgb = stops ? S.colourAt(stops, 0.5 + (0.5 * (amp * w)) / max) : [200, 190, 160];
      const pa = P(a),
        pb = P(b),
        pc = P(c);
      const u = [pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]],
        v = [pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]];
      const nn = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
      const shade =
        0.6 + 0.4 * Math.abs((nn[0] * L[0] + nn[1] * L[1] + nn[2] * L[2]) / ((Math.hypot(...nn) || 1) * ll));
      for (let j = 0; j < 3; j++) rgb[j] = Math.round(rgb[j] * shade);
      c2.fillStyle = `rgb(${rgb[0]},${rgb[1]},${rgb[2]})`;
      c2.strokeStyle = c2.fillStyle;
      c2.lineWidth = 0.7;
      c2.beginPath();
      c2.moveTo(proj.xy[2 * a], proj.xy[2 * a + 1]);
      c2.lineTo(proj.xy[2 * b], proj.xy[2 * b + 1]);
      c2.lineTo(proj.xy[2 * c], proj.xy[2 * c + 1]);
      c2.closePath();
      c2.fill();
      c2.stroke();
    }
    // The undeformed outline (root to tip), thin and dark, for reference.
    const ol = S.outline(fe.nodes);
    const pr = S.projector(geom.cam, cssW, cssH);
    c2.strokeStyle = 'rgba(40,40,40,0.55)';
    c2.setLineDash([3, 3]);
    c2.lineWidth = 1;
    c2.beginPath();
    const m = ol.nodes.length / 3;
    for (let j = 0; j <= m; j++) {
      const i = j % m;
      const p = pr(ol.nodes[3 * i], ol.nodes[3 * i + 1], 0);
      if (!p) continue;
      if (j === 0) c2.moveTo(p[0], p[1]);
      else c2.lineTo(p[0], p[1]);
    }
    c2.stroke();
    c2.setLineDash([]);
    c2.fillStyle = '#222';
    c2.font = '12px system-ui, sans-serif';
    c2.fillText(`mode ${k + 1}: ${fe.kinds[k] || ''}, ${fmt(fe.freq_hz[k], 4)} Hz`, 8, 16);
    box.dataset.drawn = String(Number(box.dataset.drawn || 0) + 1);
  }

  function onFe() {
    const s = store.get();
    fe = s.fe;
    box.hidden = !fe;
    empty.hidden = !!fe;
    box.dataset.state = fe ? 'ready' : 'empty';
    if (!fe) {
      setPlaying(false);
      return;
    }
    const prev = pick.value;
    pick.replaceChildren(
      ...Array.from({ length: fe.n_modes }, (_, j) =>
        el('option', {
          value: String(j),
          text: `Mode ${j + 1}: ${fe.kinds[j] || 'mode'}, ${fmt(fe.freq_hz[j], 4)} Hz`,
        }),
      ),
    );
    k = prev !== '' && Number(prev) < fe.n_modes ? Number(prev) : 0;
    pick.value = String(k);
    geom = null;
    note.replaceChildren(
      rich(
        `The FE wing’s ${fe.n_modes} mode shapes (${fe.n_nodes} nodes, ${fmt(fe.mesh_size_mm, 3)} mm elements), one at a time. Drawn oscillating once every ${ANIM_PERIOD_S} s whatever f_k, deflection scaled so the largest is ${DRAWN_FRACTION * 100} % of the span (mass-normalised shapes have no physical size); dashed: the flat outline. Colours: the 3-D view’s map, blue down, red up. a_k couples the mode to the flapping forces (Eq. 13): every response of mode k scales with |a_k|.${s.modes === 'paper' ? ' (The paper’s table has frequencies and a_k but no shapes: these are the FE wing’s, as in the 3-D view.)' : ''}`,
      ),
    );
    describe();
    draw();
  }

  const unsub = store.subscribe(['fe', 'modes'], onFe);
  /** @type {IntersectionObserver | null} */
  let io = null;
  if (typeof IntersectionObserver === 'function') {
    io = new IntersectionObserver((entries) => {
      visible = entries.some((e) => e.isIntersecting);
    });
    io.observe(box);
  }
  /** @type {ResizeObserver | null} */
  let ro = null;
  if (typeof ResizeObserver === 'function') {
    let lastW = 0;
    ro = new ResizeObserver(() => {
      const w = box.clientWidth;
      if (fe && w && Math.abs(w - lastW) > 4) {
        lastW = w;
        geom = null;
        draw();
      }
    });
    ro.observe(box);
  }
  onFe();
  if (!reduced && fe) setPlaying(true);

  return {
    get mode() {
      return k + 1;
    },
    /** Shows mode `m` (1-based). */
    setMode(m) {
      pick.value = String(Math.max(0, Math.min((fe ? fe.n_modes : 1) - 1, Math.round(m) - 1)));
      pick.dispatchEvent(new Event('change'));
    },
    setPlaying,
    destroy() {
      unsub();
      playing = false;
      if (raf) cancelAnimationFrame(raf);
      if (io) io.disconnect();
      if (ro) ro.disconnect();
    },
  };
}
