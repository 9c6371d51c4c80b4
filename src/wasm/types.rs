//! The TypeScript declarations of the wasm API's inputs and results, emitted into the
//! generated `.d.ts` by wasm-bindgen. They describe the serde types of the core (field for
//! field) and the objects built in [`super::marshal`]; `tests/ts_types.rs` (and the wasm suites)
//! read the string below from this file and fail when it drifts from the types.

use wasm_bindgen::prelude::*;

/// The declarations, as wasm-bindgen writes them into `wingbeat.d.ts`.
#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &'static str = r#"
/** One harmonic `amplitude · sin(n ω_d t + phase)`; rad. */
export interface Harmonic { n: number; amplitude: number; phase?: number }
/** How one angle is given: mean + harmonics, or samples over one period (rad). */
export type Angle =
  | { kind: "fourier"; mean?: number; harmonics?: Harmonic[] }
  | { kind: "sampled"; values: number[]; max_harmonic?: number | null };
/** Body angular velocity ω_b(t) in body axes (I, J, K), rad/s, each component given like an angle; missing components are zero. */
export interface BodyRate { x?: Angle; y?: Angle; z?: Angle }
/** Rotation kinematics (paper §2.1, Eq. 1); `body_rate` omitted = no body rotation. */
export interface Kinematics { flap_freq_hz: number; alpha: Angle; beta: Angle; gamma: Angle; body_rate?: BodyRate }
/** Modal strain at a named point, per unit q (Eqs. 16–18). */
export interface ModalStrain { point: string; eps_x: number; eps_y: number; gamma_xy: number }
/** One vibration mode: ω_k/2π in Hz, a_k in kg^½·m, damping ratio ζ. */
export interface Mode { name?: string; freq_hz: number; a: [number, number]; zeta?: number; strains?: ModalStrain[] }
/** A simulation request; every field is optional (missing = the paper's forward-flight case). */
export interface SimConfig {
  kinematics?: Kinematics;
  modes?: Mode[];
  duration_s?: number;
  sample_rate_hz?: number;
  initial_conditions?: [number, number][];
  /** The fluid around the wing (default: vacuum, the paper). A density above 0 needs `wing`. */
  aero?: AeroConfig;
  /** The mesh and mode shapes air needs, in `feModes`' layout (`cfg.wing = fe` works). Not JSON: it is read as typed arrays and never returned. */
  wing?: WingInput;
}
/** The medium and the quasi-steady aerodynamic model (docs/model.md, "The wing in air"). */
export interface AeroConfig { air_density_kg_m3?: number; normal_force_coefficient?: number; added_mass?: boolean; strips?: number; chord_points?: number }
/** A named medium of `media()`: its density, kg/m³. */
export interface Medium { name: string; density_kg_m3: number }
/** An FE wing for the air: nodes (x, y, z per node, m), triangles (3 node indices each), shapes (mode-major, one per node and mode of the config, kg^-½). */
export interface WingInput { nodes: Float64Array | number[]; triangles: Uint32Array | number[]; shapes: Float64Array | number[] }
/** Welch PSD options (Hann window). detrend "none" keeps the DC part visible. */
export interface WelchOptions { segment_len?: number; overlap?: number; detrend?: "none" | "mean" | "linear"; max_peaks?: number }
export type SweepParam = "gamma0" | "alpha0" | "beta0" | "flap_hz" | "zeta";
export interface SweepOptions { param: SweepParam; from: number; to: number; points: number }
export interface IcMapOptions {
  mode?: number; n_q?: number; n_qdot?: number;
  q_range?: [number, number] | null; qdot_range?: [number, number] | null;
  attribution?: "forced" | "carried";
}
/** Shares of the total response's RMS, %. `aerodynamic` only in a medium. */
export interface Contributions { euler: number; centrifugal: number; coriolis: number; aerodynamic?: number }
export interface FloquetResult {
  multipliers: [number, number][]; monodromy: [[number, number], [number, number]];
  stable: boolean; max_modulus: number; growth_rate_per_s: number; homogeneous_period_s: number;
  characteristic_freq_hz: number; dominant_harmonic: number; effective_freq_hz: number;
  averaged_freq_hz: number; beat_harmonic: number;
  /** null when f_eff coincides with n·f_d, and for an unstable mode (|λ| > 1: growth, not a beat). */
  beat_period_s: number | null;
  beat_period_vs_2fd_s: number | null;
}
export interface Accuracy { method: string; period_error_estimate: number; periods: number; run_error_bound: number }
export interface Responses { euler: Float64Array; centrifugal: Float64Array; coriolis: Float64Array; free: Float64Array; total: Float64Array; aerodynamic?: Float64Array }
/** What air does to one mode (only in a medium). */
export interface ModeAir {
  still_air_freq_hz: number; added_mass_shift_hz: number; aero_damping_ratio: number;
  decay_rate_per_s: number; decay_time_s: number | null; beat: string; participation: number;
}
/** The run's air summary (only in a medium). */
export interface AirSummary {
  aero: AeroConfig; area_m2: number; points: number; added_mass: number[][];
  multipliers: [number, number][]; stable: boolean; steps_per_period: number;
}
export interface ModeResult {
  name: string; freq_hz: number; zeta: number; q: Responses; qdot_total: Float64Array;
  contribution_percent: Contributions; floquet: FloquetResult; accuracy: Accuracy; air?: ModeAir;
}
export interface StrainSeries { point: string; eps_x: Float64Array; eps_y: Float64Array; gamma_xy: Float64Array }
export interface SimResult {
  n: number; sample_rate_hz: number; flap_freq_hz: number; t: Float64Array; modes: ModeResult[];
  strain: StrainSeries | null; strain_points: StrainSeries[]; warnings: string[]; air?: AirSummary;
}
/** Force terms of one mode and the stiffness coefficient S(t) = α̇²cos²β + β̇² (1/s²). */
export interface ForceSeries { euler: Float64Array; centrifugal: Float64Array; coriolis: Float64Array; stiffness_coefficient: Float64Array; aerodynamic?: Float64Array }
export interface Peak { freq_hz: number; psd: number; flap_multiple: number | null }
export interface Spectrum { freq_hz: Float64Array; psd: Float64Array; peaks: Peak[] }
/** Spectra of one mode: force terms, the stiffness force S(t)·q_k (S = α̇²cos²β+β̇²), and the total response. */
export interface ModeSpectra { euler: Spectrum; centrifugal: Spectrum; coriolis: Spectrum; stiffness_force: Spectrum; total: Spectrum; aerodynamic?: Spectrum }
/** Force terms of one mode and the stiffness force S(t)·q_k, same units. */
export interface ModeForces { euler: Float64Array; centrifugal: Float64Array; coriolis: Float64Array; stiffness_force: Float64Array; aerodynamic?: Float64Array }
export interface Analysis {
  sim: SimResult;
  /** Per mode; null for modes not asked for. */
  forces: (ModeForces | null)[];
  spectra: (ModeSpectra | null)[];
  /** Envelope |analytic signal| of each asked-for mode's Coriolis response (see analyze()). */
  envelope: (Float64Array | null)[];
  /** α, β, γ (rad) at `sim.t`, for posing the 3-D wing without calling anglesAt per frame. */
  angles: AngleSeries;
  /** The run's largest |value|s, computed in the core (NaN if a sample is NaN). */
  peaks: AnalysisPeaks;
  /**
   * Sample indices (increasing) where every run-wide extreme of a linear function of the modal
   * state q(t) is reached: q's minimum and maximum for one mode, the trajectory's convex-hull
   * vertices for two (exact), at most 1000 evenly spaced samples plus each mode's minimum and
   * maximum for three or more (a display bound the run may exceed).
   */
  extreme_samples: Uint32Array;
}
/** Largest |q| over the run of each response of one mode. */
export interface ResponsePeaks { euler: number; centrifugal: number; coriolis: number; total: number }
/** Largest |strain| over the run at the strain point, per component. */
export interface StrainPeaks { eps_x: number; eps_y: number; gamma_xy: number }
export interface AnalysisPeaks { q: ResponsePeaks[]; strain: StrainPeaks | null }
export interface SweepModeColumns {
  euler: Float64Array; centrifugal: Float64Array; coriolis: Float64Array;
  effective_freq_hz: Float64Array; beat_period_s: Float64Array; peak_abs_q: Float64Array; stable: boolean[];
}
export interface SweepResult { param: SweepParam; values: Float64Array; modes: SweepModeColumns[] }
export interface IcMapResult {
  mode: number; n_q: number; n_qdot: number; q0: Float64Array; qdot0: Float64Array;
  /** Row-major: row j = qdot0[j], column i = q0[i]. */
  coriolis_percent: Float64Array; min_percent: number; max_percent: number;
  fraction_above_60: number; attribution: "forced" | "carried";
}
/** Shell FE input (paper §3.1); every field optional (missing = the default synthetic wing). */
export interface FemInput {
  planform_mm?: [number, number][]; planform_note?: string; camber?: number;
  clamp?: "root" | "free" | { strip: { x_mm: number } };
  material?: { thickness_m: number; e_pa: number; rho_kg_m3: number; nu: number };
  n_modes?: number;
  /** Target element edge, mm; missing or null = automatic from the planform's area. */
  mesh_size_mm?: number | null;
  /** Node cap, 1 ..= 20 000; feModes uses min(this, BROWSER_MAX_NODES = 6000). */
  max_nodes?: number | null;
}
/** Options of feModes. */
export interface FeModesOptions {
  /** Strain point [x, y], mm; default: P = (3, −6) on the default outline, else inside the wing near its root. */
  strain_point_mm?: [number, number];
  /** Also return `modes_json`, the `wingbeat modes` JSON document. */
  json?: boolean;
}
/** Shell FE modes: SI summary, Eq. 13 inputs (`modes`, strain at P) and the mesh as flat typed arrays. */
export interface FeModesResult {
  planform_note: string; freq_hz: Float64Array; a: [number, number][]; b: [number, number][];
  mass_kg: number; centre_of_mass_m: [number, number, number]; kinds: string[];
  residuals: Float64Array; mass_orthonormality_error: number; n_dofs: number;
  n_nodes: number; n_triangles: number; n_modes: number;
  /** The element size used, mm (the automatic one when the input left it out). */ mesh_size_mm: number;
  /** The node cap applied. */ max_nodes: number;
  /** The strain point of `modes[k].strains`, mm. */ strain_point_mm: [number, number]; modes: Mode[];
  /** With `opts.json`: the `wingbeat modes` JSON document (for `wingbeat simulate --modes`). */ modes_json?: string;
  /** x, y, z per node, m. */ nodes: Float64Array;
  /** Three node indices per triangle. */ triangles: Uint32Array;
  /** Mode-major: shapes[k·n_nodes + i], kg^-½. */ shapes: Float64Array;
  /** strain_nodes[(k·n_nodes + i)·3 + c], c = ε_x, ε_y, γ_xy per unit q. */ strain_nodes: Float64Array;
}
export interface Limits {
  max_duration_s: number; max_sample_rate_hz: number; max_samples: number;
  web_max_sample_values: number; max_sweep_points: number; max_ic_cells: number; max_modes: number;
  /** Resonance map caps: flap frequencies, α0 rows, and total work in integration steps. */
  max_resonance_points: number; max_resonance_alpha0_values: number; max_resonance_work: number;
  /** strainField's peak cap (nodes × samples × modes) and the most outline points accepted. */
  max_strain_field_work: number; max_outline_points: number;
  /** Work budget (docs/limits.md): one browser run and one sweep, in step equivalents; the flap frequency range, Hz; strain points per run. */
  web_max_run_work: number; max_sweep_work: number; min_flap_hz: number; max_flap_hz: number; max_strain_points: number;
  /** Harmonics a sampled angle keeps when its `max_harmonic` is not given (the table's N/2 if fewer). */
  default_sampled_max_harmonic: number;
}
/** Key of one of the lab's numeric parameters (core `params`). */
export type ParamKey =
  | "alpha0" | "beta0" | "gamma0" | "flap_hz" | "zeta"
  | "alpha_phase" | "beta_phase" | "gamma_phase" | "duration" | "air_density";
