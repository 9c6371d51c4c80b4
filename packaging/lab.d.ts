// Types of the `<wing-lab>` custom element (wingbeat-lab's main entry, lab.js). Hand-written
// for the package; the wasm API's own types are in ./pkg/wingbeat.d.ts (export "./api").
// Importing the module registers the element (a side effect); it exports the class as well.

import type { Analysis, FeModesResult, SimConfig } from './pkg/wingbeat.js';

/** The lab's parameters, as attributes, URL parameters and the `state` property. */
export interface WingLabParams {
  alpha0: number;
  beta0: number;
  gamma0: number;
  flap_hz: number;
  zeta: number;
  alpha_phase: number;
  beta_phase: number;
  gamma_phase: number;
  duration: number;
  modes: 'paper' | 'fe';
  mode: '1' | '2' | '3' | '4' | '5' | '6' | '7' | '8';
  detrend: 'none' | 'mean' | 'linear';
  /** Wing parameters (camber, clamp, e_pa, rho, nu, thickness_um, mesh_mm, n_modes) and others. */
  [key: string]: unknown;
}

/** The observable state behind the element (www/store.js). */
export interface WingLabStore {
  /** The current state: the parameters plus derived keys such as `result`, `fe`, `status`. */
  get(): Readonly<Record<string, unknown> & Partial<WingLabParams>>;
  /** Shallow-merges `patch` (e.g. `{ gamma0: 0.1 }`), recomputes, returns the changed keys. */
  set(patch: Partial<WingLabParams> & Record<string, unknown>): string[];
  /** Calls `fn` after each change of one of `keys` ('*': any); returns the unsubscribe function. */
  subscribe(
    keys: string[] | '*',
    fn: (state: Readonly<Record<string, unknown>>, changed: string[]) => void,
  ): () => void;
}

/** `detail` of `wl-rendered`: milliseconds spent computing and drawing the latest redraw. */
export interface WingLabRenderedDetail {
  compute: number;
  draw: number;
  end: number;
}

/** `detail` of `wl-study`: which study finished (e.g. 'fig6', 'resonance', 'reproduce'). */
export interface WingLabStudyDetail {
  kind: string;
  [key: string]: unknown;
}

export interface WingLabEventMap extends HTMLElementEventMap {
  /** The wasm module is loaded. */
  'wl-ready': CustomEvent<unknown>;
  /** After every redraw. */
  'wl-rendered': CustomEvent<WingLabRenderedDetail>;
  /** A study finished. */
  'wl-study': CustomEvent<WingLabStudyDetail>;
}

/**
 * `<wing-lab>`: the wingbeat lab as a custom element, rendered in an open shadow root.
 *
 * Attributes (all optional, read on connect, later changes apply): `alpha0`, `beta0`, `gamma0`,
 * `flap_hz`, `zeta`, `alpha_phase`, `beta_phase`, `gamma_phase`, `duration`, `mode`, `modes`,
 * `detrend`, the wing's `camber`, `clamp`, `e_pa`, `rho`, `nu`, `thickness_um`, `mesh_mm`,
 * `n_modes`, `outline`, `panels` (comma-separated subset of the panels), `embed` (one column),
 * `layout`, `sync-url`. The element sets `data-layout` (`wide` | `medium` | `narrow`) and
 * `data-renders` (redraw count) on itself. Events bubble and are `composed`.
 */
export declare class WingLab extends HTMLElement {
  /** The current parameters (defaults before the element has connected). */
  readonly state: WingLabParams;
  /** The observable state; `store.set({ gamma0: 0.1 })` drives the lab. Set once connected. */
  readonly store: WingLabStore | undefined;
  /** The latest analysis of the wasm core (undefined until the first computation). */
  readonly analysis: Analysis | undefined;
  /** The uPlot instances of the visible plots, by name. */
  readonly plots: Record<string, unknown>;
  /** The FE wing in use, or null (paper modes, or not computed yet). */
  readonly fe: FeModesResult | null;
  /** The 3-D view's handle when the `wing3d` panel is built. */
  readonly wing3d: unknown;
  /** The core's SimConfig for the current parameters. */
  config(): SimConfig;

  addEventListener<K extends keyof WingLabEventMap>(
    type: K,
    listener: (this: WingLab, ev: WingLabEventMap[K]) => unknown,
    options?: boolean | AddEventListenerOptions,
  ): void;
  addEventListener(
    type: string,
    listener: EventListenerOrEventListenerObject,
    options?: boolean | AddEventListenerOptions,
  ): void;
  removeEventListener<K extends keyof WingLabEventMap>(
    type: K,
    listener: (this: WingLab, ev: WingLabEventMap[K]) => unknown,
    options?: boolean | EventListenerOptions,
  ): void;
  removeEventListener(
    type: string,
    listener: EventListenerOrEventListenerObject,
    options?: boolean | EventListenerOptions,
  ): void;
}

/** Loads (once) and returns the wasm module's API, resolved next to lab.js. */
export declare function loadWasm(): Promise<typeof import('./pkg/wingbeat.js')>;

declare global {
  interface HTMLElementTagNameMap {
    'wing-lab': WingLab;
  }
}
