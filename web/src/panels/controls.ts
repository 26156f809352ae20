// The control panel (lil-gui), generated from GET /api/schema: pendulum parameters with units and limits,
// the model picker (model.ts), integrator and step, time scale, run controls, scenario picker, view toggles
// (view.ts) and exports. It sends
// commands and shows the server's status; it holds no simulation state of its own.
import GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import type { Command, ScenarioInfo, Schema, Status } from '../protocol';
import type { ViewOptions } from '../scene/scene';
import { ModelControls } from './model';
import { addParam, throttle } from './params';
import { addViewControls } from './view';

export interface ControlActions {
  send(cmd: Command): void;
  explain(message: string): void;
  downloadCSV(): void;
  downloadTOML(): void;
  screenshot(): void;
  copyLink(): void;
  viewChanged(view: ViewOptions, topView: boolean): void;
}

export class Controls {
  readonly gui: GUI;
  private readonly model: Record<string, number | string | boolean | (() => void)>;
  private readonly synced: Controller[] = [];
  private runButton!: Controller;
  private readonly modelControls: ModelControls;
  private topView = false;

  constructor(
    container: HTMLElement,
    schema: Schema,
    scenarios: ScenarioInfo[],
    private readonly view: ViewOptions,
    actions: ControlActions,
  ) {
    this.gui = new GUI({ container, title: 'Pendulab lab', width: 270 });
    const m: Record<string, number | string | boolean | (() => void)> = {};
    this.model = m;

    // --- pendulum: length, mass, g (every model has them), then the model and its own parameters ---
    const pend = this.gui.addFolder('Pendulum');
    const sendParams = throttle((name: string, value: number) => {
      actions.send({ type: 'set_params', [name]: value } as Command);
    }, 50);
    for (const p of schema.model.params) {
      const send = (v: number) => sendParams(p.name, v);
      this.synced.push(addParam(pend, m as Record<string, unknown>, p, send, actions.explain));
    }
    this.modelControls = new ModelControls(pend, schema, actions);

    // --- integrator ---
    const integ = this.gui.addFolder('Integrator');
    const methodLabels: Record<string, string> = {};
    for (const info of schema.methods) {
      const props = [`order ${info.order}`, info.symplectic ? 'symplectic' : '', info.adaptive ? 'adaptive' : '']
        .filter(Boolean)
        .join(', ');
      methodLabels[`${info.name} (${props})`] = info.name;
    }
    m['method'] = schema.methods.find((x) => x.default)?.name ?? schema.methods[0]?.name ?? 'rattle';
    const method = integ
      .add(m, 'method', methodLabels)
      .onChange((v: string) => actions.send({ type: 'set_method', method: v }));
    method.domElement.title = schema.methods.map((x) => `${x.name}: ${x.summary}`).join('\n');
    this.synced.push(method);
    const dtLim = schema.controls.dt;
    m['dt'] = dtLim.default ?? 1e-3;
    const dt = integ
      .add(m, 'dt')
      .name('dt [s]')
      .decimals(6)
      .onFinishChange((v: number) => {
        if (!(v >= dtLim.min && v <= dtLim.max)) {
          actions.explain(`dt must be between ${dtLim.min} and ${dtLim.max} s`);
          return;
        }
        actions.send({ type: 'set_method', dt: v });
      });
    dt.domElement.title = `${dtLim.description}; ${dtLim.min} … ${dtLim.max} s (dop853 chooses its own)`;
    this.synced.push(dt);

    // --- run ---
    const run = this.gui.addFolder('Run');
    const tsLim = schema.controls.time_scale;
    m['time_scale'] = tsLim.default ?? 1;
    const ts = run
      .add(m, 'time_scale')
      .name('time scale [×]')
      .decimals(3)
      .onFinishChange((v: number) => {
        if (!(v >= tsLim.min && v <= tsLim.max)) {
          actions.explain(`the time scale must be between ${tsLim.min} and ${tsLim.max}`);
          return;
        }
        actions.send({ type: 'set_time_scale', time_scale: v });
      });
    ts.domElement.title = `${tsLim.description}; ${tsLim.min} … ${tsLim.max}`;
    this.synced.push(ts);
    m['paused'] = false;
    m['run'] = () => actions.send({ type: m['paused'] === true ? 'resume' : 'pause' });
    this.runButton = run.add(m, 'run').name('pause');
    m['stepN'] = 1;
    const stepLim = schema.controls.step_n;
    run.add(m, 'stepN', stepLim.min, Math.min(stepLim.max, 1000), 1).name('steps per step');
    m['step'] = () => actions.send({ type: 'step', n: Math.round(Number(m['stepN'])) });
    run.add(m, 'step').name('step');
    m['reset'] = () => actions.send({ type: 'reset' });
    run.add(m, 'reset').name('reset to start');
    const names: Record<string, string> = {};
    for (const s of scenarios) if (s.error === undefined) names[s.title ? `${s.name}: ${s.title}` : s.name] = s.name;
    m['scenario'] = '';
    const scen = run
      .add(m, 'scenario', names)
      .name('scenario')
      .onChange((v: string) => actions.send({ type: 'load_scenario', name: v }));
    this.synced.push(scen);

    // --- view ---
    addViewControls(this.gui, view, () => actions.viewChanged(this.view, this.topView), (top) => {
      this.topView = top;
    });

    // --- export ---
    const ex = this.gui.addFolder('Share and export').close();
    m['csv'] = () => actions.downloadCSV();
    ex.add(m, 'csv').name('download trajectory (CSV)');
    m['toml'] = () => actions.downloadTOML();
    const toml = ex.add(m, 'toml').name('download scenario (TOML)');
    toml.domElement.dataset['control'] = 'toml';
    toml.domElement.title =
      'the scenario as it stands (model, parameters, start, method) as a file for `pendulab run`';
    m['png'] = () => actions.screenshot();
    ex.add(m, 'png').name('screenshot (PNG)');
    m['link'] = () => actions.copyLink();
    ex.add(m, 'link').name('copy link to this scenario');
  }

  /** Shows the server's status (without sending anything back). Fields being edited are left alone. */
  sync(s: Status): void {
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
    this.runButton.name(s.paused ? 'start' : 'pause');
    this.modelControls.sync(s);
  }
}
