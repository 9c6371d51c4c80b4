// @ts-check
// `wingbeat modes` documents in the lab (pure; the Wing panel's import and export): telling a
// modes document from an outline file, writing the chosen strain point into an exported
// document, finding where an imported document's strain point lies on its mesh, and turning a
// read document (wasm modesFromJson) into the lab's FE wing. No DOM; unit-tested in
// tests/js/strain_locate.test.mjs and tests/js/wingform.test.mjs.

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
    m.strains = [
      { point: CHOSEN_POINT, eps_x: strains[k].eps_x, eps_y: strains[k].eps_y, gamma_xy: strains[k].gamma_xy },
      ...rest,
    ];
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
    const a = triangles[t],
      b = triangles[t + 1],
      c = triangles[t + 2];
    let uu = 0,
      uv = 0,
      vv = 0,
      ur = 0,
      vr = 0;
    for (let j = 0; j < tv.length; j++) {
      const s0 = sv(a, j),
        u = sv(b, j) - s0,
        v = sv(c, j) - s0,
        r = tv[j] - s0;
      uu += u * u;
      uv += u * v;
      vv += v * v;
      ur += u * r;
      vr += v * r;
    }
    const det = uu * vv - uv * uv;
    if (!(Math.abs(det) > 1e-300)) continue;
    const l1 = (vv * ur - uv * vr) / det,
      l2 = (uu * vr - uv * ur) / det,
      l0 = 1 - l1 - l2;
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

/**
 * The lab's FE wing (what wasm feModes returns) from a read `wingbeat modes` document (wasm
 * modesFromJson's `{ modes, fe }`) and the document's text: flat typed arrays, one frequency and
 * kind per mode, `imported: true`, and the strain point located from the first point's strains
 * when the mesh reproduces them. Throws when the document has no FE mesh.
 * @param {{ modes: any[], fe?: any }} r
 * @param {string} text
 */
export function feFromModesDocument(r, text) {
  const f = r.fe;
  if (!f || !f.nodes)
    throw new Error(
      'the document has no FE mesh (nodes, triangles, shapes); the lab needs the full `wingbeat modes` output',
    );
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
  return fe;
}
