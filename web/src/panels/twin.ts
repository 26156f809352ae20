// The two-pendulum panel (docs/web.md, "Two pendulums"): what the second pendulum differs in, the button
// that (re)starts both together, and the plot of their separation. It owns the second session: a
// Connection of its own with a LabStore of its own (twin.ts has the pure parts).
import { Connection } from '../connection';
import type { Command, MethodInfo } from '../protocol';
import { LabStore } from '../state';
import type { TrailSlice } from '../scene/trail';
import { CurvePlot, dataRange } from './curves';
import { Visibility } from './visible';
import { rowOffsets, separation, sideBySide, twinCommands } from '../twin';
import type { ExtraPendulums } from './extras';
import { numberInput, twinRefusal } from './extras';
import type { Frame, Vec3 } from '../protocol';
import type { TwinMode, TwinOptions } from '../twin';
import { DEG } from '../measure';
import { typedNumber } from '../format';
import { methodWords, t } from '../i18n';

export interface TwinActions {
  /** Sends to the first pendulum's session. */
  send(cmd: Command): void;
  explain(text: string, info?: boolean): void;
}

/** The pendulum of `store` at the first one's drawn time `t` [s] (clamped to its frames) with its trail. */
function drawnAt(store: LabStore, t: number | null, trailSeconds: number): { frame: Frame | null; trail: TrailSlice } | null {
  if (t === null || store.frames.length === 0) return null;
  const fs = store.frames;
  store.playT = Math.min(Math.max(t, (fs[0] as Frame).t), (fs[fs.length - 1] as Frame).t);
  const { start, end } = store.trailRange(trailSeconds);
  return { frame: store.displayed(), trail: { frames: store.trail, start, end } };
}

