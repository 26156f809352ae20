// The in-page engine behind the WebSocket's interface (docs/lab.md): each socket is a Web Worker
// (worker.ts) running one session of the Rust core as WebAssembly. Commands go in as the same JSON texts;
// frames come out as ArrayBuffers of float64 records and notices as JSON texts, exactly as from
// `pendulab serve`, so connection.ts, the store and every panel cannot tell the difference.
import EngineWorker from './worker?worker&inline';
import type { LabBundle, SocketLike } from './index';
import type { FromWorker, ToWorker } from './messages';

export class EngineSocket implements SocketLike {
  binaryType: BinaryType = 'arraybuffer';
  readyState = 0; // CONNECTING, then 1 OPEN, 3 CLOSED (WebSocket's numbers)
  onopen: ((ev: Event) => unknown) | null = null;
  onmessage: ((ev: MessageEvent) => unknown) | null = null;
  onclose: ((ev: CloseEvent) => unknown) | null = null;
  private readonly worker: Worker;

  constructor(wasm: WebAssembly.Module, lab: LabBundle) {
    this.worker = new EngineWorker();
    this.worker.onmessage = (ev: MessageEvent<FromWorker>) => this.receive(ev.data);
    this.worker.onerror = (ev) => {
      console.error(`the in-page engine failed: ${ev.message}`);
      this.closed();
    };
    const schema = lab.schema as { tick_hz?: number };
    const init: ToWorker = {
      type: 'init',
      wasm,
      config: JSON.stringify({ scenarios: lab.scenarios, scenario: lab.scenario }),
      tickHz: schema.tick_hz ?? 60,
    };
    this.worker.postMessage(init);
  }

  private receive(m: FromWorker): void {
    if (m.type === 'open') {
      this.readyState = 1;
      this.onopen?.(new Event('open'));
    } else if (m.type === 'failed') {
      console.error(`the in-page engine could not start: ${m.message}`);
      this.closed();
    } else {
      this.onmessage?.(new MessageEvent('message', { data: m.data }));
    }
  }

  private closed(): void {
    if (this.readyState === 3) return;
    this.readyState = 3;
    this.worker.terminate();
    this.onclose?.(new CloseEvent('close'));
  }

  send(data: string): void {
    const m: ToWorker = { type: 'command', text: data };
    this.worker.postMessage(m);
  }

  close(): void {
    this.closed();
  }
}
