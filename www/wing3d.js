// The 3-D panel of <wing-lab>: the shell-FE wing flapping (roll α, pitch β, yaw γ about the
// root), bending and twisting as the simulated modal responses say, coloured by strain. Drawn
// by the wasm `WingView` (wgpu: WebGPU where the browser has it, WebGL2 otherwise); when
// neither works the panel says why and the rest of the lab carries on.
//
// Time: the view shows the simulated run at one instant t (the sample nearest t on the 10 kHz
// output grid). Play advances t at `slow-motion × real time`, looping over the run; the slider
// scrubs; a click on the responses plot jumps there, and that plot shows t as a cursor line.
// Test hooks on the panel box: data-state (loading | ready | unavailable), data-backend,
// data-frames (frames drawn).

const COLOURS = [
  ['0', 'none (shading only)'],
  ['1', 'ε_x, spanwise strain'],
  ['2', 'ε_y, chordwise strain'],
  ['3', 'γ_xy, shear strain'],
  ['4', '|ε|, strain magnitude'],
];
const SLOW = [
  ['0.002', '1/500'],
  ['0.005', '1/200'],
  ['0.01', '1/100'],
  ['0.02', '1/50'],
  ['0.05', '1/20'],
];

function el(tag, props = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) {
    if (k === 'class') e.className = v;
    else if (k === 'text') e.textContent = v;
    else if (k.startsWith('aria-') || k.startsWith('data-') || k === 'role' || k === 'for' || k === 'tabindex') e.setAttribute(k, v);
    else e[k] = v;
  }
  for (const c of children) if (c != null) e.append(c);
  return e;
}

function fmtNum(v, digits = 3) {
  if (!Number.isFinite(v)) return '—';
  if (v === 0) return '0';
  const a = Math.abs(v);
  return a >= 1e-3 && a < 1e4 ? String(Number(v.toPrecision(digits))) : v.toExponential(digits - 1);
}

export class Wing3D {
  /**
   * @param {HTMLElement} lab  the <wing-lab> element (analysis, config(), ensureFe(), plots)
   * @param {HTMLElement} sec  the panel section to fill
   */
  constructor(lab, sec) {
    this.lab = lab;
    // Start mid-run and mid-stroke (12.625 flap periods at 25 Hz), where the beat has built up.
    this.t = 0.505;
    this.playing = false;
    this.frames = 0;
    this.view = null;
    const uid = lab.uid;
    this.box = el('div', { class: 'wl-wing3d-box', 'data-wing3d': '', 'data-state': 'loading' });
    if (!document.getElementById('wing3d')) this.box.id = 'wing3d';
    this.canvas = el('canvas', {
      class: 'wl-w3-canvas',
      tabindex: '0',
      role: 'img',
      'aria-label': '3-D view of the flexing wing. Drag, or use the arrow keys, to orbit; wheel or + and − to zoom.',
      width: 640,
      height: 384,
    });
    this.legend = el('canvas', { class: 'wl-w3-legend', width: 240, height: 14, 'aria-hidden': 'true' });
    this.legendText = el('span', { class: 'wl-w3-legend-text' });
    this.status = el('p', { class: 'wl-w3-status', role: 'status', text: 'Starting the 3-D view…' });
    this.stage = el('div', { class: 'wl-w3-stage' }, this.canvas);
    this.box.append(this.stage);

    this.playBtn = el('button', { type: 'button', class: 'wl-w3-play', text: 'Play', 'aria-pressed': 'false', onclick: () => this.setPlaying(!this.playing) });
    this.slow = el('select', { id: `${uid}-w3-slow`, 'aria-label': 'Slow-motion factor' });
    for (const [v, t] of SLOW) this.slow.append(el('option', { value: v, text: t }));
    this.slow.value = '0.01';
    this.slow.addEventListener('change', () => this.describeTime());
    this.time = el('input', { type: 'range', id: `${uid}-w3-time`, min: 0, max: 2, step: 0.0001, value: 0.505, 'aria-label': 'Simulated time t, in s' });
    this.time.addEventListener('input', () => {
      this.setPlaying(false);
      this.setTime(Number(this.time.value));
    });
    this.timeText = el('span', { class: 'wl-w3-time', 'aria-live': 'off' });
    this.exag = el('input', { type: 'range', id: `${uid}-w3-exag`, min: 0, max: 3, step: 0.05, value: 1, 'aria-label': 'Deflection exaggeration, as a power of ten' });
    this.exag.addEventListener('input', () => {
      this.exagTouched = true;
      this.draw();
    });
    this.exagText = el('span', { class: 'wl-w3-exag' });
    this.colour = el('select', { id: `${uid}-w3-colour`, 'aria-label': 'Colour the wing by' });
    for (const [v, t] of COLOURS) this.colour.append(el('option', { value: v, text: t }));
    this.colour.value = '3';
    this.colour.addEventListener('change', () => this.draw());

    const row = (label, id, ...inputs) => el('div', { class: 'wl-w3-row' }, el('label', { for: id, text: label }), ...inputs);
    this.controls = el(
      'div',
      { class: 'wl-w3-controls' },
      el('div', { class: 'wl-w3-row' }, this.playBtn, el('label', { for: this.slow.id, text: 'slow motion' }), this.slow),
      row('time', this.time.id, this.time, this.timeText),
      row('exaggeration', this.exag.id, this.exag, this.exagText),
      row('colour', this.colour.id, this.colour),
      el('div', { class: 'wl-w3-row' }, this.legend, this.legendText),
    );
    this.note = el('p', { class: 'wl-note' });
    sec.append(this.box, this.status, this.controls, this.note);
    this.bindCamera();
    this.describeTime();
  }

