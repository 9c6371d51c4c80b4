// @ts-check
// The guided experiments' number format (www/experiments.js and its parts in www/experiments/).

/**
 * Compact number formatting in the lab's rich-label markup (www/format.js): exponents as
 * ×10^{k}, a real minus sign. The sentences below are markup too (f_{eff}, γ_0, ω_1), rendered
 * with sub/superscripts by the view and as plain text by `plain`.
 */
export function fmt(v, digits = 4) {
  if (v == null || Number.isNaN(v)) return '—';
  if (!Number.isFinite(v)) return v > 0 ? '∞' : '−∞';
  if (v === 0) return '0';
  const a = Math.abs(v);
  const minus = (t) => t.replace(/-/g, '−');
  if (a >= 1e5 || a < 1e-3) {
    const [m, e] = v.toExponential(digits - 1).split('e');
    return minus(`${m}×10^{${Number(e)}}`);
  }
  return minus(Number(v.toPrecision(digits)).toString());
}
