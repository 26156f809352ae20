// The first pendulum's fading trail (docs/web.md, "View"): the bob's positions [m] over the last
// `trailSeconds` of simulated time, oldest first, drawn as one line whose colour blends from the background
// (oldest) to the trail's colour (newest). The buffers are allocated once for TRAIL_MAX points (state.ts)
// and written in place every frame; only the part drawn is uploaded.
import * as THREE from 'three';
import type { Frame } from '../protocol';
import { TRAIL_MAX } from '../state';

/** The trail to draw: `frames[start..end)`, oldest first (LabStore.trailRange). */
export interface TrailSlice {
  frames: readonly Frame[];
  start: number;
  end: number;
}

/** No trail. */
export const NO_TRAIL: TrailSlice = { frames: [], start: 0, end: 0 };

const TRAIL_COLOR = new THREE.Color(0x59c3ff);

export class FadingTrail {
  readonly line: THREE.Line;
  private readonly positions = new Float32Array(3 * (TRAIL_MAX + 1));
  private readonly colors = new Float32Array(3 * (TRAIL_MAX + 1));
  /** Points the fade colours were computed for (they depend on the count only). */
  private colored = -1;

  /** `background`: the colour the oldest points fade into. */
  constructor(private readonly background: THREE.Color) {
    const tg = new THREE.BufferGeometry();
    tg.setAttribute('position', new THREE.BufferAttribute(this.positions, 3));
    tg.setAttribute('color', new THREE.BufferAttribute(this.colors, 3));
    tg.setDrawRange(0, 0);
    this.line = new THREE.Line(tg, new THREE.LineBasicMaterial({ vertexColors: true }));
    this.line.frustumCulled = false;
  }

  /** Draws nothing. */
  hide(): void {
    this.line.geometry.setDrawRange(0, 0);
  }

  /** Writes the trail's points (the slice, then the drawn state `now`; each at pivot + x [m]) into the fixed
   *  buffers in place and uploads only the part drawn; the fade colours are recomputed only when the number
   *  of points changed. */
  update(trail: TrailSlice, now: Frame): void {
    const n = Math.min(trail.end - trail.start, TRAIL_MAX);
    const geom = this.line.geometry;
    if (n <= 0) {
      geom.setDrawRange(0, 0);
      return;
    }
    const start = trail.end - n;
    const p = this.positions;
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
    if (total !== this.colored) this.fade(total);
  }

  /** Colours `total` points: old points blend into the background. */
  private fade(total: number): void {
    this.colored = total;
    const c = this.colors;
    const tmp = new THREE.Color();
    for (let i = 0; i < total; i++) {
      tmp.copy(this.background).lerp(TRAIL_COLOR, (i + 1) / total);
      c[3 * i] = tmp.r;
      c[3 * i + 1] = tmp.g;
      c[3 * i + 2] = tmp.b;
    }
    const color = this.line.geometry.getAttribute('color') as THREE.BufferAttribute;
    color.clearUpdateRanges();
    color.addUpdateRange(0, 3 * total);
    color.needsUpdate = true;
  }
}
