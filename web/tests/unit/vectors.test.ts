import { describe, expect, it } from 'vitest';
import type { Frame, Vec3 } from '../../src/protocol';
import { arrowScales, bobVectors, cross, gravityDirection } from '../../src/scene/vectors';

/** Uniform circular motion x = (R cos ωt, R sin ωt, −h) with its exact acceleration (test data, not physics). */
function conical(t: number, R = 0.6, w = 2, h = 0.8): Frame {
  return {
    t,
    x: [R * Math.cos(w * t), R * Math.sin(w * t), -h],
    v: [-R * w * Math.sin(w * t), R * w * Math.cos(w * t), 0],
    a: [-R * w * w * Math.cos(w * t), -R * w * w * Math.sin(w * t), 0],
    energy: 0,
    j3: 0,
    tension: 5,
    power: 0,
    pivot: [0, 0, 0],
    taut: true,
    errorX: 0,
  };
}

describe('vectors at the bob', () => {
  it('are m v, m g d, −T x/|x|, m a, and about the origin L = (x − o) × m v, τ = (x − o) × m a', () => {
    const f = conical(0.3);
    const o: Vec3 = [0.1, -0.2, 0.05];
    const v = bobVectors(f, 2, 9.81, [0, 0, -1], o);
    expect(v.momentum).toEqual(f.v.map((c) => 2 * c));
    expect(v.gravity).toEqual([0, 0, -2 * 9.81]);
    expect(v.net).toEqual(f.a.map((c) => 2 * c));
    const r = Math.hypot(...f.x);
    v.tension.forEach((c, i) => expect(c).toBeCloseTo((-5 * (f.x[i] as number)) / r, 14));
    const arm: Vec3 = [f.x[0] - o[0], f.x[1] - o[1], f.x[2] - o[2]];
    expect(v.angularMomentum).toEqual(cross(arm, v.momentum));
    expect(v.torque).toEqual(cross(arm, v.net));
  });

  it('satisfy dL/dt = τ along a motion (central difference)', () => {
    const o: Vec3 = [0.3, 0.1, -0.4];
    const h = 1e-5;
    const L = (t: number) => bobVectors(conical(t), 1.5, 9.81, [0, 0, -1], o).angularMomentum;
    const tau = bobVectors(conical(0.7), 1.5, 9.81, [0, 0, -1], o).torque;
    const [a, b] = [L(0.7 - h), L(0.7 + h)];
    for (let i = 0; i < 3; i++) expect(((b[i] as number) - (a[i] as number)) / (2 * h)).toBeCloseTo(tau[i] as number, 6);
  });

  it('about the pivot, L₃ is J₃ = m (x × v)·e₃ and a conical orbit has no vertical torque', () => {
    const f = conical(1.1);
    const v = bobVectors(f, 3, 9.81, [0, 0, -1], [0, 0, 0]);
    expect(v.angularMomentum[2]).toBeCloseTo(3 * (f.x[0] * f.v[1] - f.x[1] * f.v[0]), 14);
    expect(v.torque[2]).toBeCloseTo(0, 14);
  });

  it('takes the gravity direction of a model that tilts it, normalised; −e₃ otherwise', () => {
    expect(gravityDirection(undefined)).toEqual([0, 0, -1]);
    expect(gravityDirection({ damping: 0.1 })).toEqual([0, 0, -1]);
    const d = gravityDirection({ gravity_x: 3, gravity_y: 0, gravity_z: -4 });
    [0.6, 0, -0.8].forEach((c, i) => expect(d[i]).toBeCloseTo(c, 15));
    expect(gravityDirection({ gravity_x: 0, gravity_y: 0, gravity_z: 0 })).toEqual([0, 0, -1]);
    const v = bobVectors(conical(0), 1, -9.81, d, [0, 0, 0]);
    expect(v.gravity[2]).toBeCloseTo(0.8 * 9.81, 12); // negative g points the other way
  });

  it('are drawn on scales where the weight is half a rod and m l² ω₀ is half a rod', () => {
    const s = arrowScales(2, 3, 9.81);
    expect(3 * 9.81 * s.gravity).toBeCloseTo(1, 14);
    expect(s.tension).toBe(s.gravity);
    expect(s.net).toBe(s.gravity);
    expect(3 * 4 * Math.sqrt(9.81 / 2) * s.angularMomentum).toBeCloseTo(1, 14);
    expect(3 * 9.81 * 2 * s.torque).toBeCloseTo(1, 14);
    expect(arrowScales(1, 1, 0).gravity).toBe(0.5); // g = 0: the scale of |g| = 1
  });
});
