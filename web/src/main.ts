// Wires the lab together: the store (state.ts) receives from the connection; the scene and panels draw
// from the store; controls send commands. Nothing here integrates: the server's core does all physics.
// The wiring itself is in wiring/ (one module per part: page, link, session, toolbar, keys, tools,
// controls, connect, gestures, loop, debug); this file only builds the parts in order.
import 'uplot/dist/uPlot.min.css';
import './style.css';
import { socketUrl } from './connection';
import { DataPanel } from './panels/data';
import { Plots } from './panels/plots';
import { Portraits } from './panels/portraits';
import { Analyses, getJSON } from './analyses';
import type { ScenarioInfo, Schema } from './protocol';
import { ReducedView } from './scene/reduced';
import { PendulumScene } from './scene/scene';
import { DEFAULT_VIEW } from './scene/options';
import { probeRenderer, renderQuality } from './scene/quality';
import type { RenderQuality } from './scene/quality';
import { FrameCosts } from './perf';
import { LabStore } from './state';
import { t } from './i18n';
import { EnergyBars } from './panels/energy';
import { ChosenPlot } from './panels/chosen';
import { TwinPanel } from './panels/twin';
import { ExtraPendulums } from './panels/extras';
import { Glossary } from './panels/glossary';
import { accessibleSliders } from './keyboard';
import { installEngine } from './engine';
import type { EngineKind } from './engine';
import { byId, MessageLine, setUpPage } from './wiring/page';
import { SharedLink } from './wiring/link';
import { Session } from './wiring/session';
import type { LabCore } from './wiring/session';
import { rememberedSimple, wireToolbar } from './wiring/toolbar';
import { wireKeys } from './wiring/keys';
import { wireTools } from './wiring/tools';
import { wireControls } from './wiring/controls';
import { connect, openEarly } from './wiring/connect';
import { wireGestures } from './wiring/gestures';
import { startLoop } from './wiring/loop';
import type { DrawnPanels } from './wiring/loop';
import type { LabHandles } from './wiring/debug';
import { mark } from './wiring/debug';
import { CraneMode } from './crane';

/** The 3-D view with the drawing quality this machine allows (a software rasteriser — headless
 *  chromium, no GPU — draws without MSAA at one pixel per CSS pixel, and the footer says so). */
function makeScene(quality: RenderQuality): PendulumScene {
  if (quality.software) {
    byId('render').textContent = ` · ${t('page.software')}`;
    byId('render').title = t('page.softwareHelp', { renderer: quality.renderer ?? '' });
  }
  const scene = new PendulumScene(byId('scene'), quality);
  scene.renderer.domElement.setAttribute('role', 'img');
  scene.renderer.domElement.setAttribute('aria-label', t('page.scene'));
  return scene;
}

/** The handles window.pendulab gives tests and profiling (wiring/debug.ts). */
function handles(lab: LabCore, p: DrawnPanels, quality: RenderQuality, costs: FrameCosts, engine: EngineKind, more: Pick<LabHandles, 'drawn' | 'lastVideo' | 'twin'>): LabHandles {
  const { store, scene, session } = lab;
  return {
    ...more,
    store,
    send: session.send,
    screenshot: () => scene.screenshot(),
    bobOnScreen: () => scene.bobOnScreen(),
    handleOnScreen: () => scene.handleOnScreen(),
    lastPull: () => scene.lastPull(),
    handleAt: () => scene.handleAt(),
    quality: () => quality,
    frameCosts: () => costs.take(),
    twinOnScreen: () => scene.twinOnScreen(),
    extras: () => session.twin?.extras?.running() ?? [],
    extrasOnScreen: () => scene.extrasOnScreen(),
    instrumentsOnScreen: () => scene.instrumentsOnScreen(),
    tones: () => p.tools.tones,
    sphereOnScreen: () => scene.sphereOnScreen(),
    separation: () => session.twin?.separationNow() ?? { t: [], d: [] },
    energy: () => p.energy.shown,
    plotScales: () => p.plots.scales(),
    measuredPoints: () => scene.measuredPoints(),
    engine: () => engine,
  };
}

async function main(): Promise<void> {
  mark('start');
  const engine = await installEngine(); // the one-file lab: the core in a Web Worker (docs/lab.md)
  const early = openEarly(); // the socket's handshake overlaps building the page (wiring/connect.ts)
  setUpPage();
  const store = new LabStore();
  const messages = new MessageLine(byId('message'));
  const explain = messages.explain;
  const [schema, scenarios] = await Promise.all([getJSON<Schema>('api/schema'), getJSON<ScenarioInfo[]>('api/scenarios')]);
  store.tickHz = schema.tick_hz;
  mark('schema');
  const quality = renderQuality(probeRenderer(), window.devicePixelRatio);
  const scene = makeScene(quality);
  mark('scene');
  const costs = new FrameCosts();
  const chosen = new ChosenPlot(byId('plots'));
  const plots = new Plots(byId('plots'), (ms) => costs.add('plots drawn (uPlot)', ms));
  const portraits = new Portraits(byId('portraits'));
  const reduced = new ReducedView(byId('reduced'), quality);
  const data = new DataPanel(byId('data'));
  // the simple view first (issue 28), unless this device chose the advanced one; a link may say either
  const view = { ...DEFAULT_VIEW, simple: rememberedSimple(DEFAULT_VIEW.simple) };
  const link = new SharedLink(store, view, explain); // a shared link's view options, scenario and second pendulum
  const session = new Session(store, explain);
  session.conn = early.conn;
  const lab: LabCore = { store, scene, view, session, explain };
  const { toolbar, help, lastVideo } = wireToolbar(lab);
  const tools = wireTools(lab);
  wireKeys(lab, help, tools);
  const energy = new EnergyBars(byId('energy'));
  const controls = wireControls(lab, schema, scenarios, link);
  scene.setStereo(view.stereo);
  const analyses = new Analyses(store, reduced, explain);
  const twin = new TwinPanel(byId('tools'), store, schema.methods, socketUrl(window.location), { send: session.send, explain });
  session.twin = twin;
  twin.extras = new ExtraPendulums(byId('tools'), socketUrl(window.location), explain);
  link.attach(chosen, twin);
  new Glossary(byId('tools'));
  new CraneMode(lab, byId('tools')); // the crane mode: panel, drawing, keys J L I K (crane/)
  accessibleSliders(controls.gui);
  mark('panels');
  connect(lab, early.held, { controls, tools, toolbar, portraits, energy }, messages, link, analyses, costs);
  wireGestures(lab);
  const panels: DrawnPanels = { plots, chosen, portraits, reduced, data, energy, tools, analyses };
  let drawn = () => 0;
  window.pendulab = handles(lab, panels, quality, costs, engine, { drawn: () => drawn(), lastVideo, twin: twin.store });
  drawn = startLoop(lab, panels, link, costs);
}

main().catch((e: unknown) => {
  const el = document.getElementById('offline');
  if (el) {
    el.textContent = `${t('conn.noStart')} ${e instanceof Error ? e.message : String(e)}`;
    el.hidden = false;
  }
  console.error(e);
});
