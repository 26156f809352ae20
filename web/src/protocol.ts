// The wire protocol between `pendulab serve` and the page (docs/web.md), with no DOM: types of the JSON
// commands and notices, and the decoding of binary state frames.
//
// Frames: every binary WebSocket message holds one or more records of little-endian float64 values in the
// order of `frame.json` (shared with the Python server, pendulab/server/frame.json):
//   [t, x1, x2, x3, v1, v2, v3, energy, j3, tension, power, a1, a2, a3, pivot1, pivot2, pivot3, taut, error_x]
//   in s, m, m/s, J, kg m²/s, N, W, m/s², m, 1, m. x, v and a are relative to the pivot (at `pivot`, 0 when
//   fixed); taut is 0 while the string is slack (model `string`), else 1; error_x is the global position
//   error of the record's state (true or estimated, the status's `error_estimate` says how), −1 unknown.
import layout from '../../python/pendulab/server/frame.json';

export type Vec3 = [number, number, number];

/** Names of the float64 values of one record, in wire order. */
export const FRAME_FIELDS: readonly string[] = layout.fields;
/** SI unit of each field. */
export const FRAME_UNITS: readonly string[] = layout.units;
export const RECORD_LEN = FRAME_FIELDS.length;
export const RECORD_BYTES = 8 * RECORD_LEN;

function fieldIndex(name: string): number {
  const i = FRAME_FIELDS.indexOf(name);
  if (i < 0) throw new Error(`frame.json lacks the field ${name}`);
  return i;
}
const I = {
  t: fieldIndex('t'),
  x: [fieldIndex('x1'), fieldIndex('x2'), fieldIndex('x3')] as const,
  v: [fieldIndex('v1'), fieldIndex('v2'), fieldIndex('v3')] as const,
  energy: fieldIndex('energy'),
  j3: fieldIndex('j3'),
  tension: fieldIndex('tension'),
  power: fieldIndex('power'),
  a: [fieldIndex('a1'), fieldIndex('a2'), fieldIndex('a3')] as const,
  pivot: [fieldIndex('pivot1'), fieldIndex('pivot2'), fieldIndex('pivot3')] as const,
  taut: fieldIndex('taut'),
  errorX: fieldIndex('error_x'),
};

/** One state as computed by the server's core: time t [s], position x [m] and velocity v [m/s] relative to
 *  the pivot, energy E [J], J₃ [kg m²/s], rod tension T [N], power of the non-conservative forces P [W],
 *  acceleration a = ẍ [m/s²] relative to the pivot (m a is the net force on the bob there) and the
 *  pivot's position [m] (0 for a fixed pivot; the bob is at pivot + x), and whether the rod, spring or
 *  string holds the bob (false only while the string is slack: free flight, tension 0), and the global
 *  position error of this state [m] since the stepper's start (the exact one for the ideal pendulum, else
 *  an estimate: Status.error_estimate), or −1 while unknown (the estimate paused: out of work budget). */
export interface Frame {
  t: number;
  x: Vec3;
  v: Vec3;
  energy: number;
  j3: number;
  tension: number;
  power: number;
  a: Vec3;
  pivot: Vec3;
  taut: boolean;
  errorX: number;
}

export class ProtocolError extends Error {}

/** Decodes one binary message into its records. Throws ProtocolError on a length that is not whole records. */
export function decodeFrames(buf: ArrayBuffer): Frame[] {
  if (buf.byteLength === 0 || buf.byteLength % RECORD_BYTES !== 0) {
    throw new ProtocolError(`a frame message has a multiple of ${RECORD_BYTES} bytes, got ${buf.byteLength}`);
  }
  const view = new DataView(buf);
  const n = buf.byteLength / RECORD_BYTES;
  const out: Frame[] = [];
  for (let k = 0; k < n; k++) {
    const base = k * RECORD_BYTES;
    const at = (i: number): number => view.getFloat64(base + 8 * i, true);
    const vec = (i: readonly [number, number, number]): Vec3 => [at(i[0]), at(i[1]), at(i[2])];
    out.push({
      t: at(I.t),
      x: vec(I.x),
      v: vec(I.v),
      energy: at(I.energy),
      j3: at(I.j3),
      tension: at(I.tension),
      power: at(I.power),
      a: vec(I.a),
      pivot: vec(I.pivot),
      taut: at(I.taut) !== 0,
      errorX: at(I.errorX),
    });
  }
  return out;
}

