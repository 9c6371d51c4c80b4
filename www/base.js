// @ts-check
// The lab's folder (www/: index.html, lab.js, worker.js, pkg/, vendor/, style.css), as an
// absolute URL. The one place that reads import.meta.url for it: this file sits in the folder's
// root, and so does the built bundle of the lab's modules (lab.bundle.js, scripts/bundle.mjs),
// so the URL is the same whether the lab runs from its modules or from the bundle, and also when
// it is loaded from another origin.
export const WWW = new URL('./', import.meta.url);
