// The lab's state store: everything the page knows, with no DOM and no WebGL, so it is unit-tested alone.
//
// It receives what the server sends (status notices, frame records, errors) and offers what the views
// draw: the state at the playhead (interpolated between received frames — the page never integrates),
// the trail, the histories of ΔE, ΔJ₃, z and tension for the plots, and the trajectory as CSV.
import type { ErrorNotice, EventNotice, ExactQuantities, Frame, Status, Vec3 } from './protocol';
import { recordEvent } from './events';
import { PeriodTimer, workBetween } from './measure';
import { pythonJSON } from './format';

/** Frames kept for interpolation. */
export const BUFFER_MAX = 512;
/** Frames kept for the trail. */
export const TRAIL_MAX = 4000;
/** Points per plotted series before the history is thinned (every other point dropped). */
export const HISTORY_MAX = 4000;
/** Frames kept for the CSV download (about 16 MB). */
export const TRAJECTORY_MAX = 200_000;
/** Most simulated time the playhead trails the newest frame, in ticks of the server. */
export const MAX_LAG_TICKS = 3;
/** Most wall-clock time [s] (times the time scale: simulated time) the playhead waits for a pendulum drawn
 *  beside this one (`LabStore.advancePlayhead`'s `holdAt`). */
export const MAX_HOLD_SECONDS = 1;

/** How the lab's engine rounds a·b + c, both the page's and `pendulab serve`'s (the live session steps with
 *  the core's default, `Arithmetic::Unfused`: docs/lab.md, "Against the Python package"); `pl.simulate(...,
 *  arithmetic=...)` with it replays a CSV download bit for bit. */
export const LAB_ARITHMETIC = 'unfused';

/** Columns of the CSV download, in SI units. */
export const CSV_COLUMNS = [
  't [s]',
  'x1 [m]',
  'x2 [m]',
  'x3 [m]',
  'v1 [m/s]',
  'v2 [m/s]',
  'v3 [m/s]',
  'energy [J]',
  'j3 [kg m^2/s]',
  'tension [N]',
  'power [W]',
  'a1 [m/s^2]',
  'a2 [m/s^2]',
  'a3 [m/s^2]',
  'pivot1 [m]',
  'pivot2 [m]',
  'pivot3 [m]',
  'taut [1]',
  'error_x [m]',
] as const;

export interface History {
  t: number[];
  dE: number[];
  dJ3: number[];
  z: number[];
  /** ż = v₃ [m/s] (the phase portrait's ordinate). */
  zdot: number[];
  tension: number[];
  /** The frames of the points above (for the plot of chosen variables, panels/chosen.ts). */
  frames: Frame[];
}

function emptyHistory(): History {
  return { t: [], dE: [], dJ3: [], z: [], zdot: [], tension: [], frames: [] };
}

/** Smallest and largest tension [N] received in the epoch, with their times [s]. */
export interface Extremes {
  min: number;
  tMin: number;
  max: number;
  tMax: number;
}

type Listener = () => void;

export function lerp(a: number, b: number, s: number): number {
  return a + (b - a) * s;
}

/** Linear interpolation of two frames at parameter s ∈ [0, 1]; the position is put back on the sphere of
 *  radius lerp(|x_a|, |x_b|) so the bob never cuts the chord (the spring's and the slack string's radius
 *  varies, so the radius is interpolated too); slack if either frame is; the error unknown (−1) if either
 *  is. Drawing only: no dynamics. */
export function interpolateFrames(a: Frame, b: Frame, s: number): Frame {
  const vec = (p: Vec3, q: Vec3): Vec3 => [lerp(p[0], q[0], s), lerp(p[1], q[1], s), lerp(p[2], q[2], s)];
  const x = vec(a.x, b.x);
  const r = lerp(Math.hypot(...a.x), Math.hypot(...b.x), s);
  const n = Math.hypot(...x);
  if (n > 0) for (let i = 0; i < 3; i++) x[i] = (x[i] as number) * (r / n);
  return {
    t: lerp(a.t, b.t, s),
    x,
    v: vec(a.v, b.v),
    energy: lerp(a.energy, b.energy, s),
    j3: lerp(a.j3, b.j3, s),
    tension: lerp(a.tension, b.tension, s),
    power: lerp(a.power, b.power, s),
    a: vec(a.a, b.a),
    pivot: vec(a.pivot, b.pivot),
    taut: a.taut && b.taut,
    errorX: a.errorX < 0 || b.errorX < 0 ? -1 : lerp(a.errorX, b.errorX, s),
  };
}

