// Drawing quality for the WebGL renderer the browser actually has (docs/performance.md, "Lab frame rate").
// A software rasteriser (SwiftShader, as in headless chromium with --disable-gpu or a machine without a
// usable GPU; Mesa's llvmpipe/softpipe; Windows' Basic Render Driver) draws on the CPU, where the cost
// scales with the samples shaded: 4× multisampling (MSAA) made the 3-D view cost ~40 ms of CPU per frame
// instead of ~16 ms on the reference machine, and of those ~16 ms the faint sphere of reach, drawn as two
// translucent layers (its back and front faces) over a fifth of the canvas, took ~4 more than one layer
// does. Even one layer was most of what was left: SwiftShader's raster threads spent ~15 of ~19 ms per
// frame on it (bench/lab_frames.mjs, docs/performance.md, "The one-file lab in the browser"). There the
// scene is drawn without MSAA at one pixel per CSS pixel and the sphere of reach as lines (meridians and
// parallels, as in the anaglyph: framing.ts) instead of its fill; with a GPU it keeps MSAA, up to two
// pixels per CSS pixel and both layers. The decisions are pure functions (unit-tested); `probeRenderer`
// asks the browser.

/** Names of software rasterisers as WebGL reports them (WEBGL_debug_renderer_info, or RENDERER). */
const SOFTWARE = /swiftshader|llvmpipe|softpipe|software|basic render driver|lavapipe/i;

export function isSoftwareRenderer(name: string | null): boolean {
  return name !== null && SOFTWARE.test(name);
}

export interface RenderQuality {
  /** The renderer's name as WebGL reports it (null: unknown, taken as a GPU). */
  renderer: string | null;
  software: boolean;
  /** Multisampled antialiasing of the WebGL canvases (a context attribute: fixed at creation). */
  antialias: boolean;
  /** Canvas pixels per CSS pixel. */
  pixelRatio: number;
  /** Translucent layers of the sphere of reach: 2 (back and front faces), 1 (the front face, with the
   *  opacity of both: `layeredOpacity`; the same colour wherever nothing lies inside the sphere) or 0 (no
   *  fill: the sphere drawn as lines, framing.ts `reachLines`). */
  reachLayers: 0 | 1 | 2;
}

/** The opacity of `layers` layers of opacity `alpha` of one colour, one over the other (blending one colour
 *  is order-independent): 1 − (1 − alpha)^layers. */
export function layeredOpacity(alpha: number, layers: number): number {
  return 1 - (1 - alpha) ** layers;
}

/** The quality for a renderer named `renderer` on a screen of `devicePixelRatio`. */
export function renderQuality(renderer: string | null, devicePixelRatio: number): RenderQuality {
  const software = isSoftwareRenderer(renderer);
  const dpr = Number.isFinite(devicePixelRatio) && devicePixelRatio > 0 ? devicePixelRatio : 1;
  return {
    renderer,
    software,
    antialias: !software,
    pixelRatio: Math.min(dpr, software ? 1 : 2),
    reachLayers: software ? 0 : 2,
  };
}

/** The WebGL renderer's name, from a throw-away context: RENDERER where it names the renderer (Firefox,
 *  which warns that WEBGL_debug_renderer_info is deprecated), else the unmasked name (Chromium, Safari:
 *  RENDERER says "WebKit WebGL"); null when WebGL is missing or says nothing. */
export function probeRenderer(): string | null {
  const canvas = document.createElement('canvas');
  const gl = canvas.getContext('webgl2') ?? canvas.getContext('webgl');
  if (gl === null) return null;
  let name: unknown = gl.getParameter(gl.RENDERER);
  if (typeof name !== 'string' || name === '' || /^webkit webgl$/i.test(name)) {
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    if (info !== null) name = gl.getParameter(info.UNMASKED_RENDERER_WEBGL);
  }
  gl.getExtension('WEBGL_lose_context')?.loseContext(); // browsers cap the live contexts per page
  return typeof name === 'string' && name !== '' && !/^webkit webgl$/i.test(name) ? name : null;
}
