// The scenario in the page's URL (no DOM): opening a shared link reproduces the motion exactly.
//
// Query keys: s (example name), model (a registry name), mp (the model's own parameters, name:value pairs,
// comma-separated, SI units), l [m], m [kg], g [m/s²], method, dt [s], ts (time scale), x, v (the start:
// three numbers each, comma-separated, in m and m/s), paused (1). Numbers are written with JavaScript's
// shortest round-trip form, so every float64 reads back bit for bit.
import type { Command, ModelParams, Status, Vec3 } from './protocol';

export interface UrlScenario {
  scenario?: string;
  model?: string;
  modelParams?: ModelParams;
  length?: number;
  mass?: number;
  g?: number;
  method?: string;
  dt?: number;
  timeScale?: number;
  x?: Vec3;
  v?: Vec3;
  paused?: boolean;
}

function num(n: number): string {
  return Object.is(n, -0) ? '-0' : String(n);
}

/** The query string (without '?') for a scenario. */
export function encodeUrl(u: UrlScenario): string {
  const q = new URLSearchParams();
  if (u.scenario !== undefined) q.set('s', u.scenario);
  if (u.model !== undefined) q.set('model', u.model);
  if (u.modelParams !== undefined && Object.keys(u.modelParams).length > 0) {
    q.set('mp', Object.entries(u.modelParams).map(([k, v]) => `${k}:${num(v)}`).join(','));
  }
  if (u.length !== undefined) q.set('l', num(u.length));
  if (u.mass !== undefined) q.set('m', num(u.mass));
  if (u.g !== undefined) q.set('g', num(u.g));
  if (u.method !== undefined) q.set('method', u.method);
  if (u.dt !== undefined) q.set('dt', num(u.dt));
  if (u.timeScale !== undefined) q.set('ts', num(u.timeScale));
  if (u.x !== undefined) q.set('x', u.x.map(num).join(','));
  if (u.v !== undefined) q.set('v', u.v.map(num).join(','));
  if (u.paused === true) q.set('paused', '1');
  return q.toString();
}

const NAME = /^[A-Za-z0-9_.-]{1,100}$/;

function parseNumber(text: string): number | null {
  if (!/^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(text.trim())) return null;
  const n = Number(text);
  return Number.isFinite(n) ? n : null;
}

/** The scenario in a query string, and one message per value that could not be read (those are left out;
 *  the server still checks ranges and that x, v lie on TS²). */
export function decodeUrl(query: string): { value: UrlScenario; problems: string[] } {
  const q = new URLSearchParams(query.startsWith('?') ? query.slice(1) : query);
  const value: UrlScenario = {};
  const problems: string[] = [];
  const known = new Set(['s', 'model', 'mp', 'l', 'm', 'g', 'method', 'dt', 'ts', 'x', 'v', 'paused', 'lang']);
  for (const key of q.keys()) if (!known.has(key)) problems.push(`unknown URL key ${key}`);
  const name = (key: string): string | undefined => {
    const t = q.get(key);
    if (t === null) return undefined;
    if (!NAME.test(t)) {
      problems.push(`${key} = ${JSON.stringify(t)} is not a name`);
      return undefined;
    }
    return t;
  };
  const number = (key: string): number | undefined => {
    const t = q.get(key);
    if (t === null) return undefined;
    const n = parseNumber(t);
    if (n === null) problems.push(`${key} = ${JSON.stringify(t)} is not a finite number`);
    return n ?? undefined;
  };
  const vec = (key: string): Vec3 | undefined => {
    const t = q.get(key);
    if (t === null) return undefined;
    const parts = t.split(',').map(parseNumber);
    if (parts.length !== 3 || parts.some((p) => p === null)) {
      problems.push(`${key} = ${JSON.stringify(t)} is not three finite numbers`);
      return undefined;
    }
    return parts as Vec3;
  };
  const s = name('s');
  if (s !== undefined) value.scenario = s;
  const model = name('model');
  if (model !== undefined) value.model = model;
  const mp = q.get('mp');
  if (mp !== null) {
    const params: ModelParams = {};
    for (const pair of mp.split(',')) {
      const [k, v, ...rest] = pair.split(':');
      const n = v === undefined ? null : parseNumber(v);
      if (k === undefined || !/^[A-Za-z_][A-Za-z0-9_]{0,40}$/.test(k) || n === null || rest.length > 0) {
        problems.push(`mp: ${JSON.stringify(pair)} is not name:number`);
        continue;
      }
      params[k] = n;
    }
    if (Object.keys(params).length > 0) value.modelParams = params;
  }
  const l = number('l');
  if (l !== undefined) value.length = l;
  const m = number('m');
  if (m !== undefined) value.mass = m;
  const g = number('g');
  if (g !== undefined) value.g = g;
  const method = name('method');
  if (method !== undefined) value.method = method;
  const dt = number('dt');
  if (dt !== undefined) value.dt = dt;
  const ts = number('ts');
  if (ts !== undefined) value.timeScale = ts;
  const x = vec('x');
  const v = vec('v');
  if ((x === undefined) !== (v === undefined) && problems.length === 0) {
    problems.push('the start needs both x and v');
  } else if (x !== undefined && v !== undefined) {
    value.x = x;
    value.v = v;
  }
  const paused = q.get('paused');
  if (paused !== null) value.paused = paused === '1' || paused === 'true';
  return { value, problems };
}

/** What the URL should say for a status (the scenario as it stands: parameters, method, start). */
export function fromStatus(s: Status): UrlScenario {
  const u: UrlScenario = {
    model: s.model,
    length: s.params.length,
    mass: s.params.mass,
    g: s.params.g,
    method: s.method,
    dt: s.dt,
    timeScale: s.time_scale,
    x: s.start.x,
    v: s.start.v,
  };
  if (s.scenario !== null) u.scenario = s.scenario;
  if (Object.keys(s.model_params).length > 0) u.modelParams = { ...s.model_params };
  if (s.paused) u.paused = true;
  return u;
}

/** The commands that put a fresh session into the URL's scenario (in this order: scenario, model and its
 *  parameters, parameters, method, time scale, start, then reset to t0 and pause if asked). */
export function commandsFor(u: UrlScenario): Command[] {
  const out: Command[] = [];
  if (u.scenario !== undefined) out.push({ type: 'load_scenario', name: u.scenario });
  if (u.model !== undefined) out.push({ type: 'set_model', model: u.model, params: { ...u.modelParams } });
  const params: { type: 'set_params'; length?: number; mass?: number; g?: number } = { type: 'set_params' };
  if (u.length !== undefined) params.length = u.length;
  if (u.mass !== undefined) params.mass = u.mass;
  if (u.g !== undefined) params.g = u.g;
  if (Object.keys(params).length > 1) out.push(params);
  const method: { type: 'set_method'; method?: string; dt?: number } = { type: 'set_method' };
  if (u.method !== undefined) method.method = u.method;
  if (u.dt !== undefined) method.dt = u.dt;
  if (Object.keys(method).length > 1) out.push(method);
  if (u.timeScale !== undefined) out.push({ type: 'set_time_scale', time_scale: u.timeScale });
  if (u.x !== undefined && u.v !== undefined) out.push({ type: 'set_state', x: u.x, v: u.v });
  if (out.length > 0) out.push({ type: 'reset' });
  if (u.paused === true) out.push({ type: 'pause' });
  return out;
}
