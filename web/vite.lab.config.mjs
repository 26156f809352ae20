// The one-file lab (plain JS: the project has no Node types for TypeScript) (docs/lab.md, `make lab-html`): the same page as the server's, with the Rust core as
// WebAssembly inside — the .wasm (raw DEFLATE at level 9, then base64: src/engine/unpack.ts inflates it; the
// SIMD128 build and the baseline fallback), the schema and the example scenarios as `pendulab serve`
// answers them (tools/lab_snapshot.py) in the define __PENDULAB_LAB__, the engine's Web Worker inlined
// (started from a Blob URL), scripts and styles inlined into index.html by vite-plugin-singlefile. Reads
// PENDULAB_WASM, PENDULAB_WASM_SIMD and PENDULAB_LAB_SNAPSHOT (paths); writes LAB_OUT_DIR (default ../target/lab-html).
import { readFileSync } from 'node:fs';
import { constants, deflateRawSync } from 'node:zlib';
import { mergeConfig } from 'vite';
import { viteSingleFile } from 'vite-plugin-singlefile';
import base from './vite.config';

function input(name) {
  const path = process.env[name];
  if (path === undefined || path === '') throw new Error(`${name} (a path) is required: run 'make lab-html'`);
  return path;
}

/** The .wasm at `path` as the base64 of its raw DEFLATE stream (0.74 MB -> 0.37 MB of base64; 0.99 MB
 *  uncompressed). */
function packed(path) {
  return deflateRawSync(readFileSync(path), { level: constants.Z_BEST_COMPRESSION }).toString('base64');
}

const snapshot = JSON.parse(readFileSync(input('PENDULAB_LAB_SNAPSHOT'), 'utf8'));
const wasm = packed(input('PENDULAB_WASM'));
// the SIMD128 build, which the page prefers where the browser has SIMD128 (web/src/engine/index.ts)
const wasmSimd = packed(input('PENDULAB_WASM_SIMD'));

export default mergeConfig(base, {
  define: { __PENDULAB_LAB__: JSON.stringify({ ...snapshot, wasm, wasmSimd }) },
  plugins: [viteSingleFile({ removeViteModuleLoader: true })],
  build: { outDir: process.env['LAB_OUT_DIR'] ?? '../target/lab-html', emptyOutDir: true },
});
