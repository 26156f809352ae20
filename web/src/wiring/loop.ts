// The drawing loop (docs/performance.md): the scene follows every animation frame, but is rendered only
// when what it shows changed (a paused lab draws nothing until the camera moves); the panels (numbers,
// plots, portraits) redraw at 10 Hz, which reads as live and spares the CPU. Times: wall clock in ms
// for the costs, simulated seconds [s] for the playhead and trails; mass kg, g m/s², length m.
import type { Analyses } from '../analyses';
import { describeMotion } from '../describe';
import { energySplit } from '../measure';
import { ChangeGate, RateLimiter } from '../perf';
import type { FrameCosts } from '../perf';
import type { ChosenPlot } from '../panels/chosen';
import type { DataPanel } from '../panels/data';
import type { EnergyBars } from '../panels/energy';
import { driftScales } from '../panels/plots';
import type { Plots } from '../panels/plots';
import type { Portraits } from '../panels/portraits';
import type { Tools } from '../panels/tools';
import type { ReducedView } from '../scene/reduced';
import { gravityDirection } from '../scene/vectors';
import { byId } from './page';
import type { SharedLink } from './link';
import type { LabCore } from './session';
import { mark } from './debug';

/** Everything the loop draws besides the scene. */
export interface DrawnPanels {
  plots: Plots;
  chosen: ChosenPlot;
  portraits: Portraits;
  reduced: ReducedView;
  data: DataPanel;
  energy: EnergyBars;
  tools: Tools;
  analyses: Analyses;
}

/** Physical parameters of the shown run (defaults before the first status). */
function params(lab: LabCore): { mass: number; g: number; length: number } {
  const p = lab.store.status?.params;
  return { mass: p?.mass ?? 1, g: p?.g ?? 9.81, length: p?.length ?? 1 };
}

/** Updates the scene (and the second pendulum) if its inputs changed; true if it then drew. */
function drawScene(lab: LabCore, gate: ChangeGate, costs: FrameCosts): boolean {
  const { store, scene, view, session } = lab;
  const t0 = performance.now();
  const f = store.displayed();
  const { mass, g } = params(lab);
  const gdir = gravityDirection(store.status?.model_params);
  const { start, end } = store.trailRange(view.trailSeconds);
  const twin = session.twin;
  const second = twin?.drawn(store.playT, view.trailSeconds) ?? null;
  scene.setTwinLayout(twin?.layout() ?? null);
  scene.setExtras(twin?.extraLayouts() ?? []);
  const more = twin?.drawnExtras(store.playT, view.trailSeconds) ?? [];
  const inputs = [f, store.trail, start, end, mass, g, ...gdir, ...Object.values(view), second?.frame ?? null, second?.trail.end ?? 0, ...more.map((m) => m.frame)];
  const changed = gate.changed(inputs);
  if (changed) {
    scene.update(f, { frames: store.trail, start, end }, view, mass, g, gdir);
    scene.updateTwin(second?.frame ?? null, second?.trail ?? { frames: [], start: 0, end: 0 });
    scene.updateExtras(more);
  }
  const t1 = performance.now();
  costs.add('scene update', t1 - t0);
  const drew = scene.draw(changed);
  if (drew) costs.add('scene render (submit)', performance.now() - t1);
  return drew;
}

/** The 10 Hz part: plots, portraits, reduced view, energy bars, then the text (tools, description, data
 *  panel) and the URL. What reads the layout (the panels' widths) runs before what writes text into the
 *  page: a read after a write forces a layout in the middle of the frame, which it did every tick
 *  (docs/performance.md, "The one-file lab in the browser"). */
function drawPanels(lab: LabCore, panels: DrawnPanels, link: SharedLink, costs: FrameCosts, now: number): void {
  const { store, session } = lab;
  const f = store.displayed();
  const { mass, g, length } = params(lab);
  const twin = session.twin;
  let t0 = performance.now();
  const ref = store.reference;
  panels.plots.update(store.history, store.events, driftScales(ref?.energy ?? 0, ref?.j3 ?? 0, mass, g, length));
  panels.chosen.update(store.history.frames, { mass, g, length }, twin?.on ? twin.store.history.frames : null);
  twin?.update(byId('plots').clientWidth - 8);
  let t1 = performance.now();
  costs.add('plots setData', t1 - t0);
  panels.portraits.update(store.history, f, panels.analyses.veff, mass, g, length);
  panels.portraits.updateEM(panels.analyses.em, f);
  t0 = performance.now();
  costs.add('portraits', t0 - t1);
  panels.reduced.update(f, length);
  t1 = performance.now();
  costs.add('reduced view', t1 - t0);
  const latest = store.latest();
  const split = latest ? energySplit(latest, mass, g, length, store.work) : null;
  panels.energy.draw(split, store.status?.model !== 'ideal');
  t0 = performance.now();
  costs.add('energy bars', t0 - t1);
  panels.tools.update(f?.x ?? null, f?.t ?? null, f ? Math.hypot(...f.v) : 0);
  panels.tools.describe(describeMotion(f, split), now);
  link.write();
  t1 = performance.now();
  costs.add('tools and link', t1 - t0);
  panels.data.update(f, store);
  costs.add('data panel', performance.now() - t1);
}

/** Starts the loop; returns the number of scene renders so far (for the tests). */
export function startLoop(lab: LabCore, panels: DrawnPanels, link: SharedLink, costs: FrameCosts): () => number {
  let drawn = 0;
  let lastWall = performance.now();
  const panelTick = new RateLimiter(100);
  const gate = new ChangeGate();
  const frame = (now: number) => {
    mark('loop');
    lab.store.advancePlayhead((now - lastWall) / 1000, lab.session.twin?.newest() ?? null);
    lastWall = now;
    if (drawScene(lab, gate, costs)) {
      drawn++;
      mark('first render');
      if (lab.store.frames.length > 0) mark('first frame drawn');
    }
    if (panelTick.due(now)) {
      drawPanels(lab, panels, link, costs, now);
      mark('panels drawn');
    }
    requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);
  return () => drawn;
}
