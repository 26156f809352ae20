// Parameter controls generated from the schema (GET /api/schema): a slider spanning ui_min … ui_max with a
// label carrying the unit, a tooltip with the description and the allowed values, and a check against the
// hard limits before anything is sent (the server checks again and explains in an error notice). No DOM
// of its own beyond lil-gui's; the checks are pure and unit-tested.
import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import type { ParamSchema } from '../protocol';
import { paramWords, t } from '../i18n';

/** A unit for display: m/s^2 → m/s², 1 → no unit. */
export function unitLabel(unit: string): string {
  return unit === '1' ? '' : unit.replace('^2', '²').replace('^3', '³');
}

/** The parameter's words in the page's language: its label (the registry's, or the name) and help. */
export function paramWordsOf(p: ParamSchema): [label: string, help: string] {
  return paramWords(p.name, p.label ?? p.name, p.description);
}

/** The control's label: `label [unit]` (the label in words; the key name goes into the tooltip). */
export function paramLabel(p: ParamSchema): string {
  const u = unitLabel(p.unit);
  const [label] = paramWordsOf(p);
  return u ? `${label} [${u}]` : label;
}

/** The allowed range in words, e.g. `0 … 1000 kg`, `≥ 0 1/s`, `any finite number`. */
export function allowedRange(p: ParamSchema): string {
  const u = unitLabel(p.unit);
  const unit = u ? ` ${u}` : '';
  if (p.min !== null && p.max !== null) return `${p.min} … ${p.max}${unit}`;
  if (p.min !== null) return `≥ ${p.min}${unit}`;
  if (p.max !== null) return `≤ ${p.max}${unit}`;
  return 'any finite number';
}

/** Null when `v` is allowed for `p`, else a sentence naming the value and what is allowed. */
export function checkParam(p: ParamSchema, v: number): string | null {
  const ok = Number.isFinite(v) && (p.min === null || v >= p.min) && (p.max === null || v <= p.max);
  if (ok) return null;
  return t('msg.notAllowed', { name: p.name, value: v, allowed: p.allowed ?? allowedRange(p), range: allowedRange(p) });
}

/** One parameter control's edits (`addParam`). A slider drag, or the slider's arrow keys, is sent as it
 *  comes (the caller throttles); a number typed into the box is sent when it is complete — Enter, or
 *  leaving the box — never the keystrokes on the way: lil-gui reports every keystroke, and typing 0.5 for
 *  the length sent 0 (refused, a red message for a value that was fine), typing −1e9 for g sent −1 (taken:
 *  the pendulum turned upside down) before the whole was refused. A refused value is explained and the
 *  control shows the value in effect again (`restore`), not the refused one. */
export class ParamEdit {
  private typed: number | null = null;

  constructor(
    private readonly p: ParamSchema,
    private readonly send: (v: number) => void,
    private readonly explain: (message: string) => void,
    private readonly restore: () => void,
  ) {}

  /** lil-gui's onChange with the new value; `typing`: the number box has the focus. */
  changed(v: number, typing: boolean): void {
    if (typing) {
      this.typed = v;
      return;
    }
    this.typed = null;
    this.commit(v);
  }

  /** lil-gui's onFinishChange (Enter, leaving the box, the end of a drag): a typed value is sent now. */
  finished(): void {
    const v = this.typed;
    this.typed = null;
    if (v !== null) this.commit(v);
  }

  /** The box left (Enter, or the focus gone) holding `text`: when lil-gui reads no number in it (`abc`, an
   *  emptied box: its parseFloat is NaN), lil-gui drops it and shows the old value again without a word;
   *  this says so and shows the value in effect. A number (even `1e999`, `12abc`) is lil-gui's, as typed. */
  left(text: string): void {
    if (!Number.isNaN(Number.parseFloat(text))) return;
    this.typed = null;
    this.explain(t('start.notNumber', { name: this.p.name }));
    this.restore();
  }

  private commit(v: number): void {
    const problem = checkParam(this.p, v);
    if (problem === null) {
      this.send(v);
      return;
    }
    this.explain(problem);
    this.restore();
  }
}

/** Adds the control of `p` (bound to obj[p.name]) to `folder`; calls `send(v)` for allowed values and
 *  `explain(message)` otherwise (`ParamEdit`), then shows `current()` again (the value in effect, from the
 *  last status; the schema's default before one). */
export function addParam(
  folder: GUI,
  obj: Record<string, unknown>,
  p: ParamSchema,
  send: (v: number) => void,
  explain: (message: string) => void,
  current: () => number | undefined,
): Controller {
  if (typeof obj[p.name] !== 'number') obj[p.name] = p.default;
  const c = folder.add(obj, p.name, p.ui_min, p.ui_max).name(paramLabel(p));
  const box = c.domElement.querySelector('input');
  const edit = new ParamEdit(p, send, explain, () => {
    obj[p.name] = current() ?? p.default;
    c.updateDisplay();
  });
  c.onChange((v: number) => edit.changed(v, box !== null && document.activeElement === box));
  c.onFinishChange(() => edit.finished());
  // captured on the control, so before lil-gui's own blur puts the old value back into the box
  c.domElement.addEventListener('blur', (e) => e.target === box && box !== null && edit.left(box.value), true);
  const [, help] = paramWordsOf(p);
  c.domElement.title = t('gui.paramHelp', { help, name: p.name, unit: p.unit, range: allowedRange(p), default: p.default });
  c.domElement.dataset['param'] = p.name;
  // the slider's step, not snapping typed values (7.292e-5 stays; lil-gui's step(step, explicit = false))
  (c as unknown as { step(step: number, explicit: boolean): unknown }).step(p.step, false);
  // lil-gui clamps a typed value to the slider's span; the span is only the slider's, the limits are the
  // schema's (checked above, and by the server), so typed values pass through unclamped (lil-gui 0.21).
  const clamped = c as unknown as { _clamp?: (v: number) => number };
  if (typeof clamped._clamp === 'function') clamped._clamp = (v: number) => v;
  return c;
}

/** Calls `fn` at most every `ms` milliseconds, always with the latest arguments (trailing call kept). */
export function throttle<A extends unknown[]>(fn: (...args: A) => void, ms: number): (...args: A) => void {
  let last = -Infinity;
  let timer: ReturnType<typeof setTimeout> | null = null;
  let pending: A | null = null;
  return (...args: A) => {
    pending = args;
    const wait = last + ms - performance.now();
    if (wait <= 0 && timer === null) {
      last = performance.now();
      fn(...args);
      pending = null;
    } else if (timer === null) {
      timer = setTimeout(
        () => {
          timer = null;
          last = performance.now();
          if (pending !== null) fn(...pending);
          pending = null;
        },
        Math.max(0, wait),
      );
    }
  };
}
