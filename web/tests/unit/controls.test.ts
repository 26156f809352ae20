// The classroom panel's pure parts: the never-degenerate plot ranges, the variables of the chosen plot, the
// keyboard shortcuts and slider steps, the words tables (every language every key), and the classroom
// controls' commands (friction, start in degrees, gravity presets, framing, ruler steps, recording).
import { describe, expect, it } from 'vitest';
import { DEG } from '../../src/measure';
import { FLOAT64_EPS, logRange, MIN_RELATIVE_SPAN, relativeDrift, safeRange } from '../../src/panels/ranges';
import { columns, VARIABLES } from '../../src/variables';
import { ariaNumber, ownsKeys, shortcutFor, sliderSteps } from '../../src/keyboard';
import { chooseLanguage, LANGUAGES, modelWords, paramWords, setLanguage, t } from '../../src/i18n';
import { EN } from '../../src/i18n/en';
import { frictionCommand, GRAVITY_PRESETS, startCommand } from '../../src/panels/tools';
import { framingDistance } from '../../src/scene/scene';
import { rulerStep } from '../../src/scene/instruments';
import { tick } from '../../src/panels/curves';
import { webmType } from '../../src/record';
import { frame, status } from './classroom_fixtures';

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
