// The measured path in the scene (docs/fit.md, "In the lab"): the bob positions of a fitted data file,
// relative to the fitted pivot [m] (z up, the physics' own coordinates), drawn as a dotted gold polyline
// about the lab's pivot beside the live fitted motion. Only drawing; the server computes the points.
import * as THREE from 'three';
import type { Vec3 } from '../protocol';

/** The colour of the measured path: gold, unlike the bob (orange), the trail and the axes. */
export const MEASURED_COLOR = 0xffd700;

/** Most points drawn (the server thins to 2000). */
export const MEASURED_MAX = 4000;

/** The points `x` [m] (relative to the pivot) about the pivot at `pivot` [m], as a flat xyz array; at
 *  most MEASURED_MAX of them, non-finite ones left out. */
export function pathPositions(x: readonly Vec3[], pivot: Vec3 = [0, 0, 0]): Float32Array {
  const kept = x.filter((p) => p.every(Number.isFinite)).slice(0, MEASURED_MAX);
  const out = new Float32Array(3 * kept.length);
  kept.forEach((p, i) => {
    out[3 * i] = p[0] + pivot[0];
    out[3 * i + 1] = p[1] + pivot[1];
    out[3 * i + 2] = p[2] + pivot[2];
  });
  return out;
}

/** The dash and gap lengths [m] of the dotted line for a path of `points` points of total length
 *  `length` [m]: dots of a third of the mean spacing, at least visible at l/400. */
export function dotPattern(length: number, points: number): { dash: number; gap: number } {
  const spacing = points > 1 ? length / (points - 1) : 0;
  const dash = Math.max(spacing / 3, 1e-4);
  return { dash, gap: Math.max(2 * dash, 1e-4) };
}

export class MeasuredDrawing {
  readonly line: THREE.Line;
  private readonly material = new THREE.LineDashedMaterial({ color: MEASURED_COLOR, dashSize: 0.01, gapSize: 0.02 });

  constructor() {
    this.line = new THREE.Line(new THREE.BufferGeometry(), this.material);
    this.line.frustumCulled = false;
    this.line.visible = false;
    this.line.name = 'measured-path';
  }

  /** Draws the points `x` [m] relative to the pivot (null or empty: nothing). */
  set(x: readonly Vec3[] | null): void {
    this.line.geometry.dispose();
    const geom = new THREE.BufferGeometry();
    const positions = pathPositions(x ?? []);
    geom.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    this.line.geometry = geom;
    const n = positions.length / 3;
    this.line.visible = n > 1;
    if (n < 2) return;
    this.line.computeLineDistances();
    const dist = geom.getAttribute('lineDistance') as THREE.BufferAttribute;
    const { dash, gap } = dotPattern(dist.getX(n - 1), n);
    this.material.dashSize = dash;
    this.material.gapSize = gap;
  }

  /** The number of points drawn (0 when hidden), for tests. */
  get points(): number {
    return this.line.visible ? this.line.geometry.getAttribute('position').count : 0;
  }
}
