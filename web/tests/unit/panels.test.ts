import { describe, expect, it } from 'vitest';
import { scenarioRequest } from '../../src/export';
import { dataRange, potentialRange } from '../../src/panels/curves';
import { modelOptions, pickCommand } from '../../src/panels/model';
import { allowedRange, checkParam, paramLabel, unitLabel } from '../../src/panels/params';
import { polarAngle } from '../../src/panels/portraits';
import type { ParamSchema, Status } from '../../src/protocol';

const damping: ParamSchema = {
  name: 'damping',
  unit: '1/s',
  description: 'linear damping c',
  allowed: 'a finite number >= 0',
  default: 0,
  min: 0,
  max: null,
  ui_min: 0,
  ui_max: 2,
  step: 0.001,
};

describe('parameter controls', () => {
  it('label with units and say what is allowed', () => {
    expect(unitLabel('m/s^2')).toBe('m/s²');
    expect(unitLabel('1')).toBe('');
    expect(paramLabel(damping)).toBe('damping [1/s]');
    expect(paramLabel({ ...damping, name: 'gravity_x', unit: '1' })).toBe('gravity_x');
    expect(allowedRange(damping)).toBe('≥ 0 1/s');
    expect(allowedRange({ ...damping, min: null })).toBe('any finite number');
    expect(allowedRange({ ...damping, min: -1, max: 1, unit: 'rad' })).toBe('-1 … 1 rad');
  });

  it('refuse values outside the hard limits before sending, naming the value', () => {
    expect(checkParam(damping, 0.3)).toBeNull();
    expect(checkParam(damping, 50)).toBeNull(); // beyond the slider, within the limits
    expect(checkParam(damping, -0.1)).toBe('damping = -0.1 is not allowed: a finite number >= 0 (≥ 0 1/s)');
    expect(checkParam(damping, NaN)).toMatch(/damping = NaN/);
    expect(checkParam({ ...damping, min: null }, -5)).toBeNull();
  });

  it('offer every model by its label in words (the summary is the tooltip)', () => {
    const opts = modelOptions([
      { name: 'ideal', label: 'Ideal pendulum', summary: 'the ideal one (T-2.1)', params: [] },
      { name: 'damped', summary: 'with friction', params: [damping] },
    ]);
    expect(opts).toEqual({ 'Ideal pendulum (ideal)': 'ideal', damped: 'damped' });
  });

  it('picking damped starts with visible friction; other models with the registry defaults', () => {
    expect(pickCommand('damped')).toEqual({ type: 'set_model', model: 'damped', params: { damping: 0.3 } });
    expect(pickCommand('rotating')).toEqual({ type: 'set_model', model: 'rotating' });
  });

  it('label a parameter in words with its unit, the key name only when there are no words', () => {
    expect(paramLabel({ ...damping, label: 'friction (linear damping) c' })).toBe('friction (linear damping) c [1/s]');
    expect(paramLabel(damping)).toBe('damping [1/s]');
  });
});

describe('curve plots', () => {
  it('span the data with a margin, and a flat or empty set sensibly', () => {
    expect(dataRange([0, 10])).toEqual({ lo: -1, hi: 11 });
    expect(dataRange([NaN, 2, Infinity, 4])).toEqual({ lo: 1.8, hi: 4.2 });
    expect(dataRange([])).toEqual({ lo: -1, hi: 1 });
    expect(dataRange([3, 3])).toEqual({ lo: 2.5, hi: 3.5 });
  });

  it('show V_eff from below its minimum to above the energy', () => {
    const r = potentialRange(-10, -4, 9.81);
    expect(r.lo).toBeLessThan(-10);
    expect(r.hi).toBeGreaterThan(-4);
    const flat = potentialRange(-10, -10, 9.81); // at the bottom: a scale of the well
    expect(flat.hi - flat.lo).toBeCloseTo(2.35 * 0.2 * 9.81, 12);
  });

  it('measure θ from the downward vertical', () => {
    expect(polarAngle([0, 0, -1])).toBe(0);
    expect(polarAngle([1, 0, 0])).toBeCloseTo(Math.PI / 2, 15);
    expect(polarAngle([0, 0.5, 0.5])).toBeCloseTo((3 * Math.PI) / 4, 15);
  });
});

describe('scenario download', () => {
  it('sends the status as the body of /api/scenario.toml, running past the time reached', () => {
    const s: Status = {
      type: 'status',
      epoch: 1,
      scenario: 'damped',
      title: 'Damped',
      paused: false,
      time_scale: 1,
      method: 'rattle4',
      adaptive: false,
      dt: 0.002,
      params: { length: 1.5, mass: 2, g: 9 },
      model: 'damped',
      model_params: { damping: 0.1 },
      t: 250.2,
      t0: 0,
      start: { x: [0, 0, -1.5], v: [1, 0, 0] },
      lagging: false,
      frame_fields: [],
    };
    expect(scenarioRequest(s)).toEqual({
      title: 'Damped (from the lab)',
      model: 'damped',
      length: 1.5,
      mass: 2,
      g: 9,
      params: { damping: 0.1 },
      x: [0, 0, -1.5],
      v: [1, 0, 0],
      method: 'rattle4',
      dt: 0.002,
      t0: 0,
      t_end: 251,
    });
    expect(scenarioRequest({ ...s, t: 3 }).t_end).toBe(100);
    // an adaptive method: its tolerances, no dt (in a scenario file dt would be dop853's first step)
    const adaptive = scenarioRequest({ ...s, method: 'dop853', adaptive: true, dt: 0.001, rtol: 1e-8, atol: 1e-11 });
    expect(adaptive).toMatchObject({ method: 'dop853', rtol: 1e-8, atol: 1e-11 });
    expect('dt' in adaptive).toBe(false);
    expect('rtol' in scenarioRequest({ ...s, rtol: 1e-8, atol: 1e-11 })).toBe(false);
  });
});
