// Dragging the bob over the sphere of reach to choose a start: a press on the bob stops the camera's
// orbiting and starts a drag; while the pointer moves, the ray under it is cut with the sphere of radius l
// around the pivot (the nearer crossing, else the sphere's point nearest the ray), and the position
// relative to the pivot [m] is handed on; releasing ends it. The page turns that into `set_state` (at rest
// there: v = 0) — the server checks it and computes everything from it.
import * as THREE from 'three';
import type { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import type { Vec3 } from '../protocol';

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
