// The seeded PRNG of the randomised JS tests (mulberry32: uniform in [0, 1)), so a failing
// seed reproduces. Not a test file itself (node --test picks up *.test.mjs only).

/** @param {number} seed */
export function prng(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
