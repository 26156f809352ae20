// The reduced view (Holm's Figure 2, docs/theory.md §3): in σ-space (σ₁ = z/l, σ₂ = ż/l, σ₃ = |v|²/l²) the J₃
// surface C = σ₃(1 − σ₁²) − σ₂² − σ₆² = 0 and the energy plane H = ½σ₃ + (g/l)σ₁ = const, whose
// intersection is the orbit; the orbit itself (from the server: pendulab.reduce over one z-period, POST
// /api/reduced) and the current σ point. Axes are scaled into a box (σ₂ by its span S, σ₃ by its span),
// so the picture fits whatever the energy; the surface above the box is clipped. Drawing only.
import * as THREE from 'three';
import { t } from '../i18n';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import type { Frame, ReducedCurves } from '../protocol';
import type { RenderQuality } from './quality';

/** σ₁, σ₂, σ₃ of a state x [m], v [m/s] relative to the pivot, for rod length l [m] (T-3.1). */
export function sigmaOf(f: Pick<Frame, 'x' | 'v'>, length: number): [number, number, number] {
  const l2 = length * length;
  return [f.x[2] / length, f.v[2] / length, (f.v[0] ** 2 + f.v[1] ** 2 + f.v[2] ** 2) / l2];
}

/** The box scales: σ₂ ∈ [−S, S] → [−1, 1], σ₃ ∈ [0, top] → [−1, 1], σ₁ as it is. */
export function boxScales(c: ReducedCurves): { s2: number; s3top: number } {
  const s2 = Math.max(...c.surface.sigma2.map(Math.abs), 1e-9);
  const s3 = Math.max(...c.orbit.sigma3, c.point[2], 1e-9);
  return { s2, s3top: 1.6 * s3 + 1e-9 };
}

export class ReducedView {
  private readonly renderer: THREE.WebGLRenderer;
  private readonly camera = new THREE.PerspectiveCamera(35, 1, 0.01, 100);
  private readonly controls: OrbitControls;
  private readonly scene = new THREE.Scene();
  private readonly group = new THREE.Group();
  private readonly point: THREE.Mesh;
  private scales: { s2: number; s3top: number } | null = null;
  private readonly note: HTMLElement;
  /** Drawn only while on screen (the side panel scrolls), at most every MIN_INTERVAL ms. */
  private visible = false;
  private lastDrawn = -Infinity;
  private dirty = true;

  constructor(
    private readonly container: HTMLElement,
    quality: RenderQuality,
  ) {
    const title = document.createElement('div');
    title.className = 'curve-title';
    title.textContent = t('data.reduced');
    container.appendChild(title);
    this.renderer = new THREE.WebGLRenderer({ antialias: quality.antialias, preserveDrawingBuffer: true });
    this.renderer.localClippingEnabled = true;
    this.renderer.setPixelRatio(quality.pixelRatio);
    this.renderer.domElement.className = 'reduced-canvas';
    container.appendChild(this.renderer.domElement);
    this.note = document.createElement('p');
    this.note.className = 'note';
    container.appendChild(this.note);
    this.scene.background = new THREE.Color(0x161a22);
    this.camera.up.set(0, 0, 1);
    this.camera.position.set(3.2, -3.6, 2.2);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.point = new THREE.Mesh(
      new THREE.SphereGeometry(0.05, 16, 12),
      new THREE.MeshBasicMaterial({ color: 0xff8c42, depthTest: false, transparent: true }),
    );
    this.point.renderOrder = 3;
    this.point.visible = false;
    this.scene.add(this.group, this.point, new THREE.AxesHelper(1.2));
    this.resize();
    new ResizeObserver(() => this.resize()).observe(container);
    new IntersectionObserver((entries) => {
      this.visible = entries.some((e) => e.isIntersecting);
    }).observe(this.renderer.domElement);
    this.controls.addEventListener('change', () => {
      this.dirty = true;
    });
  }

  resize(): void {
    const w = Math.max(200, this.container.clientWidth - 8);
    const h = 220;
    this.renderer.setSize(w, h, false);
    this.renderer.domElement.style.width = `${w}px`;
    this.renderer.domElement.style.height = `${h}px`;
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
  }

