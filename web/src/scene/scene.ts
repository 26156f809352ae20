// The three.js view of the pendulum: pivot (where the model moves it), faint sphere of reach, rod, bob,
// fading trail, axes and toggled vectors (vectors.ts: velocity, momentum, gravity, rod force, net force,
// angular momentum and torque about a chosen origin), the velocity arrow's grab handle (pulling it sets the
// start velocity: drag.ts, velocity.ts). Coordinates are the physics' own (z up, metres): the camera's up
// vector is +z. It only draws what the store hands it.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { StereoEffect } from 'three/addons/effects/StereoEffect.js';
import type { Frame, Vec3 } from '../protocol';
import type { DragPhase, PullBasis } from './drag';
import { BobDrag, VelocityDrag } from './drag';
import { TRAIL_MAX } from '../state';
import type { VectorName } from './vectors';
import { arrowScales, bobVectors } from './vectors';
import type { PulledVelocity } from './velocity';
import { handleOffset, maxStartSpeed } from './velocity';
import { Tether } from './tether';
import { tetherStyle } from '../models';
import type { RenderQuality } from './quality';
import { layeredOpacity } from './quality';
import { Instruments } from './instruments';
import { MaskAnaglyph } from './anaglyph';
import { framingDistance, reachLines, sphereBox } from './framing';
import { EXTRA_COLORS, TwinDrawing } from './twin';
import { MeasuredDrawing } from './measured';

export { framingDistance } from './framing';
export { TWIN_COLOR } from './twin';

/** The trail to draw: `frames[start..end)`, oldest first (LabStore.trailRange). */
export interface TrailSlice {
  frames: readonly Frame[];
  start: number;
  end: number;
}

export interface ViewOptions extends Record<VectorName, boolean> {
  trail: boolean;
  trailSeconds: number;
  sphere: boolean;
  axes: boolean;
  /** Origin of the angular momentum and the torque, relative to the pivot [m]. */
  originX: number;
  originY: number;
  originZ: number;
  /** Stereo: off, red–cyan anaglyph (colour masks: anaglyph.ts) or side by side for a viewer (StereoEffect). */
  stereo: Stereo;
  /** The ruler and the protractor (instruments.ts). */
  ruler: boolean;
  protractor: boolean;
  /** Where the ruler and the protractor were moved to, in rod lengths from their places (issue 28: movable):
   *  the ruler sideways (to the camera's right) and up, the protractor along its dial's plane and up. */
  rulerShift: number;
  rulerLift: number;
  protractorShift: number;
  protractorLift: number;
  /** Presentation mode: large type in the panel (the page's; kept here so that a link carries it). */
  present: boolean;
  /** The simple view: the classroom tools only (docs/web.md, "Simple view"). */
  simple: boolean;
}

export const STEREO_MODES = ['off', 'anaglyph', 'side by side'] as const;
export type Stereo = (typeof STEREO_MODES)[number];

export const DEFAULT_VIEW: ViewOptions = {
  trail: true,
  trailSeconds: 10,
  sphere: true,
  axes: true,
  velocity: true,
  momentum: false,
  gravity: false,
  tension: false,
  net: false,
  angularMomentum: false,
  torque: false,
  originX: 0,
  originY: 0,
  originZ: 0,
  stereo: 'off',
  ruler: false,
  protractor: false,
  rulerShift: 0,
  rulerLift: 0,
  protractorShift: 0,
  protractorLift: 0,
  present: false,
  simple: false,
};

/** Arrow colours (the legend in docs/web.md). */
export const ARROW_COLORS: Record<VectorName, number> = {
  velocity: 0xe07bff,
  momentum: 0x9b8cff,
  gravity: 0xffb347,
  tension: 0xff5d73,
  net: 0xffffff,
  angularMomentum: 0x4dd9c0,
  torque: 0xffe14d,
};
const AT_ORIGIN: readonly VectorName[] = ['angularMomentum', 'torque'];