/** One numeric parameter of the lab: its slider (range, step, unit) and default (the paper case). */
export interface Param {
  key: ParamKey; symbol: string; label: string; unit: string;
  min: number; max: number; step: number; default: number;
}
/** Named parameters for `applyOverrides`; each optional, each inside its `Param` range. */
export type Overrides = Partial<Record<ParamKey, number>>;
/** Resonance map request: flap frequencies (Hz) and optionally roll amplitudes α0 (rad). */
export interface ResonanceOptions { from_hz: number; to_hz: number; points: number; alpha0_values?: number[] | null }
/** One mode's resonance map; arrays row-major [alpha0][flap_hz] (one row without alpha0). */
export interface ResonanceModeColumns {
  name: string; freq_hz: number; effective_freq_hz: Float64Array; max_modulus: Float64Array;
  /** NaN where the effective frequency coincides with n·f_d and where the mode is unstable (|λ| > 1: growth, not a beat). */ beat_period_s: Float64Array;
  /** The flap harmonic n the beat is measured against. */ beat_harmonic: Uint32Array;
  /** 1 = Floquet-stable, 0 = parametric resonance (max_modulus > 1). */ stable: Uint8Array;
}
export interface ResonanceMapResult { flap_hz: Float64Array; alpha0?: Float64Array; modes: ResonanceModeColumns[] }
/** Roll α, pitch β and yaw γ (rad) at the simulation's sample times `sim.t`. */
export interface AngleSeries { alpha: Float64Array; beta: Float64Array; gamma: Float64Array }
/** A built-in outline (all synthetic), mm: counter-clockwise, root edge on x = 0, chord toward −y. */
export interface BuiltinPlanform { id: string; label: string; note: string; points_mm: [number, number][] }
/** checkPlanform on a valid outline: area (mm²), extents (mm), distinct points, whether an edge lies on x = 0 (root clamp possible), the automatic mesh size (mm) and strain point (mm) feModes would use. */
export interface PlanformOk {
  ok: true; area_mm2: number; span_mm: number; chord_mm: number; n_points: number; root_edge: boolean;
  default_mesh_size_mm: number; default_strain_point_mm: [number, number];
}
/** checkPlanform on an invalid outline: what is wrong, naming the point or edge. */
export interface PlanformError { ok: false; error: string }
export type PlanformCheck = PlanformOk | PlanformError;
/** Key of one of the wing's parameters (core `params::WING_PARAMS`). */
export type WingParamKey = "camber" | "clamp_mm" | "e_pa" | "rho" | "nu" | "thickness_um" | "mesh_mm" | "n_modes";
/** One wing parameter: camber (rise / chord), clamp_mm (0 = root edge, else strip width, mm), e_pa (Pa), rho (kg/m³), nu, thickness_um (µm), mesh_mm (0 = automatic, mm), n_modes (1–8). */
export interface WingParam {
  key: WingParamKey; symbol: string; label: string; unit: string;
  min: number; max: number; step: number; default: number;
}
/** Named wing parameters for `wingInput`; each optional (missing = its default), each inside its `WingParam` range. */
export type WingOverrides = Partial<Record<WingParamKey, number>>;
/** One of the paper's two materials, in the wing parameters' units. */
export interface MaterialPreset { id: string; label: string; e_pa: number; rho: number; nu: number; thickness_um: number }
/** Modal strain of one mode at a point, per unit q (top surface, Eqs. 16–18). */
export interface ModalStrainValues { eps_x: number; eps_y: number; gamma_xy: number }
/** Strain component of a whole-wing map; von_mises = √(ε_x² − ε_x ε_y + ε_y² + 3 (γ_xy/2)²). */
export type StrainComponent = "eps_x" | "eps_y" | "gamma_xy" | "von_mises";
export interface StrainFieldOptions { component?: StrainComponent; stat: "rms" | "peak" }
/** Options of kinematicsFromCsv: units of the angle columns, the flap frequency (Hz) the samples are folded at, an optional low-pass. */
export interface CsvKinematicsOptions { units: "deg" | "rad"; flap_hz: number; max_harmonic?: number | null }
/** The file's samples folded onto one period: t in [0, 1/flap_hz) s, angles in rad, file order. */
export interface FoldedSamples { t: Float64Array; alpha: Float64Array; beta: Float64Array; gamma: Float64Array }
/** A measured stroke as the core's kinematics (sampled angles on a uniform grid over one period). */
export interface KinematicsTable {
  kinematics: Kinematics; samples: FoldedSamples; n_periods: number;
  /** grid: per-point means on a uniform grid aligned with t = 0 mod T; least_squares: a fitted Fourier series. */
  method: "grid" | "least_squares"; grid_points: number; max_harmonic: number; warnings: string[];
}
/** One accepted range of the body angular velocity (core params::BODY_RATE_RANGES). */
export interface BodyRateRange { what: "mean" | "amplitude" | "phase" | "value" | "peak"; min: number; max: number; unit: string }
/** The STA filter of classifyRotation's encoder (ω_s rad/ms, δ, w and the window in ms), or none. */
export type NeuralFilter =
  | { kind: "identity" }
  | { kind: "sta"; omega_rad_per_ms: number; delay_ms: number; width_ms: number; window_ms: number; orientation: "causal" | "published_code" };
