// Curve plots on a plain 2-D canvas, for what uPlot's time-series charts do not fit: the phase portrait
// (z, ż) — a closed, unsorted curve — and the effective potential V_eff(θ) (from the server) with the
// current energy as a horizontal line and the current θ as a vertical one. The ranges are pure functions
// (unit-tested); the drawing only maps data to pixels. Each layer with a label gets a legend entry.
import { safeRange } from './ranges';
import { chartSummary, setAltText } from './alttext';

export interface Range {
  lo: number;
  hi: number;
}

/** The range of finite values with a margin (`margin` of the span on each side); a flat set ±max(0.5,
 *  a tenth of its value), a nearly flat one the least span of ranges.ts (never a zero-width range). */
export function dataRange(values: Iterable<number>, margin = 0.1): Range {
  let lo = Infinity;
  let hi = -Infinity;
  for (const v of values) {
    if (!Number.isFinite(v)) continue;
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
  if (lo > hi) return { lo: -1, hi: 1 };
  if (lo === hi) return { lo: lo - Math.max(0.5, Math.abs(lo) * 0.1), hi: hi + Math.max(0.5, Math.abs(lo) * 0.1) };
  const [a, b] = safeRange(lo, hi, margin);
  return { lo: a, hi: b };
}

/** The energy axis of the V_eff plot: from below the well's bottom to above the energy E [J] (or, below
 *  the bottom, a scale of the depth m·max(|g|, 1)·l), so the singular ends near the poles stay off-scale. */
export function potentialRange(vMin: number, energy: number | null, weightScale: number): Range {
  const span = Math.max(energy === null ? 0 : energy - vMin, 0.2 * weightScale);
  return { lo: vMin - 0.15 * span, hi: vMin + 2.2 * span };
}

/** A tick label of `v` on an axis spanning `span`: enough digits that the two ends of a narrow range at a
 *  large value read differently (−3.40512 and −3.40508, not −3.41 and −3.41). */
export function tick(v: number, span = Math.abs(v)): string {
  if (v === 0) return '0';
  const a = Math.abs(v);
  const digits = Math.min(12, Math.max(3, Math.ceil(Math.log10(a / Math.max(span, 1e-300))) + 2));
  return a >= 1e-2 && a < 1e4 ? String(+v.toPrecision(digits)) : v.toExponential(Math.max(1, digits - 2));
}

export interface CurveLayer {
  x: readonly number[];
  y: readonly number[];
  color: string;
  /** The legend's words for this layer (none: not in the legend). */
  label?: string;
}

export class CurvePlot {
  readonly canvas: HTMLCanvasElement;
  private readonly ctx: CanvasRenderingContext2D | null;

  constructor(
    container: HTMLElement,
    private title: string,
    public xLabel: string,
    public yLabel: string,
    private readonly height = 150,
  ) {
    const wrap = document.createElement('div');
    wrap.className = 'plot curve';
    const h = document.createElement('div');
    h.className = 'curve-title';
    h.textContent = title;
    wrap.appendChild(h);
    this.canvas = document.createElement('canvas');
    this.canvas.setAttribute('aria-label', title);
    this.canvas.setAttribute('role', 'img');
    wrap.appendChild(this.canvas);
    container.appendChild(wrap);
    this.ctx = this.canvas.getContext('2d');
  }

  /** Draws the layers in the box x ∈ xr, y ∈ yr, with optional horizontal/vertical marker lines and a dot. */
  draw(
    width: number,
    layers: readonly CurveLayer[],
    xr: Range,
    yr: Range,
    marks: { hLine?: number | null; vLine?: number | null; dot?: [number, number] | null } = {},
  ): void {
    const first = layers[0];
    setAltText(this.canvas, chartSummary(this.title, this.xLabel, this.yLabel, first?.x ?? [], first?.y ?? []));
    const ctx = this.ctx;
    if (ctx === null) return;
    const ratio = Math.min(window.devicePixelRatio || 1, 2);
    const w = Math.max(100, width);
    const h = this.height;
    if (this.canvas.width !== Math.round(w * ratio)) {
      this.canvas.width = Math.round(w * ratio);
      this.canvas.height = Math.round(h * ratio);
      this.canvas.style.width = `${w}px`;
      this.canvas.style.height = `${h}px`;
    }
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, w, h);
    const left = 56;
    const bottom = h - 20;
    const top = 6;
    const right = w - 8;
    const px = (x: number) => left + ((x - xr.lo) / (xr.hi - xr.lo)) * (right - left);
    const py = (y: number) => bottom - ((y - yr.lo) / (yr.hi - yr.lo)) * (bottom - top);
    ctx.strokeStyle = '#2a2f3a';
    ctx.strokeRect(left, top, right - left, bottom - top);
    ctx.fillStyle = '#aab';
    ctx.font = '11px system-ui, sans-serif';
    ctx.fillText(tick(yr.hi, yr.hi - yr.lo), 4, top + 10);
    ctx.fillText(tick(yr.lo, yr.hi - yr.lo), 4, bottom);
    ctx.fillText(this.yLabel, 4, (top + bottom) / 2);
    ctx.fillText(tick(xr.lo, xr.hi - xr.lo), left, h - 4);
    const hiText = tick(xr.hi, xr.hi - xr.lo);
    ctx.fillText(hiText, right - ctx.measureText(hiText).width, h - 4);
    ctx.fillText(this.xLabel, (left + right) / 2 - 10, h - 4);
    ctx.save();
    ctx.beginPath();
    ctx.rect(left, top, right - left, bottom - top);
    ctx.clip();
    if (marks.hLine !== undefined && marks.hLine !== null) this.line(ctx, left, py(marks.hLine), right, py(marks.hLine), '#ffb347');
    if (marks.vLine !== undefined && marks.vLine !== null) this.line(ctx, px(marks.vLine), top, px(marks.vLine), bottom, '#888');
    for (const layer of layers) {
      ctx.strokeStyle = layer.color;
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      let pen = false;
      for (let i = 0; i < layer.x.length; i++) {
        const x = layer.x[i] as number;
        const y = layer.y[i] as number;
        if (!Number.isFinite(x) || !Number.isFinite(y)) {
          pen = false;
          continue;
        }
        const yc = Math.max(-1e4, Math.min(1e4, py(y)));
        if (pen) ctx.lineTo(px(x), yc);
        else ctx.moveTo(px(x), yc);
        pen = true;
      }
      ctx.stroke();
    }
    if (marks.dot) {
      ctx.fillStyle = '#ff8c42';
      ctx.beginPath();
      ctx.arc(px(marks.dot[0]), py(marks.dot[1]), 3.5, 0, 2 * Math.PI);
      ctx.fill();
    }
    ctx.restore();
    // legend: top right, one line per labelled layer in its colour
    let ly = top + 12;
    ctx.textAlign = 'right';
    for (const layer of layers) {
      if (!layer.label) continue;
      ctx.fillStyle = layer.color;
      ctx.fillText(`— ${layer.label}`, right - 4, ly);
      ly += 13;
    }
    ctx.textAlign = 'left';
  }

  private line(ctx: CanvasRenderingContext2D, x0: number, y0: number, x1: number, y1: number, color: string): void {
    ctx.strokeStyle = color;
    ctx.lineWidth = 1;
    ctx.setLineDash([4, 3]);
    ctx.beginPath();
    ctx.moveTo(x0, y0);
    ctx.lineTo(x1, y1);
    ctx.stroke();
    ctx.setLineDash([]);
  }
}
