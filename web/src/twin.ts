// Two pendulums at once (docs/web.md, "Two pendulums"): a second WebSocket session of the same server, opened
// by this page, runs a copy of the first pendulum that differs in one thing — its start turned by ε in θ,
// another integrator, or damping beside the ideal one — and the scene draws it beside the first (in green).
// Both are reset together, so their times agree; the separation |r₁ − r₂| of the bobs [m] (r = pivot + x)
// is the difference of the two streamed states at the first one's frame times (the second's frames
// interpolated, never integrated). Run, pause, reset and step go to both. Mode `own`: a pendulum of its own
// length, mass and start (the same model, g and method), drawn beside the first from a pivot of its own —
// PhET's experiment, the period against length and mass, each timed by its own period timer.
import type { Command, Frame, Status, Vec3 } from './protocol';
import { interpolateFrames } from './state';

/** At most this many pendulums besides the first two (panels/extras.ts). */
export const MAX_EXTRAS = 2;

export type TwinMode = 'off' | 'epsilon' | 'method' | 'damped' | 'own';

export interface TwinOptions {
  mode: TwinMode;
  /** The second start's θ is the first's + ε [rad]. */
  epsilon: number;
  /** The second pendulum's integrator (mode `method`). */
  method: string;
  /** The second pendulum's damping c [1/s] (mode `damped`). */
  damping: number;
  /** Mode `own`: the second pendulum's own rod length [m], bob mass [kg] and start angle θ₀ [rad] (a planar
   *  swing from rest, φ₀ = 0), hung from its own pivot beside the first (drawn side by side). */
  length: number;
  mass: number;
  theta: number;
  /** Mode `own`: pendulums 3 and 4 (panels/extras.ts), each its rod length [m], mass [kg] and θ₀ [rad]. */
  extras?: ExtraOptions[];
}

/** One more pendulum of mode `own`: rod length [m], bob mass [kg], start angle θ₀ [rad]. */
export interface ExtraOptions {
  length: number;
  mass: number;
  theta: number;
}

/** The horizontal offset [m] at which the second pivot is drawn in mode `own`, beside the first: the two
 *  spheres of reach (radii l₁, l₂ [m]) side by side with a gap of a tenth of their sum, along the default
 *  camera's screen-right direction (scene.ts: the camera looks from (3.3, −3.9, ·)). Drawing only: each
 *  session's states stay relative to its own pivot. */
export function sideBySide(l1: number, l2: number): Vec3 {
  const d = 1.1 * (l1 + l2);
  const r = Math.hypot(3.9, 3.3);
  return [(d * 3.9) / r, (d * 3.3) / r, 0];
}

/** x [m] turned by ε [rad] in θ (away from the downward vertical) about the pivot, |x| kept. */
export function tiltedStart(x: Readonly<Vec3>, epsilon: number): Vec3 {
  const r = Math.hypot(...x);
  const theta = Math.atan2(Math.hypot(x[0], x[1]), -x[2]) + epsilon;
  const phi = Math.atan2(x[1], x[0]);
  return [r * Math.sin(theta) * Math.cos(phi), r * Math.sin(theta) * Math.sin(phi), -r * Math.cos(theta)];
}

/** What is wrong with the inputs of `o`'s mode, or null: `'own'` (mode own, and pendulums 3 and 4: a finite
 *  length > 0 m, mass > 0 kg and θ₀ in [0, π]), `'bad'` (mode epsilon: a finite ε; mode damped: a finite
 *  damping ≥ 0). NaN (an emptied or mistyped box, format.ts `typedNumber`) fails every test. */
export function twinProblem(o: TwinOptions): 'own' | 'bad' | null {
  const finite = Number.isFinite;
  if (o.mode === 'own') return finite(o.length) && o.length > 0 && finite(o.mass) && o.mass > 0 && o.theta >= 0 && o.theta <= Math.PI ? null : 'own';
  if (o.mode === 'epsilon') return finite(o.epsilon) ? null : 'bad';
  if (o.mode === 'damped') return finite(o.damping) && o.damping >= 0 ? null : 'bad';
  return null;
}

/** The commands that make the second session a copy of the first (`s`) that differs as `o` says, ending
 *  with a reset (and pause if the first is paused). */
