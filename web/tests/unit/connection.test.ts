// The language switch's wait (connection.ts, whenCaughtUp): the page reloads from its URL only once the
// server's status has counted every command the page sent, so a command sent just before is not lost.
import { describe, expect, it } from 'vitest';
import { whenCaughtUp } from '../../src/connection';

describe('whenCaughtUp', () => {
  it('resolves at once when the server has handled everything sent', async () => {
    expect(await whenCaughtUp(() => 7, () => 7, 1000)).toBe(true);
    expect(await whenCaughtUp(() => 0, () => 0, 1000)).toBe(true);
  });

  it('waits for the status that counts the last command', async () => {
    let handled = 3;
    setTimeout(() => (handled = 4), 60);
    const t0 = Date.now();
    expect(await whenCaughtUp(() => handled, () => 4, 2000, 5)).toBe(true);
    expect(Date.now() - t0).toBeGreaterThanOrEqual(50);
  });

  it('gives up after the timeout (no status yet, or a server that never confirms)', async () => {
    expect(await whenCaughtUp(() => undefined, () => 1, 50, 5)).toBe(false);
    expect(await whenCaughtUp(() => 2, () => 3, 50, 5)).toBe(false);
  });
});
