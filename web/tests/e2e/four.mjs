// End-to-end check of up to four pendulums (issue 28: "more than two pendulums side by side, each with
// own length, mass, start and pivot, timed separately; PhET's period-vs-length-and-mass experiment doable
// in a minute"), run by smoke.mjs, through the panel as a teacher would: the first pendulum 1 m, 1 kg; the
// second (mode "own") 0.25 m; pendulum 3 the first's length with three times its mass; pendulum 4 0.5 m;
// all released from 10°. Each one's period timer (from its own motion) must give T₃ = T₁ (mass does not
// matter), T₂/T₁ = √(0.25) and T₄/T₁ = √(0.5) (the same amplitude: the ratio is exactly √(l/l₁)) to 2e-5
// (the period timers from the Hermite interpolant: their error 1e-7 is far below; the engine's own 2e-6);
// all four bobs drawn apart inside the view; the whole experiment within 60 s of wall time; the share
// link carries all four.
const TOL = 2e-5;

export async function checkFourPendulums(page, { check, WAIT, shot }) {
  const t0 = Date.now();
  await page.evaluate(() => {
    const send = window.pendulab.send;
    send({ type: 'set_model', model: 'ideal', params: {} });
    send({ type: 'set_params', length: 1, mass: 1, g: 9.81 });
    send({ type: 'set_state', theta: (10 * Math.PI) / 180, phi: 0, theta_dot: 0, phi_dot: 0 });
    send({ type: 'set_time_scale', time_scale: 1 });
  });
  await page.waitForFunction(() => window.pendulab.store.status?.model === 'ideal' && window.pendulab.store.status.params.length === 1, null, { timeout: WAIT });
  await page.locator('[data-input="twin-mode"]').selectOption('own');
  await page.locator('[data-input="twin-length"]').fill('0.25');
  await page.locator('[data-input="twin-mass"]').fill('1');
  await page.locator('[data-input="twin-theta"]').fill('10');
  await page.locator('[data-action="extra-add"]').click();
  await page.locator('[data-action="extra-add"]').click();
  await page.locator('[data-input="extra-length-3"]').fill('1');
  await page.locator('[data-input="extra-mass-3"]').fill('3');
  await page.locator('[data-input="extra-length-4"]').fill('0.5');
  await page.locator('[data-input="extra-theta-3"]').fill('10');
  await page.locator('[data-input="extra-theta-4"]').fill('10');
  await page.locator('[data-action="twin-start"]').click();
  await page.evaluate(() => window.pendulab.send({ type: 'resume' }));
  // every pendulum's own timer has two whole periods
  await page.waitForFunction(
    () => {
      const stores = [window.pendulab.store, window.pendulab.twin, ...window.pendulab.extras()];
      return stores.length === 4 && stores.every((s) => (s.periodTimer.reading().intervals ?? 0) >= 2 && s.periodTimer.reading().period !== null);
    },
    null,
    { timeout: WAIT, polling: 200 },
  );
  const seconds = (Date.now() - t0) / 1000;
  await page.waitForTimeout(300);
  const got = await page.evaluate(() => {
    const stores = [window.pendulab.store, window.pendulab.twin, ...window.pendulab.extras()];
    const c = document.getElementById('scene-canvas').getBoundingClientRect();
    return {
      T: stores.map((s) => s.periodTimer.reading().period),
      l: stores.map((s) => s.status.params.length),
      m: stores.map((s) => s.status.params.mass),
      rows: document.querySelector('[data-readout="twin-periods"]').rows.length,
      bobs: [window.pendulab.bobOnScreen(), window.pendulab.twinOnScreen(), ...window.pendulab.extrasOnScreen()],
      canvas: { left: c.left, right: c.right, top: c.top, bottom: c.bottom },
    };
  });
  await page.screenshot({ path: shot('four-pendulums') });
  const [T1, T2, T3, T4] = got.T;
  check(
    got.l.join() === '1,0.25,1,0.5' && got.m.join() === '1,1,3,1' && got.rows === 5,
    `four pendulums, each its own session: l = ${got.l.join(', ')} m, m = ${got.m.join(', ')} kg; the periods table has a row for each`,
  );
  check(
    Math.abs(T3 / T1 - 1) < TOL && Math.abs(T2 / T1 - 0.5) < TOL && Math.abs(T4 / T1 - Math.SQRT1_2) < TOL,
    `PhET's experiment: T = ${got.T.map((x) => x.toFixed(6)).join(', ')} s; T₃/T₁ = ${(T3 / T1).toFixed(7)} (3× the mass: 1), T₂/T₁ = ${(T2 / T1).toFixed(7)} (√0.25), T₄/T₁ = ${(T4 / T1).toFixed(7)} (√0.5 = 0.7071068)`,
  );
  const inside = got.bobs.every((b) => b && b.x >= got.canvas.left && b.x <= got.canvas.right && b.y >= got.canvas.top && b.y <= got.canvas.bottom);
  let apart = Infinity;
  for (let i = 0; i < got.bobs.length; i++) for (let j = i + 1; j < got.bobs.length; j++) apart = Math.min(apart, Math.hypot(got.bobs[i].x - got.bobs[j].x, got.bobs[i].y - got.bobs[j].y));
  check(got.bobs.length === 4 && inside && apart > 20, `all four bobs drawn in the view, side by side (at least ${apart.toFixed(0)} px apart)`);
  check(seconds < 60, `the experiment took ${seconds.toFixed(1)} s of wall time from the first setting to four periods (a minute allowed)`);
  // the share link carries pendulums 3 and 4: a second page opened with it runs all four again
  await page.waitForFunction(() => /twin=own%3A0\.25%3A1%3A10%2C1%3A3%3A10%2C0\.5%3A1%3A10/.test(location.search), null, { timeout: WAIT });
  const p2 = await page.context().newPage();
  await p2.goto(page.url(), { timeout: WAIT });
  await p2.waitForFunction(() => window.pendulab?.extras().length === 2 && window.pendulab.twin.status?.params.length === 0.25, null, { timeout: WAIT, polling: 200 });
  const again = await p2.evaluate(() => window.pendulab.extras().map((s) => `${s.status.params.length}:${s.status.params.mass}`));
  await p2.close();
  check(again.join() === '1:3,0.5:1', `the link carries all four (twin=own:0.25:1:10,1:3:10,0.5:1:10): a page opened with it runs pendulums 3 and 4 again (${again.join(', ')})`);
  await page.locator('[data-input="twin-mode"]').selectOption('off');
  await page.locator('[data-action="extra-remove-4"]').click();
  await page.locator('[data-action="extra-remove-3"]').click();
  const left = await page.evaluate(() => window.pendulab.extras().length + document.querySelectorAll('[data-extra]').length);
  check(left === 0, 'the extra pendulums go with the second');
}