  /**
   * Starts the view when the panel first scrolls into sight, so a page that never shows it
   * never pays for the FE solve (a few seconds of a worker) or a GPU context.
   */
  startWhenVisible(wb) {
    if (this.started || this.io) return;
    this.status.textContent = 'The 3-D view starts when this panel is on screen.';
    this.io = new IntersectionObserver((entries) => {
      if (entries.some((e) => e.isIntersecting)) {
        this.io.disconnect();
        this.start(wb);
      }
    });
    this.io.observe(this.box);
  }

  /** Creates the view once the FE wing is available. Never throws: failures show in the panel. */
  async start(wb) {
    if (this.started) return;
    this.started = true;
    if (typeof wb.WingView !== 'function') {
      this.unavailable('this build of the lab has no renderer (built without the `render` feature)');
      return;
    }
    let fe;
    try {
      this.status.textContent = 'Computing the shell FE wing (mesh + modes) in a worker, a few seconds…';
      fe = await this.lab.ensureFe();
    } catch (e) {
      this.unavailable(`the FE wing could not be computed: ${e && e.message ? e.message : e}`);
      return;
    }
    this.fe = fe;
    this.fitCanvas();
    try {
      this.view = await wb.WingView.createFromArrays(this.canvas, fe.nodes, fe.triangles, fe.shapes, fe.strain_nodes);
    } catch (e) {
      this.unavailable(e && e.message ? e.message : String(e));
      return;
    }
    // Back the camera off a little so the whole stroke (α up to ±0.8 rad) stays in view.
    this.view.zoom(1.35);
    this.box.dataset.state = 'ready';
    this.box.dataset.backend = this.view.backend();
    this.observer = new ResizeObserver(() => {
      if (this.fitCanvas()) this.draw();
    });
    this.observer.observe(this.stage);
    this.draw();
  }

  unavailable(why) {
    this.box.dataset.state = 'unavailable';
    this.box.replaceChildren(el('p', { class: 'wl-w3-fallback', text: `3-D view unavailable: ${why}. Everything else in the lab works without it.` }));
    this.status.textContent = '';
    this.controls.hidden = true;
  }

  stop() {
    this.setPlaying(false);
    if (this.io) this.io.disconnect();
    if (this.observer) this.observer.disconnect();
    if (this.view) this.view.free();
    this.view = null;
  }

