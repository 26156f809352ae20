// The first pendulum's body in the scene: the pivot (where the model moves it), the faint sphere of reach
// (its equator, and its lines in the anaglyph and with a software renderer: framing.ts, quality.ts), the rod, the bob, the axes, the link the model
// draws instead of a rod (the spring's coil, the slack string: tether.ts), the slewing crane's boom from the
// slewing axis to the pivot, and the velocity arrow's grab handle (velocity.ts, drag.ts). Coordinates are the
// physics' own (z up, metres); sizes are in units of the rod length l [m]. Only drawing.
import * as THREE from 'three';
import type { Frame, Vec3 } from '../protocol';
import { tetherStyle } from '../models';
import type { RenderQuality } from './quality';
import { layeredOpacity } from './quality';
import { reachLines } from './framing';
import { handleOffset } from './velocity';
import { Tether } from './tether';

/** Opacity of each of the two faces of the sphere of reach. */
const REACH_OPACITY = 0.06;
const Y = new THREE.Vector3(0, 1, 0);
/** The velocity arrow's grab handle: drawn radius, grab radius and the least distance of its centre from
 *  the bob's (bob radius 0.05 l + the handle's), all in units of l. */
const HANDLE_RADIUS = 0.025;
export const HANDLE_GRAB = 0.06;
const HANDLE_CLEAR = 0.085;

/** What of the body to show (ViewOptions' part of it). */
export interface BodyView {
  sphere: boolean;
  axes: boolean;
  velocity: boolean;
}

export class PendulumBody {
  readonly sphere: THREE.Mesh;
  private readonly equator: THREE.LineLoop;
  /** The sphere of reach as lines, drawn instead of its fill in the anaglyph (framing.ts). */
  private readonly reachLines = reachLines(0x8fb3ff, 0.18);
  /** Whether the sphere of reach is drawn filled (false: as lines always; a software renderer, quality.ts). */
  private readonly fill: boolean;
  private readonly rod: THREE.Mesh;
  readonly bob: THREE.Mesh;
  private readonly pivot: THREE.Mesh;
  private readonly axes: THREE.AxesHelper;
  /** The slewing crane's boom, from the slewing axis to the pivot (drawn while the pivot is off the axis). */
  private readonly boom: THREE.Line;
  /** The grab handle at the velocity arrow's tip (shown with the velocity arrow). */
  readonly handle: THREE.Mesh;
  /** The spring's coil and the slack string (tether.ts); the model decides what links pivot and bob. */
  private readonly tether = new Tether();
  private readonly tmpX = new THREE.Vector3();
  private readonly tmpDir = new THREE.Vector3();
  private readonly tmpHandle = new THREE.Vector3();
  /** The bob's position [m, world] as drawn last. */
  readonly bobAt = new THREE.Vector3();
  model = 'ideal';
  private length = 1;

