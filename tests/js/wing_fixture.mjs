// The flat test wing shared by the 3-D tests (scene3d, wing3d camera, marks and picking). Not a
// test file itself (node --test picks up *.test.mjs only).

/**
 * A flat rectangular "wing": span 0.05 m along x, chord 0.02 m toward −y, on an 11 × 5 grid of
 * nodes, with one mode whose shape is the node's x (a bending-like deflection growing to the tip).
 */
export function flatWing() {
  const nodes = [],
    tris = [];
  for (let i = 0; i <= 10; i++) for (let j = 0; j <= 4; j++) nodes.push(0.005 * i, -0.005 * j, 0);
  for (let i = 0; i < 10; i++)
    for (let j = 0; j < 4; j++) {
      const a = i * 5 + j,
        b = a + 5;
      tris.push(a, b, a + 1, b, b + 1, a + 1);
    }
  const n = nodes.length / 3;
  return {
    nodes: Float64Array.from(nodes),
    triangles: Uint32Array.from(tris),
    shapes: Float64Array.from({ length: n }, (_, i) => nodes[3 * i]),
  };
}
