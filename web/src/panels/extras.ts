// Pendulums 3 and 4 (docs/web.md, "Two pendulums"; issue 28: "more than two pendulums side by side"):
// beside the second pendulum of mode `own`, up to MAX_EXTRAS more, each a session of its own on the same
// server with its own rod length [m], bob mass [kg] and start angle θ₀ [°] (a planar swing from rest), the
// first's model, g, method and time scale; started, paused, reset and stepped with the others, drawn in a
// row beside them (twin.ts `rowOffsets`) and timed by its own period timer (the periods table of
// panels/twin.ts). PhET's experiment — the period against length and mass — with four pendulums at once.
import { Connection } from '../connection';
import type { Command, Status } from '../protocol';
import { LabStore } from '../state';
import { twinCommands, twinProblem } from '../twin';
import { MAX_EXTRAS } from '../twin';
import type { ExtraOptions, TwinOptions } from '../twin';
import { DEG } from '../measure';
import { typedNumber } from '../format';
import { t } from '../i18n';


/** One more pendulum: its inputs, its session and its store. */
interface Extra {
  readonly store: LabStore;
  readonly row: HTMLElement;
  readonly inputs: { length: HTMLInputElement; mass: HTMLInputElement; theta: HTMLInputElement };
  conn: Connection | null;
  pending: Command[];
}

/** A labelled number input (`label` then the field, 4.5 em wide) appended to `row`: `name` is its
 *  data-input (the e2e tests' handle), `value` and `step` its starting value and step. The inputs of
 *  pendulums 2 (panels/twin.ts, mode `own`), 3 and 4. */
export function numberInput(row: HTMLElement, label: string, name: string, value: string, step: string): HTMLInputElement {
  const l = document.createElement('label');
  l.append(`${label} `);
  const i = document.createElement('input');
  i.type = 'number';
  i.step = step;
  i.value = value;
  i.dataset['input'] = name;
  i.style.width = '4.5em';
  l.appendChild(i);
  row.appendChild(l);
  return i;
}

/** The refusal of the first of `list` (pendulums of mode `own`, numbered from `first`: 2 for the second
 *  pendulum, 3 for the rows of pendulums 3 and 4) whose length, mass or θ₀ `twinProblem` refuses, naming
 *  that pendulum (`twin.badOwn`); null when every one is fine. */
export function ownRefusal(list: readonly TwinOptions[], first: number): string | null {
  const bad = list.findIndex((o) => twinProblem({ ...o, mode: 'own' }) !== null);
  return bad < 0 ? null : t('twin.badOwn', { n: first + bad });
}

/** The refusal of the second pendulum's inputs for its mode (null when fine), naming what is wrong: the
 *  pendulum of mode `own`, ε of mode `epsilon`, the damping of mode `damped` (one message for both said
 *  "ε must be a number and the damping ≥ 0" of a refused damping too). */
export function twinRefusal(o: TwinOptions): string | null {
  if (twinProblem(o) === null) return null;
  if (o.mode === 'own') return ownRefusal([o], 2);
  return t(o.mode === 'epsilon' ? 'twin.badEpsilon' : 'twin.badDamping');
}

export class ExtraPendulums {
  readonly extras: Extra[] = [];
  private readonly list: HTMLElement;
  private readonly add: HTMLButtonElement;

  constructor(
    container: HTMLElement,
    private readonly socket: string,
    private readonly explain: (text: string) => void,
  ) {
    this.list = document.createElement('div');
    this.list.dataset['output'] = 'extras';
    this.add = document.createElement('button');
    this.add.type = 'button';
    this.add.dataset['action'] = 'extra-add';
    this.add.textContent = t('extras.add');
    this.add.addEventListener('click', () => this.addRow());
    const box = document.createElement('section');
    box.className = 'tools';
    box.dataset['tool'] = 'extras';
    const h = document.createElement('h3');
    h.textContent = t('extras.title');
    const hint = document.createElement('p');
    hint.textContent = t('extras.hint');
    box.append(h, hint, this.list, this.add);
    container.appendChild(box);
  }

  /** The "add" button while fewer than MAX_EXTRAS; a remove button on the last row only (pendulums keep
   *  their numbers). */
  private show(): void {
    this.add.hidden = this.extras.length >= MAX_EXTRAS;
    this.extras.forEach((e, i) => {
      const b = e.row.querySelector('button');
      if (b !== null) b.hidden = i !== this.extras.length - 1;
    });
  }

