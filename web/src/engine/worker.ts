// The in-page engine's Web Worker (docs/lab.md): one session of the Rust core (wasm.ts), ticked tickHz
// times a second like the server's ticker — the commands received since the last tick, the wall-clock
// time elapsed, a stepping budget of TICK_BUDGET seconds — so drawing never waits for physics. Frames
// are transferred, not copied.
import { Engine } from './wasm';
import type { FromWorker, ToWorker } from './messages';

/** Stepping time per tick [s]: the server's 6 ms (pendulab.server.budget.TICK_BUDGET); this worker has
 *  a thread of its own, but the page draws on a second core of a 2-core machine too. */
const TICK_BUDGET = 0.006;

const scope = self as unknown as {
  onmessage: ((ev: MessageEvent<ToWorker>) => void) | null;
  postMessage(m: FromWorker, transfer?: Transferable[]): void;
};
let engine: Engine | null = null;
let handle = -1;
let queue: string[] = [];
let last = 0;

function deliver(messages: (ArrayBuffer | string)[]): void {
  for (const data of messages) {
    scope.postMessage({ type: 'message', data }, typeof data === 'string' ? [] : [data]);
  }
}

function tick(): void {
  if (engine === null) return;
  const now = performance.now();
  const elapsed = (now - last) / 1000;
  last = now;
  const commands = queue;
  queue = [];
  try {
    deliver(engine.tick(handle, commands, elapsed, TICK_BUDGET));
  } catch (e) {
    scope.postMessage({ type: 'failed', message: e instanceof Error ? e.message : String(e) });
    engine = null;
  }
}

scope.onmessage = (ev) => {
  const m = ev.data;
  if (m.type === 'command') {
    queue.push(m.text);
    return;
  }
  Engine.load(m.wasm)
    .then((e) => {
      const opened = e.open(m.config);
      [engine, handle, last] = [e, opened.handle, performance.now()];
      scope.postMessage({ type: 'open' });
      deliver(opened.messages);
      setInterval(tick, 1000 / m.tickHz);
    })
    .catch((e: unknown) => scope.postMessage({ type: 'failed', message: e instanceof Error ? e.message : String(e) }));
};
