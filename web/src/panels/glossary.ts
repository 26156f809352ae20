// The glossary (issue 28; docs/web.md, "Languages"): the lab's words in a student's words, each a
// <details> element — a tap, a click or Enter opens it, and its text is on the page (a projector and a
// touch screen show what a tooltip never would) — and the switch of the advanced layer (advanced.ts:
// formula numbers in the tooltips, the physicist's extra rows). Words from the i18n tables.
import { t } from '../i18n';
import type { Key } from '../i18n';
import { chooseAdvanced, isAdvanced } from '../advanced';

/** The glossary's entries: [term, explanation] keys. */
export const GLOSSARY: readonly [Key, Key][] = [
  ['gloss.period', 'gloss.periodText'],
  ['gloss.amplitude', 'gloss.amplitudeText'],
  ['gloss.lowest', 'gloss.lowestText'],
  ['gloss.friction', 'gloss.frictionText'],
  ['gloss.gravity', 'gloss.gravityText'],
  ['gloss.energy', 'gloss.energyText'],
  ['gloss.spin', 'gloss.spinText'],
  ['gloss.precession', 'gloss.precessionText'],
  ['gloss.method', 'gloss.methodText'],
  ['gloss.drift', 'gloss.driftText'],
];

export class Glossary {
  constructor(container: HTMLElement) {
    const box = document.createElement('section');
    box.className = 'tools glossary';
    box.dataset['tool'] = 'glossary';
    const h = document.createElement('h3');
    h.textContent = t('gloss.title');
    box.appendChild(h);
    for (const [term, text] of GLOSSARY) {
      const d = document.createElement('details');
      const s = document.createElement('summary');
      s.textContent = t(term);
      const p = document.createElement('p');
      p.textContent = t(text);
      d.append(s, p);
      box.appendChild(d);
    }
    const l = document.createElement('label');
    const box2 = document.createElement('input');
    box2.type = 'checkbox';
    box2.dataset['input'] = 'advanced';
    box2.checked = isAdvanced();
    box2.addEventListener('change', () => chooseAdvanced(box2.checked));
    l.append(box2, ` ${t('gloss.advanced')}`);
    box.appendChild(l);
    container.appendChild(box);
  }
}
