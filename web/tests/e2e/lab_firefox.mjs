// The one-file lab in Firefox (docs/web.md, "Firefox"; `make test-lab-firefox`, optional, not in CI):
// dist/pendulab-lab.html opened from file:// in Debian's firefox-esr, driven by geckodriver (crates.io:
// `cargo install geckodriver`) over W3C WebDriver — plain HTTP from node, no client library (playwright
// drives only its own patched Firefox build, which cannot be downloaded here). Firefox runs with a
// display, a virtual one (`xvfb-run`, as `make test-lab-firefox` starts it): headless, Firefox 153 ESR
// creates no WebGL context on this machine ("Exhausted GL driver options",
// FEATURE_FAILURE_WEBGL_EXHAUSTED_DRIVERS) and the lab cannot start; under Xvfb it draws with Mesa's
// software GL (llvmpipe). Every request
// other than file:, blob: and data: goes to a proxy that is not there (127.0.0.1:9), so none leaves the
// machine. Checks: the engine is the page's ("wasm", the SIMD128 build or the baseline one), the first
// frame arrives (its time printed), frames move, the true error travels in them, a refused value is
// explained, a share link (the page's URL after set_params) opened in a new page reproduces the run.
// Usage: node tests/e2e/lab_firefox.mjs /abs/path/pendulab-lab.html
// Environment: FIREFOX (default: firefox-esr on PATH), GECKODRIVER (default: geckodriver on PATH).
import { spawn, execFileSync } from 'node:child_process';
import { checker, freePort, labFileUrl, WAIT } from './file_lab.mjs';

const file = labFileUrl(process.argv[2]);
const which = (name) => execFileSync('sh', ['-c', `command -v ${name}`]).toString().trim();
const firefox = process.env.FIREFOX ?? which('firefox-esr');
const geckodriver = process.env.GECKODRIVER ?? which('geckodriver');

const port = await freePort();
const driver = spawn(geckodriver, ['--port', String(port), '--log', 'warn'], { stdio: 'ignore' });
const base = `http://127.0.0.1:${port}`;

/** One WebDriver call: its `value`, or an Error with the driver's message. */
async function wd(method, path, body) {
  const r = await fetch(base + path, { method, headers: { 'content-type': 'application/json' }, body: body === undefined ? undefined : JSON.stringify(body) });
  const out = await r.json();
  if (!r.ok) throw new Error(`${method} ${path}: ${out.value?.error}: ${out.value?.message}`);
  return out.value;
}
for (let i = 0; ; i++) {
  try {
    await fetch(`${base}/status`);
    break;
  } catch {
    if (i > 100) throw new Error(`geckodriver (${geckodriver}) did not answer`);
    await new Promise((r) => setTimeout(r, 100));
  }
}

const { check, finish } = checker('lab file in Firefox');

let session = null;
try {
  const caps = await wd('POST', '/session', {
    capabilities: {
      alwaysMatch: {
        browserName: 'firefox',
        'moz:firefoxOptions': {
          binary: firefox,
          args: ['--width=1280', '--height=800'],
          prefs: {
            // no request leaves the machine: every one goes to a proxy that is not there
            'network.proxy.type': 1,
            'network.proxy.http': '127.0.0.1',
            'network.proxy.http_port': 9,
            'network.proxy.ssl': '127.0.0.1',
            'network.proxy.ssl_port': 9,
            'network.proxy.allow_hijacking_localhost': true,
            'network.dns.disabled': true,
          },
        },
      },
    },
  });
  session = caps.sessionId;
  console.log(`${caps.capabilities.browserName} ${caps.capabilities.browserVersion} on display ${process.env.DISPLAY ?? '(none)'} (geckodriver)`);
  const s = `/session/${session}`;
  /** Runs `fn` (a function's source) in the page with `args` until it returns a value other than null. */
  const until = async (fn, args = [], what = fn) => {
    const t0 = Date.now();
    for (;;) {
      const v = await wd('POST', `${s}/execute/sync`, { script: `return (${fn})(...arguments);`, args });
      if (v !== null && v !== false) return v;
      if (Date.now() - t0 > WAIT) throw new Error(`timed out waiting for ${what}`);
      await new Promise((r) => setTimeout(r, 20));
    }
  };
  const run = (fn, args = []) => wd('POST', `${s}/execute/sync`, { script: `return (${fn})(...arguments);`, args });

  const opened = Date.now();
  await wd('POST', `${s}/url`, { url: file });
  await until('() => (window.pendulab?.store.frames.length ?? 0) > 0 || null', [], 'the first frame');
  const first = (Date.now() - opened) / 1000;
  console.log(`first frame ${first.toFixed(2)} s after opening the file`);
  check(first < 15, `the first frame arrives (${first.toFixed(2)} s)`);
  const engine = await run('() => [window.pendulab.engine(), document.documentElement.dataset.wasmBuild]');
  check(engine[0] === 'wasm', `window.pendulab.engine() is "${engine[0]}" (the ${engine[1]} build)`);

  await until('() => (window.pendulab.store.latest()?.t ?? 0) > 0.5 || null', [], 'half a simulated second');
  const a = await run('() => ({ t: window.pendulab.store.latest().t, w: Date.now(), d: window.pendulab.drawn() })');
  await new Promise((r) => setTimeout(r, 2000));
  const b = await run('() => ({ t: window.pendulab.store.latest().t, w: Date.now(), d: window.pendulab.drawn(), err: window.pendulab.store.latest().errorX, how: window.pendulab.store.status?.error_estimate?.how })');
  const rate = (b.t - a.t) / ((b.w - a.w) / 1000);
  const fps = (b.d - a.d) / ((b.w - a.w) / 1000);
  check(rate > 0.6 && rate < 1.4, `frames move, paced: ${rate.toFixed(2)} simulated s per s; drawn at ${fps.toFixed(1)} frames/s`);
  check(b.how === 'exact' && b.err > 1e-12 && b.err < 1e-3, `the true error travels in the frames: ${b.err} m (${b.how})`);

  await run("() => window.pendulab.send({ type: 'set_params', length: -1 })");
  const said = await until("() => { const t = document.getElementById('message')?.textContent ?? ''; return /length = -1/.test(t) ? t : null; }", [], 'the refusal explained');
  check(true, `a refused value is explained: ${said}`);

  // the share link: the page's URL after set_params, opened anew, reproduces the run
  await run("() => window.pendulab.send({ type: 'set_params', length: 1.7, g: 3.71 })");
  await until("() => /length=1.7|l=1.7/.test(window.location.search) ? window.location.href : null", [], 'the share link');
  const link = await run('() => window.location.href');
  await wd('POST', `${s}/url`, { url: 'about:blank' });
  await wd('POST', `${s}/url`, { url: link });
  const p = await until('() => { const s = window.pendulab?.store.status; return s && s.params.length === 1.7 ? s.params : null; }', [], 'the linked run');
  check(p.g === 3.71, `the share link reproduces the run from file://: l = ${p.length} m, g = ${p.g} m/s² (${link.slice(link.indexOf('?'))})`);
  const errors = await run("() => window.pendulab.store.status?.paused === undefined ? 'no status' : null");
  check(errors === null, 'the linked page has its status');
} catch (e) {
  check(false, `lab file in Firefox: ${e instanceof Error ? e.message : String(e)}`);
} finally {
  if (session !== null) await wd('DELETE', `/session/${session}`).catch(() => {});
  driver.kill();
}
finish();
