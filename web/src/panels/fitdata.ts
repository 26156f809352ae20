// The "Measured data" section of the panel (docs/fit.md, "In the lab"): a file input that posts a CSV data
// file to POST /api/fit with the model and the parameters to fit, shows the server's report, hands the
// fitted scenario and the measured path to the page (which loads the one into the session and draws the
// other in the scene), and a button that clears the path. The checking and the commands are fitdata.ts's.
import { FIT_MODELS, MAX_FIT_BYTES, fitRequest, readFitAnswer } from '../fitdata';
import type { FitAnswer } from '../fitdata';
import { httpProblem, modelWords, t } from '../i18n';
import { fitLine, fitReportLines } from '../i18n/fitwords';

export interface FitDataActions {
  /** A fit of file `name` arrived: load its scenario, draw its measured path. */
  loaded(answer: FitAnswer, name: string): void;
  /** The measured path is to go. */
  cleared(): void;
  explain(text: string, info?: boolean): void;
}

function el<K extends keyof HTMLElementTagNameMap>(tag: K, attrs: Record<string, string> = {}, text = ''): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text) e.textContent = text;
  return e;
}

export class FitDataPanel {
  readonly input: HTMLInputElement;
  private readonly model: HTMLSelectElement;
  private readonly names: HTMLInputElement;
  private readonly clear: HTMLButtonElement;
  private readonly report: HTMLPreElement;
  private readonly warnings: HTMLUListElement;
  /** The server's full report as pendulab fit prints it (English, the code names), folded away below the
   *  report in the page's language. */
  private readonly full = el('details', { class: 'fit-full', 'data-output': 'fit-full' });
  private readonly fullText = el('pre', { class: 'fit-report' });
  private busy = false;

  constructor(parent: HTMLElement, private readonly actions: FitDataActions) {
    const s = el('section', { class: 'tools', 'data-tool': 'fit' });
    s.appendChild(el('h3', {}, t('fit.title')));
    const load = el('label');
    load.append(`${t('fit.load')} `);
    this.input = el('input', { type: 'file', accept: '.csv,.txt,.tsv,text/csv,text/plain', 'data-input': 'fit-file' });
    load.appendChild(this.input);
    load.title = t('fit.help');
    const modelLabel = el('label');
    modelLabel.append(`${t('fit.model')} `);
    this.model = el('select', { 'data-input': 'fit-model' });
    for (const m of FIT_MODELS) this.model.appendChild(el('option', { value: m }, modelWords(m, m)));
    modelLabel.appendChild(this.model);
    const namesLabel = el('label');
    namesLabel.append(`${t('fit.params')} `);
    this.names = el('input', { type: 'text', 'data-input': 'fit-params', placeholder: t('fit.paramsDefault') });
    this.names.style.width = '12em';
    namesLabel.appendChild(this.names);
    namesLabel.title = t('fit.paramsHelp');
    this.clear = el('button', { type: 'button', 'data-action': 'fit-clear' }, t('fit.clear'));
    this.clear.disabled = true;
    this.clear.addEventListener('click', () => this.reset());
    this.report = el('pre', { class: 'fit-report', 'data-output': 'fit-report', 'aria-live': 'polite' });
    this.report.hidden = true;
    // the fit's warnings (a model that does not fit the data, a parameter not determined) above the report,
    // where they cannot be missed (issue 28: an ideal fit of damped data said g = 11.0 without a word)
    this.warnings = el('ul', { class: 'fit-warnings', 'data-output': 'fit-warnings' });
    this.warnings.hidden = true;
    for (const row of [load, modelLabel, namesLabel, this.clear]) {
      const p = el('p');
      p.appendChild(row);
      s.appendChild(p);
    }
    this.full.append(el('summary', {}, t('fit.fullReport')), this.fullText);
    this.full.hidden = true;
    s.append(this.warnings, this.report, this.full);
    parent.appendChild(s);
    this.input.addEventListener('change', () => {
      const file = this.input.files?.[0];
      if (file !== undefined) void this.send(file);
    });
  }

  /** Clears the report and the measured path. */
  reset(): void {
    this.report.hidden = true;
    this.report.textContent = '';
    this.warnings.hidden = true;
    this.warnings.replaceChildren();
    this.full.hidden = true;
    this.clear.disabled = true;
    this.input.value = '';
    this.actions.cleared();
  }

  private async send(file: File): Promise<void> {
    if (this.busy) return;
    const text = file.size > MAX_FIT_BYTES ? '' : await file.text();
    const req = fitRequest(file.name, text, file.size, this.model.value, this.names.value);
    if (typeof req === 'string') return this.actions.explain(req);
    this.busy = true;
    this.input.disabled = true;
    this.report.hidden = false;
    this.report.textContent = t('fit.running', { name: file.name });
    try {
      const r = await fetch('api/fit', {
        method: 'POST',
        headers: { 'content-type': 'application/json' },
        body: JSON.stringify(req),
      });
      const raw: unknown = await r.json().catch(() => ({ detail: `HTTP ${r.status}` }));
      if (!r.ok) throw new Error(httpProblem(raw, `HTTP ${r.status}`));
      const answer = readFitAnswer(raw);
      if (typeof answer === 'string') throw new Error(answer);
      // the report and the warnings in the page's language (keyed by the server: i18n/fitwords.ts), in
      // student words; the server's own text (English, code names) folded away below
      const state = t(answer.converged ? 'fit.converged' : 'fit.notConverged');
      const notes = answer.notes.length > 0 ? answer.notes.map(fitLine) : answer.warnings;
      const lines = [...fitReportLines(answer.items, answer.params), ...notes.map((w) => `⚠ ${w}`)];
      if (answer.items.length === 0) lines.unshift(t('fit.summary', { model: modelWords(this.model.value, this.model.value), state }));
      this.fullText.textContent = answer.report;
      this.full.hidden = false;
      if (answer.measured === null) lines.push(t('fit.noPath'));
      this.report.textContent = lines.join('\n');
      // the fit's warnings above the report, where they cannot be missed
      const said = [...new Set(notes)];
      this.warnings.replaceChildren(...said.map((w) => el('li', {}, `⚠ ${w}`)));
      this.warnings.hidden = said.length === 0;
      this.clear.disabled = false;
      this.actions.loaded(answer, file.name);
    } catch (e: unknown) {
      const why = e instanceof Error ? e.message : String(e);
      this.report.textContent = `${file.name}: ${why}`;
      this.actions.explain(t('fit.failed', { why }));
    } finally {
      this.busy = false;
      this.input.disabled = false;
    }
  }
}