  /** Sizes the drawing buffer to the stage (device pixels). Returns true when it changed. */
  fitCanvas() {
    const w = Math.max(160, Math.round(this.stage.clientWidth || 640));
    const h = Math.max(120, Math.round(Math.min(w * 0.55, 480)));
    const dpr = Math.min(2, window.devicePixelRatio || 1);
    const W = Math.round(w * dpr), H = Math.round(h * dpr);
    this.canvas.style.height = `${h}px`;
    if (this.canvas.width === W && this.canvas.height === H) return false;
    this.canvas.width = W;
    this.canvas.height = H;
    if (this.view) {
      try {
        this.view.resize(W, H);
      } catch (e) {
        this.status.textContent = `resize: ${e.message || e}`;
      }
    }
    return true;
  }

  bindCamera() {
    const c = this.canvas;
    let last = null;
    c.addEventListener('pointerdown', (e) => {
      last = [e.clientX, e.clientY];
      c.setPointerCapture(e.pointerId);
    });
    c.addEventListener('pointermove', (e) => {
      if (!last || !this.view) return;
      this.view.orbit(e.clientX - last[0], e.clientY - last[1]);
      last = [e.clientX, e.clientY];
      this.draw();
    });
    const end = () => { last = null; };
    c.addEventListener('pointerup', end);
    c.addEventListener('pointercancel', end);
    c.addEventListener('wheel', (e) => {
      if (!this.view) return;
      e.preventDefault();
      this.view.zoom(e.deltaY > 0 ? 1.1 : 1 / 1.1);
      this.draw();
    }, { passive: false });
    c.addEventListener('keydown', (e) => {
      if (!this.view) return;
      if (e.key === ' ') {
        e.preventDefault();
        this.setPlaying(!this.playing);
      } else if (this.view.key(e.key)) {
        e.preventDefault();
        this.draw();
      }
    });
  }

  /**
   * New simulation results (called after every live recompute). The frame is drawn on the next
   * animation frame, so a slider move's own redraw is not delayed by the 3-D view.
   */
  update(analysis, cfg) {
    this.analysis = analysis;
    this.cfg = cfg;
    const dur = analysis.sim.t[analysis.sim.t.length - 1] || 0;
    this.time.max = String(dur);
    this.time.step = String(1 / analysis.sim.sample_rate_hz);
    if (this.t > dur) this.t = 0;
    if (!this.view || this.playing || this.pending) return;
    this.pending = requestAnimationFrame(() => {
      this.pending = 0;
      this.draw();
    });
  }

  setPlaying(on) {
    this.playing = on && !!this.view;
    this.playBtn.textContent = this.playing ? 'Pause' : 'Play';
    this.playBtn.setAttribute('aria-pressed', String(this.playing));
    if (this.playing && !this.raf) {
      let prev = performance.now();
      const step = (now) => {
        if (!this.playing) {
          this.raf = 0;
          return;
        }
        const dur = Number(this.time.max) || 0;
        this.t += ((now - prev) / 1000) * Number(this.slow.value);
        prev = now;
        if (this.t > dur) this.t = 0;
        this.time.value = String(this.t);
        this.draw();
        this.raf = requestAnimationFrame(step);
      };
      this.raf = requestAnimationFrame(step);
    }
  }

  setTime(t) {
    const dur = Number(this.time.max) || 0;
    this.t = Math.min(dur, Math.max(0, Number.isFinite(t) ? t : 0));
    this.time.value = String(this.t);
    this.draw();
  }

  describeTime() {
    const a = this.analysis;
    const fd = a ? a.sim.flap_freq_hz : 25;
    const s = Number(this.slow.value);
    this.timeText.textContent = `t = ${this.t.toFixed(4)} s · flap ${fmtNum(fd)} Hz shown at ${fmtNum(fd * s)} Hz`;
    this.time.setAttribute('aria-valuetext', `${this.t.toFixed(4)} s`);
  }

