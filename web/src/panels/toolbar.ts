// The toolbar at the top of the docked panel (docs/web.md, "Layout" and "Keyboard"): start/pause, reset,
// step, record, the `?` help, the language and the panel's collapse button. On a wide screen the panel
// docks on the right and collapses to this toolbar; on a phone it is a bottom sheet that does the same.
// The canvas always gets what the panel leaves (the scene resizes itself: ResizeObserver).
import { LANGUAGES, language, t } from '../i18n';
import type { Lang } from '../i18n';

/** When the panel is a bottom sheet (style.css has the same query). */
const PHONE = '(max-width: 700px), (max-aspect-ratio: 3/4)';

export interface ToolbarActions {
  run(): void;
  reset(): void;
  step(): void;
  record(): void;
  help(): void;
  language(lang: Lang): void;
  collapsed(on: boolean): void;
  /** Presentation mode (large type for a projector) switched on or off. */
  present(on: boolean): void;
  /** The simple view (the classroom tools only) switched on or off. */
  simple(on: boolean): void;
}

/** A button's accessible name: its tooltip, led by its visible words when the tooltip does not contain them
 *  (WCAG 2.5.3 "label in name", axe's label-content-name-mismatch: "● Aufnahme" beside "Video aufnehmen"
 *  becomes "Aufnahme: Video aufnehmen (WebM)"; "A⁺" becomes "A⁺: mode présentation …"). */
export function accessibleName(text: string, title: string): string {
  const shown = text.replace(/^[^\p{L}\p{N}]+/u, '').trim();
  const words = (s: string) => s.toLocaleLowerCase().split(/[^\p{L}\p{N}]+/u).filter(Boolean);
  const have = words(title);
  const inside = (w: string[]) => w.length > 0 && have.some((_, i) => w.every((x, k) => have[i + k] === x));
  return shown === '' || inside(words(shown)) ? title : `${shown}: ${title}`;
}

function button(action: string, text: string, title: string, open = false): HTMLButtonElement {
  const b = document.createElement('button');
  b.type = 'button';
  b.dataset['action'] = action;
  b.textContent = text;
  b.title = title;
  b.setAttribute('aria-label', accessibleName(text, title));
  if (open) b.classList.add('when-open');
  return b;
}

export class Toolbar {
  readonly runButton: HTMLButtonElement;
  readonly recordButton: HTMLButtonElement;
  private readonly toggle: HTMLButtonElement;
  private readonly presentButton: HTMLButtonElement;
  private readonly simpleButton: HTMLButtonElement;

  /** Shows whether presentation mode is on. */
  showPresenting(on: boolean): void {
    this.presentButton.setAttribute('aria-pressed', String(on));
  }

  /** Shows whether the simple view is on. */
  showSimple(on: boolean): void {
    this.simpleButton.setAttribute('aria-pressed', String(on));
  }

  constructor(
    bar: HTMLElement,
    private readonly panel: HTMLElement,
    actions: ToolbarActions,
  ) {
    bar.setAttribute('aria-label', t('toolbar.label'));
    this.toggle = button('panel', '', t('toolbar.collapse'));
    this.toggle.setAttribute('aria-controls', 'panel-body');
    this.toggle.addEventListener('click', () => {
      this.setCollapsed(!panel.classList.contains('collapsed'));
      actions.collapsed(panel.classList.contains('collapsed'));
    });
    this.runButton = button('run', t('toolbar.pauseShort'), t('toolbar.pause'));
    this.runButton.addEventListener('click', () => actions.run());
    const reset = button('reset', t('toolbar.resetShort'), t('toolbar.reset'));
    reset.addEventListener('click', () => actions.reset());
    const step = button('step', t('toolbar.stepShort'), t('toolbar.step'));
    step.addEventListener('click', () => actions.step());
    this.recordButton = button('record', t('toolbar.recordShort'), t('toolbar.record'));
    this.recordButton.setAttribute('aria-pressed', 'false');
    this.recordButton.addEventListener('click', () => actions.record());
    const help = button('help', '?', t('toolbar.help'));
    help.addEventListener('click', () => actions.help());
    // presentation mode: large type for a projector at the back of a classroom
    this.presentButton = button('present', 'A⁺', t('toolbar.present'), true);
    this.presentButton.setAttribute('aria-pressed', 'false');
    this.presentButton.addEventListener('click', () => actions.present(this.presentButton.getAttribute('aria-pressed') !== 'true'));
    // the simple view: PhET-level tools only (the physicist's panels folded away)
    this.simpleButton = button('simple', t('toolbar.simpleShort'), t('toolbar.simple'), true);
    this.simpleButton.setAttribute('aria-pressed', 'false');
    this.simpleButton.addEventListener('click', () => actions.simple(this.simpleButton.getAttribute('aria-pressed') !== 'true'));
    const lang = document.createElement('select');
    lang.dataset['input'] = 'language';
    lang.classList.add('when-open');
    lang.setAttribute('aria-label', t('toolbar.language'));
    for (const [code, info] of Object.entries(LANGUAGES)) {
      const o = document.createElement('option');
      o.value = code;
      o.textContent = info.name;
      lang.appendChild(o);
    }
    lang.value = language();
    lang.addEventListener('change', () => actions.language(lang.value as Lang));
    bar.append(this.toggle, this.runButton, reset, step, this.recordButton, help, this.simpleButton, this.presentButton, lang);
    this.setCollapsed(false);
    // the arrow points where the panel goes: right on a wide screen, down on a phone
    window.matchMedia(PHONE).addEventListener('change', () => this.setCollapsed(panel.classList.contains('collapsed')));
  }

  setCollapsed(on: boolean): void {
    this.panel.classList.toggle('collapsed', on);
    this.toggle.setAttribute('aria-expanded', String(!on));
    const phone = window.matchMedia(PHONE).matches;
    this.toggle.textContent = phone ? (on ? '▴' : '▾') : on ? '◂' : '▸';
    this.toggle.title = on ? t('toolbar.expand') : t('toolbar.collapse');
    this.toggle.setAttribute('aria-label', this.toggle.title);
  }

  showRunning(paused: boolean): void {
    const text = paused ? t('toolbar.startShort') : t('toolbar.pauseShort');
    if (this.runButton.textContent !== text) {
      this.runButton.textContent = text;
      this.runButton.title = paused ? t('toolbar.start') : t('toolbar.pause');
      this.runButton.setAttribute('aria-label', accessibleName(text, this.runButton.title));
    }
  }

  showRecording(on: boolean): void {
    this.recordButton.setAttribute('aria-pressed', String(on));
    this.recordButton.textContent = on ? t('toolbar.recordStopShort') : t('toolbar.recordShort');
    this.recordButton.title = on ? t('toolbar.recordStop') : t('toolbar.record');
    this.recordButton.setAttribute('aria-label', accessibleName(this.recordButton.textContent, this.recordButton.title));
  }
}
