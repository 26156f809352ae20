// Red–cyan anaglyph by colour masks (docs/web.md, "Stereo"; docs/performance.md, "Lab frame rate"): the left
// eye's view is drawn into the red channel only, the depth buffer cleared, the right eye's into green and
// blue — two ordinary renders into the canvas. three.js's AnaglyphEffect instead renders both eyes into
// two offscreen targets and mixes them in a third, full-screen pass; in software WebGL (SwiftShader) that
// cost 15 fps where the plain view draws 56. The eyes are three.js's StereoCamera (parallel axes, the
// screen plane at camera.focus).
import * as THREE from 'three';

export class MaskAnaglyph {
  private readonly stereo = new THREE.StereoCamera();

  constructor(private readonly renderer: THREE.WebGLRenderer) {
    this.stereo.aspect = 1;
  }

  /** Renders `scene` seen from `camera` with the eyes `eyeSep` apart [m] and the screen plane at `focus`
   *  [m]; `background` is the clear colour. */
  render(scene: THREE.Scene, camera: THREE.PerspectiveCamera, eyeSep: number, focus: number, background: THREE.Color): void {
    const r = this.renderer;
    const gl = r.getContext();
    camera.focus = focus;
    camera.updateMatrixWorld();
    this.stereo.eyeSep = eyeSep;
    this.stereo.update(camera);
    const autoClear = r.autoClear;
    const bg = scene.background;
    r.autoClear = false;
    scene.background = null;
    r.setClearColor(background, 1);
    r.clear();
    try {
      gl.colorMask(true, false, false, true);
      r.render(scene, this.stereo.cameraL);
      r.clearDepth();
      gl.colorMask(false, true, true, true);
      r.render(scene, this.stereo.cameraR);
    } finally {
      gl.colorMask(true, true, true, true);
      scene.background = bg;
      r.autoClear = autoClear;
    }
  }
}
