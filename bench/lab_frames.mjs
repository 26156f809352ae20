// The one-file lab's first frame and frame rate (docs/performance.md, "The one-file lab in the browser";
// `make bench-lab-html`): dist/pendulab-lab.html opened from file:// in Debian's headless chromium with the
// end-to-end test's flags (web/tests/e2e/lab_file.mjs), no network. Measures
//   - the first frame: OPENS fresh pages, each from navigation to the first frame drawn (the page's
//     `pendulab:first frame drawn` mark, ms since the navigation began) and as the test sees it (from
//     page.goto to the first frame in the store); the median and range;
//   - the frame rate with the error estimate on, SECONDS each: the rosette (ideal pendulum, RATTLE, its
//     true error against the exact solution in every frame) and the damped model (its error estimated
//     by the Richardson companion, a second run at dt/2): requestAnimationFrame intervals (median, 90th
//     percentile, the share within 20 ms), frames drawn per second, and the frames the engine sent
//     per second;
//   - baselines in the same run, counted the same way, each page alone in the browser: a blank page
//     (before the lab and again after it), three.js drawing only its background on a canvas of the lab's
//     scene size, and a bare three.js scene like the lab's (bob, rod, trail, translucent sphere of reach)
//     on it; the lab's frame rate as a ratio to the blank page's and the bare scene's;
//   - per frame of each phase: the page's main thread busy (CDP Performance.getMetrics: TaskDuration, of
//     it script and style + layout; wall time, so it grows under load), the CPU time of every chromium
//     thread by process (/proc: robust under load; SwiftShader's raster threads are the GPU process's
//     Thread<00>, Thread<01>) and the lab's own parts (window.pendulab.frameCosts());
//   - the machine's 1-minute load average before and after each part (say it next to any number).
// Not a test: it prints. About 1.5 min. Usage: node bench/lab_frames.mjs [dist/pendulab-lab.html] [--opens 5] [--seconds 10]
// Environment: CHROMIUM (default /usr/bin/chromium). playwright-core is the web/ package's; the browser is
// opened as the tests open it (web/tests/e2e/file_lab.mjs), its CPU read as they read it (cpu.mjs).
import { createRequire } from 'node:module';
import { loadavg } from 'node:os';
import { dirname, join } from 'node:path';
import { cpuByThread } from '../web/tests/e2e/cpu.mjs';
import { cdpMetrics, labFileUrl, launchChromium, waitFrames, WAIT } from '../web/tests/e2e/file_lab.mjs';

const require = createRequire(new URL('../web/package.json', import.meta.url));

const args = process.argv.slice(2);
const opt = (name, fallback) => {
  const i = args.indexOf(name);
  if (i < 0) return fallback;
  const v = Number(args[i + 1]);
  args.splice(i, 2);
  if (!(v > 0)) throw new Error(`${name}: a positive number is required`);
  return v;
};
const OPENS = opt('--opens', 5);
const SECONDS = opt('--seconds', 10);
const file = labFileUrl(args[0], 'dist/pendulab-lab.html');
const load = () => loadavg()[0].toFixed(2);
const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};

