// The string's event notices (the server's leaves and snaps): parsing, the message line, the list the data
// panel shows. Pure TS, no DOM.
import { describe, expect, it } from 'vitest';
import { EVENTS_SHOWN, eventMessage, eventRow, recordEvent } from '../../src/events';
import { liveRows } from '../../src/panels/data';
import type { EventNotice, Frame, Status } from '../../src/protocol';
import { ProtocolError, parseNotice } from '../../src/protocol';
import { LabStore } from '../../src/state';

function event(over: Partial<EventNotice> = {}): EventNotice {
  return { type: 'event', kind: 'slack', t: 1.2345, energy_lost: 0, x: [0.8, 0, 0.5], epoch: 3, skipped: 0, ...over };
}

function status(model: string, epoch: number): Status {
  return {
    type: 'status',
    epoch,
    scenario: 'string_slack',
    title: null,
    paused: false,
    time_scale: 1,
    method: 'rattle8',
    adaptive: false,
    dt: 0.001,
    params: { length: 1, mass: 1, g: 9.81 },
    t: 0,
    t0: 0,
    start: { x: [0, 0, -1], v: [5.859, 0, 0] },
    lagging: false,
    frame_fields: [],
    model,
    model_params: { restitution: 0 },
  };
}

const frame: Frame = {
  t: 2,
  x: [0, 0, -1],
  v: [0, 0, 0],
  energy: -1,
  j3: 0,
  tension: 9.81,
  power: 0,
  a: [0, 0, 0],
  pivot: [0, 0, 0],
  taut: true,
  errorX: 0,
};

describe('event notices', () => {
  it('parses a leave and a snap as the server sends them', () => {
    const slack = parseNotice(
      '{"type": "event", "kind": "slack", "t": 0.9123, "energy_lost": 0.0, "x": [0.86, 0.0, 0.5], "epoch": 2, "skipped": 0}',
    );
    expect(slack).toEqual({ type: 'event', kind: 'slack', t: 0.9123, energy_lost: 0, x: [0.86, 0, 0.5], epoch: 2, skipped: 0 });
    const taut = parseNotice(
      '{"type": "event", "kind": "taut", "t": 1.5, "energy_lost": 12.25, "x": [0, 0.1, -0.99], "epoch": 2, "skipped": 3}',
    );
    expect(taut).toMatchObject({ kind: 'taut', energy_lost: 12.25, skipped: 3 });
  });

  it('refuses a bad kind, a missing or non-finite time, a negative energy, a bad x or epoch', () => {
    const base = { type: 'event', kind: 'taut', t: 1, energy_lost: 0.5, x: [0, 0, -1], epoch: 0, skipped: 0 };
    const bad: Record<string, unknown>[] = [
      { kind: 'snap' },
      { kind: undefined },
      { t: null },
      { t: '1.0' },
      { energy_lost: -0.1 },
      { energy_lost: null },
      { x: [0, 0] },
      { x: [0, 0, 'a'] },
      { epoch: 1.5 },
      { skipped: -1 },
    ];
    for (const change of bad) {
      expect(() => parseNotice(JSON.stringify({ ...base, ...change }))).toThrow(ProtocolError);
    }
    expect(() => parseNotice(JSON.stringify({ ...base, t: 'NaN' }))).toThrow(/t is not a finite number/);
  });

  it('words the message line: when, and for a snap the energy lost', () => {
    expect(eventMessage(event())).toBe('t = 1.234 s: the string went slack (tension 0: free flight)');
    expect(eventMessage(event({ kind: 'taut', t: 2, energy_lost: 0.1234 }))).toBe(
      't = 2.000 s: the string snapped taut, lost 0.123 J',
    );
    expect(eventMessage(event({ kind: 'taut', energy_lost: 0, skipped: 2 }))).toMatch(
      /lost 0 J \(2 earlier events of this moment not shown\)$/,
    );
    expect(eventRow(event({ kind: 'taut', t: 2, energy_lost: 0.1234 }))).toEqual([
      'snapped taut',
      't = 2.00000 s, lost 0.1234',
      'J',
    ]);
  });

  it('keeps the last few events of the epoch shown, oldest first, and ignores those of another epoch', () => {
    let list: readonly EventNotice[] = [];
    for (let k = 0; k < EVENTS_SHOWN + 3; k++) list = recordEvent(list, event({ t: k }), 3);
    expect(list.map((e) => e.t)).toEqual([3, 4, 5, 6, 7]);
    expect(recordEvent(list, event({ epoch: 2 }), 3)).toBe(list);
    expect(recordEvent(list, event(), null)).toBe(list);
  });

  it('the store clears them with a new trajectory; the data panel lists them, newest first, for the string', () => {
    const store = new LabStore();
    store.onStatus(status('string', 3));
    expect(liveRows(frame, store).find((r) => r[0] === 'events')?.[1]).toBe('none yet (slack, snaps)');
    store.onEvent(event({ t: 0.9 }));
    store.onEvent(event({ kind: 'taut', t: 1.6, energy_lost: 19.5 }));
    store.onEvent(event({ epoch: 2, t: 5 })); // from the trajectory before: not listed
    expect(store.events.map((e) => e.t)).toEqual([0.9, 1.6]);
    const rows = liveRows(frame, store);
    const at = rows.findIndex((r) => r[0] === 'snapped taut');
    expect(rows.slice(at)).toEqual([
      ['snapped taut', 't = 1.60000 s, lost 19.50', 'J'],
      ['went slack', 't = 0.900000 s', ''],
    ]);
    store.onStatus(status('string', 4)); // reset: a new epoch
    expect(store.events).toEqual([]);
    store.onStatus(status('ideal', 5));
    store.onEvent(event({ epoch: 5 }));
    expect(liveRows(frame, store).some((r) => r[0] === 'went slack' || r[0] === 'events')).toBe(false);
  });
});
