// Times wing_f1 (compute_modes of the default wing) in Node's wasm engine (V8, as in
// Chromium) for each backend present in the given .wasm files.
//   node bench.mjs skyline.wasm [faer.wasm]
import { readFileSync } from 'node:fs';

const meshes = [2.0, 1.25, 1.0, 0.75];
for (const file of process.argv.slice(2)) {
  const { instance } = await WebAssembly.instantiate(readFileSync(file), {});
  const f1 = instance.exports.wing_f1;
  const backends = file.includes('faer') ? [0, 1] : [0];
  for (const b of backends) {
    for (const h of meshes) {
      const times = [];
      let f = NaN;
      for (let r = 0; r < 3; r++) {
        const t = performance.now();
        f = f1(h, b);
        times.push(performance.now() - t);
      }
      times.sort((x, y) => x - y);
      console.log(
        `${file} backend=${b ? 'faer' : 'skyline'} h=${h} mm f1=${f.toFixed(6)} Hz median ${times[1].toFixed(1)} ms`,
      );
    }
  }
}
