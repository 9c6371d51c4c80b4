// @ts-check
// Page bootstrap for index.html: registers <wing-lab> and applies the chrome-less iframe mode
// (?embed=1). The lab itself lives in lab.js.
import './lab.js';

const embed = new URLSearchParams(location.search).get('embed') === '1';
if (embed) {
  document.documentElement.classList.add('embed');
  const lab = document.getElementById('lab');
  if (lab) lab.setAttribute('embed', '');
}
