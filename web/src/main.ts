// Wires the lab together: the store (state.ts) receives from the connection; the scene and panels draw
// from the store; controls send commands. Nothing here integrates: the server's core does all physics.
import 'uplot/dist/uPlot.min.css';
import './style.css';
import { Connection, socketUrl } from './connection';
import { DataPanel } from './panels/data';
import { Controls } from './panels/controls';
import { Plots } from './panels/plots';
import { Portraits } from './panels/portraits';
import { Analyses, getJSON } from './analyses';
import type { Command, ScenarioInfo, Schema, Status, Vec3 } from './protocol';
import { eventMessage } from './events';
import { ReducedView } from './scene/reduced';
import { throttle } from './panels/params';
import { PendulumScene, DEFAULT_VIEW } from './scene/scene';
import type { RenderQuality } from './scene/quality';
import { probeRenderer, renderQuality } from './scene/quality';
import { ChangeGate, FrameCosts, RateLimiter } from './perf';
import { gravityDirection } from './scene/vectors';
import { scenarioRequest } from './export';
import { LabStore } from './state';
import { commandsFor, decodeUrl, encodeUrl, fromStatus } from './url';

declare global {
  interface Window {
    /** For debugging, profiling and end-to-end tests: the store, frames drawn, a command sender, a
     *  screenshot, the bob's and the velocity handle's positions on the page, the drawing quality chosen
     *  for the WebGL renderer, and the mean milliseconds per part of the frame since the last call
     *  (tests/e2e/profile.mjs). */
    pendulab?: {
      store: LabStore;
      drawn: () => number;
      send: (cmd: Command) => void;
      screenshot: () => string;
      bobOnScreen: () => { x: number; y: number } | null;
      handleOnScreen: () => { x: number; y: number } | null;
      quality: () => RenderQuality;
      frameCosts: () => Record<string, { ms: number; count: number }>;
    };
  }
}

function byId(id: string): HTMLElement {
  const el = document.getElementById(id);
  if (el === null) throw new Error(`#${id} missing from index.html`);
  return el;
}

function download(name: string, href: string): void {
  const a = document.createElement('a');
  a.href = href;
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
}

