// Dragging the bob over the sphere of reach to choose a start: a press on the bob stops the camera's
// orbiting and starts a drag; while the pointer moves, the ray under it is cut with the sphere of radius l
// around the pivot (the nearer crossing, else the sphere's point nearest the ray), and the position
// relative to the pivot [m] is handed on; releasing ends it. The page turns that into `set_state` (at rest
// there: v = 0) — the server checks it and computes everything from it. Likewise pulling the velocity
// arrow's grab handle chooses the start velocity at the bob's position (VelocityDrag; its geometry in
// velocity.ts).
import * as THREE from 'three';
import type { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import type { Vec3 } from '../protocol';
import type { PulledVelocity } from './velocity';
import { velocityFromRay } from './velocity';

export type DragPhase = 'start' | 'move' | 'end';

/** The point of the sphere (centre c, radius r) under the ray: the nearer crossing, or where the ray
 *  passes closest when it misses (so a drag past the rim slides along it). Relative to the centre. */
export function pointOnSphere(ray: THREE.Ray, c: THREE.Vector3, r: number): THREE.Vector3 {
  const hit = ray.intersectSphere(new THREE.Sphere(c, r), new THREE.Vector3());
  if (hit !== null) return hit.sub(c);
  const closest = ray.closestPointToPoint(c, new THREE.Vector3()).sub(c);
  const n = closest.length();
  return n > 0 ? closest.multiplyScalar(r / n) : new THREE.Vector3(0, 0, -r);
}

export class BobDrag {
  private dragging = false;
  private readonly raycaster = new THREE.Raycaster();

  constructor(
    private readonly canvas: HTMLCanvasElement,
    private readonly camera: THREE.Camera,
    private readonly controls: OrbitControls,
    private readonly bob: THREE.Object3D,
    private readonly onDrag: (x: Vec3, phase: DragPhase) => void,
    private readonly sphere: () => { pivot: THREE.Vector3; length: number },
  ) {
    canvas.addEventListener('pointerdown', (e) => this.down(e), { capture: true });
    canvas.addEventListener('pointermove', (e) => this.move(e));
    canvas.addEventListener('pointerup', (e) => this.up(e));
    canvas.addEventListener('pointercancel', (e) => this.up(e));
  }

  get active(): boolean {
    return this.dragging;
  }

  private ray(e: PointerEvent): THREE.Ray {
    const r = this.canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.camera);
    return this.raycaster.ray;
  }

  private position(e: PointerEvent): Vec3 {
    const { pivot, length } = this.sphere();
    const p = pointOnSphere(this.ray(e), pivot, length);
    return [p.x, p.y, p.z];
  }

  private down(e: PointerEvent): void {
    if (e.button !== 0 || !this.bob.visible) return;
    this.ray(e);
    if (this.raycaster.intersectObject(this.bob, false).length === 0) return;
    this.dragging = true;
    this.controls.enabled = false;
    this.canvas.setPointerCapture?.(e.pointerId);
    e.stopImmediatePropagation();
    this.onDrag(this.position(e), 'start');
  }

  private move(e: PointerEvent): void {
    if (this.dragging) this.onDrag(this.position(e), 'move');
  }

  private up(e: PointerEvent): void {
    if (!this.dragging) return;
    this.dragging = false;
    this.controls.enabled = true;
    this.onDrag(this.position(e), 'end');
  }
}

/** What a pull of the velocity arrow works with, read when it starts: the pivot and the bob's position
 *  relative to it [m] as drawn, metres of arrow per m/s, and the largest speed it may set [m/s]. */
export interface PullBasis {
  pivot: Vec3;
  x: Vec3;
  arrowScale: number;
  vmax: number;
}

/** Pulling the velocity arrow by its grab handle (`handle`, at the arrow's tip): a press on it starts a
 *  pull (the camera's orbiting off); while the pointer moves, the velocity whose arrow ends under it
 *  (velocity.ts `velocityFromRay`, in the plane through the bob perpendicular to x, x fixed at the start
 *  of the pull) is handed on; releasing ends it. `onPull(x, pulled, phase)`: pulled is null at the start
 *  and at an end without any move (a press alone changes nothing). */
