// The crane mode's panel (docs/web.md, "Crane mode"): the switch, the drive buttons (hold to drive, as the
// keys J L I K do), moves of ±5 m, stop, the shaper (off, ZV, ZVD), the rope length (the hoist winds to
// it live), the wind's speed and direction, and the sway gauge with the last move's predicted residual
// sway. It sends commands and shows the status and frames; the core computes everything. SI units (m, m/s;
// angles shown in degrees).
import type { Command, CraneStatus, Frame } from '../protocol';
import { cw } from '../i18n/cranewords';
import type { CraneWord } from '../i18n/cranewords';
import { recentMaxSway, ropeLength, swayAngle, windPolar, windVector } from './sway';

const DEG = 180 / Math.PI;
/** The gauge's full scale [degrees] and the window of the residual sway [s]. */
export const GAUGE_DEG = 15;
export const RESIDUAL_WINDOW = 10;
/** The distance [m] of the move buttons. */
export const MOVE_STEP = 5;

function el<K extends keyof HTMLElementTagNameMap>(tag: K, attrs: Record<string, string> = {}, text = ''): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text) e.textContent = text;
  return e;
}

function labelled(text: CraneWord, input: HTMLElement, help?: CraneWord): HTMLLabelElement {
  const l = el('label', { class: 'crane-row' });
  l.append(`${cw(text)} `, input);
  if (help) l.title = cw(help);
  return l;
}

export class CranePanel {
  readonly root: HTMLElement;
  readonly toggle: HTMLButtonElement;
  private readonly controls = el('div', { class: 'crane-controls' });
  private readonly shaping = el('select', { 'data-crane': 'shaping' });
  private readonly rope = el('input', { type: 'range', min: '1', max: '50', step: '0.5', 'data-crane': 'rope' });
  private readonly ropeOut = el('output');
  private readonly windSpeed = el('input', { type: 'range', min: '0', max: '30', step: '1', 'data-crane': 'wind' });
  private readonly windDir = el('input', { type: 'range', min: '0', max: '355', step: '5', 'data-crane': 'wind-dir' });
  private readonly windOut = el('output');
  private readonly gauge = el('meter', { min: '0', max: String(GAUGE_DEG), 'data-crane': 'sway' });
  private readonly swayText = el('span', { 'data-crane': 'sway-text' });
  private readonly residualText = el('span', { 'data-crane': 'residual' });
  private readonly readout = el('p', { 'data-crane': 'readout' });
  private readonly predicted = el('p', { 'data-crane': 'predicted' });
  private on = false;

  constructor(
    parent: HTMLElement,
    private readonly send: (cmd: Command) => void,
    private readonly vMax: () => number,
    private readonly gNow: () => number,
  ) {
    this.root = el('section', { class: 'tools crane', 'data-tool': 'crane' });
    this.root.appendChild(el('h3', {}, cw('title')));
    this.toggle = el('button', { type: 'button', 'data-crane': 'toggle', title: cw('onHelp') }, cw('on'));
    this.toggle.addEventListener('click', () => this.switchMode());
    this.root.append(this.toggle, this.controls);
    this.buildDrive();
    this.buildSettings();
    this.buildGauge();
    this.controls.hidden = true;
    parent.prepend(this.root);
  }

  private switchMode(): void {
    if (this.on) {
      this.send({ type: 'set_model', model: 'ideal' });
      return;
    }
    // a crane-sized start: a 10 m rope and a 1 t load hanging at rest (gravity down: 9.81 m/s² unless it
    // already pulls down), then the crane mode from there
    const g = this.gNow();
    this.send({ type: 'set_params', length: 10, mass: 1000, g: g > 0 ? g : 9.81 });
    this.send({ type: 'set_state', theta: 0, phi: 0, theta_dot: 0, phi_dot: 0 });
    this.send({ type: 'crane', on: true });
    this.send({ type: 'resume' });
  }

  /** Drives at `dir` × v_max (x, y) while held; a release stops. */
  private hold(button: HTMLButtonElement, dir: [number, number]): void {
    const go = (e: Event) => {
      e.preventDefault();
      this.drive(dir);
    };
    const stop = () => this.drive([0, 0]);
    button.addEventListener('pointerdown', go);
    button.addEventListener('pointerup', stop);
    button.addEventListener('pointerleave', (e) => e.buttons !== 0 && stop());
    button.addEventListener('keydown', (e) => (e.key === 'Enter' || e.key === ' ') && !e.repeat && go(e));
    button.addEventListener('keyup', (e) => (e.key === 'Enter' || e.key === ' ') && stop());
  }

  /** Drives the trolley at `dir` × v_max [m/s] (x, y); [0, 0] stops. */
  drive(dir: [number, number]): void {
    const v = this.vMax();
    this.send(dir[0] === 0 && dir[1] === 0 ? { type: 'crane', stop: true } : { type: 'crane', drive: [dir[0] * v, dir[1] * v] });
  }

