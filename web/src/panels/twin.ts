// The two-pendulum panel (docs/web.md, "Two pendulums"): what the second pendulum differs in, the button
// that (re)starts both together, and the plot of their separation. It owns the second session: a
// Connection of its own with a LabStore of its own (twin.ts has the pure parts).
import { Connection } from '../connection';
import type { Command, MethodInfo } from '../protocol';
import { LabStore } from '../state';
import type { TrailSlice } from '../scene/scene';
import { CurvePlot, dataRange } from './curves';
import { Visibility } from './visible';
import { separation, twinCommands } from '../twin';
import type { TwinMode, TwinOptions } from '../twin';
import { DEG } from '../measure';
import { t } from '../i18n';

export interface TwinActions {
  /** Sends to the first pendulum's session. */
  send(cmd: Command): void;
  explain(text: string, info?: boolean): void;
}

export class TwinPanel {
  readonly store = new LabStore();
  readonly options: TwinOptions = { mode: 'off', epsilon: 0.01 / DEG, method: 'rk4', damping: 0.5 };
  private conn: Connection | null = null;
  private pending: Command[] = [];
  private readonly plot: CurvePlot;
  private readonly visibility = new Visibility();

  constructor(
    container: HTMLElement,
    private readonly first: LabStore,
    methods: readonly MethodInfo[],
    private readonly socket: string,
    private readonly actions: TwinActions,
  ) {
    const box = document.createElement('section');
    box.className = 'tools';
    box.dataset['tool'] = 'twin';
    const h = document.createElement('h3');
    h.textContent = t('twin.title');
    box.appendChild(h);
    const modeLabel = document.createElement('label');
    modeLabel.append(`${t('twin.mode')} `);
    const mode = document.createElement('select');
    mode.dataset['input'] = 'twin-mode';
    const modes: [TwinMode, string][] = [
      ['off', t('twin.off')],
      ['epsilon', t('twin.epsilon')],
      ['method', t('twin.method')],
      ['damped', t('twin.damped')],
    ];
    for (const [value, words] of modes) {
      const o = document.createElement('option');
      o.value = value;
      o.textContent = words;
      mode.appendChild(o);
    }
    modeLabel.appendChild(mode);
    const epsLabel = document.createElement('label');
    epsLabel.append('ε [°] ');
    const eps = document.createElement('input');
    eps.type = 'number';
    eps.step = '0.01';
    eps.value = '0.01';
    eps.dataset['input'] = 'twin-epsilon';
    eps.style.width = '5em';
    epsLabel.appendChild(eps);
    const methodLabel = document.createElement('label');
    methodLabel.append(`${t('twin.methodPick')} `);
    const method = document.createElement('select');
    method.dataset['input'] = 'twin-method';
    for (const m of methods) {
      const o = document.createElement('option');
      o.value = m.name;
      o.textContent = m.name;
      method.appendChild(o);
    }
    method.value = methods.some((m) => m.name === 'rk4') ? 'rk4' : (methods[0]?.name ?? '');
    methodLabel.appendChild(method);
    const dampLabel = document.createElement('label');
    dampLabel.append(`${t('twin.damping')} `);
    const damp = document.createElement('input');
    damp.type = 'number';
    damp.step = '0.1';
    damp.min = '0';
    damp.value = '0.5';
    damp.dataset['input'] = 'twin-damping';
    damp.style.width = '5em';
    dampLabel.appendChild(damp);
    const start = document.createElement('button');
    start.type = 'button';
    start.dataset['action'] = 'twin-start';
    start.textContent = t('twin.start');
    const showFor = () => {
      epsLabel.hidden = mode.value !== 'epsilon';
      methodLabel.hidden = mode.value !== 'method';
      dampLabel.hidden = mode.value !== 'damped';
      start.hidden = mode.value === 'off';
    };
    mode.addEventListener('change', () => {
      showFor();
      if (mode.value === 'off') this.stop();
    });
    start.addEventListener('click', () => {
      this.options.mode = mode.value as TwinMode;
      this.options.epsilon = Number(eps.value) / DEG;
      this.options.method = method.value;
      this.options.damping = Number(damp.value);
      if (!Number.isFinite(this.options.epsilon) || !(this.options.damping >= 0)) {
        actions.explain(t('twin.bad'));
        return;
      }
      this.start();
    });
    showFor();
    box.append(modeLabel, ' ', epsLabel, methodLabel, dampLabel, ' ', start);
    container.appendChild(box);
    this.plot = new CurvePlot(container, t('twin.separation'), 't [s]', '|r₁ − r₂| [m]', 140);
    this.plot.canvas.dataset['plot'] = 'separation';
    this.plot.canvas.parentElement?.setAttribute('hidden', '');
    this.visibility.watch(this.plot.canvas);
  }

