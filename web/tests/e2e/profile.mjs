// Where the lab's frame time goes (docs/performance.md, "Lab frame rate"): starts `pendulab serve` on a free
// port, opens the lab in Debian's headless chromium with the end-to-end test's flags (smoke.mjs) and, over a
// few seconds of the rosette running, measures
//   - the frame rate (requestAnimationFrame intervals: median, 90th percentile),
//   - the page's own per-frame costs by part (window.pendulab.frameCosts(): scene update, WebGL submit,
//     panels, frame decoding; main-thread JavaScript only),
//   - the renderer main thread's busy time by kind (CDP Performance.getMetrics: script, layout, style),
//   - the CPU time of every process: the browser, its GPU process (where SwiftShader rasterises WebGL and
//     the compositor draws), the page's renderer, and the server, from /proc (Linux).
// Not a test: it prints. Usage (from web/, after `make build`):
//   node tests/e2e/profile.mjs [seconds=4] [query, e.g. "s=rosette"]     (PAUSE=1: the lab paused)
// The browser is opened as the tests open it (file_lab.mjs), its CPU read as they read it (cpu.mjs).
// Environment: PENDULAB (default ../.venv/bin/pendulab), CHROMIUM (default /usr/bin/chromium); STATIC=dir
// serves that build of the page instead of the package's (e.g. `git archive` of an older commit's
// python/pendulab/server/static, to compare before and after on the same machine state).
import { spawn } from 'node:child_process';
import { rmSync } from 'node:fs';
import { cpuByThread } from './cpu.mjs';
import { cdpMetrics, freePort, launchChromium, waitFrames } from './file_lab.mjs';

const seconds = Number(process.argv[2] ?? 4);
const query = process.argv[3] ?? '';
const pendulab = process.env.PENDULAB ?? '../.venv/bin/pendulab';

const port = await freePort();
// STATIC=dir serves another build of the page (e.g. an older one, to compare) with the same server
const server = process.env.STATIC
  ? spawn(
      process.env.PY ?? '../.venv/bin/python',
      [
        '-c',
        'import sys, uvicorn; from pathlib import Path; from pendulab.server.app import create_app; ' +
          'uvicorn.run(create_app(static_dir=Path(sys.argv[1])), host="127.0.0.1", port=int(sys.argv[2]), log_level="warning")',
        process.env.STATIC,
        String(port),
      ],
      { stdio: 'ignore' },
    )
  : spawn(pendulab, ['serve', '--no-browser', '--host', '127.0.0.1', '--port', String(port)], {
      env: { ...process.env, PENDULAB_NO_BROWSER: '1' },
      stdio: 'ignore',
    });
const base = `http://127.0.0.1:${port}`;
for (let i = 0; ; i++) {
  try {
    if ((await fetch(`${base}/api/schema`)).ok) break;
  } catch {
    /* not up yet */
  }
  if (i > 300) throw new Error('server did not answer');
  await new Promise((r) => setTimeout(r, 300));
}

/** CPU seconds by process kind and thread name of the browser launched with `marker` on its command line
 *  (and its descendants) and of the server (cpu.mjs). */
const cpuByKind = (marker, serverPid) =>
  cpuByThread(
    marker,
    (args) => {
      const type = args.find((a) => a.startsWith('--type='))?.slice(7);
      const sub = args.find((a) => a.startsWith('--utility-sub-type='))?.slice(19);
      const webui = args.includes('--top-chrome-webui') ? ' (browser UI)' : '';
      return `chromium ${type ? (sub ? `${type} (${sub})` : type + webui) : 'browser'}`;
    },
    [[serverPid, 'server']],
  );