/** The inverse of decodeFrames (used by tests and to replay recordings). */
export function encodeFrames(frames: readonly Frame[]): ArrayBuffer {
  const buf = new ArrayBuffer(frames.length * RECORD_BYTES);
  const view = new DataView(buf);
  frames.forEach((f, k) => {
    const base = k * RECORD_BYTES;
    const put = (i: number, value: number): void => view.setFloat64(base + 8 * i, value, true);
    put(I.t, f.t);
    I.x.forEach((i, c) => put(i, f.x[c] ?? NaN));
    I.v.forEach((i, c) => put(i, f.v[c] ?? NaN));
    put(I.energy, f.energy);
    put(I.j3, f.j3);
    put(I.tension, f.tension);
    put(I.power, f.power);
    I.a.forEach((i, c) => put(i, f.a[c] ?? NaN));
    I.pivot.forEach((i, c) => put(i, f.pivot[c] ?? NaN));
    put(I.taut, f.taut ? 1 : 0);
    put(I.errorX, f.errorX);
  });
  return buf;
}

// --- commands (page → server), one JSON object per text message ---

/** A model's own parameters by name, SI units (GET /api/schema → models). */
export type ModelParams = Record<string, number>;

export type Command =
  | { type: 'set_params'; length?: number; mass?: number; g?: number; params?: ModelParams }
  | { type: 'set_model'; model: string; params?: ModelParams }
  | { type: 'set_state'; x: Vec3; v: Vec3; project?: boolean }
  | { type: 'set_state'; theta: number; phi?: number; theta_dot?: number; phi_dot?: number }
  | { type: 'set_method'; method?: string; dt?: number }
  | { type: 'set_time_scale'; time_scale: number }
  | { type: 'pause' }
  | { type: 'resume' }
  | { type: 'step'; n?: number }
  | { type: 'reset' }
  | { type: 'load_scenario'; name: string }
  | { type: 'crane'; on?: boolean; drive?: [number, number]; move?: [number, number]; stop?: boolean; rope?: number };

// --- notices (server → page), JSON text ---

export interface Params {
  length: number;
  mass: number;
  g: number;
}

export interface Status {
  type: 'status';
  epoch: number;
  scenario: string | null;
  title: string | null;
  paused: boolean;
  time_scale: number;
  method: string;
  adaptive: boolean;
  dt: number;
  params: Params;
  /** The model of the core's registry and all its own parameters (SI units). */
  model: string;
  model_params: ModelParams;
  t: number;
  t0: number;
  start: { x: Vec3; v: Vec3 };
  lagging: boolean;
  /** Command messages of this connection the server has handled (applied, refused or dropped). */
  commands?: number;
  /** How the frames' error_x is obtained (docs/web.md, "Error estimate"). */
  error_estimate?: ErrorEstimateInfo;
  frame_fields: string[];
  /** The crane mode's state (null outside it; crane/index.ts, docs/web.md "Crane mode"). */
  crane?: CraneStatus | null;
}

/** The status's `crane`: rope l [m] (and its rate [m/s], the hoist's target [m]), the trolley's position
 *  [m] and velocity [m/s], the operator's commanded velocity, the shaper (`off`, `zv`, `zvd`; its impulse
 *  times [s], amplitudes and design ω [rad/s]), the wind [m/s], c_W·A [m²], ρ [kg/m³], the limits, and the
 *  last move with its linear residual sway unshaped and shaped [rad] and the time [s] it ends. */
export interface CraneStatus {
  rope: number;
  rope_rate: number;
  rope_target: number;
  trolley: Vec3;
  trolley_velocity: Vec3;
  command_velocity: Vec3;
  moving: boolean;
  hoisting: boolean;
  shaping: 'off' | 'zv' | 'zvd';
  shaper: { times: number[]; amplitudes: number[]; omega: number };
  wind: Vec3;
  drag_area: number;
  air_density: number;
  v_max: number;
  a_max: number;
  hoist_speed: number;
  hoist_accel: number;
  last_move: {
    t: number;
    distance: [number, number];
    omega: number;
    shaping: string;
    residual_unshaped: number;
    residual_shaped: number;
    rope: number;
    end: number;
  } | null;
}

/** The status's `error_estimate`: `how` the frames' error_x is obtained — `exact` (the ideal pendulum: the
 *  true error against the exact solution), `richardson` (a companion at dt/2 = reference.dt, e ≈ |x_h −
 *  x_h/2|·2^p/(2^p − 1), p = order), `companion` (dop853: a companion at reference.rtol, reference.atol),
 *  or null (none; `note` says why) —, and `since` [s], the start the error is counted from. */
