// @ts-check
// The lab's panels: the view module of each (views/<panel>.js) and their DOM order. Used by
// www/lab.js, which mounts them into its grid.
import * as controls from '../views/controls.js';
import * as numbers from '../views/numbers.js';
import * as time from '../views/time.js';
import * as spectrum from '../views/spectrum.js';
import * as strain from '../views/strain.js';
import * as studies from '../views/studies.js';
import * as wing3d from '../views/wing3d.js';
import * as report from '../views/report.js';
import * as experiments from '../views/experiments.js';
import * as resonance from '../views/resonance.js';
import * as wing from '../views/wing.js';
import * as kinematics from '../views/kinematics.js';
import * as modeshape from '../views/modeshape.js';
import * as sensing from '../views/sensing.js';
import * as neural from '../views/neural.js';

/** The view of each panel, by name (www/state.js PANELS). */
export const VIEWS = {
  controls,
  numbers,
  time,
  spectrum,
  strain,
  studies,
  wing3d,
  report,
  experiments,
  resonance,
  wing,
  kinematics,
  modeshape,
  sensing,
  neural,
};
/** DOM (= tab) order of the panels; layout.js places them so that it is also the visual order. */
export const LAYOUT = [
  'wing3d',
  'controls',
  'time',
  'experiments',
  'wing',
  'kinematics',
  'spectrum',
  'numbers',
  'modeshape',
  'strain',
  'sensing',
  'neural',
  'studies',
  'resonance',
  'report',
];
