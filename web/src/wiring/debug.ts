// window.pendulab: the lab's handles for debugging, profiling and the end-to-end tests
// (tests/e2e/*.mjs). Positions on the page in CSS pixels, separations in metres, energies in joules,
// times in simulated seconds, video sizes in bytes.
import type { Command } from '../protocol';
import type { RenderQuality } from '../scene/quality';
import type { ReleasedPull } from '../scene/drag';
import type { EngineKind } from '../engine';
import type { EnergySplit } from '../measure';
import type { LabStore } from '../state';

export interface LabHandles {
  store: LabStore;
  drawn: () => number;
  send: (cmd: Command) => void;
  screenshot: () => string;
  bobOnScreen: () => { x: number; y: number } | null;
  handleOnScreen: () => { x: number; y: number } | null;
  /** The last pull of the velocity arrow as released: pointer and arrow tip on the page with the camera of
   *  that instant, and the velocity [m/s] handed on (scene/drag.ts). */
  lastPull: () => ReleasedPull | null;
  /** The velocity handle's position [m, world] and the arrow scale [m per m/s] it was drawn with. */
  handleAt: () => { at: [number, number, number]; scale: number } | null;
  quality: () => RenderQuality;
  frameCosts: () => Record<string, { ms: number; count: number }>;
  /** The second pendulum's store (two-pendulum mode) and where its bob is drawn on the page. */
  twin: LabStore;
  twinOnScreen: () => { x: number; y: number } | null;
  /** Pendulums 3 and 4 (panels/extras.ts): their stores and where their bobs are drawn on the page. */
  extras: () => LabStore[];
  extrasOnScreen: () => { x: number; y: number }[];
  /** Where the ruler's and the protractor's centres are drawn on the page (null: not shown). */
  instrumentsOnScreen: () => { ruler: { x: number; y: number } | null; protractor: { x: number; y: number } | null };
  /** Tones the sonification played (a tone per lowest point while the sound is on). */
  tones: () => number;
  sphereOnScreen: () => { left: number; right: number; top: number; bottom: number };
  /** The separation of the two bobs, |r₁ − r₂| [m] at the first one's history times [s]. */
  separation: () => { t: number[]; d: number[] };
  /** The energies the bar chart shows (J). */
  energy: () => EnergySplit | null;
  /** The last recorded video's size [bytes] and its first bytes (hex), once a recording stopped. */
  lastVideo: () => { size: number; head: string } | null;
  /** The live plots' y scales (key, distribution — 3 is log —, range). */
  plotScales: () => { key: string; distr: number; min: number | null; max: number | null }[];
  /** The number of points of a fitted data file's measured path drawn in the scene (0: none). */
  measuredPoints: () => number;
  /** Where the physics runs: "wasm" (in this page, docs/lab.md) or "server" (`pendulab serve`). */
  engine: () => EngineKind;
}

declare global {
  interface Window {
    /** For debugging, profiling and end-to-end tests: the store, frames drawn, a command sender, a
     *  screenshot, the bob's and the velocity handle's positions on the page, the drawing quality chosen
     *  for the WebGL renderer, and the mean milliseconds per part of the frame since the last call
     *  (tests/e2e/profile.mjs). */
    pendulab?: LabHandles;
  }
}

/** Marks a step of the start-up in the browser's performance timeline (`pendulab:<step>`; ms since the
 *  navigation began): each step once; the end-to-end test reads them to say where the time to the first frame goes. */
export function mark(step: string): void {
  if (marked.has(step)) return;
  marked.add(step);
  performance.mark(`pendulab:${step}`);
}
const marked = new Set<string>();