  /** The pendulums as their inputs say (θ₀ in rad), for the share link. */
  values(): ExtraOptions[] {
    return this.extras.map((e) => ({ length: Number(e.inputs.length.value), mass: Number(e.inputs.mass.value), theta: Number(e.inputs.theta.value) / DEG }));
  }

  /** Makes the rows `list` (a shared link's pendulums 3 and 4). */
  setRows(list: readonly ExtraOptions[]): void {
    while (this.extras.length > 0) this.removeLast();
    for (const o of list.slice(0, MAX_EXTRAS)) {
      const e = this.addRow();
      if (e === null) return;
      e.inputs.length.value = String(o.length);
      e.inputs.mass.value = String(o.mass);
      e.inputs.theta.value = String(Number((o.theta * DEG).toPrecision(12)));
    }
  }

  private addRow(): Extra | null {
    if (this.extras.length >= MAX_EXTRAS) return null;
    const n = this.extras.length + 3;
    const row = document.createElement('p');
    row.dataset['extra'] = String(n);
    row.append(`${t('extras.pendulum', { n })}: `);
    const inputs = {
      length: numberInput(row, 'l [m]', `extra-length-${n}`, '0.75', '0.05'),
      mass: numberInput(row, 'm [kg]', `extra-mass-${n}`, '1', '0.1'),
      theta: numberInput(row, 'θ₀ [°]', `extra-theta-${n}`, '10', '1'),
    };
    const remove = document.createElement('button');
    remove.type = 'button';
    remove.dataset['action'] = `extra-remove-${n}`;
    remove.textContent = '✕';
    remove.title = t('extras.remove', { n });
    remove.setAttribute('aria-label', remove.title);
    remove.addEventListener('click', () => this.removeLast());
    row.appendChild(remove);
    this.list.appendChild(row);
    const e: Extra = { store: new LabStore(), row, inputs, conn: null, pending: [] };
    this.extras.push(e);
    this.show();
    return e;
  }

  private removeLast(): void {
    const e = this.extras.pop();
    if (e === undefined) return;
    e.conn?.close();
    e.row.remove();
    this.show();
  }

  /** Starts every extra pendulum as a copy of the first (`s`) with its own length, mass and θ₀; false (and
   *  a message) when an input is out of range. */
  start(s: Status): boolean {
    const opts = this.extras.map((e): TwinOptions => ({ mode: 'own', epsilon: 0, method: s.method, damping: 0, length: typedNumber(e.inputs.length), mass: typedNumber(e.inputs.mass), theta: typedNumber(e.inputs.theta) / DEG }));
    const refused = ownRefusal(opts, 3);
    if (refused !== null) {
      this.explain(refused);
      return false;
    }
    this.extras.forEach((e, i) => {
      e.pending = twinCommands(s, opts[i] as TwinOptions);
      if (e.conn === null) e.conn = this.connect(e);
      else this.flush(e);
    });
    return true;
  }

  private connect(e: Extra): Connection {
    return new Connection(this.socket, {
      onOpen: () => this.flush(e),
      onClose: () => e.store.setConnected(false),
      onFrames: (frames) => e.store.onFrames(frames),
      onNotice: (n) => {
        if (n.type === 'status') e.store.onStatus(n);
        else if (n.type === 'event') e.store.onEvent(n);
        else this.explain(`${t('extras.pendulum', { n: e.row.dataset['extra'] ?? '' })}: ${n.message}`);
      },
      onProtocolError: (m) => this.explain(m),
    });
  }

  private flush(e: Extra): void {
    if (e.conn === null || !e.conn.isOpen) return;
    for (const c of e.pending) e.conn.send(c);
    e.pending = [];
  }

  /** The running extra pendulums' stores, in order (3, 4). */
  running(): LabStore[] {
    return this.extras.filter((e) => e.conn !== null && e.store.status !== null).map((e) => e.store);
  }

  stop(): void {
    for (const e of this.extras) {
      e.conn?.close();
      e.conn = null;
      e.store.clear();
      e.store.status = null;
    }
  }

  /** Run, pause, reset and step go to every extra pendulum too. */
  mirror(cmd: Command): void {
    if (cmd.type !== 'pause' && cmd.type !== 'resume' && cmd.type !== 'reset' && cmd.type !== 'step') return;
    for (const e of this.extras) e.conn?.send(cmd);
  }
}
