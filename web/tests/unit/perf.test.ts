import { describe, expect, it } from 'vitest';
import { ChangeGate, FrameCosts, RateLimiter } from '../../src/perf';
import { isSoftwareRenderer, layeredOpacity, renderQuality } from '../../src/scene/quality';

describe('render quality', () => {
  const swiftshader =
    'ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)';
  it('recognises software rasterisers by the names WebGL reports', () => {
    for (const name of [
      swiftshader,
      'Google SwiftShader',
      'llvmpipe (LLVM 15.0.6, 256 bits)',
      'Mesa softpipe',
      'ANGLE (Microsoft, Microsoft Basic Render Driver Direct3D11 vs_5_0 ps_5_0)',
      'Apple Software Renderer',
    ]) {
      expect(isSoftwareRenderer(name), name).toBe(true);
    }
    for (const name of ['ANGLE (NVIDIA, NVIDIA GeForce RTX 3060 Direct3D11)', 'Apple M2', 'Mali-G78', 'WebKit WebGL']) {
      expect(isSoftwareRenderer(name), name).toBe(false);
    }
    expect(isSoftwareRenderer(null)).toBe(false);
  });

  it('drops MSAA, draws one pixel per CSS pixel and the sphere as lines (no fill) in software', () => {
    expect(renderQuality(swiftshader, 2)).toEqual({
      renderer: swiftshader,
      software: true,
      antialias: false,
      pixelRatio: 1,
      reachLayers: 0,
    });
    expect(renderQuality(swiftshader, 0.75).pixelRatio).toBe(0.75);
  });

  it('keeps MSAA, up to two pixels per CSS pixel and both layers on a GPU', () => {
    expect(renderQuality('Apple M2', 3)).toEqual({
      renderer: 'Apple M2',
      software: false,
      antialias: true,
      pixelRatio: 2,
      reachLayers: 2,
    });
    expect(renderQuality('Apple M2', 1.5).pixelRatio).toBe(1.5);
  });

  it('takes an unknown renderer as a GPU and a bad device pixel ratio as 1', () => {
    expect(renderQuality(null, Number.NaN)).toMatchObject({ software: false, antialias: true, pixelRatio: 1 });
    expect(renderQuality(null, 0).pixelRatio).toBe(1);
  });

  it('gives one layer the opacity of two: the same colour over the background', () => {
    const bg = 0.1;
    const c = 0.8;
    const a = 0.06;
    const twice = (c - bg) * a + bg; // one layer over the background ...
    const layered = (c - twice) * a + twice; // ... and the second over it
    expect((c - bg) * layeredOpacity(a, 2) + bg).toBeCloseTo(layered, 15);
    expect(layeredOpacity(a, 1)).toBeCloseTo(a, 15);
    expect(layeredOpacity(0.5, 3)).toBe(0.875);
  });
});

describe('rate limiter', () => {
  it('is due at most once per interval, first at once', () => {
    const r = new RateLimiter(100);
    const due = [0, 16.7, 33.3, 99.9, 100, 116.7, 200, 216.7, 300.1].map((t) => r.due(t));
    expect(due).toEqual([true, false, false, false, true, false, true, false, true]);
  });

  it('is due again at once after a reset', () => {
    const r = new RateLimiter(100);
    expect(r.due(50)).toBe(true);
    expect(r.due(60)).toBe(false);
    r.reset();
    expect(r.due(61)).toBe(true);
    expect(r.due(62)).toBe(false);
  });
});

describe('change gate', () => {
  it('says changed on the first call and whenever a value or the length differs (Object.is)', () => {
    const gate = new ChangeGate();
    const f = { t: 1 };
    expect(gate.changed([f, 0, 1, 'off'])).toBe(true);
    expect(gate.changed([f, 0, 1, 'off'])).toBe(false);
    expect(gate.changed([{ t: 1 }, 0, 1, 'off'])).toBe(true); // another object, even if equal
    const g = { t: 1 };
    gate.changed([g, 0, 1, 'off']);
    expect(gate.changed([g, 0, 2, 'off'])).toBe(true);
    expect(gate.changed([g, 0, 2, 'anaglyph'])).toBe(true);
    expect(gate.changed([g, 0, 2])).toBe(true);
    expect(gate.changed([g, 0, 2])).toBe(false);
    expect(gate.changed([g, -0, 2])).toBe(true);
  });

  it('keeps its own copy of the values', () => {
    const gate = new ChangeGate();
    const values = [1, 2];
    gate.changed(values);
    values[1] = 3;
    expect(gate.changed(values)).toBe(true);
  });
});

describe('frame costs', () => {
  it('gives the mean and count per part since the last take, then starts afresh', () => {
    const c = new FrameCosts();
    c.add('render', 2);
    c.add('render', 4);
    c.add('plots', 1);
    expect(c.take()).toEqual({ render: { ms: 3, count: 2 }, plots: { ms: 1, count: 1 } });
    expect(c.take()).toEqual({});
  });
});
