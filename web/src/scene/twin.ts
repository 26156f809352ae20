// The second pendulum in the scene (two-pendulum mode, docs/web.md "Two pendulums"): its bob, a thin rod and
// its trail in green, drawn from the second session's streamed states (interpolated at the first one's
// time by panels/twin.ts). Only drawing.
import * as THREE from 'three';
import type { Frame } from '../protocol';
import { TRAIL_MAX } from '../state';

/** The colour of the second pendulum. */
export const TWIN_COLOR = 0xc8f560;
/** The colours of pendulums 3 and 4 (panels/extras.ts). */
export const EXTRA_COLORS = [0xff7ad9, 0x6fd3ff] as const;

const Y = new THREE.Vector3(0, 1, 0);

/** Trail frames `frames[start..end)`, oldest first. */
export interface TwinTrail {
  frames: readonly Frame[];
  start: number;
  end: number;
}

export class TwinDrawing {
  readonly group = new THREE.Group();
  readonly bob: THREE.Mesh;
  private readonly rod: THREE.Mesh;
  /** The second pivot, drawn when it is not the first's (mode `own`). */
  private readonly pivotMark: THREE.Mesh;
  private readonly trail: THREE.Line;
  private readonly positions = new Float32Array(3 * (TRAIL_MAX + 1));
  private readonly tmpX = new THREE.Vector3();
  private readonly tmpPivot = new THREE.Vector3();
  private readonly tmpDir = new THREE.Vector3();
  private length = 1;
  /** Where the second pivot is drawn relative to the first [m] (mode `own`: side by side; else 0). */
  readonly offset = new THREE.Vector3();

  constructor(color: number = TWIN_COLOR) {
    this.bob = new THREE.Mesh(new THREE.SphereGeometry(1, 24, 16), new THREE.MeshStandardMaterial({ color, roughness: 0.4 }));
    this.rod = new THREE.Mesh(
      new THREE.CylinderGeometry(1, 1, 1, 8),
      new THREE.MeshStandardMaterial({ color, metalness: 0.3, roughness: 0.5 }),
    );
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(this.positions, 3));
    g.setDrawRange(0, 0);
    this.trail = new THREE.Line(g, new THREE.LineBasicMaterial({ color, transparent: true, opacity: 0.6 }));
    this.trail.frustumCulled = false;
    this.pivotMark = new THREE.Mesh(new THREE.SphereGeometry(1, 12, 8), new THREE.MeshStandardMaterial({ color }));
    this.pivotMark.visible = false;
    this.group.add(this.bob, this.rod, this.trail, this.pivotMark);
    this.group.visible = false;
  }

  /** Rescales to rod length l [m]; the bob, rod and pivot drawn at the size of a pendulum of length
   *  `size` [m] (a row of pendulums: the first's, so that a short one stays as visible as the others). */
  setLength(l: number, size = l): void {
    this.length = size;
    this.bob.scale.setScalar(0.045 * size);
  }

  /** Hangs the second pendulum from its own pivot at `offset` [m] from the first (null: the same pivot). */
  setOffset(offset: readonly [number, number, number] | null): void {
    if (offset === null) this.offset.set(0, 0, 0);
    else this.offset.fromArray(offset);
    this.pivotMark.visible = offset !== null;
    this.pivotMark.position.copy(this.offset);
    this.pivotMark.scale.setScalar(0.03 * this.length);
  }

  /** Draws the state `f` (null: hidden) with the trail frames. */
  update(f: Frame | null, trail: TwinTrail): void {
    this.group.visible = f !== null;
    if (f === null) return;
    const x = this.tmpX.fromArray(f.x);
    const pivot = this.tmpPivot.fromArray(f.pivot).add(this.offset);
    this.bob.position.copy(x).add(pivot);
    const r = x.length();
    if (r > 0) {
      this.rod.position.copy(x).multiplyScalar(0.5).add(pivot);
      this.rod.quaternion.setFromUnitVectors(Y, this.tmpDir.copy(x).divideScalar(r));
      this.rod.scale.set(0.005 * this.length, r, 0.005 * this.length);
    }
    const n = Math.max(0, Math.min(trail.end - trail.start, TRAIL_MAX));
    const p = this.positions;
    for (let i = 0; i < n; i++) {
      const g = trail.frames[trail.end - n + i] as Frame;
      p[3 * i] = g.x[0] + g.pivot[0] + this.offset.x;
      p[3 * i + 1] = g.x[1] + g.pivot[1] + this.offset.y;
      p[3 * i + 2] = g.x[2] + g.pivot[2] + this.offset.z;
    }
    const geom = this.trail.geometry;
    geom.setDrawRange(0, n);
    const position = geom.getAttribute('position') as THREE.BufferAttribute;
    position.clearUpdateRanges();
    position.addUpdateRange(0, 3 * Math.max(n, 1));
    position.needsUpdate = true;
  }
}
