// Values typed into the panel's boxes (the lab audit of 2026-11-27, in both transports): a lil-gui
// parameter box sends its value when it is complete, never the keystrokes on the way, and a refused value
// leaves the box showing the value in effect; an emptied or mistyped number box is "not a number" with a
// message, never 0 (the start angle, the second, third and fourth pendulums).
import { describe, expect, it } from 'vitest';
import { typedNumber } from '../../src/format';
import { ParamEdit } from '../../src/panels/params';
import { startCommand } from '../../src/panels/tools';
import { twinProblem } from '../../src/twin';
import type { TwinOptions } from '../../src/twin';
import type { ParamSchema } from '../../src/protocol';

const g: ParamSchema = {
  name: 'g',
  unit: 'm/s^2',
  description: 'gravity',
  default: 9.81,
  min: -1e4,
  max: 1e4,
  ui_min: -30,
  ui_max: 30,
  step: 0.01,
};

/** A ParamEdit of `p` recording what it sends, explains and how often it shows the value in effect. */
function edit(p: ParamSchema) {
  const log = { sent: [] as number[], said: [] as string[], restored: 0 };
  const e = new ParamEdit(p, (v) => log.sent.push(v), (m) => log.said.push(m), () => log.restored++);
  return { e, log };
}

describe('a parameter box', () => {
  it('left with no number in it says so and shows the value in effect (lil-gui dropped "abc" silently)', () => {
    for (const text of ['abc', '', ' ', 'NaN', '-']) {
      const { e, log } = edit(g);
      e.left(text);
      expect(log.said).toEqual(['g must be a number']);
      expect([log.sent, log.restored]).toEqual([[], 1]);
    }
    for (const text of ['9.81', '12abc', '1e999', '-1e9']) {
      const { e, log } = edit(g);
      e.left(text); // a number: lil-gui reads it and the commit checks it
      expect([log.said, log.sent, log.restored]).toEqual([[], [], 0]);
    }
  });

  it('sends a typed number once it is complete, not its keystrokes (typing -1e9 sent g = -1)', () => {
    const { e, log } = edit(g);
    for (const v of [-1, -1, -1e9]) e.changed(v, true); // lil-gui's parseFloat of "-1", "-1e", "-1e9"
    expect(log.sent).toEqual([]);
    e.finished(); // Enter, or leaving the box
    expect(log.sent).toEqual([]);
    expect(log.said).toHaveLength(1);
    expect(log.said[0]).toMatch(/g = -1000000000/);
    expect(log.restored).toBe(1); // the box shows the g in effect again, not -1e9
  });

  it('sends an allowed typed number on finishing, once; the slider live', () => {
    const { e, log } = edit({ ...g, name: 'length', min: 1e-6, max: 1e4, unit: 'm' });
    for (const v of [0, 0, 0.5]) e.changed(v, true); // "0", "0.", "0.5": no message about 0
    e.finished();
    e.finished(); // a second finish sends nothing more
    expect(log).toEqual({ sent: [0.5], said: [], restored: 0 });
    e.changed(0.7, false); // the slider (or its arrow keys): live
    e.changed(0.8, false);
    e.finished(); // the end of the drag: already sent
    expect(log.sent).toEqual([0.5, 0.7, 0.8]);
  });
});

/** An <input type="number"> as the browser reports it. */
const box = (value: string, badInput = false) => ({ value, validity: { badInput } });

describe('a number box', () => {
  it('is NaN when empty or unreadable, never 0', () => {
    expect(typedNumber(box('12.5'))).toBe(12.5);
    expect(typedNumber(box('-1e9'))).toBe(-1e9);
    expect(typedNumber(box('0'))).toBe(0);
    expect(typedNumber(box(''))).toBeNaN(); // emptied
    expect(typedNumber(box('  '))).toBeNaN();
    expect(typedNumber(box('', true))).toBeNaN(); // "abc": the browser reports '' and badInput
  });

  it('an emptied or mistyped start angle is a message, not a start at 0°', () => {
    expect(startCommand(typedNumber(box('', true)), 0, 0)).toMatch(/θ₀/);
    expect(startCommand(30, typedNumber(box('')), 0)).toMatch(/φ₀/);
    expect(typeof startCommand(typedNumber(box('0')), 0, 0)).toBe('object');
  });

  it("the other pendulums' inputs: the chosen mode's only, NaN refused", () => {
    const o: TwinOptions = { mode: 'own', epsilon: NaN, method: 'rk4', damping: NaN, length: 0.5, mass: 1, theta: 0.2 };
    expect(twinProblem(o)).toBeNull(); // ε and the damping belong to other modes
    expect(twinProblem({ ...o, theta: NaN })).toBe('own');
    expect(twinProblem({ ...o, length: 0 })).toBe('own');
    expect(twinProblem({ ...o, mass: Infinity })).toBe('own');
    expect(twinProblem({ ...o, mode: 'epsilon' })).toBe('bad');
    expect(twinProblem({ ...o, mode: 'epsilon', epsilon: 0.001 })).toBeNull();
    expect(twinProblem({ ...o, mode: 'damped' })).toBe('bad');
    expect(twinProblem({ ...o, mode: 'damped', damping: -1 })).toBe('bad');
    expect(twinProblem({ ...o, mode: 'damped', damping: 0.5 })).toBeNull();
    expect(twinProblem({ ...o, mode: 'method', length: NaN })).toBeNull();
  });
});
