// The period timer's precision when frames arrive far apart (issue 28): frames of the ideal pendulum
// (l = 1 m, g = 9.81 m/s², integrated here by RK4 on x, v with a = −g ẑ + (g z − |v|²) x, T-2.2 for l = 1,
// to ~1e-12) at time scale 4 (60 frames per wall second: h = 1/15 s of simulated time) and with frames
// dropped at random (gaps up to 0.4 s), against the exact periods: a planar swing's 4K(k²)/ω₀ (T-4.6) and a
// spherical orbit's T_z and Δφ (T-4.5) by quadrature of the turning-point cubic, independent of the timer.
import { describe, expect, it } from 'vitest';
import type { Frame, Vec3 } from '../../src/protocol';
import { ellipticK, lowestPoint, PeriodTimer } from '../../src/measure';

const G = 9.81;

function accel(x: Vec3, v: Vec3): Vec3 {
  const lam = G * x[2] - (v[0] ** 2 + v[1] ** 2 + v[2] ** 2);
  return [lam * x[0], lam * x[1], -G + lam * x[2]];
}

/** Frames of the ideal pendulum (l = 1 m) from x0, v0 for `seconds`, every `every` RK4 steps of `dt` [s];
 *  `keep(k)` false drops frame k; `withA` false sends the acceleration as unknown (NaN). */
function frames(x0: Vec3, v0: Vec3, seconds: number, dt: number, every: number, keep: (k: number) => boolean, withA = true): Frame[] {
  let [x, v] = [[...x0] as Vec3, [...v0] as Vec3];
  const out: Frame[] = [];
  const add = (y: Vec3, s: Vec3, k: number): Vec3 => [y[0] + k * s[0], y[1] + k * s[1], y[2] + k * s[2]];
  const steps = Math.round(seconds / dt);
  for (let n = 0; n <= steps; n++) {
    if (n % every === 0 && keep(n / every)) {
      const a = withA ? accel(x, v) : ([NaN, NaN, NaN] as Vec3);
      out.push({ t: n * dt, x: [...x], v: [...v], energy: 0, j3: 0, tension: 0, power: 0, a, pivot: [0, 0, 0], taut: true, errorX: 0 });
    }
    const k1x = v;
    const k1v = accel(x, v);
    const k2x = add(v, k1v, dt / 2);
    const k2v = accel(add(x, k1x, dt / 2), k2x);
    const k3x = add(v, k2v, dt / 2);
    const k3v = accel(add(x, k2x, dt / 2), k3x);
    const k4x = add(v, k3v, dt);
    const k4v = accel(add(x, k3x, dt), k4x);
    const rk = (y: Vec3, a: Vec3, b: Vec3, c: Vec3, d: Vec3): Vec3 => {
      const at = (i: 0 | 1 | 2) => y[i] + (dt / 6) * (a[i] + 2 * b[i] + 2 * c[i] + d[i]);
      return [at(0), at(1), at(2)];
    };
    [x, v] = [rk(x, k1x, k2x, k3x, k4x), rk(v, k1v, k2v, k3v, k4v)];
  }
  return out;
}

/** Frames kept with probability 0.6 (a fixed linear congruential sequence): gaps of several frames. */
function dropping(): (k: number) => boolean {
  let s = 12345;
  return (k) => {
    s = (1103515245 * s + 12345) % 2147483648;
    return k === 0 || s / 2147483648 < 0.6;
  };
}

/** The exact z-period T_z [s] and azimuthal advance Δφ [rad] of the ideal spherical pendulum (l = 1 m,
 *  m = 1 kg) started at a turning point u_a = z₀ with azimuthal speed w [rad/s]: u̇² = P(u) =
 *  2G(u − u₁)(u₂ − u)(u₃ − u); with u = u₁ + (u₂ − u₁) sin²ψ, dt = 2 dψ / √(2G(u₃ − u)), a smooth
 *  π-periodic integrand the trapezoidal rule integrates to rounding. */
function sphericalExact(ua: number, w: number): { Tz: number; dphi: number } {
  const L = (1 - ua * ua) * w; // J₃ / (m l²)
  const E2 = L * L / (1 - ua * ua) + 2 * G * ua; // 2E/(m l²) at the turning point (u̇ = 0)
  // P(u) = (1 − u²)(E2 − 2G u) − L² = 2G u³ − E2 u² − 2G u + E2 − L²; divided by (u − ua): 2G u² + b u + c
  const b = -E2 + 2 * G * ua;
  const c = -2 * G + b * ua;
  const disc = Math.sqrt(b * b - 8 * G * c);
  const r = [(-b - disc) / (4 * G), (-b + disc) / (4 * G), ua].sort((p, q) => p - q) as [number, number, number];
  const [u1, u2, u3] = r;
  const n = 4000;
  let [tz, dphi] = [0, 0];
  for (let k = 0; k < n; k++) {
    const psi = (Math.PI * k) / n;
    const u = u1 + (u2 - u1) * Math.sin(psi) ** 2;
    const dt = 2 / Math.sqrt(2 * G * (u3 - u));
    tz += dt;
    dphi += (L / (1 - u * u)) * dt;
  }
  return { Tz: (tz * Math.PI) / n, dphi: (dphi * Math.PI) / n };
}

