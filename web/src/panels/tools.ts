// The classroom tools at the top of the panel (docs/web.md, "Measuring tools"): the start amplitude typed in
// degrees, gravity presets and friction, the angles now in degrees, a stopwatch on the simulated time, the
// period timer (measured beside the exact values of the server) and the ruler/protractor toggles. They send
// commands or read the store; the measurements themselves are measure.ts's (no physics here).
import type { Command, Status } from '../protocol';
import type { LabStore } from '../state';
import { DEG, periodComparison, sphericalAngles, Stopwatch, swingTheory } from '../measure';
import { fmt, typedNumber } from '../format';
import { modelWords, t } from '../i18n';
import type { Key } from '../i18n';

/** Gravity presets [m/s²] (surface gravity; NASA planetary fact sheets, rounded). */
export const GRAVITY_PRESETS: readonly [Key, number][] = [
  ['gravity.earth', 9.81],
  ['gravity.moon', 1.62],
  ['gravity.mars', 3.71],
  ['gravity.jupiter', 24.79],
  ['gravity.zero', 0],
  ['gravity.negative', -9.81],
];

/** The damping c [1/s] a friction slider change sends: `set_params` on a model with a `damping`
 *  parameter; for the ideal pendulum, the `damped` model with that damping (0: nothing to change). */
export function frictionCommand(status: Status | null, damping: number): Command | null {
  if (status === null) return null;
  if ('damping' in (status.model_params ?? {})) return { type: 'set_params', params: { damping } };
  if (status.model === 'ideal' && damping > 0) return { type: 'set_model', model: 'damped', params: { damping } };
  return null;
}

/** The `set_state` of a start typed in degrees: θ₀ from the downward vertical, φ₀, and the azimuthal rate
 *  φ̇₀ [°/s] (0: a planar swing), or a sentence saying what is wrong. */
export function startCommand(thetaDeg: number, phiDeg: number, phiDotDeg: number): Command | string {
  for (const [name, v] of [['θ₀', thetaDeg], ['φ₀', phiDeg], ['φ̇₀', phiDotDeg]] as const) {
    if (!Number.isFinite(v)) return t('start.notNumber', { name });
  }
  if (thetaDeg < 0 || thetaDeg > 180) return t('start.thetaRange', { value: thetaDeg });
  return { type: 'set_state', theta: thetaDeg / DEG, phi: phiDeg / DEG, theta_dot: 0, phi_dot: phiDotDeg / DEG };
}

/** The mystery planet's gravity [m/s²] for a uniform random u ∈ [0, 1): 2 … 20 m/s² in steps of 0.01,
 *  never within 0.3 m/s² of a preset (a class should not recognise it by the period alone). */
export function mysteryGravity(u: number): number {
  let g = Math.round((2 + 18 * u) * 100) / 100;
  for (const [, p] of GRAVITY_PRESETS) if (Math.abs(g - p) < 0.3) g = Math.round((g + 0.6) * 100) / 100;
  return g;
}

/** The tone [Hz] for a bob passing its lowest point at `speed` [m/s]: 440 Hz at rest, an octave up per
 *  2 m/s, at most 1760 Hz. */
export function soundPitch(speed: number): number {
  return Math.min(1760, 440 * 2 ** (Math.max(0, speed) / 2));
}

export interface ToolActions {
  send(cmd: Command): void;
  explain(text: string, info?: boolean): void;
  /** The ruler or the protractor switched on or off in the scene. */
  overlay(which: 'ruler' | 'protractor', on: boolean): void;
  /** The ruler or the protractor moved by [sideways, up] rod lengths; null: back to its place. */
  move(which: 'ruler' | 'protractor', by: [number, number] | null): void;
}

function el<K extends keyof HTMLElementTagNameMap>(tag: K, attrs: Record<string, string> = {}, text = ''): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text) e.textContent = text;
  return e;
}

function section(parent: HTMLElement, title: string, name: string): HTMLElement {
  const s = el('section', { class: 'tools', 'data-tool': name });
  s.appendChild(el('h3', {}, title));
  parent.appendChild(s);
  return s;
}

