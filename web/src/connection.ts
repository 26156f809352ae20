// The WebSocket to `pendulab serve` (/ws): binary frames and JSON notices in, JSON commands out.
// Reconnects with back-off when the server goes away; commands sent while closed are dropped.
import type { Command, Frame, Notice } from './protocol';
import { decodeFrames, parseNotice, ProtocolError } from './protocol';

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

export class Connection {
  private ws: WebSocket | null = null;
  private retryMs = 500;
  private closedByUs = false;

  constructor(
    private readonly url: string,
    private readonly handlers: ConnectionHandlers,
  ) {
    this.open();
  }

  private open(): void {
    const ws = new WebSocket(this.url);
    ws.binaryType = 'arraybuffer';
    ws.onopen = () => {
      this.retryMs = 500;
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
    return this.ws !== null && this.ws.readyState === WebSocket.OPEN;
  }

  send(cmd: Command): boolean {
    if (!this.isOpen || this.ws === null) return false;
    this.ws.send(JSON.stringify(cmd));
    return true;
  }

  close(): void {
    this.closedByUs = true;
    this.ws?.close();
  }
}
