// The three.js view of the pendulum: pivot, faint sphere of reach, rod, bob, fading trail, axes and
// toggled vectors (velocity, gravity, rod force). Coordinates are the physics' own (z up, metres): the
// camera's up vector is +z. It only draws what the store hands it.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import type { Frame } from '../protocol';
import { TRAIL_MAX } from '../state';

export interface ViewOptions {
  trail: boolean;
  trailSeconds: number;
  sphere: boolean;
  axes: boolean;
  velocity: boolean;
  gravity: boolean;
  tension: boolean;
}

export const DEFAULT_VIEW: ViewOptions = {
  trail: true,
  trailSeconds: 10,
  sphere: true,
  axes: true,
  velocity: true,
  gravity: false,
  tension: false,
};

const BACKGROUND = new THREE.Color(0x11141b);
const TRAIL_COLOR = new THREE.Color(0x59c3ff);
const Y = new THREE.Vector3(0, 1, 0);

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
  private readonly rod: THREE.Mesh;
  private readonly bob: THREE.Mesh;
  private readonly pivot: THREE.Mesh;
  private readonly axes: THREE.AxesHelper;
  private readonly trail: THREE.Line;
  private readonly trailPositions: Float32Array;
  private readonly trailColors: Float32Array;
  private readonly velocityArrow = arrow(0xe07bff);
  private readonly gravityArrow = arrow(0xffb347);
  private readonly tensionArrow = arrow(0xff5d73);
  private length = 1;
  private topView = false;

  constructor(private readonly container: HTMLElement) {
    this.renderer = new THREE.WebGLRenderer({ antialias: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
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
        opacity: 0.06,
        depthWrite: false,
        side: THREE.DoubleSide,
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

    this.trailPositions = new Float32Array(3 * (TRAIL_MAX + 1));
    this.trailColors = new Float32Array(3 * (TRAIL_MAX + 1));
    const tg = new THREE.BufferGeometry();
    tg.setAttribute('position', new THREE.BufferAttribute(this.trailPositions, 3));
    tg.setAttribute('color', new THREE.BufferAttribute(this.trailColors, 3));
    tg.setDrawRange(0, 0);
    this.trail = new THREE.Line(tg, new THREE.LineBasicMaterial({ vertexColors: true }));
    this.trail.frustumCulled = false;

    this.scene.add(
      this.sphere,
      this.equator,
      this.pivot,
      this.rod,
      this.bob,
      this.axes,
      this.trail,
      this.velocityArrow,
      this.gravityArrow,
      this.tensionArrow,
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
    this.sphere.scale.setScalar(l);
    this.equator.scale.setScalar(l);
    this.pivot.scale.setScalar(l);
    this.bob.scale.setScalar(0.05 * l);
    this.axes.scale.setScalar(l);
    if (changed) this.resetCamera();
  }

  resetCamera(): void {
    const l = this.length;
    if (this.topView) this.camera.position.set(0, -1e-4 * l, 5.2 * l);
    else this.camera.position.set(3.3 * l, -3.9 * l, 1.5 * l);
    this.controls.target.set(0, 0, 0);
    this.camera.near = 0.01 * l;
    this.camera.far = 100 * l;
    this.camera.updateProjectionMatrix();
    this.controls.update();
  }

  setTopView(on: boolean): void {
    this.topView = on;
    this.resetCamera();
  }

  resize(): void {
    const w = Math.max(1, this.container.clientWidth);
    const h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
  }

  /** Draws the state `f` of a pendulum of mass `mass` [kg] under gravity `g` [m/s²], with the trail frames. */
  update(f: Frame | null, trail: readonly Frame[], view: ViewOptions, mass: number, g: number): void {
    this.sphere.visible = view.sphere;
    this.equator.visible = view.sphere;
    this.axes.visible = view.axes;
    const has = f !== null;
    this.rod.visible = has;
    this.bob.visible = has;
    if (f === null) {
      this.trail.geometry.setDrawRange(0, 0);
      for (const a of [this.velocityArrow, this.gravityArrow, this.tensionArrow]) a.visible = false;
      return;
    }
    const x = new THREE.Vector3(...f.x);
    const r = x.length();
    this.bob.position.copy(x);
    if (r > 0) {
      this.rod.position.copy(x).multiplyScalar(0.5);
      this.rod.quaternion.setFromUnitVectors(Y, x.clone().divideScalar(r));
      this.rod.scale.set(0.008 * this.length, r, 0.008 * this.length);
    }
    this.updateTrail(view.trail ? trail : [], f);

    // vectors from the bob: velocity at 0.25 s of travel; forces on one scale, m·max(|g|, 1) ↔ 0.5 l
    const l = this.length;
    this.setArrow(this.velocityArrow, view.velocity, x, new THREE.Vector3(...f.v).multiplyScalar(0.25));
    const forceScale = (0.5 * l) / (mass * Math.max(Math.abs(g), 1));
    this.setArrow(this.gravityArrow, view.gravity, x, new THREE.Vector3(0, 0, -mass * g * forceScale));
    const rodForce = r > 0 ? x.clone().multiplyScalar((-f.tension / r) * forceScale) : new THREE.Vector3();
    this.setArrow(this.tensionArrow, view.tension, x, rodForce);
  }

  private setArrow(a: THREE.ArrowHelper, on: boolean, from: THREE.Vector3, vec: THREE.Vector3): void {
    const len = vec.length();
    a.visible = on && len > 1e-6 * this.length;
    if (!a.visible) return;
    a.position.copy(from);
    a.setDirection(vec.clone().divideScalar(len));
    const head = Math.min(0.25 * len, 0.08 * this.length);
    a.setLength(len, head, 0.5 * head);
  }

  private updateTrail(frames: readonly Frame[], now: Frame): void {
    const n = Math.min(frames.length, TRAIL_MAX);
    const start = frames.length - n;
    const p = this.trailPositions;
    const c = this.trailColors;
    const tmp = new THREE.Color();
    const total = n + 1;
    for (let i = 0; i < total; i++) {
      const f = i < n ? (frames[start + i] as Frame) : now;
      p[3 * i] = f.x[0];
      p[3 * i + 1] = f.x[1];
      p[3 * i + 2] = f.x[2];
      // fade: old points blend into the background
      tmp.copy(BACKGROUND).lerp(TRAIL_COLOR, total > 1 ? (i + 1) / total : 1);
      c[3 * i] = tmp.r;
      c[3 * i + 1] = tmp.g;
      c[3 * i + 2] = tmp.b;
    }
    const geom = this.trail.geometry;
    geom.setDrawRange(0, n > 0 ? total : 0);
    (geom.getAttribute('position') as THREE.BufferAttribute).needsUpdate = true;
    (geom.getAttribute('color') as THREE.BufferAttribute).needsUpdate = true;
  }

  render(): void {
    this.controls.update();
    this.renderer.render(this.scene, this.camera);
  }

  /** A PNG of the current view, as a data URL (rendered now, so the drawing buffer is full). */
  screenshot(): string {
    this.render();
    return this.renderer.domElement.toDataURL('image/png');
  }
}
