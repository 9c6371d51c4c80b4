// @ts-check
// Optional: building this course site with Vite (npm run build → dist/). The lab loads its
// worker, stylesheets and wasm module next to its own lab.js, so it is kept out of the bundle
// (external; the page's import map resolves `wingbeat-lab`) and its installed folder is
// published unchanged at the URL the import map names. The Vite dev server needs nothing special.
import { cpSync } from 'node:fs';

export default {
  optimizeDeps: { exclude: ['wingbeat-lab'] },
  build: { rollupOptions: { external: ['wingbeat-lab'] } },
  plugins: [
    {
      name: 'wingbeat-lab-files',
      apply: /** @type {const} */ ('build'),
      closeBundle() {
        cpSync('node_modules/wingbeat-lab', 'dist/node_modules/wingbeat-lab', { recursive: true });
      },
    },
  ],
};
