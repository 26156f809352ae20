// The crane mode's sway gauge (docs/web.md, "Crane mode"): the angle of the rope from the downward
// vertical, read off the frames the core sends (the load at x relative to the trolley [m]), and the
// largest angle over the last seconds of simulated time — the residual sway once the trolley stops.
// Geometry of the frames only: no physics here. Angles in rad.
import type { Frame, Vec3 } from '../protocol';

/** The rope's angle from the downward vertical [rad] of the load at `x` [m] relative to the trolley. */
export function swayAngle(x: Vec3): number {
  return Math.atan2(Math.hypot(x[0], x[1]), -x[2]);
}

/** The largest sway angle [rad] over the last `seconds` [s] of simulated time up to the latest frame
 *  (frames in time order; 0 for none). */
export function recentMaxSway(frames: readonly Frame[], seconds: number): number {
  let best = 0;
  const last = frames[frames.length - 1];
  if (last === undefined) return 0;
  for (let i = frames.length - 1; i >= 0; i--) {
    const f = frames[i];
    if (f === undefined || f.t < last.t - seconds) break;
    best = Math.max(best, swayAngle(f.x));
  }
  return best;
}

/** The rope length [m]: the load's distance from the trolley. */
export function ropeLength(x: Vec3): number {
  return Math.hypot(x[0], x[1], x[2]);
}

/** The wind's (x, y) [m/s] from its speed [m/s] and the direction it blows towards [degrees from +x]. */
export function windVector(speed: number, degrees: number): [number, number] {
  const a = (degrees * Math.PI) / 180;
  const r = (v: number) => Math.round(v * 1e9) / 1e9;
  return [r(speed * Math.cos(a)), r(speed * Math.sin(a))];
}

/** Speed [m/s] and direction [degrees from +x, 0 … 360) of the wind (x, y) [m/s]. */
export function windPolar(w: readonly number[]): { speed: number; degrees: number } {
  const [x = 0, y = 0] = w;
  const deg = (Math.atan2(y, x) * 180) / Math.PI;
  return { speed: Math.hypot(x, y), degrees: Math.round(((deg % 360) + 360) % 360) };
}
