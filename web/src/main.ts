// Wires the lab together: the store (state.ts) receives from the connection; the scene and panels draw
// from the store; controls send commands. Nothing here integrates: the server's core does all physics.
import 'uplot/dist/uPlot.min.css';
import './style.css';
import { Connection, socketUrl, whenCaughtUp } from './connection';
import { DataPanel } from './panels/data';
import { Controls } from './panels/controls';
import { Plots } from './panels/plots';
import { Portraits } from './panels/portraits';
import { Analyses, computationsIdle, getJSON } from './analyses';
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
import { commandsFor, decodeUrl, encodeUrl, encodeView, fromStatus, linkContents } from './url';
import type { UrlScenario } from './url';
import { STEREO_MODES } from './scene/scene';
import { language } from './i18n';
import { chooseLanguage, setLanguage, t } from './i18n';
import { Toolbar } from './panels/toolbar';
import { Tools } from './panels/tools';
import { EnergyBars } from './panels/energy';
import { ChosenPlot } from './panels/chosen';
import { TwinPanel } from './panels/twin';
import { HelpOverlay } from './panels/help';
import { driftScales } from './panels/plots';
import { Recorder } from './record';
import { accessibleSliders, ownsKeys, shortcutFor, viewKey } from './keyboard';
import { describeMotion } from './describe';
import { initAdvanced } from './advanced';
import { Glossary } from './panels/glossary';
import { DEG, sphericalAngles } from './measure';
import { energySplit } from './measure';
import { FitDataPanel } from './panels/fitdata';
import { loadCommands } from './fitdata';
import type { EnergySplit } from './measure';
import type { EngineKind } from './engine';
import { installEngine } from './engine';

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
      /** The second pendulum's store (two-pendulum mode) and where its bob is drawn on the page. */
      twin: LabStore;
      twinOnScreen: () => { x: number; y: number } | null;
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
  const engine = await installEngine(); // the one-file lab: the core in a Web Worker (docs/lab.md)
  const lang = chooseLanguage(
    new URLSearchParams(window.location.search).get('lang'),
    window.localStorage?.getItem('pendulab.lang') ?? null,
    navigator.languages ?? [navigator.language],
  );
  setLanguage(lang);
  document.documentElement.lang = lang;
  initAdvanced();
  document.title = t('page.title');
  byId('page-title').textContent = t('page.title');
  byId('units').textContent = t('page.units');
  byId('scene').setAttribute('aria-label', t('page.scene'));
  byId('panel').setAttribute('aria-label', t('page.panel'));
  byId('panel-title').textContent = t('page.panel');
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
    byId('render').textContent = ` · ${t('page.software')}`;
    byId('render').title = t('page.softwareHelp', { renderer: quality.renderer ?? '' });
  }
  const scene = new PendulumScene(byId('scene'), quality);
  scene.renderer.domElement.setAttribute('role', 'img');
  scene.renderer.domElement.setAttribute('aria-label', t('page.scene'));
  const view = { ...DEFAULT_VIEW };
  const costs = new FrameCosts();
  const chosen = new ChosenPlot(byId('plots'));
  const plots = new Plots(byId('plots'), (ms) => costs.add('plots drawn (uPlot)', ms));
  const portraits = new Portraits(byId('portraits'));
  const reduced = new ReducedView(byId('reduced'), quality);
  const data = new DataPanel(byId('data'));

  const fromUrl = decodeUrl(window.location.search);
  // a shared link's view options: only known ones, of the default's type (the stereo mode one of its words)
  for (const [k, v] of Object.entries(fromUrl.value.view ?? {})) {
    const d = (DEFAULT_VIEW as unknown as Record<string, unknown>)[k];
    const ok = d !== undefined && typeof d === typeof v && (k !== 'stereo' || (STEREO_MODES as readonly unknown[]).includes(v));
    if (ok) (view as unknown as Record<string, unknown>)[k] = v;
    else fromUrl.problems.push(`view: ${k} = ${String(v)} is not a view option`);
  }
  if (fromUrl.problems.length > 0) explain(`link: ${fromUrl.problems.join('; ')}`);
  let startup: Command[] = commandsFor(fromUrl.value);
  // with a second pendulum, the paused time's steps wait until both run (they go to both)
  let replay: Command[] = [];
  if (fromUrl.value.twin !== undefined) {
    replay = startup.filter((c) => c.type === 'step');
    startup = startup.filter((c) => c.type !== 'step');
  }
  let conn: Connection | null = null;
  let twin: TwinPanel | null = null;
  const send = (cmd: Command) => {
    if (conn === null || !conn.send(cmd)) explain(t('msg.notConnected'));
    else twin?.mirror(cmd);
  };
  const run = () => send({ type: store.status?.paused === false ? 'pause' : 'resume' });
  const reset = () => send({ type: 'reset' });
  const step = () => send({ type: 'step', n: 1 });
  let lastVideo: { size: number; head: string } | null = null;
  const recorder = new Recorder(scene.renderer.domElement, (video) => {
    void video.slice(0, 4).arrayBuffer().then((b) => {
      lastVideo = { size: video.size, head: [...new Uint8Array(b)].map((x) => x.toString(16).padStart(2, '0')).join('') };
    });
    const url = URL.createObjectURL(video);
    download(`pendulab-${store.status?.scenario ?? 'lab'}.webm`, url);
    setTimeout(() => URL.revokeObjectURL(url), 10_000);
    explain(t('msg.recorded', { mb: (video.size / 1e6).toFixed(1) }), true);
  });
  const help = new HelpOverlay(byId('help'));
  const toolbar = new Toolbar(byId('toolbar'), byId('panel'), {
    run,
    reset,
    step,
    record: () => {
      if (recorder.recording) recorder.stop();
      else {
        const why = recorder.start();
        if (why !== null) explain(t('msg.noRecording', { why }));
        else explain(t('msg.recording'), true);
      }
      toolbar.showRecording(recorder.recording);
    },
    help: () => help.toggle(),
    language: (l) => {
      window.localStorage?.setItem('pendulab.lang', l);
      // The page reloads from its URL, which each status updates: wait (≤ 2 s) until the server has
      // handled every command sent, else one just sent — a resume, a fitted scenario — would be lost (the
      // page came back paused, or with the old scenario, and waited for frames that never came).
      void Promise.all([whenCaughtUp(() => store.status?.commands, () => conn?.sent ?? 0, 2000), computationsIdle(2000)]).then(() => {
        const q = new URLSearchParams(window.location.search);
        q.set('lang', l);
        window.location.search = q.toString();
      });
    },
    collapsed: () => undefined,
    present: (on) => {
      view.present = on;
      document.body.classList.toggle('present', on);
      toolbar.showPresenting(on);
    },
  });
  document.body.classList.toggle('present', view.present);
  toolbar.showPresenting(view.present);
  // the 3-D view by keyboard: focusable, the arrows turn the camera, + − zoom, Shift + ← → the bob's start
  const canvas = scene.renderer.domElement;
  canvas.tabIndex = 0;
  canvas.setAttribute('aria-label', `${t('page.scene')}. ${t('help.camera')}; Shift + ← →: ${t('help.bobKeys')}`);
  canvas.addEventListener('keydown', (e) => {
    const k = viewKey(e.key, e.shiftKey);
    if (k === null || e.ctrlKey || e.metaKey || e.altKey) return;
    e.preventDefault();
    if ('orbit' in k) scene.orbitBy(k.orbit[0], k.orbit[1], k.zoom);
    else {
      const s = store.status;
      if (s === null) return;
      if (!s.paused) send({ type: 'pause' });
      const a = sphericalAngles(s.start.x);
      const theta = Math.min(Math.max(a.theta + k.bob / DEG, 0), Math.PI);
      send({ type: 'set_state', theta, phi: a.phi, theta_dot: 0, phi_dot: 0 });
      explain(t('describe.text', { theta: (theta * DEG).toFixed(0), dir: t('describe.rest'), v: '0.00' }), true);
    }
  });
  document.addEventListener('keydown', (e) => {
    if ((e.key === 'd' || e.key === 'D') && !e.ctrlKey && !e.metaKey && !e.altKey && !ownsKeys(e.target, e.key) && !help.open) {
      const latest = store.latest();
      tools.describe(describeMotion(store.displayed(), latest ? energySplit(latest, store.status?.params.mass ?? 1, store.status?.params.g ?? 9.81, store.status?.params.length ?? 1, store.work) : null), performance.now(), true);
      return;
    }
    const action = shortcutFor(e.key, e.ctrlKey || e.metaKey || e.altKey);
    if (action === null) return;
    if (action === 'close') {
      if (help.open) help.toggle(false);
      return;
    }
    if (ownsKeys(e.target, e.key)) return;
    if (help.open && action !== 'help') return;
    e.preventDefault();
    if (action === 'run') run();
    else if (action === 'reset') reset();
    else if (action === 'step') step();
    else help.toggle();
  });
  const tools = new Tools(byId('tools'), store, {
    send,
    explain,
    overlay: (which, on) => {
      view[which] = on;
    },
    move: (which, by) => {
      const [shift, lift] = which === 'ruler' ? (['rulerShift', 'rulerLift'] as const) : (['protractorShift', 'protractorLift'] as const);
      const round = (v: number) => Math.round(v * 1000) / 1000; // link-friendly numbers
      view[shift] = by === null ? 0 : round(view[shift] + by[0]);
      view[lift] = by === null ? 0 : round(view[lift] + by[1]);
      view[which] = true;
      tools.showOverlay(which, true);
    },
  });
  const energy = new EnergyBars(byId('energy'));
  // a measured data file fitted by the server: its scenario loaded like a shared link, its path drawn
  new FitDataPanel(byId('tools'), {
    loaded: (answer, name) => {
      scene.setMeasured(answer.measured?.x ?? null);
      if (answer.lab !== null) for (const c of loadCommands(answer.lab)) send(c);
      explain(t('fit.loaded', { name }), true);
    },
    cleared: () => scene.setMeasured(null),
    explain,
  });

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
      if (s === null) return explain(t('msg.notConnected'));
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
      writeUrl();
      const link = window.location.href;
      const what = linkContents(lab());
      navigator.clipboard?.writeText(link).then(
        () => explain(t('msg.linkCopied', { what }), true),
        () => explain(`${link} — ${what}`, true),
      ) ?? explain(`${link} — ${what}`, true);
    },
    viewChanged: (v, top) => {
      scene.setTopView(top);
      scene.setStereo(v.stereo);
    },
  });

  // the whole lab in the URL (docs/web.md, "Share and export"): the server's status, the view options that
  // differ from the defaults, the chosen plot, the second pendulum, the language
  const lab = (): UrlScenario => {
    const s = store.status;
    const u: UrlScenario = s === null ? {} : fromStatus(s);
    u.view = encodeView(view as unknown as Record<string, boolean | number | string>, DEFAULT_VIEW as unknown as Record<string, boolean | number | string>);
    if (chosen.choice.x !== 't' || chosen.choice.y !== 'theta') u.plot = [chosen.choice.x, chosen.choice.y];
    if (twin?.on && twin.options.mode !== 'off') u.twin = { ...twin.options };
    u.lang = language();
    return u;
  };
  const writeUrl = () => {
    if (startup.length > 0 || store.status === null) return;
    const q = `?${encodeUrl(lab())}`;
    if (q !== window.location.search) window.history.replaceState(null, '', q);
  };
  if (fromUrl.value.plot) chosen.choose(...fromUrl.value.plot);
  tools.showOverlay('ruler', view.ruler);
  tools.showOverlay('protractor', view.protractor);
  scene.setStereo(view.stereo);
  let twinToRestore = fromUrl.value.twin ?? null;
  const analyses = new Analyses(store, reduced, explain);
  twin = new TwinPanel(byId('tools'), store, schema.methods, socketUrl(window.location), { send, explain });
  new Glossary(byId('tools'));
  accessibleSliders(controls.gui);

  const onStatus = (s: Status) => {
    const before = store.status;
    store.onStatus(s);
    if (before !== null && (before.scenario !== s.scenario || before.model !== s.model)) {
      // the previous scenario's news (a string event, a hint) is no longer about what is shown
      if (message.classList.contains('info')) message.classList.remove('shown');
    }
    if (before === null || before.epoch !== s.epoch) energy.rescale();
    controls.sync(s);
    accessibleSliders(controls.gui);
    tools.sync(s);
    toolbar.showRunning(s.paused);
    scene.setLength(s.params.length);
    scene.setModel(s.model);
    portraits.setModel(s.model);
    writeUrl();
  };

  conn = new Connection(socketUrl(window.location), {
    onOpen: () => {
      store.setConnected(true);
      byId('conn').textContent = t('conn.connected');
      byId('offline').hidden = true;
    },
    onClose: () => {
      store.setConnected(false);
      byId('conn').textContent = t('conn.retrying');
      // the server is gone: an unmistakable banner above the view (the footer's grey text was all before)
      byId('offline').textContent = t('conn.gone');
      byId('offline').hidden = false;
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
      // a shared link's second pendulum: a copy of the first once the server has the link's scenario
      if (twinToRestore !== null) {
        const o = twinToRestore;
        twinToRestore = null;
        void whenCaughtUp(() => store.status?.commands, () => conn?.sent ?? 0, 5000)
          .then(() => {
            twin?.restore(o);
            return whenCaughtUp(() => (twin?.store.status?.paused ? 1 : undefined), () => 1, 5000);
          })
          .then(() => {
            for (const c of replay) send(c);
            replay = [];
          });
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
      if (phase === 'end') explain(t('msg.dragged'), true);
    },
    (x, pulled, phase) => {
      if (phase === 'start') {
        pauseForGesture();
        explain(t('msg.pull'), true);
        return;
      }
      if (pulled === null) return;
      sendStart(x, pulled.v);
      const cap = pulled.capped ? t('msg.capped') : '';
      explain(
        phase === 'end'
          ? t('msg.velocitySet', { v: pulled.speed.toFixed(2), cap })
          : t('msg.velocity', { v: pulled.speed.toFixed(2), cap }),
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
    twin: twin.store,
    twinOnScreen: () => scene.twinOnScreen(),
    instrumentsOnScreen: () => scene.instrumentsOnScreen(),
    tones: () => tools.tones,
    sphereOnScreen: () => scene.sphereOnScreen(),
    separation: () => twin?.separationNow() ?? { t: [], d: [] },
    energy: () => energy.shown,
    lastVideo: () => lastVideo,
    plotScales: () => plots.scales(),
    measuredPoints: () => scene.measuredPoints(),
    engine: () => engine,
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
    const second = twin?.drawn(store.playT, view.trailSeconds) ?? null;
    scene.setTwinLayout(twin?.layout() ?? null);
    const changed = sceneInputs.changed([
      f,
      store.trail,
      start,
      end,
      mass,
      g,
      ...gdir,
      ...Object.values(view),
      second?.frame ?? null,
      second?.trail.end ?? 0,
    ]);
    if (changed) {
      scene.update(f, { frames: store.trail, start, end }, view, mass, g, gdir);
      scene.updateTwin(second?.frame ?? null, second?.trail ?? { frames: [], start: 0, end: 0 });
    }
    let t1 = performance.now();
    costs.add('scene update', t1 - t0);
    if (scene.draw(changed)) {
      drawn++;
      t0 = performance.now();
      costs.add('scene render (submit)', t0 - t1);
    } else t0 = t1;
    if (panelTick.due(now)) {
      const ref = store.reference;
      const length = p?.length ?? 1;
      plots.update(
        store.history,
        store.events,
        driftScales(ref?.energy ?? 0, ref?.j3 ?? 0, mass, g, length),
      );
      const ctx = { mass, g, length };
      chosen.update(store.history.frames, ctx, twin?.on ? twin.store.history.frames : null);
      twin?.update(byId('plots').clientWidth - 8);
      tools.update(f?.x ?? null, f?.t ?? null, f ? Math.hypot(...f.v) : 0);
      writeUrl();
      const latest = store.latest();
      const split = latest ? energySplit(latest, mass, g, length, store.work) : null;
      energy.draw(split, store.status?.model !== 'ideal');
      tools.describe(describeMotion(f, split), now);
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
  const el = document.getElementById('offline');
  if (el) {
    el.textContent = `${t('conn.noStart')} ${e instanceof Error ? e.message : String(e)}`;
    el.hidden = false;
  }
  console.error(e);
});
