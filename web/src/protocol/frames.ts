// The state frames of the wire protocol (docs/web.md; protocol.ts re-exports them), with no DOM.
//
// Frames: every binary WebSocket message holds one or more records of little-endian float64 values in the
// order of `frame.json` (shared with the Python server, pendulab/server/frame.json):
//   [t, x1, x2, x3, v1, v2, v3, energy, j3, tension, power, a1, a2, a3, pivot1, pivot2, pivot3, taut, error_x]
//   in s, m, m/s, J, kg m²/s, N, W, m/s², m, 1, m. x, v and a are relative to the pivot (at `pivot`, 0 when
//   fixed); taut is 0 while the string is slack (model `string`), else 1; error_x is the global position
//   error of the record's state (true or estimated, the status's `error_estimate` says how), −1 unknown.
import layout from '../../../python/pendulab/server/frame.json';

export type Vec3 = [number, number, number];

/** Names of the float64 values of one record, in wire order. */
export const FRAME_FIELDS: readonly string[] = layout.fields;
/** SI unit of each field. */
export const FRAME_UNITS: readonly string[] = layout.units;
export const RECORD_LEN = FRAME_FIELDS.length;
export const RECORD_BYTES = 8 * RECORD_LEN;

function fieldIndex(name: string): number {
  const i = FRAME_FIELDS.indexOf(name);
  if (i < 0) throw new Error(`frame.json lacks the field ${name}`);
  return i;
}
const I = {
  t: fieldIndex('t'),
  x: [fieldIndex('x1'), fieldIndex('x2'), fieldIndex('x3')] as const,
  v: [fieldIndex('v1'), fieldIndex('v2'), fieldIndex('v3')] as const,
  energy: fieldIndex('energy'),
  j3: fieldIndex('j3'),
  tension: fieldIndex('tension'),
  power: fieldIndex('power'),
  a: [fieldIndex('a1'), fieldIndex('a2'), fieldIndex('a3')] as const,
  pivot: [fieldIndex('pivot1'), fieldIndex('pivot2'), fieldIndex('pivot3')] as const,
  taut: fieldIndex('taut'),
  errorX: fieldIndex('error_x'),
};

/** One state as computed by the server's core: time t [s], position x [m] and velocity v [m/s] relative to
 *  the pivot, energy E [J], J₃ [kg m²/s], rod tension T [N], power of the non-conservative forces P [W],
 *  acceleration a = ẍ [m/s²] relative to the pivot (m a is the net force on the bob there) and the
 *  pivot's position [m] (0 for a fixed pivot; the bob is at pivot + x), and whether the rod, spring or
 *  string holds the bob (false only while the string is slack: free flight, tension 0), and the global
 *  position error of this state [m] since the stepper's start (the exact one for the ideal pendulum, else
 *  an estimate: Status.error_estimate), or −1 while unknown (the estimate paused: out of work budget). */
export interface Frame {
  t: number;
  x: Vec3;
  v: Vec3;
  energy: number;
  j3: number;
  tension: number;
  power: number;
  a: Vec3;
  pivot: Vec3;
  taut: boolean;
  errorX: number;
}

export class ProtocolError extends Error {}

/** Decodes one binary message into its records. Throws ProtocolError on a length that is not whole records. */
export function decodeFrames(buf: ArrayBuffer): Frame[] {
  if (buf.byteLength === 0 || buf.byteLength % RECORD_BYTES !== 0) {
    throw new ProtocolError(`a frame message has a multiple of ${RECORD_BYTES} bytes, got ${buf.byteLength}`);
  }
  const view = new DataView(buf);
  const n = buf.byteLength / RECORD_BYTES;
  const out: Frame[] = [];
  for (let k = 0; k < n; k++) {
    const base = k * RECORD_BYTES;
    const at = (i: number): number => view.getFloat64(base + 8 * i, true);
    const vec = (i: readonly [number, number, number]): Vec3 => [at(i[0]), at(i[1]), at(i[2])];
    out.push({
      t: at(I.t),
      x: vec(I.x),
      v: vec(I.v),
      energy: at(I.energy),
      j3: at(I.j3),
      tension: at(I.tension),
      power: at(I.power),
      a: vec(I.a),
      pivot: vec(I.pivot),
      taut: at(I.taut) !== 0,
      errorX: at(I.errorX),
    });
  }
  return out;
}

/** The inverse of decodeFrames (used by tests and to replay recordings). */
export function encodeFrames(frames: readonly Frame[]): ArrayBuffer {
  const buf = new ArrayBuffer(frames.length * RECORD_BYTES);
  const view = new DataView(buf);
  frames.forEach((f, k) => {
    const base = k * RECORD_BYTES;
    const put = (i: number, value: number): void => view.setFloat64(base + 8 * i, value, true);
    put(I.t, f.t);
    I.x.forEach((i, c) => put(i, f.x[c] ?? NaN));
    I.v.forEach((i, c) => put(i, f.v[c] ?? NaN));
    put(I.energy, f.energy);
    put(I.j3, f.j3);
    put(I.tension, f.tension);
    put(I.power, f.power);
    I.a.forEach((i, c) => put(i, f.a[c] ?? NaN));
    I.pivot.forEach((i, c) => put(i, f.pivot[c] ?? NaN));
    put(I.taut, f.taut ? 1 : 0);
    put(I.errorX, f.errorX);
  });
  return buf;
}