/** Whether the status notice `next` starts a new trajectory, so that the trail (and the frames and plots)
 *  must break there rather than join the old path to the new one with a chord: the first status, a new
 *  epoch (reset, set_state — dragging the bob —, a scenario or URL loaded, new parameters or model), or
 *  time gone back behind the newest frame held, `latestT` (a server session that started afresh, whose
 *  epoch count restarts). Within one trajectory the server's status time never falls behind its frames. */
export function startsNewTrajectory(prev: Status | null, next: Status, latestT: number | null): boolean {
  return prev === null || next.epoch !== prev.epoch || (latestT !== null && next.t < latestT);
}

/** The index of the first frame of the time-sorted `frames` with t > `t` (with t ≥ `t` if `inclusive`). */
function firstAfter(frames: readonly Frame[], t: number, inclusive: boolean): number {
  let lo = 0;
  let hi = frames.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    const ft = (frames[mid] as Frame).t;
    if (inclusive ? ft < t : ft <= t) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

export class LabStore {
  status: Status | null = null;
  /** Recent frames of the current epoch, oldest first (for interpolation). */
  frames: Frame[] = [];
  /** Frames for the trail, oldest first. */
  trail: Frame[] = [];
  history: History = emptyHistory();
  /** Every frame of the current epoch (up to TRAJECTORY_MAX), for the CSV download. */
  trajectory: Frame[] = [];
  trajectoryTruncated = false;
  /** The method and dt the trajectory was stepped with, and from when [s]: one, unless set_method (which
   *  goes on from the current state in the same epoch) changed them; for the CSV download. */
  methods: { t: number; method: string; dt: number }[] = [];
  /** E and J₃ of the epoch's first frame: the references of the drift plots. */
  reference: { energy: number; j3: number } | null = null;
  /** Tension extremes of the epoch (every received frame), or null before the first. */
  tensionExtremes: Extremes | null = null;
  /** Simulated time shown [s], or null before the first frame. */
  playT: number | null = null;
  exact: ExactQuantities | null = null;
  exactError: string | null = null;
  errors: ErrorNotice[] = [];
  /** The string's last events of the current epoch (the server's `event` notices), oldest first. */
  events: readonly EventNotice[] = [];
  connected = false;
  tickHz = 60;
  /** ∫P dt [J] over the received frames of the epoch (trapezoidal), minus the energy the string's snaps
   *  lost: the energy bar chart's "lost" is its negative (measure.ts). */
  work = 0;
  /** The z-period and azimuthal advance measured from the received frames (measure.ts). */
  readonly periodTimer = new PeriodTimer();

  private historyStride = 1;
  private historyCount = 0;
  /** The connection was lost: the next status comes from another server session (a new trajectory). */
  private disconnected = false;
  private listeners = new Set<Listener>();

  subscribe(fn: Listener): () => void {
    this.listeners.add(fn);
    return () => this.listeners.delete(fn);
  }

  private emit(): void {
    for (const fn of this.listeners) fn();
  }

  /** A status notice. A new trajectory (startsNewTrajectory, or the first status after a reconnection)
   *  clears frames, trail and plots: the trail never joins two trajectories. */
  onStatus(s: Status): void {
    const restart = this.disconnected || startsNewTrajectory(this.status, s, this.latest()?.t ?? null);
    this.disconnected = false;
    this.status = s;
    if (restart) this.clear();
    const last = this.methods[this.methods.length - 1];
    if (restart || last === undefined) this.methods = [{ t: s.t, method: s.method, dt: s.dt }];
    else if (last.method !== s.method || last.dt !== s.dt) this.methods.push({ t: s.t, method: s.method, dt: s.dt });
    this.emit();
  }

  clear(): void {
    this.frames = [];
    this.trail = [];
    this.history = emptyHistory();
    this.trajectory = [];
    this.trajectoryTruncated = false;
    this.reference = null;
    this.tensionExtremes = null;
    this.playT = null;
    this.exact = null;
    this.exactError = null;
    this.events = [];
    this.work = 0;
    this.periodTimer.reset();
    this.historyStride = 1;
    this.historyCount = 0;
  }

  onError(e: ErrorNotice): void {
    this.errors.push(e);
    if (this.errors.length > 20) this.errors.shift();
    this.emit();
  }

  /** An `event` notice: kept (the last EVENTS_SHOWN) when it belongs to the trajectory shown. */
  onEvent(e: EventNotice): void {
    const before = this.events;
    this.events = recordEvent(before, e, this.status?.epoch ?? null);
    if (this.events !== before) {
      this.work -= e.energy_lost;
      this.emit();
    }
  }

  setConnected(c: boolean): void {
    this.connected = c;
    if (!c) this.disconnected = true;
    this.emit();
  }

  setExact(q: ExactQuantities | null, error: string | null = null): void {
    this.exact = q;
    this.exactError = error;
    this.emit();
  }

  /** Frames of one binary message. Frames older than the newest one held (a late message) are ignored. */
  onFrames(frames: readonly Frame[]): void {
    for (const f of frames) {
      const last = this.frames[this.frames.length - 1];
      if (last !== undefined && f.t < last.t) continue;
      if (last !== undefined && f.t === last.t) this.frames.pop(); // same time: the newer numbers win
      else if (last !== undefined) this.work += workBetween(last, f);
      this.frames.push(f);
      this.periodTimer.push(f);
      if (this.reference === null) this.reference = { energy: f.energy, j3: f.j3 };
      const ex = this.tensionExtremes;
      if (ex === null) this.tensionExtremes = { min: f.tension, tMin: f.t, max: f.tension, tMax: f.t };
      else {
        if (f.tension < ex.min) [ex.min, ex.tMin] = [f.tension, f.t];
        if (f.tension > ex.max) [ex.max, ex.tMax] = [f.tension, f.t];
      }
      this.pushTrail(f);
      this.pushHistory(f);
      if (this.trajectory.length < TRAJECTORY_MAX) this.trajectory.push(f);
      else this.trajectoryTruncated = true;
      if (this.playT === null) this.playT = f.t;
    }
    if (this.frames.length > BUFFER_MAX) this.frames.splice(0, this.frames.length - BUFFER_MAX);
  }

  private pushTrail(f: Frame): void {
    const last = this.trail[this.trail.length - 1];
    if (last !== undefined && last.t === f.t) this.trail.pop();
    this.trail.push(f);
    if (this.trail.length > TRAIL_MAX) this.trail.splice(0, this.trail.length - TRAIL_MAX);
  }

  private pushHistory(f: Frame): void {
    const ref = this.reference;
    if (ref === null) return;
    const h = this.history;
    if (h.t.length > 0 && f.t <= (h.t[h.t.length - 1] as number)) return;
    if (this.historyCount++ % this.historyStride !== 0) return;
    h.t.push(f.t);
    h.dE.push(f.energy - ref.energy);
    h.dJ3.push(f.j3 - ref.j3);
    h.z.push(f.x[2]);
    h.zdot.push(f.v[2]);
    h.tension.push(f.tension);
    h.frames.push(f);
    if (h.t.length > HISTORY_MAX) {
      // thin: keep every other point (always the first), take every other future point
      const keep = <T>(a: T[]): T[] => a.filter((_, i) => i % 2 === 0);
      this.history = {
        t: keep(h.t),
        dE: keep(h.dE),
        dJ3: keep(h.dJ3),
        z: keep(h.z),
        zdot: keep(h.zdot),
        tension: keep(h.tension),
        frames: keep(h.frames),
      };
      this.historyStride *= 2;
      this.historyCount = 1;
    }
  }

  latest(): Frame | null {
    return this.frames[this.frames.length - 1] ?? null;
  }

  /** Moves the playhead by wallDt seconds of wall clock × time scale, kept within MAX_LAG_TICKS ticks of the
   *  newest frame (and at it while paused). `holdAt` [s]: the newest time of the pendulums drawn beside
   *  this one (the two-pendulum panel); a session started after this one's restart runs a constant time
   *  behind it (about 0.17 s in the one-file lab, where its engine starts), so the playhead waits there,
   *  and all are drawn at one time, unless that is more than MAX_HOLD_SECONDS × time scale behind this
   *  one's newest frame (a stalled session does not stop this one). Returns the time shown, or null
   *  without frames. */
  advancePlayhead(wallDt: number, holdAt: number | null = null): number | null {
    const latest = this.latest();
    const first = this.frames[0];
    if (latest === undefined || latest === null || first === undefined) return (this.playT = null);
    const s = this.status;
    let t: number;
    if (s === null || s.paused || this.playT === null) t = latest.t;
    else {
      const maxLag = (MAX_LAG_TICKS * s.time_scale) / this.tickHz;
      t = this.playT + Math.max(0, wallDt) * s.time_scale;
      t = Math.min(t, latest.t);
      t = Math.max(t, latest.t - maxLag, first.t);
    }
    const hold = MAX_HOLD_SECONDS * (s?.time_scale ?? 1);
    if (holdAt !== null && holdAt < t && holdAt >= latest.t - hold) t = Math.max(holdAt, first.t);
    this.playT = t;
    return t;
  }

  /** The state at the playhead: the received frames interpolated (never integrated). */
  displayed(): Frame | null {
    const t = this.playT;
    const fs = this.frames;
    if (t === null || fs.length === 0) return null;
    const last = fs[fs.length - 1] as Frame;
    if (t >= last.t) return last;
    // binary search for the last frame with time <= t
    let lo = 0;
    let hi = fs.length - 1;
    if (t <= (fs[0] as Frame).t) return fs[0] as Frame;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if ((fs[mid] as Frame).t <= t) lo = mid;
      else hi = mid;
    }
    const a = fs[lo] as Frame;
    const b = fs[hi] as Frame;
    const span = b.t - a.t;
    return interpolateFrames(a, b, span > 0 ? (t - a.t) / span : 1);
  }

  /** The trail frames with time in [playT − seconds, playT]: `this.trail[start..end)` (the trail is sorted
   *  by time; found by bisection, nothing copied: the scene reads it every frame). */
  trailRange(seconds: number): { start: number; end: number } {
    const t = this.playT;
    if (t === null) return { start: 0, end: 0 };
    const end = firstAfter(this.trail, t, false);
    const start = firstAfter(this.trail, t - seconds, true);
    return { start: Math.min(start, end), end };
  }

  /** Trail frames with time in [playT − seconds, playT] (a copy). */
  trailWindow(seconds: number): Frame[] {
    const { start, end } = this.trailRange(seconds);
    return this.trail.slice(start, end);
  }

  /** The trajectory received in this epoch as CSV: a `#` line of metadata as the CLI's CSVs have it
   *  (`# pendulab lab trajectory; metadata (JSON): {…}`, keys sorted: python/pendulab/io.py `csv_header`),
   *  a header with units, rows. The metadata carries what replays the run with `pl.simulate` (docs/web.md,
   *  "Share and export"): the pendulum as `pl.Pendulum(**pendulum)` takes it, the method, the start (the
   *  epoch's first frame: the state the engine stepped on from, also after a change of model or parameters
   *  mid-run, where the scenario's start would not replay the rows), `options` as the CLI writes them with
   *  the arithmetic the engine steps with, and `method_changes` (set_method mid-epoch: t, method, dt). */
  toCSV(): string {
    const s = this.status;
    const first = this.trajectory[0];
    const meta = {
      software: 'pendulab',
      source: 'pendulab lab',
      scenario: s?.scenario ?? null,
      pendulum: s === null ? null : { model: s.model, ...s.params, ...s.model_params },
      params: s?.params ?? null,
      model: s?.model ?? null,
      model_params: s?.model_params ?? null,
      method: s?.method ?? null,
      // an adaptive method (dop853) chooses its own steps: the lab's dt setting is none of them
      adaptive: s?.adaptive ?? null,
      dt: s === null || s.adaptive ? null : s.dt,
      start: first === undefined ? null : { t: first.t, x: first.x, v: first.v },
      options: s === null ? null : { arithmetic: LAB_ARITHMETIC, ...(s.adaptive ? {} : { dt: s.dt }), t0: first?.t ?? s.t0 },
      method_changes: this.methods.slice(1),
      truncated: this.trajectoryTruncated,
    };
    const header = CSV_COLUMNS.join(',');
    const rows = this.trajectory.map((f) =>
      [f.t, ...f.x, ...f.v, f.energy, f.j3, f.tension, f.power, ...f.a, ...f.pivot, f.taut ? 1 : 0, f.errorX].map((v) => String(v)).join(','),
    );
    return [`# pendulab lab trajectory; metadata (JSON): ${pythonJSON(meta)}`, header, ...rows].join('\n') + '\n';
  }
}
