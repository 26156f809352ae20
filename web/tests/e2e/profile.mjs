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
// Environment: PENDULAB (default ../.venv/bin/pendulab), CHROMIUM (default /usr/bin/chromium); STATIC=dir
// serves that build of the page instead of the package's (e.g. `git archive` of an older commit's
// python/pendulab/server/static, to compare before and after on the same machine state).
import { spawn } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { chromium } from 'playwright-core';

const seconds = Number(process.argv[2] ?? 4);
const query = process.argv[3] ?? '';
const pendulab = process.env.PENDULAB ?? '../.venv/bin/pendulab';

const port = await new Promise((resolve) => {
  const s = createServer().listen(0, '127.0.0.1', () => {
    const p = s.address().port;
    s.close(() => resolve(p));
  });
});
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

const TICK = 100; // /proc/<pid>/stat counts CPU time in clock ticks (USER_HZ, 100 on Linux)
const readStat = (path) => {
  const stat = readFileSync(path, 'utf8');
  const f = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
  return { ppid: Number(f[1]), cpu: (Number(f[11]) + Number(f[12])) / TICK }; // utime + stime
};
/** CPU seconds by process kind and thread name of the browser launched with `marker` on its command line
 *  (and its descendants) and of the server. */
function cpuByKind(marker, serverPid) {
  const procs = new Map();
  for (const pid of readdirSync('/proc').filter((d) => /^\d+$/.test(d))) {
    try {
      // chromium rewrites its children's command lines into one space-separated string
      const cmd = readFileSync(`/proc/${pid}/cmdline`, 'utf8').split(/[\0 ]/);
      procs.set(Number(pid), { cmd, ppid: readStat(`/proc/${pid}/stat`).ppid });
    } catch {
      /* gone */
    }
  }
  const ours = new Map();
  for (const [pid, p] of procs) if (p.cmd.some((a) => a.includes(marker))) ours.set(pid, p);
  for (let grew = true; grew; ) {
    grew = false;
    for (const [pid, p] of procs) {
      if (!ours.has(pid) && ours.has(p.ppid)) {
        ours.set(pid, p);
        grew = true;
      }
    }
  }
  const out = {};
  const add = (pid, kind) => {
    let tids = [];
    try {
      tids = readdirSync(`/proc/${pid}/task`);
    } catch {
      return;
    }
    for (const tid of tids) {
      try {
        const name = readFileSync(`/proc/${pid}/task/${tid}/comm`, 'utf8').trim().replace(/\d+$/, '');
        const key = `${kind}: ${name}`;
        out[key] = (out[key] ?? 0) + readStat(`/proc/${pid}/task/${tid}/stat`).cpu;
      } catch {
        /* gone */
      }
    }
  };
  for (const [pid, p] of ours) {
    const type = p.cmd.find((a) => a.startsWith('--type='))?.slice(7);
    const sub = p.cmd.find((a) => a.startsWith('--utility-sub-type='))?.slice(19);
    const webui = p.cmd.includes('--top-chrome-webui') ? ' (browser UI)' : '';
    add(pid, `chromium ${type ? (sub ? `${type} (${sub})` : type + webui) : 'browser'}`);
  }
  add(serverPid, 'server');
  return out;
}

const userDataDir = mkdtempSync(join(tmpdir(), 'pendulab-profile-'));
const context = await chromium.launchPersistentContext(userDataDir, {
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  headless: true,
  viewport: { width: 1280, height: 800 },
  args: [
    '--headless',
    '--no-sandbox',
    '--disable-gpu',
    '--disable-quic',
    '--no-first-run',
    '--disable-background-networking',
    '--disable-component-update',
    '--disable-sync',
  ],
});
try {
  const page = context.pages()[0] ?? (await context.newPage());
  if (process.env.EXP) await page.addInitScript((e) => localStorage.setItem('pendulab-exp', e), process.env.EXP);
  await page.goto(`${base}/${query ? '?' + query : ''}`);
  await page.waitForFunction(() => (window.pendulab?.store.frames.length ?? 0) > 5, null, { timeout: 60_000 });
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

  const cdp = await context.newCDPSession(page);
  await cdp.send('Performance.enable');
  const metrics = async () =>
    Object.fromEntries((await cdp.send('Performance.getMetrics')).metrics.map((m) => [m.name, m.value]));
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
