// The early socket's held handlers (web/src/wiring/connect.ts): calls before the panels exist are kept
// and replayed in their order when the real handlers are attached; later calls go straight through.
import { describe, expect, it } from 'vitest';
import { HeldHandlers } from '../../src/wiring/connect';
import type { ConnectionHandlers } from '../../src/connection';

describe('held handlers', () => {
  it('replays what came before attach, in order, then passes calls through', () => {
    const seen: string[] = [];
    const real: ConnectionHandlers = {
      onOpen: () => seen.push('open'),
      onClose: () => seen.push('close'),
      onFrames: (f) => seen.push(`frames ${f.length}`),
      onNotice: (n) => seen.push(`notice ${n.type}`),
      onProtocolError: (m) => seen.push(`protocol ${m}`),
    };
    const held = new HeldHandlers();
    held.onOpen();
    held.onNotice({ type: 'error', message: 'x', command: null });
    held.onFrames([]);
    held.onProtocolError('bad');
    expect(seen).toEqual([]);
    held.attach(real);
    expect(seen).toEqual(['open', 'notice error', 'frames 0', 'protocol bad']);
    held.onClose();
    expect(seen.at(-1)).toBe('close');
    expect(seen).toHaveLength(5);
  });
});