function numberBox(label: string, name: string, value: number, step: string): [HTMLLabelElement, HTMLInputElement] {
  const l = el('label');
  l.append(`${label} `);
  const i = el('input', { type: 'number', step, name, 'data-input': name });
  i.value = String(value);
  i.style.width = '5.5em';
  l.appendChild(i);
  return [l, i];
}

export class Tools {
  readonly stopwatch = new Stopwatch();
  private readonly angleText: HTMLElement;
  private readonly watchText: HTMLElement;
  private readonly lapList: HTMLElement;
  private readonly watchButton: HTMLButtonElement;
  private readonly periodTable: HTMLTableElement;
  private readonly friction: HTMLInputElement;
  private readonly frictionValue: HTMLOutputElement;
  private readonly gravity: HTMLSelectElement;
  private now = 0;
  /** The mystery planet's g [m/s²] while its value is hidden (null: none). */
  mysteryG: number | null = null;
  private readonly reveal: HTMLButtonElement;
  private readonly description: HTMLElement;
  private readonly describeLive: HTMLInputElement;
  private describedAt = -Infinity;
  private readonly sound: HTMLInputElement;
  private audio: AudioContext | null = null;
  private heard = 0;
  /** Tones played (for tests). */
  tones = 0;

  /** A tone for each new lowest point while the sound is on; `speed` [m/s] there sets the pitch. */
  private listen(speed: number): void {
    const n = this.store.periodTimer.lowCount;
    if (n < this.heard) this.heard = n; // the timer was reset
    if (n === this.heard) return;
    this.heard = n;
    if (!this.sound.checked || typeof AudioContext === 'undefined') return;
    this.audio ??= new AudioContext();
    const ctx = this.audio;
    const osc = ctx.createOscillator();
    const gain = ctx.createGain();
    osc.frequency.value = soundPitch(speed);
    gain.gain.setValueAtTime(0.15, ctx.currentTime);
    gain.gain.exponentialRampToValueAtTime(0.001, ctx.currentTime + 0.12);
    osc.connect(gain).connect(ctx.destination);
    osc.start();
    osc.stop(ctx.currentTime + 0.12);
    this.tones++;
  }
  private spokenUntil = -Infinity;

  private endMystery(): void {
    this.mysteryG = null;
    document.body.classList.remove('mystery');
    this.reveal.hidden = true;
  }

  /** The motion in words (describe.ts) under the angles: with "describe every 5 s" on it is a polite live
   *  region renewed every 5 s (a screen reader reads it out); `now` forces it (the D key). */
  describe(text: string, wallMs: number, now = false): void {
    const live = this.describeLive.checked;
    if (now) this.spokenUntil = wallMs + 3000; // a region asked to speak stays live while it is read out
    this.description.setAttribute('aria-live', live || wallMs < this.spokenUntil ? 'polite' : 'off');
    if (!now && live && wallMs - this.describedAt < 5000) return;
    if (!now && !live && wallMs - this.describedAt < 1000) return;
    this.describedAt = wallMs;
    if (this.description.textContent !== text) this.description.textContent = text;
    else if (now) {
      // the same words again: a screen reader reads a live region only when it changes
      this.description.textContent = '';
      requestAnimationFrame(() => (this.description.textContent = text));
    }
  }
  private readonly overlayBoxes: Partial<Record<'ruler' | 'protractor', HTMLInputElement>> = {};

  /** Shows the ruler's or the protractor's state (a shared link's view). */
  showOverlay(which: 'ruler' | 'protractor', on: boolean): void {
    const box = this.overlayBoxes[which];
    if (box) box.checked = on;
  }

