// Live plots (uPlot) of the store's histories: energy drift ΔE = E − E₀, J₃ drift, z(t) and the rod tension
// T(t). The values are the server's (computed by the core for every frame); the page only subtracts the
// epoch's first value.
import uPlot from 'uplot';
import type { History } from '../state';

interface PlotSpec {
  title: string;
  key: keyof Omit<History, 't'>;
  unit: string;
  color: string;
}

export const PLOTS: readonly PlotSpec[] = [
  { title: 'ΔE = E − E₀', key: 'dE', unit: 'J', color: '#ffb347' },
  { title: 'ΔJ₃ = J₃ − J₃(0)', key: 'dJ3', unit: 'kg m²/s', color: '#7dff8a' },
  { title: 'z(t)', key: 'z', unit: 'm', color: '#59c3ff' },
  { title: 'tension T(t)', key: 'tension', unit: 'N', color: '#ff5d73' },
];

function formatTick(v: number): string {
  if (v === 0) return '0';
  const a = Math.abs(v);
  return a >= 1e-3 && a < 1e4 ? String(+v.toPrecision(4)) : v.toExponential(1);
}

export class Plots {
  private readonly charts: uPlot[] = [];

  constructor(private readonly container: HTMLElement) {
    for (const spec of PLOTS) {
      const el = document.createElement('div');
      el.className = 'plot';
      container.appendChild(el);
      const opts: uPlot.Options = {
        title: `${spec.title} [${spec.unit}]`,
        width: this.width(),
        height: 150,
        scales: { x: { time: false } },
        legend: { show: false },
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

  update(h: History): void {
    PLOTS.forEach((spec, i) => {
      this.charts[i]?.setData([h.t, h[spec.key]]);
    });
  }
}
