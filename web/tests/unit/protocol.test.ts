import { describe, expect, it } from 'vitest';
import layout from '../../../python/pendulab/server/frame.json';
import type { Frame } from '../../src/protocol';
import {
  FRAME_FIELDS,
  ProtocolError,
  RECORD_BYTES,
  decodeFrames,
  encodeFrames,
  parseNotice,
} from '../../src/protocol';

const frame = (t: number): Frame => ({
  t,
  x: [0.8660254037844386, 0, -0.5000000000000001],
  v: [0, 1.7320508075688772, 0],
  energy: -3.405,
  j3: 1.5,
  tension: 7.905,
  power: 0,
  a: [-1, 0.5, 2],
  pivot: [0, 0, 0],
  taut: true,
  errorX: 0,
});

describe('frame layout', () => {
  it('is the shared frame.json: t, x, v, energy, j3, tension, power, a, pivot, taut, error_x as 152-byte float64 records', () => {
    expect(FRAME_FIELDS).toEqual(layout.fields);
    expect(FRAME_FIELDS).toEqual([
      't', 'x1', 'x2', 'x3', 'v1', 'v2', 'v3', 'energy', 'j3', 'tension',
      'power', 'a1', 'a2', 'a3', 'pivot1', 'pivot2', 'pivot3', 'taut', 'error_x',
    ]);
    expect(RECORD_BYTES).toBe(152);
    expect(layout.byte_order).toBe('little');
  });

  it('decodes little-endian float64 records written by hand in wire order', () => {
    const first = [0.5, 1, 2, 3, 4, 5, 6, -7.25, 8, 9.5, -0.125, 11, 12, 13, 14, 15, 16, 0, -1];
    const second = [...first.slice(0, -2).map((v) => v + 100), 1, 2.5e-9];
    const values = [...first, ...second];
    const buf = new ArrayBuffer(values.length * 8);
    const view = new DataView(buf);
    values.forEach((v, i) => view.setFloat64(8 * i, v, true));
    const [a, b] = decodeFrames(buf);
    expect(a).toEqual({
      t: 0.5,
      x: [1, 2, 3],
      v: [4, 5, 6],
      energy: -7.25,
      j3: 8,
      tension: 9.5,
      power: -0.125,
      a: [11, 12, 13],
      pivot: [14, 15, 16],
      taut: false,
      errorX: -1,
    });
    expect(b?.t).toBe(100.5);
    expect(b?.errorX).toBe(2.5e-9);
    expect(b?.taut).toBe(true);
    expect(b?.tension).toBe(109.5);
    expect(b?.pivot).toEqual([114, 115, 116]);
  });

  it('round-trips every bit, NaN and -0 included', () => {
    const f = frame(Number.MIN_VALUE);
    f.x = [-0, Number.MAX_VALUE, 0.1 + 0.2];
    f.energy = NaN;
    f.pivot = [5e-324, -1e300, 0.3];
    const [back] = decodeFrames(encodeFrames([f]));
    expect(back?.pivot).toEqual(f.pivot);
    expect(back?.a).toEqual(f.a);
    expect(Object.is(back?.x[0], -0)).toBe(true);
    expect(back?.x[2]).toBe(0.1 + 0.2);
    expect(back?.t).toBe(Number.MIN_VALUE);
    expect(Number.isNaN(back?.energy)).toBe(true);
  });

  it('refuses messages that are not whole records', () => {
    expect(() => decodeFrames(new ArrayBuffer(0))).toThrow(ProtocolError);
    expect(() => decodeFrames(new ArrayBuffer(80))).toThrow(/multiple of 152 bytes, got 80/);
    expect(decodeFrames(new ArrayBuffer(304))).toHaveLength(2);
  });
});

describe('notices', () => {
  it('parses errors and statuses', () => {
    expect(parseNotice('{"type":"error","message":"bad g","command":"set_params"}')).toEqual({
      type: 'error',
      message: 'bad g',
      command: 'set_params',
    });
    const s = parseNotice(
      JSON.stringify({ type: 'status', epoch: 2, method: 'rattle', params: { length: 1, mass: 1, g: 9.81 } }),
    );
    expect(s.type).toBe('status');
  });

  it('refuses junk and a status with another frame layout', () => {
    expect(() => parseNotice('nope')).toThrow(ProtocolError);
    expect(() => parseNotice('[1]')).toThrow(/not a JSON object/);
    expect(() => parseNotice('{"type":"hello"}')).toThrow(/unknown notice type/);
    const other = { type: 'status', epoch: 0, method: 'rk4', params: {}, frame_fields: ['t', 'x'] };
    expect(() => parseNotice(JSON.stringify(other))).toThrow(/frame layout/);
  });
});
