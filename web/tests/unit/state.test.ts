import { beforeEach, describe, expect, it } from 'vitest';
import type { Frame, Status } from '../../src/protocol';
import { BUFFER_MAX, HISTORY_MAX, LabStore, MAX_HOLD_SECONDS, TRAIL_MAX, interpolateFrames, startsNewTrajectory } from '../../src/state';

function status(over: Partial<Status> = {}): Status {
  return {
    type: 'status',
    epoch: 0,
    scenario: 'rosette',
    title: null,
    paused: false,
    time_scale: 1,
    method: 'rattle',
    adaptive: false,
    dt: 0.001,
    params: { length: 1, mass: 1, g: 9.81 },
    t: 0,
    t0: 0,
    start: { x: [0, 0, -1], v: [1, 0, 0] },
    lagging: false,
    frame_fields: [],
    model: 'ideal',
    model_params: {},
    ...over,
  };
}

/** A frame on the unit circle in the xy plane at angle ω t (not physics: just data to draw). */
function frame(t: number, energy = -9.81, j3 = 1): Frame {
  return {
    t,
    x: [Math.cos(t), Math.sin(t), 0],
    v: [-Math.sin(t), Math.cos(t), 0],
    energy,
    j3,
    tension: 1,
    power: 0,
    a: [-Math.cos(t), -Math.sin(t), 0],
    pivot: [0, 0, 0],
    taut: true,
    errorX: 0,
  };
}

