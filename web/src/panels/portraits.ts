// The phase portrait (z, ż) of the received history with the drawn state as a dot, and the effective
// potential V_eff(θ) = −m g l cos θ + J₃²/(2 m l² sin²θ) (T-2.5; the curve comes from the server,
// POST /api/effective_potential) with the current energy E as a line and the current θ: the motion keeps
// to where V_eff ≤ E, the turning angles are where the line meets the curve.
import type { EffectivePotential, Frame } from '../protocol';
import type { History } from '../state';
import { CurvePlot, dataRange, potentialRange } from './curves';

/** Polar angle θ from the downward vertical [rad] of a position x [m] relative to the pivot. */
export function polarAngle(x: readonly [number, number, number]): number {
  return Math.atan2(Math.hypot(x[0], x[1]), -x[2]);
}

export class Portraits {
  private readonly phase: CurvePlot;
  private readonly potential: CurvePlot;

  constructor(private readonly container: HTMLElement) {
    this.phase = new CurvePlot(container, 'phase portrait (z, ż) [m, m/s]', 'z [m]', 'ż');
    this.potential = new CurvePlot(container, 'V_eff(θ) and the energy E [J]', 'θ [rad]', 'J');
  }

  /** Redraws both from the history, the drawn frame `f`, the server's V_eff curve (or null), and the
   *  pendulum's mass [kg], g [m/s²], length [m]. */
  update(h: History, f: Frame | null, veff: EffectivePotential | null, mass: number, g: number, length: number): void {
    const width = Math.max(200, this.container.clientWidth - 8);
    const dot: [number, number] | null = f ? [f.x[2], f.v[2]] : null;
    const zs = f ? [...h.z, f.x[2]] : h.z;
    const zds = f ? [...h.zdot, f.v[2]] : h.zdot;
    this.phase.draw(width, [{ x: h.z, y: h.zdot, color: '#59c3ff' }], dataRange(zs), dataRange(zds), { dot });
    if (veff === null || veff.theta.length === 0) {
      this.potential.draw(width, [], { lo: 0, hi: Math.PI }, { lo: -1, hi: 1 });
      return;
    }
    const yr = potentialRange(veff.minimum.v_eff, f?.energy ?? null, mass * Math.max(Math.abs(g), 1) * length);
    this.potential.draw(width, [{ x: veff.theta, y: veff.v_eff, color: '#7dff8a' }], { lo: 0, hi: Math.PI }, yr, {
      hLine: f?.energy ?? null,
      vLine: f ? polarAngle(f.x) : null,
    });
  }
}
