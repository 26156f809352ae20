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
//   - the machine's 1-minute load average before and after each part (say it next to any number).
// Not a test: it prints. Usage: node bench/lab_frames.mjs [dist/pendulab-lab.html] [--opens 5] [--seconds 10]
// Environment: CHROMIUM (default /usr/bin/chromium). playwright-core is the web/ package's.
import { mkdtempSync } from 'node:fs';
import { createRequire } from 'node:module';
import { loadavg, tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const require = createRequire(new URL('../web/package.json', import.meta.url));
const { chromium } = require('playwright-core');

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
const file = pathToFileURL(resolve(args[0] ?? 'dist/pendulab-lab.html')).href;
const WAIT = 60_000;
const load = () => loadavg()[0].toFixed(2);
const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};

const context = await chromium.launchPersistentContext(mkdtempSync(join(tmpdir(), 'pendulab-frames-')), {
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  headless: true,
  viewport: { width: 1280, height: 800 },
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync',
    '--host-resolver-rules=MAP * ~NOTFOUND'],
});
await context.route('**/*', (route) => (/^(file|blob|data):/.test(route.request().url()) ? route.continue() : route.abort()));
const firstFrame = () =>
  performance.getEntriesByName('pendulab:first frame drawn')[0]?.startTime ?? null;

try {
  console.log(`${file}\nheadless chromium ${context.browser()?.version() ?? ''}, load average ${load()} before`);
  // 1. the first frame, OPENS fresh pages (the first one also compiles what the browser caches)
  const marks = [];
  const seen = [];
  for (let i = 0; i < OPENS; i++) {
    const page = await context.newPage();
    const t0 = Date.now();
    await page.goto(file, { timeout: WAIT });
    await page.waitForFunction(() => (window.pendulab?.store.frames.length ?? 0) > 0, null, { timeout: WAIT, polling: 10 });
    seen.push((Date.now() - t0) / 1000);
    await page.waitForFunction(firstFrame, null, { timeout: WAIT, polling: 10 });
    const build = await page.evaluate(() => document.documentElement.dataset['wasmBuild'] ?? '?');
    marks.push((await page.evaluate(firstFrame)) / 1000);
    console.log(`  open ${i + 1}: first frame drawn ${marks.at(-1).toFixed(3)} s after navigation, in the store ${seen.at(-1).toFixed(3)} s after page.goto (engine build ${build}, load ${load()})`);
    await page.close();
  }
  console.log(`first frame drawn: median ${median(marks).toFixed(3)} s (${Math.min(...marks).toFixed(3)}–${Math.max(...marks).toFixed(3)}); as the test sees it: median ${median(seen).toFixed(3)} s`);

  // 2. the frame rate with the error estimate on
  const page = await context.newPage();
  await page.goto(file, { timeout: WAIT });
  await page.waitForFunction(() => (window.pendulab?.store.frames.length ?? 0) > 5, null, { timeout: WAIT });
  const phases = [['rosette (exact error)', null], ['damped (Richardson companion)', { type: 'set_model', model: 'damped', params: { damping: 0.3 } }]];
  for (const [name, cmd] of phases) {
    if (cmd) {
      await page.evaluate((c) => window.pendulab.send(c), cmd);
      await page.waitForFunction(() => window.pendulab.store.status?.model === 'damped', null, { timeout: WAIT });
    }
    await page.waitForTimeout(1500); // past the start-up work of the phase (plots, the exact solution)
    const before = load();
    const r = await page.evaluate((ms) => new Promise((done) => {
      const ts = [];
      const s = window.pendulab.store;
      const [d0, t0] = [window.pendulab.drawn(), s.latest()?.t ?? 0];
      const f = (now) => {
        ts.push(now);
        if (now - ts[0] < ms) requestAnimationFrame(f);
        else done({ ts, drawn: window.pendulab.drawn() - d0, simulated: (s.latest()?.t ?? 0) - t0, how: s.status?.error_estimate?.how ?? null, err: s.latest()?.errorX ?? null });
      };
      requestAnimationFrame(f);
    }), SECONDS * 1000);
    const dts = r.ts.slice(1).map((t, i) => t - r.ts[i]);
    const wall = (r.ts.at(-1) - r.ts[0]) / 1000;
    const sorted = [...dts].sort((a, b) => a - b);
    const within = dts.filter((d) => d <= 20).length / dts.length;
    console.log(`${name}: error estimate ${r.how} (last ${r.err} m); ${(dts.length / wall).toFixed(1)} frames/s (median interval ${median(dts).toFixed(1)} ms, ` +
      `90th percentile ${sorted[Math.floor(0.9 * sorted.length)].toFixed(1)} ms, ${(100 * within).toFixed(0)} % within 20 ms), ` +
      `scene drawn ${(r.drawn / wall).toFixed(1)}/s, ${(r.simulated / wall).toFixed(2)} simulated s per s, over ${wall.toFixed(1)} s; load ${before} → ${load()}`);
  }
} finally {
  await context.close();
}
