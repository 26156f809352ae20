// End-to-end test of the running lab in Debian's headless chromium (playwright-core; no browser download),
// once per transport (issue 26 item 7): against `pendulab serve` (the physics on the server, over the
// WebSocket) and against the one-file lab dist/pendulab-lab.html opened from file:// with every network
// request refused (the physics in the page, WebAssembly); the same checks, so every panel and tool is
// tested with both. Run by tests/e2e/run.sh (`make test-e2e`), which starts the server and runs both; by hand:
//   pendulab serve --no-browser --port 8765 &  node tests/e2e/smoke.mjs http://127.0.0.1:8765
//   node tests/e2e/smoke.mjs ../dist/pendulab-lab.html        (after `make lab-html`)
// What needs Python is skipped in the file transport, each with its reason printed (`skip …`): the
// server going away (there is none), fitting a data file and the scenario as a TOML file (the page says
// they need `pendulab serve`: checked instead). Classroom mode (many devices, one server) is not part of
// this suite.
// Checks (more in models.mjs, classroom.mjs and fitdata.mjs): no console errors, frames arrive and are drawn, the data panel shows the
// position error (the true one on the ideal pendulum), the canvas shows the pendulum (pixels differ from
// the background), the frame rate (median of the page's frame times, printed; above 25 fps, see MIN_FPS) and
// the software renderer recognised (no MSAA there), negative g visibly changes the motion (the bob goes
// above the pivot), pause stops the frames, the shared URL reproduces the scenario, a sample of the
// documentation site's "open in the lab" links (tools/lab_links.py) opens in its set-up. Writes
// test-results/lab.png and test-results/lab-negative-g.png (…-file.png for the file transport). Waits are generous (a loaded
// 2-core machine), but every check compares against a bound and can fail.
import { mkdirSync, rmSync } from 'node:fs';
import { errorWatcher, labFileUrl, launchChromium, WAIT } from './file_lab.mjs';
import { checkModels, checkOffSphere, checkViews } from './models.mjs';
import { checkFitData } from './fitdata.mjs';
import { checkFirstFrame } from './startup.mjs';
import { checkWords } from './words.mjs';
import { checkSimpleView } from './simple.mjs';
import { checkFourPendulums } from './four.mjs';
import { checkEnergyAndTwin, checkKeyboard, checkLanguage, dataRows, checkLayout, checkPeriodTimer, checkPlots, checkRecordingAndStereo, checkScenarios, checkShare, checkTouch, checkAxe } from './classroom.mjs';
import { checkDocLinks } from './doclinks.mjs';
import { checkCrane } from './crane.mjs';

const target = process.argv[2] ?? 'http://127.0.0.1:8765';
/** "server" (`pendulab serve` at an http URL) or "file" (the one-file lab from file://, no network). */
const transport = /^https?:/.test(target) ? 'server' : 'file';
const home = transport === 'server' ? target.replace(/\/$/, '') + '/' : labFileUrl(target);
const shot = (name) => `test-results/${name}${transport === 'file' ? '-file' : ''}.png`;
const ONLY = (process.env.E2E_ONLY ?? '').split(',').filter(Boolean);
const MIN_FPS = 25; // see the frame-rate check below
// the file transport: no name resolves and every request that is not the file itself (or a blob:/data:
// URL it makes) is refused and counted; the count must stay 0
const { context, userDataDir, refused } = await launchChromium('e2e', { offline: transport === 'file' });
console.log(`== e2e transport: ${transport} (${home})`);
const failures = [];
let checks = 0;
const check = (ok, what) => {
  checks++;
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures.push(what);
};
const skipped = [];
/** A part that cannot run in this transport, with the reason (printed, and counted in the summary). */
const skip = (what, reason) => {
  skipped.push(what);
  console.log(`skip ${what} (${transport} transport): ${reason}`);
};
const { errors, watch } = errorWatcher();
/** Waits until the current epoch's received trajectory spans `seconds` of simulated time. */
const simulated = (page, seconds) =>
  page.waitForFunction(
    (s) => {
      const tr = window.pendulab?.store.trajectory ?? [];
      return tr.length > 1 && tr[tr.length - 1].t - tr[0].t >= s;
    },
    seconds,
    { timeout: WAIT, polling: 100 },
  );
