// End-to-end test of the one-file lab (docs/lab.md, `make test-lab-html`): dist/pendulab-lab.html opened
// from file:// in Debian's headless chromium with every network request refused (counted and aborted;
// DNS mapped to nothing). Checks: the physics runs in the page (window.pendulab.engine() is "wasm"), the
// first frame arrives (time printed), frames move paced by the wall clock, the true error against the exact
// solution travels in them, commands work through the same protocol (the model picker's damped model with
// its damping, a scenario loaded, a refused command explained, and in German and French; a typed value out of
// range named with the lab's range, no number in the box said so), the page's URL reproduces the run in a
// second page, what needs Python says so, the CSV download replayed by the Python package bit for bit
// (tools/replay_lab_csv.py: pl.simulate with the arithmetic its header names; the SIMD128 build, and the
// baseline build in a page told it has no SIMD128), no request left the machine, no console errors.
// Usage: node tests/e2e/lab_file.mjs /abs/path/pendulab-lab.html
import { execFileSync } from 'node:child_process';
import { mkdirSync } from 'node:fs';
import { checker, errorWatcher, labFileUrl, launchChromium, waitFrames, WAIT } from './file_lab.mjs';

const file = labFileUrl(process.argv[2]);
const { context, refused } = await launchChromium('lab', { offline: true });
const { check, finish } = checker('lab file');
const { errors, watch } = errorWatcher();
const status = (page) => page.evaluate(() => window.pendulab.store.status);
const PYTHON = process.env.PYTHON ?? '../.venv/bin/python';

/** Downloads the CSV through the page's button (Share and export → CSV) into test-results/lab-NAME.csv and
 *  replays it with the Python package; checks it is reproduced bit for bit. */
async function replayCSV(page, name) {
  // the export folder is in the advanced view (the simple view, the first visit's, hides it): there and back
  const simple = await page.evaluate(() => document.body.classList.contains('simple'));
  if (simple) await page.locator('[data-action="simple"]').click();
  const button = page.locator('[data-control="csv"] button');
  if (!(await button.isVisible())) await page.locator('.lil-title', { hasText: 'Share and export' }).click();
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: WAIT }), button.click()]);
  if (simple) await page.locator('[data-action="simple"]').click();
  const path = `test-results/lab-${name}.csv`;
  await download.saveAs(path);
  try {
    const said = execFileSync(PYTHON, ['../tools/replay_lab_csv.py', path], { encoding: 'utf8', stdio: 'pipe' }).trim();
    check(/: 0 differ from pl\.simulate\(arithmetic='unfused'\)/.test(said), `the CSV download replayed by the Python package: ${said}`);
  } catch (e) {
    check(false, `the CSV download (${path}) replayed by the Python package: ${e.stdout ?? ''}${e.stderr ?? e.message}`);
  }
}

