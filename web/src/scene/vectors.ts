// The vectors the scene can draw at the bob, from the server's numbers only (no DOM, no WebGL, unit-tested):
// velocity v, momentum m v, gravity m g d, the rod force −T x/|x|, the net force m a (a = ẍ from the core),
// and about a chosen origin o (relative to the pivot; the pivot by default) the angular momentum
// L = (x − o) × m v and the torque τ = (x − o) × m a, so that dL/dt = τ. All in the pivot's frame (the
// model's own: rotating or moving with the pivot where the model says so), SI units. The page computes
// nothing dynamic here: tension and acceleration are the core's, the rest is algebra on them.
import type { Frame, ModelParams, Vec3 } from '../protocol';

export type VectorName = 'velocity' | 'momentum' | 'gravity' | 'tension' | 'net' | 'angularMomentum' | 'torque';

export interface Vectors {
  /** Velocity v [m/s]. */
  velocity: Vec3;
  /** Momentum m v [kg m/s]. */
  momentum: Vec3;
  /** Weight m g d [N] (d the unit gravity direction, −e₃ unless the model tilts it). */
  gravity: Vec3;
  /** Force of the rod on the bob −T x/|x| [N]. */
  tension: Vec3;
  /** Net force m a [N], a the core's acceleration relative to the pivot. */
  net: Vec3;
  /** Angular momentum about the origin (x − o) × m v [kg m²/s]. */
  angularMomentum: Vec3;
  /** Torque about the origin (x − o) × m a [N m]. */
  torque: Vec3;
}

export const cross = (a: Vec3, b: Vec3): Vec3 => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
const scale = (a: Vec3, k: number): Vec3 => [a[0] * k, a[1] * k, a[2] * k];
const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];

/** The unit gravity direction d of a model: (gravity_x, gravity_y, gravity_z) normalised where the model
 *  has them (damped), −e₃ otherwise. */
export function gravityDirection(params: ModelParams | undefined): Vec3 {
  const d: Vec3 = [params?.['gravity_x'] ?? 0, params?.['gravity_y'] ?? 0, params?.['gravity_z'] ?? -1];
  const n = Math.hypot(...d);
  return n > 0 ? scale(d, 1 / n) : [0, 0, -1];
}

/** Every vector at the frame `f` of a bob of mass [kg] under gravity g [m/s²] along `gdir`, about the origin
 *  `origin` [m] relative to the pivot. */
export function bobVectors(f: Frame, mass: number, g: number, gdir: Vec3, origin: Vec3): Vectors {
  const r = Math.hypot(...f.x);
  const momentum = scale(f.v, mass);
  const net = scale(f.a, mass);
  const arm = sub(f.x, origin);
  return {
    velocity: f.v,
    momentum,
    gravity: scale(gdir, mass * g),
    tension: r > 0 ? scale(f.x, -f.tension / r) : [0, 0, 0],
    net,
    angularMomentum: cross(arm, momentum),
    torque: cross(arm, net),
  };
}

/** Metres of arrow per unit of each vector, for a pendulum of length [m], mass [kg], gravity g [m/s²]:
 *  velocity and momentum as 0.25 s of travel (momentum per kg), forces on one scale (m·max(|g|, 1) N ↔
 *  0.5 l), angular momentum m l² ω (ω = √(max(|g|, 1)/l)) ↔ 0.5 l, torque m·max(|g|, 1)·l N m ↔ 0.5 l. */
export function arrowScales(length: number, mass: number, g: number): Record<VectorName, number> {
  const gg = Math.max(Math.abs(g), 1);
  const force = (0.5 * length) / (mass * gg);
  const omega = Math.sqrt(gg / length);
  return {
    velocity: 0.25,
    momentum: 0.25,
    gravity: force,
    tension: force,
    net: force,
    angularMomentum: (0.5 * length) / (mass * length * length * omega),
    torque: force / length,
  };
}
