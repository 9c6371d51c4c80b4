// @ts-check
// A vertical marker that moves without repainting its plot: a line and a label as elements
// over uPlot's plotting area (`u.over`), placed from the x scale. For a value that changes on
// every animation frame (the 3-D view's instant while it plays), moving an element is one
// style write; a marker drawn on the canvas repainted every series of the plot each frame (at
// f_d = 25.5 Hz over 10 s: 100 000 samples a series), which kept the main thread busy and key
// presses waiting for their paint.

/**
 * @typedef {{ label: string, color: string, width?: number }} LiveMarkerSpec
 * The part of a uPlot the marker needs.
 * @typedef {{ over: HTMLElement, bbox: { width: number }, valToPos: (v: number, scale: string) => number }} LivePlot
 */

/**
 * Adds the marker to `u`, hidden until it has a value inside the x window.
 * @param {LivePlot} u
 * @param {LiveMarkerSpec} spec
 */
export function liveMarker(u, spec) {
  const width = spec.width ?? 1.5;
  const line = document.createElement('div');
  line.className = 'wl-live-marker';
  line.setAttribute('aria-hidden', 'true');
  Object.assign(line.style, {
    position: 'absolute',
    top: '0',
    bottom: '0',
    left: '0',
    width: `${width}px`,
    background: spec.color,
    pointerEvents: 'none',
    display: 'none',
  });
  const label = document.createElement('span');
  label.className = 'wl-live-marker-label';
  label.setAttribute('aria-hidden', 'true');
  label.textContent = spec.label;
  Object.assign(label.style, {
    position: 'absolute',
    // below the three rows the canvas markers' labels may take (www/plot/marks.js)
    top: '41px',
    left: '0',
    font: '11px system-ui, sans-serif',
    lineHeight: '13px',
    color: spec.color,
    background: 'rgba(255,255,255,0.8)',
    padding: '0 1px',
    whiteSpace: 'nowrap',
    pointerEvents: 'none',
    display: 'none',
  });
  u.over.append(line, label);
  /** @type {number | null} */
  let x = null;
  let shown = false;
  const place = () => {
    const px = x == null ? Number.NaN : u.valToPos(x, 'x');
    // The plotting area's width from uPlot's own box (device pixels): reading the element's
    // size here would force a layout on every frame.
    const inside = Number.isFinite(px) && px >= 0 && px <= u.bbox.width / (globalThis.devicePixelRatio || 1);
    if (inside !== shown) {
      shown = inside;
      line.style.display = label.style.display = inside ? '' : 'none';
    }
    if (!inside) return;
    line.style.transform = `translateX(${px - width / 2}px)`;
    label.style.transform = `translateX(${px + 2}px)`;
  };
  return {
    /** Moves the marker to `v` (x units); null hides it. @param {number | null} v */
    set(v) {
      x = v != null && Number.isFinite(v) ? v : null;
      place();
    },
    /** Places it again after the x scale or the size changed (the plot's draw hook). */
    place,
    /** The value shown, or null. */
    get x() {
      return x;
    },
    /** Whether it is inside the x window and shown. */
    get shown() {
      return shown;
    },
  };
}
