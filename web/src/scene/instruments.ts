// The ruler and the protractor drawn in the scene (docs/web.md, "Measuring tools"), in the physics' own
// metres, so they measure what the camera shows from any angle. The ruler stands beside the sphere of reach
// on the camera's right, vertical, from z = +l to z = −l relative to the pivot, with ticks at a round step (0.1 m for l = 1 m)
// and labels every fifth tick. The protractor is a circle of radius 0.4 l about the pivot in the vertical
// plane through the bob, with a tick every 10° of θ (from the downward vertical) and labels every 30°,
// and the bob's θ in degrees beside it. Only drawing: the angle is the streamed state's.
import * as THREE from 'three';

export const INSTRUMENT_COLOR = 0xe6d3a3;

/** A round tick step [m] for a ruler of length `span` [m]: 1, 2 or 5 × 10^k, about a twentieth of it. */
export function rulerStep(span: number): number {
  const raw = span / 20;
  const k = 10 ** Math.floor(Math.log10(raw));
  const m = raw / k;
  return (m < 1.5 ? 1 : m < 3.5 ? 2 : 5) * k;
}

/** A text sprite (a canvas texture), `height` [m] tall. */
export class Label {
  readonly sprite: THREE.Sprite;
  private readonly canvas = document.createElement('canvas');
  private readonly texture: THREE.CanvasTexture;
  private text = '';

  constructor(text: string, height: number) {
    this.canvas.width = 256;
    this.canvas.height = 64;
    this.texture = new THREE.CanvasTexture(this.canvas);
    this.sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map: this.texture, depthTest: false, transparent: true }));
    this.sprite.scale.set(4 * height, height, 1);
    this.set(text);
  }

  set(text: string): void {
    if (text === this.text) return;
    this.text = text;
    const ctx = this.canvas.getContext('2d');
    if (ctx === null) return;
    ctx.clearRect(0, 0, 256, 64);
    ctx.font = 'bold 44px system-ui, sans-serif';
    ctx.fillStyle = `#${INSTRUMENT_COLOR.toString(16)}`;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.fillText(text, 128, 32);
    this.texture.needsUpdate = true;
  }
}

function lines(points: THREE.Vector3[]): THREE.LineSegments {
  const g = new THREE.BufferGeometry().setFromPoints(points);
  return new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: INSTRUMENT_COLOR }));
}

export class Instruments {
  readonly ruler = new THREE.Group();
  readonly protractor = new THREE.Group();
  /** The protractor's circle and ticks, turned about z to the bob's azimuth. */
  private readonly dial = new THREE.Group();
  private readonly thetaLabel = new Label('', 0.1);
  private built = -1;
  private readonly pivot = new THREE.Vector3();
  private moved: { ruler: [number, number]; protractor: [number, number] } = { ruler: [0, 0], protractor: [0, 0] };

  constructor() {
    this.ruler.visible = false;
    this.protractor.visible = false;
    this.protractor.add(this.dial, this.thetaLabel.sprite);
  }

