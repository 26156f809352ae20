import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../src/protocol';
import { arrowScales } from '../../src/scene/vectors';
import { handleOffset, maxStartSpeed, velocityFromRay } from '../../src/scene/velocity';

const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const S = arrowScales(1, 1, 9.81).velocity; // 0.25 m of arrow per m/s
const BIG = 1e9;

/** Distance from point p to the ray (origin o, direction d). */
function distanceToRay(p: Vec3, o: Vec3, d: Vec3): number {
  const n = Math.hypot(...d);
  const u: Vec3 = [d[0] / n, d[1] / n, d[2] / n];
  const w: Vec3 = [p[0] - o[0], p[1] - o[1], p[2] - o[2]];
  const t = dot(w, u);
  return Math.hypot(w[0] - t * u[0], w[1] - t * u[1], w[2] - t * u[2]);
}

describe('pulling the velocity arrow', () => {
  it('looking at the bob along its radius: v is the offset on the screen over the arrow scale', () => {
    // bob at the bottom (0, 0, -1); camera below it looking up, pointer 0.5 m along +x from the bob
    const r = velocityFromRay({ origin: [0.5, 0, -6], direction: [0, 0, 2] }, [0, 0, 0], [0, 0, -1], S, BIG);
    expect(r).not.toBeNull();
    expect(r!.v[0]).toBeCloseTo(0.5 / S, 12);
    expect(r!.v[1]).toBeCloseTo(0, 12);
    expect(r!.v[2]).toBeCloseTo(0, 12);
    expect(r!.speed).toBeCloseTo(2, 12);
    expect(r!.capped).toBe(false);
  });

  it('puts the arrow tip under the pointer on an oblique ray, with v tangent to the sphere', () => {
    const pivot: Vec3 = [0.3, -0.2, 0.5];
    const x: Vec3 = [0.6, 0, -0.8];
    const o: Vec3 = [4, -5, 2];
    const d: Vec3 = [-0.55, 0.9, -0.37];
    const r = velocityFromRay({ origin: o, direction: d }, pivot, x, S, BIG)!;
    expect(Math.abs(dot(r.v, x))).toBeLessThan(1e-12);
    const tip: Vec3 = [pivot[0] + x[0] + S * r.v[0], pivot[1] + x[1] + S * r.v[1], pivot[2] + x[2] + S * r.v[2]];
    expect(distanceToRay(tip, o, d)).toBeLessThan(1e-12);
    expect(r.speed).toBeCloseTo(Math.hypot(...r.v), 12);
  });

  it('uses the plane perpendicular to the bob’s own radius off the sphere (spring, slack string)', () => {
    const x: Vec3 = [0, 1.7, 0]; // |x| = 1.7, the rest length 1
    const r = velocityFromRay({ origin: [0.25, 8, 0.5], direction: [0, -1, 0] }, [0, 0, 0], x, S, BIG)!;
    expect(r.v[0]).toBeCloseTo(1, 12);
    expect(r.v[1]).toBe(0);
    expect(r.v[2]).toBeCloseTo(2, 12);
  });

  it('caps |v| at vmax, keeping the direction asked for', () => {
    const r = velocityFromRay({ origin: [30, 40, -6], direction: [0, 0, 1] }, [0, 0, 0], [0, 0, -1], S, 5)!;
    expect(r.capped).toBe(true);
    expect(r.speed).toBe(5);
    expect(Math.hypot(...r.v)).toBeCloseTo(5, 12);
    expect(r.v[0]).toBeCloseTo(3, 12);
    expect(r.v[1]).toBeCloseTo(4, 12);
  });

  it('stays finite and tangent when the ray runs along the plane or the plane is behind the camera', () => {
    const x: Vec3 = [0, 0, -1];
    const along = velocityFromRay({ origin: [-3, 0.2, -1], direction: [1, 0, 0] }, [0, 0, 0], x, S, 8)!;
    expect(along.v.every(Number.isFinite)).toBe(true);
    expect(along.v[2]).toBe(0);
    expect(along.v[1]).toBeCloseTo(0.2 / S, 12);
    const behind = velocityFromRay({ origin: [0.1, 0, -3], direction: [0, 0, -1] }, [0, 0, 0], x, S, 8)!;
    expect(behind.v[2]).toBe(0);
    expect(behind.v[0]).toBeCloseTo(0.1 / S, 12);
  });

  it('refuses x = 0 and non-finite input', () => {
    expect(velocityFromRay({ origin: [0, 0, 5], direction: [0, 0, -1] }, [0, 0, 0], [0, 0, 0], S, 5)).toBeNull();
    expect(velocityFromRay({ origin: [NaN, 0, 5], direction: [0, 0, -1] }, [0, 0, 0], [0, 0, -1], S, 5)).toBeNull();
    expect(velocityFromRay({ origin: [0, 0, 5], direction: [0, 0, 0] }, [0, 0, 0], [0, 0, -1], S, 5)).toBeNull();
  });

  it('caps at 4 √(max(|g|, 1) l): twice the speed that carries the bob over the top', () => {
    expect(maxStartSpeed(1, 9.81)).toBeCloseTo(2 * 2 * Math.sqrt(9.81), 12);
    expect(maxStartSpeed(2, -9.81)).toBeCloseTo(4 * Math.sqrt(19.62), 12);
    expect(maxStartSpeed(1, 0)).toBe(4);
  });

  it('puts the handle at the tip, or just outside the bob while the tip is hidden in it', () => {
    expect(handleOffset([0, 0, -1], [2, 0, 0], 0.25, 0.085)).toEqual([0.5, 0, 0]);
    const short = handleOffset([0, 0, -1], [0, 0.1, 0], 0.25, 0.085);
    expect(short[1]).toBeCloseTo(0.085, 15);
    // at rest: along the horizontal tangent e₃ × x, at the pole along e₁
    const rest = handleOffset([1, 0, 0], [0, 0, 0], 0.25, 0.085);
    expect(rest[0]).toBeCloseTo(0, 15);
    expect(rest[1]).toBeCloseTo(0.085, 15);
    expect(handleOffset([0, 0, -1], [0, 0, 0], 0.25, 0.085)).toEqual([0.085, 0, 0]);
  });
});
