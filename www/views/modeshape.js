// @ts-check
// Mode-shape viewer: one mode of the FE wing alone, animated as φ_k(x, y)·sin(2π t / T) (a slow
// stand-in for its natural frequency), with its natural frequency f_k, kind (bending, torsion …)
// and first-moment vector a_k = ∫ φ_k dm (what couples it to the flapping forces, Eq. 13).
// Drawn in 2-D on a canvas (no GPU needed) from the FE mesh by views/modeshape-draw.js: the wing
// seen obliquely with the renderer's camera mirror and rotation (www/scene3d.js), triangles
// painted back to front, coloured by the out-of-plane displacement with the renderer's colour map
// (WingView.colourMap). The deflection is scaled so the largest |φ_k| is 15 % of the span: shapes
// only, not amplitudes (a mass-normalised mode has no physical size).
import { el, rich } from '../dom.js';
import { fmt, errorText } from '../format.js';
import { context2d } from '../export.js';
import { DRAWN_FRACTION, modeGeometry, paintMode } from './modeshape-draw.js';

export const title = 'Mode shapes';

/** Period of the drawn oscillation, s (every mode alike: the shape matters, not its speed). */
const ANIM_PERIOD_S = 2;

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
  /** @type {ReturnType<typeof modeGeometry> | null} per mode */
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
    if (!geom) geom = modeGeometry(fe, k, cssW, cssH);
    const c2 = context2d(canvas);
    c2.setTransform(dpr, 0, 0, dpr, 0, 0);
    const R = engine.renderer;
    paintMode(c2, fe, k, geom, deg, R ? R.colourMap() : null, cssW, cssH);
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
