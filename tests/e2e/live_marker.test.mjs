// The 3-D view's instant on the responses plot (www/plot/live-marker.js): a line over the plot at
// the store's `t3d`, placed by the x scale, moved without repainting the plot's canvas (while the
// view plays it moves every frame), hidden outside the x window, and placed again when the
// window changes. Pixels and positions, in Chromium.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { setup, openPage, waitRenders } from './helpers.mjs';

let env;
before(async () => {
  env = await setup();
});
after(async () => {
  if (env) await env.close();
});

/** The marker's state and where the x scale puts t3d, and a fingerprint of the plot's canvas. */
const read = (page) =>
  page.evaluate(() => {
    const plot = __wl.q('[data-plot="time"]');
    const m = /** @type {HTMLElement} */ (plot.querySelector('.wl-live-marker'));
    const label = /** @type {HTMLElement} */ (plot.querySelector('.wl-live-marker-label'));
    const canvas = /** @type {HTMLCanvasElement} */ (plot.querySelector('canvas'));
    const over = /** @type {HTMLElement} */ (plot.querySelector('.u-over'));
    const lab = __wl.lab();
    const t3d = lab.store.get().t3d;
    const mr = m.getBoundingClientRect(),
      or = over.getBoundingClientRect();
    return {
      shown: m.style.display !== 'none',
      label: label.textContent,
      // the line's centre, CSS px from the plotting area's left edge
      centre: mr.left + mr.width / 2 - or.left,
      overWidth: or.width,
      t3d,
      canvas: canvas.toDataURL(),
    };
  });

test('the 3-D instant moves over the responses plot without repainting it, and hides outside the window', async () => {
  const { page, context, problems } = await openPage(env.browser, env.url, { width: 1280, height: 800 });
  try {
    await page.goto(env.url);
    await waitRenders(page, 1);
    // the window is the beat's (about 0.14–0.39 s for the paper case)
    const win = await page.evaluate(() => __wl.lab().views.time.main.xWindow());
    const at = (t) => (t - win[0]) / (win[1] - win[0]);
    const set = async (t) => {
      await page.evaluate((x) => __wl.lab().store.set({ t3d: x, playing: false }), t);
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      return read(page);
    };
    const t1 = win[0] + 0.3 * (win[1] - win[0]);
    const t2 = win[0] + 0.7 * (win[1] - win[0]);
    const a = await set(t1);
    assert.equal(a.shown, true);
    assert.equal(a.label, '3-D t');
    assert.ok(Math.abs(a.centre - at(t1) * a.overWidth) < 1.5, `${a.centre} vs ${at(t1) * a.overWidth}`);
    const b = await set(t2);
    assert.ok(Math.abs(b.centre - at(t2) * b.overWidth) < 1.5, `${b.centre} vs ${at(t2) * b.overWidth}`);
    assert.ok(b.centre - a.centre > 0.3 * a.overWidth, 'it moved right by 40 % of the width');
    assert.equal(b.canvas, a.canvas, 'the plot itself was not repainted');
    // Outside the window: hidden. A window that contains it again (the whole run): shown at its place.
    const c = await set(win[1] + 0.5);
    assert.equal(c.shown, false);
    await page.evaluate(() => {
      const u = __wl.lab().views.time.main.u;
      u.setScale('x', { min: u.data[0][0], max: u.data[0][u.data[0].length - 1] });
    });
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const d = await read(page);
    const whole = await page.evaluate(() => __wl.lab().views.time.main.xWindow());
    assert.equal(d.shown, true);
    const frac = (d.t3d - whole[0]) / (whole[1] - whole[0]);
    assert.ok(Math.abs(d.centre - frac * d.overWidth) < 1.5, `${d.centre} vs ${frac * d.overWidth}`);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