  constructor(
    container: HTMLElement,
    private readonly store: LabStore,
    actions: ToolActions,
  ) {
    // the stopwatch reads the simulated time shown at the moment of the click
    const nowT = () => (this.now = store.playT ?? this.now);
    // the start, typed in degrees
    const start = section(container, t('tools.start'), 'start');
    const [l1, theta] = numberBox('θ₀ [°]', 'theta0', 30, '1');
    const [l2, phi] = numberBox('φ₀ [°]', 'phi0', 0, '1');
    const [l3, rate] = numberBox('φ̇₀ [°/s]', 'phidot0', 0, '10');
    theta.title = t('tools.thetaHelp');
    phi.title = t('tools.phiHelp');
    rate.title = t('tools.phiDotHelp');
    const set = el('button', { type: 'button', 'data-action': 'set-start' }, t('tools.setStart'));
    const apply = () => {
      const cmd = startCommand(typedNumber(theta), typedNumber(phi), typedNumber(rate));
      if (typeof cmd === 'string') actions.explain(cmd);
      else actions.send(cmd);
    };
    set.addEventListener('click', apply);
    for (const i of [theta, phi, rate]) i.addEventListener('keydown', (e) => e.key === 'Enter' && apply());
    start.append(l1, l2, l3, set);

    // gravity presets and friction
    const world = section(container, t('tools.world'), 'world');
    const gl = el('label');
    gl.append(`${t('tools.gravity')} `);
    this.gravity = el('select', { 'data-input': 'gravity-preset' });
    this.gravity.appendChild(el('option', { value: '' }, t('gravity.custom')));
    for (const [key, g] of GRAVITY_PRESETS) this.gravity.appendChild(el('option', { value: String(g) }, `${t(key)} (${g} m/s²)`));
    this.gravity.appendChild(el('option', { value: 'mystery' }, t('tools.mystery')));
    const reveal = el('button', { type: 'button', 'data-action': 'reveal-g', hidden: '' }, t('tools.reveal'));
    this.reveal = reveal;
    this.gravity.addEventListener('change', () => {
      if (this.gravity.value === 'mystery') {
        this.mysteryG = mysteryGravity(Math.random());
        document.body.classList.add('mystery');
        reveal.hidden = false;
        actions.send({ type: 'set_params', g: this.mysteryG });
        actions.explain(t('tools.mysteryOn'), true);
      } else if (this.gravity.value !== '') actions.send({ type: 'set_params', g: Number(this.gravity.value) });
    });
    reveal.addEventListener('click', () => {
      actions.explain(t('tools.revealed', { g: this.mysteryG ?? '?' }), true);
      this.endMystery();
    });
    gl.append(this.gravity, ' ', reveal);
    const fl = el('label');
    fl.append(`${t('tools.friction')} `);
    this.friction = el('input', { type: 'range', min: '0', max: '2', step: '0.01', 'data-input': 'friction' });
    this.friction.value = '0';
    this.friction.title = t('tools.frictionHelp');
    this.frictionValue = el('output');
    this.friction.addEventListener('input', () => {
      this.frictionValue.textContent = `${Number(this.friction.value).toFixed(2)} 1/s`;
    });
    this.friction.addEventListener('change', () => {
      const cmd = frictionCommand(store.status, Number(this.friction.value));
      if (cmd !== null) actions.send(cmd);
      else if (Number(this.friction.value) > 0) actions.explain(t('tools.noFriction', { model: modelWords(store.status?.model ?? '?', store.status?.model ?? '?') }));
    });
    fl.append(this.friction, ' ', this.frictionValue);
    world.append(gl, fl);

    // the angles now
    const now = section(container, t('tools.now'), 'angles');
    this.angleText = el('div', { class: 'big', 'data-readout': 'angles', 'aria-live': 'off' });
    this.description = el('p', { class: 'describe', 'data-readout': 'describe', 'aria-live': 'off', 'aria-atomic': 'true' });
    const dl = el('label');
    this.describeLive = el('input', { type: 'checkbox', 'data-input': 'describe' });
    dl.append(this.describeLive, ` ${t('describe.toggle')}`);
    // sonification: a short tone each time the bob passes its lowest point (the period timer's count), its
    // pitch rising with the speed there — the rhythm of the swing to the ear
    const sl = el('label');
    this.sound = el('input', { type: 'checkbox', 'data-input': 'sound' });
    sl.append(this.sound, ` ${t('tools.sound')}`);
    now.append(this.angleText, this.description, dl, sl);

    // stopwatch
    const sw = section(container, t('tools.stopwatch'), 'stopwatch');
    this.watchText = el('div', { class: 'big', 'data-readout': 'stopwatch' }, '0.000 s');
    this.watchButton = el('button', { type: 'button', 'data-action': 'stopwatch' }, t('tools.swStart'));
    const lap = el('button', { type: 'button', 'data-action': 'lap' }, t('tools.swLap'));
    const reset = el('button', { type: 'button', 'data-action': 'stopwatch-reset' }, t('tools.swReset'));
    this.lapList = el('ol', { class: 'laps' });
    this.watchButton.addEventListener('click', () => {
      if (this.stopwatch.running) this.stopwatch.stop(nowT());
      else this.stopwatch.start(nowT());
      this.watchButton.textContent = this.stopwatch.running ? t('tools.swStop') : t('tools.swStart');
    });
    lap.addEventListener('click', () => this.stopwatch.lap(nowT()));
    reset.addEventListener('click', () => {
      this.stopwatch.reset();
      this.watchButton.textContent = t('tools.swStart');
    });
    sw.append(this.watchText, this.watchButton, ' ', lap, ' ', reset, this.lapList);

    // period timer
    const pt = section(container, t('tools.period'), 'period');
    pt.title = t('tools.periodHelp');
    this.periodTable = el('table', { 'data-readout': 'period' });
    pt.appendChild(this.periodTable);

    // overlays
    const ov = section(container, t('tools.overlays'), 'overlays');
    for (const which of ['ruler', 'protractor'] as const) {
      const l = el('label');
      const box = el('input', { type: 'checkbox', 'data-input': which });
      box.addEventListener('change', () => actions.overlay(which, box.checked));
      this.overlayBoxes[which] = box;
      // movable (issue 28): buttons a finger, a mouse and the keyboard can use, a twentieth of l a press
      const pad = el('span', { class: 'move-pad', role: 'group', 'aria-label': t('tools.moveGroup', { what: t(which === 'ruler' ? 'tools.ruler' : 'tools.protractor') }) });
      const moves: [string, Key, [number, number] | null][] = [
        ['◀', 'tools.moveLeft', [-0.05, 0]],
        ['▶', 'tools.moveRight', [0.05, 0]],
        ['▲', 'tools.moveUp', [0, 0.05]],
        ['▼', 'tools.moveDown', [0, -0.05]],
        ['⟲', 'tools.moveBack', null],
      ];
      for (const [glyph, words, by] of moves) {
        const b = el('button', { type: 'button', 'data-action': `move-${which}`, 'aria-label': t(words), title: t(words) }, glyph);
        b.addEventListener('click', () => actions.move(which, by));
        pad.appendChild(b);
      }
      l.append(box, ` ${t(which === 'ruler' ? 'tools.ruler' : 'tools.protractor')}`);
      ov.append(l, pad);
    }
  }

