// The quantities the plot of chosen variables offers (docs/web.md, "Plots"): each read from one streamed
// frame (the core's numbers) and the pendulum's m [kg], g [m/s²], l [m]; angles in degrees. No DOM.
import type { Frame } from './protocol';
import { DEG, sphericalAngles } from './measure';
import type { Key } from './i18n';

export interface PlotContext {
  mass: number;
  g: number;
  length: number;
}

export interface Variable {
  name: string;
  /** The words (i18n key) and the unit shown on the axis. */
  label: Key;
  unit: string;
  get(f: Frame, c: PlotContext): number;
}

const kinetic = (f: Frame, c: PlotContext) => 0.5 * c.mass * (f.v[0] ** 2 + f.v[1] ** 2 + f.v[2] ** 2);

export const VARIABLES: readonly Variable[] = [
  { name: 't', label: 'var.t', unit: 's', get: (f) => f.t },
  { name: 'theta', label: 'var.theta', unit: '°', get: (f) => sphericalAngles(f.x).theta * DEG },
  { name: 'phi', label: 'var.phi', unit: '°', get: (f) => sphericalAngles(f.x).phi * DEG },
  { name: 'x', label: 'var.x', unit: 'm', get: (f) => f.x[0] },
  { name: 'y', label: 'var.y', unit: 'm', get: (f) => f.x[1] },
  { name: 'z', label: 'var.z', unit: 'm', get: (f) => f.x[2] },
  { name: 'zdot', label: 'var.zdot', unit: 'm/s', get: (f) => f.v[2] },
  { name: 'speed', label: 'var.speed', unit: 'm/s', get: (f) => Math.hypot(...f.v) },
  { name: 'energy', label: 'var.energy', unit: 'J', get: (f) => f.energy },
  { name: 'kinetic', label: 'var.kinetic', unit: 'J', get: kinetic },
  { name: 'potential', label: 'var.potential', unit: 'J', get: (f, c) => f.energy - kinetic(f, c) },
  { name: 'j3', label: 'var.j3', unit: 'kg m²/s', get: (f) => f.j3 },
  { name: 'tension', label: 'var.tension', unit: 'N', get: (f) => f.tension },
  { name: 'power', label: 'var.power', unit: 'W', get: (f) => f.power },
  { name: 'radius', label: 'var.radius', unit: 'm', get: (f) => Math.hypot(...f.x) },
];

export function variable(name: string): Variable {
  return VARIABLES.find((v) => v.name === name) ?? (VARIABLES[0] as Variable);
}

/** The columns (x, y) of the chosen variables over `frames`. */
export function columns(frames: readonly Frame[], xName: string, yName: string, c: PlotContext): { x: number[]; y: number[] } {
  const [vx, vy] = [variable(xName), variable(yName)];
  return { x: frames.map((f) => vx.get(f, c)), y: frames.map((f) => vy.get(f, c)) };
}
