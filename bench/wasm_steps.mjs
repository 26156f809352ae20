// RATTLE steps per second of the lab's WebAssembly engine in node beside the native build of the same
// code (docs/performance.md, "The engine in the page"; `make bench-wasm`). Both run run.rs's plain
// trajectory — the ideal pendulum, RATTLE, dt = 1 ms, STEPS steps in one call — REPEAT times each,
// alternating, and the best of each counts (the least disturbed by other work on the machine).
// Prints the machine's load average beside the numbers: compare only runs on an idle machine.
// Usage: node bench/wasm_steps.mjs WASM NATIVE_EXAMPLE [STEPS] [REPEAT]
import { readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { availableParallelism, loadavg } from 'node:os';

const [wasmPath, native, stepsArg, repeatArg] = process.argv.slice(2);
const STEPS = Number(stepsArg ?? 2_000_000);
const REPEAT = Number(repeatArg ?? 5);
const { instance } = await WebAssembly.instantiate(readFileSync(wasmPath), {
  env: { pl_now: () => performance.now() / 1000 },
});
const w = instance.exports;
const spec = JSON.stringify({ model: 'ideal', method: 'rattle', dt: 1e-3, theta: 1.0, phi_dot: 1.5, steps: STEPS, records: 1 });

function wasmSeconds() {
  const bytes = new TextEncoder().encode(spec);
  const ptr = w.pl_alloc(bytes.length);
  new Uint8Array(w.memory.buffer, ptr, bytes.length).set(bytes);
  const t0 = performance.now();
  const rc = w.pl_run(ptr, bytes.length);
  const t1 = performance.now();
  w.pl_free(ptr, bytes.length);
  if (rc !== 0) throw new Error('pl_run failed');
  return (t1 - t0) / 1000;
}
const nativeSeconds = () => Number(execFileSync(native, ['--time', spec]).toString().trim());

const load0 = loadavg()[0];
let bestWasm = Infinity;
let bestNative = Infinity;
wasmSeconds(); // compile and warm up
for (let i = 0; i < REPEAT; i++) {
  bestWasm = Math.min(bestWasm, wasmSeconds());
  bestNative = Math.min(bestNative, nativeSeconds());
}
const rw = STEPS / bestWasm;
const rn = STEPS / bestNative;
console.log(`RATTLE, ideal pendulum, ${STEPS} steps, best of ${REPEAT}:`);
console.log(`  wasm in node ${process.version}: ${(rw / 1e6).toFixed(2)} M steps/s`);
console.log(`  native:                  ${(rn / 1e6).toFixed(2)} M steps/s`);
console.log(`  ratio wasm/native: ${(rw / rn).toFixed(2)}   (load average ${load0.toFixed(2)} → ${loadavg()[0].toFixed(2)}, ${availableParallelism()} cores)`);
