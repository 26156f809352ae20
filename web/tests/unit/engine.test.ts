// The in-page engine's transport without a browser (docs/lab.md): the packed answers of the WebAssembly
// engine unpacked into the WebSocket's messages, and the page's REST requests answered in the page.
import { describe, expect, it } from 'vitest';
import { KIND_FRAMES, KIND_JSON, unpack } from '../../src/engine/wasm';
import { answer, needsServer } from '../../src/engine/api';
import { chooseWasm, hasSimd128 } from '../../src/engine/index';
import { unpackWasm } from '../../src/engine/unpack';
import { deflateSync } from 'fflate';
import { decodeFrames, encodeFrames, parseNotice, RECORD_BYTES } from '../../src/protocol';
import type { Frame } from '../../src/protocol';

function pack(parts: [number, Uint8Array][]): Uint8Array {
  const n = parts.reduce((s, [, b]) => s + 5 + b.length, 0);
  const out = new Uint8Array(n);
  const view = new DataView(out.buffer);
  let i = 0;
  for (const [kind, bytes] of parts) {
    out[i] = kind;
    view.setUint32(i + 1, bytes.length, true);
    out.set(bytes, i + 5);
    i += 5 + bytes.length;
  }
  return out;
}

const frame: Frame = {
  t: 0.25, x: [0.1, 0.2, -0.97], v: [1, 2, 0.6], energy: -9.5, j3: 0.1, tension: 12, power: 0, a: [0, 0, 1],
  pivot: [0, 0, 0], taut: true, errorX: 1e-9,
};

describe('unpack', () => {
  it('gives frames as ArrayBuffers and notices as texts, in order', () => {
    const frames = new Uint8Array(encodeFrames([frame, { ...frame, t: 0.5 }]));
    const status = new TextEncoder().encode('{"type":"error","message":"m","command":null}');
    const got = unpack(pack([[KIND_JSON, status], [KIND_FRAMES, frames]]));
    expect(got).toHaveLength(2);
    expect(parseNotice(got[0] as string)).toEqual({ type: 'error', message: 'm', command: null });
    const buf = got[1] as ArrayBuffer;
    expect(buf.byteLength).toBe(2 * RECORD_BYTES);
    expect(decodeFrames(buf)[1]).toEqual({ ...frame, t: 0.5 });
  });
  it('gives nothing for an empty answer', () => {
    expect(unpack(new Uint8Array(0))).toEqual([]);
  });
});

describe('answer', () => {
  const lab = { wasm: '', schema: { tick_hz: 60 }, scenarios: [{ name: 'rosette' }], scenario: 'rosette' };
  it('answers the schema and the scenarios from the file', async () => {
    expect(await answer('api/schema', lab)?.json()).toEqual({ tick_hz: 60 });
    expect(await answer('./api/scenarios', lab)?.json()).toEqual([{ name: 'rosette' }]);
  });
  it('says plainly what needs the server', async () => {
    const r = answer('api/fit', lab);
    expect(r?.status).toBe(501);
    expect((await r?.json()).detail).toBe(needsServer('fitting a data file'));
    expect(needsServer('x')).toMatch(/pendulab serve/);
  });
  it('hands the analyses the core answers in the page to the engine, with the request body', async () => {
    const asked: [string, unknown][] = [];
    const engine = { request: (path: string, body: unknown) => (asked.push([path, body]), { status: 200, body: { kind: 'generic' } }) };
    const r = answer('api/exact', lab, engine as never, '{"length": 1}');
    expect(r?.status).toBe(200);
    expect(await r?.json()).toEqual({ kind: 'generic' });
    expect(asked).toEqual([['api/exact', { length: 1 }]]);
    expect(answer('api/effective_potential', lab, engine as never, 'not json')?.status).toBe(422);
    expect(answer('api/scenario.toml', lab, engine as never, '{}')?.status).toBe(501);
  });
  it('leaves other requests to the network', () => {
    expect(answer('https://example.org/api/schema', lab)).toBeNull();
    expect(answer('style.css', lab)).toBeNull();
  });
});

describe('chooseWasm', () => {
  const lab = { wasm: 'BASE', wasmSimd: 'SIMD', schema: {}, scenarios: [], scenario: null };
  it('takes the SIMD128 build where the browser has SIMD128, the baseline build elsewhere', () => {
    expect(chooseWasm(lab, true)).toEqual({ build: 'simd128', base64: 'SIMD' });
    expect(chooseWasm(lab, false)).toEqual({ build: 'baseline', base64: 'BASE' });
    const { wasmSimd: _, ...older } = lab; // a file built before the SIMD128 build
    expect(chooseWasm(older, true)).toEqual({ build: 'baseline', base64: 'BASE' });
  });
  it('detects SIMD128 with a module that is valid exactly when SIMD128 is there (node 20 has it)', () => {
    expect(hasSimd128()).toBe(true);
  });
});

describe('unpackWasm', () => {
  // the smallest SIMD128 module (engine/index.ts's probe), as vite.lab.config.mjs packs a .wasm: raw DEFLATE, base64
  const probe = Uint8Array.of(0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253, 15, 253, 98, 11);
  const base64 = (b: Uint8Array): string => btoa(String.fromCharCode(...b));
  it("gives back the module's bytes, which compile", async () => {
    const bytes = unpackWasm(base64(deflateSync(probe, { level: 9 })));
    expect([...bytes]).toEqual([...probe]);
    expect(await WebAssembly.compile(bytes)).toBeInstanceOf(WebAssembly.Module);
  });
  it('says so when the file carries something else', () => {
    expect(() => unpackWasm(base64(probe))).toThrow(/the lab's engine \(.wasm\) in this file is damaged/);
    expect(() => unpackWasm(base64(deflateSync(Uint8Array.of(1, 2, 3, 4, 5, 6, 7, 8))))).toThrow(/not a WebAssembly module \(8 bytes/);
  });
});
