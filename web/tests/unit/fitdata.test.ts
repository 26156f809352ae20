import { describe, expect, it } from 'vitest';
import { MAX_FIT_BYTES, fitRequest, loadCommands, readFitAnswer } from '../../src/fitdata';
import type { FittedLab } from '../../src/fitdata';
import { MEASURED_MAX, dotPattern, pathPositions } from '../../src/scene/measured';

const lab: FittedLab = {
  title: 'fitted to swing.csv',
  params: { length: 0.62, mass: 1, g: 9.8 },
  model: 'damped',
  model_params: { damping: 0.02 },
  start: { x: [0.3, 0, -0.54], v: [0, 0, 0] },
  method: 'dop853',
  dt: 0.001,
};

describe('fitRequest', () => {
  it('sends the text, the name, the model and the parameters split at commas and spaces', () => {
    expect(fitRequest('a.csv', 't,x,z\n0,1,2\n', 12, 'damped', ' length, g  pivot,')).toEqual({
      csv: 't,x,z\n0,1,2\n',
      name: 'a.csv',
      model: 'damped',
      fit: ['length', 'g', 'pivot'],
    });
  });
  it('leaves the parameters to the server when none are named', () => {
    expect(fitRequest('a.csv', 't,x\n', 5, 'ideal', '  ')).not.toHaveProperty('fit');
  });
  it('refuses a file over the server limit and an empty one, naming the file', () => {
    const big = fitRequest('big.csv', '', MAX_FIT_BYTES + 1, 'damped', '');
    expect(big).toMatch(/^big\.csv: 2\.0 MiB; the lab fits files of at most 2 MiB/);
    expect(fitRequest('e.csv', ' \n', 2, 'damped', '')).toBe('e.csv: the file is empty');
    expect(typeof fitRequest('ok.csv', 'x', MAX_FIT_BYTES, 'damped', '')).toBe('object');
  });
});

describe('readFitAnswer', () => {
  const good = {
    report: 'fit of the damped pendulum',
    scenario_toml: 'title = "x"',
    warnings: ['w', 3],
    params: { length: { value: 0.62, stderr: 0.003, unit: 'm', determined: true } },
    converged: true,
    lab,
    measured: { t: [0, 0.1], x: [[0.1, 0, -0.6], [0.2, 0, -0.58]], points: 2 },
  };
  it('keeps a well-formed answer (non-string warnings dropped)', () => {
    const a = readFitAnswer(good);
    if (typeof a === 'string') throw new Error(a);
    expect(a.measured?.x).toHaveLength(2);
    expect(a.warnings).toEqual(['w']);
    expect(a.lab?.model).toBe('damped');
  });
  it('accepts frame-free data without a path', () => {
    const a = readFitAnswer({ ...good, measured: null });
    expect(typeof a === 'string' ? a : a.measured).toBeNull();
  });
  it('refuses a malformed path or a missing report with a sentence', () => {
    expect(readFitAnswer({ ...good, measured: { t: [0], x: [[1, 2]] } })).toMatch(/malformed measured path/);
    expect(readFitAnswer({ ...good, measured: { t: [0, 1], x: [[1, 2, 3]] } })).toMatch(/malformed/);
    expect(readFitAnswer({ ...good, measured: { t: [0], x: [[1, 2, null]] } })).toMatch(/malformed/);
    expect(readFitAnswer({ ...good, report: undefined })).toMatch(/no report/);
    expect(readFitAnswer(null)).toMatch(/not an object/);
  });
});

describe('loadCommands', () => {
  it('loads the fitted model, parameters, method and start, then resets to it', () => {
    const cmds = loadCommands(lab);
    expect(cmds[0]).toEqual({ type: 'set_model', model: 'damped', params: { damping: 0.02 } });
    expect(cmds).toContainEqual({ type: 'set_params', length: 0.62, mass: 1, g: 9.8 });
    expect(cmds).toContainEqual({ type: 'set_method', method: 'dop853', dt: 0.001 });
    expect(cmds).toContainEqual({ type: 'set_state', x: [0.3, 0, -0.54], v: [0, 0, 0] });
    expect(cmds[cmds.length - 1]).toEqual({ type: 'reset' });
  });
});

describe('measured path geometry', () => {
  it('places the points about the pivot and drops non-finite ones', () => {
    const p = pathPositions(
      [
        [0.1, 0.2, -0.5],
        [Number.NaN, 0, 0],
        [0, 0, -1],
      ],
      [1, 2, 3],
    );
    expect(Array.from(p)).toEqual([1.1, 2.2, 2.5, 1, 2, 2].map((v) => Math.fround(v)));
  });
  it('draws at most MEASURED_MAX points', () => {
    const many = Array.from({ length: MEASURED_MAX + 10 }, (_, i) => [i, 0, 0] as [number, number, number]);
    expect(pathPositions(many).length).toBe(3 * MEASURED_MAX);
  });
  it('puts one dot per segment: dash + gap equal the mean spacing', () => {
    const { dash, gap } = dotPattern(3, 301);
    expect(dash + gap).toBeCloseTo(0.01, 12);
    expect(dash).toBeCloseTo(0.01 / 3, 12);
    expect(dotPattern(0, 1).dash).toBeGreaterThan(0);
  });
});
