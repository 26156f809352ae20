// Live plots (uPlot) of the store's histories: energy drift ΔE = E − E₀, J₃ drift, z(t) and the rod tension
// T(t). The values are the server's (computed by the core for every frame); the page only subtracts the
// epoch's first value. The string's events (the server's `event` notices) are marked on z(t) and T(t) as
// vertical lines at their times: dashed where the string went slack, solid where it snapped taut.
import uPlot from 'uplot';
import type { EventNotice } from '../protocol';
import type { History } from '../state';
import { Visibility } from './visible';

interface PlotSpec {
  title: string;
  key: keyof Omit<History, 't'>;
  unit: string;
  color: string;
  /** Whether the string's events are marked on this plot. */
  events?: boolean;
}

export const PLOTS: readonly PlotSpec[] = [
  { title: 'ΔE = E − E₀', key: 'dE', unit: 'J', color: '#ffb347' },
  { title: 'ΔJ₃ = J₃ − J₃(0)', key: 'dJ3', unit: 'kg m²/s', color: '#7dff8a' },
  { title: 'z(t)', key: 'z', unit: 'm', color: '#59c3ff', events: true },
  { title: 'tension T(t)', key: 'tension', unit: 'N', color: '#ff5d73', events: true },
];

function formatTick(v: number): string {
  if (v === 0) return '0';
  const a = Math.abs(v);
  return a >= 1e-3 && a < 1e4 ? String(+v.toPrecision(4)) : v.toExponential(1);
}

export class Plots {
  private readonly charts: uPlot[] = [];
  private readonly els: HTMLElement[] = [];
  private readonly visibility = new Visibility();
  /** Per chart, the history (object, length, last time) it shows: an unchanged one is not redrawn. */
  private readonly shown: { h: History | null; n: number; t: number; ev: readonly EventNotice[] | null }[] = [];
  /** The events marked (the store's last few of the epoch). */
  private events: readonly EventNotice[] = [];

  /** `onDrawn(ms)` after each chart's drawing (uPlot draws in a microtask after setData), for profiling. */
  constructor(
    private readonly container: HTMLElement,
    onDrawn: (ms: number) => void = () => {},
  ) {
    let drawStart = 0;
    const hooks: uPlot.Hooks.Arrays = {
      drawClear: [() => void (drawStart = performance.now())],
      draw: [() => onDrawn(performance.now() - drawStart)],
    };
    for (const spec of PLOTS) {
      const el = document.createElement('div');
      el.className = 'plot';
      container.appendChild(el);
      this.els.push(el);
      this.visibility.watch(el);
      this.shown.push({ h: null, n: -1, t: NaN, ev: null });
      const opts: uPlot.Options = {
        title: `${spec.title} [${spec.unit}]`,
        width: this.width(),
        height: 150,
        scales: { x: { time: false } },
        legend: { show: false },
        hooks: spec.events ? { ...hooks, draw: [...(hooks.draw ?? []), (u) => this.markEvents(u)] } : hooks,
        cursor: { show: true, drag: { x: false, y: false } },
        series: [{ label: 't [s]' }, { label: spec.title, stroke: spec.color, width: 1.5 }],
        axes: [
          { stroke: '#aab', grid: { stroke: '#2a2f3a' }, ticks: { stroke: '#2a2f3a' } },
          {
            stroke: '#aab',
            size: 64,
            grid: { stroke: '#2a2f3a' },
            ticks: { stroke: '#2a2f3a' },
            values: (_u, splits) => splits.map(formatTick),
          },
        ],
      };
      this.charts.push(new uPlot(opts, [[], []], el));
    }
    new ResizeObserver(() => this.resize()).observe(container);
  }

  private width(): number {
    return Math.max(200, this.container.clientWidth - 8);
  }

  resize(): void {
    for (const c of this.charts) c.setSize({ width: this.width(), height: 150 });
  }

  /** Vertical lines at the events' times within the chart's time range. */
  private markEvents(u: uPlot): void {
    const [lo, hi] = [u.scales['x']?.min, u.scales['x']?.max];
    if (lo === undefined || hi === undefined || lo === null || hi === null) return;
    const { ctx, bbox } = u;
    ctx.save();
    ctx.lineWidth = 1;
    ctx.strokeStyle = '#e0e0e0';
    for (const e of this.events) {
      if (e.t < lo || e.t > hi) continue;
      const x = Math.round(u.valToPos(e.t, 'x', true)) + 0.5;
      ctx.setLineDash(e.kind === 'slack' ? [4, 3] : []);
      ctx.beginPath();
      ctx.moveTo(x, bbox.top);
      ctx.lineTo(x, bbox.top + bbox.height);
      ctx.stroke();
    }
    ctx.restore();
  }

  /** Redraws the charts on screen whose data changed (uPlot redraws the whole chart on every setData);
   *  `events`: the string's events to mark on z(t) and T(t). */
  update(h: History, events: readonly EventNotice[] = []): void {
    this.events = events;
    const n = h.t.length;
    const t = h.t[n - 1] ?? NaN;
    PLOTS.forEach((spec, i) => {
      const chart = this.charts[i];
      const el = this.els[i];
      const shown = this.shown[i];
      if (chart === undefined || el === undefined || shown === undefined || !this.visibility.visible(el)) return;
      if (shown.h === h && shown.n === n && Object.is(shown.t, t) && shown.ev === events) return;
      Object.assign(shown, { h, n, t, ev: events });
      chart.setData([h.t, h[spec.key]]);
    });
  }
}