try {
  mkdirSync('test-results', { recursive: true });
  const page = context.pages()[0] ?? (await context.newPage());
  watch(page);
  const opened = Date.now();
  await page.goto(file, { timeout: WAIT });
  await waitFrames(page, 0, 20);
  const first = (Date.now() - opened) / 1000;
  console.log(`first frame ${first.toFixed(2)} s after opening the file`);
  check(first < 15, `the first frame arrives (${first.toFixed(2)} s; the goal is 1.5 s on an idle machine)`);
  check((await page.evaluate(() => window.pendulab.engine())) === 'wasm', 'window.pendulab.engine() is "wasm"');
  const simd = await page.evaluate(() => document.documentElement.dataset.wasmBuild);
  check(simd === 'simd128', `chromium runs the SIMD128 build (${simd})`);

  // paced by the wall clock: 0.6–1.4 simulated seconds per second over 2 s
  await page.waitForFunction(() => (window.pendulab.store.latest()?.t ?? 0) > 0.5, null, { timeout: WAIT });
  const a = await page.evaluate(() => ({ t: window.pendulab.store.latest().t, w: Date.now(), d: window.pendulab.drawn() }));
  await page.waitForTimeout(2000);
  const b = await page.evaluate(() => ({ t: window.pendulab.store.latest().t, w: Date.now(), d: window.pendulab.drawn() }));
  const rate = (b.t - a.t) / ((b.w - a.w) / 1000);
  check(rate > 0.6 && rate < 1.4, `frames move, paced: ${rate.toFixed(2)} simulated s per s`);
  const fps = (b.d - a.d) / ((b.w - a.w) / 1000);
  console.log(`drawn at ${fps.toFixed(1)} frames/s`);
  check(fps > 10, `the scene is drawn (${fps.toFixed(1)} frames/s)`);
  const s0 = await status(page);
  const err = await page.evaluate(() => window.pendulab.store.latest().errorX);
  check(s0.error_estimate?.how === 'exact' && err > 1e-12 && err < 1e-3, `the true error travels in the frames: ${err} m (${s0.error_estimate?.how})`);
  // the exact solution's quantities, computed by the core in the page (the period timer compares them)
  const exact = await page.evaluate(async (s) => {
    const r = await fetch('api/exact', { method: 'POST', body: JSON.stringify({ ...s.params, ...s.start }) });
    return r.json();
  }, s0);
  check(exact.kind === 'generic' && exact.period_z > 0 && Math.abs(exact.energy - (await page.evaluate(() => window.pendulab.store.trajectory[0].energy))) < 1e-12,
    `the exact solution in the page: ${exact.kind}, T_z = ${exact.period_z} s, W = ${exact.rotation_number}`);
  const views = await page.evaluate(async (s) => {
    const post = async (path) => (await fetch(path, { method: 'POST', body: JSON.stringify({ ...s.params, ...s.start }) })).json();
    const [em, red] = [await post('api/em_map'), await post('api/reduced')];
    return { boundary: em.boundary?.j3.length, orbit: red.orbit?.sigma1.length };
  }, s0);
  check(views.boundary > 100 && views.orbit > 100, `the EM map and the reduced view in the page (${views.boundary} boundary points, ${views.orbit} orbit points)`);
  await page.screenshot({ path: 'test-results/lab-file.png' });
  await replayCSV(page, 'rosette');

  // the same commands as over the WebSocket: the model picker's damped model, then its damping
  await page.evaluate(() => window.pendulab.send({ type: 'set_model', model: 'damped', params: { damping: 0.8 } }));
  await page.waitForFunction(() => window.pendulab.store.status?.model === 'damped', null, { timeout: WAIT });
  const e1 = await page.evaluate(() => window.pendulab.store.latest().energy);
  await page.waitForTimeout(1500);
  const e2 = await page.evaluate(() => window.pendulab.store.latest().energy);
  const s1 = await status(page);
  check(s1.model_params.damping === 0.8 && e2 < e1, `damped (${s1.model_params.damping} 1/s): E ${e1.toFixed(4)} → ${e2.toFixed(4)} J`);
  check(s1.error_estimate?.how === 'richardson', `its error estimated by Richardson (${s1.error_estimate?.how})`);
  await replayCSV(page, 'damped');
  // a refused command is explained on the page
  await page.evaluate(() => window.pendulab.send({ type: 'set_params', length: -1 }));
  const said = await page.waitForFunction(() => {
    const text = document.getElementById('message')?.textContent ?? '';
    return /length = -1/.test(text) ? text : null;
  }, null, { timeout: WAIT, polling: 20 });
  check(true, `a refused command is explained: ${await said.jsonValue()}`);
  // a value typed into the length box is refused in the page naming the lab's range, not the core's wider
  // one that allows it (it said "length = 5000 is not allowed: a number in [1e-6, 1e4] m (0.001 … 1000 m)")
  const box = page.locator('[data-param="length"] input').first();
  await box.fill('5000');
  await box.press('Enter');
  const typed = await (await page.waitForFunction(() => {
    const text = document.getElementById('message')?.textContent ?? '';
    return /length = 5000/.test(text) ? text : null;
  }, null, { timeout: WAIT, polling: 20 })).jsonValue();
  check(/\[0\.001, 1000\] m/.test(typed) && !/1e4/.test(typed), `a typed length out of range names the lab's range: ${typed}`);
  // no number in the box: lil-gui dropped it without a word; now the page says so and the box shows the length
  await box.fill('abc');
  await box.press('Enter');
  const nan = await (await page.waitForFunction(() => {
    const text = document.getElementById('message')?.textContent ?? '';
    return /must be a number/.test(text) ? text : null;
  }, null, { timeout: WAIT, polling: 20 })).jsonValue();
  const shown = await box.inputValue();
  check(nan === 'length must be a number' && Number(shown) === (await status(page)).params.length, `"abc" typed for the length: ${nan}; the box shows ${shown}`);
  // the same for the time scale's box (dt's is lil-gui's too, in the advanced view)
  const tsBox = page.locator('[data-folder="run"] .lil-controller', { hasText: /time scale/i }).locator('input').first();
  await tsBox.fill('');
  await tsBox.press('Enter');
  const tsSaid = await (await page.waitForFunction(() => {
    const text = document.getElementById('message')?.textContent ?? '';
    return /time_scale must be a number/.test(text) ? text : null;
  }, null, { timeout: WAIT, polling: 20 })).jsonValue();
  const tsShown = await tsBox.inputValue();
  check(Number(tsShown) === (await status(page)).time_scale, `an emptied time-scale box: ${tsSaid}; the box shows ${tsShown}`);
  // a scenario of the file's list
  const names = await page.evaluate(async () => (await (await fetch('api/scenarios')).json()).map((s) => s.name));
  const other = names.find((n) => n !== 'rosette' && n !== s1.scenario) ?? names[0];
  await page.evaluate((n) => window.pendulab.send({ type: 'load_scenario', name: n }), other);
  await page.waitForFunction((n) => window.pendulab.store.status?.scenario === n, other, { timeout: WAIT });
  check(true, `scenario ${other} loaded (${names.length} in the file)`);
  // what needs Python says so
  const fit = await page.evaluate(async () => {
    const r = await fetch('api/fit', { method: 'POST', body: '{}' });
    return { status: r.status, detail: (await r.json()).detail };
  });
  check(fit.status === 501 && /pendulab serve/.test(fit.detail), `fitting says it needs the server: ${fit.detail}`);

  // two pendulums: the second is a second session in a second worker, started ε = 0.5° apart
  await page.locator('[data-input="twin-mode"]').selectOption('epsilon');
  await page.locator('[data-input="twin-epsilon"]').fill('0.5');
  await page.locator('[data-action="twin-start"]').click();
  await page.waitForFunction(() => window.pendulab.twin.trajectory.length > 30 && window.pendulab.separation().t.length > 10, null, { timeout: WAIT, polling: 100 });
  const sep = await page.evaluate(() => {
    const s = window.pendulab.separation();
    return { d0: s.d[0], l: window.pendulab.store.status.params.length, twin: window.pendulab.twin.status.scenario };
  });
  const want = 2 * sep.l * Math.sin((0.5 * Math.PI) / 180 / 2);
  check(Math.abs(sep.d0 - want) < 0.02 * want, `two pendulums, two workers: separation ${sep.d0.toExponential(3)} m at the start (2 l sin(ε/2) = ${want.toExponential(3)} m)`);
  await page.locator('[data-input="twin-mode"]').selectOption('off');

  // the share link: the page's URL, opened in a second page from file://, reproduces the run
  await page.evaluate(() => window.pendulab.send({ type: 'set_params', length: 1.7, g: 3.71 }));
  await page.waitForFunction(() => window.pendulab.store.status?.params.length === 1.7, null, { timeout: WAIT });
  await page.waitForFunction(() => /length=1.7|l=1.7/.test(window.location.search), null, { timeout: WAIT });
  const link = page.url();
  const second = await context.newPage();
  watch(second);
  await second.goto(link, { timeout: WAIT });
  await second.waitForFunction(() => window.pendulab?.store.status?.params.length === 1.7, null, { timeout: WAIT });
  const s2 = await status(second);
  check(s2.params.g === 3.71 && s2.scenario === other, `the link reproduces the run: l = ${s2.params.length} m, g = ${s2.params.g} m/s², ${s2.scenario}`);
  await second.close();

  // the engine's refusals carry the server's message keys, so a German or French page says them in its
  // language (python/pendulab/server/messages.json, the tables' server.<key>), the parameter by its name
  // in that language (the tables' parameter words)
  for (const [lang, words] of [['de', /Länge l = 5000: höchstens 1000 erlaubt/], ['fr', /longueur l = 5000 : au plus 1000/]]) {
    const p = await context.newPage();
    watch(p);
    await p.goto(`${file}?lang=${lang}`, { timeout: WAIT });
    await waitFrames(p, 0, 20);
    await p.evaluate(() => window.pendulab.send({ type: 'set_params', length: 5000 }));
    const text = await p.waitForFunction((re) => {
      const t = document.getElementById('message')?.textContent ?? '';
      return new RegExp(re).test(t) ? t : null;
    }, words.source, { timeout: WAIT, polling: 20 });
    check(true, `a refusal in the page's language (${lang}): ${await text.jsonValue()}`);
    await p.close();
  }

  // the baseline build (a browser without SIMD128: WebAssembly.validate refuses the page's probe) computes the same
  const old = await context.newPage();
  watch(old);
  await old.addInitScript(() => {
    WebAssembly.validate = () => false;
  });
  await old.goto(file, { timeout: WAIT });
  await waitFrames(old, 0, 20);
  const build = await old.evaluate(() => document.documentElement.dataset.wasmBuild);
  check(build === 'baseline', `a browser without SIMD128 runs the baseline build (${build})`);
  await old.waitForFunction(() => (window.pendulab.store.latest()?.t ?? 0) > 1, null, { timeout: WAIT });
  await replayCSV(old, 'baseline');
  await old.close();

  check(refused.length === 0, `no network request (${refused.length} refused${refused.length ? ': ' + refused.slice(0, 3).join(', ') : ''})`);
  check(errors.length === 0, `no console errors${errors.length ? ': ' + errors.slice(0, 3).join(' | ') : ''}`);
} catch (e) {
  check(false, `lab file: ${e instanceof Error ? e.message : String(e)}`);
} finally {
  await context.close();
}
finish();