export function twinCommands(s: Status, o: TwinOptions): Command[] {
  const cmds: Command[] = [];
  if (s.scenario) cmds.push({ type: 'load_scenario', name: s.scenario });
  const damped = o.mode === 'damped';
  const own = o.mode === 'own';
  const model = damped && s.model === 'ideal' ? 'damped' : s.model;
  const params = { ...s.model_params };
  if (damped) params['damping'] = o.damping;
  cmds.push({ type: 'set_model', model, params });
  cmds.push({ type: 'set_params', length: own ? o.length : s.params.length, mass: own ? o.mass : s.params.mass, g: s.params.g });
  cmds.push({ type: 'set_method', method: o.mode === 'method' ? o.method : s.method, dt: s.dt });
  if (own) cmds.push({ type: 'set_state', theta: o.theta, phi: 0, theta_dot: 0, phi_dot: 0 });
  else {
    const x = o.mode === 'epsilon' ? tiltedStart(s.start.x, o.epsilon) : s.start.x;
    cmds.push({ type: 'set_state', x, v: s.start.v, project: true });
  }
  cmds.push({ type: 'set_time_scale', time_scale: s.time_scale });
  cmds.push({ type: 'reset' });
  cmds.push({ type: s.paused ? 'pause' : 'resume' });
  return cmds;
}

/** The frame of the time-sorted `frames` at time t, interpolated; null outside their span. */
export function frameAt(frames: readonly Frame[], t: number): Frame | null {
  const n = frames.length;
  if (n === 0) return null;
  const first = frames[0] as Frame;
  const last = frames[n - 1] as Frame;
  if (t < first.t || t > last.t) return null;
  let lo = 0;
  let hi = n - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if ((frames[mid] as Frame).t <= t) lo = mid;
    else hi = mid;
  }
  const a = frames[lo] as Frame;
  const b = frames[hi] as Frame;
  return b.t > a.t ? interpolateFrames(a, b, (t - a.t) / (b.t - a.t)) : a;
}

/** The bob's position r = pivot + x [m] at time t from the time-sorted `frames`: x by cubic Hermite
 *  interpolation of the two frames around t with their x and v = ẋ (error O(h⁴) for frames h apart — a
 *  loaded server sends a frame per tick, up to 0.1 s apart, where the linear one was off by centimetres),
 *  the pivot linearly; null outside their span. */
export function positionAt(frames: readonly Frame[], t: number): Vec3 | null {
  const n = frames.length;
  if (n === 0) return null;
  const first = frames[0] as Frame;
  const last = frames[n - 1] as Frame;
  if (t < first.t || t > last.t) return null;
  let lo = 0;
  let hi = n - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if ((frames[mid] as Frame).t <= t) lo = mid;
    else hi = mid;
  }
  const a = frames[lo] as Frame;
  const b = frames[hi] as Frame;
  const h = b.t - a.t;
  if (!(h > 0)) return [a.x[0] + a.pivot[0], a.x[1] + a.pivot[1], a.x[2] + a.pivot[2]];
  const s = (t - a.t) / h;
  const [h00, h10, h01, h11] = [2 * s ** 3 - 3 * s ** 2 + 1, s ** 3 - 2 * s ** 2 + s, -2 * s ** 3 + 3 * s ** 2, s ** 3 - s ** 2];
  const r = (i: 0 | 1 | 2) =>
    h00 * a.x[i] + h10 * h * a.v[i] + h01 * b.x[i] + h11 * h * b.v[i] + (1 - s) * a.pivot[i] + s * b.pivot[i];
  return [r(0), r(1), r(2)];
}

/** |r₁ − r₂| [m] of the bobs (r = pivot + x) at the times of `first` where `second` has frames (the
 *  second's position there by `positionAt`). */
export function separation(first: readonly Frame[], second: readonly Frame[]): { t: number[]; d: number[] } {
  const t: number[] = [];
  const d: number[] = [];
  for (const f of first) {
    const g = positionAt(second, f.t);
    if (g === null) continue;
    t.push(f.t);
    d.push(Math.hypot(f.x[0] + f.pivot[0] - g[0], f.x[1] + f.pivot[1] - g[1], f.x[2] + f.pivot[2] - g[2]));
  }
  return { t, d };
}

/** The pivots of a row of pendulums of lengths `lengths` [m] (the first at the origin): each next one
 *  beside the one before, as `sideBySide` places the second, so no two spheres of reach overlap. Returns
 *  the offsets [m] of pendulums 2 … n from the first. Drawing only. */
export function rowOffsets(lengths: readonly number[]): Vec3[] {
  const out: Vec3[] = [];
  let at: Vec3 = [0, 0, 0];
  for (let i = 1; i < lengths.length; i++) {
    const step = sideBySide(lengths[i - 1] as number, lengths[i] as number);
    at = [at[0] + step[0], at[1] + step[1], at[2] + step[2]];
    out.push(at);
  }
  return out;
}
