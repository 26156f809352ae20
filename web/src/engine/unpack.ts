// The one-file lab's .wasm builds are carried compressed (docs/lab.md, "One file"): raw DEFLATE (RFC 1951,
// node:zlib's deflateRawSync at level 9 in web/vite.lab.config.mjs), then base64 — about 0.37 MB each in the
// file instead of 0.99 MB. Inflated by fflate, plain JavaScript, so the baseline build's browsers (those
// without SIMD128: Safari before 16.4) need no DecompressionStream (Safari 16.4, Firefox 113) to read it.
import { inflateSync } from 'fflate';

/** The bytes of base64 `text` (a plain loop: `Uint8Array.from(atob(text), mapFn)` took 100–600 ms for the
 *  0.99 MB of an uncompressed build on the loaded 2-core machine, this loop about 1 ms). */
export function fromBase64(text: string): Uint8Array<ArrayBuffer> {
  const chars = atob(text);
  const out = new Uint8Array(chars.length);
  for (let i = 0; i < chars.length; i++) out[i] = chars.charCodeAt(i);
  return out;
}

/** The .wasm's bytes from the base64 of its raw DEFLATE stream; an error naming what is wrong when it is
 *  not one, or not of a WebAssembly module (the magic `\0asm`). */
export function unpackWasm(base64: string): Uint8Array<ArrayBuffer> {
  let bytes: Uint8Array<ArrayBuffer>;
  try {
    bytes = inflateSync(fromBase64(base64)) as Uint8Array<ArrayBuffer>; // a new array: fflate allocates it
  } catch (e) {
    throw new Error(`the lab's engine (.wasm) in this file is damaged: ${e instanceof Error ? e.message : String(e)}`);
  }
  if (bytes.length < 8 || bytes[0] !== 0 || bytes[1] !== 0x61 || bytes[2] !== 0x73 || bytes[3] !== 0x6d) {
    throw new Error(`the lab's engine in this file is not a WebAssembly module (${bytes.length} bytes inflated)`);
  }
  return bytes;
}
