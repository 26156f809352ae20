// The classroom tools' pure parts: angles, the stopwatch, the period timer against a known motion, the
// energy split, the never-degenerate ranges, the variables, the shortcuts, the words tables and the two
// pendulums' commands and separation.
import { describe, expect, it } from 'vitest';
import type { Frame, Status, Vec3 } from '../../src/protocol';
import { DEG, energySplit, PeriodTimer, periodComparison, sphericalAngles, Stopwatch, workBetween, wrapAngle } from '../../src/measure';
import { FLOAT64_EPS, logRange, MIN_RELATIVE_SPAN, relativeDrift, safeRange } from '../../src/panels/ranges';
import { columns, VARIABLES } from '../../src/variables';
import { ownsKeys, shortcutFor, sliderSteps } from '../../src/keyboard';
import { chooseLanguage, LANGUAGES, modelWords, paramWords, setLanguage, t } from '../../src/i18n';
import { EN } from '../../src/i18n/en';
import { frameAt, positionAt, separation, tiltedStart, twinCommands } from '../../src/twin';
import { frictionCommand, GRAVITY_PRESETS, startCommand } from '../../src/panels/tools';
import { framingDistance } from '../../src/scene/scene';
import { rulerStep } from '../../src/scene/instruments';
import { tick } from '../../src/panels/curves';
import { webmType } from '../../src/record';

function frame(t: number, x: Vec3, v: Vec3, extra: Partial<Frame> = {}): Frame {
  return { t, x, v, energy: 0, j3: 0, tension: 0, power: 0, a: [0, 0, 0], pivot: [0, 0, 0], taut: true, errorX: 0, ...extra };
}

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

