// The classroom tools' pure parts: angles, the stopwatch, the period timer against a known motion, the
// energy split, the never-degenerate ranges, the variables, the shortcuts, the words tables and the two
// pendulums' commands and separation.
import { describe, expect, it } from 'vitest';
import type { Frame, Status, Vec3 } from '../../src/protocol';
import { DEG, ellipticK, energySplit, PeriodTimer, periodComparison, sphericalAngles, Stopwatch, swingTheory, workBetween, wrapAngle } from '../../src/measure';
import { FLOAT64_EPS, logRange, MIN_RELATIVE_SPAN, relativeDrift, safeRange } from '../../src/panels/ranges';
import { columns, VARIABLES } from '../../src/variables';
import { ariaNumber, ownsKeys, shortcutFor, sliderSteps } from '../../src/keyboard';
import { chooseLanguage, LANGUAGES, modelWords, paramWords, setLanguage, t } from '../../src/i18n';
import { EN } from '../../src/i18n/en';
import { frameAt, positionAt, separation, sideBySide, tiltedStart, twinCommands } from '../../src/twin';
import { frictionCommand, GRAVITY_PRESETS, mysteryGravity, soundPitch, startCommand, swingTheoryFor } from '../../src/panels/tools';
import { describeMotion } from '../../src/describe';
import { stripFormulaRefs } from '../../src/advanced';
import { chartSummary } from '../../src/panels/alttext';
import { viewKey } from '../../src/keyboard';
import { framingDistance } from '../../src/scene/scene';
import { rulerStep } from '../../src/scene/instruments';
import { tick } from '../../src/panels/curves';
import { webmType } from '../../src/record';
import { accessibleName } from '../../src/panels/toolbar';

function frame(t: number, x: Vec3, v: Vec3, extra: Partial<Frame> = {}): Frame {
  return { t, x, v, energy: 0, j3: 0, tension: 0, power: 0, a: [NaN, NaN, NaN], pivot: [0, 0, 0], taut: true, errorX: 0, ...extra };
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

/** A planar motion in the vertical plane at azimuth `az` with signed angle θ(t) and rate θ̇(t) [rad, rad/s],
 *  l = 1 m, sampled at 60 Hz for `seconds`, optionally with a small sideways offset `side` [m] (a thin
 *  ellipse: J₃ ≠ 0). */
function planar(theta: (t: number) => number, rate: (t: number) => number, seconds: number, az = 0.7, side = 0): Frame[] {
  const out: Frame[] = [];
  const [c, s] = [Math.cos(az), Math.sin(az)];
  for (let k = 0; k <= seconds * 60; k++) {
    const t = k / 60;
    const [q, w] = [theta(t), rate(t)];
    const u = side * Math.cos(2 * Math.PI * t);
    const x: Vec3 = [Math.sin(q) * c - u * s, Math.sin(q) * s + u * c, -Math.cos(q)];
    out.push(frame(t, x, [Math.cos(q) * w * c, Math.cos(q) * w * s, Math.sin(q) * w]));
  }
  return out;
}

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
    // ARIA values in plain decimals (axe-core: "1e-9" is not a valid aria-valuemin)
    expect([1e-9, 0.1, 9.81, -2.5e3].map(ariaNumber)).toEqual(['0.000000001', '0.1', '9.81', '-2500']);
    expect(ownsKeys(null)).toBe(false);
  });
});

