// The WebSocket to `pendulab serve` (/ws), or the in-page engine with the same messages (engine/, docs/lab.md):
// binary frames and JSON notices in, JSON commands out.
// Reconnects with back-off when the server goes away; commands sent while closed are dropped.
import type { Command, Frame, Notice } from './protocol';
import { decodeFrames, parseNotice, ProtocolError } from './protocol';
import type { SocketLike } from './engine';
import { openSocket } from './engine';

export interface ConnectionHandlers {
  onFrames(frames: Frame[]): void;
  onNotice(notice: Notice): void;
  onOpen(): void;
  onClose(): void;
  onProtocolError(message: string): void;
}

export function socketUrl(loc: Location): string {
  const scheme = loc.protocol === 'https:' ? 'wss:' : 'ws:';
  const dir = loc.pathname.endsWith('/') ? loc.pathname : loc.pathname.replace(/[^/]*$/, '');
  return `${scheme}//${loc.host}${dir}ws`;
}

/** Resolves true once the server has handled every command this page sent on the connection —
 *  `handled()`, the latest status's `commands`, has reached `sent()` — or false after `timeoutMs` (a
 *  server that never confirms: the caller goes on anyway). Checked every `pollMs`. The language switch
 *  waits for it before it reloads the page from its URL, which the statuses keep up to date: a command
 *  sent just before (a resume, a fitted scenario's commands) is then in the URL, not lost. */
export function whenCaughtUp(handled: () => number | undefined, sent: () => number, timeoutMs: number, pollMs = 20): Promise<boolean> {
  const end = Date.now() + timeoutMs;
  return new Promise((resolve) => {
    const check = () => {
      if ((handled() ?? -1) >= sent()) resolve(true);
      else if (Date.now() >= end) resolve(false);
      else setTimeout(check, pollMs);
    };
    check();
  });
}

export class Connection {
  /** Commands sent on the current socket (a new socket, a new server session: counted from 0). */
  sent = 0;
  private ws: SocketLike | null = null;
  private retryMs = 500;
  private closedByUs = false;

  constructor(
    private readonly url: string,
    private readonly handlers: ConnectionHandlers,
  ) {
    this.open();
  }

  private open(): void {
    const ws = openSocket(this.url); // the server's WebSocket, or the in-page engine (engine/)
    ws.binaryType = 'arraybuffer';
    ws.onopen = () => {
      this.retryMs = 500;
      this.sent = 0;
      this.handlers.onOpen();
    };
    ws.onmessage = (ev: MessageEvent<unknown>) => {
      try {
        if (ev.data instanceof ArrayBuffer) this.handlers.onFrames(decodeFrames(ev.data));
        else if (typeof ev.data === 'string') this.handlers.onNotice(parseNotice(ev.data));
      } catch (e) {
        if (e instanceof ProtocolError) this.handlers.onProtocolError(e.message);
        else throw e;
      }
    };
    ws.onclose = () => {
      this.ws = null;
      this.handlers.onClose();
      if (!this.closedByUs) {
        setTimeout(() => this.open(), this.retryMs);
        this.retryMs = Math.min(this.retryMs * 2, 5000);
      }
    };
    this.ws = ws;
  }

  get isOpen(): boolean {
    return this.ws !== null && this.ws.readyState === 1; // WebSocket.OPEN
  }

  send(cmd: Command): boolean {
    if (!this.isOpen || this.ws === null) return false;
    this.ws.send(JSON.stringify(cmd));
    this.sent++;
    return true;
  }

  close(): void {
    this.closedByUs = true;
    this.ws?.close();
  }
}