const { context, userDataDir } = await launchChromium('profile');
try {
  const page = context.pages()[0] ?? (await context.newPage());
  if (process.env.EXP) await page.addInitScript((e) => localStorage.setItem('pendulab-exp', e), process.env.EXP);
  await page.goto(`${base}/${query ? '?' + query : ''}`);
  await waitFrames(page, 5);
  await page.waitForTimeout(1500); // past the start-up work (first plots, exact solution, V_eff)
  if (process.env.PAUSE) {
    // PAUSE=1: the lab paused (nothing moves: what does an idle page cost?)
    await page.evaluate(() => window.pendulab.send({ type: 'pause' }));
    await page.waitForFunction(() => window.pendulab.store.status?.paused === true);
    await page.waitForTimeout(500);
  }
  const info = await page.evaluate(() => {
    const gl = document.createElement('canvas').getContext('webgl2');
    const ext = gl?.getExtension('WEBGL_debug_renderer_info');
    const c = document.getElementById('scene-canvas');
    return {
      renderer: ext ? gl.getParameter(ext.UNMASKED_RENDERER_WEBGL) : '?',
      canvas: c ? `${c.width}×${c.height}` : '?',
      dpr: window.devicePixelRatio,
      quality: window.pendulab?.quality?.() ?? null,
    };
  });
  console.log(`WebGL: ${info.renderer}; scene canvas ${info.canvas} px; devicePixelRatio ${info.dpr}`);
  if (info.quality) console.log(`quality: ${JSON.stringify(info.quality)}`);

  const { metrics } = await cdpMetrics(context, page);
  await page.evaluate(() => window.pendulab?.frameCosts?.());
  const drawn0 = await page.evaluate(() => window.pendulab?.drawn() ?? 0);
  const m0 = await metrics();
  const c0 = cpuByKind(userDataDir, server.pid);
  const w0 = performance.now();
  const stamps = await page.evaluate(
    (ms) =>
      new Promise((resolve) => {
        const ts = [];
        const f = (now) => {
          ts.push(now);
          if (now - ts[0] < ms) requestAnimationFrame(f);
          else resolve(ts);
        };
        requestAnimationFrame(f);
      }),
    seconds * 1000,
  );
  const wall = (performance.now() - w0) / 1000;
  const c1 = cpuByKind(userDataDir, server.pid);
  const m1 = await metrics();
  const costs = await page.evaluate(() => window.pendulab?.frameCosts?.() ?? null);
  const drawn = (await page.evaluate(() => window.pendulab?.drawn() ?? 0)) - drawn0;

  const dts = stamps
    .slice(1)
    .map((t, i) => t - stamps[i])
    .sort((p, q) => p - q);
  const median = dts[Math.floor(dts.length / 2)];
  const p90 = dts[Math.floor(dts.length * 0.9)];
  console.log(
    `frame rate: median ${(1000 / median).toFixed(1)} fps (${median.toFixed(1)} ms), 90th percentile ` +
      `${p90.toFixed(1)} ms, ${dts.length} frames in ${wall.toFixed(1)} s, the scene rendered in ${drawn}`,
  );
  const n = dts.length;
  if (costs) {
    console.log('page per frame (main-thread JavaScript, mean ms over the frames it ran in):');
    for (const [k, v] of Object.entries(costs)) console.log(`  ${k.padEnd(22)} ${v.ms.toFixed(2)} ms × ${v.count}`);
  }
  console.log(`renderer main thread per frame (CDP Performance.getMetrics, ms over ${n} frames):`);
  for (const k of ['TaskDuration', 'ScriptDuration', 'LayoutDuration', 'RecalcStyleDuration']) {
    console.log(`  ${k.padEnd(22)} ${((1000 * (m1[k] - m0[k])) / n).toFixed(2)} ms`);
  }
  console.log(`CPU per process over ${wall.toFixed(1)} s (cores busy; the machine has 2):`);
  const kinds = [...new Set([...Object.keys(c0), ...Object.keys(c1)])].sort();
  let total = 0;
  for (const k of kinds) {
    const d = (c1[k] ?? 0) - (c0[k] ?? 0);
    total += d;
    if (d / wall >= 0.01) console.log(`  ${k.padEnd(44)} ${(d / wall).toFixed(2)}  (${((1000 * d) / n).toFixed(1)} ms per frame)`);
  }
  console.log(`  ${'total'.padEnd(44)} ${(total / wall).toFixed(2)}`);
} finally {
  await context.close();
  rmSync(userDataDir, { recursive: true, force: true });
  server.kill('SIGTERM');
}
