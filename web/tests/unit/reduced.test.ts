import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import type { ReducedCurves } from '../../src/protocol';
import { pointOnSphere } from '../../src/scene/drag';
import { boxScales, sigmaOf } from '../../src/scene/reduced';

describe('reduced view', () => {
  it('takes σ₁ = z/l, σ₂ = ż/l, σ₃ = |v|²/l² of a state', () => {
    expect(sigmaOf({ x: [0, 1, -1.5], v: [1, 2, 2] }, 2)).toEqual([-0.75, 1, 9 / 4]);
  });

  it('scales the box by the span of σ₂ and above the orbit’s largest σ₃', () => {
    const c: ReducedCurves = {
      orbit: { sigma1: [0], sigma2: [0], sigma3: [2, 5] },
      orbit_time: 1,
      surface: { sigma1: [0], sigma2: [-3, 3], sigma3: [[1, 1]] },
      plane: { h: 1, gamma: 9.81 },
      point: [0, 0, 4],
      j: 1,
    };
    expect(boxScales(c)).toEqual({ s2: 3, s3top: 1.6 * 5 + 1e-9 });
  });
});

describe('dragging the bob', () => {
  const c = new THREE.Vector3(1, 0, 0);
  it('takes the nearer crossing of the ray with the sphere, relative to its centre', () => {
    const ray = new THREE.Ray(new THREE.Vector3(1, -5, 0), new THREE.Vector3(0, 1, 0));
    const p = pointOnSphere(ray, c, 2);
    expect(p.toArray()).toEqual([0, -2, 0]);
  });

  it('slides along the rim when the ray misses the sphere', () => {
    const ray = new THREE.Ray(new THREE.Vector3(1, -5, 3), new THREE.Vector3(0, 1, 0));
    const p = pointOnSphere(ray, c, 2);
    expect(p.length()).toBeCloseTo(2, 14);
    expect(p.z).toBeCloseTo(2, 14);
  });
});