describe('LabStore', () => {
  let store: LabStore;
  beforeEach(() => {
    store = new LabStore();
    store.onStatus(status());
  });

  it('starts the playhead at the first frame and keeps drift references', () => {
    store.onFrames([frame(0, -9.81, 1), frame(1 / 60, -9.8, 1.5)]);
    expect(store.playT).toBe(0);
    expect(store.reference).toEqual({ energy: -9.81, j3: 1 });
    expect(store.history.dE[1]).toBeCloseTo(0.01, 12);
    expect(store.history.dJ3).toEqual([0, 0.5]);
    expect(store.history.z).toEqual([0, 0]);
  });

  it('advances the playhead with wall clock × time scale, never past the newest frame', () => {
    store.onStatus(status({ time_scale: 2 }));
    store.onFrames([frame(0), frame(0.05), frame(0.1)]);
    expect(store.advancePlayhead(0.01)).toBeCloseTo(0.02, 12);
    expect(store.advancePlayhead(1)).toBe(0.1);
  });

  it('keeps the playhead within a few ticks of the newest frame', () => {
    store.onFrames([frame(0)]);
    store.onFrames([frame(10)]);
    // max lag = 3 ticks × time scale 1 / 60 Hz
    expect(store.advancePlayhead(0)).toBeCloseTo(10 - 3 / 60, 12);
  });

  it('waits for a pendulum drawn beside it, at most MAX_HOLD_SECONDS behind the newest frame', () => {
    // the second session started 0.17 s after this one's restart: both are drawn at its newest time
    store.onFrames([frame(0), frame(5), frame(10)]);
    expect(store.advancePlayhead(0, 9.83)).toBe(9.83);
    expect(store.advancePlayhead(1 / 60, 9.85)).toBe(9.85); // where the max-lag rule alone gives 10 − 3/60
    expect(store.advancePlayhead(1 / 60, 12)).toBeCloseTo(10 - 3 / 60, 12); // ahead of this one: no hold
    expect(store.advancePlayhead(0, 10 - MAX_HOLD_SECONDS - 0.01)).toBeCloseTo(10 - 3 / 60, 12); // stalled: not held
    store.onStatus(status({ paused: true, t: 10 }));
    expect(store.advancePlayhead(0, 9.9)).toBe(9.9); // paused: both shown at one time too
    expect(store.advancePlayhead(0, null)).toBe(10);
    store.onStatus(status({ paused: false, t: 10, time_scale: 4 })); // the hold scales with the time scale
    expect(store.advancePlayhead(0, 10 - 2 * MAX_HOLD_SECONDS)).toBe(10 - 2 * MAX_HOLD_SECONDS);
    const young = new LabStore();
    young.onStatus(status());
    young.onFrames([frame(1), frame(1.5)]);
    expect(young.advancePlayhead(0, 0.75)).toBe(1); // never before this one's first frame
  });

  it('shows the newest frame while paused', () => {
    store.onFrames([frame(0), frame(0.5)]);
    store.onStatus(status({ paused: true, t: 0.5 }));
    expect(store.advancePlayhead(0)).toBe(0.5);
    expect(store.displayed()).toEqual(frame(0.5));
  });

  it('interpolates between frames and keeps the bob on the sphere (drawing only)', () => {
    store.onFrames([frame(0), frame(Math.PI / 2)]);
    store.playT = Math.PI / 4;
    const f = store.displayed();
    expect(f).not.toBeNull();
    expect(Math.hypot(...(f as Frame).x)).toBeCloseTo(1, 14);
    expect((f as Frame).x[0]).toBeCloseTo(Math.SQRT1_2, 14);
    const mid = interpolateFrames(frame(0, 1, 1), frame(1, 3, 5), 0.5);
    expect(mid.energy).toBe(2);
    expect(mid.j3).toBe(3);
  });

  it('clears frames, trail, plots and the exact solution on a new epoch only', () => {
    store.onFrames([frame(0), frame(0.1)]);
    store.setExact({
      kind: 'generic',
      energy: 0,
      j3: 0,
      omega0: 1,
      turning_heights: [-1, 0],
      modulus: 0.5,
      period_z: 1,
      period_z_infinite: false,
      azimuth_advance: 3,
      rotation_number: 0.5,
      phases: null,
      phases_note: null,
    });
    store.onStatus(status({ paused: true, t: 0.1 })); // same epoch (the server's t: its newest frame's)
    expect(store.frames).toHaveLength(2);
    expect(store.exact).not.toBeNull();
    store.onStatus(status({ epoch: 1 }));
    expect(store.frames).toHaveLength(0);
    expect(store.trail).toHaveLength(0);
    expect(store.history.t).toHaveLength(0);
    expect(store.reference).toBeNull();
    expect(store.exact).toBeNull();
    expect(store.playT).toBeNull();
  });

  it('ignores late frames and lets a frame at the same time replace the last', () => {
    store.onFrames([frame(0), frame(1)]);
    store.onFrames([frame(0.5)]);
    expect(store.frames.map((f) => f.t)).toEqual([0, 1]);
    store.onFrames([frame(1, -1)]);
    expect(store.frames).toHaveLength(2);
    expect(store.latest()?.energy).toBe(-1);
  });

  it('bounds the buffers: frames, trail, and a thinned history covering the whole run', () => {
    const n = 3 * HISTORY_MAX + 7;
    const frames = Array.from({ length: n }, (_, i) => frame(i / 60));
    store.onFrames(frames);
    expect(store.frames).toHaveLength(BUFFER_MAX);
    expect(store.trail).toHaveLength(Math.min(n, TRAIL_MAX));
    expect(store.history.t.length).toBeLessThanOrEqual(HISTORY_MAX);
    expect(store.history.t.length).toBeGreaterThan(HISTORY_MAX / 4);
    expect(store.history.t[0]).toBe(0);
    const last = store.history.t[store.history.t.length - 1] as number;
    expect(last).toBeGreaterThan(((n - 1) / 60) * 0.99);
    const ts = store.history.t;
    expect(ts.every((t, i) => i === 0 || t > (ts[i - 1] as number))).toBe(true);
    expect(store.trajectory).toHaveLength(n);
  });

  it('decides where the trail breaks: a new epoch, or time gone back behind the newest frame', () => {
    const s0 = status({ epoch: 3, t: 2 });
    expect(startsNewTrajectory(null, s0, null)).toBe(true);
    expect(startsNewTrajectory(s0, status({ epoch: 3, t: 2, paused: true }), 2)).toBe(false);
    expect(startsNewTrajectory(s0, status({ epoch: 4, t: 2 }), 2)).toBe(true);
    expect(startsNewTrajectory(s0, status({ epoch: 3, t: 0 }), 2)).toBe(true);
    expect(startsNewTrajectory(s0, status({ epoch: 3, t: 0 }), null)).toBe(false);
  });

  it('draws no segment joining two epochs: the trail holds only the new epoch', () => {
    store.onFrames([0, 1, 2].map((t) => frame(t)));
    store.onStatus(status({ epoch: 1, t: 2 })); // e.g. set_state (dragging the bob) at t = 2
    const jumped = { ...frame(2), x: [0, 0, -1] as [number, number, number] };
    store.onFrames([jumped, { ...jumped, t: 2.1 }]);
    store.playT = 2.1;
    expect(store.trailWindow(10).map((f) => [f.t, f.x[2]])).toEqual([
      [2, -1],
      [2.1, -1],
    ]);
  });

  it('breaks the trail when time goes back within one epoch (a session started afresh)', () => {
    store.onFrames([0, 1, 2, 3].map((t) => frame(t)));
    store.onStatus(status({ epoch: 0, t: 0 })); // the server's epoch count restarted: same number, t back
    store.onFrames([frame(0), frame(0.1)]);
    expect(store.trail.map((f) => f.t)).toEqual([0, 0.1]);
    expect(store.frames.map((f) => f.t)).toEqual([0, 0.1]);
    expect(store.playT).toBe(0);
  });

  it('breaks the trail after a reconnection even with the same epoch and a later time', () => {
    store.onFrames([frame(0), frame(1)]);
    store.setConnected(false);
    store.setConnected(true);
    store.onStatus(status({ epoch: 0, t: 5 }));
    store.onFrames([frame(5), frame(5.1)]);
    expect(store.trail.map((f) => f.t)).toEqual([5, 5.1]);
    store.onStatus(status({ epoch: 0, t: 5.1, paused: true })); // an ordinary status: no break
    expect(store.trail).toHaveLength(2);
  });

  it('gives a trail window ending at the playhead', () => {
    store.onFrames([0, 1, 2, 3, 4].map((t) => frame(t)));
    store.playT = 3.5;
    expect(store.trailWindow(2).map((f) => f.t)).toEqual([2, 3]);
  });

  it('finds the trail window as an index range without copying, both ends included', () => {
    store.onFrames([0, 1, 2, 3, 4].map((t) => frame(t)));
    store.playT = 3;
    expect(store.trailRange(2)).toEqual({ start: 1, end: 4 }); // t = 1, 2, 3
    store.playT = 3.5;
    expect(store.trailRange(0.2)).toEqual({ start: 4, end: 4 }); // nothing in [3.3, 3.5]
    store.playT = 10;
    expect(store.trailRange(100)).toEqual({ start: 0, end: 5 });
    store.playT = -1;
    expect(store.trailRange(10)).toEqual({ start: 0, end: 0 });
    store.playT = null;
    expect(store.trailRange(10)).toEqual({ start: 0, end: 0 });
  });

  it('gives the same trail window by bisection as by filtering', () => {
    const ts = Array.from({ length: 300 }, (_, i) => 0.37 * i + 0.01 * Math.sin(i));
    store.onFrames(ts.map((t) => frame(t)));
    for (const [play, seconds] of [
      [50, 10],
      [0.37 * 100, 0.37 * 20],
      [200, 5],
      [0, 0],
      [111.1, 111.1],
    ] as const) {
      store.playT = play;
      const want = store.trail.filter((f) => f.t <= play && f.t >= play - seconds).map((f) => f.t);
      expect(store.trailWindow(seconds).map((f) => f.t)).toEqual(want);
    }
  });

  it('writes the trajectory as CSV with metadata and units', () => {
    store.onFrames([frame(0), frame(0.5)]);
    const lines = store.toCSV().trim().split('\n');
    expect(lines).toHaveLength(4);
    // the CLI's metadata line (python/pendulab/io.py csv_header), read as the README reads it
    const [prefix, json] = (lines[0] as string).split('metadata (JSON): ');
    expect(prefix).toBe('# pendulab lab trajectory; ');
    const meta = JSON.parse(json as string) as Record<string, unknown>;
    expect(meta).toMatchObject({ scenario: 'rosette', method: 'rattle', model: 'ideal', model_params: {} });
    // what replays the run: pl.Pendulum(**pendulum), the epoch's start, the arithmetic the engine steps with
    expect(meta['pendulum']).toEqual({ model: 'ideal', length: 1, mass: 1, g: 9.81 });
    expect(meta['start']).toEqual({ t: 0, x: [1, 0, 0], v: [0, 1, 0] }); // the first frame's state
    expect(meta['method_changes']).toEqual([]);
    expect(meta['options']).toEqual({ arithmetic: 'unfused', dt: 0.001, t0: 0 });
    expect(Object.keys(meta)).toEqual([...Object.keys(meta)].sort()); // sorted as json.dumps(sort_keys=True)
    expect(json).toContain('"options": {"arithmetic": "unfused", "dt": 0.001, "t0": 0}');
    expect(lines[1]).toBe(
      't [s],x1 [m],x2 [m],x3 [m],v1 [m/s],v2 [m/s],v3 [m/s],energy [J],j3 [kg m^2/s],tension [N],' +
        'power [W],a1 [m/s^2],a2 [m/s^2],a3 [m/s^2],pivot1 [m],pivot2 [m],pivot3 [m],taut [1],error_x [m]',
    );
    const row = (lines[3] as string).split(',').map(Number);
    const [c, s] = [Math.cos(0.5), Math.sin(0.5)];
    expect(row).toEqual([0.5, c, s, 0, -s, c, 0, -9.81, 1, 1, 0, -c, -s, 0, 0, 0, 0, 1, 0]);
    expect(meta).toMatchObject({ adaptive: false, dt: 0.001 });
  });

  it('writes no dt for an adaptive method, which chooses its own steps', () => {
    store.onStatus(status({ method: 'dop853', adaptive: true, dt: 0.001 }));
    store.onFrames([frame(0), frame(0.5)]);
    const meta = JSON.parse((store.toCSV().split('\n')[0] as string).split('metadata (JSON): ')[1] as string);
    expect(meta).toMatchObject({ method: 'dop853', adaptive: true, dt: null });
    expect(meta.options).toEqual({ arithmetic: 'unfused', t0: 0 }); // as pl.simulate's: no dt for dop853
  });

  it("starts the CSV's run at the epoch's first frame, with the model's own parameters and any change of method", () => {
    // a change of model mid-run: a new epoch going on from the state reached, not from the scenario's start
    store.onStatus(status({ epoch: 1, t: 2.5, model: 'damped', model_params: { damping: 0.8 } }));
    store.onFrames([frame(2.5), frame(2.6)]);
    const meta = () => JSON.parse((store.toCSV().split('\n')[0] as string).split('metadata (JSON): ')[1] as string) as Record<string, unknown>;
    expect(meta()['pendulum']).toEqual({ model: 'damped', length: 1, mass: 1, g: 9.81, damping: 0.8 });
    expect(meta()['start']).toEqual({ t: 2.5, x: [Math.cos(2.5), Math.sin(2.5), 0], v: [-Math.sin(2.5), Math.cos(2.5), 0] });
    expect(meta()['options']).toMatchObject({ arithmetic: 'unfused', t0: 2.5 });
    // set_method goes on in the same epoch: said, with when
    store.onStatus(status({ epoch: 1, t: 2.7, model: 'damped', model_params: { damping: 0.8 } }));
    expect(meta()['method_changes']).toEqual([]);
    store.onStatus(status({ epoch: 1, t: 2.75, method: 'rk4', dt: 0.01, model: 'damped', model_params: { damping: 0.8 } }));
    expect(meta()['method_changes']).toEqual([{ dt: 0.01, method: 'rk4', t: 2.75 }]);
    store.onStatus(status({ epoch: 2, t: 3 }));
    expect(meta()['method_changes']).toEqual([]);
  });

  it('notifies subscribers and keeps the last errors', () => {
    let calls = 0;
    const off = store.subscribe(() => calls++);
    store.onError({ type: 'error', message: 'x', command: null });
    off();
    store.onError({ type: 'error', message: 'y', command: null });
    expect(calls).toBe(1);
    expect(store.errors.map((e) => e.message)).toEqual(['x', 'y']);
  });
});

describe('tension extremes and the phase history', () => {
  it('keeps the smallest and largest tension of the epoch with their times, and ż', () => {
    const store = new LabStore();
    store.onStatus(status());
    const tensions = [3, 1, 7, 2];
    store.onFrames(tensions.map((T, i) => ({ ...frame(i), tension: T, v: [0, 0, i] as [number, number, number] })));
    expect(store.tensionExtremes).toEqual({ min: 1, tMin: 1, max: 7, tMax: 2 });
    expect(store.history.zdot).toEqual([0, 1, 2, 3]);
    store.onStatus(status({ epoch: 1 }));
    expect(store.tensionExtremes).toBeNull();
  });

  it('interpolates the pivot, the acceleration and the power too', () => {
    const a = { ...frame(0), pivot: [0, 0, 0] as [number, number, number], power: 0 };
    const b = { ...frame(1), pivot: [2, 0, -4] as [number, number, number], power: -2 };
    const m = interpolateFrames(a, b, 0.25);
    expect(m.pivot).toEqual([0.5, 0, -1]);
    expect(m.power).toBe(-0.5);
    expect(m.a[0]).toBeCloseTo(0.75 * -1 + 0.25 * -Math.cos(1), 15);
  });
});
