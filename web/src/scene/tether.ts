// The link from the pivot to the bob for the models that leave the sphere (models.ts): the swinging
// spring as a coil stretched from the pivot to the bob (its length is the spring's), and the slack string
// as a dashed curve of the string's length sagging between them (a quadratic Bézier whose arc length is
// the string's; straight when taut). The point sets are pure functions (unit-tested); `Tether` holds the
// two three.js lines. Positions relative to the pivot [m].
import * as THREE from 'three';
import type { Vec3 } from '../protocol';
import type { TetherStyle } from '../models';

const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const norm = (a: Vec3): number => Math.hypot(a[0], a[1], a[2]);
const scale = (a: Vec3, s: number): Vec3 => [a[0] * s, a[1] * s, a[2] * s];
const cross = (a: Vec3, b: Vec3): Vec3 => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];

/** A unit vector perpendicular to the unit vector `u`, as close to `prefer` as possible. */
function perpendicular(u: Vec3, prefer: Vec3): Vec3 {
  const d = prefer[0] * u[0] + prefer[1] * u[1] + prefer[2] * u[2];
  let p = sub(prefer, scale(u, d));
  if (norm(p) < 1e-9) p = Math.abs(u[0]) < 0.9 ? cross(u, [1, 0, 0]) : cross(u, [0, 1, 0]);
  return scale(p, 1 / norm(p));
}

/** Points of a helix of `turns` turns and radius `radius` [m] around the segment from the pivot (0) to `x`,
 *  `n` + 1 points from 0 to x (the ends on the axis: the coil starts and ends at pivot and bob). */
export function coilPoints(x: Vec3, turns: number, radius: number, n: number): Vec3[] {
  const r = norm(x);
  if (!(r > 0)) return [[0, 0, 0], [...x]];
  const u = scale(x, 1 / r);
  const e1 = perpendicular(u, [0, 0, 1]);
  const e2 = cross(u, e1);
  const out: Vec3[] = [];
  for (let i = 0; i <= n; i++) {
    const s = i / n;
    // the radius rises from 0 over the first and falls over the last 5 % (straight leads at the ends)
    const rho = radius * Math.min(1, s / 0.05, (1 - s) / 0.05);
    const a = 2 * Math.PI * turns * s;
    const [c, sn] = [Math.cos(a) * rho, Math.sin(a) * rho];
    out.push([
      x[0] * s + e1[0] * c + e2[0] * sn,
      x[1] * s + e1[1] * c + e2[1] * sn,
      x[2] * s + e1[2] * c + e2[2] * sn,
    ]);
  }
  return out;
}

/** Length of the polyline through `pts` [m]. */
export function polylineLength(pts: readonly Vec3[]): number {
  let s = 0;
  for (let i = 1; i < pts.length; i++) s += norm(sub(pts[i] as Vec3, pts[i - 1] as Vec3));
  return s;
}

function bezier(x: Vec3, control: Vec3, n: number): Vec3[] {
  const out: Vec3[] = [];
  for (let i = 0; i <= n; i++) {
    const s = i / n;
    const [b1, b2] = [2 * s * (1 - s), s * s];
    out.push([control[0] * b1 + x[0] * b2, control[1] * b1 + x[1] * b2, control[2] * b1 + x[2] * b2]);
  }
  return out;
}

/** `n` + 1 points of a slack string of length `length` [m] from the pivot (0) to the bob at `x`, sagging
 *  along `down` (a unit vector, the direction gravity pulls): the quadratic Bézier from 0 to x whose middle
 *  control point is moved along `down` (perpendicular to the chord) until the curve is as long as the
 *  string (to 0.1 %). Straight when |x| ≥ length. */
export function sagPoints(x: Vec3, length: number, n: number, down: Vec3 = [0, 0, -1]): Vec3[] {
  const r = norm(x);
  const mid = scale(x, 0.5);
  if (!(r > 0) || r >= length) return bezier(x, mid, n);
  const d = perpendicular(scale(x, 1 / r), down);
  const curve = (sag: number): Vec3[] => bezier(x, [mid[0] + d[0] * sag, mid[1] + d[1] * sag, mid[2] + d[2] * sag], n);
  let [lo, hi] = [0, length];
  for (let k = 0; k < 40 && hi - lo > 1e-4 * length; k++) {
    const m = 0.5 * (lo + hi);
    if (polylineLength(curve(m)) < length) lo = m;
    else hi = m;
  }
  return curve(0.5 * (lo + hi));
}

const COIL_POINTS = 400;
const STRING_POINTS = 48;

/** The coil and the slack string as three.js lines (hidden for the other styles). */
export class Tether {
  readonly group = new THREE.Group();
  private readonly coil: THREE.Line;
  private readonly slack: THREE.Line;

  constructor() {
    this.coil = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints(Array.from({ length: COIL_POINTS + 1 }, () => new THREE.Vector3())),
      new THREE.LineBasicMaterial({ color: 0xd8d8d8 }),
    );
    this.slack = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints(Array.from({ length: STRING_POINTS + 1 }, () => new THREE.Vector3())),
      new THREE.LineDashedMaterial({ color: 0xf2e6c9, dashSize: 0.04, gapSize: 0.03 }),
    );
    for (const line of [this.coil, this.slack]) {
      line.frustumCulled = false;
      line.visible = false;
    }
    this.group.add(this.coil, this.slack);
  }

  /** Draws `style` for the bob at `x` relative to the pivot at `pivot` [m]; `length` is the rod's (the
   *  spring's rest length, the string's length), `down` the direction gravity pulls. */
  update(style: TetherStyle, x: Vec3, pivot: Vec3, length: number, down: Vec3): void {
    this.coil.visible = style === 'coil';
    this.slack.visible = style === 'slack string';
    this.group.position.set(...pivot);
    if (style === 'coil') this.fill(this.coil, coilPoints(x, 14, 0.035 * length, COIL_POINTS));
    if (style === 'slack string') {
      this.fill(this.slack, sagPoints(x, length, STRING_POINTS, down));
      const m = this.slack.material as THREE.LineDashedMaterial;
      m.dashSize = 0.04 * length;
      m.gapSize = 0.03 * length;
      this.slack.computeLineDistances();
    }
  }

  private fill(line: THREE.Line, pts: readonly Vec3[]): void {
    const attr = line.geometry.getAttribute('position') as THREE.BufferAttribute;
    pts.forEach((p, i) => attr.setXYZ(i, p[0], p[1], p[2]));
    attr.needsUpdate = true;
  }
}
