// The page around the lab: its language and fixed texts, the message line under the view, element
// look-up and downloads. No physics and no units here (the page's units line says SI: m, s, kg, rad).
import { chooseLanguage, setLanguage, t } from '../i18n';
import { initAdvanced } from '../advanced';

/** The element with this id in index.html (an error naming the id if the page lacks it). */
export function byId(id: string): HTMLElement {
  const el = document.getElementById(id);
  if (el === null) throw new Error(`#${id} missing from index.html`);
  return el;
}

/** Saves `href` (a Blob or data URL) as the file `name`. */
export function download(name: string, href: string): void {
  const a = document.createElement('a');
  a.href = href;
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
}

/** Saves a Blob as the file `name` and releases its URL after 10 s. */
export function downloadBlob(name: string, blob: Blob): void {
  const url = URL.createObjectURL(blob);
  download(name, url);
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/** What `firstControl` asks of an element (an HTMLElement; plain objects in the unit tests). */
export interface Focusable {
  readonly classList: { contains(name: string): boolean };
  getClientRects(): { readonly length: number };
  matches(selector: string): boolean;
}

/** The elements of the settings panel that take the focus by Tab, in document order. */
export const FOCUSABLE = 'input, select, textarea, button, [tabindex]:not([tabindex="-1"])';

/** The first of `candidates` (the settings panel's focusable elements, in order) that is shown, enabled and
 *  a control — not a folder's title (lil-gui's `.lil-title`): in the simple view the length's slider. */
export function firstControl<E extends Focusable>(candidates: Iterable<E>): E | null {
  for (const e of candidates) if (!e.classList.contains('lil-title') && !e.matches(':disabled') && e.getClientRects().length > 0) return e;
  return null;
}

/** "Skip to controls" (#skip, the page's first focusable element; visually hidden until focused): Enter
 *  moves the focus past the toolbar and the tools to the first control of the settings panel (#gui), the
 *  rod length in the simple view, where about 28 Tab presses led before. Without scripts it is a plain
 *  link to #gui; with them the address keeps no #gui (the share link is the address). */
function wireSkipLink(): void {
  const skip = byId('skip');
  skip.textContent = t('page.skip');
  skip.addEventListener('click', (e) => {
    e.preventDefault();
    const target = firstControl(byId('gui').querySelectorAll<HTMLElement>(FOCUSABLE));
    target?.focus();
    target?.scrollIntoView({ block: 'nearest' });
  });
}

/** Chooses the language (the link's `lang`, the last choice, the browser's) and writes the page's fixed texts. */
export function setUpPage(): void {
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
  const regions = { tools: 'page.tools', energy: 'page.energy', data: 'page.data', plots: 'page.plots', portraits: 'page.portraits', reduced: 'page.reduced' } as const;
  for (const [id, key] of Object.entries(regions)) byId(id).setAttribute('aria-label', t(key));
  wireSkipLink();
}

/** Shows a text in the message line: a problem (red) or, with `info`, news (blue). */
export type Explain = (text: string, info?: boolean) => void;

/** The message line under the view (#message): each message shown for 6 s. */
export class MessageLine {
  private timer: ReturnType<typeof setTimeout> | null = null;

  constructor(private readonly el: HTMLElement) {}

  readonly explain: Explain = (text, info = false) => {
    this.el.textContent = text;
    this.el.classList.toggle('info', info);
    this.el.classList.add('shown');
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = setTimeout(() => this.el.classList.remove('shown'), 6000);
  };

  /** Hides news (not problems): called when the scenario changes and the news is no longer about it. */
  clearNews(): void {
    if (this.el.classList.contains('info')) this.el.classList.remove('shown');
  }
}
