// The motion in words, for screen readers (docs/web.md, "Keyboard and accessibility"; issue 28): the angle
// from the vertical, whether the bob rises or falls, its speed and how the energy is split — read from the
// drawn state and the energy bars' numbers (measure.ts), nothing computed anew. No DOM; unit-tested.
// Units: angles in degrees, speed in m/s, the energy split in per cent of kinetic + potential + lost.
import type { Frame } from './protocol';
import type { EnergySplit } from './measure';
import { DEG, sphericalAngles } from './measure';
import { t } from './i18n';

/** One sentence about state `f` (speeds below `still` [m/s] are "at rest", vertical speeds below a
 *  thousandth of the speed a turning point) with the energy split `e` (null: left out). */
export function describeMotion(f: Frame | null, e: EnergySplit | null, still = 1e-6): string {
  if (f === null) return t('describe.none');
  const theta = sphericalAngles(f.x).theta * DEG;
  const speed = Math.hypot(...f.v);
  const zdot = f.v[2];
  const dir = speed < still ? t('describe.rest') : Math.abs(zdot) < 1e-3 * speed ? t('describe.turning') : zdot > 0 ? t('describe.rising') : t('describe.falling');
  let text = t('describe.text', { theta: theta.toFixed(0), dir, v: speed.toFixed(2) });
  if (e !== null) {
    const sum = Math.abs(e.kinetic) + Math.abs(e.potential) + Math.abs(e.lost);
    if (sum > 0) {
      const pc = (x: number) => Math.round((100 * x) / sum);
      text += t('describe.energy', { k: pc(e.kinetic), u: pc(e.potential) });
      if (Math.abs(e.lost) > 0.005 * sum) text += t('describe.lost', { p: pc(e.lost) });
    }
  }
  return text;
}
