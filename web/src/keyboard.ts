// Keyboard access (docs/web.md, "Keyboard"): Space start/pause, R reset, S step, ? the help overlay (Esc
// closes it), and on a focused slider the arrows (one step), Page Up/Down (ten steps), Home/End (the
// slider's ends). lil-gui's sliders are plain elements: `accessibleSliders` makes them focusable ARIA
// sliders with labels for screen readers. The key → action table is pure (unit-tested).
import type GUI from 'lil-gui';

export type Shortcut = 'run' | 'reset' | 'step' | 'help' | 'close';

/** The action of a key pressed outside a text field, or null. */
export function shortcutFor(key: string, modifiers: boolean): Shortcut | null {
  if (modifiers) return null;
  switch (key) {
    case ' ':
    case 'Spacebar':
      return 'run';
    case 'r':
    case 'R':
      return 'reset';
    case 's':
    case 'S':
      return 'step';
    case '?':
      return 'help';
    case 'Escape':
      return 'close';
    default:
      return null;
  }
}

/** How many slider steps a key moves (±Infinity: to the end), or null for other keys. */
export function sliderSteps(key: string): number | null {
  switch (key) {
    case 'ArrowUp':
    case 'ArrowRight':
      return 1;
    case 'ArrowDown':
    case 'ArrowLeft':
      return -1;
    case 'PageUp':
      return 10;
    case 'PageDown':
      return -10;
    case 'Home':
      return -Infinity;
    case 'End':
      return Infinity;
    default:
      return null;
  }
}

/** Whether the key `key` pressed in `target` belongs to it (text, numbers, selects, sliders; Space on a
 *  button or a check box, which it presses) rather than to the lab. */
export function ownsKeys(target: EventTarget | null, key = ''): boolean {
  if (typeof HTMLElement === 'undefined' || !(target instanceof HTMLElement)) return false;
  if (key === ' ' && (target instanceof HTMLButtonElement || (target instanceof HTMLInputElement && ['checkbox', 'radio', 'button'].includes(target.type)))) return true;
  if (target.isContentEditable) return true;
  if (target instanceof HTMLSelectElement || target instanceof HTMLTextAreaElement) return true;
  if (target instanceof HTMLInputElement) return !['checkbox', 'radio', 'button'].includes(target.type);
  return target.getAttribute('role') === 'slider';
}

interface NumberControllerLike {
  $slider?: HTMLElement;
  _min?: number;
  _max?: number;
  _step?: number;
  domElement: HTMLElement;
  getValue(): unknown;
  setValue(v: number): unknown;
  $name: HTMLElement;
}

/** Makes every lil-gui slider under `gui` focusable and keyboard-driven, with role, label and value for
 *  screen readers. Safe to call again (folders are rebuilt when the model changes). */
/** A number as an ARIA value: plain decimal notation ("0.000000001", not "1e-9", which axe-core reports as an
 *  invalid aria-valuemin: a damped model's friction_speed slider starts at 1e-9). */
export function ariaNumber(v: unknown): string {
  const n = Number(v);
  return Number.isFinite(n) ? n.toLocaleString('en-US', { useGrouping: false, maximumFractionDigits: 20 }) : String(v);
}

export function accessibleSliders(gui: GUI): void {
  for (const c of gui.controllersRecursive() as unknown as NumberControllerLike[]) {
    const s = c.$slider;
    if (s === undefined) continue;
    s.setAttribute('aria-valuenow', ariaNumber(c.getValue()));
    if (s.dataset['keys'] === '1') continue;
    s.dataset['keys'] = '1';
    s.tabIndex = 0;
    s.setAttribute('role', 'slider');
    s.setAttribute('aria-label', c.$name.textContent ?? '');
    if (c._min !== undefined) s.setAttribute('aria-valuemin', ariaNumber(c._min));
    if (c._max !== undefined) s.setAttribute('aria-valuemax', ariaNumber(c._max));
    s.addEventListener('keydown', (e) => {
      const n = sliderSteps(e.key);
      if (n === null) return;
      e.preventDefault();
      e.stopPropagation();
      const [lo, hi, step] = [c._min ?? -Infinity, c._max ?? Infinity, c._step ?? 0.01];
      const v = Number(c.getValue());
      const next = n === Infinity ? hi : n === -Infinity ? lo : Math.min(hi, Math.max(lo, v + n * step));
      if (Number.isFinite(next)) c.setValue(+next.toPrecision(12));
      s.setAttribute('aria-valuenow', ariaNumber(c.getValue()));
    });
  }
}

/** What a key does on the focused 3-D view (issue 28: the view and the bob by keyboard): the arrows turn the
 *  camera (5° a press), + and − zoom, Shift + ← → moves the bob's start by ∓1° of θ, or null. */
export function viewKey(key: string, shift: boolean): { orbit: [number, number]; zoom: number } | { bob: number } | null {
  const step = (5 * Math.PI) / 180;
  if (shift && key === 'ArrowLeft') return { bob: -1 };
  if (shift && key === 'ArrowRight') return { bob: 1 };
  switch (key) {
    case 'ArrowLeft':
      return { orbit: [-step, 0], zoom: 1 };
    case 'ArrowRight':
      return { orbit: [step, 0], zoom: 1 };
    case 'ArrowUp':
      return { orbit: [0, step], zoom: 1 };
    case 'ArrowDown':
      return { orbit: [0, -step], zoom: 1 };
    case '+':
    case '=':
      return { orbit: [0, 0], zoom: 1 / 1.1 };
    case '-':
      return { orbit: [0, 0], zoom: 1.1 };
    default:
      return null;
  }
}
