// The Rust core's WebAssembly engine (crates/pendulab-wasm) through its plain C ABI: strings are written
// into the module's memory from pl_alloc, every answer is read from pl_out_ptr/pl_out_len; the one import
// is env.pl_now, the clock [s] for the per-tick budget. No DOM: runs in a Web Worker and in node.

export interface EngineExports {
  memory: WebAssembly.Memory;
  pl_alloc(len: number): number;
  pl_free(ptr: number, len: number): void;
  pl_out_ptr(): number;
  pl_out_len(): number;
  pl_session_new(ptr: number, len: number): number;
  pl_session_tick(handle: number, ptr: number, len: number, elapsed: number, budget: number): number;
  pl_session_free(handle: number): void;
  pl_run(ptr: number, len: number): number;
  pl_request(ptr: number, len: number): number;
}

/** A packed answer's kinds (crates/pendulab-wasm/src/engine.rs). */
export const KIND_FRAMES = 0;
export const KIND_JSON = 1;

export class Engine {
  private constructor(private readonly w: EngineExports) {}

  /** An engine from the .wasm's bytes or its compiled module (compiled once, shared with the worker). */
  static async load(source: BufferSource | WebAssembly.Module): Promise<Engine> {
    const imports = { env: { pl_now: () => performance.now() / 1000 } };
    const instance =
      source instanceof WebAssembly.Module
        ? await WebAssembly.instantiate(source, imports)
        : (await WebAssembly.instantiate(source, imports)).instance;
    return new Engine(instance.exports as unknown as EngineExports);
  }

  /** Calls `fn(ptr, len, ...rest)` with `text` in memory; the answer's bytes (a copy) and the code. */
  private call(text: string, fn: (ptr: number, len: number) => number): { code: number; out: Uint8Array } {
    const bytes = new TextEncoder().encode(text);
    const ptr = this.w.pl_alloc(bytes.length);
    new Uint8Array(this.w.memory.buffer, ptr, bytes.length).set(bytes);
    const code = fn(ptr, bytes.length);
    this.w.pl_free(ptr, bytes.length);
    const out = new Uint8Array(this.w.memory.buffer, this.w.pl_out_ptr(), this.w.pl_out_len()).slice();
    if (code < 0) throw new Error(new TextDecoder().decode(out));
    return { code, out };
  }

  /** A new session (its handle) and its first messages. */
  open(config: string): { handle: number; messages: (ArrayBuffer | string)[] } {
    const { code, out } = this.call(config, (p, n) => this.w.pl_session_new(p, n));
    return { handle: code, messages: unpack(out) };
  }

  /** One tick of session `handle`: the command texts since the last, the wall-clock seconds elapsed,
   *  the stepping budget [s]; the messages to deliver. */
  tick(handle: number, commands: string[], elapsed: number, budget: number): (ArrayBuffer | string)[] {
    const text = commands.length > 0 ? JSON.stringify(commands) : '';
    return unpack(this.call(text, (p, n) => this.w.pl_session_tick(handle, p, n, elapsed, budget)).out);
  }

  close(handle: number): void {
    this.w.pl_session_free(handle);
  }

  /** A REST request answered by the core in the page (crates/pendulab-wasm/src/analyses.rs): api/exact,
   *  api/effective_potential, api/em_map, api/reduced; its HTTP status and JSON answer. */
  request(path: string, body: unknown): { status: number; body: unknown } {
    const { code, out } = this.call(JSON.stringify({ path, body }), (p, n) => this.w.pl_request(p, n));
    return { status: code, body: JSON.parse(new TextDecoder().decode(out)) as unknown };
  }

  /** A plain trajectory (crates/pendulab-wasm/src/run.rs): its float64 records. */
  run(spec: object): Float64Array {
    return new Float64Array(this.call(JSON.stringify(spec), (p, n) => this.w.pl_run(p, n)).out.buffer);
  }
}

/** The messages of a packed answer: frames as ArrayBuffers, notices as JSON texts. */
export function unpack(buf: Uint8Array): (ArrayBuffer | string)[] {
  const out: (ArrayBuffer | string)[] = [];
  const view = new DataView(buf.buffer, buf.byteOffset, buf.byteLength);
  let i = 0;
  while (i + 5 <= buf.length) {
    const kind = buf[i];
    const n = view.getUint32(i + 1, true);
    const bytes = buf.slice(i + 5, i + 5 + n);
    out.push(kind === KIND_FRAMES ? bytes.buffer : new TextDecoder().decode(bytes));
    i += 5 + n;
  }
  return out;
}
