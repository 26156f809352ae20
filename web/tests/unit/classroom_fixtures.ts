// Known motions and a status for the classroom tools' unit tests (measure, controls, twin, inclusion
// .test.ts): a frame from t [s], x [m], v [m/s]; a planar swing sampled at 60 Hz; an ideal pendulum's
// status (l = 1 m, m = 1 kg, g = 9.81 m/s²). Not a test file itself.
import type { Frame, Status, Vec3 } from '../../src/protocol';

export function frame(t: number, x: Vec3, v: Vec3, extra: Partial<Frame> = {}): Frame {
  return { t, x, v, energy: 0, j3: 0, tension: 0, power: 0, a: [NaN, NaN, NaN], pivot: [0, 0, 0], taut: true, errorX: 0, ...extra };
}

/** A planar motion in the vertical plane at azimuth `az` with signed angle θ(t) and rate θ̇(t) [rad, rad/s],
 *  l = 1 m, sampled at 60 Hz for `seconds`, optionally with a small sideways offset `side` [m] (a thin
 *  ellipse: J₃ ≠ 0). */
export function planar(theta: (t: number) => number, rate: (t: number) => number, seconds: number, az = 0.7, side = 0): Frame[] {
  const out: Frame[] = [];
  const [c, s] = [Math.cos(az), Math.sin(az)];
  for (let k = 0; k <= seconds * 60; k++) {
    const t = k / 60;
    const [q, w] = [theta(t), rate(t)];
    const u = side * Math.cos(2 * Math.PI * t);
    const x: Vec3 = [Math.sin(q) * c - u * s, Math.sin(q) * s + u * c, -Math.cos(q)];
    out.push(frame(t, x, [Math.cos(q) * w * c, Math.cos(q) * w * s, Math.sin(q) * w]));
  }
  return out;
}

export const status = (over: Partial<Status> = {}): Status => ({
  type: 'status',
  epoch: 1,
  scenario: null,
  title: null,
  paused: false,
  time_scale: 1,
  method: 'rattle',
  adaptive: false,
  dt: 0.001,
  params: { length: 1, mass: 1, g: 9.81 },
  model: 'ideal',
  model_params: {},
  t: 0,
  t0: 0,
  start: { x: [Math.sin(0.5), 0, -Math.cos(0.5)], v: [0, 1, 0] },
  lagging: false,
  frame_fields: [],
  ...over,
});