  /** Draws the frame at this.t. Cheap enough for every animation frame. */
  draw() {
    const a = this.analysis;
    if (!this.view || !a) return;
    const sim = a.sim;
    const n = sim.t.length;
    const i = Math.min(n - 1, Math.max(0, Math.round(this.t * sim.sample_rate_hz)));
    let ang;
    try {
      // The pose at the sample's own time, from the same config as the responses (Eq. 1 angles).
      ang = this.lab.wb.anglesAt(this.cfg, new Float64Array([sim.t[i]]));
    } catch (e) {
      this.status.textContent = `kinematics: ${e.message || e}`;
      return;
    }
    const q = new Float64Array(sim.modes.map((m) => m.q.total[i]));
    const fe = this.lab.state.modes === 'fe';
    // Until the user moves it: true scale for the FE wing (its SI deflection is millimetres);
    // ×10 for the paper table, whose q are about ten times smaller than SI (Table 4).
    if (!this.exagTouched) this.exag.value = fe ? '0' : '1';
    const exag = 10 ** Number(this.exag.value);
    let legend;
    try {
      legend = this.view.set_frame(ang[0], ang[1], ang[2], q, exag, Number(this.colour.value));
      this.view.render();
    } catch (e) {
      this.status.textContent = `render: ${e.message || e}`;
      return;
    }
    this.frames += 1;
    this.box.dataset.frames = String(this.frames);
    this.describeTime();
    const defl = legend.max_deflection_m;
    this.exagText.textContent = `×${fmtNum(exag)}`;
    this.exag.setAttribute('aria-valuetext', `deflection drawn ${fmtNum(exag)} times true scale`);
    this.status.textContent =
      `${this.view.backend() === 'webgpu' ? 'WebGPU' : 'WebGL2'} · ${this.view.triangles()} triangles · ` +
      `α ${ang[0].toFixed(3)}, β ${ang[1].toFixed(3)}, γ ${ang[2].toFixed(3)} rad · ` +
      (fe ? `true largest deflection ${fmtNum(defl * 1e3)} mm, drawn ×${fmtNum(exag)}` : `largest deflection ${fmtNum(defl * 1e3)} (paper q units, not SI), drawn ×${fmtNum(exag)}`);
    this.drawLegend(legend, fe);
    this.note.textContent = fe
      ? `The shell-FE wing (synthetic Manduca-like outline, not digitised) with its first ${sim.modes.length} modes driven by the simulated q_k(t); strain per the FE modal strain fields (dimensionless, true scale).`
      : `Paper mode set: the paper's q_k(t) (Table 4 units, not SI) drawn on the shell-FE wing's first ${sim.modes.length} mode shapes, so shapes and timing are right and magnitudes are not physical. Choose the FE wing mode set for SI deflection and strain.`;
    if (this.lab.showTimeCursor) this.lab.showTimeCursor(sim.t[i]);
  }

  drawLegend(legend, fe) {
    const ctx = this.legend.getContext('2d');
    const { width: w, height: h } = this.legend;
    ctx.clearRect(0, 0, w, h);
    const stops = this.view.legend_stops();
    if (!stops.length || legend.component === 'none') {
      this.legend.hidden = true;
      this.legendText.textContent = 'plain shading';
      return;
    }
    this.legend.hidden = false;
    const lo = stops[0], hi = stops[stops.length - 4];
    const g = ctx.createLinearGradient(0, 0, w, 0);
    for (let j = 0; j < stops.length; j += 4) {
      const f = hi > lo ? (stops[j] - lo) / (hi - lo) : 0;
      const c = stops.slice(j + 1, j + 4).map((v) => Math.round(255 * Math.min(1, Math.max(0, v))));
      g.addColorStop(Math.min(1, Math.max(0, f)), `rgb(${c[0]},${c[1]},${c[2]})`);
    }
    ctx.fillStyle = g;
    ctx.fillRect(0, 0, w, h);
    const units = fe ? 'strain (–)' : '(FE strain × paper q: not physical)';
    this.legendText.textContent = `${legend.component}: ${fmtNum(legend.min)} … ${fmtNum(legend.max)} ${units}`;
  }
}