const BACKGROUND = new THREE.Color(0x11141b);
/** Opacity of each of the two faces of the sphere of reach. */
const REACH_OPACITY = 0.06;
const TRAIL_COLOR = new THREE.Color(0x59c3ff);
const Y = new THREE.Vector3(0, 1, 0);
/** The velocity arrow's grab handle: drawn radius, grab radius and the least distance of its centre from
 *  the bob's (bob radius 0.05 l + the handle's), all in units of l. */
const HANDLE_RADIUS = 0.025;
const HANDLE_GRAB = 0.06;
const HANDLE_CLEAR = 0.085;
const NO_TRAIL: TrailSlice = { frames: [], start: 0, end: 0 };

function arrow(color: number): THREE.ArrowHelper {
  const a = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 1, color);
  a.visible = false;
  return a;
}

export class PendulumScene {
  readonly renderer: THREE.WebGLRenderer;
  readonly camera: THREE.PerspectiveCamera;
  readonly controls: OrbitControls;
  private readonly scene = new THREE.Scene();
  private readonly sphere: THREE.Mesh;
  private readonly equator: THREE.LineLoop;
  /** The sphere of reach as lines, drawn instead of its fill in the anaglyph (framing.ts). */
  private readonly reachLines = reachLines(0x8fb3ff, 0.18);
  private readonly rod: THREE.Mesh;
  private readonly bob: THREE.Mesh;
  private readonly pivot: THREE.Mesh;
  private readonly axes: THREE.AxesHelper;
  private readonly trail: THREE.Line;
  private readonly trailPositions: Float32Array;
  private readonly trailColors: Float32Array;
  /** Points the fade colours were computed for (they depend on the count only). */
  private trailColored = -1;
  // scratch vectors: update() runs every frame and allocates none of its own
  private readonly tmpX = new THREE.Vector3();
  private readonly tmpBob = new THREE.Vector3();
  private readonly tmpDir = new THREE.Vector3();
  private readonly tmpVec = new THREE.Vector3();
  private readonly tmpOrigin = new THREE.Vector3();
  private readonly arrows = Object.fromEntries(
    Object.entries(ARROW_COLORS).map(([name, color]) => [name, arrow(color)]),
  ) as Record<VectorName, THREE.ArrowHelper>;
  private length = 1;
  private extent = 1;
  private stereo: Stereo = 'off';
  private anaglyph: MaskAnaglyph | null = null;
  private readonly instruments = new Instruments();
  /** The slewing crane's boom, from the slewing axis to the pivot (drawn while the pivot is off the axis). */
  private readonly boom: THREE.Line;
  /** The second pendulum (two-pendulum mode): bob, rod and trail (twin.ts). */
  private readonly twin = new TwinDrawing();
  /** Pendulums 3 and 4 (panels/extras.ts), each from its own pivot in a row after the second. */
  private readonly extras = EXTRA_COLORS.map((c) => new TwinDrawing(c));
  private extraLayouts: readonly { offset: readonly [number, number, number]; length: number }[] = [];
  private extrasKey = '';
  /** A fitted data file's measured path, dotted (measured.ts). */
  private readonly measured = new MeasuredDrawing();
  /** The camera follows the pivot (the slewing crane: the pendulum stays framed as the boom turns). */
  private follow = false;
  private followAt: THREE.Vector3 | null = null;
  /** The largest |x| [m] drawn in this fit (the spring stretches past l). */
  private reach = 1;
  private twinLayoutKey = '';
  private twinLayout: { offset: readonly [number, number, number]; length: number } | null = null;
  private sideBySide: StereoEffect | null = null;
  /** Dragging the bob on the sphere (drag.ts); null until `enableDrag`. */
  drag: BobDrag | null = null;
  /** Pulling the velocity arrow by its handle (drag.ts); null until `enableDrag`. */
  pull: VelocityDrag | null = null;
  /** The grab handle at the velocity arrow's tip (shown with the velocity arrow). */
  private readonly handle: THREE.Mesh;
  /** The state drawn last, the velocity arrow's scale [m per m/s] and g [m/s²] it was drawn with. */
  private drawn: Frame | null = null;
  private velocityScale = arrowScales(1, 1, 9.81).velocity;
  private gNow = 9.81;
  private readonly tmpHandle = new THREE.Vector3();
  private pivotNow = new THREE.Vector3();
  private topView = false;
  /** The spring's coil and the slack string (tether.ts); the model decides what links pivot and bob. */
  private readonly tether = new Tether();
  private model = 'ideal';
  /** Something drawn changed outside `update` (size, length, camera, stereo): `draw` must render. */
  private invalid = true;

