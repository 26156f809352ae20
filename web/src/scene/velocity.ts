// Pulling the velocity arrow to choose a start velocity: the geometry only (no DOM, no three.js,
// unit-tested). The pointer's ray is cut with the plane through the bob perpendicular to its radius
// (tangent to the sphere of reach for the models on it; for the spring and a slack string, whose bob is
// off that sphere, the plane perpendicular to the bob's own radius), and the velocity is the offset of
// that point from the bob divided by the velocity arrow's scale (vectors.ts `arrowScales`: metres of arrow
// per m/s), so the arrow's tip lands under the pointer; its length is capped at `maxStartSpeed`. The page
// only builds the requested (x, v) from this: the server checks it (and projects it onto TS²).
import type { Vec3 } from '../protocol';

const dot = (a: Vec3, b: Vec3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const add = (a: Vec3, b: Vec3): Vec3 => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const scale = (a: Vec3, k: number): Vec3 => [a[0] * k, a[1] * k, a[2] * k];

/** The largest start speed the velocity arrow sets [m/s], for a pendulum of length l [m] (the spring's
 *  rest length) under gravity g [m/s²]: 4 √(max(|g|, 1 m/s²) · l), twice the speed 2 √(g l) with which
 *  the ideal pendulum, started at the bottom, just reaches the top — so every kind of orbit (swings,
 *  rosettes, conical orbits, rotations over the top) can be set; its arrow (0.25 s of travel) is
 *  √(max(|g|, 1) l) m long (3.1 m for l = 1 m, g = 9.81 m/s²). The floor of 1 m/s² is the one `arrowScales` uses for g ≈ 0. */
export function maxStartSpeed(length: number, g: number): number {
  return 4 * Math.sqrt(Math.max(Math.abs(g), 1) * Math.max(length, 0));
}

/** A ray: the camera's position and the direction through the pointer (any length > 0). */
export interface Ray3 {
  origin: Vec3;
  direction: Vec3;
}

export interface PulledVelocity {
  /** The requested start velocity [m/s], perpendicular to x, |v| ≤ the cap. */
  v: Vec3;
  /** |v| [m/s]. */
  speed: number;
  /** Whether the pointer asked for more than the cap (v then points where it asked, shortened). */
  capped: boolean;
}

/** The velocity whose arrow (drawn from the bob with `arrowScale` metres per m/s) ends where the ray
 *  meets the plane through the bob (at pivot + x, in the scene's coordinates) perpendicular to x, capped
 *  at `vmax` [m/s]. Where the ray misses that plane (parallel to it, or the plane behind the camera) the
 *  point of the ray nearest the bob, moved into the plane, is taken instead. Null
 *  when x = 0 (no radius, no plane) or the inputs are not finite. */
export function velocityFromRay(ray: Ray3, pivot: Vec3, x: Vec3, arrowScale: number, vmax: number): PulledVelocity | null {
  const r = Math.hypot(...x);
  const dn = Math.hypot(...ray.direction);
  if (!(r > 0) || !(dn > 0) || !(arrowScale > 0) || !Number.isFinite(r) || !Number.isFinite(dn)) return null;
  if (![...pivot, ...ray.origin].every(Number.isFinite)) return null;
  const n = scale(x, 1 / r);
  const d = scale(ray.direction, 1 / dn);
  const bob = add(pivot, x);
  const toBob = sub(bob, ray.origin);
  const denom = dot(n, d);
  const t = Math.abs(denom) > 1e-9 ? dot(n, toBob) / denom : -1;
  // the crossing in front of the camera, else the point of the ray nearest the bob
  const point = t > 0 ? add(ray.origin, scale(d, t)) : add(ray.origin, scale(d, Math.max(dot(toBob, d), 0)));
  let offset = sub(point, bob);
  offset = sub(offset, scale(n, dot(offset, n))); // exactly in the plane (removes rounding and the fallback's normal part)
  let v = scale(offset, 1 / arrowScale);
  const speed = Math.hypot(...v);
  if (!Number.isFinite(speed)) return null;
  const limit = Math.max(vmax, 0);
  if (speed > limit) {
    v = speed > 0 ? scale(v, limit / speed) : [0, 0, 0];
    return { v, speed: limit, capped: true };
  }
  return { v, speed, capped: false };
}

/** Where the grab handle of the velocity arrow sits, relative to the bob [m]: at the arrow's tip
 *  (`arrowScale` · v), or, while the tip is hidden in the bob (closer than `clear` [m]), at `clear` from
 *  the bob's centre along v — along the horizontal tangent (e₃ × x, else e₁ at the poles) when v = 0. */
export function handleOffset(x: Vec3, v: Vec3, arrowScale: number, clear: number): Vec3 {
  const tip = scale(v, arrowScale);
  const len = Math.hypot(...tip);
  if (len >= clear) return tip;
  if (len > 1e-12 * clear) return scale(tip, clear / len);
  const h: Vec3 = [-x[1], x[0], 0]; // e₃ × x
  const hn = Math.hypot(...h);
  return hn > 1e-12 * Math.hypot(...x) && hn > 0 ? scale(h, clear / hn) : [clear, 0, 0];
}
