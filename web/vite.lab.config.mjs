// The one-file lab (plain JS: the project has no Node types for TypeScript) (docs/lab.md, `make lab-html`): the same page as the server's, with the Rust core as
// WebAssembly inside — the .wasm (base64; the SIMD128 build and the baseline fallback), the schema and the example scenarios as `pendulab serve`
// answers them (tools/lab_snapshot.py) in the define __PENDULAB_LAB__, the engine's Web Worker inlined
// (started from a Blob URL), scripts and styles inlined into index.html by vite-plugin-singlefile. Reads
// PENDULAB_WASM, PENDULAB_WASM_SIMD and PENDULAB_LAB_SNAPSHOT (paths); writes LAB_OUT_DIR (default ../target/lab-html).
import { readFileSync } from 'node:fs';
import { mergeConfig } from 'vite';
import { viteSingleFile } from 'vite-plugin-singlefile';
import base from './vite.config';

function input(name) {
  const path = process.env[name];
  if (path === undefined || path === '') throw new Error(`${name} (a path) is required: run 'make lab-html'`);
  return path;
}

const snapshot = JSON.parse(readFileSync(input('PENDULAB_LAB_SNAPSHOT'), 'utf8'));
const wasm = readFileSync(input('PENDULAB_WASM')).toString('base64');
// the SIMD128 build, which the page prefers where the browser has SIMD128 (web/src/engine/index.ts)
const wasmSimd = readFileSync(input('PENDULAB_WASM_SIMD')).toString('base64');

export default mergeConfig(base, {
  define: { __PENDULAB_LAB__: JSON.stringify({ ...snapshot, wasm, wasmSimd }) },
  plugins: [viteSingleFile({ removeViteModuleLoader: true })],
  build: { outDir: process.env['LAB_OUT_DIR'] ?? '../target/lab-html', emptyOutDir: true },
});
