// The View folder (lil-gui): trail, sphere of reach, axes, top view, stereo, and the vector toggles with the origin
// of the angular momentum and the torque (relative to the pivot, metres). Only the drawing changes: nothing
// is sent to the server.
import type GUI from 'lil-gui';
import type { ViewOptions } from '../scene/scene';
import { STEREO_MODES } from '../scene/scene';
import type { VectorName } from '../scene/vectors';

/** Labels of the vector toggles, with what each arrow is and its scale (docs/web.md). */
export const VECTOR_LABELS: Record<VectorName, [label: string, title: string]> = {
  velocity: ['velocity v', 'v [m/s], drawn as 0.25 s of travel'],
  momentum: ['momentum m v', 'm v [kg m/s], 0.25 m per kg m/s'],
  gravity: ['gravity m g', 'the weight m g d [N] (d: the gravity direction); forces: m·max(|g|, 1) N ↔ 0.5 l'],
  tension: ['rod force (tension)', 'the rod force −T x/|x| [N], T from the server'],
  net: ['net force m a', 'm a [N]: a = ẍ computed by the server’s core (relative to the pivot)'],
  angularMomentum: ['angular momentum L', 'L = (x − o) × m v [kg m²/s] about the origin o, drawn from o'],
  torque: ['torque τ', 'τ = (x − o) × m a [N m] about the origin o, drawn from o; dL/dt = τ'],
};

export function addViewControls(
  gui: GUI,
  view: ViewOptions,
  changed: () => void,
  setTopView: (top: boolean) => void,
): GUI {
  const vf = gui.addFolder('View');
  vf.add(view, 'trail').onChange(changed);
  vf.add(view, 'trailSeconds', 1, 120, 1).name('trail [s]').onChange(changed);
  vf.add(view, 'sphere').name('sphere of reach').onChange(changed);
  vf.add(view, 'axes').onChange(changed);
  const top = { topView: false };
  vf.add(top, 'topView')
    .name('top view')
    .onChange((v: boolean) => {
      setTopView(v);
      changed();
    });
  vf.add(view, 'stereo', [...STEREO_MODES])
    .name('stereo')
    .onChange(changed).domElement.title =
    'anaglyph: red–cyan glasses; side by side: a stereo viewer (three.js AnaglyphEffect / StereoEffect)';
  vf.close();

  const vec = gui.addFolder('Vectors');
  for (const [name, [label, title]] of Object.entries(VECTOR_LABELS) as [VectorName, [string, string]][]) {
    const c = vec.add(view, name).name(label).onChange(changed);
    c.domElement.title = title;
    c.domElement.dataset['vector'] = name;
  }
  for (const axis of ['X', 'Y', 'Z'] as const) {
    const key = `origin${axis}` as const;
    vec
      .add(view, key, -5, 5, 0.01)
      .name(`origin ${axis.toLowerCase()} [m]`)
      .onChange(changed).domElement.title = 'origin of L and τ relative to the pivot (0: the pivot)';
  }
  vec.close();
  return vf;
}
