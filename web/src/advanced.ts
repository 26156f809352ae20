// The advanced layer (issue 28; docs/web.md, "Languages"): formula numbers (T-7.1, §2 of docs/theory.md)
// and the physicist's extra rows belong to it. Off (the default), every tooltip of the page is shown without
// them — a MutationObserver keeps new and changed tooltips plain — and elements marked `data-advanced` are
// hidden (body class `advanced` shows them). On, the tooltips are shown in full. The choice is kept in the
// browser (localStorage `pendulab.advanced`). `stripFormulaRefs` is pure and unit-tested.

/** `text` without formula references: "(T-7.1)", "T-2.4", "(docs/theory.md §3)", "§2", "Holm's Figure 2"
 *  kept; the spaces and punctuation left behind tidied. */
export function stripFormulaRefs(text: string): string {
  return text
    .replace(/\s*\((?:docs\/theory\.md\s*)?(?:T-\d+\.\d+|§\s?\d+)(?:[,;]\s*(?:T-\d+\.\d+|§\s?\d+))*\)/g, '')
    .replace(/\s*(?:docs\/theory\.md\s*)?(?:T-\d+\.\d+|§\s?\d+)/g, '')
    .replace(/\s+([,;.:)])/g, '$1')
    .replace(/[,;]+\)/g, ')')
    .replace(/\(\s*\)/g, '')
    .replace(/\s{2,}/g, ' ')
    .trim();
}

let advanced = false;

/** Whether the advanced layer is shown. */
export function isAdvanced(): boolean {
  return advanced;
}

function apply(el: Element): void {
  if (!(el instanceof HTMLElement) || !el.hasAttribute('title')) return;
  const cur = el.title;
  if (cur !== el.dataset['titleShown']) el.dataset['titleFull'] = cur; // set anew by the page
  const full = el.dataset['titleFull'] ?? cur;
  const want = advanced ? full : stripFormulaRefs(full);
  el.dataset['titleShown'] = want;
  if (cur !== want) el.title = want;
}

function applyAll(root: ParentNode): void {
  if (root instanceof Element) apply(root);
  for (const el of root.querySelectorAll('[title]')) apply(el);
}

/** Shows (`on`) or hides the advanced layer, and keeps the page's tooltips to it from now on. */
export function setAdvanced(on: boolean): void {
  advanced = on;
  document.body.classList.toggle('advanced', on);
  applyAll(document.body);
}

/** Starts the layer as stored in the browser and watches the page's tooltips. */
export function initAdvanced(): void {
  let stored = false;
  try {
    stored = window.localStorage?.getItem('pendulab.advanced') === '1';
  } catch {
    stored = false;
  }
  setAdvanced(stored);
  new MutationObserver((records) => {
    for (const r of records) {
      if (r.type === 'attributes' && r.target instanceof Element) apply(r.target);
      for (const n of r.addedNodes) if (n instanceof Element) applyAll(n);
    }
  }).observe(document.body, { subtree: true, childList: true, attributes: true, attributeFilter: ['title'] });
}

/** Stores the choice and shows it. */
export function chooseAdvanced(on: boolean): void {
  try {
    window.localStorage?.setItem('pendulab.advanced', on ? '1' : '0');
  } catch {
    // a browser without storage: the choice lasts this page
  }
  setAdvanced(on);
}
