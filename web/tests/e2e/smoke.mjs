// Smoke test of the running lab in Debian's headless chromium (playwright-core; no browser download).
// Usage: start `pendulab serve --no-browser --port 8765`, then `node tests/e2e/smoke.mjs http://127.0.0.1:8765`.
// Checks: no console errors, frames arrive and are drawn, the canvas shows the pendulum (pixels differ from
// the background), negative g moves the bob above the pivot, pause stops the frames, the URL reproduces
// the scenario. Writes test-results/lab.png. Not yet part of `make test` (see docs/web.md).
import { mkdirSync } from 'node:fs';
import { chromium } from 'playwright-core';

const base = process.argv[2] ?? 'http://127.0.0.1:8765';
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking'],
});
const failures = [];
const check = (ok, what) => {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures.push(what);
};
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const errors = [];
  page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(base + '/');
  await page.waitForFunction(() => (window.pendulab?.store.frames.length ?? 0) > 5, null, { timeout: 10000 });
  const d0 = await page.evaluate(() => window.pendulab.drawn());
  const t0 = await page.evaluate(() => window.pendulab.store.latest().t);
  await page.waitForTimeout(2000);
  const d1 = await page.evaluate(() => window.pendulab.drawn());
  const t1 = await page.evaluate(() => window.pendulab.store.latest().t);
  console.log(`drawn ${((d1 - d0) / 2).toFixed(1)} frames/s; simulated ${(t1 - t0).toFixed(3)} s in 2 s`);
  check(t1 - t0 > 1.5 && t1 - t0 < 2.5, 'simulation paced to wall clock');
  check(d1 - d0 > 20, 'page draws frames');
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
    let differ = 0;
    for (let i = 0; i < px.length; i += 4) {
      if (Math.abs(px[i] - 0x11) + Math.abs(px[i + 1] - 0x14) + Math.abs(px[i + 2] - 0x1b) > 30) differ++;
    }
    return differ / (px.length / 4);
  });
  check(lit > 0.005, `canvas shows the pendulum (${(100 * lit).toFixed(2)} % of pixels differ from background)`);
  mkdirSync('test-results', { recursive: true });
  await page.screenshot({ path: 'test-results/lab.png' });

  await page.evaluate(() => window.pendulab.send({ type: 'set_params', g: -9.81 }));
  await page.waitForTimeout(2000);
  const z = await page.evaluate(() => Math.max(...window.pendulab.store.trajectory.map((f) => f.x[2])));
  check(z > 0.5, `negative g: the bob swings up above the pivot (highest z = ${z.toFixed(3)} m)`);

  await page.evaluate(() => window.pendulab.send({ type: 'pause' }));
  await page.waitForTimeout(300);
  const n0 = await page.evaluate(() => window.pendulab.store.trajectory.length);
  await page.waitForTimeout(700);
  const n1 = await page.evaluate(() => window.pendulab.store.trajectory.length);
  check(n0 === n1, 'pause stops the frames');

  const url = page.url();
  const page2 = await browser.newPage();
  await page2.goto(url);
  await page2.waitForFunction(() => window.pendulab?.store.status?.paused === true, null, { timeout: 10000 });
  const same = await page2.evaluate(
    (u) => {
      const s = window.pendulab.store.status;
      return s.params.g === -9.81 && window.location.search === new URL(u).search;
    },
    url,
  );
  check(same, 'the shared URL reproduces the scenario');
  check(errors.length === 0, `no console errors${errors.length ? ': ' + errors.join(' | ') : ''}`);
} finally {
  await browser.close();
}
process.exit(failures.length ? 1 : 0);
