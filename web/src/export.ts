// What the page exports besides the CSV (state.ts) and the PNG (scene.ts): the scenario as it stands, as
// the body of POST /api/scenario.toml, where the server renders it as a TOML file for `pendulab run` (no DOM).
import type { ModelParams, Status, Vec3 } from './protocol';

/** Body of POST /api/scenario.toml: model, l [m], m [kg], g [m/s²], the model's own parameters (SI), the
 *  start x [m], v [m/s], method, dt [s] (a fixed-step method's) or rtol and atol [m, m/s] (an adaptive
 *  method's: in a file a dt would be its first step), t0 [s] and t_end [s] (at least 100 s after t0, and
 *  past the time reached, so the file replays what was watched). */
export interface ScenarioRequest {
  title?: string;
  model: string;
  length: number;
  mass: number;
  g: number;
  params: ModelParams;
  x: Vec3;
  v: Vec3;
  method: string;
  dt?: number;
  rtol?: number;
  atol?: number;
  t0: number;
  t_end: number;
}

export function scenarioRequest(s: Status): ScenarioRequest {
  const out: ScenarioRequest = {
    model: s.model,
    length: s.params.length,
    mass: s.params.mass,
    g: s.params.g,
    params: { ...s.model_params },
    x: s.start.x,
    v: s.start.v,
    method: s.method,
    t0: s.t0,
    t_end: Math.max(s.t0 + 100, Math.ceil(s.t)),
  };
  if (!s.adaptive) out.dt = s.dt;
  else {
    if (s.rtol !== undefined) out.rtol = s.rtol;
    if (s.atol !== undefined) out.atol = s.atol;
  }
  const title = s.title ?? s.scenario;
  if (title) out.title = `${title} (from the lab)`;
  return out;
}