  private buildDrive(): void {
    const row = el('div', { class: 'crane-drive', role: 'group' });
    const buttons: [string, CraneWord, [number, number]][] = [
      ['◀', 'left', [-1, 0]],
      ['▲', 'back', [0, 1]],
      ['▼', 'fwd', [0, -1]],
      ['▶', 'right', [1, 0]],
    ];
    for (const [text, word, dir] of buttons) {
      const b = el('button', { type: 'button', 'aria-label': cw(word), title: cw(word), 'data-crane': word }, text);
      this.hold(b, dir);
      row.appendChild(b);
    }
    const stop = el('button', { type: 'button', 'data-crane': 'stop' }, cw('stop'));
    stop.addEventListener('click', () => this.drive([0, 0]));
    row.appendChild(stop);
    for (const d of [-MOVE_STEP, MOVE_STEP]) {
      const b = el('button', { type: 'button', title: cw('moveHelp', { d }), 'data-crane': `move${d}` }, cw('moveBy', { d: d > 0 ? `+${d}` : d }));
      b.addEventListener('click', () => this.send({ type: 'crane', move: [d, 0] }));
      row.appendChild(b);
    }
    this.controls.appendChild(row);
  }

  private buildSettings(): void {
    const options: [string, string][] = [['0', cw('shapingOff')], ['1', 'ZV'], ['2', 'ZVD']];
    for (const [value, text] of options) this.shaping.appendChild(el('option', { value }, text));
    this.shaping.addEventListener('change', () => this.send({ type: 'set_params', params: { shaping: Number(this.shaping.value) } }));
    this.controls.appendChild(labelled('shaping', this.shaping, 'shapingHelp'));
    this.rope.addEventListener('input', () => (this.ropeOut.textContent = `${this.rope.value} m`));
    this.rope.addEventListener('change', () => this.send({ type: 'crane', rope: Number(this.rope.value) }));
    const ropeRow = labelled('rope', this.rope, 'ropeHelp');
    ropeRow.appendChild(this.ropeOut);
    this.controls.appendChild(ropeRow);
    const sendWind = () => {
      const [x, y] = windVector(Number(this.windSpeed.value), Number(this.windDir.value));
      this.windOut.textContent = `${this.windSpeed.value} m/s → ${this.windDir.value}°`;
      this.send({ type: 'set_params', params: { wind_x: x, wind_y: y } });
    };
    this.windSpeed.addEventListener('change', sendWind);
    this.windDir.addEventListener('change', sendWind);
    this.controls.append(labelled('wind', this.windSpeed, 'windHelp'), labelled('windDir', this.windDir, 'windHelp'), this.windOut);
  }

  private buildGauge(): void {
    const row = labelled('sway', this.gauge);
    row.append(' ', this.swayText);
    const res = el('p');
    res.append(`${cw('residual')}: `, this.residualText);
    this.controls.append(row, res, this.readout, this.predicted);
  }

  /** Shows the crane's status (null: not in the crane mode). Controls being edited are left alone. */
  sync(c: CraneStatus | null | undefined): void {
    this.on = c !== null && c !== undefined;
    this.controls.hidden = !this.on;
    this.toggle.textContent = cw(this.on ? 'off' : 'on');
    this.toggle.setAttribute('aria-pressed', String(this.on));
    if (!this.on || c === null || c === undefined) return;
    const idle = (e: HTMLElement) => document.activeElement !== e;
    if (idle(this.shaping)) this.shaping.value = String(['off', 'zv', 'zvd'].indexOf(c.shaping));
    if (idle(this.rope)) {
      this.rope.value = String(c.rope_target);
      this.ropeOut.textContent = `${c.rope_target} m`;
    }
    const w = windPolar(c.wind);
    if (idle(this.windSpeed) && idle(this.windDir)) {
      this.windSpeed.value = String(Math.round(w.speed));
      this.windDir.value = String(w.degrees);
      this.windOut.textContent = `${w.speed.toFixed(1)} m/s → ${w.degrees}°`;
    }
    const m = c.last_move;
    this.predicted.textContent =
      m === null
        ? ''
        : cw('predicted', { u: (m.residual_unshaped * DEG).toFixed(2), s: (m.residual_shaped * DEG).toFixed(2), shaper: m.shaping === 'off' ? 'ZVD' : m.shaping.toUpperCase() });
  }

  /** Shows the gauge from the frames (oldest first) and the latest frame. */
  show(frames: readonly Frame[], latest: Frame | null): void {
    if (!this.on || latest === null) return;
    const angle = swayAngle(latest.x) * DEG;
    this.gauge.value = Math.min(angle, GAUGE_DEG);
    this.swayText.textContent = `${angle.toFixed(2)}°`;
    this.residualText.textContent = `${(recentMaxSway(frames, RESIDUAL_WINDOW) * DEG).toFixed(2)}°`;
    const p = latest.pivot;
    this.readout.textContent = cw('readout', { x: p[0].toFixed(2), y: p[1].toFixed(2), l: ropeLength(latest.x).toFixed(2) });
  }
}
