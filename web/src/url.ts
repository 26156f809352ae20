// The scenario in the page's URL (no DOM): opening a shared link reproduces the motion exactly.
//
// Query keys: s (example name), model (a registry name), mp (the model's own parameters, name:value pairs,
// comma-separated, SI units), l [m], m [kg], g [m/s²], method, dt [s], ts (time scale), x, v (the start:
// three numbers each, comma-separated, in m and m/s), paused (1). Numbers are written with JavaScript's
// shortest round-trip form, so every float64 reads back bit for bit.
//
// The whole lab (issue 28: a teacher hands out a prepared experiment): lang (the language), at [s] (the
// paused time since the start: replayed by `step` commands of the fixed-step method, which reach the same
// state bit for bit), view (the view options that differ from the defaults: `ruler`, `-trail`,
// `stereo:anaglyph`, `trailSeconds:20`), plot (the chosen plot's x,y variables) and twin (the second
// pendulum: `own:l:m:θ₀°`, `eps:ε°`, `method:name`, `damped:c`).
import type { Command, ModelParams, Status, Vec3 } from './protocol';
import type { ExtraOptions, TwinOptions } from './twin';
import { MAX_EXTRAS } from './twin';
import { t, t as tr } from './i18n'; // tr: where a local t (a URL value's text) hides t

/** A view option's value (scene.ts ViewOptions): a toggle, a number or a word (the stereo mode). */
export type ViewValue = boolean | number | string;

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
  /** The language of the page (i18n code). */
  lang?: string;
  /** The paused time since the start [s] (only with paused and a fixed-step method). */
  at?: number;
  /** View options that differ from the defaults. */
  view?: Record<string, ViewValue>;
  /** The chosen plot's variables [x, y] (variables.ts names). */
  plot?: [string, string];
  /** The second pendulum (TwinOptions without the mode `off`; angles in radians). */
  twin?: TwinOptions;
}

const DEG = 180 / Math.PI;

/** The `view` value: the options of `view` that differ from `defaults`. */
export function encodeView(view: Readonly<Record<string, ViewValue>>, defaults: Readonly<Record<string, ViewValue>>): Record<string, ViewValue> {
  const out: Record<string, ViewValue> = {};
  for (const [k, v] of Object.entries(view)) if (k in defaults && defaults[k] !== v) out[k] = v;
  return out;
}