  /** Shows the server's status: the gravity preset that matches g, the damping on the friction slider. */
  sync(s: Status): void {
    const match = GRAVITY_PRESETS.find(([, g]) => g === s.params.g);
    if (this.mysteryG !== null && s.params.g !== this.mysteryG) this.endMystery(); // g changed by other means
    if (document.activeElement !== this.gravity) this.gravity.value = this.mysteryG !== null ? 'mystery' : match ? String(match[1]) : '';
    const c = s.model_params?.['damping'];
    if (document.activeElement !== this.friction) {
      this.friction.value = String(c ?? 0);
      this.friction.disabled = c === undefined && s.model !== 'ideal';
      this.frictionValue.textContent = `${(c ?? 0).toFixed(2)} 1/s`;
    }
  }

  /** The readouts at the drawn frame (10 times a second). */
  update(x: readonly [number, number, number] | null, tNow: number | null, speed = 0): void {
    if (tNow !== null) this.now = tNow;
    this.listen(speed);
    const angles = x === null ? null : sphericalAngles(x as [number, number, number]);
    const text = angles === null ? '—' : `θ = ${(angles.theta * DEG).toFixed(1)}°   φ = ${(angles.phi * DEG).toFixed(1)}°`;
    if (this.angleText.textContent !== text) this.angleText.textContent = text;
    const w = `${this.stopwatch.reading(this.now).toFixed(3)} s`;
    if (this.watchText.textContent !== w) this.watchText.textContent = w;
    const laps = this.stopwatch.laps.map((v) => `${v.toFixed(3)} s`).join('|');
    if (this.lapList.dataset['shown'] !== laps) {
      this.lapList.dataset['shown'] = laps;
      this.lapList.replaceChildren(...this.stopwatch.laps.map((v) => el('li', {}, `${v.toFixed(3)} s`)));
    }
    this.fillPeriod();
  }

