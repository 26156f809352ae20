// The classroom tools' measurements (src/measure.ts): angles [rad, °], the stopwatch [s], the period timer
// against known motions (swings recognised from the motion, orbits), the period comparison against the
// exact solution, the swing theory (T-6.2, T-7.1) and the energy split [J].
import { describe, expect, it } from 'vitest';
import type { Frame, Status, Vec3 } from '../../src/protocol';
import { ellipticK, energySplit, PeriodTimer, periodComparison, sphericalAngles, Stopwatch, swingTheory, workBetween, wrapAngle } from '../../src/measure';
import { swingTheoryFor } from '../../src/panels/tools';
import { frame, planar } from './classroom_fixtures';

describe('angles', () => {
  it('θ from the downward vertical, φ the azimuth', () => {
    const a = sphericalAngles([Math.sin(0.3) * Math.cos(1), Math.sin(0.3) * Math.sin(1), -Math.cos(0.3)]);
    expect(a.theta).toBeCloseTo(0.3, 14);
    expect(a.phi).toBeCloseTo(1, 14);
    expect(sphericalAngles([0, 0, 1]).theta).toBeCloseTo(Math.PI, 14);
    expect(wrapAngle(3 * Math.PI / 2)).toBeCloseTo(-Math.PI / 2, 14);
    expect(wrapAngle(-Math.PI)).toBeCloseTo(Math.PI, 14);
  });
});

describe('stopwatch', () => {
  it('adds the running stretches, laps, resets', () => {
    const w = new Stopwatch(2);
    w.start(1);
    expect(w.reading(3.5)).toBe(2.5);
    w.stop(4);
    expect(w.reading(10)).toBe(3);
    w.start(10);
    w.lap(11);
    w.lap(12);
    w.lap(13);
    expect(w.laps).toEqual([5, 6]);
    expect(w.reading(9)).toBe(3); // time went back (a reset run): no negative stretch
    w.reset();
    expect(w.reading(20)).toBe(0);
    expect(w.running).toBe(false);
  });
});

describe('period timer', () => {
  // a known motion: z = −l cos(θ) with θ = θ₀ cos(2π t/T), φ = Ω t (a precessing swing); sampled at 60 Hz
  const T = 1.7;
  const omega = 0.4;
  const sample = (t: number): Frame => {
    const theta = 0.5 + 0.2 * Math.cos((2 * Math.PI * t) / T);
    const thetaDot = (-0.2 * 2 * Math.PI * Math.sin((2 * Math.PI * t) / T)) / T;
    const phi = omega * t;
    const x: Vec3 = [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), -Math.cos(theta)];
    return frame(t, x, [0, 0, Math.sin(theta) * thetaDot]);
  };
  it('measures the z-period and the azimuthal advance to 1e-4', () => {
    const p = new PeriodTimer();
    for (let k = 0; k <= 60 * 12; k++) p.push(sample(k / 60));
    const r = p.reading();
    expect(r.intervals).toBeGreaterThanOrEqual(5);
    expect(Math.abs((r.period as number) - T) / T).toBeLessThan(1e-4);
    expect(Math.abs((r.advance as number) - omega * T) / (omega * T)).toBeLessThan(1e-4);
  });
  it('ignores rounding noise of a conical orbit and starts afresh on reset', () => {
    const p = new PeriodTimer();
    for (let k = 0; k < 600; k++) p.push(frame(k / 60, [0.5, 0, -0.8], [0, 0, (k % 2 ? 1 : -1) * 1e-16]));
    expect(p.reading().period).toBeNull();
    p.reset();
    expect(p.reading().intervals).toBe(0);
  });
});

describe('period timer: swings recognised from the motion', () => {
  // a damped swing θ = A e^{−γt} cos(ω_d t): its zeros, the lowest points, are exactly π/ω_d apart
  const [A, gamma, wd] = [0.17, 0.15, 3.1285];
  const theta = (t: number) => A * Math.exp(-gamma * t) * Math.cos(wd * t);
  const rate = (t: number) => -A * Math.exp(-gamma * t) * (gamma * Math.cos(wd * t) + wd * Math.sin(wd * t));
  const Td = (2 * Math.PI) / wd;
  it('a damped planar swing: the full period 2π/ω_d (not half), counted in whole periods', () => {
    const p = new PeriodTimer();
    for (const f of planar(theta, rate, 2.3 * Td)) p.push(f);
    const r = p.reading();
    expect(r.kind).toBe('swing');
    expect(r.lowPerPeriod).toBe(2);
    expect(r.intervals).toBe(2); // lowest points at T/4, 3T/4, …, 9T/4: two whole periods, not four
    expect(Math.abs((r.period as number) - Td) / Td).toBeLessThan(1e-4);
    expect(r.advance).toBeNull();
    expect(r.amplitude as number).toBeGreaterThan(0.1);
    expect(r.amplitude as number).toBeLessThan(A);
  });
  it('one period is null until the bob passes the bottom the same way again', () => {
    const p = new PeriodTimer();
    for (const f of planar(theta, rate, 0.9 * Td)) p.push(f);
    expect(p.reading().period).toBeNull();
    expect(p.reading().intervals).toBe(0);
  });
  it('a swing over the top: one lowest point per period', () => {
    const w = 7;
    const p = new PeriodTimer();
    for (const f of planar((t) => w * t + 1, () => w, 5)) p.push(f);
    const r = p.reading();
    expect(r.kind).toBe('swing');
    expect(r.lowPerPeriod).toBe(1);
    expect(Math.abs((r.period as number) - (2 * Math.PI) / w) / ((2 * Math.PI) / w)).toBeLessThan(1e-4);
  });
  it('a nearly planar swing (a thin ellipse, J₃ ≠ 0) is a swing; a wide one an orbit', () => {
    const thin = new PeriodTimer();
    for (const f of planar((t) => 0.3 * Math.cos(2 * Math.PI * t), (t) => -0.6 * Math.PI * Math.sin(2 * Math.PI * t), 6, 0, 0.001)) thin.push(f);
    expect(thin.reading().kind).toBe('swing');
    expect(Math.abs((thin.reading().period as number) - 1)).toBeLessThan(1e-3);
  });
});