  /** `quality` (quality.ts): the sphere of reach's layers for the browser's renderer. */
  constructor(quality: RenderQuality) {
    this.fill = quality.reachLayers > 0;
    this.sphere = new THREE.Mesh(
      new THREE.SphereGeometry(1, 48, 32),
      new THREE.MeshBasicMaterial({
        color: 0x8fb3ff,
        transparent: true,
        // one face with the opacity of both, or each face with its own
        opacity: quality.reachLayers === 2 ? REACH_OPACITY : layeredOpacity(REACH_OPACITY, 2),
        depthWrite: false,
        side: quality.reachLayers === 2 ? THREE.DoubleSide : THREE.FrontSide,
      }),
    );
    const ring = new THREE.BufferGeometry().setFromPoints(
      Array.from({ length: 128 }, (_, i) => {
        const a = (2 * Math.PI * i) / 128;
        return new THREE.Vector3(Math.cos(a), Math.sin(a), 0);
      }),
    );
    this.equator = new THREE.LineLoop(
      ring,
      new THREE.LineBasicMaterial({ color: 0x8fb3ff, transparent: true, opacity: 0.25 }),
    );
    this.pivot = new THREE.Mesh(
      new THREE.SphereGeometry(0.02, 16, 12),
      new THREE.MeshStandardMaterial({ color: 0xcccccc }),
    );
    this.rod = new THREE.Mesh(
      new THREE.CylinderGeometry(1, 1, 1, 12),
      new THREE.MeshStandardMaterial({ color: 0xd8d8d8, metalness: 0.6, roughness: 0.3 }),
    );
    this.bob = new THREE.Mesh(
      new THREE.SphereGeometry(1, 32, 24),
      new THREE.MeshStandardMaterial({ color: 0xff8c42, roughness: 0.35 }),
    );
    this.axes = new THREE.AxesHelper(1.3);
    this.handle = new THREE.Mesh(
      new THREE.SphereGeometry(1, 16, 12),
      new THREE.MeshBasicMaterial({ color: 0xf2c8ff }),
    );
    this.handle.name = 'velocity handle';
    this.handle.visible = false;
    this.boom = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(), new THREE.Vector3()]),
      new THREE.LineBasicMaterial({ color: 0x9aa4b8 }),
    );
    this.boom.visible = false;
    this.boom.frustumCulled = false;
  }

  /** The objects, to add to a scene (in the order the scene drew them before the split). */
  objects(): THREE.Object3D[] {
    return [
      this.sphere,
      this.equator,
      this.reachLines,
      this.pivot,
      this.rod,
      this.bob,
      this.axes,
      this.tether.group,
      this.handle,
      this.boom,
    ];
  }

  /** Rescales the fixed parts to the rod length l [m]. */
  setLength(l: number): void {
    this.length = l;
    this.sphere.scale.setScalar(l);
    this.equator.scale.setScalar(l);
    this.reachLines.scale.setScalar(l);
    this.pivot.scale.setScalar(l);
    this.bob.scale.setScalar(0.05 * l);
    this.handle.scale.setScalar(HANDLE_RADIUS * l);
    this.axes.scale.setScalar(l);
  }

  /** Shows or hides the parts for state `f` (null: no state yet) and the view; `lines`: the sphere of
   *  reach as lines (the anaglyph; always with a software renderer). */
  show(f: Frame | null, view: BodyView, anaglyph: boolean, gdir: Vec3): void {
    const lines = anaglyph || !this.fill;
    this.sphere.visible = view.sphere && !lines;
    this.reachLines.visible = view.sphere && lines;
    this.equator.visible = view.sphere;
    this.axes.visible = view.axes;
    const has = f !== null;
    const style = tetherStyle(this.model, f?.taut ?? true);
    this.rod.visible = has && (style === 'rod' || style === 'taut string');
    this.bob.visible = has;
    this.handle.visible = has && view.velocity;
    if (f === null) this.tether.update('rod', [0, 0, 0], [0, 0, 0], this.length, gdir);
  }

  /** Places the body at state `f`: the pivot at `pivot` [m, world], the bob at pivot + f.x; g [m/s²] along
   *  the unit vector `gdir` (the slack string sags along gravity, flipped for g < 0); the velocity handle
   *  at the arrow's tip for an arrow scale `velocityScale` [m per m/s]. Returns the bob's position. */
  place(f: Frame, pivot: THREE.Vector3, g: number, gdir: Vec3, velocityScale: number): THREE.Vector3 {
    const style = tetherStyle(this.model, f.taut ?? true);
    const boomR = Math.hypot(pivot.x, pivot.y);
    this.boom.visible = boomR > 1e-9 * this.length;
    if (this.boom.visible) {
      const pos = this.boom.geometry.getAttribute('position') as THREE.BufferAttribute;
      pos.setXYZ(0, 0, 0, pivot.z);
      pos.setXYZ(1, pivot.x, pivot.y, pivot.z);
      pos.needsUpdate = true;
    }
    for (const o of [this.sphere, this.equator, this.reachLines, this.pivot]) o.position.copy(pivot);
    const x = this.tmpX.fromArray(f.x);
    const r = x.length();
    const bob = this.bobAt.copy(x).add(pivot);
    this.bob.position.copy(bob);
    if (r > 0) {
      this.rod.position.copy(x).multiplyScalar(0.5).add(pivot);
      this.rod.quaternion.setFromUnitVectors(Y, this.tmpDir.copy(x).divideScalar(r));
      const thick = style === 'taut string' ? 0.003 : 0.008;
      this.rod.scale.set(thick * this.length, r, thick * this.length);
    }
    const down: Vec3 = g < 0 ? [-gdir[0], -gdir[1], -gdir[2]] : gdir;
    this.tether.update(style, f.x, f.pivot, this.length, down);
    if (this.handle.visible) {
      const off = handleOffset(f.x, f.v, velocityScale, HANDLE_CLEAR * this.length);
      this.handle.position.copy(this.tmpHandle.fromArray(off).add(bob));
    }
    return bob;
  }
}
