// The phase portrait (z, ż) of the received history with the drawn state as a dot; the effective
// potential V_eff(θ) = −m g l cos θ + J₃²/(2 m l² sin²θ) (T-2.5; the curve comes from the server,
// POST /api/effective_potential) with the current energy E as a line and the current θ: the motion keeps
// to where V_eff ≤ E, the turning angles are where the line meets the curve; and the energy–momentum map
// (T-6.4): the boundary of the image of (J₃, E) (the conical orbits, from POST /api/em_map), the line
// J₃ = 0 of planar motions, and the current (J₃, E) of the frames.
import type { EMView, EffectivePotential, Frame } from '../protocol';
import type { History } from '../state';
import { CurvePlot, dataRange, potentialRange } from './curves';
import { offSphereNote } from '../models';
import { Visibility } from './visible';
import { t } from '../i18n';

/** Polar angle θ from the downward vertical [rad] of a position x [m] relative to the pivot. */
export function polarAngle(x: readonly [number, number, number]): number {
  return Math.atan2(Math.hypot(x[0], x[1]), -x[2]);
}

export class Portraits {
  private readonly phase: CurvePlot;
  private readonly potential: CurvePlot;
  private readonly em: CurvePlot;
  private readonly note: HTMLElement;
  /** Only the plots on screen are drawn (the side panel scrolls). */
  private readonly visibility = new Visibility();

  constructor(private readonly container: HTMLElement) {
    this.phase = new CurvePlot(container, t('portrait.phase'), 'z [m]', 'ż [m/s]');
    this.potential = new CurvePlot(container, t('portrait.veff'), 'θ [rad]', 'E [J]');
    this.em = new CurvePlot(container, t('portrait.em'), 'J₃ [kg m²/s]', 'E [J]');
    for (const p of [this.phase, this.potential, this.em]) this.visibility.watch(p.canvas);
    this.note = document.createElement('p');
    this.note.className = 'note';
    this.note.dataset['note'] = 'portraits';
    container.appendChild(this.note);
  }

  /** Says why V_eff and the map are empty for a model off the sphere (models.ts), or nothing. */
  setModel(model: string): void {
    const text = offSphereNote(model) ?? '';
    if (this.note.textContent !== text) this.note.textContent = text;
  }

  /** Draws the energy–momentum map's boundary (or nothing) and the frame's (J₃, E), when on screen. */
  updateEM(em: EMView | null, f: Frame | null): void {
    if (!this.visibility.visible(this.em.canvas)) return;
    const width = Math.max(200, this.container.clientWidth - 8);
    if (em === null) {
      this.em.draw(width, [], { lo: -1, hi: 1 }, { lo: -1, hi: 1 });
      return;
    }
    const weight = em.top.energy;
    const jr = dataRange([...em.boundary.j3.filter((_, i) => (em.boundary.energy[i] ?? Infinity) < 2.6 * weight), f?.j3 ?? 0], 0.05);
    const yr = { lo: em.bottom.energy - 0.15 * weight, hi: Math.max(2.6 * weight, (f?.energy ?? 0) + 0.2 * weight) };
    this.em.draw(width, [{ x: em.boundary.j3, y: em.boundary.energy, color: '#c9a0ff', label: t('portrait.emBoundary') }], jr, yr, {
      vLine: 0,
      hLine: em.top.energy,
      dot: f ? [f.j3, f.energy] : null,
    });
  }

  /** Redraws both (those on screen) from the history, the drawn frame `f`, the server's V_eff curve (or
   *  null), and the pendulum's mass [kg], g [m/s²], length [m]. */
  update(h: History, f: Frame | null, veff: EffectivePotential | null, mass: number, g: number, length: number): void {
    const width = Math.max(200, this.container.clientWidth - 8);
    if (this.visibility.visible(this.phase.canvas)) {
      const dot: [number, number] | null = f ? [f.x[2], f.v[2]] : null;
      const zr = dataRange(f ? [...h.z, f.x[2]] : h.z);
      const zdr = dataRange(f ? [...h.zdot, f.v[2]] : h.zdot);
      this.phase.draw(width, [{ x: h.z, y: h.zdot, color: '#59c3ff', label: t('portrait.orbit') }], zr, zdr, { dot });
    }
    if (!this.visibility.visible(this.potential.canvas)) return;
    if (veff === null || veff.theta.length === 0) {
      this.potential.draw(width, [], { lo: 0, hi: Math.PI }, { lo: -1, hi: 1 });
      return;
    }
    const yr = potentialRange(veff.minimum.v_eff, f?.energy ?? null, mass * Math.max(Math.abs(g), 1) * length);
    this.potential.draw(width, [{ x: veff.theta, y: veff.v_eff, color: '#7dff8a', label: 'V_eff(θ)' }], { lo: 0, hi: Math.PI }, yr, {
      hLine: f?.energy ?? null,
      vLine: f ? polarAngle(f.x) : null,
    });
  }
}
