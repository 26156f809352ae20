// Opening the lab in a browser, shared by every script that does it (issue 25): the one-file lab
// (dist/pendulab-lab.html, `make lab-html`; docs/lab.md) from file:// with no network in lab_file.mjs
// (`make test-lab-html`), lab_firefox.mjs (`make test-lab-firefox`), smoke.mjs's file transport
// (`make test-e2e`) and bench/lab_frames.mjs (`make bench-lab-html`); the same headless chromium and its
// CDP metrics for the served lab in smoke.mjs and profile.mjs.
//   - labFileUrl: the file:// URL of the lab file named on the command line (relative to the working
//     directory);
//   - launchChromium: Debian's headless chromium (playwright-core, never a downloaded browser; CHROMIUM,
//     default /usr/bin/chromium) with a fresh profile directory, 1280 × 800 px, no GPU, no background
//     traffic; `offline`: no host name resolves and every request other than file:, blob: and data: is
//     refused and counted, so nothing can leave the machine;
//   - waitFrames: until the page's store holds more than n frames (the lab has started);
//   - cdpMetrics: the renderer's CDP Performance.getMetrics (TaskDuration, ScriptDuration, … in seconds);
//   - errorWatcher: a page's console errors and uncaught exceptions, collected;
//   - freePort: a free TCP port on 127.0.0.1 (for geckodriver);
//   - checker: the tests' `check(ok, what)` lines (ok / FAIL) and their summary and exit code.
import { mkdtempSync } from 'node:fs';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';

/** ms: the longest any page condition is waited for (a loaded 2-core machine). */
export const WAIT = 60_000;

/** The file:// URL of `path` (a file:// URL is kept as it is), else of `fallback`. */
export function labFileUrl(path, fallback = '../dist/pendulab-lab.html') {
  const p = path ?? fallback;
  return p.startsWith('file:') ? p : pathToFileURL(resolve(p)).href;
}

/** Chromium's flags: headless, software rendering, no background traffic. */
export const CHROMIUM_FLAGS = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
];
/** The offline flag: no host name resolves, so nothing could reach a network even past the route. */
export const NO_DNS = '--host-resolver-rules=MAP * ~NOTFOUND';

/**
 * Debian's headless chromium with a fresh profile directory named `pendulab-<prefix>-…` (its path marks
 * the browser's processes in /proc, cpu.mjs). `offline`: the no-DNS flag and every request other than
 * file:, blob: and data: aborted and pushed to `refused` (a test checks it stays empty).
 * @returns {Promise<{ context: import('playwright-core').BrowserContext, userDataDir: string, refused: string[] }>}
 */
export async function launchChromium(prefix, { offline = false } = {}) {
  const userDataDir = mkdtempSync(join(tmpdir(), `pendulab-${prefix}-`));
  const context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    viewport: { width: 1280, height: 800 },
    args: offline ? [...CHROMIUM_FLAGS, NO_DNS] : CHROMIUM_FLAGS,
  });
  const refused = [];
  if (offline) {
    await context.route('**/*', (route) => {
      const url = route.request().url();
      if (/^(file|blob|data):/.test(url)) return route.continue();
      refused.push(url);
      return route.abort();
    });
  }
  return { context, userDataDir, refused };
}

/** Waits until the lab in `page` has more than `n` frames in its store (polling every `polling` ms, or
 *  on every animation frame when not given). */
export const waitFrames = (page, n = 0, polling = undefined) =>
  page.waitForFunction((k) => (window.pendulab?.store.frames.length ?? 0) > k, n, { timeout: WAIT, ...(polling ? { polling } : {}) });

/**
 * The page's renderer metrics over CDP (Performance.enable, then Performance.getMetrics): `metrics()`
 * gives { name: value } (durations in s), `detach()` ends the session.
 */
export async function cdpMetrics(context, page) {
  const cdp = await context.newCDPSession(page);
  await cdp.send('Performance.enable');
  const metrics = async () => Object.fromEntries((await cdp.send('Performance.getMetrics')).metrics.map((m) => [m.name, m.value]));
  return { metrics, detach: () => cdp.detach() };
}

/** `watch(page)` collects the page's console errors and uncaught exceptions in `errors`. */
export function errorWatcher() {
  const errors = [];
  const watch = (page) => {
    page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
    page.on('pageerror', (e) => errors.push(String(e)));
  };
  return { errors, watch };
}

/** A TCP port free on 127.0.0.1 just now. */
export const freePort = () =>
  new Promise((done) => {
    const s = createServer().listen(0, '127.0.0.1', () => {
      const p = s.address().port;
      s.close(() => done(p));
    });
  });

/**
 * A test's checks: `check(ok, what)` prints `ok  what` or `FAIL what` and counts it; `failures` lists
 * the failed ones; `finish()` prints `<name>: n passed, m failed` and exits (1 if any failed).
 */
export function checker(name) {
  const failures = [];
  let checks = 0;
  const check = (ok, what) => {
    checks++;
    console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
    if (!ok) failures.push(what);
  };
  const finish = () => {
    console.log(`${name}: ${checks - failures.length} passed, ${failures.length} failed`);
    process.exit(failures.length > 0 ? 1 : 0);
  };
  return { check, failures, finish, count: () => checks };
}
