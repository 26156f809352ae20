// The control panel (lil-gui), generated from GET /api/schema: pendulum parameters with units and limits,
// the model picker (model.ts), integrator and step, time scale, run controls, scenario picker, view toggles
// (view.ts) and exports. It sends
// commands and shows the server's status; it holds no simulation state of its own.
import GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import type { Command, ScenarioInfo, Schema, Status } from '../protocol';
import type { ViewOptions } from '../scene/options';
import { ModelControls } from './model';
import { addParam, throttle } from './params';
import { addViewControls } from './view';
import { language, methodWords, scenarioWords, t } from '../i18n';

export interface ControlActions {
  send(cmd: Command): void;
  explain(message: string): void;
  downloadCSV(): void;
  downloadTOML(): void;
  screenshot(): void;
  copyLink(): void;
  viewChanged(view: ViewOptions, topView: boolean): void;
}

/** A folder of `gui` named `title`, its element tagged `data-folder="tag"` (the simple view's CSS keeps some). */
function taggedFolder(gui: GUI, title: string, tag: string): GUI {
  const f = gui.addFolder(title);
  f.domElement.dataset['folder'] = tag;
  return f;
}

export class Controls {
  readonly gui: GUI;
  private readonly model: Record<string, number | string | boolean | (() => void)>;
  private readonly synced: Controller[] = [];
  private runButton!: Controller;
  private readonly modelControls: ModelControls;
  private topView = false;
  /** The last status shown (a refused value's control shows its value again). */
  private status: Status | null = null;

  constructor(
    container: HTMLElement,
    schema: Schema,
    scenarios: ScenarioInfo[],
    private readonly view: ViewOptions,
    actions: ControlActions,
  ) {
    this.gui = new GUI({ container, title: t('gui.title'), width: 270 });
    const m: Record<string, number | string | boolean | (() => void)> = {};
    this.model = m;

    // --- pendulum: length, mass, g (every model has them), then the model and its own parameters ---
    const pend = taggedFolder(this.gui, t('gui.pendulum'), 'pendulum'); // the simple view keeps it and `run`
    const sendParams = throttle((name: string, value: number) => {
      actions.send({ type: 'set_params', [name]: value } as Command);
    }, 50);
    for (const p of schema.model.params) {
      const send = (v: number) => sendParams(p.name, v);
      const current = () => (this.status?.params as Record<string, number> | undefined)?.[p.name];
      this.synced.push(addParam(pend, m as Record<string, unknown>, p, send, actions.explain, current));
    }
    this.modelControls = new ModelControls(pend, schema, actions);

    // --- integrator ---
    const integ = this.gui.addFolder(t('gui.integrator')).close();
    const methodLabels: Record<string, string> = {};
    // the words a student reads ("Symplectic (RATTLE, 2nd order)"); the code name in the tooltip
    for (const info of schema.methods) methodLabels[methodWords(info.name, info.order)] = info.name;
    m['method'] = schema.methods.find((x) => x.default)?.name ?? schema.methods[0]?.name ?? 'rattle';
    const method = integ
      .add(m, 'method', methodLabels)
      .name(t('gui.method'))
      .onChange((v: string) => actions.send({ type: 'set_method', method: v }));
    // the code name for the curious; the registry's English summary only on the English page
    method.domElement.title = schema.methods.map((x) => `${methodWords(x.name, x.order)} — ${x.name}${language() === 'en' ? `: ${x.summary}` : ''}`).join('\n');
    this.synced.push(method);
    const dtLim = schema.controls.dt;
    m['dt'] = dtLim.default ?? 1e-3;
    const dt = integ
      .add(m, 'dt')
      .name('dt [s]')
      .decimals(6)
      .onFinishChange((v: number) => {
        if (v >= dtLim.min && v <= dtLim.max) actions.send({ type: 'set_method', dt: v });
        else this.refuse(actions, dt, 'dt', t('gui.dtRange', { min: dtLim.min, max: dtLim.max }));
      });
    dt.domElement.title = t('gui.dtHelp', { min: dtLim.min, max: dtLim.max });
    this.saysNotNumber(actions, dt, 'dt');
    this.synced.push(dt);

    // --- run ---
    const run = taggedFolder(this.gui, t('gui.run'), 'run');
    const tsLim = schema.controls.time_scale;
    m['time_scale'] = tsLim.default ?? 1;
    const ts = run
      .add(m, 'time_scale')
      .name(t('gui.timeScale'))
      .decimals(3)
      .onFinishChange((v: number) => {
        if (v >= tsLim.min && v <= tsLim.max) actions.send({ type: 'set_time_scale', time_scale: v });
        else this.refuse(actions, ts, 'time_scale', t('gui.tsRange', { min: tsLim.min, max: tsLim.max }));
      });
    ts.domElement.title = t('gui.tsHelp', { min: tsLim.min, max: tsLim.max });
    this.saysNotNumber(actions, ts, 'time_scale');
    this.synced.push(ts);
    m['paused'] = false;
    m['run'] = () => actions.send({ type: m['paused'] === true ? 'resume' : 'pause' });
    this.runButton = run.add(m, 'run').name(t('toolbar.pause'));
    m['stepN'] = 1;
    const stepLim = schema.controls.step_n;
    run.add(m, 'stepN', stepLim.min, Math.min(stepLim.max, 1000), 1).name(t('gui.stepN'));
    m['step'] = () => actions.send({ type: 'step', n: Math.round(Number(m['stepN'])) });
    run.add(m, 'step').name(t('toolbar.step'));
    m['reset'] = () => actions.send({ type: 'reset' });
    run.add(m, 'reset').name(t('toolbar.reset'));
    const names: Record<string, string> = {};
    // the title a class reads (the file's name is in the URL and the tooltip)
    for (const s of scenarios) if (s.error === undefined) names[scenarioWords(s.name, s.title)] = s.name;
    m['scenario'] = '';
    const scen = run
      .add(m, 'scenario', names)
      .name(t('gui.scenario'))
      .onChange((v: string) => actions.send({ type: 'load_scenario', name: v }));
    scen.domElement.title = scenarios
      .filter((s) => s.error === undefined)
      .map((s) => `${s.name}: ${scenarioWords(s.name, s.title)}`)
      .join('\n');
    this.synced.push(scen);

    // --- view ---
    addViewControls(this.gui, view, () => actions.viewChanged(this.view, this.topView), (top) => {
      this.topView = top;
    });

    // --- export ---
    const ex = this.gui.addFolder(t('gui.export')).close();
    m['csv'] = () => actions.downloadCSV();
    ex.add(m, 'csv').name(t('gui.csv')).domElement.dataset['control'] = 'csv';
    m['toml'] = () => actions.downloadTOML();
    const toml = ex.add(m, 'toml').name(t('gui.toml'));
    toml.domElement.dataset['control'] = 'toml';
    toml.domElement.title = t('gui.tomlHelp');
    m['png'] = () => actions.screenshot();
    ex.add(m, 'png').name(t('gui.png'));
    m['link'] = () => actions.copyLink();
    ex.add(m, 'link').name(t('gui.link'));
  }

