// The crane mode's page side (web/src/crane/): the gauge's geometry of the frames, the wind's vector and
// its polar form, the words in every language with the same placeholders, and a shared link in the crane
// mode entering it by the `crane` command.
import { describe, expect, it } from 'vitest';
import { recentMaxSway, ropeLength, swayAngle, windPolar, windVector } from '../../src/crane/sway';
import { CRANE_WORDS, cw } from '../../src/i18n/cranewords';
import { setLanguage } from '../../src/i18n';
import type { Frame, Vec3 } from '../../src/protocol';
import { commandsFor } from '../../src/url';

const frame = (t: number, x: Vec3): Frame => ({ t, x, v: [0, 0, 0], energy: 0, j3: 0, tension: 0, power: 0, a: [0, 0, 0], pivot: [0, 0, 0], taut: true, errorX: 0 });

describe('crane gauge', () => {
  it('reads the sway angle and the rope off the load relative to the trolley', () => {
    expect(swayAngle([0, 0, -10])).toBe(0);
    expect(swayAngle([3, 4, -5])).toBeCloseTo(Math.PI / 4, 15);
    expect(swayAngle([0, 1, 0])).toBeCloseTo(Math.PI / 2, 15);
    expect(ropeLength([3, 4, -12])).toBe(13);
  });
  it('takes the largest angle of the last seconds only', () => {
    const frames = [frame(0, [5, 0, -5]), frame(5, [1, 0, -10]), frame(12, [0, 2, -10]), frame(14, [0, 0, -10])];
    expect(recentMaxSway(frames, 10)).toBeCloseTo(Math.atan(0.2), 15);
    expect(recentMaxSway(frames, 100)).toBeCloseTo(Math.PI / 4, 15);
    expect(recentMaxSway([], 10)).toBe(0);
  });
  it('turns the wind between speed and direction and (x, y)', () => {
    expect(windVector(10, 0)).toEqual([10, 0]);
    expect(windVector(10, 90)).toEqual([0, 10]);
    expect(windVector(2, 225)).toEqual([-Math.round(Math.SQRT2 * 1e9) / 1e9, -Math.round(Math.SQRT2 * 1e9) / 1e9]);
    expect(windPolar([0, -3])).toEqual({ speed: 3, degrees: 270 });
    const back = windPolar(windVector(7, 135));
    expect(back.speed).toBeCloseTo(7, 8);
    expect(back.degrees).toBe(135);
  });
});

describe('crane words', () => {
  it('every language has every word, its own and with the same placeholders', () => {
    const holes = (s: string) => [...s.matchAll(/\{(\w+)\}/g)].map((m) => m[1]).sort();
    for (const lang of ['de', 'fr'] as const) {
      for (const [k, v] of Object.entries(CRANE_WORDS.en)) {
        const own = CRANE_WORDS[lang][k as keyof typeof CRANE_WORDS.en];
        expect(holes(own), `${lang}.${k}`).toEqual(holes(v));
        expect(own.length).toBeGreaterThan(0);
      }
      expect(CRANE_WORDS[lang].on).not.toBe(CRANE_WORDS.en.on);
      expect(CRANE_WORDS[lang].rope).not.toBe(CRANE_WORDS.en.rope);
    }
    setLanguage('de');
    expect(cw('moveBy', { d: 5 })).toBe('5 m fahren');
    setLanguage('fr');
    expect(cw('rope')).toBe('Longueur du câble (m)');
    setLanguage('en');
    expect(cw('readout', { x: 1, y: 2, l: 3 })).toBe('Trolley at x = 1 m, y = 2 m · rope 3 m');
  });
});

describe('crane link', () => {
  it('a shared link in the crane mode enters it by the crane command, then its parameters', () => {
    const cmds = commandsFor({ model: 'crane', modelParams: { shaping: 1, wind_y: 5 }, length: 12 });
    expect(cmds.slice(0, 3)).toEqual([
      { type: 'crane', on: true },
      { type: 'set_params', params: { shaping: 1, wind_y: 5 } },
      { type: 'set_params', length: 12 },
    ]);
    expect(cmds.some((c) => c.type === 'set_model')).toBe(false);
  });
});
