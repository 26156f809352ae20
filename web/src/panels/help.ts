// The `?` overlay (docs/web.md, "Keyboard"): the keyboard shortcuts and the colour key of the scene (the
// vectors, the bob and its trail, the second pendulum). A modal dialog over the page while open; Esc, the
// close button or `?` closes it and gives the focus back; while it is open the focus stays in it.
import { ARROW_COLORS } from '../scene/options';
import type { VectorName } from '../scene/vectors';
import { t } from '../i18n';
import type { Key } from '../i18n';

const hex = (c: number) => `#${c.toString(16).padStart(6, '0')}`;

export const VECTOR_WORDS: Record<VectorName, Key> = {
  velocity: 'vec.velocity',
  momentum: 'vec.momentum',
  gravity: 'vec.gravity',
  tension: 'vec.tension',
  net: 'vec.net',
  angularMomentum: 'vec.angularMomentum',
  torque: 'vec.torque',
};

export class HelpOverlay {
  private returnFocus: HTMLElement | null = null;

  constructor(private readonly el: HTMLElement) {
    el.setAttribute('aria-label', t('help.title'));
    const box = document.createElement('div');
    box.className = 'help-box';
    const h = document.createElement('h2');
    h.textContent = t('help.title');
    const keys = document.createElement('table');
    const rows: [string, Key][] = [
      [t('key.space'), 'help.space'],
      ['R', 'help.r'],
      ['S', 'help.s'],
      ['← → ↑ ↓', 'help.arrows'],
      [t('key.page'), 'help.page'],
      ['← → ↑ ↓ / + −', 'help.camera'],
      [`${t('key.shift')} + ← →`, 'help.bobKeys'],
      ['D', 'help.describe'],
      ['Tab', 'help.tab'],
      ['?', 'help.help'],
      ['Esc', 'help.esc'],
    ];
    for (const [k, what] of rows) {
      const tr = keys.insertRow();
      const kc = tr.insertCell();
      const kbd = document.createElement('kbd');
      kbd.textContent = k;
      kc.appendChild(kbd);
      tr.insertCell().textContent = t(what);
    }
    const h3 = document.createElement('h3');
    h3.textContent = t('help.colours');
    const key = document.createElement('ul');
    key.className = 'colour-key';
    const swatches: [string, string][] = [
      ['#ff8c42', t('help.bob')],
      ['#59c3ff', t('help.trail')],
      ['#c8f560', t('help.twin')],
      ...(Object.entries(VECTOR_WORDS) as [VectorName, Key][]).map(([n, w]): [string, string] => [hex(ARROW_COLORS[n]), t(w)]),
      ['#e6d3a3', t('help.ruler')],
    ];
    for (const [colour, words] of swatches) {
      const li = document.createElement('li');
      const sw = document.createElement('span');
      sw.className = 'swatch';
      sw.style.background = colour;
      li.append(sw, ` ${words}`);
      key.appendChild(li);
    }
    const close = document.createElement('button');
    close.type = 'button';
    close.dataset['action'] = 'help-close';
    close.textContent = t('help.close');
    close.addEventListener('click', () => this.toggle(false));
    box.append(h, keys, h3, key, close);
    el.appendChild(box);
    el.addEventListener('click', (e) => e.target === el && this.toggle(false));
    // the focus stays in the dialog while it is open: Tab and Shift+Tab cycle through its controls
    el.addEventListener('keydown', (e) => {
      if (e.key !== 'Tab') return;
      const items = [...el.querySelectorAll<HTMLElement>('button, [href], input, select, [tabindex]:not([tabindex="-1"])')];
      const first = items[0];
      const last = items[items.length - 1];
      if (first === undefined || last === undefined) return;
      if (e.shiftKey && document.activeElement === first) {
        e.preventDefault();
        last.focus();
      } else if (!e.shiftKey && document.activeElement === last) {
        e.preventDefault();
        first.focus();
      }
    });
    // a focus that leaves the open dialog (a click outside it, a screen reader's jump) comes back
    document.addEventListener('focusin', (e) => {
      if (this.open && e.target instanceof Node && !el.contains(e.target)) this.el.querySelector<HTMLElement>('button')?.focus();
    });
  }

  get open(): boolean {
    return !this.el.hidden;
  }

  toggle(on = !this.open): void {
    if (on === this.open) return;
    if (on) {
      this.returnFocus = document.activeElement instanceof HTMLElement ? document.activeElement : null;
      this.el.hidden = false;
      this.el.querySelector('button')?.focus();
    } else {
      this.el.hidden = true;
      this.returnFocus?.focus();
    }
  }
}
