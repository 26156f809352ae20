// A measured data file fitted by the server (POST /api/fit, docs/fit.md "In the lab", docs/web.md): the
// request body, the answer read and checked, and the fitted scenario as the commands that load it into the
// running session (the same path as a shared link: url.ts's commandsFor). No DOM, no physics: the server
// parses the file (pendulab.fitting.table) and fits it (pl.fit). SI units.
import type { Command, ModelParams, Vec3 } from './protocol';
import { commandsFor } from './url';
import type { UrlScenario } from './url';

/** Largest data file the server fits [bytes] (python/pendulab/server/fit.py, MAX_FIT_BYTES). */
export const MAX_FIT_BYTES = 2 * 2 ** 20;

/** The models the fit handles (pendulab.fitting.problem.ROD_MODELS: the lab runs the spring, but fits rods only). */
export const FIT_MODELS = ['damped', 'ideal', 'rotating', 'slewing', 'vibrating'] as const;

/** Body of POST /api/fit. */
export interface FitRequest {
  csv: string;
  name: string;
  model: string;
  fit?: string[];
}

/** A line of the fit's answer as a message key with values (python/pendulab/server/fit_words.py; the page
 *  words it: i18n/fitwords.ts), with the server's English `text` where it has one, and the keyed clauses
 *  a warning carries after its own words (`clauses`: the band scan's power, the damping law's hint). */
export interface KeyedLine {
  key: string | null;
  values: Record<string, string>;
  text?: string;
  clauses?: KeyedLine[];
}

/** One fitted parameter: value and standard error (null: the data do not determine it) in `unit`; `reason`
 *  why it is not determined (keyed). */
export interface FittedParam {
  value: number;
  stderr: number | null;
  unit: string;
  determined: boolean;
  reason?: KeyedLine;
}

/** The fitted scenario as GET /api/scenarios describes one. */
export interface FittedLab {
  title: string | null;
  params: { length: number; mass: number; g: number };
  model: string;
  model_params: ModelParams;
  start: { x: Vec3; v: Vec3 };
  method: string;
  dt: number;
}

/** The measured path: bob positions relative to the fitted pivot [m] at times [s] from the first sample. */
export interface MeasuredPath {
  t: number[];
  x: Vec3[];
  points: number;
}

/** The answer of POST /api/fit (the fields the page uses). */
export interface FitAnswer {
  report: string;
  warnings: string[];
  /** The warnings keyed (one per warning, in order). */
  notes: KeyedLine[];
  /** The report's lines keyed (the parameters are `params`). */
  items: KeyedLine[];
  params: Record<string, FittedParam>;
  converged: boolean;
  scenario_toml: string;
  lab: FittedLab | null;
  measured: MeasuredPath | null;
}

/** The request for file `name` with text `csv`, or a sentence saying why it is not sent. `fitText`: the
 *  parameters to fit, comma or space separated (empty: the server's default for the data). */
export function fitRequest(name: string, csv: string, size: number, model: string, fitText: string): FitRequest | string {
  if (size > MAX_FIT_BYTES) {
    return `${name}: ${(size / 2 ** 20).toFixed(1)} MiB; the lab fits files of at most ${MAX_FIT_BYTES / 2 ** 20} MiB (use pendulab fit for larger ones)`;
  }
  if (csv.trim() === '') return `${name}: the file is empty`;
  const req: FitRequest = { csv, name, model };
  const names = fitText.split(/[\s,]+/).filter((s) => s !== '');
  if (names.length > 0) req.fit = names;
  return req;
}

const isNum = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v);
const isVec3 = (v: unknown): v is Vec3 => Array.isArray(v) && v.length === 3 && v.every(isNum);

/** A keyed line as the server sent it, or null when malformed (values other than strings are dropped). */
export function readKeyed(raw: unknown): KeyedLine | null {
  if (typeof raw !== 'object' || raw === null) return null;
  const r = raw as Record<string, unknown>;
  const key = r['key'];
  if (key !== null && typeof key !== 'string') return null;
  const values: Record<string, string> = {};
  if (typeof r['values'] === 'object' && r['values'] !== null) {
    for (const [k, v] of Object.entries(r['values'] as Record<string, unknown>)) if (typeof v === 'string') values[k] = v;
  }
  const line: KeyedLine = { key, values };
  if (typeof r['text'] === 'string') line.text = r['text'];
  if (Array.isArray(r['clauses'])) line.clauses = r['clauses'].map(readKeyed).filter((l): l is KeyedLine => l !== null);
  return line;
}

const keyedList = (raw: unknown): KeyedLine[] => (Array.isArray(raw) ? raw.map(readKeyed).filter((l): l is KeyedLine => l !== null) : []);

/** The server's answer checked (a malformed one is a sentence, never a half-drawn path). */
export function readFitAnswer(raw: unknown): FitAnswer | string {
  if (typeof raw !== 'object' || raw === null) return 'the fit answer is not an object';
  const a = raw as Record<string, unknown>;
  if (typeof a['report'] !== 'string' || typeof a['scenario_toml'] !== 'string') return 'the fit answer has no report';
  const m = a['measured'];
  if (m !== null && m !== undefined) {
    const path = m as Record<string, unknown>;
    const t = path['t'];
    const x = path['x'];
    if (!Array.isArray(t) || !Array.isArray(x) || t.length !== x.length || !t.every(isNum) || !x.every(isVec3)) {
      return 'the fit answer has a malformed measured path';
    }
  }
  return {
    report: a['report'],
    warnings: Array.isArray(a['warnings']) ? a['warnings'].filter((w): w is string => typeof w === 'string') : [],
    notes: keyedList(a['notes']),
    items: keyedList(a['items']),
    params: (a['params'] ?? {}) as Record<string, FittedParam>,
    converged: a['converged'] === true,
    scenario_toml: a['scenario_toml'],
    lab: (a['lab'] ?? null) as FittedLab | null,
    measured: (m ?? null) as MeasuredPath | null,
  };
}

/** The commands that put the running session into the fitted scenario (model and its parameters, l, m,
 *  g, method, dt, start; then reset to it): the fitted motion starts where the data start. */
export function loadCommands(lab: FittedLab): Command[] {
  const u: UrlScenario = {
    model: lab.model,
    modelParams: { ...lab.model_params },
    length: lab.params.length,
    mass: lab.params.mass,
    g: lab.params.g,
    method: lab.method,
    dt: lab.dt,
    x: lab.start.x,
    v: lab.start.v,
  };
  return commandsFor(u);
}
