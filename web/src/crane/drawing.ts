// The crane as a crane engineer draws it (docs/web.md, "Crane mode"): a girder the trolley runs on, the
// trolley at the pivot, the rope down to the hook block, slings and the load, and the wind as an arrow at
// the load. It only places what the frames say: the trolley at frame.pivot, the rope's end (the load's
// point mass, hook and payload together) at pivot + x. Coordinates are the physics' (z up, metres).
import * as THREE from 'three';
import type { Frame, Vec3 } from '../protocol';

/** How long the girder is drawn [m] (centred on the origin, along x). */
export const GIRDER_LENGTH = 80;
/** The hook block sits this far [m] above the rope's end; the load box hangs below it. */
const HOOK_ABOVE = 1.0;
/** Wind arrow: metres of arrow per m/s of wind, and its longest [m]. */
const WIND_SCALE = 0.4;
const WIND_MAX = 8;

function box(w: number, d: number, h: number, color: number): THREE.Mesh {
  return new THREE.Mesh(new THREE.BoxGeometry(w, d, h), new THREE.MeshStandardMaterial({ color, roughness: 0.6 }));
}

function line(color: number, points: number, segments = false): THREE.Line {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(points * 3), 3));
  const material = new THREE.LineBasicMaterial({ color });
  const l = segments ? new THREE.LineSegments(g, material) : new THREE.Line(g, material);
  l.frustumCulled = false;
  return l;
}

function setLine(l: THREE.Line, ...pts: THREE.Vector3[]): void {
  const pos = l.geometry.getAttribute('position') as THREE.BufferAttribute;
  pts.forEach((p, i) => pos.setXYZ(i, p.x, p.y, p.z));
  pos.needsUpdate = true;
}

const DOWN = new THREE.Vector3(0, 0, -1);

export class CraneDrawing {
  readonly group = new THREE.Group();
  private readonly girder = box(GIRDER_LENGTH, 0.5, 0.7, 0xf2b600);
  private readonly trolley = box(1.4, 1.1, 0.5, 0xe07020);
  private readonly rope = line(0xcfd6e0, 2);
  private readonly hook = box(0.45, 0.3, 0.6, 0xf2c200);
  private readonly load = box(1.6, 1.2, 1.0, 0x4a7bd0);
  private readonly slings = line(0xb0b8c0, 4, true);
  private readonly wind = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 1, 0x66ddff, 0.6, 0.4);
  private readonly p = new THREE.Vector3();
  private readonly end = new THREE.Vector3();
  private readonly u = new THREE.Vector3();

  constructor() {
    this.group.add(this.girder, this.trolley, this.rope, this.hook, this.load, this.slings, this.wind);
    this.group.visible = false;
  }

  /** Shows the crane at frame `f` with the wind (x, y) [m/s], or hides it (f null). */
  update(f: Frame | null, wind: Vec3 | null): void {
    this.group.visible = f !== null;
    if (f === null) return;
    const p = this.p.fromArray(f.pivot);
    const end = this.end.fromArray(f.x).add(p);
    const l = Math.hypot(...f.x);
    const u = this.u.fromArray(f.x).divideScalar(l > 0 ? l : 1);
    this.girder.position.set(0, p.y, p.z + 0.6);
    this.trolley.position.set(p.x, p.y, p.z + 0.25);
    const hook = u.clone().multiplyScalar(-Math.min(HOOK_ABOVE, 0.5 * l)).add(end);
    setLine(this.rope, p, hook);
    const turn = new THREE.Quaternion().setFromUnitVectors(DOWN, u);
    this.hook.position.copy(hook);
    this.hook.quaternion.copy(turn);
    this.load.position.copy(u.clone().multiplyScalar(0.5).add(end));
    this.load.quaternion.copy(turn);
    const corner = (sx: number) => new THREE.Vector3(0.7 * sx, 0, 0).applyQuaternion(turn).add(end);
    setLine(this.slings, hook, corner(-1), hook, corner(1));
    const speed = wind === null ? 0 : Math.hypot(wind[0], wind[1]);
    this.wind.visible = speed > 0;
    if (wind !== null && speed > 0) {
      const len = Math.min(WIND_MAX, Math.max(1, WIND_SCALE * speed));
      const dir = new THREE.Vector3(wind[0] / speed, wind[1] / speed, 0);
      this.wind.setDirection(dir);
      this.wind.setLength(len, 0.6, 0.4);
      this.wind.position.copy(end).addScaledVector(dir, -len - 1.5);
    }
  }
}