describe('words', () => {
  it('picks the language from the URL, then the stored choice, then the browser', () => {
    expect(chooseLanguage('de', 'en', ['en-US'])).toBe('de');
    expect(chooseLanguage(null, 'de', ['en-US'])).toBe('de');
    expect(chooseLanguage(null, null, ['it-IT', 'de-AT'])).toBe('de');
    expect(chooseLanguage(null, null, ['fr-CA', 'de-AT'])).toBe('fr');
    expect(chooseLanguage('xx', null, ['it'])).toBe('en');
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

describe('inclusion (issue 28)', () => {
  it('a button’s accessible name contains its visible words (axe label-content-name-mismatch) in every language', () => {
    expect(accessibleName('● Record', 'record a video (WebM)')).toBe('record a video (WebM)');
    expect(accessibleName('● Aufnahme', 'Video aufnehmen (WebM)')).toBe('Aufnahme: Video aufnehmen (WebM)');
    expect(accessibleName('A⁺', 'mode présentation : gros caractères pour un vidéoprojecteur')).toBe('A⁺: mode présentation : gros caractères pour un vidéoprojecteur');
    expect(accessibleName('■ Arrêter', 'arrêter de filmer et télécharger la vidéo')).toBe('arrêter de filmer et télécharger la vidéo');
    expect(accessibleName('▾', 'collapse the panel')).toBe('collapse the panel');
    for (const lang of Object.keys(LANGUAGES) as (keyof typeof LANGUAGES)[]) {
      setLanguage(lang);
      for (const [short, long] of [['toolbar.recordShort', 'toolbar.record'], ['toolbar.recordStopShort', 'toolbar.recordStop'], ['toolbar.startShort', 'toolbar.start'], ['toolbar.pauseShort', 'toolbar.pause']] as const) {
        const name = accessibleName(t(short), t(long)).toLocaleLowerCase();
        expect(name).toContain(t(short).replace(/^[^\p{L}]+/u, '').toLocaleLowerCase());
      }
    }
    setLanguage('en');
  });
  it('describes the motion: angle, rising or falling, speed, the energy split', () => {
    setLanguage('en');
    const x: Vec3 = [Math.sin(0.2), 0, -Math.cos(0.2)];
    const text = describeMotion(frame(0, x, [0.5, 0, 0.1]), { kinetic: 3, potential: 1, lost: 0, total: 4 });
    expect(text).toBe('angle 11° from the vertical, rising, speed 0.51 m/s; energy 75 % kinetic, 25 % potential');
    expect(describeMotion(frame(0, x, [0, 0, 0]), null)).toContain('at rest');
    expect(describeMotion(frame(0, x, [1, 0, -0.5]), { kinetic: 1, potential: 1, lost: 2, total: 4 })).toMatch(/falling.*25 % kinetic, 25 % potential, 50 % lost/);
  });
  it('keys on the 3-D view: arrows turn, + − zoom, Shift + ← → the bob', () => {
    expect(viewKey('ArrowLeft', false)).toEqual({ orbit: [(-5 * Math.PI) / 180, 0], zoom: 1 });
    expect(viewKey('ArrowRight', true)).toEqual({ bob: 1 });
    expect(viewKey('-', false)).toEqual({ orbit: [0, 0], zoom: 1.1 });
    expect(viewKey('x', false)).toBeNull();
  });
  it('a mystery planet is 2 … 20.6 m/s², never near a preset', () => {
    for (let k = 0; k < 1000; k++) {
      const g = mysteryGravity(k / 1000);
      expect(g).toBeGreaterThanOrEqual(2);
      expect(g).toBeLessThanOrEqual(20.6);
      for (const [, p] of GRAVITY_PRESETS) expect(Math.abs(g - p)).toBeGreaterThanOrEqual(0.29);
    }
  });
  it('charts have a text alternative: ranges and the latest point', () => {
    setLanguage('en');
    expect(chartSummary('height z(t)', 'time t [s]', 'z [m]', [0, 1, 2], [-1, -0.5, null])).toBe('height z(t): z [m] from -1.00 to -0.500 against time t [s] from 0.00 to 1.00; now — at 2.00');
    expect(chartSummary('T', 'x', 'y', [], [])).toBe('T: no data yet');
  });
  it('the plain layer drops formula numbers from the words, keeping the rest', () => {
    expect(stripFormulaRefs('linear viscous damping (T-7.1), the force −m c v')).toBe('linear viscous damping, the force −m c v');
    expect(stripFormulaRefs('classic RK4 on the Cartesian ODE T-2.4, no projection')).toBe('classic RK4 on the Cartesian ODE, no projection');
    expect(stripFormulaRefs('Holm’s Figure 2 (docs/theory.md §3)')).toBe('Holm’s Figure 2');
    expect(stripFormulaRefs('in a rotating frame (Foucault, T-7.3), optionally damped')).toBe('in a rotating frame (Foucault), optionally damped');
  });
  it('sound: 440 Hz at rest, an octave per 2 m/s, at most 1760 Hz; one count per lowest point', () => {
    expect(soundPitch(0)).toBe(440);
    expect(soundPitch(2)).toBe(880);
    expect(soundPitch(100)).toBe(1760);
    const p = new PeriodTimer();
    for (const f of planar((t) => 0.3 * Math.cos(2 * Math.PI * t), (t) => -0.6 * Math.PI * Math.sin(2 * Math.PI * t), 2.1)) p.push(f);
    expect(p.lowCount).toBe(4); // lowest points at 0.25, 0.75, 1.25, 1.75 s
  });
});