  /** `quality` (quality.ts): MSAA, pixel ratio and the sphere of reach's layers for the browser's renderer
   *  (in software: no MSAA, 1, one layer). */
  constructor(
    private readonly container: HTMLElement,
    quality: RenderQuality,
  ) {
    this.renderer = new THREE.WebGLRenderer({ antialias: quality.antialias });
    this.renderer.setPixelRatio(quality.pixelRatio);
    this.renderer.domElement.id = 'scene-canvas';
    container.appendChild(this.renderer.domElement);
    this.scene.background = BACKGROUND;

    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.enableDamping = true;

    this.scene.add(new THREE.AmbientLight(0xffffff, 0.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    sun.position.set(2, -3, 4);
    this.scene.add(sun);

    this.sphere = new THREE.Mesh(
      new THREE.SphereGeometry(1, 48, 32),
      new THREE.MeshBasicMaterial({
        color: 0x8fb3ff,
        transparent: true,
        // one face with the opacity of both, or each face with its own
        opacity: quality.reachLayers === 1 ? layeredOpacity(REACH_OPACITY, 2) : REACH_OPACITY,
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

    this.trailPositions = new Float32Array(3 * (TRAIL_MAX + 1));
    this.trailColors = new Float32Array(3 * (TRAIL_MAX + 1));
    const tg = new THREE.BufferGeometry();
    tg.setAttribute('position', new THREE.BufferAttribute(this.trailPositions, 3));
    tg.setAttribute('color', new THREE.BufferAttribute(this.trailColors, 3));
    tg.setDrawRange(0, 0);
    this.trail = new THREE.Line(tg, new THREE.LineBasicMaterial({ vertexColors: true }));
    this.trail.frustumCulled = false;

    this.boom = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(), new THREE.Vector3()]),
      new THREE.LineBasicMaterial({ color: 0x9aa4b8 }),
    );
    this.boom.visible = false;
    this.boom.frustumCulled = false;

    this.scene.add(
      this.sphere,
      this.equator,
      this.reachLines,
      this.pivot,
      this.rod,
      this.bob,
      this.axes,
      this.trail,
      this.tether.group,
      this.handle,
      this.boom,
      this.twin.group, ...this.extras.map((e) => e.group),
      this.measured.line,
      this.instruments.ruler,
      this.instruments.protractor,
      ...Object.values(this.arrows),
    );
    this.setLength(1);
    this.resetCamera();
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  /** Rescales the fixed parts to the rod length l [m]. */
  setLength(l: number): void {
    if (!(l > 0)) return;
    const changed = Math.abs(l - this.length) > 1e-12 * l;
    this.length = l;
    if (changed) this.extent = this.reach = l;
    this.sphere.scale.setScalar(l);
    this.equator.scale.setScalar(l);
    this.reachLines.scale.setScalar(l);
    this.pivot.scale.setScalar(l);
    this.bob.scale.setScalar(0.05 * l);
    this.twin.setLength(this.twinLayout?.length ?? l, Math.max(this.twinLayout?.length ?? 0, l));
    this.extras.forEach((e, i) => e.setLength(this.extraLayouts[i]?.length ?? l, Math.max(this.extraLayouts[i]?.length ?? 0, l)));
    this.handle.scale.setScalar(HANDLE_RADIUS * l);
    this.axes.scale.setScalar(l);
    if (changed) this.resetCamera();
    this.invalid = true;
  }

  /** Fits the camera to a scene of radius r [m] around the origin (length + the pivot's distance) when it
   *  changed by more than a fifth; a small change leaves the user's camera alone. */
  private fit(r: number): void {
    if (Math.abs(r - this.extent) <= 0.2 * this.extent) return;
    this.extent = r;
    this.resetCamera();
  }

  /** Frames the scene: the sphere of radius `extent` (the sphere of reach, the spring's largest stretch,
   *  or, with a fixed pivot off the origin, that too) fills 90 % of the canvas's narrower side; with
   *  `follow` (the slewing crane) the camera looks at the pivot and moves with it. */
  resetCamera(): void {
    // with pendulums beside the first (in a row), a sphere around every sphere of reach, centred between
    // the first pivot and the last
    const row = this.twinLayout === null ? [] : [this.twinLayout, ...this.extraLayouts];
    const tw = row[row.length - 1] ?? null;
    const half = tw === null ? 0 : 0.5 * Math.hypot(...tw.offset);
    const l = tw === null ? this.extent : half + Math.max(this.extent, ...row.map((p) => p.length));
    const r = 1.1 * l; // the bob's radius and the ruler's labels
    const aspect = this.stereo === 'side by side' ? this.camera.aspect / 2 : this.camera.aspect;
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
    this.invalid = true;
  }

  /** The model drawn (models.ts): a rod, the spring's coil, or the string (taut, or slack and dashed). */
  setModel(model: string): void {
    if (model === this.model) return;
    this.invalid = true;
    this.model = model;
    this.follow = model === 'slewing';
    this.followAt = null;
    this.extent = this.reach = this.length;
    this.resetCamera();
  }

  setTopView(on: boolean): void {
    this.topView = on;
    this.resetCamera();
  }

  /** Lets the user drag the bob over the sphere of reach: `onDrag(x, phase)` gets the position relative to
   *  the pivot [m] at the start, while moving and at the end of a drag; and pull the velocity arrow by its
   *  handle: `onPull(x, pulled, phase)` gets the bob's position as drawn when the pull started and the
   *  velocity asked for (null at the start, and at an end without a move) (drag.ts). */
  enableDrag(
    onDrag: (x: Vec3, phase: DragPhase) => void,
    onPull: (x: Vec3, pulled: PulledVelocity | null, phase: DragPhase) => void,
  ): void {
    const canvas = this.renderer.domElement;
    // the handle first: its press listener must see the pointer before the bob's
    this.pull = new VelocityDrag(
      canvas,
      this.camera,
      this.controls,
      this.handle,
      this.bob,
      () => HANDLE_GRAB * this.length,
      () => this.pullBasis(),
      onPull,
    );
    this.drag = new BobDrag(canvas, this.camera, this.controls, this.bob, onDrag, () => ({
      pivot: this.pivotNow,
      length: this.length,
    }));
  }

  /** What a pull of the velocity arrow starts from: the state drawn, the arrow's scale, the speed cap. */
  private pullBasis(): PullBasis | null {
    const f = this.drawn;
    if (f === null) return null;
    return {
      pivot: [...f.pivot],
      x: [...f.x],
      arrowScale: this.velocityScale,
      vmax: maxStartSpeed(this.length, this.gNow),
    };
  }

  private onScreen(o: THREE.Object3D): { x: number; y: number } | null {
    if (!o.visible) return null;
    const p = o.position.clone().project(this.camera);
    const r = this.renderer.domElement.getBoundingClientRect();
    return { x: r.left + ((p.x + 1) / 2) * r.width, y: r.top + ((1 - p.y) / 2) * r.height };
  }

  /** The bob's position on the page [CSS px], or null when it is not drawn (for tests). */
  bobOnScreen(): { x: number; y: number } | null {
    return this.onScreen(this.bob);
  }

  /** The velocity arrow's grab handle on the page [CSS px], or null when it is not drawn (for tests). */
  handleOnScreen(): { x: number; y: number } | null {
    return this.onScreen(this.handle);
  }

  setStereo(mode: Stereo): void {
    this.stereo = mode;
    if (mode === 'anaglyph' && this.anaglyph === null) this.anaglyph = new MaskAnaglyph(this.renderer);
    if (mode === 'side by side' && this.sideBySide === null) this.sideBySide = new StereoEffect(this.renderer);
    this.resize();
    this.resetCamera();
  }

  resize(): void {
    const w = Math.max(1, this.container.clientWidth);
    const h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    if (this.stereo === 'side by side') this.sideBySide?.setSize(w, h);
    this.renderer.domElement.style.width = '';
    this.renderer.domElement.style.height = '';
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.resetCamera(); // the framing depends on the canvas's shape
    this.invalid = true;
  }

  /** Draws the state `f` of a pendulum of mass `mass` [kg] under gravity g [m/s²] along the unit vector
   *  `gdir`, with the trail frames; the pivot at f.pivot, the bob at f.pivot + f.x. */
  update(f: Frame | null, trail: TrailSlice, view: ViewOptions, mass: number, g: number, gdir: Vec3): void {
    const lines = this.stereo === 'anaglyph';
    this.sphere.visible = view.sphere && !lines;
    this.reachLines.visible = view.sphere && lines;
    this.equator.visible = view.sphere;
    this.axes.visible = view.axes;
    const has = f !== null;
    const style = tetherStyle(this.model, f?.taut ?? true);
    this.rod.visible = has && (style === 'rod' || style === 'taut string');
    this.bob.visible = has;
    this.drawn = f;
    this.gNow = g;
    this.velocityScale = arrowScales(this.length, mass, g).velocity;
    this.handle.visible = has && view.velocity;
    if (f === null) {
      this.tether.update('rod', [0, 0, 0], [0, 0, 0], this.length, gdir);
      this.trail.geometry.setDrawRange(0, 0);
      for (const a of Object.values(this.arrows)) a.visible = false;
      return;
    }
    const pivot = this.pivotNow.fromArray(f.pivot);
    this.followPivot(pivot);
    this.reach = Math.max(this.reach, Math.hypot(...f.x));
    this.fit(this.reach + (this.follow ? 0 : pivot.length()));
    this.instruments.update(pivot, f.x, this.length, view.ruler, view.protractor, this.camera.position, {
      ruler: [view.rulerShift, view.rulerLift],
      protractor: [view.protractorShift, view.protractorLift],
    });
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
    const bob = this.tmpBob.copy(x).add(pivot);
    this.bob.position.copy(bob);
    if (r > 0) {
      this.rod.position.copy(x).multiplyScalar(0.5).add(pivot);
      this.rod.quaternion.setFromUnitVectors(Y, this.tmpDir.copy(x).divideScalar(r));
      const thick = style === 'taut string' ? 0.003 : 0.008;
      this.rod.scale.set(thick * this.length, r, thick * this.length);
    }
    const down: Vec3 = g < 0 ? [-gdir[0], -gdir[1], -gdir[2]] : gdir;
    this.tether.update(style, f.x, f.pivot, this.length, down);
    this.updateTrail(view.trail ? trail : NO_TRAIL, f);
    if (this.handle.visible) {
      const off = handleOffset(f.x, f.v, this.velocityScale, HANDLE_CLEAR * this.length);
      this.handle.position.copy(this.tmpHandle.fromArray(off).add(bob));
    }

    const names = Object.keys(this.arrows) as VectorName[];
    if (!names.some((name) => view[name])) {
      for (const name of names) this.arrows[name].visible = false;
      return;
    }
    const origin: Vec3 = [view.originX, view.originY, view.originZ];
    const vectors = bobVectors(f, mass, g, gdir, origin);
    const scales = arrowScales(this.length, mass, g);
    const originWorld = this.tmpOrigin.fromArray(origin).add(pivot);
    for (const name of names) {
      const from = AT_ORIGIN.includes(name) ? originWorld : bob;
      const vec = this.tmpVec.fromArray(vectors[name]).multiplyScalar(scales[name]);
      this.setArrow(this.arrows[name], view[name], from, vec);
    }
  }

  /** Moves camera and target with the pivot (when following it): the view keeps its angle and distance. */
  private followPivot(pivot: THREE.Vector3): void {
    if (!this.follow) return;
    if (this.followAt === null) {
      this.followAt = pivot.clone();
      this.resetCamera();
      return;
    }
    const dx = this.tmpVec.copy(pivot).sub(this.followAt);
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
    this.invalid = true;
  }

  /** The second pendulum of its own (two-pendulum mode `own`): rod length `length` [m], its pivot drawn at
   *  `offset` [m] beside the first; the camera frames both spheres of reach. Null: the second hangs from the
   *  first's pivot with the first's length (the other modes). */
  setTwinLayout(layout: { offset: readonly [number, number, number]; length: number } | null): void {
    const key = layout === null ? '' : `${layout.offset.join(',')}|${layout.length}`;
    if (key === this.twinLayoutKey) return;
    this.twinLayoutKey = key;
    this.twinLayout = layout;
    this.twin.setLength(layout?.length ?? this.length, Math.max(layout?.length ?? 0, this.length));
    this.twin.setOffset(layout?.offset ?? null);
    this.resetCamera();
  }

  /** Pendulums 3 and 4: their rod lengths [m] and pivots at `offset` [m] from the first (none: hidden). */
  setExtras(layouts: readonly { offset: readonly [number, number, number]; length: number }[]): void {
    const key = layouts.map((p) => `${p.offset.join(',')}|${p.length}`).join(';');
    if (key === this.extrasKey) return;
    this.extrasKey = key;
    this.extraLayouts = layouts;
    this.extras.forEach((e, i) => {
      const p = layouts[i];
      if (p === undefined) return e.update(null, { frames: [], start: 0, end: 0 });
      e.setLength(p.length, Math.max(p.length, this.length));
      e.setOffset(p.offset);
    });
    this.resetCamera();
  }

  /** Draws pendulums 3 and 4 at their states (null: hidden) with their trails. */
  updateExtras(drawn: readonly { frame: Frame | null; trail: TrailSlice }[]): void {
    this.extras.forEach((e, i) => e.update(drawn[i]?.frame ?? null, drawn[i]?.trail ?? { frames: [], start: 0, end: 0 }));
    this.invalid = true;
  }

  /** Pendulums 3 and 4's bobs on the page [CSS px] (for tests), those drawn. */
  extrasOnScreen(): { x: number; y: number }[] {
    return this.extras.filter((e) => e.group.visible).flatMap((e) => this.onScreen(e.bob) ?? []);
  }

  /** Draws the second pendulum at state `f` (null: hidden) with its trail frames (two-pendulum mode). */
  updateTwin(f: Frame | null, trail: TrailSlice): void {
    this.twin.update(f, trail);
    this.invalid = true;
  }

  /** Draws a measured path: bob positions [m] relative to the pivot (null: none). */
  setMeasured(x: readonly Vec3[] | null): void {
    this.measured.set(x);
    this.invalid = true;
  }

  /** The number of measured points drawn (for tests). */
  measuredPoints(): number {
    return this.measured.points;
  }

  /** The box [CSS px] of the sphere of reach (its silhouette: points around its outline as seen from the
   *  camera) on the page, for tests: inside the canvas means the whole sphere is in view. */
  sphereOnScreen(): { left: number; right: number; top: number; bottom: number } {
    return sphereBox(this.sphere.position, this.sphere.scale.x, this.camera, this.renderer.domElement);
  }

  /** Where the ruler's and the protractor's centres are on the page [CSS px] (for tests). */
  instrumentsOnScreen(): { ruler: { x: number; y: number } | null; protractor: { x: number; y: number } | null } {
    return { ruler: this.onScreen(this.instruments.ruler), protractor: this.onScreen(this.instruments.protractor) };
  }

  /** The second pendulum's bob on the page [CSS px], or null when it is not drawn (for tests). */
  twinOnScreen(): { x: number; y: number } | null {
    return this.twin.group.visible ? this.onScreen(this.twin.bob) : null;
  }

  /** Points the arrow `a` from `from` along `vec` (which it may scale). */
  private setArrow(a: THREE.ArrowHelper, on: boolean, from: THREE.Vector3, vec: THREE.Vector3): void {
    const len = vec.length();
    a.visible = on && len > 1e-6 * this.length;
    if (!a.visible) return;
    a.position.copy(from);
    a.setDirection(vec.divideScalar(len));
    const head = Math.min(0.25 * len, 0.08 * this.length);
    a.setLength(len, head, 0.5 * head);
  }

  /** Writes the trail's points (the slice, then the drawn state) into the fixed buffers in place and
   *  uploads only the part drawn; the fade colours are recomputed only when the number of points changed. */
  private updateTrail(trail: TrailSlice, now: Frame): void {
    const n = Math.min(trail.end - trail.start, TRAIL_MAX);
    const geom = this.trail.geometry;
    if (n <= 0) {
      geom.setDrawRange(0, 0);
      return;
    }
    const start = trail.end - n;
    const p = this.trailPositions;
    const total = n + 1;
    for (let i = 0; i < total; i++) {
      const f = i < n ? (trail.frames[start + i] as Frame) : now;
      p[3 * i] = f.x[0] + f.pivot[0];
      p[3 * i + 1] = f.x[1] + f.pivot[1];
      p[3 * i + 2] = f.x[2] + f.pivot[2];
    }
    geom.setDrawRange(0, total);
    const position = geom.getAttribute('position') as THREE.BufferAttribute;
    position.clearUpdateRanges();
    position.addUpdateRange(0, 3 * total);
    position.needsUpdate = true;
    if (total !== this.trailColored) {
      this.trailColored = total;
      const c = this.trailColors;
      const tmp = new THREE.Color();
      for (let i = 0; i < total; i++) {
        // fade: old points blend into the background
        tmp.copy(BACKGROUND).lerp(TRAIL_COLOR, (i + 1) / total);
        c[3 * i] = tmp.r;
        c[3 * i + 1] = tmp.g;
        c[3 * i + 2] = tmp.b;
      }
      const color = geom.getAttribute('color') as THREE.BufferAttribute;
      color.clearUpdateRanges();
      color.addUpdateRange(0, 3 * total);
      color.needsUpdate = true;
    }
  }

  /** Moves the camera (OrbitControls, with its damping) and renders if anything drawn changed: the
   *  caller's `changed` (the inputs of `update`), the camera, or size, length, view or stereo. A still
   *  scene is not drawn again (the canvas keeps its picture). Returns whether it rendered. */
  draw(changed: boolean): boolean {
    const moved = this.controls.update();
    if (moved && this.instruments.ruler.visible) this.instruments.face(this.camera.position);
    if (!changed && !moved && !this.invalid) return false;
    this.invalid = false;
    this.render();
    return true;
  }

  /** Renders now. */
  render(): void {
    // stereo: the screen plane through the orbit's centre, eyes 1/30 of the viewing distance apart
    const distance = this.camera.position.distanceTo(this.controls.target);
    if (this.stereo === 'anaglyph' && this.anaglyph !== null) {
      this.anaglyph.render(this.scene, this.camera, distance / 30, distance, BACKGROUND);
    } else if (this.stereo === 'side by side' && this.sideBySide !== null) {
      this.camera.focus = distance;
      this.sideBySide.setEyeSeparation(distance / 30);
      this.sideBySide.render(this.scene, this.camera);
    } else this.renderer.render(this.scene, this.camera);
  }

  /** A PNG of the current view, as a data URL (rendered now, so the drawing buffer is full). */
  screenshot(): string {
    this.render();
    return this.renderer.domElement.toDataURL('image/png');
  }
}