  /** Shows `text` instead of the picture (another model, or an error); null to clear. */
  setNote(text: string | null): void {
    this.note.textContent = text ?? '';
    if (text !== null) this.set(null);
  }

  /** Replaces the curves (null: none). */
  set(c: ReducedCurves | null): void {
    for (const child of [...this.group.children]) {
      this.group.remove(child);
      const m = child as THREE.Mesh;
      m.geometry?.dispose();
      (m.material as THREE.Material | undefined)?.dispose();
    }
    this.scales = c === null ? null : boxScales(c);
    this.dirty = true;
    if (c === null || this.scales === null) return;
    const { s2, s3top } = this.scales;
    const map = (a: number, b: number, d: number) => new THREE.Vector3(a, b / s2, (2 * d) / s3top - 1);
    const clip = [new THREE.Plane(new THREE.Vector3(0, 0, -1), 1)];
    // the J₃ surface: a grid mesh
    const { sigma1, sigma2, sigma3 } = c.surface;
    const pos: number[] = [];
    sigma1.forEach((a, i) => sigma2.forEach((b, k) => pos.push(...map(a, b, sigma3[i]?.[k] ?? NaN).toArray())));
    const index: number[] = [];
    const n2 = sigma2.length;
    for (let i = 0; i + 1 < sigma1.length; i++) {
      for (let k = 0; k + 1 < n2; k++) {
        const q = i * n2 + k;
        index.push(q, q + n2, q + 1, q + 1, q + n2, q + n2 + 1);
      }
    }
    const sg = new THREE.BufferGeometry();
    sg.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
    sg.setIndex(index);
    const surfMat = { color: 0x8fb3ff, transparent: true, opacity: 0.25, side: THREE.DoubleSide, clippingPlanes: clip };
    this.group.add(new THREE.Mesh(sg, new THREE.MeshBasicMaterial({ ...surfMat, depthWrite: false })));
    this.group.add(new THREE.Mesh(sg.clone(), new THREE.MeshBasicMaterial({ ...surfMat, wireframe: true, opacity: 0.25 })));
    // the energy plane σ₃ = 2(h − γσ₁), over σ₁ ∈ [−1, 1], σ₂ ∈ [−S, S]
    const { h, gamma } = c.plane;
    const corner = (a: number, b: number) => map(a, b, 2 * (h - gamma * a));
    const pg = new THREE.BufferGeometry().setFromPoints([corner(-1, -s2), corner(1, -s2), corner(1, s2), corner(-1, s2)]);
    pg.setIndex([0, 1, 2, 0, 2, 3]);
    const planeMat = new THREE.MeshBasicMaterial({
      color: 0xffb347,
      transparent: true,
      opacity: 0.22,
      side: THREE.DoubleSide,
      depthWrite: false,
      clippingPlanes: [...clip, new THREE.Plane(new THREE.Vector3(0, 0, 1), 1)],
    });
    this.group.add(new THREE.Mesh(pg, planeMat));
    // the orbit
    const o = c.orbit;
    const line = new THREE.BufferGeometry().setFromPoints(
      o.sigma1.map((a, i) => map(a, o.sigma2[i] ?? NaN, o.sigma3[i] ?? NaN)),
    );
    const orbit = new THREE.Line(line, new THREE.LineBasicMaterial({ color: 0x59c3ff, depthTest: false, transparent: true }));
    orbit.renderOrder = 2; // over the translucent surface and plane
    this.group.add(orbit);
    this.point.visible = true;
  }

  /** Moves the current point to the σ of `f` (pendulum length [m]) and renders when on screen. */
  update(f: Frame | null, length: number): void {
    if (this.scales !== null && f !== null) {
      const [a, b, d] = sigmaOf(f, length);
      this.point.position.set(a, b / this.scales.s2, (2 * d) / this.scales.s3top - 1);
    }
    this.point.visible = this.scales !== null && f !== null;
    const now = performance.now();
    if (!this.visible || (!this.dirty && now - this.lastDrawn < ReducedView.MIN_INTERVAL)) return;
    this.lastDrawn = now;
    this.dirty = false;
    this.controls.update();
    this.renderer.render(this.scene, this.camera);
  }

  static readonly MIN_INTERVAL = 250;
}
