// Classroom measurements on the streamed states (docs/web.md, "Measuring tools"), with no DOM: the angles in
// degrees, the stopwatch, the period timer and the energy split of the bar chart. They measure what the
// server's core computed — nothing here integrates the motion.
//
// Period timer: the z-period T_z is the time between two successive lowest points of the bob (z minimal,
// where ż = v₃ changes sign from − to +), the azimuthal advance Δφ the change of the unwrapped azimuth
// φ = atan2(x₂, x₁) between them (T-5.1 defines both for the exact solution; the data panel shows those
// beside the measured ones). The crossing time between the two frames around it is the root of ż of the
// quintic Hermite interpolant of z through both frames' z, ż = v₃ and z̈ = a₃ (the core's acceleration the
// records carry): its error is O(h⁶) in z and O(h⁵) in ż for frames h [s] apart, so the timer keeps the
// engine's precision when frames arrive far apart (a high time scale, a loaded machine, dropped frames);
// without a finite acceleration the cubic Hermite interpolant of z and ż.
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
  /** What the motion is, recognised from the motion itself: `swing` (the bob passes through the bottom:
   *  its horizontal distance from the vertical at the lowest point is below `planarRatio` of the largest in
   *  the half swing before), `orbit` (it goes round the vertical, never through the bottom), or null
   *  before the first two lowest points. */
  kind: 'swing' | 'orbit' | null;
  /** swing: the mean full period [s] (back through the bottom in the same direction: every second lowest
   *  point of a to-and-fro swing, every one of a swing over the top); orbit: the mean z-period T_z [s]
   *  between successive lowest points. Null before one whole period. */
  period: number | null;
  /** orbit: the mean change of the unwrapped azimuth per T_z [rad] (T-4.5's Δφ), else null. */
  advance: number | null;
  /** orbit: how far the orbit's pattern turns per round, 2Δφ − 2π [rad] (Airy's precession, T-6.3, for a
   *  small ellipse; Δφ = π is a closed ellipse), else null. */
  precession: number | null;
  /** Lowest points per full period: 2 for a to-and-fro swing, 1 for a swing over the top or an orbit. */
  lowPerPeriod: 1 | 2;
  /** How many whole periods (swing) or z-periods (orbit) the means are over. */
  intervals: number;
  /** The largest angle from the downward vertical [rad] in the window of the means (mean over its half
   *  swings, root mean square), null before it. */
  amplitude: number | null;
  /** The smallest and largest angle from the vertical [rad] since the last lowest point (an orbit's band). */
  thetaMin: number | null;
  thetaMax: number | null;
  /** Simulated times [s] of the first and last lowest point the means are over. */
  from: number | null;
  to: number | null;
}

interface Low {
  /** Time of the lowest point [s], the root of the Hermite interpolant's ż (`lowestPoint`). */
  t: number;
  /** Unwrapped azimuth there [rad]. */
  phi: number;
  /** Horizontal velocity direction there (unit). */
  dir: [number, number];
  /** True when the bob passed (through) the bottom: planar-like. */
  through: boolean;
  /** Largest θ [rad] in the half swing that ended here. */
  thetaMax: number;
  /** Smallest θ [rad] in the half swing that ended here. */
  thetaMin: number;
}

const EMPTY: PeriodReading = {
  kind: null,
  period: null,
  advance: null,
  precession: null,
  lowPerPeriod: 1,
  intervals: 0,
  amplitude: null,
  thetaMin: null,
  thetaMax: null,
  from: null,
  to: null,
};

type Sextic = [number, number, number, number, number, number];

/** The coefficients c₀…c₅ in s ∈ [0, 1] (t = p.t + s h, h = f.t − p.t) of the quintic Hermite interpolant of
 *  coordinate `i` of the position through frames p and f: its value, velocity and acceleration at both ends
 *  (c₀ = x, c₁ = h v, c₂ = h² a / 2 at p; c₃…c₅ from the three conditions at f). Without a finite
 *  acceleration at either end the cubic Hermite interpolant of position and velocity (c₂ from the ends'
 *  positions and velocities, c₄ = c₅ = 0). */