  /** Rebuilds both for rod length l [m] (when it changed). */
  private build(l: number): void {
    if (l === this.built) return;
    this.built = l;
    for (const g of [this.ruler, this.dial]) {
      for (const c of [...g.children]) {
        g.remove(c);
        if (c instanceof THREE.Mesh || c instanceof THREE.LineSegments || c instanceof THREE.Sprite) {
          c.geometry.dispose();
          (c.material as THREE.Material).dispose();
        }
      }
    }
    // ruler: at x = 1.1 l (the group turns x to the camera's right), from z = −l to +l
    const step = rulerStep(2 * l);
    const x0 = 1.1 * l;
    const pts: THREE.Vector3[] = [new THREE.Vector3(x0, 0, -l), new THREE.Vector3(x0, 0, l)];
    const n = Math.floor(l / step + 1e-9);
    for (let i = -n; i <= n; i++) {
      const z = i * step;
      const long = i % 5 === 0;
      pts.push(new THREE.Vector3(x0, 0, z), new THREE.Vector3(x0 - (long ? 0.08 : 0.04) * l, 0, z));
      if (long) {
        const label = new Label(`${+z.toPrecision(6)} m`, 0.07 * l);
        label.sprite.position.set(x0 + 0.16 * l, 0, z);
        this.ruler.add(label.sprite);
      }
    }
    this.ruler.add(lines(pts));
    // protractor: circle of radius r in the (u, z) plane, u = e₁ before the turn to the bob's azimuth
    const r = 0.4 * l;
    const arc: THREE.Vector3[] = [];
    for (let d = 0; d < 360; d += 2) {
      const a0 = (d * Math.PI) / 180;
      const a1 = ((d + 2) * Math.PI) / 180;
      arc.push(new THREE.Vector3(r * Math.sin(a0), 0, -r * Math.cos(a0)), new THREE.Vector3(r * Math.sin(a1), 0, -r * Math.cos(a1)));
    }
    for (let d = 0; d < 360; d += 10) {
      const a = (d * Math.PI) / 180;
      const k = d % 30 === 0 ? 0.85 : 0.92;
      arc.push(new THREE.Vector3(r * Math.sin(a), 0, -r * Math.cos(a)), new THREE.Vector3(k * r * Math.sin(a), 0, -k * r * Math.cos(a)));
      if (d % 30 === 0 && d <= 180) {
        const label = new Label(`${d}°`, 0.06 * l);
        label.sprite.position.set(1.2 * r * Math.sin(a), 0, -1.2 * r * Math.cos(a));
        this.dial.add(label.sprite);
      }
    }
    // the vertical through the pivot (θ = 0 and 180°)
    arc.push(new THREE.Vector3(0, 0, -r), new THREE.Vector3(0, 0, r));
    this.dial.add(lines(arc));
  }

  /** Turns the ruler to stand beside the sphere on the camera's right: right = (−d_y, d_x) for d = camera −
   *  pivot (called again when the camera moves). */
  face(camera: THREE.Vector3): void {
    const p = this.ruler.position;
    this.ruler.rotation.set(0, 0, Math.atan2(camera.x - p.x, -(camera.y - p.y)));
    this.placeRuler();
  }

  /** The ruler's place: the pivot, moved by `moved.ruler` [rod lengths] along its own x (the camera's right)
   *  and up. */
  private placeRuler(): void {
    const a = this.ruler.rotation.z;
    const [shift, lift] = this.moved.ruler;
    const l = this.built > 0 ? this.built : 1;
    this.ruler.position.set(this.pivot.x + shift * l * Math.cos(a), this.pivot.y + shift * l * Math.sin(a), this.pivot.z + lift * l);
  }

  /** Places both at the pivot [m] for rod length l [m] and turns the protractor to the bob at x (relative
   *  to the pivot), labelling its θ in degrees. */
  update(
    pivot: THREE.Vector3,
    x: readonly [number, number, number],
    l: number,
    rulerOn: boolean,
    protractorOn: boolean,
    camera: THREE.Vector3,
    moved: { ruler: [number, number]; protractor: [number, number] } = { ruler: [0, 0], protractor: [0, 0] },
  ): void {
    this.ruler.visible = rulerOn;
    this.protractor.visible = protractorOn;
    if (!rulerOn && !protractorOn) return;
    this.build(l);
    this.moved = moved;
    this.pivot.copy(pivot);
    this.ruler.position.copy(pivot);
    this.face(camera);
    const phi = Math.atan2(x[1], x[0]);
    // the protractor moved along its dial's plane (the vertical plane through the bob) and up
    const [ps, pl] = moved.protractor;
    const c = Number.isFinite(phi) ? Math.cos(phi) : 1;
    const sn = Number.isFinite(phi) ? Math.sin(phi) : 0;
    this.protractor.position.set(pivot.x + ps * l * c, pivot.y + ps * l * sn, pivot.z + pl * l);
    const theta = Math.atan2(Math.hypot(x[0], x[1]), -x[2]);
    this.dial.rotation.set(0, 0, Number.isFinite(phi) ? phi : 0);
    // the reading half way between the vertical and the rod, beyond the dial's labels (at 0.48 l), so that
    // at small angles it no longer sits on the 0° label (issue 28)
    const r = 0.72 * l;
    const mid = theta / 2;
    this.thetaLabel.sprite.position.set(r * Math.sin(mid) * Math.cos(phi), r * Math.sin(mid) * Math.sin(phi), -r * Math.cos(mid));
    this.thetaLabel.sprite.scale.set(0.4 * l, 0.1 * l, 1);
    this.thetaLabel.set(`θ = ${((theta * 180) / Math.PI).toFixed(1)}°`);
  }
}
