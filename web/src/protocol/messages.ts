// The JSON messages of the wire protocol (docs/web.md; protocol.ts re-exports them), one object per text
// message: the commands (page → server) and the notices (server → page: the status with the run's
// settings, refusals and errors keyed for the page's language, the string pendulum's events), which
// parseNotice checks. Lengths in m, masses in kg, g in m/s², times in s, angles in rad, a model's own
// parameters in the SI units of GET /api/schema. No DOM.
import { FRAME_FIELDS, ProtocolError } from './frames';
import type { Vec3 } from './frames';

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
  /** A fixed-step method's step [s]. An adaptive method (dop853) does not use it (it chooses all its
   *  steps, the first too): then it is only the step of a fixed-step method chosen next, and neither
   *  the URL nor the exported scenario carries it, but the tolerances below. */
  dt: number;
  /** The adaptive method's tolerances (relative; absolute in m and m/s). */
  rtol?: number;
  atol?: number;
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