describe('period comparison', () => {
  it('a planar swing is compared as the swing period (z repeats twice per swing), without Δφ', () => {
    const m = { period: 1.01, advance: 3.1, intervals: 4 };
    const planar = periodComparison(m, { kind: 'planar', period_z: 2.02, period_z_infinite: false, azimuth_advance: null });
    expect(planar.swing).toBe(true);
    expect(planar.period).toEqual([2.02, 2.02]);
    expect(planar.advance).toEqual([null, null]);
    const generic = periodComparison(m, { kind: 'generic', period_z: 1.02, period_z_infinite: false, azimuth_advance: 3.2 });
    expect(generic.period).toEqual([1.01, 1.02]);
    expect(generic.advance).toEqual([3.1, 3.2]);
    expect(periodComparison(m, null).period).toEqual([1.01, null]);
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

describe('ranges', () => {
  it('never degenerate: a few ulps at 4905 N or −10 m become a plottable span', () => {
    for (const [lo, hi] of [
      [4905, 4905 + 1e-12],
      [-10 - 1e-15, -10],
      [0, 0],
      [1e300, 1e300],
    ] as const) {
      const [a, b] = safeRange(lo, hi);
      expect(b - a).toBeGreaterThanOrEqual(MIN_RELATIVE_SPAN * Math.max(Math.abs(lo), Math.abs(hi)) * 0.999);
      expect(a <= lo && b >= hi).toBe(true);
    }
    expect(safeRange(null, 3)).toEqual([-1, 1]);
    expect(safeRange(NaN, 3)).toEqual([-1, 1]);
    expect(safeRange(0, 10)).toEqual([-0.5, 10.5]);
  });
  it('tick labels of a narrow range at a large value differ', () => {
    expect(tick(-3.40512, 4e-5)).not.toBe(tick(-3.40508, 4e-5));
    expect(tick(2.5, 5)).toBe('2.5');
    expect(tick(0)).toBe('0');
  });
  it('log drifts: never 0, the float64 floor always on the axis', () => {
    expect(relativeDrift(0, 2)).toBe(FLOAT64_EPS / 10);
    expect(relativeDrift(-1e-10, 2)).toBeCloseTo(5e-11, 20);
    expect(relativeDrift(1, 0)).toBeNull();
    const [a, b] = logRange(1e-14, 1e-9);
    expect(a <= FLOAT64_EPS && b >= 1e-9).toBe(true);
    expect(logRange(null, null)[0]).toBeLessThan(FLOAT64_EPS);
  });
});

describe('variables', () => {
  it('every variable reads a frame; θ in degrees; U = E − K', () => {
    const f = frame(2, [0, Math.sin(0.5), -Math.cos(0.5)], [0, 0, 1], { energy: 3 });
    const c = columns([f], 'theta', 'potential', { mass: 2, g: 9.81, length: 1 });
    expect(c.x[0]).toBeCloseTo(0.5 * DEG, 12);
    expect(c.y[0]).toBeCloseTo(2, 14);
    for (const v of VARIABLES) expect(Number.isFinite(v.get(f, { mass: 1, g: 9.81, length: 1 }))).toBe(true);
  });
});

describe('keyboard', () => {
  it('maps the shortcuts and the slider keys', () => {
    expect(shortcutFor(' ', false)).toBe('run');
    expect(shortcutFor('R', false)).toBe('reset');
    expect(shortcutFor('s', false)).toBe('step');
    expect(shortcutFor('?', false)).toBe('help');
    expect(shortcutFor('s', true)).toBeNull();
    expect(shortcutFor('x', false)).toBeNull();
    expect(sliderSteps('PageUp')).toBe(10);
    expect(sliderSteps('ArrowLeft')).toBe(-1);
    expect(sliderSteps('End')).toBe(Infinity);
    expect(sliderSteps('a')).toBeNull();
    expect(ownsKeys(null)).toBe(false);
  });
});

describe('words', () => {
  it('picks the language from the URL, then the stored choice, then the browser', () => {
    expect(chooseLanguage('de', 'en', ['en-US'])).toBe('de');
    expect(chooseLanguage(null, 'de', ['en-US'])).toBe('de');
    expect(chooseLanguage(null, null, ['fr-FR', 'de-AT'])).toBe('de');
    expect(chooseLanguage('xx', null, ['fr'])).toBe('en');
  });
  it('every language has every key, non-empty, with the same placeholders', () => {
    for (const { words } of Object.values(LANGUAGES)) {
      for (const key of Object.keys(EN) as (keyof typeof EN)[]) {
        expect(words[key].length).toBeGreaterThan(0);
        const holes = (s: string) => [...s.matchAll(/\{(\w+)\}/g)].map((m) => m[1]).sort();
        expect(holes(words[key])).toEqual(holes(EN[key]));
      }
    }
  });
  it('fills placeholders and switches', () => {
    setLanguage('de');
    expect(t('tools.periodCount', { n: 3 })).toBe('Mittel über 3 Perioden');
    expect(modelWords('damped', 'Damped and driven')).toBe('Gedämpft und angetrieben');
    expect(paramWords('damping', 'friction', 'help')[0]).toMatch(/Reibung/);
    expect(paramWords('no_such', 'x', 'y')).toEqual(['x', 'y']);
    setLanguage('en');
    expect(t('tools.periodCount', { n: 3 })).toBe('mean over 3 periods');
    expect(modelWords('damped', 'Damped and driven')).toBe('Damped and driven');
  });
});

const status = (over: Partial<Status> = {}): Status => ({
  type: 'status',
  epoch: 1,
  scenario: null,
  title: null,
  paused: false,
  time_scale: 1,
  method: 'rattle',
  adaptive: false,
  dt: 0.001,
  params: { length: 1, mass: 1, g: 9.81 },
  model: 'ideal',
  model_params: {},
  t: 0,
  t0: 0,
  start: { x: [Math.sin(0.5), 0, -Math.cos(0.5)], v: [0, 1, 0] },
  lagging: false,
  frame_fields: [],
  ...over,
});

describe('two pendulums', () => {
  it('the second start is turned by ε in θ, |x| kept', () => {
    const x = tiltedStart([Math.sin(0.5), 0, -Math.cos(0.5)], 0.01);
    expect(Math.hypot(...x)).toBeCloseTo(1, 14);
    expect(sphericalAngles(x).theta).toBeCloseTo(0.51, 14);
  });
  it('copies the first pendulum with one difference and resets', () => {
    const c = twinCommands(status({ scenario: 'rosette' }), { mode: 'damped', epsilon: 0, method: 'rk4', damping: 0.5 });
    expect(c[0]).toEqual({ type: 'load_scenario', name: 'rosette' });
    expect(c).toContainEqual({ type: 'set_model', model: 'damped', params: { damping: 0.5 } });
    expect(c.at(-2)).toEqual({ type: 'reset' });
    const m = twinCommands(status({ paused: true }), { mode: 'method', epsilon: 0, method: 'rk4', damping: 0 });
    expect(m).toContainEqual({ type: 'set_method', method: 'rk4', dt: 0.001 });
    expect(m.at(-1)).toEqual({ type: 'pause' });
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

describe('classroom controls', () => {
  it('friction: set_params on a model with damping, the damped model from the ideal one', () => {
    expect(frictionCommand(status(), 0.3)).toEqual({ type: 'set_model', model: 'damped', params: { damping: 0.3 } });
    expect(frictionCommand(status(), 0)).toBeNull();
    expect(frictionCommand(status({ model: 'damped', model_params: { damping: 0 } }), 0.2)).toEqual({
      type: 'set_params',
      params: { damping: 0.2 },
    });
  });
  it('the start in degrees; presets include zero and negative gravity', () => {
    expect(startCommand(30, 90, 0)).toEqual({ type: 'set_state', theta: 30 / DEG, phi: 90 / DEG, theta_dot: 0, phi_dot: 0 });
    expect(startCommand(200, 0, 0)).toMatch(/200/);
    expect(startCommand(NaN, 0, 0)).toMatch(/θ₀/);
    expect(GRAVITY_PRESETS.map(([, g]) => g)).toEqual(expect.arrayContaining([0, -9.81, 1.62]));
  });
  it('frames the sphere of reach in the narrower direction; round ruler steps', () => {
    const d = framingDistance(1, 40, 0.5);
    expect(d).toBeGreaterThan(framingDistance(1, 40, 2));
    expect(1 / d).toBeLessThan(Math.sin((Math.atan(Math.tan((20 * Math.PI) / 180) * 0.5))));
    expect(rulerStep(2)).toBe(0.1);
    expect(rulerStep(20)).toBe(1);
    expect(rulerStep(0.9)).toBe(0.05);
  });
  it('records WebM when the browser can', () => {
    expect(webmType((t) => t === 'video/webm;codecs=vp8')).toBe('video/webm;codecs=vp8');
    expect(webmType(() => false)).toBeNull();
  });
});
