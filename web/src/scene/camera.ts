// The camera of the 3-D view (docs/web.md, "Layout" and "Keyboard"): a perspective camera with z up (the
// physics' own axes, metres) on OrbitControls, framed so that the scene — the sphere of reach of radius
// l [m], the spring's largest stretch, the pivot's distance from the origin, and with pendulums in a row
// every sphere of reach — fills 90 % of the canvas's narrower side (framing.ts); refitted only when that
// radius changed by more than a fifth, so that a small change leaves the user's camera alone. With the
// slewing crane the camera follows the pivot (the view keeps its angle and distance). Keyboard orbiting
// and the top view.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { framingDistance } from './framing';

/** A pendulum beside the first: its pivot at `offset` [m] from the first's, its rod length [m]. */
export interface PivotLayout {
  offset: readonly [number, number, number];
  length: number;
}

/** What the framing needs from the scene: the pendulums in a row beside the first (none: []) and whether
 *  the canvas is split in two eyes (side by side: each eye's aspect is half the canvas's). */
export interface FramingInputs {
  row: () => readonly PivotLayout[];
  halfWidth: () => boolean;
}

export class CameraRig {
  readonly camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
  readonly controls: OrbitControls;
  /** The rod length l [m]. */
  private length = 1;
  /** The radius [m] the camera was framed for. */
  private extent = 1;
  /** The largest |x| [m] drawn in this fit (the spring stretches past l). */
  private reach = 1;
  /** The camera follows the pivot (the slewing crane: the pendulum stays framed as the boom turns). */
  private follow = false;
  private followAt: THREE.Vector3 | null = null;
  private topView = false;
  private readonly tmp = new THREE.Vector3();

  /** `invalidate`: the camera moved, the scene must render again. */
  constructor(
    canvas: HTMLElement,
    private readonly inputs: FramingInputs,
    private readonly invalidate: () => void,
  ) {
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.enableDamping = true;
  }

  /** A new rod length l [m]: a changed one restarts the reach and reframes. */
  setLength(l: number): void {
    const changed = Math.abs(l - this.length) > 1e-12 * l;
    this.length = l;
    if (!changed) return;
    this.extent = this.reach = l;
    this.reset();
  }

  /** A new model: the camera follows the pivot of the slewing crane only; the reach restarts. */
  setModel(model: string): void {
    this.follow = model === 'slewing';
    this.followAt = null;
    this.extent = this.reach = this.length;
    this.reset();
  }

  setTopView(on: boolean): void {
    this.topView = on;
    this.reset();
  }

  /** Frames the scene: the sphere of radius `extent` (the sphere of reach, the spring's largest stretch,
   *  or, with a fixed pivot off the origin, that too) fills 90 % of the canvas's narrower side; with
   *  `follow` (the slewing crane) the camera looks at the pivot and moves with it. */
  reset(): void {
    // with pendulums beside the first (in a row), a sphere around every sphere of reach, centred between
    // the first pivot and the last
    const row = this.inputs.row();
    const tw = row[row.length - 1] ?? null;
    const half = tw === null ? 0 : 0.5 * Math.hypot(...tw.offset);
    const l = tw === null ? this.extent : half + Math.max(this.extent, ...row.map((p) => p.length));
    const r = 1.1 * l; // the bob's radius and the ruler's labels
    const aspect = this.inputs.halfWidth() ? this.camera.aspect / 2 : this.camera.aspect;
    const d = framingDistance(r, this.camera.fov, aspect);
    const centre = this.follow && this.followAt !== null ? this.followAt.clone() : new THREE.Vector3();
    if (tw !== null) centre.add(new THREE.Vector3(...tw.offset).multiplyScalar(0.5));
    if (this.topView) this.camera.position.set(0, -1e-4 * d, d).add(centre);
    else this.camera.position.set(3.3, -3.9, 1.5).normalize().multiplyScalar(d).add(centre);
    this.controls.target.copy(centre);
    this.camera.near = 0.01 * this.length;
    this.camera.far = 100 * l;
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.invalidate();
  }

  /** The canvas's new shape (width/height). */
  setAspect(aspect: number): void {
    this.camera.aspect = aspect;
    this.camera.updateProjectionMatrix();
    this.reset(); // the framing depends on the canvas's shape
  }

  /** Follows the pivot at `pivot` [m] (with the slewing crane) and refits when the bob at `x` [m] from it
   *  reaches farther than the radius framed. */
  track(pivot: THREE.Vector3, x: readonly number[]): void {
    this.followPivot(pivot);
    this.reach = Math.max(this.reach, Math.hypot(...x));
    this.fit(this.reach + (this.follow ? 0 : pivot.length()));
  }

  /** Fits the camera to a scene of radius r [m] around the origin (length + the pivot's distance) when it
   *  changed by more than a fifth; a small change leaves the user's camera alone. */
  private fit(r: number): void {
    if (Math.abs(r - this.extent) <= 0.2 * this.extent) return;
    this.extent = r;
    this.reset();
  }

  /** Moves camera and target with the pivot (when following it): the view keeps its angle and distance. */
  private followPivot(pivot: THREE.Vector3): void {
    if (!this.follow) return;
    if (this.followAt === null) {
      this.followAt = pivot.clone();
      this.reset();
      return;
    }
    const dx = this.tmp.copy(pivot).sub(this.followAt);
    if (dx.lengthSq() === 0) return;
    this.camera.position.add(dx);
    this.controls.target.add(dx);
    this.followAt.copy(pivot);
  }

  /** Turns the camera about its target by `azimuth` [rad] around the vertical and `elevation` [rad] up or
   *  down (kept off the poles), and moves it `zoom` times as far (keyboard access to the view). */
  orbitBy(azimuth: number, elevation: number, zoom = 1): void {
    const offset = this.camera.position.clone().sub(this.controls.target);
    const sph = new THREE.Spherical().setFromCartesianCoords(offset.x, offset.z, -offset.y); // y-up spherical
    sph.theta += azimuth;
    sph.phi = Math.min(Math.max(sph.phi - elevation, 0.05), Math.PI - 0.05);
    sph.radius *= zoom;
    const v = new THREE.Vector3().setFromSpherical(sph);
    this.camera.position.set(v.x, -v.z, v.y).add(this.controls.target);
    this.camera.lookAt(this.controls.target);
    this.controls.update();
    this.invalidate();
  }
}
