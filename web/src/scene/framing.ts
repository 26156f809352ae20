// Framing the scene for the canvas it has (docs/web.md, "Layout"): the camera distance at which a sphere
// fills the narrower side of the view, the sphere of reach as lines (the anaglyph's and a software
// renderer's cheap stand-in for its translucent fill), and where a sphere's outline lands on the page (for the layout's tests). Pure where it
// can be: framingDistance is unit-tested.
import * as THREE from 'three';

/** The camera's distance [m] at which a sphere of radius r [m] fills a view of vertical field of view
 *  `fovDeg` [°] and aspect `aspect` (width/height) up to `fill` of its narrower side. */
export function framingDistance(r: number, fovDeg: number, aspect: number, fill = 0.9): number {
  const halfV = (fovDeg * Math.PI) / 360;
  const halfH = Math.atan(Math.tan(halfV) * Math.max(aspect, 1e-3));
  const half = Math.min(halfV, halfH);
  return r / Math.sin(half * fill);
}

/** The unit sphere as lines: 6 meridians and the parallels at z = ±0.25, ±0.5, ±0.75 (the equator is drawn
 *  on its own). Drawn instead of the translucent fill in the anaglyph, which renders the scene twice, and
 *  always with a software renderer (quality.ts): the fill's blending over a fifth of the canvas is what a
 *  software renderer pays most for (30 fps with it, 60 without; docs/performance.md). */
export function reachLines(color: number, opacity: number): THREE.LineSegments {
  const grid: THREE.Vector3[] = [];
  const N = 96;
  const arc = (f: (a: number) => THREE.Vector3) => {
    for (let i = 0; i < N; i++) grid.push(f((2 * Math.PI * i) / N), f((2 * Math.PI * (i + 1)) / N));
  };
  for (let m = 0; m < 6; m++) {
    const phi = (m * Math.PI) / 6;
    arc((a) => new THREE.Vector3(Math.sin(a) * Math.cos(phi), Math.sin(a) * Math.sin(phi), Math.cos(a)));
  }
  for (const z of [-0.75, -0.5, -0.25, 0.25, 0.5, 0.75]) {
    const rho = Math.sqrt(1 - z * z);
    arc((a) => new THREE.Vector3(rho * Math.cos(a), rho * Math.sin(a), z));
  }
  const lines = new THREE.LineSegments(
    new THREE.BufferGeometry().setFromPoints(grid),
    new THREE.LineBasicMaterial({ color, transparent: true, opacity }),
  );
  lines.visible = false;
  return lines;
}

/** The box [CSS px] on the page of the outline of the sphere (centre, radius r [m]) seen by `camera`
 *  drawn into `canvas`: its silhouette circle, radius r√(1 − r²/d²), centred r²/d towards the camera. */
export function sphereBox(
  centre: THREE.Vector3,
  r: number,
  camera: THREE.Camera,
  canvas: HTMLCanvasElement,
): { left: number; right: number; top: number; bottom: number } {
  const toCam = camera.position.clone().sub(centre).normalize();
  const u = new THREE.Vector3().crossVectors(toCam, new THREE.Vector3(0, 0, 1));
  if (u.lengthSq() < 1e-12) u.set(1, 0, 0);
  u.normalize();
  const w = new THREE.Vector3().crossVectors(toCam, u).normalize();
  const dist = camera.position.distanceTo(centre);
  const rs = r * Math.sqrt(Math.max(0, 1 - (r * r) / (dist * dist)));
  const c = centre.clone().addScaledVector(toCam, (r * r) / dist);
  const rect = canvas.getBoundingClientRect();
  const box = { left: Infinity, right: -Infinity, top: Infinity, bottom: -Infinity };
  for (let i = 0; i < 64; i++) {
    const a = (2 * Math.PI * i) / 64;
    const p = c.clone().addScaledVector(u, rs * Math.cos(a)).addScaledVector(w, rs * Math.sin(a)).project(camera);
    const x = rect.left + ((p.x + 1) / 2) * rect.width;
    const y = rect.top + ((1 - p.y) / 2) * rect.height;
    box.left = Math.min(box.left, x);
    box.right = Math.max(box.right, x);
    box.top = Math.min(box.top, y);
    box.bottom = Math.max(box.bottom, y);
  }
  return box;
}
