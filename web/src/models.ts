// What the page does differently for the two models whose bob leaves the sphere |x| = l (docs/web.md):
// the swinging spring (`spring`: an elastic rod of rest length l, its length varies) and the pendulum on a
// string (`string`: taut on the sphere, or slack in free flight inside it). No DOM; unit-tested.
import { t } from './i18n';

/** The models whose bob is not always on the sphere of radius l (the crane mode's load: the hoist changes
 *  its rope, crane/). */
export const OFF_SPHERE_MODELS: readonly string[] = ['spring', 'string', 'crane'];

/** True when the model's bob always stays on the sphere |x| = l: the sphere's analyses (exact solution,
 *  V_eff, energy–momentum map, reduced view) apply. False for the swinging spring and the string. */
export function staysOnSphere(model: string | null | undefined): boolean {
  return !OFF_SPHERE_MODELS.includes(model ?? 'ideal');
}

/** Why the sphere's analyses are not shown for this model, or null when they are. */
export function offSphereNote(model: string | null | undefined): string | null {
  if (model === 'spring') {
    return t('note.spring');
  }
  if (model === 'string') {
    return t('note.string');
  }
  return null;
}

/** How the link from the pivot to the bob is drawn: a rod; a coil whose length follows the spring; a thin
 *  taut string; a dashed sagging string while slack. */
export type TetherStyle = 'rod' | 'coil' | 'taut string' | 'slack string';

export function tetherStyle(model: string | null | undefined, taut: boolean): TetherStyle {
  if (model === 'spring') return 'coil';
  if (model === 'string') return taut ? 'taut string' : 'slack string';
  return 'rod';
}
