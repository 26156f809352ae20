// Two pendulums (src/twin.ts): the second start turned by ε, its commands, a pendulum of its own length [m],
// mass [kg] and start, positions [m] between coarse frames to O(h⁴), and the separation [m] of the two.
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../src/protocol';
import { sphericalAngles } from '../../src/measure';
import { frameAt, positionAt, separation, sideBySide, tiltedStart, twinCommands } from '../../src/twin';
import { frame, status } from './classroom_fixtures';

describe('two pendulums', () => {
  it('the second start is turned by ε in θ, |x| kept', () => {
    const x = tiltedStart([Math.sin(0.5), 0, -Math.cos(0.5)], 0.01);
    expect(Math.hypot(...x)).toBeCloseTo(1, 14);
    expect(sphericalAngles(x).theta).toBeCloseTo(0.51, 14);
  });
  it('copies the first pendulum with one difference and resets', () => {
    const c = twinCommands(status({ scenario: 'rosette' }), { mode: 'damped', epsilon: 0, method: 'rk4', damping: 0.5, length: 1, mass: 1, theta: 0 });
    expect(c[0]).toEqual({ type: 'load_scenario', name: 'rosette' });
    expect(c).toContainEqual({ type: 'set_model', model: 'damped', params: { damping: 0.5 } });
    expect(c.at(-2)).toEqual({ type: 'reset' });
    const m = twinCommands(status({ paused: true }), { mode: 'method', epsilon: 0, method: 'rk4', damping: 0, length: 1, mass: 1, theta: 0 });
    expect(m).toContainEqual({ type: 'set_method', method: 'rk4', dt: 0.001 });
    expect(m.at(-1)).toEqual({ type: 'pause' });
  });
  it('own: a pendulum of its own length, mass and start angle, its pivot drawn beside the first', () => {
    const c = twinCommands(status({}), { mode: 'own', epsilon: 0, method: 'rk4', damping: 0, length: 0.5, mass: 2, theta: 0.2 });
    expect(c).toContainEqual({ type: 'set_params', length: 0.5, mass: 2, g: 9.81 });
    expect(c).toContainEqual({ type: 'set_state', theta: 0.2, phi: 0, theta_dot: 0, phi_dot: 0 });
    const d = sideBySide(1, 0.5);
    expect(Math.hypot(...d)).toBeCloseTo(1.65, 14); // the spheres of reach 1 m and 0.5 m apart by a tenth
    expect(d[2]).toBe(0);
  });
  it('positions between coarse frames to O(h⁴): a conical orbit sampled 0.1 s apart', () => {
    const w = 3;
    const at = (t: number) => frame(t, [Math.cos(w * t), Math.sin(w * t), -1], [-w * Math.sin(w * t), w * Math.cos(w * t), 0]);
    const frames = Array.from({ length: 11 }, (_, k) => at(k / 10));
    let worst = 0;
    for (let t = 0; t <= 1; t += 0.013) {
      const r = positionAt(frames, t) as Vec3;
      const want = at(t).x;
      worst = Math.max(worst, Math.hypot(r[0] - want[0], r[1] - want[1], r[2] - want[2]));
    }
    expect(worst).toBeLessThan(1e-4); // linear interpolation: h² ω² / 8 ≈ 1.1e-2
    expect(positionAt(frames, 1.5)).toBeNull();
  });
  it('separation: the second interpolated at the first one’s times', () => {
    const a = [frame(0, [0, 0, -1], [0, 0, 0]), frame(1, [1, 0, 0], [0, 0, 0])];
    const b = [frame(0, [1, 0, 0], [0, 0, 0]), frame(2, [1, 0, 0], [0, 0, 0], { pivot: [0, 2, 0] })];
    expect(frameAt(b, 1)?.pivot).toEqual([0, 1, 0]);
    expect(frameAt(b, 3)).toBeNull();
    const s = separation(a, b);
    expect(s.t).toEqual([0, 1]);
    expect(s.d[0]).toBeCloseTo(Math.sqrt(2), 14);
    expect(s.d[1]).toBeCloseTo(1, 14);
  });
});