export class TwinPanel {
  readonly store = new LabStore();
  readonly options: TwinOptions = { mode: 'off', epsilon: 0.01 / DEG, method: 'rk4', damping: 0.5, length: 0.5, mass: 1, theta: 10 / DEG };
  private readonly periods: HTMLTableElement;
  /** Sets the panel's inputs to `o` (a shared link's second pendulum). */
  private readonly setInputs: (o: TwinOptions) => void;
  private conn: Connection | null = null;
  private pending: Command[] = [];
  private readonly plot: CurvePlot;
  private readonly visibility = new Visibility();
  /** Pendulums 3 and 4 beside the second in mode `own` (panels/extras.ts; null: none). */
  extras: ExtraPendulums | null = null;

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
      ['own', t('twin.own')],
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
      o.textContent = methodWords(m.name, m.order);
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
    // mode `own`: its own length, mass and start angle (PhET's lesson: does length or mass change the period?)
    const ownBox = document.createElement('span');
    const len2 = numberInput(ownBox, t('twin.length'), 'twin-length', '0.5', '0.05');
    const mass2 = numberInput(ownBox, t('twin.mass'), 'twin-mass', '1', '0.1');
    const theta2 = numberInput(ownBox, t('twin.theta'), 'twin-theta', '10', '1');
    const start = document.createElement('button');
    start.type = 'button';
    start.dataset['action'] = 'twin-start';
    start.textContent = t('twin.start');
    const showFor = () => {
      epsLabel.hidden = mode.value !== 'epsilon';
      methodLabel.hidden = mode.value !== 'method';
      dampLabel.hidden = mode.value !== 'damped';
      ownBox.hidden = mode.value !== 'own';
      start.hidden = mode.value === 'off';
    };
    mode.addEventListener('change', () => {
      showFor();
      if (mode.value === 'off') this.stop();
    });
    start.addEventListener('click', () => {
      const o: TwinOptions = {
        ...this.options,
        mode: mode.value as TwinMode,
        epsilon: typedNumber(eps) / DEG,
        method: method.value,
        damping: typedNumber(damp),
        length: typedNumber(len2),
        mass: typedNumber(mass2),
        theta: typedNumber(theta2) / DEG,
      };
      // the chosen mode's inputs only (an emptied box of another mode is no reason to refuse), and the
      // options kept as they were when refused (the share link writes them)
      const refused = twinRefusal(o);
      if (refused !== null) {
        actions.explain(refused);
        return;
      }
      Object.assign(this.options, o);
      this.start();
    });
    showFor();
    this.setInputs = (o) => {
      mode.value = o.mode;
      eps.value = String(o.epsilon * DEG);
      method.value = o.method;
      damp.value = String(o.damping);
      len2.value = String(o.length);
      mass2.value = String(o.mass);
      theta2.value = String(o.theta * DEG);
      showFor();
    };
    // both pendulums' periods, each measured by its own timer from its own motion
    this.periods = document.createElement('table');
    this.periods.dataset['readout'] = 'twin-periods';
    this.periods.hidden = true;
    box.append(modeLabel, ' ', epsLabel, methodLabel, dampLabel, ownBox, ' ', start, this.periods);
    container.appendChild(box);
    this.plot = new CurvePlot(container, t('twin.separation'), 't [s]', '|r₁ − r₂| [m]', 140);
    this.plot.canvas.dataset['plot'] = 'separation';
    this.plot.canvas.parentElement?.setAttribute('hidden', '');
    this.visibility.watch(this.plot.canvas);
  }

  get on(): boolean {
    return this.conn !== null;
  }

  /** Where the scene draws the second pendulum: its own length and its pivot beside the first (mode `own`,
   *  with both statuses known), else null (the first's pivot). */
  layout(): { offset: [number, number, number]; length: number } | null {
    const [a, b] = [this.first.status, this.store.status];
    if (this.conn === null || this.options.mode !== 'own' || a === null || b === null) return null;
    return { offset: sideBySide(a.params.length, b.params.length), length: b.params.length };
  }

  /** Where the scene draws pendulums 3 and 4 (mode `own`): pivots in a row after the second (twin.ts
   *  `rowOffsets`), each with its length [m]. */
  extraLayouts(): { offset: Vec3; length: number }[] {
    const a = this.first.status;
    const b = this.store.status;
    const more = this.extras?.running() ?? [];
    if (this.layout() === null || a === null || b === null || more.length === 0) return [];
    const lengths = more.map((s) => (s.status as NonNullable<LabStore['status']>).params.length);
    const offsets = rowOffsets([a.params.length, b.params.length, ...lengths]);
    return lengths.map((length, i) => ({ offset: offsets[i + 1] as Vec3, length }));
  }

  /** Pendulums 3 and 4 at the first one's drawn time `t` [s] with their trails. */
  drawnExtras(t: number | null, trailSeconds: number): { frame: Frame | null; trail: TrailSlice }[] {
    if (this.conn === null || this.options.mode !== 'own') return [];
    return (this.extras?.running() ?? []).map((s) => drawnAt(s, t, trailSeconds) ?? { frame: null, trail: { frames: [], start: 0, end: 0 } });
  }

  /** Starts the second pendulum as `o` says (a shared link), once the first has its status. */
  restore(o: TwinOptions): void {
    Object.assign(this.options, o);
    this.setInputs(o);
    this.extras?.setRows(o.extras ?? []);
    if (o.mode !== 'off') this.start();
  }

  /** (Re)starts both pendulums together: the second becomes the first's copy with its one difference. */
  start(): void {
    const s = this.first.status;
    if (s === null) return this.actions.explain(t('msg.notConnected'));
    if (this.options.mode === 'own' && this.extras !== null) {
      if (!this.extras.start(s)) return; // an input of pendulum 3 or 4 refused (its message is shown)
      this.options.extras = this.extras.values(); // the share link carries them
    } else {
      this.extras?.stop();
      delete this.options.extras;
    }
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
    this.periods.hidden = false;
  }

  private flush(): void {
    if (this.conn === null || !this.conn.isOpen) return;
    for (const c of this.pending) this.conn.send(c);
    this.pending = [];
  }

  stop(): void {
    this.extras?.stop();
    this.conn?.close();
    this.conn = null;
    this.store.clear();
    this.store.status = null;
    this.plot.canvas.parentElement?.setAttribute('hidden', '');
    this.periods.hidden = true;
  }

  /** Run, pause, reset and step go to both pendulums. */
  mirror(cmd: Command): void {
    if (this.conn === null) return;
    this.extras?.mirror(cmd);
    if (cmd.type === 'pause' || cmd.type === 'resume' || cmd.type === 'reset' || cmd.type === 'step') this.conn.send(cmd);
  }

  /** The least newest time [s] of the pendulums drawn beside the first (the second, and 3 and 4 in mode
   *  `own`): the first's playhead waits there (`LabStore.advancePlayhead`); null when none is running. */
  newest(): number | null {
    if (this.conn === null) return null;
    const times = [this.store, ...(this.extras?.running() ?? [])].map((s) => s.latest()?.t ?? null);
    const known = times.filter((x): x is number => x !== null);
    return known.length > 0 ? Math.min(...known) : null;
  }

  /** The second pendulum at the first one's drawn time `t` [s] with its trail (null: not shown). */
  drawn(t: number | null, trailSeconds: number): { frame: ReturnType<LabStore['displayed']>; trail: TrailSlice } | null {
    if (this.conn === null) return null;
    return drawnAt(this.store, t, trailSeconds);
  }

  /** Redraws the periods table and the separation plot (10 times a second). */
  update(width: number): void {
    if (this.conn !== null) this.fillPeriods();
    if (this.conn === null || !this.visibility.visible(this.plot.canvas)) return;
    const sep = separation(this.first.history.frames, this.store.trajectory);
    this.plot.draw(width, [{ x: sep.t, y: sep.d, color: '#c8f560', label: t('twin.separation') }], dataRange(sep.t, 0.02), dataRange([0, ...sep.d]));
  }

  /** The two pendulums side by side: length, mass, start angle and the period each one's timer measured. */
  private fillPeriods(): void {
    const row = (name: string, store: LabStore): string[] => {
      const s = store.status;
      const r = store.periodTimer.reading();
      const th = s === null ? null : Math.atan2(Math.hypot(s.start.x[0], s.start.x[1]), -s.start.x[2]) * DEG;
      return [
        name,
        s === null ? '—' : s.params.length.toPrecision(3),
        s === null ? '—' : s.params.mass.toPrecision(3),
        th === null ? '—' : th.toFixed(1),
        r.period === null ? '—' : `${r.period.toFixed(4)} (${r.intervals})`,
      ];
    };
    const rows = [
      ['', t('twin.colLength'), t('twin.colMass'), t('twin.colTheta'), t('twin.colPeriod')],
      row(t('twin.first'), this.first),
      row(t('twin.second'), this.store),
      ...(this.extras?.running() ?? []).map((st, i) => row(t('extras.pendulum', { n: i + 3 }), st)),
    ];
    while (this.periods.rows.length > rows.length) this.periods.deleteRow(-1);
    rows.forEach((r, i) => {
      const tr = this.periods.rows[i] ?? this.periods.insertRow();
      while (tr.cells.length < r.length) tr.insertCell();
      r.forEach((v, k) => {
        const c = tr.cells[k];
        if (c && c.textContent !== v) c.textContent = v;
      });
    });
  }

  /** The separation now, for tests: [t [s], |r₁ − r₂| [m]] pairs of the last update's data. */
  separationNow(): { t: number[]; d: number[] } {
    return separation(this.first.history.frames, this.store.trajectory);
  }
}