const { context, userDataDir } = await launchChromium('frames', { offline: true });
// The baselines' pages, served by the page's own route (never the network).
const BENCH = 'http://bench.invalid';
// A bare three.js scene like the lab's (its background, two lights, a bob, a rod, a fading 2000-point
// trail, a translucent sphere of reach drawn by its front face) on a canvas of the lab's scene size, as
// the lab draws in software WebGL (no MSAA, pixel ratio 1), moving every frame.
const threeHtml = ({ w, h }, empty) => `<!doctype html><title>three</title><style>body{margin:0}</style><canvas id="c"></canvas>
<script type="module">
import * as THREE from './three.module.js';
const renderer = new THREE.WebGLRenderer({ canvas: document.getElementById('c'), antialias: false });
renderer.setPixelRatio(1);
renderer.setSize(${w}, ${h});
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x11141b);
const camera = new THREE.PerspectiveCamera(45, ${w} / ${h}, 0.01, 100);
camera.up.set(0, 0, 1);
camera.position.set(2.2, -2.6, 1.4);
camera.lookAt(0, 0, -0.3);
scene.add(new THREE.AmbientLight(0xffffff, 0.6));
const sun = new THREE.DirectionalLight(0xffffff, 1.6);
sun.position.set(2, -3, 4);
scene.add(sun);
if (${empty}) scene.visible = false;
scene.add(new THREE.Mesh(new THREE.SphereGeometry(1, 48, 32),
  new THREE.MeshBasicMaterial({ color: 0x6688aa, transparent: true, opacity: 1 - 0.94 * 0.94, depthWrite: false })));
const bob = new THREE.Mesh(new THREE.SphereGeometry(0.06, 32, 16), new THREE.MeshStandardMaterial({ color: 0xe0a040 }));
scene.add(bob);
const rodPos = new Float32Array(6);
const rod = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0xcccccc }));
rod.geometry.setAttribute('position', new THREE.BufferAttribute(rodPos, 3));
scene.add(rod);
const N = 2000;
const trailPos = new Float32Array(3 * N);
const trailCol = new Float32Array(3 * N);
for (let i = 0; i < N; i++) trailCol.set([i / N, 0.6 * i / N, 0.2], 3 * i);
const trail = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ vertexColors: true }));
trail.geometry.setAttribute('position', new THREE.BufferAttribute(trailPos, 3));
trail.geometry.setAttribute('color', new THREE.BufferAttribute(trailCol, 3));
scene.add(trail);
const at = (t, out, k) => {
  const th = 2.2 + 0.3 * Math.sin(1.3 * t), ph = 2.1 * t;
  out[k] = Math.sin(th) * Math.cos(ph); out[k + 1] = Math.sin(th) * Math.sin(ph); out[k + 2] = Math.cos(th);
};
let drawn = 0;
window.benchDrawn = () => drawn;
const frame = (now) => {
  const t = now / 1000;
  for (let i = 0; i < N; i++) at(t - (N - 1 - i) * 0.002, trailPos, 3 * i);
  trail.geometry.attributes.position.needsUpdate = true;
  at(t, rodPos, 3);
  rod.geometry.attributes.position.needsUpdate = true;
  bob.position.set(rodPos[3], rodPos[4], rodPos[5]);
  renderer.render(scene, camera);
  drawn++;
  requestAnimationFrame(frame);
};
requestAnimationFrame(frame);
</script>`;

// CPU seconds of the browser's threads by process kind (browser, gpu-process, renderer, utility) and thread
// name, from /proc (web/tests/e2e/cpu.mjs): the processes started with this run's profile directory on
// their command line and their descendants.
const cpuByKind = () => cpuByThread(userDataDir, (args) => args.find((a) => a.startsWith('--type='))?.slice(7) ?? 'browser');

const firstFrame = () =>
  performance.getEntriesByName('pendulab:first frame drawn')[0]?.startTime ?? null;

