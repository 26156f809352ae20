// The connection's handlers: frames into the store, statuses into every panel that mirrors the server
// (controls, tools, toolbar, scene, portraits, energy bars, the URL), errors and events into the message
// line, the offline banner when the server is gone, and a shared link's commands once the server answers.
// The socket is opened first thing (`openEarly`), its messages held until these handlers are attached: the
// WebSocket handshake with a loaded server took 0.4–1.2 s, which now overlaps building the page.
import { Connection, socketUrl, whenCaughtUp } from '../connection';
import type { ConnectionHandlers } from '../connection';
import type { Frame } from '../protocol';
import type { Analyses } from '../analyses';
import { eventMessage } from '../events';
import type { Notice, Status } from '../protocol';
import type { FrameCosts } from '../perf';
import type { Controls } from '../panels/controls';
import type { EnergyBars } from '../panels/energy';
import type { Portraits } from '../panels/portraits';
import type { Toolbar } from '../panels/toolbar';
import type { Tools } from '../panels/tools';
import { accessibleSliders } from '../keyboard';
import { serverWords, t } from '../i18n';
import { byId } from './page';
import type { MessageLine } from './page';
import type { SharedLink } from './link';
import type { LabCore } from './session';
import { mark } from './debug';

/** The panels a status updates. */
export interface StatusPanels {
  controls: Controls;
  tools: Tools;
  toolbar: Toolbar;
  portraits: Portraits;
  energy: EnergyBars;
}

function onStatus(lab: LabCore, panels: StatusPanels, messages: MessageLine, link: SharedLink, s: Status): void {
  const { store, scene } = lab;
  const before = store.status;
  store.onStatus(s);
  // the previous scenario's news (a string event, a hint) is no longer about what is shown
  if (before !== null && (before.scenario !== s.scenario || before.model !== s.model)) messages.clearNews();
  if (before === null || before.epoch !== s.epoch) panels.energy.rescale();
  panels.controls.sync(s);
  accessibleSliders(panels.controls.gui);
  panels.tools.sync(s);
  panels.toolbar.showRunning(s.paused);
  scene.setLength(s.params.length);
  scene.setModel(s.model);
  panels.portraits.setModel(s.model);
  link.write();
}

/** A shared link's second pendulum: a copy of the first once the server has the link's scenario; then
 *  the link's paused time is stepped on both. */
function restoreTwin(lab: LabCore, link: SharedLink): void {
  const o = link.twinToRestore;
  const twin = lab.session.twin;
  if (o === null || twin === null) return;
  link.twinToRestore = null;
  void whenCaughtUp(() => lab.store.status?.commands, () => lab.session.sent(), 5000)
    .then(() => {
      twin.restore(o);
      return whenCaughtUp(() => (twin.store.status?.paused ? 1 : undefined), () => 1, 5000);
    })
    .then(() => {
      for (const c of link.replay) lab.session.send(c);
      link.replay = [];
    });
}

function onNotice(lab: LabCore, panels: StatusPanels, messages: MessageLine, link: SharedLink, n: Notice): void {
  if (n.type === 'error') {
    lab.store.onError(n);
    const words = serverWords(n); // the page's language when the server keyed the message
    // a keyed message says what was refused in words; an unkeyed one is prefixed with the command's name
    lab.explain(n.command && n.key === undefined ? `${n.command}: ${words}` : words);
    return;
  }
  if (n.type === 'event') {
    lab.store.onEvent(n);
    lab.explain(eventMessage(n), true);
    return;
  }
  mark('first status');
  onStatus(lab, panels, messages, link, n);
  for (const c of link.takeStartup()) lab.session.send(c);
  restoreTwin(lab, link);
}

/** Connection handlers that hold every call until the real ones are attached, then replay them in order. */
export class HeldHandlers implements ConnectionHandlers {
  private real: ConnectionHandlers | null = null;
  private held: ((h: ConnectionHandlers) => void)[] = [];

  private call(f: (h: ConnectionHandlers) => void): void {
    if (this.real !== null) f(this.real);
    else this.held.push(f);
  }

  onOpen(): void {
    this.call((h) => h.onOpen());
  }
  onClose(): void {
    this.call((h) => h.onClose());
  }
  onFrames(frames: Frame[]): void {
    this.call((h) => h.onFrames(frames));
  }
  onNotice(notice: Notice): void {
    this.call((h) => h.onNotice(notice));
  }
  onProtocolError(message: string): void {
    this.call((h) => h.onProtocolError(message));
  }

  /** From now on calls go to `h`; the held ones first, in the order they came. */
  attach(h: ConnectionHandlers): void {
    this.real = h;
    for (const f of this.held.splice(0)) f(h);
  }
}

/** Opens the socket now (the session's `conn`), its messages held until `connect` attaches the handlers. */
export function openEarly(): { conn: Connection; held: HeldHandlers } {
  const held = new HeldHandlers();
  mark('socket opening');
  return { conn: new Connection(socketUrl(window.location), held), held };
}

/** Attaches the lab's handlers to the early connection (held messages replayed in order). */
export function connect(lab: LabCore, held: HeldHandlers, panels: StatusPanels, messages: MessageLine, link: SharedLink, analyses: Analyses, costs: FrameCosts): void {
  const { store } = lab;
  held.attach({
    onOpen: () => {
      mark('socket open');
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
      link.restoreShown();
    },
    onFrames: (frames) => {
      mark('first frames');
      const t0 = performance.now();
      store.onFrames(frames);
      analyses.onFrames();
      costs.add('frames received', performance.now() - t0);
    },
    onNotice: (n) => onNotice(lab, panels, messages, link, n),
    onProtocolError: (msg) => lab.explain(`protocol: ${msg}`),
  });
}