/** The encoder's nonlinearity: ξ/s₀, or the firing probability 1/(1 + exp(−g(ξ/s₀ − θ))). */
export type NeuralNonlinearity = { kind: "identity" } | { kind: "sigmoid"; gain: number; threshold: number };
/** How classifyRotation samples, encodes and classifies (core ClassifyOptions; missing = published). */
export interface ClassifyOptions {
  duration_s?: number; sample_step_s?: number; discard_s?: number; filter?: NeuralFilter; nonlinearity?: NeuralNonlinearity;
  s0?: number | null; train_fraction?: number; threshold?: "gaussian_crossing" | "midpoint"; rank?: number; l1_weight?: number;
  kept_modes?: number[]; random_counts?: number[]; random_draws?: number; seed?: number;
}
/** What classifyRotation is asked; missing = the published setup (8 FE modes, 10 rad/s, disturbances 0.312 and 0.1 rad/s) on a 2 mm grid (the browser's cap: 400 sensors). */
export interface ClassifyRequest {
  n_modes?: number; mesh_size_mm?: number | null; rotation_rad_s?: number; flap_disturbance_rad_s?: number;
  rotation_disturbance_rad_s?: number; seed?: number; grid_step_mm?: number; options?: ClassifyOptions;
}
/** SSPOC's sensors for one number of kept modes (indices into `sensors`) and their test accuracy. */
export interface SparsePoint { kept_modes: number; sensors: number[]; accuracy: number }
/** Random sets of one size: mean and sd of the test accuracy over the draws. */
export interface RandomPoint { sensors: number; mean: number; sd: number; failed_fits: number }
/** Accuracy against the number of sensors for one representation of the strain. */
export interface GreedyPoint { sensors: number[]; d_prime: number; accuracy: number }
export interface ClassifyCurves { all_sensors: number; sparse: SparsePoint[]; random: RandomPoint[]; greedy: GreedyPoint[]; s0: number }
/** The classification (core ClassifyReport); accuracies are fractions of test samples (chance 0.5), positions mm. */
export interface ClassifyReport {
  options: ClassifyOptions; train_samples: number; test_samples: number; encoded: ClassifyCurves; raw: ClassifyCurves;
  sensors: [number, number][]; steps_per_sample: number;
}
/** classifyRotation's result: the plate's modes (Hz, ζ, FE kind) and the report. */
export interface ClassifyRotationResult { modes: { freq_hz: number; zeta: number; kind: string }[]; report: ClassifyReport }
/** Options of senseRotation; missing = the core's defaults (k_max 30, ρ 0.01, σ 1e-7, 256 samples per sensor, the best sensor's point). */
export interface SenseOptions { k_max?: number | null; rho?: number | null; noise?: number | null; samples_per_sensor?: number | null; point_mm?: [number, number] | null }
/** The sensing analysis's options as used (core SensingOptions). */
export interface SensingOptions { k_max: number; rho: number; noise: number; samples_per_sensor: number }
/** One chosen sensor: rank (1 = first), node index, strain component, position (mm), single-sensor detectability D. */
export interface Sensor { rank: number; node: number; component: "eps_x" | "eps_y" | "gamma_xy"; x_mm: number; y_mm: number; d: number }
/** Strain series of the three components (dimensionless, FE modes). */
export interface StrainComponents { eps_x: Float64Array; eps_y: Float64Array; gamma_xy: Float64Array }
/** senseRotation's result. Per node i and component c: d[3i + c], e_delta[3i + c], e_flap[3i + c]; d_best[i] the largest of the three, best_component[i] its index (0 ε_x, 1 ε_y, 2 γ_xy). */
export interface SensingResult {
  body_rate: [number, number, number]; options: SensingOptions; flap_freq_hz: number; sample_rate_hz: number;
  n_nodes: number; n_modes: number; warnings: string[];
  sensors: Sensor[]; d_prime_all: number; pd_all: number; k_for_90_percent: number | null; method: string;
  point_mm: [number, number]; point_source: "opts" | "best_sensor";
  d_best: Float64Array; best_component: Uint8Array; d: Float64Array; e_delta: Float64Array; e_flap: Float64Array;
  /** d′ and P_d (1 % false alarms) with the first K sensors, K = 1 … k_max; d′ of the K best single sensors. */
  d_prime: Float64Array; pd: Float64Array; d_prime_ranked: Float64Array;
  /** Sample times, s; Δε and the flapping strain at point_mm; Welch spectra of Δε (strain²/Hz). */
  t: Float64Array; delta: StrainComponents; flap: StrainComponents;
  spectrum: { eps_x: Spectrum; eps_y: Spectrum; gamma_xy: Spectrum };
  /** Per mode: Δq_k(t) and q_k(t) without rotation (kg^½·m). */
  dq: Float64Array[]; q_flap: Float64Array[];
}
/** An FE result read back from a modes document: feModes' layout (flat typed arrays) without `modes`. */
export interface ImportedFe {
  planform_note: string; freq_hz: Float64Array; a: [number, number][]; b: [number, number][];
  mass_kg: number; centre_of_mass_m: [number, number, number]; kinds: string[];
  residuals: Float64Array; mass_orthonormality_error: number; n_dofs: number;
  n_nodes: number; n_triangles: number; n_modes: number; mesh_size_mm: number;
  clamped_nodes: number[]; material: { thickness_m: number; e_pa: number; rho_kg_m3: number; nu: number };
  /** x, y, z per node, m. */ nodes: Float64Array;
  /** Three node indices per triangle. */ triangles: Uint32Array;
  /** Mode-major: shapes[k·n_nodes + i], kg^-½. */ shapes: Float64Array;
  /** strain_nodes[(k·n_nodes + i)·3 + c], c = ε_x, ε_y, γ_xy per unit q. */ strain_nodes: Float64Array;
}
/** modesFromJson: the modes for a SimConfig, and the FE mesh when the document is a `wingbeat modes` output. */
export interface ModesDocument { modes: Mode[]; fe?: ImportedFe }
"#;