  private fillPeriod(): void {
    const m = this.store.periodTimer.reading();
    const theory = m.kind === 'swing' && m.amplitude !== null ? swingTheoryFor(this.store.status, m.amplitude) : null;
    const c = periodComparison(m, this.store.exact, theory);
    const pct = ([a, b]: [number | null, number | null]) => (a === null || b === null || b === 0 ? '' : `${(((a - b) / b) * 100).toFixed(2)} %`);
    const deg = (v: number | null) => (v === null ? '—' : (v * DEG).toFixed(2));
    const kind =
      m.kind === null ? t('tools.kindNone') : m.kind === 'orbit' ? t('tools.kindOrbit') : m.lowPerPeriod === 1 ? t('tools.kindOver') : t('tools.kindSwing');
    const reference = this.store.exact !== null ? t('tools.exact') : t('tools.theory');
    const rows: [string, string, string, string, string][] = [
      ['head', '', t('tools.measured'), reference, t('tools.difference')],
      ['kind', t('tools.motion'), kind, '', ''],
    ];
    if (c.swing) {
      rows.push(['period', t('tools.periodSwing'), fmt(c.period[0], 5), fmt(c.period[1], 5), pct(c.period)]);
      rows.push(['amplitude', t('tools.amplitude'), deg(m.amplitude), '', '']);
    } else {
      rows.push(['period', t('tools.periodZ'), fmt(c.period[0], 5), fmt(c.period[1], 5), pct(c.period)]);
      rows.push(['advance', t('tools.advance'), deg(c.advance[0]), deg(c.advance[1]), pct(c.advance)]);
      rows.push(['precession', t('tools.precession'), deg(c.precession[0]), deg(c.precession[1]), '']);
      rows.push(['band', t('tools.band'), m.thetaMin === null ? '—' : `${deg(m.thetaMin)} … ${deg(m.thetaMax)}`, '', '']);
    }
    const table = this.periodTable;
    while (table.rows.length > rows.length) table.deleteRow(-1);
    rows.forEach(([name, ...r], i) => {
      const tr = table.rows[i] ?? table.insertRow();
      tr.dataset['row'] = name;
      while (tr.cells.length < 4) tr.insertCell();
      r.forEach((v, k) => {
        const cell = tr.cells[k];
        if (cell && cell.textContent !== v) cell.textContent = v;
      });
    });
    const caption = m.intervals === 0 ? t('tools.periodWait') : t(c.swing ? 'tools.periodCount' : 'tools.periodCountZ', { n: m.intervals });
    if (table.caption?.textContent !== caption) table.createCaption().textContent = caption;
    table.dataset['period'] = m.period === null ? '' : String(m.period);
    table.dataset['kind'] = m.kind ?? '';
  }
}

/** The theory's swing period (`swingTheory`) for the current model, where it applies: the ideal pendulum
 *  (before the server's exact value arrives) and the `damped` model with linear friction only (no drag, no
 *  forcing, gravity straight down); else null. */
export function swingTheoryFor(status: Status | null, amplitude: number): number | null {
  if (status === null) return null;
  const mp = status.model_params ?? {};
  const zero = (k: string) => (mp[k] ?? 0) === 0;
  if (status.model === 'damped' && !(zero('drag') && zero('forcing_amplitude') && zero('gravity_x') && zero('gravity_y'))) return null;
  if (status.model !== 'ideal' && status.model !== 'damped') return null;
  return swingTheory(status.params.length, status.params.g, mp['damping'] ?? 0, amplitude);
}
