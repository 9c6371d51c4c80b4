// @ts-check
// "As a neuron sees it" (docs/sensing.md, "Classifying rotation"; docs/lab.md): the published
// sensing study (Mohren et al. 2018) on its plate, in the study worker (wasm classifyRotation):
// rotation or none told from the spanwise strain at 338 points, encoded as a neuron fires or
// raw. Shows the accuracy against the number of sensors for random sets (mean ± sd) and SSPOC's
// sparse sets, the all-sensor line and the published random points; where a chosen set sits on
// the plate; and our numbers beside the paper's. The same study, with the same request, as the
// guided experiment `neural-sensing`: both read it from the page's study cache
// (www/lab/study-cache.js), so it runs once and both say the same. Runs only when asked (a
// button), with progress and Cancel. Reads nothing from the store: the plate, its kinematics
// and sensors are the published ones, whatever the lab's own wing.
import { el, srOnly } from '../dom.js';
import { fmt } from '../format.js';
import { linePlot } from '../plot.js';
import { NEURAL_STUDY, bestSparse } from '../experiments/neural.js';
import { study, peekStudy, watchStudy, cancelStudy, studyKey } from '../lab/study-cache.js';
import { STRAINS, curveColumns, setChoices, setOf, comparisonRows, sensorWords, neuralWords } from './neural-data.js';
import { drawPlate, CHOSEN } from './neural-plate.js';

export const title = 'As a neuron sees it';

/** The page-wide key of the study this panel shows (the guided experiment's). */
export const NEURAL_KEY = studyKey(NEURAL_STUDY.kind, NEURAL_STUDY.opts);

