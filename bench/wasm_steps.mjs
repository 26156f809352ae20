// RATTLE steps per second of the lab's WebAssembly engine in node beside the native build of the same
// code (docs/performance.md, "The engine in the page"; `make bench-wasm`). All run run.rs's plain
// trajectory — the ideal pendulum, RATTLE, dt = 1 ms, STEPS steps in one call — in ROUNDS interleaved
// rounds: each round runs every .wasm given (e.g. the SIMD128 build and the baseline build) and the
// native build once, in an order that rotates from round to round. Timed by the CPU time of the thread
// that runs the loop (Linux: /proc/thread-self/schedstat, nanoseconds; elsewhere the wall clock), which
// the other processes of a loaded machine disturb far less than the wall clock. Reported per .wasm: the
// median and range of the per-round ratios wasm/native of steps per CPU second, and, as before, the
// ratio of the best wall-clock rates. Prints the machine's load average beside the numbers.
// Usage: node bench/wasm_steps.mjs NATIVE_EXAMPLE WASM [WASM ...] [--steps N] [--rounds R]
import { readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { availableParallelism, loadavg } from 'node:os';

const args = process.argv.slice(2);
const opt = (name, fallback) => {
  const i = args.indexOf(name);
  if (i < 0) return fallback;
  const v = Number(args[i + 1]);
  args.splice(i, 2);
  if (!Number.isInteger(v) || v < 1) throw new Error(`${name} ${args[i + 1]}: a whole number >= 1 is required`);
  return v;
};
const STEPS = opt('--steps', 2_000_000);
const ROUNDS = opt('--rounds', 9);
const [native, ...wasmPaths] = args;
if (native === undefined || wasmPaths.length === 0) {
  console.error('usage: node bench/wasm_steps.mjs NATIVE_EXAMPLE WASM [WASM ...] [--steps N] [--rounds R]');
  process.exit(2);
}
const spec = JSON.stringify({ model: 'ideal', method: 'rattle', dt: 1e-3, theta: 1.0, phi_dot: 1.5, steps: STEPS, records: 1 });

/** CPU seconds of this thread (null where /proc is not there). */
function cpuNow() {
  try {
    return Number(readFileSync('/proc/thread-self/schedstat', 'utf8').split(' ')[0]) * 1e-9;
  } catch {
    return null;
  }
}

const engines = [];
for (const path of wasmPaths) {
  const { instance } = await WebAssembly.instantiate(readFileSync(path), {
    env: { pl_now: () => performance.now() / 1000 },
  });
  engines.push({ path, w: instance.exports, wall: [], cpu: [] });
}

/** One run of the spec in engine `e`: [wall, cpu] seconds. */
function wasmRun(e) {
  const bytes = new TextEncoder().encode(spec);
  const ptr = e.w.pl_alloc(bytes.length);
  new Uint8Array(e.w.memory.buffer, ptr, bytes.length).set(bytes);
  const [t0, c0] = [performance.now(), cpuNow()];
  const rc = e.w.pl_run(ptr, bytes.length);
  const [t1, c1] = [performance.now(), cpuNow()];
  e.w.pl_free(ptr, bytes.length);
  if (rc !== 0) throw new Error(`pl_run failed in ${e.path}`);
  const wall = (t1 - t0) / 1000;
  return [wall, c0 === null ? wall : c1 - c0];
}
/** One run natively: [wall, cpu] seconds, as the example measures them. */
const nativeRun = () => execFileSync(native, ['--time', spec]).toString().trim().split(/\s+/).map(Number);

const nat = { wall: [], cpu: [] };
const loads = [loadavg()[0]];
for (const e of engines) wasmRun(e); // compile (V8's optimising tier) and warm up
for (let r = 0; r < ROUNDS; r++) {
  const order = [...engines.map((e) => () => { const [w, c] = wasmRun(e); e.wall.push(w); e.cpu.push(c); }),
    () => { const [w, c] = nativeRun(); nat.wall.push(w); nat.cpu.push(c); }];
  for (let k = 0; k < order.length; k++) order[(k + r) % order.length]();
  loads.push(loadavg()[0]);
}

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};
const rate = (s) => (STEPS / s / 1e6).toFixed(2);
console.log(`RATTLE, ideal pendulum, ${STEPS} steps a run, ${ROUNDS} interleaved rounds, node ${process.version}, ${availableParallelism()} cores`);
console.log(`  native: median ${rate(median(nat.cpu))} M steps per CPU second, best wall ${rate(Math.min(...nat.wall))} M steps/s`);
for (const e of engines) {
  const ratios = e.cpu.map((c, r) => nat.cpu[r] / c);
  const best = Math.min(...nat.wall) / Math.min(...e.wall);
  console.log(`  ${e.path}: median ${rate(median(e.cpu))} M steps per CPU second, best wall ${rate(Math.min(...e.wall))} M steps/s`);
  console.log(`    ratio wasm/native (CPU time): median ${median(ratios).toFixed(2)}, range ${Math.min(...ratios).toFixed(2)}–${Math.max(...ratios).toFixed(2)}; best wall / best wall ${best.toFixed(2)}`);
}
console.log(`  load average (1 min) over the rounds: ${Math.min(...loads).toFixed(2)}–${Math.max(...loads).toFixed(2)}`);
