// The plot of chosen variables (docs/web.md, "Plots"): any two of variables.ts (t, θ, φ, z, E, K, U, J₃,
// tension, …) against each other, with axis labels, units and a legend — the second pendulum's curve
// beside the first when it is shown. Drawn from the store's thinned history (at most 4000 frames).
import type { Frame } from '../protocol';
import { CurvePlot, dataRange } from './curves';
import type { CurveLayer } from './curves';
import { Visibility } from './visible';
import { VARIABLES, columns, variable } from '../variables';
import type { PlotContext } from '../variables';
import { t } from '../i18n';

export class ChosenPlot {
  private readonly plot: CurvePlot;
  private readonly visibility = new Visibility();
  readonly choice = { x: 't', y: 'theta' };
  private readonly selects: Partial<Record<'x' | 'y', HTMLSelectElement>> = {};

  /** Plots `y` against `x` (variables.ts names; a shared link's plot). False when one is unknown. */
  choose(x: string, y: string): boolean {
    if (![x, y].every((n) => VARIABLES.some((v) => v.name === n))) return false;
    this.choice.x = x;
    this.choice.y = y;
    if (this.selects.x) this.selects.x.value = x;
    if (this.selects.y) this.selects.y.value = y;
    this.labels();
    return true;
  }

  constructor(private readonly container: HTMLElement) {
    const bar = document.createElement('div');
    bar.className = 'tools chosen';
    bar.dataset['tool'] = 'chosen';
    const h = document.createElement('h3');
    h.textContent = t('chosen.title');
    bar.appendChild(h);
    for (const axis of ['y', 'x'] as const) {
      const label = document.createElement('label');
      label.append(`${axis === 'x' ? t('chosen.xAxis') : t('chosen.yAxis')} `);
      const select = document.createElement('select');
      select.dataset['input'] = `chosen-${axis}`;
      for (const v of VARIABLES) {
        const o = document.createElement('option');
        o.value = v.name;
        o.textContent = `${t(v.label)} [${v.unit}]`;
        select.appendChild(o);
      }
      select.value = this.choice[axis];
      this.selects[axis] = select;
      select.addEventListener('change', () => {
        this.choice[axis] = select.value;
        this.labels();
      });
      label.appendChild(select);
      bar.append(label, ' ');
    }
    container.appendChild(bar);
    this.plot = new CurvePlot(container, '', '', '', 170);
    this.plot.canvas.dataset['plot'] = 'chosen';
    this.visibility.watch(this.plot.canvas);
    this.labels();
  }

  private labels(): void {
    const [vx, vy] = [variable(this.choice.x), variable(this.choice.y)];
    this.plot.xLabel = `${t(vx.label)} [${vx.unit}]`;
    this.plot.yLabel = `${t(vy.label)} [${vy.unit}]`;
  }

  /** Draws the chosen variables of `frames` (and of the second pendulum's `twin`, if any). */
  update(frames: readonly Frame[], c: PlotContext, twin: readonly Frame[] | null = null): void {
    if (!this.visibility.visible(this.plot.canvas)) return;
    const a = columns(frames, this.choice.x, this.choice.y, c);
    const layers: CurveLayer[] = [{ ...a, color: '#59c3ff', label: twin ? t('twin.first') : t(variable(this.choice.y).label) }];
    if (twin !== null) layers.push({ ...columns(twin, this.choice.x, this.choice.y, c), color: '#c8f560', label: t('twin.second') });
    const xs = layers.flatMap((l) => l.x);
    const ys = layers.flatMap((l) => l.y);
    this.plot.draw(this.container.clientWidth - 8, layers, dataRange(xs, 0.02), dataRange(ys));
  }
}