const H = 1 / 15; // time scale 4 at 60 frames per second [s]
const DT = H / 200;

describe('period timer at time scale 4, with frames dropped', () => {
  const theta0 = (10 * Math.PI) / 180;
  const x0: Vec3 = [Math.sin(theta0), 0, -Math.cos(theta0)];
  const exact = (4 * ellipticK(Math.sin(theta0 / 2) ** 2)) / Math.sqrt(G);
  it('a 10° swing: the full period to 5e-8 of 4K(k²)/ω₀ with every frame, to 2e-6 with 4 in 10 dropped', () => {
    for (const [keep, tol] of [[() => true, 5e-8], [dropping(), 2e-6]] as const) {
      const p = new PeriodTimer();
      for (const f of frames(x0, [0, 0, 0], 24, DT, 200, keep)) p.push(f);
      const r = p.reading();
      expect(r.kind).toBe('swing');
      expect(r.intervals).toBe(10);
      expect(Math.abs((r.period as number) - exact) / exact).toBeLessThan(tol);
    }
  });
  it('without the acceleration (the cubic Hermite of z, ż) every frame: to 3e-5', () => {
    const p = new PeriodTimer();
    for (const f of frames(x0, [0, 0, 0], 24, DT, 200, () => true, false)) p.push(f);
    expect(p.reading().intervals).toBe(10);
    expect(Math.abs((p.reading().period as number) - exact) / exact).toBeLessThan(3e-5);
  });
  it('a lowest point between two frames 0.1 s apart (a late tick at time scale 4): to 1e-7 s (1e-4 s without the acceleration); the chord was over 1e-4 s off', () => {
    const fs = frames(x0, [0, 0, 0], 2, DT / 4, 1200, () => true);
    const dense = frames(x0, [0, 0, 0], 2, DT / 4, 1, () => true);
    const k = fs.findIndex((f, i) => i > 0 && (fs[i - 1] as Frame).v[2] < 0 && f.v[2] >= 0);
    const [a, b] = [fs[k - 1] as Frame, fs[k] as Frame];
    expect(b.t - a.t).toBeCloseTo(0.1, 10);
    // the reference: the lowest point between the dense frames (8e-5 s apart) around it
    const j = dense.findIndex((f, i) => i > 0 && f.t > a.t && (dense[i - 1] as Frame).v[2] < 0 && f.v[2] >= 0);
    const [c, d] = [dense[j - 1] as Frame, dense[j] as Frame];
    const ref = c.t + lowestPoint(c, d) * (d.t - c.t);
    expect(d.t - c.t).toBeLessThan(1e-4);
    expect(Math.abs(a.t + lowestPoint(a, b) * (b.t - a.t) - ref)).toBeLessThan(1e-7);
    const unknown = (f: Frame): Frame => ({ ...f, a: [NaN, NaN, NaN] });
    const cubic = a.t + lowestPoint(unknown(a), unknown(b)) * (b.t - a.t);
    const chord = a.t + (-a.v[2] / (b.v[2] - a.v[2])) * (b.t - a.t);
    expect(Math.abs(cubic - ref)).toBeLessThan(1e-4);
    expect(Math.abs(chord - ref)).toBeGreaterThan(1e-4);
  });
  it('a spherical orbit: T_z and Δφ to 1e-7 of the exact ones, frames dropped', () => {
    const th = 0.6;
    const w = 2.0; // φ̇ at the start [rad/s]
    const ex = sphericalExact(-Math.cos(th), w);
    const p = new PeriodTimer();
    const v0: Vec3 = [0, Math.sin(th) * w, 0];
    for (const f of frames([Math.sin(th), 0, -Math.cos(th)], v0, 24, DT, 200, dropping())) p.push(f);
    const r = p.reading();
    expect(r.kind).toBe('orbit');
    expect(r.intervals).toBe(10);
    expect(Math.abs((r.period as number) - ex.Tz) / ex.Tz).toBeLessThan(1e-7);
    expect(Math.abs((r.advance as number) - ex.dphi) / ex.dphi).toBeLessThan(1e-7);
  });
});
