// The energy bar chart (docs/web.md, "Energy bars"): kinetic ½m|v|², potential (the core's E − K, measured
// from the sphere's lowest point: + m|g|l), the energy lost to damping and drag (−∫P dt of the streamed
// power, and the string's snaps), and their total, which stays at E₀ + m|g|l while the power balance
// holds (T-7.1). A plain 2-D canvas; the numbers are measure.ts's.
import type { EnergySplit } from '../measure';
import { t } from '../i18n';

const COLORS = { kinetic: '#7dff8a', potential: '#59c3ff', lost: '#ff5d73', total: '#e8e8e8' } as const;
type Bar = keyof typeof COLORS;

export class EnergyBars {
  readonly canvas: HTMLCanvasElement;
  private readonly ctx: CanvasRenderingContext2D | null;
  private scale = 1;
  /** The container's width [CSS px], kept by a ResizeObserver (null until first read): `draw` runs in the
   *  panels' 10 Hz tick right after other panels wrote to the page, where reading clientWidth forced a
   *  layout every tick (docs/performance.md, "The one-file lab in the browser"). */
  private width: number | null = null;
  /** The numbers drawn last (for tests: window.pendulab.energy()). */
  shown: EnergySplit | null = null;

  constructor(container: HTMLElement) {
    const h = document.createElement('h3');
    h.textContent = t('energy.title');
    container.appendChild(h);
    this.canvas = document.createElement('canvas');
    this.canvas.setAttribute('role', 'img');
    this.canvas.setAttribute('aria-label', t('energy.title'));
    container.appendChild(this.canvas);
    this.ctx = this.canvas.getContext('2d');
    new ResizeObserver(() => (this.width = container.clientWidth)).observe(container);
  }

  /** A new trajectory: the bars' scale starts again from its total. */
  rescale(): void {
    this.scale = 1;
  }

  draw(split: EnergySplit | null, showLost: boolean): void {
    this.shown = split;
    const ctx = this.ctx;
    if (ctx === null) return;
    const ratio = Math.min(window.devicePixelRatio || 1, 2);
    this.width ??= this.canvas.parentElement?.clientWidth ?? 300;
    const w = Math.max(200, this.width - 4);
    const h = 130;
    if (this.canvas.width !== Math.round(w * ratio)) {
      this.canvas.width = Math.round(w * ratio);
      this.canvas.height = Math.round(h * ratio);
      this.canvas.style.width = `${w}px`;
      this.canvas.style.height = `${h}px`;
    }
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, w, h);
    if (split === null) return;
    const bars: [Bar, string, number][] = [
      ['kinetic', t('energy.kinetic'), split.kinetic],
      ['potential', t('energy.potential'), split.potential],
    ];
    if (showLost) bars.push(['lost', t('energy.lost'), split.lost]);
    bars.push(['total', t('energy.total'), split.total]);
    const biggest = Math.max(...bars.map(([, , v]) => Math.abs(v)), 1e-12);
    // the scale grows at once and shrinks slowly, so the bars do not jump
    this.scale = biggest > this.scale ? biggest : Math.max(biggest, 0.995 * this.scale);
    const top = 14;
    const bottom = h - 30;
    const base = bottom;
    const slot = w / bars.length;
    ctx.font = '11px system-ui, sans-serif';
    ctx.textAlign = 'center';
    bars.forEach(([key, label, v], i) => {
      const x = slot * i + slot * 0.2;
      const bw = slot * 0.6;
      const len = (Math.abs(v) / this.scale) * (bottom - top);
      ctx.fillStyle = COLORS[key];
      if (v >= 0) ctx.fillRect(x, base - len, bw, len);
      else {
        ctx.globalAlpha = 0.5;
        ctx.fillRect(x, base - len, bw, len);
        ctx.globalAlpha = 1;
      }
      ctx.fillStyle = '#dde3ee';
      ctx.fillText(label, x + bw / 2, h - 16);
      ctx.fillText(`${v.toPrecision(4)} J`, x + bw / 2, h - 3);
    });
    ctx.strokeStyle = '#555';
    ctx.beginPath();
    ctx.moveTo(0, base + 0.5);
    ctx.lineTo(w, base + 0.5);
    ctx.stroke();
  }
}
