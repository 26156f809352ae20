// The View folder (lil-gui): trail, sphere of reach, axes, top view, stereo, and the vector toggles with the origin
// of the angular momentum and the torque (relative to the pivot, metres). Only the drawing changes: nothing
// is sent to the server.
import type GUI from 'lil-gui';
import type { ViewOptions } from '../scene/options';
import { STEREO_MODES } from '../scene/options';
import type { VectorName } from '../scene/vectors';
import { ARROW_COLORS } from '../scene/options';
import { t } from '../i18n';
import type { Key } from '../i18n';

/** Labels of the vector toggles, with what each arrow is and its scale (docs/web.md). */
export const VECTOR_LABELS: Record<VectorName, [label: Key, title: Key]> = {
  velocity: ['vec.velocity', 'vec.velocityHelp'],
  momentum: ['vec.momentum', 'vec.momentumHelp'],
  gravity: ['vec.gravity', 'vec.gravityHelp'],
  tension: ['vec.tension', 'vec.tensionHelp'],
  net: ['vec.net', 'vec.netHelp'],
  angularMomentum: ['vec.angularMomentum', 'vec.angularMomentumHelp'],
  torque: ['vec.torque', 'vec.torqueHelp'],
};

export function addViewControls(
  gui: GUI,
  view: ViewOptions,
  changed: () => void,
  setTopView: (top: boolean) => void,
): GUI {
  const vf = gui.addFolder(t('gui.view'));
  vf.add(view, 'trail').name(t('gui.trail')).onChange(changed);
  vf.add(view, 'trailSeconds', 1, 120, 1).name(t('gui.trailSeconds')).onChange(changed);
  vf.add(view, 'sphere').name(t('gui.sphere')).onChange(changed);
  vf.add(view, 'axes').name(t('gui.axes')).onChange(changed);
  const top = { topView: false };
  vf.add(top, 'topView')
    .name(t('gui.topView'))
    .onChange((v: boolean) => {
      setTopView(v);
      changed();
    });
  const stereoWords: Record<string, Key> = { off: 'stereo.off', anaglyph: 'stereo.anaglyph', 'side by side': 'stereo.sideBySide' };
  const stereoLabels = Object.fromEntries(STEREO_MODES.map((m) => [stereoWords[m] ? t(stereoWords[m]) : m, m]));
  const stereo = vf.add(view, 'stereo', stereoLabels).name(t('gui.stereo')).onChange(changed);
  stereo.domElement.title = t('gui.stereoHelp');
  stereo.domElement.dataset['control'] = 'stereo';
  vf.close();

  const vec = gui.addFolder(t('gui.vectors'));
  for (const [name, [label, title]] of Object.entries(VECTOR_LABELS) as [VectorName, [Key, Key]][]) {
    const c = vec.add(view, name).name(t(label)).onChange(changed);
    c.domElement.title = t(title);
    c.domElement.dataset['vector'] = name;
    // the colour key beside each toggle
    c.$name.style.borderLeft = `10px solid #${ARROW_COLORS[name].toString(16).padStart(6, '0')}`;
    c.$name.style.paddingLeft = '4px';
  }
  for (const axis of ['X', 'Y', 'Z'] as const) {
    const key = `origin${axis}` as const;
    vec
      .add(view, key, -5, 5, 0.01)
      .name(t('gui.origin', { axis: axis.toLowerCase() }))
      .onChange(changed).domElement.title = t('gui.originHelp');
  }
  vec.close();
  return vf;
}