/** The last pull as released (for tests): the pointer and the pulled velocity's arrow tip on the page
 *  [CSS px], both with the camera of that instant, and the velocity [m/s] handed on. */
export interface ReleasedPull {
  pointer: { x: number; y: number };
  tip: { x: number; y: number };
  v: Vec3;
}

export class VelocityDrag {
  private basis: PullBasis | null = null;
  /** The last pull released with a move (null: none yet). */
  last: ReleasedPull | null = null;
  private moved = false;
  private readonly raycaster = new THREE.Raycaster();
  private readonly tmp = new THREE.Vector3();

  constructor(
    private readonly canvas: HTMLCanvasElement,
    private readonly camera: THREE.Camera,
    private readonly controls: OrbitControls,
    private readonly handle: THREE.Object3D,
    /** What may hide the handle (the bob): a press on it in front of the handle is not a pull. */
    private readonly occluder: THREE.Object3D,
    /** The handle's grab radius [m] (a little more than the drawn one, to be easy to hit). */
    private readonly grabRadius: () => number,
    private readonly pullBasis: () => PullBasis | null,
    private readonly onPull: (x: Vec3, pulled: PulledVelocity | null, phase: DragPhase) => void,
  ) {
    canvas.addEventListener('pointerdown', (e) => this.down(e), { capture: true });
    canvas.addEventListener('pointermove', (e) => this.move(e));
    canvas.addEventListener('pointerup', (e) => this.up(e));
    canvas.addEventListener('pointercancel', (e) => this.up(e));
  }

  get active(): boolean {
    return this.basis !== null;
  }

  private ray(e: PointerEvent): THREE.Ray {
    const r = this.canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.camera);
    return this.raycaster.ray;
  }

  private pulled(e: PointerEvent): PulledVelocity | null {
    if (this.basis === null) return null;
    const ray = this.ray(e);
    const { pivot, x, arrowScale, vmax } = this.basis;
    return velocityFromRay(
      { origin: [ray.origin.x, ray.origin.y, ray.origin.z], direction: [ray.direction.x, ray.direction.y, ray.direction.z] },
      pivot,
      x,
      arrowScale,
      vmax,
    );
  }

  /** The pointer and the tip of the arrow of `v` (pivot + x + v · arrowScale) on the page now. */
  private released(e: PointerEvent, basis: PullBasis, v: Vec3): ReleasedPull {
    const { pivot, x, arrowScale } = basis;
    const p = this.tmp.set(pivot[0] + x[0] + v[0] * arrowScale, pivot[1] + x[1] + v[1] * arrowScale, pivot[2] + x[2] + v[2] * arrowScale).project(this.camera);
    const r = this.canvas.getBoundingClientRect();
    const tip = { x: r.left + ((p.x + 1) / 2) * r.width, y: r.top + ((1 - p.y) / 2) * r.height };
    return { pointer: { x: e.clientX, y: e.clientY }, tip, v: [...v] };
  }

  private down(e: PointerEvent): void {
    if (e.button !== 0 || !this.handle.visible) return;
    const ray = this.ray(e);
    const centre = this.handle.getWorldPosition(this.tmp);
    const grab = this.grabRadius();
    if (ray.distanceToPoint(centre) > grab) return;
    const hidden = this.raycaster.intersectObject(this.occluder, false)[0];
    if (hidden !== undefined && hidden.distance < centre.sub(ray.origin).dot(ray.direction) - grab) return;
    const basis = this.pullBasis();
    if (basis === null) return;
    this.basis = basis;
    this.moved = false;
    this.controls.enabled = false;
    this.canvas.setPointerCapture?.(e.pointerId);
    e.stopImmediatePropagation();
    this.onPull(basis.x, null, 'start');
  }

  private move(e: PointerEvent): void {
    if (this.basis === null) return;
    this.moved = true;
    this.onPull(this.basis.x, this.pulled(e), 'move');
  }

  private up(e: PointerEvent): void {
    if (this.basis === null) return;
    const pulled = this.moved ? this.pulled(e) : null;
    const x = this.basis.x;
    if (pulled !== null) this.last = this.released(e, this.basis, pulled.v);
    this.basis = null;
    this.controls.enabled = true;
    this.onPull(x, pulled, 'end');
  }
}