export interface ErrorEstimateInfo {
  how: 'exact' | 'richardson' | 'companion' | null;
  order: number | null;
  reference: { dt?: number; rtol?: number; atol?: number };
  since: number;
  note: string | null;
}

export interface ErrorNotice {
  type: 'error';
  message: string;
  command: string | null;
  /** The message's key and values (python/pendulab/server/messages.json) when the server keyed it: the
   *  page shows `server.<key>` of its language (i18n `serverWords`). */
  key?: string;
  values?: Record<string, string | number>;
}

/** One event of the string pendulum (model `string`), computed by the server's core: `slack`, the tension
 *  reached 0 and the bob leaves the sphere; `taut`, the string snaps taut again, losing `energy_lost` [J]
 *  (½m(1 − e²)u², 0 for a leave). `t` [s], `x` the bob's position just after [m], `epoch` the trajectory
 *  it belongs to, `skipped` how many earlier events of the same tick the server did not send. */
export interface EventNotice {
  type: 'event';
  kind: 'slack' | 'taut';
  t: number;
  energy_lost: number;
  x: Vec3;
  epoch: number;
  skipped: number;
}

export type Notice = Status | ErrorNotice | EventNotice;

function isObject(v: unknown): v is Record<string, unknown> {
  return typeof v === 'object' && v !== null && !Array.isArray(v);
}

/** A notice from one text message, or a ProtocolError saying what is wrong with it. */
export function parseNotice(text: string): Notice {
  let raw: unknown;
  try {
    raw = JSON.parse(text);
  } catch (e) {
    throw new ProtocolError(`notice is not JSON: ${String(e)}`);
  }
  if (!isObject(raw)) throw new ProtocolError('notice is not a JSON object');
  if (raw['type'] === 'error' && typeof raw['message'] === 'string') {
    const command = typeof raw['command'] === 'string' ? raw['command'] : null;
    const notice: ErrorNotice = { type: 'error', message: raw['message'], command };
    const values = raw['values'];
    if (typeof raw['key'] === 'string' && isObject(values) && Object.values(values).every((v) => typeof v === 'string' || typeof v === 'number')) {
      notice.key = raw['key'];
      notice.values = values as Record<string, string | number>;
    }
    return notice;
  }
  if (raw['type'] === 'status') {
    const p = raw['params'];
    if (!isObject(p) || typeof raw['epoch'] !== 'number' || typeof raw['method'] !== 'string') {
      throw new ProtocolError('status notice lacks epoch, method or params');
    }
    const fields = raw['frame_fields'];
    if (Array.isArray(fields) && fields.join(',') !== FRAME_FIELDS.join(',')) {
      throw new ProtocolError(`server frame layout ${fields.join(',')} differs from the page's`);
    }
    return raw as unknown as Status;
  }
  if (raw['type'] === 'event') return parseEvent(raw);
  throw new ProtocolError(`unknown notice type ${JSON.stringify(raw['type'])}`);
}

function isFiniteNumber(v: unknown): v is number {
  return typeof v === 'number' && Number.isFinite(v);
}

function parseEvent(raw: Record<string, unknown>): EventNotice {
  const { kind, t, energy_lost: lost, x, epoch } = raw;
  const skipped = raw['skipped'] ?? 0;
  if (kind !== 'slack' && kind !== 'taut') {
    throw new ProtocolError(`event notice: kind ${JSON.stringify(kind)} is not "slack" or "taut"`);
  }
  if (!isFiniteNumber(t)) throw new ProtocolError('event notice: t is not a finite number');
  if (!isFiniteNumber(lost) || lost < 0) {
    throw new ProtocolError('event notice: energy_lost is not a finite number ≥ 0');
  }
  if (!Array.isArray(x) || x.length !== 3 || !x.every(isFiniteNumber)) {
    throw new ProtocolError('event notice: x is not 3 finite numbers');
  }
  if (!Number.isInteger(epoch) || !Number.isInteger(skipped) || (skipped as number) < 0) {
    throw new ProtocolError('event notice: epoch or skipped is not an integer');
  }
  return {
    type: 'event',
    kind,
    t,
    energy_lost: lost,
    x: [x[0] as number, x[1] as number, x[2] as number],
    epoch: epoch as number,
    skipped: skipped as number,
  };
}

// --- REST (GET /api/schema, GET /api/scenarios, POST /api/exact) ---

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