try {
  console.log(`${file}\nheadless chromium ${context.browser()?.version() ?? ''}, load average ${load()} before`);
  // 1. the first frame, OPENS fresh pages (the first one also compiles what the browser caches)
  const marks = [];
  let canvas = { w: 883, h: 778 }; // the lab's scene canvas at 1280 × 800, read in the first open
  const seen = [];
  for (let i = 0; i < OPENS; i++) {
    const page = await context.newPage();
    const t0 = Date.now();
    await page.goto(file, { timeout: WAIT });
    await waitFrames(page, 0, 10);
    seen.push((Date.now() - t0) / 1000);
    await page.waitForFunction(firstFrame, null, { timeout: WAIT, polling: 10 });
    const build = await page.evaluate(() => document.documentElement.dataset['wasmBuild'] ?? '?');
    if (i === 0) canvas = await page.evaluate(() => { const c = document.getElementById('scene-canvas'); return { w: c.width, h: c.height }; });
    marks.push((await page.evaluate(firstFrame)) / 1000);
    console.log(`  open ${i + 1}: first frame drawn ${marks.at(-1).toFixed(3)} s after navigation, in the store ${seen.at(-1).toFixed(3)} s after page.goto (engine build ${build}, load ${load()})`);
    await page.close();
  }
  console.log(`first frame drawn: median ${median(marks).toFixed(3)} s (${Math.min(...marks).toFixed(3)}–${Math.max(...marks).toFixed(3)}); as the test sees it: median ${median(seen).toFixed(3)} s`);

  // 2. the frame rate, each phase alone in the browser (one page open), in this order: the baselines
  // (a blank page; a bare three.js scene on a canvas of the lab's size), the lab (rosette, damped), the
  // blank page again; the lab's rates are also given as a ratio to the blank page's in the same run.
  const rows = [];
  const measureOn = async (page, name, store) => {
    await page.waitForTimeout(1500); // past the start-up work of the phase (plots, the exact solution)
    const before = load();
    const cdp = await cdpMetrics(context, page);
    const metrics = cdp.metrics;
    if (store) await page.evaluate(() => window.pendulab.frameCosts());
    const [m0, c0] = [await metrics(), cpuByKind()];
    const r = await page.evaluate(([ms, lab]) => new Promise((done) => {
      const ts = [];
      const s = lab ? window.pendulab.store : null;
      const [d0, t0] = lab ? [window.pendulab.drawn(), s.latest()?.t ?? 0] : [window.benchDrawn?.() ?? 0, 0];
      const f = (now) => {
        ts.push(now);
        if (now - ts[0] < ms) requestAnimationFrame(f);
        else done(lab
          ? { ts, drawn: window.pendulab.drawn() - d0, simulated: (s.latest()?.t ?? 0) - t0, how: s.status?.error_estimate?.how ?? null, err: s.latest()?.errorX ?? null }
          : { ts, drawn: window.benchDrawn ? window.benchDrawn() - d0 : null });
      };
      requestAnimationFrame(f);
    }), [SECONDS * 1000, store]);
    const [m1, c1] = [await metrics(), cpuByKind()];
    const costs = store ? await page.evaluate(() => window.pendulab.frameCosts()) : null;
    await cdp.detach();
    const dts = r.ts.slice(1).map((t, i) => t - r.ts[i]);
    const wall = (r.ts.at(-1) - r.ts[0]) / 1000;
    const sorted = [...dts].sort((a, b) => a - b);
    const n = dts.length;
    const row = { name, fps: n / wall, median: median(dts), p90: sorted[Math.floor(0.9 * n)], within: dts.filter((d) => d <= 20).length / n,
      late: dts.filter((d) => d > 20).length, n, wall };
    // per frame: the page's main thread busy (CDP TaskDuration) and of it script, style + layout; CPU of
    // every chromium process by kind (/proc: robust under load, unlike the rate)
    const per = (k) => (1000 * (m1[k] - m0[k])) / n;
    row.main = per('TaskDuration');
    row.script = per('ScriptDuration');
    row.layout = per('LayoutDuration') + per('RecalcStyleDuration');
    row.cpu = Object.fromEntries(Object.keys(c1).map((k) => [k, (1000 * (c1[k] - (c0[k] ?? 0))) / n]));
    row.cpuAll = Object.values(row.cpu).reduce((a, b) => a + b, 0);
    row.byKind = {};
    for (const [k, v] of Object.entries(row.cpu)) row.byKind[k.split(':')[0]] = (row.byKind[k.split(':')[0]] ?? 0) + v;
    rows.push(row);
    const extra = store
      ? `error estimate ${r.how} (last ${r.err} m); scene drawn ${(r.drawn / wall).toFixed(1)}/s, ${(r.simulated / wall).toFixed(2)} simulated s per s; `
      : r.drawn !== null ? `scene drawn ${(r.drawn / wall).toFixed(1)}/s; ` : '';
    console.log(`${name}: ${extra}${row.fps.toFixed(1)} frames/s (median interval ${row.median.toFixed(1)} ms, ` +
      `90th percentile ${row.p90.toFixed(1)} ms, ${(100 * row.within).toFixed(1)} % within 20 ms, ${row.late} of ${n} later), over ${wall.toFixed(1)} s; load ${before} → ${load()}`);
    console.log(`    per frame: main thread busy ${row.main.toFixed(2)} ms (script ${row.script.toFixed(2)}, style + layout ${row.layout.toFixed(2)}); ` +
      `CPU ${row.cpuAll.toFixed(1)} ms: ${Object.entries(row.byKind).filter(([, v]) => v > 0.05).map(([k, v]) => `${k} ${v.toFixed(1)}`).join(', ')}`);
    console.log(`    CPU per frame by thread (ms, ≥ 0.2): ${Object.entries(row.cpu).filter(([, v]) => v >= 0.2).sort((a, b) => b[1] - a[1]).map(([k, v]) => `${k} ${v.toFixed(1)}`).join('; ')}`);
    if (costs) console.log(`    the lab's own parts (mean ms per run, runs): ${Object.entries(costs).map(([k, v]) => `${k} ${v.ms.toFixed(2)} (${v.count})`).join('; ')}`);
    return row;
  };
  const baseline = async (name, path) => {
    const page = await context.newPage();
    await page.route(`${BENCH}/**`, (route) => {
      const f = route.request().url().slice(BENCH.length + 1);
      if (f === 'blank.html') return route.fulfill({ contentType: 'text/html', body: '<!doctype html><title>blank</title><body></body>' });
      if (f === 'three.html' || f === 'canvas.html') return route.fulfill({ contentType: 'text/html', body: threeHtml(canvas, f === 'canvas.html') });
      if (/^three\.(module|core)\.js$/.test(f)) return route.fulfill({ contentType: 'text/javascript', path: join(dirname(require.resolve('three')), f) });
      return route.abort();
    });
    await page.goto(`${BENCH}/${path}`, { timeout: WAIT });
    if (path !== 'blank.html') await page.waitForFunction(() => window.benchDrawn?.() > 10, null, { timeout: WAIT });
    const row = await measureOn(page, name, false);
    await page.close();
    return row;
  };
  const blank1 = await baseline('baseline: blank page', 'blank.html');
  const empty = await baseline(`baseline: three.js drawing only its background, ${canvas.w} × ${canvas.h} px`, 'canvas.html');
  const bare = await baseline(`baseline: bare three.js scene, ${canvas.w} × ${canvas.h} px`, 'three.html');
  const page = await context.newPage();
  await page.goto(file, { timeout: WAIT });
  await waitFrames(page, 5);
  const phases = [['rosette (exact error)', null], ['damped (Richardson companion)', { type: 'set_model', model: 'damped', params: { damping: 0.3 } }]];
  const lab = [];
  for (const [name, cmd] of phases) {
    if (cmd) {
      await page.evaluate((c) => window.pendulab.send(c), cmd);
      await page.waitForFunction(() => window.pendulab.store.status?.model === 'damped', null, { timeout: WAIT });
    }
    lab.push(await measureOn(page, name, true));
  }
  await page.close();
  const blank2 = await baseline('baseline: blank page again', 'blank.html');
  const base = (blank1.fps + blank2.fps) / 2;
  console.log(`the lab as a share of the blank page's rate (${base.toFixed(1)} frames/s, mean of both) and of the bare three.js scene's (${bare.fps.toFixed(1)}):`);
  for (const r of lab) console.log(`  ${r.name}: ${(r.fps / base).toFixed(3)} and ${(r.fps / bare.fps).toFixed(3)}; late intervals (> 20 ms) ${(100 * (1 - r.within)).toFixed(1)} % against the blank page's ${(100 * (1 - (blank1.within + blank2.within) / 2)).toFixed(1)} %`);
} finally {
  await context.close();
}