async function main(): Promise<void> {
  const store = new LabStore();
  const message = byId('message');
  let messageTimer: ReturnType<typeof setTimeout> | null = null;
  /** Shows `text` in the message line for 6 s: a problem (red) or, with `info`, news (blue). */
  const explain = (text: string, info = false) => {
    message.textContent = text;
    message.classList.toggle('info', info);
    message.classList.add('shown');
    if (messageTimer !== null) clearTimeout(messageTimer);
    messageTimer = setTimeout(() => message.classList.remove('shown'), 6000);
  };

  const [schema, scenarios] = await Promise.all([
    getJSON<Schema>('api/schema'),
    getJSON<ScenarioInfo[]>('api/scenarios'),
  ]);
  store.tickHz = schema.tick_hz;

  // a software rasteriser (headless chromium, no GPU) draws without MSAA at one pixel per CSS pixel
  const quality = renderQuality(probeRenderer(), window.devicePixelRatio);
  if (quality.software) {
    byId('render').textContent = ' · software WebGL: no antialiasing';
    byId('render').title = `${quality.renderer ?? ''}: drawn without multisampling for the frame rate`;
  }
  const scene = new PendulumScene(byId('scene'), quality);
  const view = { ...DEFAULT_VIEW };
  const costs = new FrameCosts();
  const plots = new Plots(byId('plots'), (ms) => costs.add('plots drawn (uPlot)', ms));
  const portraits = new Portraits(byId('portraits'));
  const reduced = new ReducedView(byId('reduced'), quality);
  const data = new DataPanel(byId('data'));

  const fromUrl = decodeUrl(window.location.search);
  if (fromUrl.problems.length > 0) explain(`link: ${fromUrl.problems.join('; ')}`);
  let startup: Command[] = commandsFor(fromUrl.value);
  let conn: Connection | null = null;
  const send = (cmd: Command) => {
    if (conn === null || !conn.send(cmd)) explain('not connected to the server');
  };

  const controls = new Controls(byId('gui'), schema, scenarios, view, {
    send,
    explain,
    downloadCSV: () => {
      const blob = new Blob([store.toCSV()], { type: 'text/csv' });
      const url = URL.createObjectURL(blob);
      download(`pendulab-${store.status?.scenario ?? 'lab'}.csv`, url);
      setTimeout(() => URL.revokeObjectURL(url), 10_000);
    },
    downloadTOML: () => {
      const s = store.status;
      if (s === null) return explain('not connected to the server');
      fetch('api/scenario.toml', {
        method: 'POST',
        headers: { 'content-type': 'application/json' },
        body: JSON.stringify(scenarioRequest(s)),
      })
        .then(async (r) => {
          if (!r.ok) throw new Error(((await r.json()) as { detail?: string }).detail ?? `HTTP ${r.status}`);
          const url = URL.createObjectURL(await r.blob());
          download(`pendulab-${s.scenario ?? 'lab'}.toml`, url);
          setTimeout(() => URL.revokeObjectURL(url), 10_000);
        })
        .catch((e: unknown) => explain(`scenario download: ${e instanceof Error ? e.message : String(e)}`));
    },
    screenshot: () => download(`pendulab-${store.status?.scenario ?? 'lab'}.png`, scene.screenshot()),
    copyLink: () => {
      const link = window.location.href;
      navigator.clipboard?.writeText(link).then(
        () => explain('link copied: it reproduces this scenario', true),
        () => explain(link),
      ) ?? explain(link);
    },
    viewChanged: (v, top) => {
      scene.setTopView(top);
      scene.setStereo(v.stereo);
    },
  });

  const analyses = new Analyses(store, reduced, explain);

  const onStatus = (s: Status) => {
    store.onStatus(s);
    controls.sync(s);
    scene.setLength(s.params.length);
    scene.setModel(s.model);
    portraits.setModel(s.model);
    if (startup.length === 0) window.history.replaceState(null, '', `?${encodeUrl(fromStatus(s))}`);
  };

  conn = new Connection(socketUrl(window.location), {
    onOpen: () => {
      store.setConnected(true);
      byId('conn').textContent = 'connected';
    },
    onClose: () => {
      store.setConnected(false);
      byId('conn').textContent = 'disconnected: retrying…';
      // a new server session starts from the default scenario: bring back the one shown
      if (store.status !== null) startup = commandsFor(fromStatus(store.status));
    },
    onFrames: (frames) => {
      const t0 = performance.now();
      store.onFrames(frames);
      analyses.onFrames();
      costs.add('frames received', performance.now() - t0);
    },
    onNotice: (n) => {
      if (n.type === 'error') {
        store.onError(n);
        explain(n.command ? `${n.command}: ${n.message}` : n.message);
        return;
      }
      if (n.type === 'event') {
        store.onEvent(n);
        explain(eventMessage(n), true);
        return;
      }
      onStatus(n);
      if (startup.length > 0) {
        const cmds = startup;
        startup = [];
        for (const c of cmds) send(c);
      }
    },
    onProtocolError: (msg) => explain(`protocol: ${msg}`),
  });

  let drawn = 0;
  // dragging the bob: pause, then the start follows the pointer (at rest there); pulling the velocity
  // arrow: pause, then the start velocity follows it (x kept). One throttle for both, so a late send of
  // one gesture never lands after the next; the server checks (and projects) every state.
  const sendStart = throttle((x: Vec3, v: Vec3) => {
    send({ type: 'set_state', x, v, project: true });
  }, 50);
  const pauseForGesture = () => {
    if (store.status?.paused === false) send({ type: 'pause' });
  };
  scene.enableDrag(
    (x, phase) => {
      if (phase === 'start') pauseForGesture();
      sendStart(x, [0, 0, 0]);
      if (phase === 'end') explain('start set by dragging (at rest there): press start to release it', true);
    },
    (x, pulled, phase) => {
      if (phase === 'start') {
        pauseForGesture();
        explain('pull the arrow to set the start velocity', true);
        return;
      }
      if (pulled === null) return;
      sendStart(x, pulled.v);
      const cap = pulled.capped ? ' (capped: the most the arrow sets, 4√(g l))' : '';
      explain(
        phase === 'end'
          ? `start velocity set: |v| = ${pulled.speed.toFixed(2)} m/s${cap}; press start to run from it`
          : `start velocity |v| = ${pulled.speed.toFixed(2)} m/s${cap}`,
        true,
      );
    },
  );
  window.pendulab = {
    store,
    drawn: () => drawn,
    send,
    screenshot: () => scene.screenshot(),
    bobOnScreen: () => scene.bobOnScreen(),
    handleOnScreen: () => scene.handleOnScreen(),
    quality: () => quality,
    frameCosts: () => costs.take(),
  };
  let lastWall = performance.now();
  // the scene follows every frame; the panels (numbers, plots, portraits) at 10 Hz, which reads as live
  // and spares the CPU: each uPlot setData redraws a whole chart (docs/performance.md)
  const panelTick = new RateLimiter(100);
  // the scene is rendered when what it shows changed (a paused lab draws nothing until the camera moves)
  const sceneInputs = new ChangeGate();
  const frame = (now: number) => {
    const dt = (now - lastWall) / 1000;
    lastWall = now;
    let t0 = performance.now();
    store.advancePlayhead(dt);
    const f = store.displayed();
    const p = store.status?.params;
    const gdir = gravityDirection(store.status?.model_params);
    const { start, end } = store.trailRange(view.trailSeconds);
    const mass = p?.mass ?? 1;
    const g = p?.g ?? 9.81;
    const changed = sceneInputs.changed([f, store.trail, start, end, mass, g, ...gdir, ...Object.values(view)]);
    if (changed) scene.update(f, { frames: store.trail, start, end }, view, mass, g, gdir);
    let t1 = performance.now();
    costs.add('scene update', t1 - t0);
    if (scene.draw(changed)) {
      drawn++;
      t0 = performance.now();
      costs.add('scene render (submit)', t0 - t1);
    } else t0 = t1;
    if (panelTick.due(now)) {
      plots.update(store.history, store.events);
      t1 = performance.now();
      costs.add('plots setData', t1 - t0);
      portraits.update(store.history, f, analyses.veff, p?.mass ?? 1, p?.g ?? 9.81, p?.length ?? 1);
      portraits.updateEM(analyses.em, f);
      t0 = performance.now();
      costs.add('portraits', t0 - t1);
      reduced.update(f, p?.length ?? 1);
      t1 = performance.now();
      costs.add('reduced view', t1 - t0);
      data.update(f, store);
      costs.add('data panel', performance.now() - t1);
    }
    requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);
}

main().catch((e: unknown) => {
  const el = document.getElementById('message');
  if (el) {
    el.textContent = `the lab could not start: ${e instanceof Error ? e.message : String(e)}`;
    el.classList.add('shown');
  }
  console.error(e);
});
