// Which engine runs the physics (docs/lab.md): the server's (`pendulab serve`, a WebSocket) or the page's
// own — the Rust core as WebAssembly in a Web Worker, in the one-file lab (`make lab-html`), which carries
// the .wasm, the schema and the example scenarios in `__PENDULAB_LAB__` (a Vite define; null in the
// server's bundle, so none of the engine's code is in it). Both speak the same commands and send the
// same frames and notices; connection.ts opens whichever `openSocket` gives.

/** What the one-file lab carries: the engine (each .wasm as the base64 of its raw DEFLATE stream,
 *  unpack.ts: `wasmSimd` built with SIMD128, `wasm` without, the fallback), GET /api/schema's and
 *  /api/scenarios' answers as the server gave them when the file was built, and the scenario to start with. */
export interface LabBundle {
  wasm: string;
  wasmSimd?: string;
  schema: unknown;
  scenarios: unknown[];
  scenario: string | null;
}

declare const __PENDULAB_LAB__: LabBundle | null;

export type EngineKind = 'wasm' | 'server';

/** The WebSocket members connection.ts uses; the in-page engine's socket has them too. */
export interface SocketLike {
  binaryType: BinaryType;
  readonly readyState: number;
  onopen: ((ev: Event) => unknown) | null;
  onmessage: ((ev: MessageEvent) => unknown) | null;
  onclose: ((ev: CloseEvent) => unknown) | null;
  send(data: string): void;
  close(): void;
}

let factory: ((url: string) => SocketLike) | null = null;

/** The bundle of the one-file lab, or null (the server's page). */
export function labBundle(): LabBundle | null {
  return typeof __PENDULAB_LAB__ !== 'undefined' ? __PENDULAB_LAB__ : null;
}

/** "wasm" when the physics runs in this page, "server" when `pendulab serve` computes it. */
export function engineKind(): EngineKind {
  return labBundle() !== null ? 'wasm' : 'server';
}

/** The smallest module with a SIMD128 instruction (a function returning i8x16.popcnt(i8x16.splat(0))):
 *  valid exactly where the browser has SIMD128 (Chrome/Edge 91, Firefox 89, Safari 16.4 and later). */
const SIMD_PROBE = Uint8Array.of(0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253, 15, 253, 98, 11);

/** Whether this browser runs WebAssembly SIMD128. */
export function hasSimd128(): boolean {
  try {
    return WebAssembly.validate(SIMD_PROBE);
  } catch {
    return false;
  }
}

export type WasmBuild = 'simd128' | 'baseline';

/** The build of the engine this browser runs: the SIMD128 one where it can (faster, the same numbers
 *  bit for bit: docs/performance.md), else the baseline one. */
export function chooseWasm(lab: LabBundle, simd: boolean = hasSimd128()): { build: WasmBuild; base64: string } {
  return simd && lab.wasmSimd !== undefined && lab.wasmSimd !== ''
    ? { build: 'simd128', base64: lab.wasmSimd }
    : { build: 'baseline', base64: lab.wasm };
}

/** Prepares the in-page engine when this page carries one (a no-op for the server's page): sockets
 *  become Web Workers running the core, and the page's REST requests are answered in the page. */
export async function installEngine(): Promise<EngineKind> {
  const lab = labBundle();
  if (lab === null) return 'server';
  const { EngineSocket } = await import('./socket');
  const { installApi } = await import('./api');
  const { Engine } = await import('./wasm');
  const { unpackWasm } = await import('./unpack');
  // compiled once: the quick analyses on this thread, each socket's worker instantiates the same module
  const chosen = chooseWasm(lab);
  document.documentElement.dataset['wasmBuild'] = chosen.build;
  const wasm = await WebAssembly.compile(unpackWasm(chosen.base64));
  factory = () => new EngineSocket(wasm, lab);
  installApi(lab, await Engine.load(wasm));

  return 'wasm';
}

/** A socket to the engine: the WebSocket at `url`, or the in-page engine once installed. */
export function openSocket(url: string): SocketLike {
  return factory !== null ? factory(url) : new WebSocket(url);
}
