// The messages between the page and the engine's Web Worker (socket.ts ⇄ worker.ts): the compiled .wasm and the
// session's configuration (scenarios as GET /api/scenarios lists them, the one to start with) once,
// then command texts in; frames (ArrayBuffers of float64 records) and notices (JSON texts) out.
export type ToWorker =
  | { type: 'init'; wasm: WebAssembly.Module; config: string; tickHz: number }
  | { type: 'command'; text: string };

export type FromWorker =
  | { type: 'open' }
  | { type: 'failed'; message: string }
  | { type: 'message'; data: ArrayBuffer | string };