function twinText(o: TwinOptions): string | null {
  // angles in degrees to 12 digits (15° read back is 15, not 14.999999999999998)
  const deg = (a: number) => num(Number((a * DEG).toPrecision(12)));
  // mode own: the second pendulum, then pendulums 3 and 4 after commas (l:m:θ₀ each)
  if (o.mode === 'own') return [`own:${num(o.length)}:${num(o.mass)}:${deg(o.theta)}`, ...(o.extras ?? []).map((e) => `${num(e.length)}:${num(e.mass)}:${deg(e.theta)}`)].join(',');
  if (o.mode === 'epsilon') return `eps:${deg(o.epsilon)}`;
  if (o.mode === 'method') return `method:${o.method}`;
  if (o.mode === 'damped') return `damped:${num(o.damping)}`;
  return null;
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
  if (u.at !== undefined && u.at > 0) q.set('at', num(u.at));
  if (u.view !== undefined && Object.keys(u.view).length > 0) {
    q.set('view', Object.entries(u.view).map(([k, v]) => (typeof v === 'boolean' ? (v ? k : `-${k}`) : `${k}:${typeof v === 'number' ? num(v) : v}`)).join(','));
  }
  if (u.plot !== undefined) q.set('plot', u.plot.join(','));
  const tw = u.twin === undefined ? null : twinText(u.twin);
  if (tw !== null) q.set('twin', tw);
  if (u.lang !== undefined) q.set('lang', u.lang);
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
  const known = new Set(['s', 'model', 'mp', 'l', 'm', 'g', 'method', 'dt', 'ts', 'x', 'v', 'paused', 'lang', 'at', 'view', 'plot', 'twin']);
  for (const key of q.keys()) if (!known.has(key)) problems.push(tr('url.unknownKey', { key }));
  const name = (key: string): string | undefined => {
    const t = q.get(key);
    if (t === null) return undefined;
    if (!NAME.test(t)) {
      problems.push(tr('url.notName', { key, value: JSON.stringify(t) }));
      return undefined;
    }
    return t;
  };
  const number = (key: string): number | undefined => {
    const t = q.get(key);
    if (t === null) return undefined;
    const n = parseNumber(t);
    if (n === null) problems.push(tr('url.notNumber', { key, value: JSON.stringify(t) }));
    return n ?? undefined;
  };
  const vec = (key: string): Vec3 | undefined => {
    const t = q.get(key);
    if (t === null) return undefined;
    const parts = t.split(',').map(parseNumber);
    if (parts.length !== 3 || parts.some((p) => p === null)) {
      problems.push(tr('url.notThree', { key, value: JSON.stringify(t) }));
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
        problems.push(tr('url.notPair', { value: JSON.stringify(pair) }));
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
    problems.push(tr('url.startXv'));
  } else if (x !== undefined && v !== undefined) {
    value.x = x;
    value.v = v;
  }
  const paused = q.get('paused');
  if (paused !== null) value.paused = paused === '1' || paused === 'true';
  const lang = q.get('lang');
  if (lang !== null && /^[a-z]{2}$/.test(lang)) value.lang = lang;
  const at = number('at');
  if (at !== undefined) {
    if (at >= 0 && at <= 1e6) value.at = at;
    else problems.push(tr('url.notTime', { value: JSON.stringify(q.get('at')) })); // as written: 2e6, not 2000000
  }
  const view = q.get('view');
  if (view !== null) {
    const v: Record<string, ViewValue> = {};
    for (const item of view.split(',').filter(Boolean)) {
      const m = /^(-?)([A-Za-z]{1,30})(?::([A-Za-z0-9 .+-]{1,30}))?$/.exec(item);
      if (m === null) {
        problems.push(tr('url.notView', { value: JSON.stringify(item) }));
        continue;
      }
      const [, neg, key, val] = m as unknown as [string, string, string, string | undefined];
      if (val === undefined) v[key] = neg !== '-';
      else v[key] = parseNumber(val) ?? val;
    }
    value.view = v;
  }
  const plot = q.get('plot');
  if (plot !== null) {
    const p = plot.split(',');
    if (p.length === 2 && p.every((n) => /^[a-z0-9_]{1,20}$/i.test(n))) value.plot = [p[0] as string, p[1] as string];
    else problems.push(tr('url.notPlot', { value: JSON.stringify(plot) }));
  }
  const twin = q.get('twin');
  if (twin !== null) {
    const o = decodeTwin(twin);
    if (o === null) problems.push(tr('url.notTwin', { value: JSON.stringify(twin) }));
    else value.twin = o;
  }
  return { value, problems };
}

/** One pendulum of mode own from its `l:m:θ₀` parts (θ₀ in degrees), null if not three numbers in range. */
function ownPendulum(parts: readonly string[]): ExtraOptions | null {
  const nums = parts.map(parseNumber);
  if (nums.length !== 3 || nums.some((n) => n === null)) return null;
  const [l, m, th] = nums as [number, number, number];
  return l > 0 && m > 0 && th >= 0 && th <= 180 ? { length: l, mass: m, theta: th / DEG } : null;
}

/** The second pendulum of a `twin` value, or null when it cannot be read. */
export function decodeTwin(text: string): TwinOptions | null {
  const o: TwinOptions = { mode: 'off', epsilon: 0.01 / DEG, method: 'rk4', damping: 0.5, length: 0.5, mass: 1, theta: 10 / DEG };
  const [first = '', ...more] = text.split(',');
  const [kind, ...rest] = first.split(':');
  const nums = rest.map(parseNumber);
  if (kind === 'own') {
    const own = [rest, ...more.map((e) => e.split(':'))].map(ownPendulum);
    if (own.length > 1 + MAX_EXTRAS || own.some((p) => p === null)) return null;
    const [second, ...extras] = own as ExtraOptions[];
    return { ...o, mode: 'own', ...(second as ExtraOptions), ...(extras.length > 0 ? { extras } : {}) };
  }
  if (more.length > 0) return null;
  if (kind === 'eps' && nums.length === 1 && nums[0] !== null) return { ...o, mode: 'epsilon', epsilon: (nums[0] as number) / DEG };
  if (kind === 'damped' && nums.length === 1 && (nums[0] ?? -1) >= 0) return { ...o, mode: 'damped', damping: nums[0] as number };
  if (kind === 'method' && rest.length === 1 && NAME.test(rest[0] as string)) return { ...o, mode: 'method', method: rest[0] as string };
  return null;
}

/** What the URL should say for a status (the scenario as it stands: parameters, method, start). */
export function fromStatus(s: Status): UrlScenario {
  const u: UrlScenario = {
    model: s.model,
    length: s.params.length,
    mass: s.params.mass,
    g: s.params.g,
    method: s.method,
    timeScale: s.time_scale,
    x: s.start.x,
    v: s.start.v,
  };
  // an adaptive method's steps are all its own (the session's dt is not one of them): no dt then
  if (!s.adaptive) u.dt = s.dt;
  if (s.scenario !== null) u.scenario = s.scenario;
  if (Object.keys(s.model_params).length > 0) u.modelParams = { ...s.model_params };
  if (s.paused) u.paused = true;
  // the paused time, where fixed steps can replay it exactly
  if (s.paused && !s.adaptive && s.t > s.t0) u.at = s.t - s.t0;
  return u;
}

/** The commands that put a fresh session into the URL's scenario (in this order: scenario, model and its
 *  parameters, parameters, method, time scale, start, then reset to t0 and pause if asked). */
export function commandsFor(u: UrlScenario): Command[] {
  const out: Command[] = [];
  if (u.scenario !== undefined) out.push({ type: 'load_scenario', name: u.scenario });
  // the crane mode is entered by its own command (the server's set_model knows the registry's models only)
  if (u.model === 'crane') out.push({ type: 'crane', on: true }, { type: 'set_params', params: { ...u.modelParams } });
  else if (u.model !== undefined) out.push({ type: 'set_model', model: u.model, params: { ...u.modelParams } });
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
  // the paused time: the same fixed steps again from the start (the server's limit is 100 000 per command)
  if (u.paused === true && u.at !== undefined && u.at > 0 && u.dt !== undefined && u.dt > 0) {
    let n = Math.round(u.at / u.dt);
    if (n > 10_000_000) n = 0; // more than a minute of work: not replayed (the start is kept)
    while (n > 0) {
      const k = Math.min(n, 100_000);
      out.push({ type: 'step', n: k });
      n -= k;
    }
  }
  return out;
}

/** What a link carries, in the page's words, for the "copy link" message: the scenario always, then the
 *  paused time, the view options, the chosen plot, the second pendulum and the language. */
export function linkContents(u: UrlScenario): string {
  const parts = [t('link.scenario')];
  if (u.paused === true) parts.push(u.at !== undefined && u.at > 0 ? t('link.pausedAt', { t: u.at.toFixed(3) }) : t('link.paused'));
  const view = Object.entries(u.view ?? {}).map(([k, v]) => (typeof v === 'boolean' ? (v ? k : `−${k}`) : `${k} ${v}`));
  if (view.length > 0) parts.push(t('link.view', { list: view.join(', ') }));
  if (u.plot !== undefined) parts.push(t('link.plot', { x: u.plot[0], y: u.plot[1] }));
  const tw = u.twin === undefined ? null : twinText(u.twin);
  if (tw !== null) parts.push(t('link.twin', { what: tw }));
  if (u.lang !== undefined) parts.push(t('link.lang', { lang: u.lang }));
  return parts.join('; ');
}