describe('period comparison', () => {
  const reading = { kind: null, period: 1.01, advance: 3.1, precession: 0.2, lowPerPeriod: 2, intervals: 4, amplitude: 0.1, thetaMin: 0, thetaMax: 0.1, from: 0, to: 4 } as const;
  it('a swing is compared as the full swing period, without Δφ', () => {
    const swing = { ...reading, kind: 'swing' as const, period: 2.02 };
    const planarQ = periodComparison(swing, { kind: 'planar', period_z: 2.02, period_z_infinite: false, azimuth_advance: null });
    expect(planarQ.swing).toBe(true);
    expect(planarQ.period).toEqual([2.02, 2.02]);
    expect(planarQ.advance).toEqual([null, null]);
    // nearly planar: the exact solution's z-period is half the swing
    const thin = periodComparison(swing, { kind: 'generic', period_z: 1.01, period_z_infinite: false, azimuth_advance: 3.15 });
    expect(thin.period).toEqual([2.02, 2.02]);
    // no exact solution (damped): the theory
    expect(periodComparison(swing, null, 2.03).period).toEqual([2.02, 2.03]);
  });
  it('an orbit: T_z, Δφ and the precession 2Δφ − 2π', () => {
    const orbit = { ...reading, kind: 'orbit' as const };
    const generic = periodComparison(orbit, { kind: 'generic', period_z: 1.02, period_z_infinite: false, azimuth_advance: 3.2 });
    expect(generic.period).toEqual([1.01, 1.02]);
    expect(generic.advance).toEqual([3.1, 3.2]);
    expect(generic.precession[1]).toBeCloseTo(6.4 - 2 * Math.PI, 14);
    expect(periodComparison(orbit, null).period).toEqual([1.01, null]);
  });
});

describe('swing theory', () => {
  it('K(0) = π/2; the period ratio 4K(sin²(θ₀/2))/2π against the 1911 Britannica table (T-6.2)', () => {
    expect(ellipticK(0)).toBeCloseTo(Math.PI / 2, 15);
    const table: [number, number][] = [[0.1, 1.0062], [0.3, 1.0585], [0.5, 1.1804], [0.9, 2.0724]];
    for (const [f, ratio] of table) {
      const T = swingTheory(1, 9.81, 0, f * Math.PI) as number;
      expect(Math.abs(T / (2 * Math.PI * Math.sqrt(1 / 9.81)) - ratio)).toBeLessThan(6e-5);
    }
  });
  it('friction c lengthens the small-swing period by ω₀/ω_d, ω_d = √(ω₀² − c²/4); overdamped: none', () => {
    const w0 = Math.sqrt(9.81);
    expect(swingTheory(1, 9.81, 0.3, 0)).toBeCloseTo((2 * Math.PI) / Math.sqrt(w0 ** 2 - 0.0225), 12);
    expect(swingTheory(1, 9.81, 7, 0.1)).toBeNull();
    expect(swingTheory(1, -9.81, 0, 0.1)).toBeNull();
  });
  it('applies to the ideal pendulum and to linear friction only', () => {
    const status = (model: string, model_params: Record<string, number>) =>
      ({ model, model_params, params: { length: 2, mass: 1, g: 9.81 } }) as unknown as Status;
    expect(swingTheoryFor(status('damped', { damping: 0.3, drag: 0 }), 0)).toBeCloseTo(swingTheory(2, 9.81, 0.3, 0) as number, 14);
    expect(swingTheoryFor(status('damped', { damping: 0.3, drag: 0.1 }), 0)).toBeNull();
    expect(swingTheoryFor(status('spring', {}), 0)).toBeNull();
    expect(swingTheoryFor(null, 0)).toBeNull();
  });
});

describe('energy bars', () => {
  it('kinetic + potential is E + m|g|l; lost is −∫P dt; the total keeps E₀ + m|g|l', () => {
    const f = frame(0, [0, 0, -1], [1, 2, 0], { energy: 2 * (0.5 * 5 - 9.81) });
    const s = energySplit(f, 2, 9.81, 1, -0.75);
    expect(s.kinetic).toBeCloseTo(5, 14);
    expect(s.potential).toBeCloseTo(0, 12);
    expect(s.lost).toBe(0.75);
    expect(s.total).toBeCloseTo(5 + 0.75, 12);
    expect(workBetween(frame(0, [0, 0, -1], [0, 0, 0], { power: -1 }), frame(0.5, [0, 0, -1], [0, 0, 0], { power: -3 }))).toBe(-1);
  });
});