/** @param {import('../lab.js').ViewContext} ctx */
export function mount(ctx) {
  const { section, engine } = ctx;
  section.append(
    el('p', {
      class: 'wl-note',
      rich: 'Can a wing feel the body turn? Mohren et al. (2018) flapped a 50 × 25 mm plate at 25 Hz, still or turning at 10 rad/s about its normal, and asked a linear classifier to tell the two apart from the strain at many points, each point first encoded as a strain-sensing neuron would fire (a filter over the last ~40 ms, then a sigmoid). This panel runs their study on wingbeat’s FE plate (338 sensors, 2 mm apart; 90 % of the 3 s trains, 10 % tests; chance is 50 %).',
    }),
  );
  const run = el('button', {
    type: 'button',
    class: 'wl-run',
    text: 'Run the study (about 6 s)',
    'data-run': 'neural',
  });
  const cancel = el('button', { type: 'button', class: 'wl-cancel', text: 'Cancel', hidden: true });
  const prog = el('progress', { class: 'wl-progress', hidden: true, 'aria-label': 'classification progress' });
  const status = el('span', { class: 'wl-status', role: 'status' });
  section.append(el('div', { class: 'wl-study-controls' }, run, cancel, prog, status));

  // Which strain: encoded (as a neuron fires) or raw.
  const strainBox = el('fieldset', { class: 'wl-neural-strain' }, el('legend', { text: 'Strain' }));
  /** @type {HTMLInputElement[]} */
  const radios = STRAINS.map((s, i) => {
    const r = /** @type {HTMLInputElement} */ (
      el('input', { type: 'radio', name: ctx.id('neural-strain'), value: s.id, id: ctx.id(`neural-${s.id}`) })
    );
    r.checked = i === 0;
    r.addEventListener('change', () => draw());
    strainBox.append(el('label', { for: r.id }, r, ` ${s.label}`));
    return r;
  });
  const body = el('div', { class: 'wl-neural-body', hidden: true });
  section.append(body);
  body.append(strainBox, el('h3', { class: 'wl-smap-title', text: 'How many sensors does it take?' }));
  const plot = linePlot(body, {
    name: 'neural-accuracy',
    title: 'Classification accuracy against the number of sensors',
    ariaLabel:
      'Plot of the test accuracy against the number of sensors: random sets (mean and ± one standard deviation), SSPOC sets, all sensors and the published random sets',
    xLabel: 'sensors',
    xUnit: 'count',
    yLabel: 'test accuracy (%)',
    series: [
      { label: 'random sets, mean', color: '#1f5fbf', width: 2, span: true, with: [1, 2] },
      { label: '± 1 sd', color: '#1f5fbf', dash: [3, 3], span: true, legend: false },
      { label: '− 1 sd', color: '#1f5fbf', dash: [3, 3], span: true, legend: false },
      { label: 'SSPOC sets', color: CHOSEN, points: true },
      { label: 'all sensors', color: '#2a7f3f', dash: [6, 3], width: 1.5 },
      { label: 'published random (Mohren 2018)', color: '#222', points: true },
      { label: 'greedy d′ sets', color: '#7b3294', width: 1.5, span: true },
    ],
    keys: false,
    height: 220,
  });
  ctx.registerPlot('neural-accuracy', plot);
  const words = el('p', { class: 'wl-note' });
  body.append(words);
  body.append(el('h3', { class: 'wl-smap-title', text: 'Where the chosen sensors sit' }));
  const chooser = /** @type {HTMLSelectElement} */ (el('select', { id: ctx.id('neural-set') }));
  chooser.addEventListener('change', () => drawSet());
  body.append(el('p', { class: 'wl-neural-pick' }, el('label', { for: chooser.id, text: 'Sensor set: ' }), chooser));
  const canvas = /** @type {HTMLCanvasElement} */ (el('canvas', { class: 'wl-neural-plate', role: 'img' }));
  const setWords = el('p', { class: 'wl-note' });
  body.append(canvas, setWords);
  const table = el('table', { class: 'wl-reporttable wl-neural-table' });
  body.append(el('h3', { class: 'wl-smap-title', text: 'Beside the published study' }), table, srOnly('p'));

  /** @returns {any} the report, or null */
  const report = () => {
    const e = peekStudy(NEURAL_KEY);
    return e && e.result ? e.result.report : null;
  };
  const strain = () => (radios.find((r) => r.checked) || radios[0]).value;

  function drawSet() {
    const rep = report();
    if (!rep) return;
    const c = rep[strain()];
    const set = setOf(c, chooser.value);
    const idx = set ? set.sensors : [];
    drawPlate(canvas, rep.sensors, idx, section.clientWidth - 24 || 600);
    const where = sensorWords(idx, rep.sensors);
    canvas.setAttribute('aria-label', `The plate, root on the left, with the chosen sensor set: ${where}`);
    setWords.textContent = set
      ? `${where}. Test accuracy with them: ${fmt(100 * set.accuracy, 3)} %.`
      : 'No sensor set.';
    section.dataset.neuralSet = String(idx.length);
  }

  function draw() {
    const rep = report();
    if (!rep) return;
    const which = strain();
    const c = rep[which];
    plot.setData(/** @type {any} */ (curveColumns(c, which === 'encoded')));
    const one = c.random.find((/** @type {any} */ r) => r.sensors === 1);
    plot.setSummary(
      `${which} strain: all ${rep.sensors.length} sensors ${fmt(100 * c.all_sensors, 3)} %; one random sensor ${one ? fmt(100 * one.mean, 3) : '—'} %.`,
    );
    words.textContent = neuralWords(rep, which);
    const best = bestSparse(c, 15);
    chooser.replaceChildren(...setChoices(c).map((o) => el('option', { value: o.value, text: o.text })));
    chooser.value = `sspoc:${Math.max(0, best ? c.sparse.indexOf(best) : 0)}`;
    drawSet();
    table.replaceChildren(
      el(
        'thead',
        {},
        el(
          'tr',
          {},
          ...['Sensors', 'Encoded, here', 'Raw, here', 'Published (encoded)'].map((h) =>
            el('th', { scope: 'col', text: h }),
          ),
        ),
      ),
      el('tbody', {}, ...comparisonRows(rep).map((row) => el('tr', {}, ...row.map((v) => el('td', { text: v }))))),
    );
    section.dataset.state = 'ready';
  }

  function refresh() {
    const e = peekStudy(NEURAL_KEY);
    const busy = !!e && !e.result && !e.error && !e.cancelled;
    run.disabled = busy;
    cancel.hidden = !busy;
    prog.hidden = !busy;
    if (e && e.total) {
      prog.max = e.total;
      prog.value = e.done;
    }
    if (!e) {
      status.textContent = 'Not run yet.';
      section.dataset.state = 'idle';
    } else if (e.error) {
      status.textContent = `The study failed: ${e.error}`;
      section.dataset.state = 'error';
    } else if (e.cancelled && !e.result) {
      status.textContent = 'Cancelled.';
      section.dataset.state = 'cancelled';
    } else if (busy) {
      status.textContent = `Computing in the study worker: the FE plate, two 4 s runs, the encoding and the classifiers (stage ${e.done} of ${e.total || '…'})…`;
      section.dataset.state = 'computing';
    } else {
      const m = e.result.modes;
      status.textContent = `Done: the plate's first modes ${m
        .slice(0, 2)
        .map((/** @type {any} */ x) => `${fmt(x.freq_hz, 3)} Hz`)
        .join(', ')}; ${e.result.report.test_samples} test samples per class.`;
    }
    body.hidden = !report();
    if (report() && section.dataset.state !== 'ready') draw();
  }

  const COLS = [
    'random mean',
    'random mean + sd',
    'random mean − sd',
    'SSPOC (best set of the size)',
    'all sensors',
    'published random (Mohren 2018)',
  ];
  ctx.registerExport('neural', {
    csv: () => {
      const rep = report();
      if (!rep) return null;
      const which = strain();
      const [x, ...ys] = curveColumns(rep[which], which === 'encoded');
      return ctx.toCSV(
        [
          { name: 'sensors', unit: 'count', values: x },
          ...ys.map((values, i) => ({ name: COLS[i], unit: '%', values })),
        ],
        [
          `wingbeat lab; As a neuron sees it (Mohren et al. 2018 setup on the FE plate), ${which} strain`,
          `request ${JSON.stringify(NEURAL_STUDY.opts)}`,
        ],
      );
    },
    figure: () => {
      const rep = report();
      if (!rep) return null;
      const which = strain();
      return {
        title: `Rotation or none from ${which} strain: accuracy against the number of sensors`,
        params: `Mohren et al. 2018 plate on wingbeat's FE; ${rep.sensors.length} sensors, 2 mm grid`,
        x: plot.u.data[0],
        xLabel: 'sensors (count)',
        yLabel: 'test accuracy (%)',
        series: plot.exportSeries(),
      };
    },
  });

  run.addEventListener('click', () => {
    study(engine, NEURAL_STUDY.kind, { opts: NEURAL_STUDY.opts }, NEURAL_KEY, { restart: true });
    refresh();
  });
  cancel.addEventListener('click', () => cancelStudy(engine, NEURAL_KEY));
  const unwatch = watchStudy(NEURAL_KEY, refresh);
  refresh();
  return {
    destroy() {
      unwatch();
      plot.destroy();
    },
  };
}
