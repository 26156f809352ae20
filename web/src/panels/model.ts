// The model picker (lil-gui): the core's registry as the server lists it (GET /api/schema → models) — ideal,
// damped, rotating, slewing, vibrating — and the chosen model's own parameters, with units and limits,
// generated from the schema. Choosing a model sends `set_model`; editing a parameter sends `set_params` with
// `params`, which keeps the model. The controls show the server's status and are rebuilt when the model
// changes (from here, a scenario or a shared link).
import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import type { Command, ModelParams, ModelSchema, Schema, Status } from '../protocol';
import { addParam, throttle } from './params';
import { modelHelp, modelWords, t } from '../i18n';

export interface ModelActions {
  send(cmd: Command): void;
  explain(message: string): void;
}

/** What a model picked in the lab starts with beyond the registry's defaults, so that choosing it changes
 *  something a class can see: `damped` with friction c = 0.3 1/s (the registry's default, 0, makes it the
 *  ideal pendulum — right for the Python API and scenario files, invisible in the lab). */
export const PICKED_PARAMS: Readonly<Record<string, ModelParams>> = { damped: { damping: 0.3 } };

/** The `set_model` command of the picker for model `name`. */
export function pickCommand(name: string): Command {
  const params = PICKED_PARAMS[name];
  return params ? { type: 'set_model', model: name, params: { ...params } } : { type: 'set_model', model: name };
}

/** The picker's options: `label (name)` → name (the summary, with its formula numbers, is the tooltip). */
export function modelOptions(models: readonly ModelSchema[]): Record<string, string> {
  const out: Record<string, string> = {};
  for (const m of models) out[m.label ? `${modelWords(m.name, m.label)} (${m.name})` : m.name] = m.name;
  return out;
}

export class ModelControls {
  private readonly state: { model: string } = { model: 'ideal' };
  private readonly picker: Controller;
  private paramsFolder: GUI | null = null;
  private paramControls: Controller[] = [];
  private values: Record<string, number> = {};
  /** The model parameters of the last status (a refused value's control shows its value again). */
  private inEffect: Record<string, number> | null = null;
  private shown: string | null = null;
  private readonly sendParam: (name: string, value: number) => void;

  constructor(
    private readonly parent: GUI,
    private readonly schema: Schema,
    private readonly actions: ModelActions,
  ) {
    this.picker = parent
      .add(this.state, 'model', modelOptions(schema.models))
      .name(t('gui.model'))
      .onChange((name: string) => actions.send(pickCommand(name)));
    this.picker.domElement.dataset['control'] = 'model';
    this.picker.domElement.title = [t('gui.modelsHelp'), ...schema.models.map((m) => `${modelWords(m.name, m.label ?? m.name)} (${m.name}): ${modelHelp(m.name, m.summary)}`)].join('\n');
    this.sendParam = throttle((name: string, value: number) => {
      actions.send({ type: 'set_params', params: { [name]: value } });
    }, 50);
  }

  /** The model's schema, or undefined for a name the server did not list. */
  spec(name: string): ModelSchema | undefined {
    return this.schema.models.find((m) => m.name === name);
  }

  private rebuild(name: string): void {
    this.paramsFolder?.destroy();
    this.paramsFolder = null;
    this.paramControls = [];
    this.values = {};
    this.shown = name;
    const spec = this.spec(name);
    if (spec === undefined || spec.params.length === 0) return;
    const folder = this.parent.addFolder(t('gui.modelParams', { model: modelWords(name, spec.label ?? name) }));
    for (const p of spec.params) {
      this.values[p.name] = p.default;
      const c = addParam(folder, this.values, p, (v) => this.sendParam(p.name, v), this.actions.explain, () => this.inEffect?.[p.name]);
      this.paramControls.push(c);
    }
    this.paramsFolder = folder;
  }

  /** Shows the server's model and parameters (sends nothing). Fields being edited are left alone. */
  sync(s: Status): void {
    const name = s.model ?? 'ideal';
    this.state.model = name;
    this.picker.updateDisplay();
    // a model the picker does not offer (the crane mode, entered by its own button): its name in words, not
    // lil-gui's fallback of the raw code name
    const display = (this.picker as Controller & { $display?: HTMLElement }).$display;
    if (display && !this.spec(name)) display.textContent = modelWords(name, name);
    if (this.shown !== name) this.rebuild(name);
    this.inEffect = s.model_params ?? {};
    for (const [k, v] of Object.entries(this.inEffect)) this.values[k] = v;
    for (const c of this.paramControls) {
      if (!c.domElement.contains(document.activeElement)) c.updateDisplay();
    }
  }
}
