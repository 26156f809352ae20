// The view's options (docs/web.md, "View"): what the scene draws — trail, sphere of reach, axes, the vectors
// (vectors.ts) and where the angular momentum and the torque are taken about [m], stereo, the ruler and the
// protractor and where they were moved to [rod lengths], presentation mode and the simple view — their
// defaults, and the vector arrows' colours (the legend). Plain data: share links (wiring/link.ts), the
// panel (panels/view.ts) and the scene (scene.ts) read it.
import type { VectorName } from './vectors';

export interface ViewOptions extends Record<VectorName, boolean> {
  trail: boolean;
  trailSeconds: number;
  sphere: boolean;
  axes: boolean;
  /** Origin of the angular momentum and the torque, relative to the pivot [m]. */
  originX: number;
  originY: number;
  originZ: number;
  /** Stereo: off, red–cyan anaglyph (colour masks: anaglyph.ts) or side by side for a viewer (StereoEffect). */
  stereo: Stereo;
  /** The ruler and the protractor (instruments.ts). */
  ruler: boolean;
  protractor: boolean;
  /** Where the ruler and the protractor were moved to, in rod lengths from their places (issue 28: movable):
   *  the ruler sideways (to the camera's right) and up, the protractor along its dial's plane and up. */
  rulerShift: number;
  rulerLift: number;
  protractorShift: number;
  protractorLift: number;
  /** Presentation mode: large type in the panel (the page's; kept here so that a link carries it). */
  present: boolean;
  /** The simple view: the classroom tools only (docs/web.md, "Simple view"); the default (issue 28: "a simple
   *  view with PhET-level tools first"), the advanced layer one click away (wiring/toolbar.ts remembers it). */
  simple: boolean;
}

export const STEREO_MODES = ['off', 'anaglyph', 'side by side'] as const;
export type Stereo = (typeof STEREO_MODES)[number];

export const DEFAULT_VIEW: ViewOptions = {
  trail: true,
  trailSeconds: 10,
  sphere: true,
  axes: true,
  velocity: true,
  momentum: false,
  gravity: false,
  tension: false,
  net: false,
  angularMomentum: false,
  torque: false,
  originX: 0,
  originY: 0,
  originZ: 0,
  stereo: 'off',
  ruler: false,
  protractor: false,
  rulerShift: 0,
  rulerLift: 0,
  protractorShift: 0,
  protractorLift: 0,
  present: false,
  simple: true,
};

/** Arrow colours (the legend in docs/web.md). */
export const ARROW_COLORS: Record<VectorName, number> = {
  velocity: 0xe07bff,
  momentum: 0x9b8cff,
  gravity: 0xffb347,
  tension: 0xff5d73,
  net: 0xffffff,
  angularMomentum: 0x4dd9c0,
  torque: 0xffe14d,
};
