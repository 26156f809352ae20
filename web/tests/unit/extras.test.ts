// Pendulums in a row (twin.ts rowOffsets; panels/extras.ts): the second pivot where sideBySide puts it,
// each next one beside the one before with the same gap rule, all on one line, no spheres overlapping; a
// refused pendulum of its own named by its number.
import { describe, expect, it } from 'vitest';
import { rowOffsets, sideBySide } from '../../src/twin';
import { decodeTwin, decodeUrl, encodeUrl } from '../../src/url';
import type { TwinOptions } from '../../src/twin';
import { ownRefusal, twinRefusal } from '../../src/panels/extras';
import { LANGUAGES, setLanguage } from '../../src/i18n';

describe('a row of pendulums', () => {
  it('places pivots 2 … n beside each other along one line, 1.1 (l_i + l_{i+1}) apart [m]', () => {
    const lengths = [1, 0.25, 1, 0.5];
    const off = rowOffsets(lengths);
    expect(off).toHaveLength(3);
    expect(off[0]).toEqual(sideBySide(1, 0.25));
    const pivots = [[0, 0, 0], ...off];
    for (let i = 1; i < pivots.length; i++) {
      const [a, b] = [pivots[i - 1] as number[], pivots[i] as number[]];
      const gap = Math.hypot(b[0]! - a[0]!, b[1]! - a[1]!, b[2]! - a[2]!);
      expect(gap).toBeCloseTo(1.1 * (lengths[i - 1]! + lengths[i]!), 12);
      expect(gap).toBeGreaterThan(lengths[i - 1]! + lengths[i]!); // spheres of reach apart
      // collinear: every pivot on the line through the first two
      const d = off[0] as number[];
      expect(b[0]! * d[1]! - b[1]! * d[0]!).toBeCloseTo(0, 12);
      expect(b[2]).toBe(0);
    }
    expect(rowOffsets([2])).toEqual([]);
  });
});

describe('pendulums 3 and 4 in the share link', () => {
  it('own:l:m:θ₀ of the second, then l:m:θ₀ of each more after commas, read back exactly', () => {
    const deg = Math.PI / 180;
    const twin = { mode: 'own' as const, epsilon: 0, method: 'rk4', damping: 0, length: 0.25, mass: 1, theta: 10 * deg, extras: [{ length: 1, mass: 3, theta: 10 * deg }, { length: 0.5, mass: 1, theta: 15 * deg }] };
    const q = encodeUrl({ twin });
    expect(decodeURIComponent(q)).toContain('twin=own:0.25:1:10,1:3:10,0.5:1:15');
    const back = decodeUrl(q);
    expect(back.problems).toEqual([]);
    expect(back.value.twin?.extras?.map((e) => [e.length, e.mass, Math.round(e.theta / deg)])).toEqual([
      [1, 3, 10],
      [0.5, 1, 15],
    ]);
    expect(decodeTwin('own:0.25:1:10')?.extras).toBeUndefined();
  });

  it('refuses more than two more, a bad one, or extras after another mode', () => {
    expect(decodeTwin('own:1:1:10,1:1:10,1:1:10,1:1:10')).toBeNull();
    expect(decodeTwin('own:1:1:10,0:1:10')).toBeNull();
    expect(decodeTwin('own:1:1:10,1:1')).toBeNull();
    expect(decodeTwin('eps:0.5,1:1:10')).toBeNull();
    expect(decodeUrl('twin=own:1:1:10,1:-1:10').problems).toHaveLength(1);
  });
});

describe('a refused pendulum of its own is named', () => {
  it('the message names the pendulum whose length, mass or θ₀ is refused (2, 3 or 4), in every language', () => {
    const deg = Math.PI / 180;
    const ok: TwinOptions = { mode: 'own', epsilon: 0, method: 'rk4', damping: 0, length: 1, mass: 1, theta: 10 * deg };
    expect(ownRefusal([ok, ok], 3)).toBeNull();
    expect(ownRefusal([ok, { ...ok, mass: -1 }], 3)).toBe('pendulum 4 needs a length > 0, a mass > 0 and a start angle 0 … 180°');
    expect(ownRefusal([{ ...ok, length: NaN }, { ...ok, mass: -1 }], 3)).toMatch(/^pendulum 3 needs/);
    expect(ownRefusal([{ ...ok, theta: 200 * deg }], 2)).toMatch(/^pendulum 2 needs/);
    setLanguage('de');
    expect(ownRefusal([ok, { ...ok, length: 0 }], 3)).toMatch(/^Pendel 4 braucht/);
    setLanguage('fr');
    expect(ownRefusal([ok, { ...ok, length: 0 }], 3)).toMatch(/^le pendule 4 demande/);
    setLanguage('en');
    // no language names a fixed pendulum ("the second") in the message of every one
    for (const { words } of Object.values(LANGUAGES)) expect(words['twin.badOwn']).toContain('{n}');
  });
});

describe('a refused second pendulum names what is wrong', () => {
  it('ε for mode epsilon, the damping for mode damped, the pendulum for mode own; nothing when fine', () => {
    const o: TwinOptions = { mode: 'damped', epsilon: 0.01, method: 'rk4', damping: -1, length: 1, mass: 1, theta: 0.1 };
    expect(twinRefusal(o)).toBe('the damping must be a number ≥ 0 (1/s)'); // said "ε must be a number and …"
    expect(twinRefusal({ ...o, mode: 'epsilon', epsilon: NaN })).toBe('ε must be a number (degrees)');
    expect(twinRefusal({ ...o, mode: 'own', mass: 0 })).toMatch(/^pendulum 2 needs/);
    expect(twinRefusal({ ...o, damping: 0.5 })).toBeNull();
    expect(twinRefusal({ ...o, mode: 'epsilon' })).toBeNull(); // another mode's bad box is no reason
    setLanguage('de');
    expect(twinRefusal(o)).toMatch(/^die Dämpfung/);
    setLanguage('en');
  });
});
