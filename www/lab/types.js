// @ts-check
// The types of the element's state and of what a view gets (JSDoc only: this module exports no
// values). www/lab.js re-exports them, so views write import('../lab.js').ViewContext.

/**
 * The store's state: the URL parameters plus what the engine and the views derive.
 * @typedef {import('../state.js').Params & {
 *   result: import('../engine.js').LiveResult | null,
 *   fe: import('../engine.js').FeModesResult | null,
 *   t3d: number | null,
 *   playing: boolean,
 *   timing: { compute: number, draw: number, end: number } | null,
 *   status: string | null,
 *   wing: WingState | null,
 *   kin: KinState | null,
 *   strain_point: [number, number] | null,
 *   strain_map: { component: 'eps_x' | 'eps_y' | 'gamma_xy' | 'von_mises', stat: 'rms' | 'peak' } | null,
 *   sense_map?: import('../views/sensing.js').SenseMap | null,
 * }} LabState
 */
/**
 * The wing in use when it is not the lab's default FE wing: the FemInput it was computed from
 * (null for imported modes), where it came from, and its outline (mm) for the editor and the
 * share fragment. `null` = the default wing (the paper table or the default FE wing).
 * @typedef {{ input: import('../pkg/wingbeat.js').FemInput | null, source: 'builtin' | 'file' | 'edited' | 'url' | 'import' | 'share', label: string, outline: string, points: [number, number][] | null }} WingState
 */
/**
 * Custom kinematics (null = the sliders' Fourier kinematics): the core's Kinematics, where they
 * came from, and for a measured table its samples (rad, one period) and the CSV text.
 * @typedef {{ kinematics: import('../pkg/wingbeat.js').Kinematics, source: 'csv' | 'edited' | 'share', label: string,
 *   samples?: { t: Float64Array | number[], alpha: Float64Array | number[], beta: Float64Array | number[], gamma: Float64Array | number[] } | null,
 *   csv?: { text: string, units: 'deg' | 'rad', flap_hz: number } | null }} KinState
 */
/** @typedef {ReturnType<typeof import('../plot.js').linePlot>} Plot */
/**
 * What a panel registers for export (each optional; `null` when there is nothing to export yet).
 * @typedef {{ csv?: () => string | null, figure?: () => any, table?: () => any, canvas?: () => HTMLCanvasElement | null }} ExportReg
 */
/**
 * What a view gets from the element (see the module map in www/lab.js).
 * @typedef {{
 *   store: import('../store.js').Store<LabState>,
 *   engine: ReturnType<typeof import('../engine.js').createEngine>,
 *   section: HTMLElement,
 *   uid: string,
 *   id: (s: string) => string,
 *   toCSV: typeof import('../export.js').toCSV,
 *   registerPlot: (name: string, plot: Plot) => void,
 *   registerExport: (name: string, reg: ExportReg) => void,
 *   exportButtons: (name: string, label: string, kinds?: string[]) => HTMLElement,
 *   emit: (type: string, detail?: unknown) => void,
 *   notice: (text: string) => void,
 *   setParams: (patch: Partial<LabState>) => void,
 *   showPanel: (name: string) => void,
 * }} ViewContext
 */
/** A mounted view: destroy() always; some views add hooks (startWhenVisible, setLayout, studies …). */
/** @typedef {{ destroy(): void, [hook: string]: any }} View */

export {};
