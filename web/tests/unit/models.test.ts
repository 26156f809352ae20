import { describe, expect, it } from 'vitest';
import { offSphereNote, staysOnSphere, tetherStyle } from '../../src/models';
import { exactNote, liveRows } from '../../src/panels/data';
import type { Frame, Status, Vec3 } from '../../src/protocol';
import { coilPoints, polylineLength, sagPoints } from '../../src/scene/tether';
import { LabStore } from '../../src/state';

const dist = (a: Vec3, b: Vec3): number => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

function status(model: string, length = 1): Status {
  return {
    type: 'status',
    epoch: 0,
    scenario: null,
    title: null,
    paused: false,
    time_scale: 1,
    method: 'rattle',
    adaptive: false,
    dt: 0.001,
    params: { length, mass: 1, g: 9.81 },
    t: 0,
    t0: 0,
    start: { x: [0, 0, -1], v: [0, 0, 0] },
    lagging: false,
    frame_fields: [],
    model,
    model_params: {},
  };
}

function frame(x: Vec3, tension: number, taut: boolean): Frame {
  return { t: 1, x, v: [0, 0, 0], energy: -1, j3: 0, tension, power: 0, a: [0, 0, -9.81], pivot: [0, 0, 0], taut, errorX: 0 };
}

describe('models off the sphere', () => {
  it('the spring and the string leave the sphere; the others stay and keep the analyses', () => {
    for (const m of ['ideal', 'damped', 'rotating', 'slewing', 'vibrating', null, undefined]) {
      expect(staysOnSphere(m)).toBe(true);
      expect(offSphereNote(m)).toBeNull();
    }
    expect(staysOnSphere('spring')).toBe(false);
    expect(staysOnSphere('string')).toBe(false);
    expect(offSphereNote('spring')).toMatch(/length varies.*not shown/);
    expect(offSphereNote('string')).toMatch(/slack.*not shown/);
  });

  it('draw a coil for the spring, a string taut or slack, else a rod', () => {
    expect(tetherStyle('spring', true)).toBe('coil');
    expect(tetherStyle('string', true)).toBe('taut string');
    expect(tetherStyle('string', false)).toBe('slack string');
    expect(tetherStyle('damped', false)).toBe('rod');
  });
});

describe('the tether drawn', () => {
  it('a coil runs from the pivot to the bob, around the axis, for any spring length', () => {
    for (const x of [[0.3, 0.1, -1.2], [0, 0, -0.5], [0, 0, 2]] as Vec3[]) {
      const pts = coilPoints(x, 10, 0.04, 400);
      expect(pts).toHaveLength(401);
      expect(dist(pts[0] as Vec3, [0, 0, 0])).toBe(0);
      expect(dist(pts[400] as Vec3, x)).toBeLessThan(1e-12);
      // in the middle the coil is at its radius from the axis
      const p = pts[200] as Vec3;
      const r = Math.hypot(...x);
      const along = (p[0] * x[0] + p[1] * x[1] + p[2] * x[2]) / r;
      expect(Math.sqrt(Math.hypot(...p) ** 2 - along ** 2)).toBeCloseTo(0.04, 10);
      expect(along).toBeCloseTo(r / 2, 10);
    }
  });

  it('a slack string is as long as the string and sags along gravity; taut it is straight', () => {
    const x: Vec3 = [0.4, 0, 0.2]; // the bob in flight, |x| < l = 1
    const pts = sagPoints(x, 1, 64);
    expect(dist(pts[0] as Vec3, [0, 0, 0])).toBe(0);
    expect(dist(pts[64] as Vec3, x)).toBeLessThan(1e-12);
    expect(Math.abs(polylineLength(pts) - 1)).toBeLessThan(2e-3);
    expect(Math.min(...pts.map((p) => p[2]))).toBeLessThan(-0.2); // it hangs below the chord
    const sideways = sagPoints([0, 0, -0.4], 1, 64, [1, 0, 0]); // gravity along +x: it sags that way
    expect(Math.max(...sideways.map((p) => p[0]))).toBeGreaterThan(0.3);
    const straight = sagPoints([0, 0.6, -0.8], 1, 10);
    expect(polylineLength(straight)).toBeCloseTo(1, 12);
    // straight down (chord along gravity): it bends sideways, still of the string's length
    expect(Math.abs(polylineLength(sagPoints([0, 0, -0.3], 1, 64)) - 1)).toBeLessThan(2e-3);
  });
});

describe('data panel for the spring and the string', () => {
  const row = (rows: [string, string, string][], label: string) => rows.find((r) => r[0] === label);

  it('shows the spring force, length and stretch', () => {
    const store = new LabStore();
    store.onStatus(status('spring', 0.75));
    const rows = liveRows(frame([0, 0, -1], 9.81, true), store);
    expect(row(rows, 'spring force k(|r| − l₀)')).toEqual(['spring force k(|r| − l₀)', '9.81000', 'N']);
    expect(row(rows, 'spring length |r|')?.[1]).toBe('1.00000');
    expect(row(rows, 'stretch |r| − l₀')?.[1]).toBe('0.2500');
    expect(row(rows, 'tension')).toBeUndefined();
    expect(exactNote(store)).toMatch(/swinging spring leaves the sphere/);
  });

  it('says slack while the string is slack and taut while it holds', () => {
    const store = new LabStore();
    store.onStatus(status('string'));
    const slack = liveRows(frame([0.3, 0, 0.4], 0, false), store);
    expect(row(slack, 'tension')?.[1]).toBe('slack (0)');
    expect(row(slack, 'string')?.[1]).toBe('slack: free flight, |x| = 0.50000 m');
    const taut = liveRows(frame([0, 0, -1], 20, true), store);
    expect(row(taut, 'tension')?.[1]).toBe('20.0000');
    expect(row(taut, 'string')?.[1]).toBe('taut');
    expect(exactNote(store)).toMatch(/string goes slack/);
  });
});
