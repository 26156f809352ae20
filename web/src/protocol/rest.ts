// The REST answers of the server the page reads (docs/web.md; protocol.ts re-exports them): GET
// /api/schema (models, parameters with units and limits, methods, controls), GET /api/scenarios,
// POST /api/exact (the exact solution's quantities), /api/reduced and /api/em_map. SI units as each
// field says. Types only, no DOM.
import type { Vec3 } from './frames';
import type { ModelParams, Params } from './messages';

export interface ParamSchema {
  name: string;
  /** The words a student reads (the core's registry), e.g. "friction (linear damping)". */
  label?: string;
  unit: string;
  /** One line of help (the tooltip; formula numbers go here, not into the label). */
  description: string;
  /** What is allowed, in words (the core's). */
  allowed?: string;
  default: number;
  /** Hard limits; null: none. */
  min: number | null;
  max: number | null;
  ui_min: number;
  ui_max: number;
  step: number;
}

export interface ControlSchema {
  unit: string;
  description: string;
  min: number;
  max: number;
  ui_min?: number;
  ui_max?: number;
  step?: number;
  default?: number;
}

export interface MethodInfo {
  name: string;
  order: number;
  symplectic: boolean;
  preserves_ts2: boolean;
  preserves_j3: boolean;
  adaptive: boolean;
  dense_output: boolean;
  default: boolean;
  summary: string;
}

export interface ModelSchema {
  name: string;
  /** The model's name in words, e.g. "Damped and driven" (the core's registry). */
  label?: string;
  summary: string;
  params: ParamSchema[];
}

export interface Schema {
  version: string;
  model: ModelSchema;
  /** Every model of the core's registry with its own parameters (beyond length, mass, g). */
  models: ModelSchema[];
  controls: { dt: ControlSchema; time_scale: ControlSchema; step_n: ControlSchema };
  methods: MethodInfo[];
  frame: { fields: string[]; units: string[]; dtype: string; byte_order: string; record_bytes: number };
  commands: string[];
  tick_hz: number;
}

export interface ScenarioInfo {
  name: string;
  title?: string | null;
  params?: Params;
  model?: string;
  model_params?: ModelParams;
  start?: { x: Vec3; v: Vec3 };
  method?: string;
  dt?: number;
  t0?: number;
  error?: string;
}

export interface ExactQuantities {
  kind: string;
  energy: number;
  j3: number;
  omega0: number;
  turning_heights: (number | null)[];
  modulus: number | null;
  period_z: number | null;
  period_z_infinite: boolean;
  azimuth_advance: number | null;
  rotation_number: number | null;
  phases: { total: number; dynamic: number; geometric: number } | null;
  phases_note: string | null;
}

export interface EffectivePotential {
  theta: number[];
  v_eff: number[];
  minimum: { theta: number; v_eff: number };
}

/** POST /api/reduced: Holm's Figure 2 in σ-space (σ₁ [1], σ₂ [1/s], σ₃ [1/s²]); `surface.sigma3[i][k]` is
 *  the J₃ surface over (sigma1[i], sigma2[k]); the plane is σ₃ = 2(h − γσ₁). */
export interface ReducedCurves {
  orbit: { sigma1: number[]; sigma2: number[]; sigma3: number[] };
  orbit_time: number;
  surface: { sigma1: number[]; sigma2: number[]; sigma3: number[][] };
  plane: { h: number; gamma: number };
  point: [number, number, number];
  j: number;
}

/** POST /api/em_map: the boundary of the energy–momentum map (J₃ [kg m²/s], E [J]) and its equilibria. */
export interface EMView {
  boundary: { j3: number[]; energy: number[] };
  bottom: { j3: number; energy: number };
  top: { j3: number; energy: number };
  point: { j3: number; energy: number };
}