export function hermiteCoefficients(p: Frame, f: Frame, i: 0 | 1 | 2): Sextic {
  const h = f.t - p.t;
  const [x0, x1, v0, v1, a0, a1] = [p.x[i], f.x[i], h * p.v[i], h * f.v[i], h * h * p.a[i], h * h * f.a[i]];
  if (!Number.isFinite(a0) || !Number.isFinite(a1)) {
    const d = x1 - x0;
    return [x0, v0, 3 * d - 2 * v0 - v1, -2 * d + v0 + v1, 0, 0];
  }
  const c2 = a0 / 2;
  const A = x1 - x0 - v0 - c2;
  const B = v1 - v0 - 2 * c2;
  const C = a1 - 2 * c2;
  return [x0, v0, c2, 10 * A - 4 * B + C / 2, -15 * A + 7 * B - C, 6 * A - 3 * B + C / 2];
}

/** Position coordinate `i` [m] and its velocity [m/s] at s ∈ [0, 1] between frames p and f, from the Hermite
 *  interpolant (`hermiteCoefficients`). */
export function hermite(p: Frame, f: Frame, i: 0 | 1 | 2, s: number): [number, number] {
  const c = hermiteCoefficients(p, f, i);
  const x = c[0] + s * (c[1] + s * (c[2] + s * (c[3] + s * (c[4] + s * c[5]))));
  const dx = c[1] + s * (2 * c[2] + s * (3 * c[3] + s * (4 * c[4] + s * 5 * c[5])));
  return [x, dx / (f.t - p.t)];
}

/** Where between frames p and f (ż < 0 at p, ż ≥ 0 at f) the bob is lowest, as s ∈ [0, 1] (t = p.t + s h):
 *  the root of the Hermite interpolant's ż, bracketed by the frames' signs and found by bisection to the last
 *  bit of s (a chord of ż, the timer's first way, errs by O(h²) of the time for frames h apart). */