const maxZ = (page) => page.evaluate(() => Math.max(...window.pendulab.store.trajectory.map((f) => f.x[2])));

try {
  mkdirSync('test-results', { recursive: true });
  const page = context.pages()[0] ?? (await context.newPage());
  watch(page);
  await page.goto(home, { timeout: WAIT });
  await page.waitForFunction(() => (window.pendulab?.store.frames.length ?? 0) > 5, null, { timeout: WAIT });
  // the first visit (a fresh profile) opens the simple view (issue 28: "a simple view with PhET-level tools
  // first"); the advanced layer is one click away and remembered on this device (localStorage), so the
  // checks below, which use the whole panel, run in it (simple.mjs checks the simple view itself)
  const first = await page.evaluate(() => ({ simple: document.body.classList.contains('simple'), stored: localStorage.getItem('pendulab.simple') }));
  await page.locator('[data-action="simple"]').click();
  const advanced = await page
    .waitForFunction(() => !document.body.classList.contains('simple') && localStorage.getItem('pendulab.simple') === '0', null, { timeout: WAIT })
    .then(() => true, () => false);
  check(first.simple && first.stored === null && advanced, `the first visit opens the simple view; one click on Simple opens the advanced one, remembered on the device (${JSON.stringify(first)}, advanced ${advanced})`);

  // E2E_ONLY=period,language (by hand, while working on a part): only the parts whose names contain one of
  // these words, without the checks above them
  if (ONLY.length === 0) {
    // the error estimate in the data panel (issue 17): rosette is the ideal pendulum, so the true error against
    // the exact solution, in m and relative to l, a few seconds into the run well above round-off and far below l
    await page.waitForFunction(() => (window.pendulab.store.latest()?.t ?? 0) > 2, null, { timeout: WAIT });
    await page.waitForTimeout(300); // the panels redraw at 10 Hz
    const rows = await dataRows(page);
    const err = rows.find((r) => r[0] === 'position error |Δx|');
    const rel = rows.find((r) => r[0] === 'position error / l');
    const how = rows.find((r) => r[0] === 'error obtained by');
    const e = Number(err?.[1]);
    check(
      err?.[2] === 'm' && e > 1e-9 && e < 1e-3 && Math.abs(Number(rel?.[1]) - e) <= 0.01 * e && /exact solution/.test(how?.[1] ?? ''),
      `the data panel shows the position error: ${err?.join(' ')}, relative ${rel?.[1]}, by ${how?.[1]}`,
    );

    // pacing: simulated time against the wall clock, measured around the same interval
    const a = await page.evaluate(() => ({ d: window.pendulab.drawn(), t: window.pendulab.store.latest().t, w: Date.now() }));
    await page.waitForTimeout(3000);
    const b = await page.evaluate(() => ({ d: window.pendulab.drawn(), t: window.pendulab.store.latest().t, w: Date.now() }));
    const ratio = (b.t - a.t) / ((b.w - a.w) / 1000);
    check(ratio > 0.6 && ratio < 1.4, `simulation paced to the wall clock (${ratio.toFixed(2)} simulated s per s)`);
    check(b.d - a.d > 10, `the page draws frames (${b.d - a.d} in ${((b.w - a.w) / 1000).toFixed(1)} s)`);

    // frame rate: the page's own frame times (requestAnimationFrame) over 3 s, up to three windows
    const window3s = () =>
      page.evaluate(
        () =>
          new Promise((resolve) => {
            const ts = [];
            const f = (now) => {
              ts.push(now);
              if (now - ts[0] < 3000) requestAnimationFrame(f);
              else resolve(ts);
            };
            requestAnimationFrame(f);
          }),
      );
    const quality = await page.evaluate(() => window.pendulab.quality());
    let fps = 0;
    const windows = [];
    // The bound, MIN_FPS = 25: headless chromium hands out frames on the display's 16.7 ms clock, so the
    // median is 60, 30, 20, 15 … fps. The lab draws at 60 here (trail and plots on), also while other builds
    // load this 2-core machine (load average 6–7.5, or two busy loops, measured); before the software-renderer
    // path (scene/quality.ts: no MSAA, one-layer sphere of reach) it drew at 30 on a quiet machine and 15–20
    // on a busy one. 30 fps (every other frame missed) is let pass, as a machine busy with other work can
    // cause it; 20 or less means a frame costs 40 ms or more again, the old cost: a regression, not noise
    // (docs/performance.md, "Lab frame rate"). Up to three 3-s windows are measured: the other agents' load
    // (load 10-18 on 2 cores) only ever slows a window, and dropped one below 25 fps now and then; a frame
    // that costs 40 ms fails every window.
    for (let i = 0; i < 3 && !(fps > MIN_FPS); i++) {
      const stamps = await window3s();
      const dts = stamps.slice(1).map((t, i) => t - stamps[i]).sort((p, q) => p - q);
      const median = dts[Math.floor(dts.length / 2)];
      const p90 = dts[Math.floor(dts.length * 0.9)];
      fps = 1000 / median;
      windows.push(fps.toFixed(1));
      console.log(
        `frame rate: median ${fps.toFixed(1)} fps (frame time ${median.toFixed(1)} ms, ` +
          `90th percentile ${p90.toFixed(1)} ms, ${dts.length} frames; WebGL ${quality.software ? 'software' : 'GPU'}: ` +
          `${quality.renderer}, antialias ${quality.antialias}, pixel ratio ${quality.pixelRatio})`,
      );
    }
    check(fps > MIN_FPS, `median frame rate above ${MIN_FPS} fps (${windows.join(', ')} fps in ${windows.length} window(s) of 3 s)`);
    const software = /swiftshader|llvmpipe/i.test(quality.renderer ?? '');
    check(quality.software === software && quality.antialias === !software, `software WebGL recognised (${quality.renderer})`);

    const lit = await page.evaluate(async () => {
      const img = new Image();
      img.src = window.pendulab.screenshot();
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.width;
      c.height = img.height;
      const ctx = c.getContext('2d');
      ctx.drawImage(img, 0, 0);
      const px = ctx.getImageData(0, 0, c.width, c.height).data;
      let bob = 0;
      let differ = 0;
      for (let i = 0; i < px.length; i += 4) {
        if (Math.abs(px[i] - 0x11) + Math.abs(px[i + 1] - 0x14) + Math.abs(px[i + 2] - 0x1b) > 30) differ++;
        if (px[i] > 200 && px[i + 1] > 90 && px[i + 1] < 190 && px[i + 2] < 120) bob++; // the orange bob
      }
      return { differ: differ / (px.length / 4), bob };
    });
    check(lit.differ > 0.005, `canvas shows the scene (${(100 * lit.differ).toFixed(2)} % of pixels differ from background)`);
    check(lit.bob > 30, `canvas shows the bob (${lit.bob} orange pixels)`);
    await page.screenshot({ path: shot('lab') });

    // negative g: the bob, which stayed below the pivot, swings up above it
    await simulated(page, 2);
    const zDown = await maxZ(page);
    await page.evaluate(() => window.pendulab.send({ type: 'set_params', g: -9.81 }));
    await page.waitForFunction(() => window.pendulab.store.status?.params.g === -9.81, null, { timeout: WAIT });
    await simulated(page, 2);
    const zUp = await maxZ(page);
    check(zDown < 0 && zUp > 0.5, `negative g: highest z ${zDown.toFixed(3)} m → ${zUp.toFixed(3)} m (above the pivot)`);
    await page.screenshot({ path: shot('lab-negative-g') });

    await page.evaluate(() => window.pendulab.send({ type: 'pause' }));
    await page.waitForFunction(() => window.pendulab.store.status?.paused === true, null, { timeout: WAIT });
    await page.waitForTimeout(300);
    const n0 = await page.evaluate(() => window.pendulab.store.trajectory.length);
    await page.waitForTimeout(1000);
    const n1 = await page.evaluate(() => window.pendulab.store.trajectory.length);
    check(n0 === n1, `pause stops the frames (${n0} → ${n1})`);

    // the URL (kept up to date by the page) reproduces the scenario in a new page
    const url = page.url();
    const want = await page.evaluate(() => {
      const s = window.pendulab.store.status;
      return { params: s.params, method: s.method, dt: s.dt, start: s.start, paused: s.paused };
    });
    const page2 = await context.newPage();
    watch(page2);
    await page2.goto(url, { timeout: WAIT });
    await page2.waitForFunction(
      () => window.pendulab?.store.status?.paused === true && window.pendulab.store.status.params.g === -9.81,
      null,
      { timeout: WAIT },
    );
    const got = await page2.evaluate(() => {
      const s = window.pendulab.store.status;
      return { params: s.params, method: s.method, dt: s.dt, start: s.start, paused: s.paused };
    });
    check(JSON.stringify(got) === JSON.stringify(want), `the shared URL reproduces the scenario (${url.split('?')[1]})`);
    await page2.close();

    await checkModels(page, { check, skip, transport, WAIT, simulated });
    await checkOffSphere(page, { check, WAIT, simulated });
    await checkViews(page, { check, WAIT, simulated });
  }
  if (ONLY.length === 0) {
    const engine = await page.evaluate(() => window.pendulab.engine());
    check(engine === (transport === 'file' ? 'wasm' : 'server'), `window.pendulab.engine() is "${engine}" in the ${transport} transport`);
  }
  const ctx = { check, skip, transport, WAIT, simulated, errors, MIN_FPS, shot, userDataDir };
  for (const [name, part] of [
    ['first frame', checkFirstFrame],
    ['layout', checkLayout],
    ['touch and server gone', checkTouch],
    ['simple view', checkSimpleView],
    ['scenarios', checkScenarios],
    ['plots', checkPlots],
    ['period timer', checkPeriodTimer],
    ['share link', checkShare],
    ['keyboard', checkKeyboard],
    ['energy and two pendulums', checkEnergyAndTwin],
    ['four pendulums', checkFourPendulums],
    ['recording and stereo', checkRecordingAndStereo],
    ['measured data', checkFitData],
    ['language', checkLanguage],
    ['words in every language', checkWords],
    ['axe accessibility', checkAxe],
    ['doc links', checkDocLinks],
    ['crane mode', checkCrane],
  ]) {
    if (ONLY.length > 0 && !ONLY.some((w) => name.includes(w))) continue;
    const t0 = Date.now();
    await part(page, ctx);
    console.log(`   (${name}: ${((Date.now() - t0) / 1000).toFixed(1)} s)`);
  }

  if (transport === 'file') check(refused.length === 0, `no network request (${refused.length} refused${refused.length ? ': ' + refused.slice(0, 3).join(', ') : ''})`);
  check(errors.length === 0, `no console errors${errors.length ? ': ' + errors.join(' | ') : ''}`);
} catch (e) {
  failures.push(String(e));
  console.log(`FAIL ${e instanceof Error ? e.stack : e}`);
} finally {
  await context.close();
  rmSync(userDataDir, { recursive: true, force: true });
}
console.log(`e2e (${transport}): ${checks - failures.length} passed, ${failures.length} failed, ${skipped.length} parts skipped${skipped.length ? ' (' + skipped.join(', ') + ')' : ''}`);
process.exit(failures.length ? 1 : 0);
