// The three.js view of the pendulum: it puts together the first pendulum's body (body.ts: pivot, sphere of
// reach, rod, bob, link, boom, velocity handle), its fading trail (trail.ts), the vector arrows (arrows.ts),
// the ruler and protractor (instruments.ts), the second pendulum and pendulums 3 and 4 (twin.ts), a fitted
// file's measured path (measured.ts) and the camera (camera.ts); it renders plain, as a red–cyan anaglyph
// (anaglyph.ts) or side by side, and lets the user drag the bob and pull the velocity arrow (drag.ts).
// Coordinates are the physics' own (z up, metres). It only draws what the store hands it.
import * as THREE from 'three';
import type { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { StereoEffect } from 'three/addons/effects/StereoEffect.js';
import type { Frame, Vec3 } from '../protocol';
import type { DragPhase, PullBasis, ReleasedPull } from './drag';
import { BobDrag, VelocityDrag } from './drag';
import { arrowScales } from './vectors';
import type { PulledVelocity } from './velocity';
import { maxStartSpeed } from './velocity';
import type { RenderQuality } from './quality';
import { Instruments } from './instruments';
import { MaskAnaglyph } from './anaglyph';
import { sphereBox } from './framing';
import { EXTRA_COLORS, TwinDrawing } from './twin';
import { MeasuredDrawing } from './measured';
import type { Stereo, ViewOptions } from './options';
import { VectorArrows } from './arrows';
import { HANDLE_GRAB, PendulumBody } from './body';
import type { PivotLayout } from './camera';
import { CameraRig } from './camera';
import type { TrailSlice } from './trail';
import { FadingTrail, NO_TRAIL } from './trail';

export { framingDistance } from './framing';
export { TWIN_COLOR } from './twin';
export type { TrailSlice } from './trail';
export type { ViewOptions, Stereo } from './options';
export { ARROW_COLORS, DEFAULT_VIEW, STEREO_MODES } from './options';

const BACKGROUND = new THREE.Color(0x11141b);

export class PendulumScene {
  readonly renderer: THREE.WebGLRenderer;
  readonly camera: THREE.PerspectiveCamera;
  readonly controls: OrbitControls;
  private readonly scene = new THREE.Scene();
  private readonly rig: CameraRig;
  private readonly body: PendulumBody;
  private readonly trail = new FadingTrail(BACKGROUND);
  private readonly arrows = new VectorArrows();
  private length = 1;
  private stereo: Stereo = 'off';
  private anaglyph: MaskAnaglyph | null = null;
  private sideBySide: StereoEffect | null = null;
  private readonly instruments = new Instruments();
  /** The second pendulum (two-pendulum mode): bob, rod and trail (twin.ts). */
  private readonly twin = new TwinDrawing();
  /** Pendulums 3 and 4 (panels/extras.ts), each from its own pivot in a row after the second. */
  private readonly extras = EXTRA_COLORS.map((c) => new TwinDrawing(c));
  private extraLayouts: readonly PivotLayout[] = [];
  private extrasKey = '';
  private twinLayoutKey = '';
  private twinLayout: PivotLayout | null = null;
  /** A fitted data file's measured path, dotted (measured.ts). */
  private readonly measured = new MeasuredDrawing();
  /** Dragging the bob on the sphere (drag.ts); null until `enableDrag`. */
  drag: BobDrag | null = null;
  /** Pulling the velocity arrow by its handle (drag.ts); null until `enableDrag`. */
  pull: VelocityDrag | null = null;
  /** The state drawn last, the velocity arrow's scale [m per m/s] and g [m/s²] it was drawn with. */
  private drawn: Frame | null = null;
  private velocityScale = arrowScales(1, 1, 9.81).velocity;
  private gNow = 9.81;
  private pivotNow = new THREE.Vector3();
  /** Something drawn changed outside `update` (size, length, camera, stereo): `draw` must render. */
  private invalid = true;
  /** The crane mode's hook (crane/index.ts): its own drawing placed after each update, and the
   *  pendulum's body hidden while it draws the rope, hook and load instead. */
  crane: { afterUpdate(f: Frame | null): void; hidesBody(): boolean } | null = null;

  /** `quality` (quality.ts): MSAA, pixel ratio and the sphere of reach's layers for the browser's renderer
   *  (in software: no MSAA, 1, lines). */
  constructor(
    private readonly container: HTMLElement,
    quality: RenderQuality,
  ) {
    this.renderer = new THREE.WebGLRenderer({ antialias: quality.antialias });
    this.renderer.setPixelRatio(quality.pixelRatio);
    this.renderer.domElement.id = 'scene-canvas';
    container.appendChild(this.renderer.domElement);
    this.scene.background = BACKGROUND;

    this.rig = new CameraRig(
      this.renderer.domElement,
      {
        row: () => (this.twinLayout === null ? [] : [this.twinLayout, ...this.extraLayouts]),
        halfWidth: () => this.stereo === 'side by side',
      },
      () => (this.invalid = true),
    );
    this.camera = this.rig.camera;
    this.controls = this.rig.controls;

    this.scene.add(new THREE.AmbientLight(0xffffff, 0.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    sun.position.set(2, -3, 4);
    this.scene.add(sun);

    this.body = new PendulumBody(quality);
    this.scene.add(
      ...this.body.objects(),
      this.trail.line,
      this.twin.group,
      ...this.extras.map((e) => e.group),
      this.measured.line,
      this.instruments.ruler,
      this.instruments.protractor,
      ...this.arrows.objects(),
    );
    this.setLength(1);
    this.resetCamera();
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  /** Rescales the fixed parts to the rod length l [m]. */
  setLength(l: number): void {
    if (!(l > 0)) return;
    this.length = l;
    this.body.setLength(l);
    this.twin.setLength(this.twinLayout?.length ?? l, Math.max(this.twinLayout?.length ?? 0, l));
    this.extras.forEach((e, i) =>
      e.setLength(this.extraLayouts[i]?.length ?? l, Math.max(this.extraLayouts[i]?.length ?? 0, l)),
    );
    this.rig.setLength(l);
    this.invalid = true;
  }

  /** Frames the scene (camera.ts). */
  resetCamera(): void {
    this.rig.reset();
  }

  /** The model drawn (models.ts): a rod, the spring's coil, or the string (taut, or slack and dashed). */
  setModel(model: string): void {
    if (model === this.body.model) return;
    this.invalid = true;
    this.body.model = model;
    this.rig.setModel(model);
  }

  setTopView(on: boolean): void {
    this.rig.setTopView(on);
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
      this.body.handle,
      this.body.bob,
      () => HANDLE_GRAB * this.length,
      () => this.pullBasis(),
      onPull,
    );
    this.drag = new BobDrag(canvas, this.camera, this.controls, this.body.bob, onDrag, () => ({
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
    this.rig.setAspect(w / h);
    this.invalid = true;
  }

  /** Draws the state `f` of a pendulum of mass `mass` [kg] under gravity g [m/s²] along the unit vector
   *  `gdir`, with the trail frames; the pivot at f.pivot, the bob at f.pivot + f.x. */
  update(f: Frame | null, trail: TrailSlice, view: ViewOptions, mass: number, g: number, gdir: Vec3): void {
    this.updateBody(f, trail, view, mass, g, gdir);
    this.crane?.afterUpdate(f);
    if (this.crane?.hidesBody() === true) for (const o of this.body.objects()) o.visible = false;
  }

  /** Adds a drawing of the crane mode (crane/drawing.ts) to the scene. */
  addDrawing(o: THREE.Object3D): void {
    this.scene.add(o);
    this.invalid = true;
  }

  private updateBody(f: Frame | null, trail: TrailSlice, view: ViewOptions, mass: number, g: number, gdir: Vec3): void {
    this.body.show(f, view, this.stereo === 'anaglyph', gdir);
    this.drawn = f;
    this.gNow = g;
    this.velocityScale = arrowScales(this.length, mass, g).velocity;
    if (f === null) {
      this.trail.hide();
      this.arrows.hide();
      return;
    }
    const pivot = this.pivotNow.fromArray(f.pivot);
    this.rig.track(pivot, f.x);
    this.instruments.update(pivot, f.x, this.length, view.ruler, view.protractor, this.camera.position, {
      ruler: [view.rulerShift, view.rulerLift],
      protractor: [view.protractorShift, view.protractorLift],
    });
    const bob = this.body.place(f, pivot, g, gdir, this.velocityScale);
    this.trail.update(view.trail ? trail : NO_TRAIL, f);
    this.arrows.update(f, view, mass, g, gdir, pivot, bob, this.length);
  }

  /** Turns the camera about its target (camera.ts; keyboard access to the view). */
  orbitBy(azimuth: number, elevation: number, zoom = 1): void {
    this.rig.orbitBy(azimuth, elevation, zoom);
  }

  private onScreen(o: THREE.Object3D): { x: number; y: number } | null {
    if (!o.visible) return null;
    const p = o.position.clone().project(this.camera);
    const r = this.renderer.domElement.getBoundingClientRect();
    return { x: r.left + ((p.x + 1) / 2) * r.width, y: r.top + ((1 - p.y) / 2) * r.height };
  }

  /** The bob's position on the page [CSS px], or null when it is not drawn (for tests). */
  bobOnScreen(): { x: number; y: number } | null {
    return this.onScreen(this.body.bob);
  }

  /** The velocity arrow's grab handle on the page [CSS px], or null when it is not drawn (for tests). */
  handleOnScreen(): { x: number; y: number } | null {
    return this.onScreen(this.body.handle);
  }

  /** The last pull of the velocity arrow as released (drag.ts; for tests). */
  lastPull(): ReleasedPull | null {
    return this.pull?.last ?? null;
  }

  /** The velocity handle's position [m, world] as drawn and the velocity arrow's scale [m per m/s] it was
   *  drawn with, or null when it is not drawn (for tests). */
  handleAt(): { at: Vec3; scale: number } | null {
    const h = this.body.handle;
    return h.visible ? { at: [h.position.x, h.position.y, h.position.z], scale: this.velocityScale } : null;
  }

  /** The second pendulum of its own (two-pendulum mode `own`): rod length `length` [m], its pivot drawn at
   *  `offset` [m] beside the first; the camera frames both spheres of reach. Null: the second hangs from the
   *  first's pivot with the first's length (the other modes). */
  setTwinLayout(layout: PivotLayout | null): void {
    const key = layout === null ? '' : `${layout.offset.join(',')}|${layout.length}`;
    if (key === this.twinLayoutKey) return;
    this.twinLayoutKey = key;
    this.twinLayout = layout;
    this.twin.setLength(layout?.length ?? this.length, Math.max(layout?.length ?? 0, this.length));
    this.twin.setOffset(layout?.offset ?? null);
    this.resetCamera();
  }

  /** Pendulums 3 and 4: their rod lengths [m] and pivots at `offset` [m] from the first (none: hidden). */
  setExtras(layouts: readonly PivotLayout[]): void {
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
    return sphereBox(this.body.sphere.position, this.body.sphere.scale.x, this.camera, this.renderer.domElement);
  }

  /** Where the ruler's and the protractor's centres are on the page [CSS px] (for tests). */
  instrumentsOnScreen(): { ruler: { x: number; y: number } | null; protractor: { x: number; y: number } | null } {
    return { ruler: this.onScreen(this.instruments.ruler), protractor: this.onScreen(this.instruments.protractor) };
  }

  /** The second pendulum's bob on the page [CSS px], or null when it is not drawn (for tests). */
  twinOnScreen(): { x: number; y: number } | null {
    return this.twin.group.visible ? this.onScreen(this.twin.bob) : null;
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
