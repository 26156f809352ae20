// The vector arrows drawn in the scene (docs/web.md, "Vectors"; the colours are options.ts's legend): one
// three.js arrow per vector of vectors.ts, from the bob (velocity, momentum, gravity, rod force, net force)
// or from the chosen origin (angular momentum, torque), each scaled by arrowScales so that a typical value
// is a fraction of the rod length l [m] (velocity [m per m/s], forces [m per N], ...). Only drawing.
import * as THREE from 'three';
import type { Frame, Vec3 } from '../protocol';
import type { VectorName } from './vectors';
import { arrowScales, bobVectors } from './vectors';
import { ARROW_COLORS } from './options';

/** Vectors drawn from the origin of the angular momentum rather than from the bob. */
const AT_ORIGIN: readonly VectorName[] = ['angularMomentum', 'torque'];

function arrow(color: number): THREE.ArrowHelper {
  const a = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 1, color);
  a.visible = false;
  return a;
}

/** Which arrows to draw and the origin [m, relative to the pivot] of the angular momentum and torque. */
export type ArrowChoice = Record<VectorName, boolean> & { originX: number; originY: number; originZ: number };

export class VectorArrows {
  readonly arrows = Object.fromEntries(
    Object.entries(ARROW_COLORS).map(([name, color]) => [name, arrow(color)]),
  ) as Record<VectorName, THREE.ArrowHelper>;
  // scratch vectors: update() runs every frame and allocates none of its own
  private readonly tmpVec = new THREE.Vector3();
  private readonly tmpOrigin = new THREE.Vector3();

  /** The arrows, to add to a scene. */
  objects(): THREE.ArrowHelper[] {
    return Object.values(this.arrows);
  }

  hide(): void {
    for (const a of Object.values(this.arrows)) a.visible = false;
  }

  /** Draws the chosen vectors of state `f` for mass `mass` [kg], gravity g [m/s²] along the unit vector
   *  `gdir`: from the bob at `bob` [m, world] or from the origin beside the pivot at `pivot` [m, world];
   *  `length` [m] is the rod length the arrows are scaled to. */
  update(
    f: Frame,
    view: ArrowChoice,
    mass: number,
    g: number,
    gdir: Vec3,
    pivot: THREE.Vector3,
    bob: THREE.Vector3,
    length: number,
  ): void {
    const names = Object.keys(this.arrows) as VectorName[];
    if (!names.some((name) => view[name])) {
      for (const name of names) this.arrows[name].visible = false;
      return;
    }
    const origin: Vec3 = [view.originX, view.originY, view.originZ];
    const vectors = bobVectors(f, mass, g, gdir, origin);
    const scales = arrowScales(length, mass, g);
    const originWorld = this.tmpOrigin.fromArray(origin).add(pivot);
    for (const name of names) {
      const from = AT_ORIGIN.includes(name) ? originWorld : bob;
      const vec = this.tmpVec.fromArray(vectors[name]).multiplyScalar(scales[name]);
      setArrow(this.arrows[name], view[name], from, vec, length);
    }
  }
}

/** Points the arrow `a` from `from` along `vec` (which it may scale); hidden when off or shorter than
 *  1e-6 l; the head a quarter of the arrow, at most 0.08 l. */
function setArrow(a: THREE.ArrowHelper, on: boolean, from: THREE.Vector3, vec: THREE.Vector3, length: number): void {
  const len = vec.length();
  a.visible = on && len > 1e-6 * length;
  if (!a.visible) return;
  a.position.copy(from);
  a.setDirection(vec.divideScalar(len));
  const head = Math.min(0.25 * len, 0.08 * length);
  a.setLength(len, head, 0.5 * head);
}