  get on(): boolean {
    return this.conn !== null;
  }

  /** (Re)starts both pendulums together: the second becomes the first's copy with its one difference. */
  start(): void {
    const s = this.first.status;
    if (s === null) return this.actions.explain(t('msg.notConnected'));
    this.pending = twinCommands(s, this.options);
    if (this.conn === null) {
      this.conn = new Connection(this.socket, {
        onOpen: () => this.flush(),
        onClose: () => this.store.setConnected(false),
        onFrames: (frames) => this.store.onFrames(frames),
        onNotice: (n) => {
          if (n.type === 'status') this.store.onStatus(n);
          else if (n.type === 'event') this.store.onEvent(n);
          else this.actions.explain(`${t('twin.second')}: ${n.message}`);
        },
        onProtocolError: (m) => this.actions.explain(`${t('twin.second')}: ${m}`),
      });
    } else this.flush();
    this.actions.send({ type: 'reset' });
    this.plot.canvas.parentElement?.removeAttribute('hidden');
  }

  private flush(): void {
    if (this.conn === null || !this.conn.isOpen) return;
    for (const c of this.pending) this.conn.send(c);
    this.pending = [];
  }

  stop(): void {
    this.conn?.close();
    this.conn = null;
    this.store.clear();
    this.store.status = null;
    this.plot.canvas.parentElement?.setAttribute('hidden', '');
  }

  /** Run, pause, reset and step go to both pendulums. */
  mirror(cmd: Command): void {
    if (this.conn === null) return;
    if (cmd.type === 'pause' || cmd.type === 'resume' || cmd.type === 'reset' || cmd.type === 'step') this.conn.send(cmd);
  }

  /** The second pendulum at the first one's drawn time `t` [s] with its trail (null: not shown). */
  drawn(t: number | null, trailSeconds: number): { frame: ReturnType<LabStore['displayed']>; trail: TrailSlice } | null {
    if (this.conn === null || t === null || this.store.frames.length === 0) return null;
    const fs = this.store.frames;
    this.store.playT = Math.min(Math.max(t, (fs[0] as { t: number }).t), (fs[fs.length - 1] as { t: number }).t);
    const { start, end } = this.store.trailRange(trailSeconds);
    return { frame: this.store.displayed(), trail: { frames: this.store.trail, start, end } };
  }

  /** Redraws the separation plot (10 times a second). */
  update(width: number): void {
    if (this.conn === null || !this.visibility.visible(this.plot.canvas)) return;
    const sep = separation(this.first.history.frames, this.store.trajectory);
    this.plot.draw(width, [{ x: sep.t, y: sep.d, color: '#c8f560', label: t('twin.separation') }], dataRange(sep.t, 0.02), dataRange([0, ...sep.d]));
  }

  /** The separation now, for tests: [t [s], |r₁ − r₂| [m]] pairs of the last update's data. */
  separationNow(): { t: number[]; d: number[] } {
    return separation(this.first.history.frames, this.store.trajectory);
  }
}
