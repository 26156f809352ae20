// Live plots (uPlot) of the store's histories: the relative drifts of E and J₃ on a log scale (|ΔE|/E_s and
// |ΔJ₃|/J_s, with the float64 roundoff 2.2e-16 marked: a drift at that line is rounding, not error), z(t)
// and the rod tension T(t). The values are the server's (computed by the core for every frame); the page
// only subtracts the epoch's first value and divides by the scale. Every range goes through ranges.ts, so a
// flat series never breaks the axis code. The string's events (the server's `event` notices) are marked
// on z(t) and T(t) as vertical lines at their times: dashed where the string went slack, solid where it
// snapped taut.
import uPlot from 'uplot';
import type { EventNotice } from '../protocol';
import type { History } from '../state';
import { Visibility } from './visible';
import { FLOAT64_EPS, logRange, relativeDrift, safeRange } from './ranges';
import { t } from '../i18n';
import type { Key } from '../i18n';
import { chartSummary, setAltText } from './alttext';

/** What a drift is divided by: E_s = max(|E₀|, m·max(|g|, 1)·l) [J], J_s = max(|J₃(0)|, m l √(max(|g|, 1) l))
 *  [kg m²/s] (the natural units of the pendulum, so a zero E₀ or J₃(0) does not divide by 0). */
export interface DriftScales {
  energy: number;
  j3: number;
}

export function driftScales(e0: number, j30: number, mass: number, g: number, length: number): DriftScales {
  const gg = Math.max(Math.abs(g), 1);
  return {
    energy: Math.max(Math.abs(e0), mass * gg * length),
    j3: Math.max(Math.abs(j30), mass * length * Math.sqrt(gg * length)),
  };
}

interface PlotSpec {
  title: Key;
  axis: string;
  key: keyof Omit<History, 't' | 'frames'>;
  color: string;
  /** A relative drift on a log scale, divided by this scale. */
  drift?: keyof DriftScales;
  /** Whether the string's events are marked on this plot. */
  events?: boolean;
}

export const PLOTS: readonly PlotSpec[] = [
  { title: 'plot.dE', axis: '|ΔE|/E_s', key: 'dE', color: '#ffb347', drift: 'energy' },
  { title: 'plot.dJ3', axis: '|ΔJ₃|/J_s', key: 'dJ3', color: '#7dff8a', drift: 'j3' },
  { title: 'plot.z', axis: 'z [m]', key: 'z', color: '#59c3ff', events: true },
  { title: 'plot.tension', axis: 'T [N]', key: 'tension', color: '#ff5d73', events: true },
];

export function formatTick(v: number | null): string {
  if (v === null || !Number.isFinite(v)) return '';
  if (v === 0) return '0';
  const a = Math.abs(v);
  return a >= 1e-3 && a < 1e4 ? String(+v.toPrecision(4)) : v.toExponential(0);
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
    const axis = { stroke: '#aab', grid: { stroke: '#2a2f3a' }, ticks: { stroke: '#2a2f3a' }, labelSize: 16 };
    for (const spec of PLOTS) {
      const el = document.createElement('div');
      el.className = 'plot';
      el.dataset['plot'] = spec.key;
      container.appendChild(el);
      this.els.push(el);
      this.visibility.watch(el);
      this.shown.push({ h: null, n: -1, t: NaN, ev: null });
      const draw: uPlot.Hooks.Arrays['draw'] = [() => onDrawn(performance.now() - drawStart)];
      if (spec.events) draw.push((u) => this.markEvents(u));
      if (spec.drift) draw.push((u) => this.markFloor(u));
      const opts: uPlot.Options = {
        title: t(spec.title),
        width: this.width(),
        height: 160,
        scales: {
          x: { time: false, range: (_u, lo, hi) => safeRange(lo, hi, 0) },
          y: spec.drift
            ? { distr: 3, log: 10, range: (_u, lo, hi) => logRange(lo, hi) }
            : { range: (_u, lo, hi) => safeRange(lo, hi) },
        },
        legend: { show: true, live: false },
        hooks: { drawClear: [() => void (drawStart = performance.now())], draw },
        cursor: { show: true, drag: { x: false, y: false } },
        series: [{ label: 't [s]' }, { label: spec.axis, stroke: spec.color, width: 1.5 }],
        axes: [
          { ...axis, label: t('plot.time') },
          { ...axis, label: spec.axis, size: 64, values: (_u, splits) => splits.map(formatTick) },
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
    for (const c of this.charts) c.setSize({ width: this.width(), height: 160 });
  }

  /** The float64 roundoff 2.2e-16 as a dashed line on the drift plots. */
  private markFloor(u: uPlot): void {
    const { ctx, bbox } = u;
    const y = Math.round(u.valToPos(FLOAT64_EPS, 'y', true)) + 0.5;
    if (!(y >= bbox.top && y <= bbox.top + bbox.height)) return;
    ctx.save();
    ctx.strokeStyle = '#8a93a6';
    ctx.setLineDash([5, 4]);
    ctx.beginPath();
    ctx.moveTo(bbox.left, y);
    ctx.lineTo(bbox.left + bbox.width, y);
    ctx.stroke();
    ctx.fillStyle = '#8a93a6';
    ctx.font = `${Math.round(11 * devicePixelRatio)}px system-ui, sans-serif`;
    ctx.textAlign = 'left';
    ctx.textBaseline = 'bottom';
    ctx.fillText(t('plot.floor'), bbox.left + 4, y - 3);
    ctx.restore();
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

  /** Each chart's y scale (for tests): the plotted key, uPlot's distribution (3: log) and range. */
  scales(): { key: string; distr: number; min: number | null; max: number | null }[] {
    return PLOTS.map((spec, i) => {
      const y = this.charts[i]?.scales['y'];
      return { key: spec.key, distr: y?.distr ?? 1, min: y?.min ?? null, max: y?.max ?? null };
    });
  }

  /** Redraws the charts on screen whose data changed (uPlot redraws the whole chart on every setData);
   *  `events`: the string's events to mark on z(t) and T(t); `scales`: what the drifts are divided by. */
  update(h: History, events: readonly EventNotice[] = [], scales: DriftScales = { energy: 1, j3: 1 }): void {
    this.events = events;
    const n = h.t.length;
    const tLast = h.t[n - 1] ?? NaN;
    PLOTS.forEach((spec, i) => {
      const chart = this.charts[i];
      const el = this.els[i];
      const shown = this.shown[i];
      if (chart === undefined || el === undefined || shown === undefined || !this.visibility.visible(el)) return;
      if (shown.h === h && shown.n === n && Object.is(shown.t, tLast) && shown.ev === events) return;
      Object.assign(shown, { h, n, t: tLast, ev: events });
      const ys = h[spec.key];
      const drift = spec.drift;
      const y = drift ? ys.map((d) => relativeDrift(d, scales[drift])) : ys;
      chart.setData([h.t, y]);
      setAltText(chart.root, chartSummary(spec.axis, t('plot.time'), spec.axis, h.t, y));
    });
  }
}
