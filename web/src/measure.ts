// Classroom measurements on the streamed states (docs/web.md, "Measuring tools"), with no DOM: the angles in
// degrees, the stopwatch, the period timer and the energy split of the bar chart. They measure what the
// server's core computed — nothing here integrates the motion.
//
// Period timer: the z-period T_z is the time between two successive lowest points of the bob (z minimal,
// where ż = v₃ changes sign from − to +; the crossing time interpolated linearly in ż between the two frames
// around it), the azimuthal advance Δφ the change of the unwrapped azimuth φ = atan2(x₂, x₁) between them
// (T-5.1 defines both for the exact solution; the data panel shows those beside the measured ones).
import type { Frame, Vec3 } from './protocol';

export const DEG = 180 / Math.PI;

/** Polar angle θ from the downward vertical and azimuth φ ∈ (−π, π] [rad] of x [m] (relative to the pivot). */
export function sphericalAngles(x: Readonly<Vec3>): { theta: number; phi: number } {
  return { theta: Math.atan2(Math.hypot(x[0], x[1]), -x[2]), phi: Math.atan2(x[1], x[0]) };
}

/** The angle a − b wrapped into (−π, π]. */
export function wrapAngle(d: number): number {
  let w = d % (2 * Math.PI);
  if (w <= -Math.PI) w += 2 * Math.PI;
  if (w > Math.PI) w -= 2 * Math.PI;
  return w;
}

/** A stopwatch on the simulated time t [s]: start, stop, lap, reset. */
export class Stopwatch {
  /** Accumulated time of the finished runs [s]. */
  private acc = 0;
  /** Simulated time when the running stretch began, or null while stopped. */
  private since: number | null = null;
  /** Readings at each lap, oldest first (at most `maxLaps`). */
  laps: number[] = [];

  constructor(private readonly maxLaps = 8) {}

  get running(): boolean {
    return this.since !== null;
  }

  /** The reading at simulated time t [s]; time going back (a reset of the run) counts as no time. */
  reading(t: number): number {
    return this.acc + (this.since === null ? 0 : Math.max(0, t - this.since));
  }

  start(t: number): void {
    if (this.since === null) this.since = t;
  }

  stop(t: number): void {
    if (this.since === null) return;
    this.acc = this.reading(t);
    this.since = null;
  }

  lap(t: number): void {
    this.laps.push(this.reading(t));
    if (this.laps.length > this.maxLaps) this.laps.shift();
  }

  reset(): void {
    [this.acc, this.since, this.laps] = [0, null, []];
  }
}

export interface PeriodReading {
  /** Mean time between successive lowest points [s] over the last crossings, or null before two. */
  period: number | null;
  /** Mean change of the unwrapped azimuth over the same intervals [rad], or null. */
  advance: number | null;
  /** How many intervals the means are over. */
  intervals: number;
}

/** The period timer: fed every received frame of one trajectory, in time order. A crossing counts only
 *  when z rose by more than `minRise` [m] since the last one (a conical orbit's rounding noise in ż is no
 *  oscillation). The means are over the last `keep` intervals. */
export class PeriodTimer {
  private prev: Frame | null = null;
  private phi = 0;
  private crossings: { t: number; phi: number }[] = [];
  private zLow = Infinity;
  private zHigh = -Infinity;

  constructor(
    private readonly minRise = 1e-7,
    private readonly keep = 10,
  ) {}

  reset(): void {
    this.prev = null;
    this.phi = 0;
    this.crossings = [];
    this.zLow = Infinity;
    this.zHigh = -Infinity;
  }

  push(f: Frame): void {
    const p = this.prev;
    if (p !== null && f.t <= p.t) return;
    const phiNow = Math.atan2(f.x[1], f.x[0]);
    if (p === null) {
      this.phi = phiNow;
      this.prev = f;
      this.zLow = this.zHigh = f.x[2];
      return;
    }
    const phiPrev = this.phi;
    this.phi = phiPrev + wrapAngle(phiNow - Math.atan2(p.x[1], p.x[0]));
    this.zLow = Math.min(this.zLow, f.x[2]);
    this.zHigh = Math.max(this.zHigh, f.x[2]);
    const [a, b] = [p.v[2], f.v[2]];
    if (a < 0 && b >= 0) {
      const s = a === b ? 0 : -a / (b - a);
      const t = p.t + s * (f.t - p.t);
      const phi = phiPrev + s * (this.phi - phiPrev);
      if (this.crossings.length === 0 || this.zHigh - this.zLow > this.minRise) {
        this.crossings.push({ t, phi });
        if (this.crossings.length > this.keep + 1) this.crossings.shift();
      }
      this.zLow = this.zHigh = f.x[2];
    }
    this.prev = f;
  }

  reading(): PeriodReading {
    const c = this.crossings;
    const n = c.length - 1;
    if (n < 1) return { period: null, advance: null, intervals: 0 };
    const first = c[0] as { t: number; phi: number };
    const last = c[n] as { t: number; phi: number };
    return { period: (last.t - first.t) / n, advance: (last.phi - first.phi) / n, intervals: n };
  }
}

export interface EnergySplit {
  /** ½ m |v|² [J] (v relative to the pivot, as in the core's E). */
  kinetic: number;
  /** E − K + m|g|l [J]: the core's potential energy measured from the lowest point of the sphere. */
  potential: number;
  /** −∫P dt since the start of the trajectory [J]: energy taken out by damping and drag (put in, if < 0,
   *  by forcing or a moving pivot). */
  lost: number;
  /** kinetic + potential + lost [J]: E₀ + m|g|l while the power balance E − E₀ = ∫P dt holds (T-7.1). */
  total: number;
}

/** The bar chart's energies for frame `f` of a bob of mass `mass` [kg] on a rod of length `length` [m]
 *  under gravity `g` [m/s²], with `work` = ∫P dt [J] since the trajectory's start. */
export function energySplit(f: Frame, mass: number, g: number, length: number, work: number): EnergySplit {
  const kinetic = 0.5 * mass * (f.v[0] ** 2 + f.v[1] ** 2 + f.v[2] ** 2);
  const potential = f.energy - kinetic + mass * Math.abs(g) * length;
  const lost = -work;
  return { kinetic, potential, lost, total: kinetic + potential + lost };
}

/** ∫P dt [J] over two successive frames by the trapezoidal rule. */
export function workBetween(a: Frame, b: Frame): number {
  return 0.5 * (a.power + b.power) * (b.t - a.t);
}

/** The period timer's numbers beside the exact ones (ExactQuantities of the server): the z-period T_z [s]
 *  and the advance Δφ [rad]. A planar swing (kind `planar`, J₃ = 0) passes the bottom twice per swing, so z
 *  repeats after half the swing period the exact solution reports (T-4.3's 4K/ω₀): there the measured
 *  value is doubled and compared as the swing period, and Δφ (φ jumps by π at the pole) is not compared. */
export function periodComparison(
  m: PeriodReading,
  exact: { kind: string; period_z: number | null; period_z_infinite: boolean; azimuth_advance: number | null } | null,
): { swing: boolean; period: [number | null, number | null]; advance: [number | null, number | null] } {
  const swing = exact?.kind === 'planar';
  const exactT = exact === null || exact.period_z_infinite ? null : exact.period_z;
  return {
    swing,
    period: [m.period === null ? null : swing ? 2 * m.period : m.period, exactT],
    advance: [swing ? null : m.advance, exact?.azimuth_advance ?? null],
  };
}