export function lowestPoint(p: Frame, f: Frame): number {
  const c = hermiteCoefficients(p, f, 2);
  const slope = (s: number) => c[1] + s * (2 * c[2] + s * (3 * c[3] + s * (4 * c[4] + s * 5 * c[5])));
  let [lo, hi] = [0, 1];
  if (!(slope(lo) < 0 && slope(hi) >= 0)) return -p.v[2] / (f.v[2] - p.v[2]); // no bracket: the chord
  while (hi - lo > 1e-16) {
    const mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    if (slope(mid) < 0) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

/** The period timer: fed every received frame of one trajectory, in time order. It finds the lowest points
 *  of the bob (ż = v₃ changes sign from − to +) — a measurement of the streamed states, for every model,
 *  damped or not. A lowest point counts only when z rose by more than `minRise` [m] since the last one (a
 *  conical orbit's rounding noise in ż is no oscillation). At a lowest point the bob passes (through) the
 *  bottom when its horizontal distance from the vertical is below `planarRatio` of the largest in the half
 *  swing before: a swing, whose full period pairs the lowest points by the direction the bob moves there
 *  (same direction again: one period). Otherwise the bob goes round: an orbit, with T_z and Δφ (T-4.5).
 *  The means are over the last `keep` periods. */
export class PeriodTimer {
  private prev: Frame | null = null;
  private phi = 0;
  private lows: Low[] = [];
  /** Lowest points counted since the last reset (the sound's clicks, tools.ts). */
  lowCount = 0;
  private zLow = Infinity;
  private zHigh = -Infinity;
  private rMax = 0;
  private thMax = 0;
  private thMin = Infinity;

  constructor(
    private readonly minRise = 1e-7,
    private readonly keep = 10,
    private readonly planarRatio = 0.02,
  ) {}

  reset(): void {
    this.prev = null;
    this.phi = 0;
    this.lows = [];
    this.lowCount = 0;
    this.zLow = Infinity;
    this.zHigh = -Infinity;
    this.rMax = 0;
    this.thMax = 0;
    this.thMin = Infinity;
  }

  push(f: Frame): void {
    const p = this.prev;
    if (p !== null && f.t <= p.t) return;
    const phiNow = Math.atan2(f.x[1], f.x[0]);
    const r = Math.hypot(f.x[0], f.x[1]);
    const th = Math.atan2(r, -f.x[2]);
    if (p === null) {
      this.phi = phiNow;
      this.prev = f;
      this.zLow = this.zHigh = f.x[2];
      [this.rMax, this.thMax, this.thMin] = [r, th, th];
      return;
    }
    const phiPrev = this.phi;
    this.phi = phiPrev + wrapAngle(phiNow - Math.atan2(p.x[1], p.x[0]));
    this.zLow = Math.min(this.zLow, f.x[2]);
    this.zHigh = Math.max(this.zHigh, f.x[2]);
    const [a, b] = [p.v[2], f.v[2]];
    if (a < 0 && b >= 0) {
      const s = lowestPoint(p, f);
      const t = p.t + s * (f.t - p.t);
      // the horizontal position and velocity at the lowest point, from the same interpolant
      const [rx, vx] = hermite(p, f, 0, s);
      const [ry, vy] = hermite(p, f, 1, s);
      const phi = phiPrev + wrapAngle(Math.atan2(ry, rx) - Math.atan2(p.x[1], p.x[0]));
      if (this.lows.length === 0 || this.zHigh - this.zLow > this.minRise) {
        const vh = Math.hypot(vx, vy) || 1;
        const rLow = Math.hypot(rx, ry);
        const rTop = Math.max(this.rMax, rLow);
        this.lows.push({
          t,
          phi,
          dir: [vx / vh, vy / vh],
          through: rTop > 0 && rLow <= this.planarRatio * rTop,
          thetaMax: this.thMax,
          thetaMin: Math.min(this.thMin, th),
        });
        if (this.lows.length > 2 * this.keep + 1) this.lows.shift();
        this.lowCount++;
      }
      this.zLow = this.zHigh = f.x[2];
      [this.rMax, this.thMax, this.thMin] = [r, th, th];
      this.prev = f;
      return;
    }
    this.rMax = Math.max(this.rMax, r);
    this.thMax = Math.max(this.thMax, th);
    this.thMin = Math.min(this.thMin, th);
    this.prev = f;
  }

  reading(): PeriodReading {
    const c = this.lows;
    const last = c[c.length - 1];
    if (last === undefined || c.length < 2) return { ...EMPTY };
    const band = { thetaMin: Math.min(last.thetaMin, this.thMin), thetaMax: Math.max(last.thetaMax, this.thMax) };
    if (last.through) {
      // a swing: the lowest points where the bob moves the way it moves at the last one end whole periods
      const same: Low[] = [];
      let within = 0;
      for (let k = c.length - 1; k >= 0 && same.length <= this.keep; k--) {
        const l = c[k] as Low;
        if (!l.through) break;
        if (l.dir[0] * last.dir[0] + l.dir[1] * last.dir[1] > 0) same.push(l);
        within = k;
      }
      const n = same.length - 1;
      const first = same[n] as Low;
      const prevLow = c[c.length - 2] as Low;
      const lowPerPeriod = prevLow.dir[0] * last.dir[0] + prevLow.dir[1] * last.dir[1] > 0 ? 1 : 2;
      // the amplitude: root mean square of the half swings' largest angles in the window
      const half = c.slice(Math.max(within, c.indexOf(first)) + 1);
      const amp = half.length > 0 ? Math.sqrt(half.reduce((acc, l) => acc + l.thetaMax ** 2, 0) / half.length) : last.thetaMax;
      return {
        ...EMPTY,
        kind: 'swing',
        period: n < 1 ? null : (last.t - first.t) / n,
        lowPerPeriod,
        intervals: Math.max(n, 0),
        amplitude: amp,
        ...band,
        from: n < 1 ? null : first.t,
        to: last.t,
      };
    }
    let k0 = c.length - 1;
    while (k0 > 0 && c.length - 1 - k0 < this.keep && !(c[k0 - 1] as Low).through) k0--;
    const first = c[k0] as Low;
    const n = c.length - 1 - k0;
    if (n < 1) return { ...EMPTY, kind: 'orbit', ...band };
    const advance = (last.phi - first.phi) / n;
    return {
      ...EMPTY,
      kind: 'orbit',
      period: (last.t - first.t) / n,
      advance,
      precession: Math.sign(advance) * (2 * Math.abs(advance) - 2 * Math.PI),
      intervals: n,
      ...band,
      from: first.t,
      to: last.t,
    };
  }
}

/** The complete elliptic integral of the first kind K(m), m = k² ∈ [0, 1), by the arithmetic–geometric
 *  mean: K = π / (2 AGM(1, √(1 − m))) (a closed-form value, no motion integrated). */
export function ellipticK(m: number): number {
  let [a, b] = [1, Math.sqrt(1 - m)];
  for (let i = 0; i < 40 && Math.abs(a - b) > 1e-16 * a; i++) [a, b] = [(a + b) / 2, Math.sqrt(a * b)];
  return Math.PI / (2 * a);
}

/** The theory's period of a planar swing of amplitude θ_a [rad] (T-4.6: 4K(k²)/ω₀, k = sin(θ_a/2),
 *  ω₀ = √(|g|/l)) with linear friction c [1/s] (T-7.1: θ̈ + c θ̇ + ω₀² sin θ = 0; for small swings the
 *  damped angular frequency ω_d = √(ω₀² − c²/4), so the period grows by ω₀/ω_d), or null when
 *  it does not swing (g ≤ 0, c ≥ 2ω₀, θ_a ≥ π). For light damping and a decaying amplitude this is the
 *  leading order in both; docs/web.md gives its accuracy. */
export function swingTheory(length: number, g: number, damping: number, amplitude: number): number | null {
  if (!(g > 0) || !(length > 0) || !(amplitude >= 0) || amplitude >= Math.PI) return null;
  const w0sq = g / length;
  const wd = Math.sqrt(w0sq - damping ** 2 / 4);
  if (!(wd > 0)) return null;
  return (4 * ellipticK(Math.sin(amplitude / 2) ** 2)) / wd;
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

/** The period timer's numbers beside the exact or theory ones. `exact` is the server's ExactQuantities of
 *  the ideal pendulum's orbit (null for other models or before it arrives); `theory` the swing period from
 *  `swingTheory` (null when it does not apply). A swing (recognised from the motion) is compared as the
 *  full swing period: the exact solution reports it for a planar orbit (kind `planar`), and for a
 *  nearly planar one (tiny J₃, kind `generic`) its z-period is half of it. Δφ and the precession are
 *  compared for orbits only (φ jumps by π at the bottom of a swing). */
export function periodComparison(
  m: PeriodReading,
  exact: { kind: string; period_z: number | null; period_z_infinite: boolean; azimuth_advance: number | null } | null,
  theory: number | null = null,
): {
  swing: boolean;
  period: [number | null, number | null];
  advance: [number | null, number | null];
  precession: [number | null, number | null];
} {
  const swing = m.kind === null ? exact?.kind === 'planar' : m.kind === 'swing';
  const exactT = exact === null || exact.period_z_infinite || exact.period_z === null ? null : exact.period_z;
  let reference: number | null = exactT;
  if (swing && exactT !== null && exact?.kind !== 'planar') reference = m.lowPerPeriod * exactT;
  if (exact === null) reference = theory;
  const adv = exact?.azimuth_advance ?? null;
  const prec = (d: number | null) => (d === null ? null : Math.sign(d) * (2 * Math.abs(d) - 2 * Math.PI));
  return {
    swing,
    period: [m.period, reference],
    advance: [swing ? null : m.advance, swing ? null : adv],
    precession: [swing ? null : m.precession, swing ? null : prec(adv)],
  };
}