  /** A typed dt or time scale refused: `message` explained, and the control `c` of `key` shows the value
   *  in effect again (the last status's; before one, the control's own), not the refused one. */
  private refuse(actions: ControlActions, c: Controller, key: 'dt' | 'time_scale', message: string): void {
    actions.explain(message);
    const value = this.status?.[key];
    if (value !== undefined) this.model[key] = value;
    c.updateDisplay();
  }

  /** The box of `c` left with no number in it (`abc`, emptied): lil-gui drops it without a word; say so
   *  and show the value in effect (captured before lil-gui's own blur puts the old value back). */
  private saysNotNumber(actions: ControlActions, c: Controller, key: 'dt' | 'time_scale'): void {
    c.domElement.addEventListener('blur', (e) => {
      const box = e.target;
      if (box instanceof HTMLInputElement && Number.isNaN(Number.parseFloat(box.value))) this.refuse(actions, c, key, t('start.notNumber', { name: key }));
    }, true);
  }

  /** Shows the server's status (without sending anything back). Fields being edited are left alone. */
  sync(s: Status): void {
    this.status = s;
    const m = this.model;
    m['length'] = s.params.length;
    m['mass'] = s.params.mass;
    m['g'] = s.params.g;
    m['method'] = s.method;
    m['dt'] = s.dt;
    m['time_scale'] = s.time_scale;
    m['paused'] = s.paused;
    m['scenario'] = s.scenario ?? '';
    for (const c of this.synced) {
      if (!c.domElement.contains(document.activeElement)) c.updateDisplay();
    }
    this.runButton.name(s.paused ? t('toolbar.start') : t('toolbar.pause'));
    this.modelControls.sync(s);
  }
}
