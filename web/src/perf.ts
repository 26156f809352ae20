// Pacing and accounting of the page's per-frame work (docs/performance.md, "Lab frame rate"). Pure: no
// DOM, unit-tested.

/** At most one `due` per `intervalMs` (the side panels redraw at 10 Hz: they need not follow 60 frames/s). */
export class RateLimiter {
  private last = -Infinity;

  constructor(readonly intervalMs: number) {}

  /** Whether the work is due at time `now` [ms]; if so, counts it as done then. */
  due(now: number): boolean {
    if (now - this.last < this.intervalMs) return false;
    this.last = now;
    return true;
  }

  /** Makes the next `due` true (e.g. a panel scrolled into view). */
  reset(): void {
    this.last = -Infinity;
  }
}

/** Whether a list of values differs from the previous call's (element by element, Object.is): the scene
 *  is rendered only when what it shows changed, so a paused lab leaves the CPU alone. */
export class ChangeGate {
  private last: readonly unknown[] | null = null;

  changed(values: readonly unknown[]): boolean {
    const prev = this.last;
    if (prev !== null && prev.length === values.length && values.every((v, i) => Object.is(v, prev[i]))) return false;
    this.last = [...values];
    return true;
  }
}

/** Milliseconds spent per named part of the frame: `add` after each run, `take` the means since the last
 *  take (window.pendulab.frameCosts, read by tests/e2e/profile.mjs). */
export class FrameCosts {
  private sums = new Map<string, { ms: number; count: number }>();

  add(part: string, ms: number): void {
    const s = this.sums.get(part);
    if (s === undefined) this.sums.set(part, { ms, count: 1 });
    else {
      s.ms += ms;
      s.count++;
    }
  }

  /** Mean milliseconds and the number of runs of each part since the last take; starts afresh. */
  take(): Record<string, { ms: number; count: number }> {
    const out: Record<string, { ms: number; count: number }> = {};
    for (const [part, s] of this.sums) out[part] = { ms: s.ms / s.count, count: s.count };
    this.sums.clear();
    return out;
  }
}
