// Classroom checks (classroom.mjs; run by smoke.mjs): the energy bars adding up (J), two pendulums, and
// PhET's experiment of a second pendulum of its own length [m], mass [kg] and start, timed by its own
// period timer against the exact period ratio (T-4.6, T-6.2). Waits are generous (a loaded 2-core
// machine), but every check compares against a bound and can fail.

/** The exact period [s] of a planar swing of amplitude a [rad] of the ideal pendulum (T-4.6: 4K(k²)/ω₀,
 *  k = sin(a/2), ω₀ = √(g/l); K by the arithmetic–geometric mean). */
const swingPeriod = (l, g, a) => {
  let [p, q] = [1, Math.sqrt(1 - Math.sin(a / 2) ** 2)];
  for (let i = 0; i < 40 && Math.abs(p - q) > 1e-16 * p; i++) [p, q] = [(p + q) / 2, Math.sqrt(p * q)];
  return (4 * (Math.PI / (2 * p))) / Math.sqrt(g / l);
};

export async function checkEnergyAndTwin(page, { check, WAIT, simulated }) {
  // damped through the friction slider: K + U + lost stays E₀ + m|g|l (the power balance, measured)
  await page.evaluate(() => {
    window.pendulab.send({ type: 'load_scenario', name: 'rosette' });
    window.pendulab.send({ type: 'resume' });
  });
  await page.waitForFunction(() => window.pendulab.store.status?.scenario === 'rosette' && !window.pendulab.store.status.paused, null, { timeout: WAIT });
  await page.locator('[data-input="friction"]').fill('0.4');
  await page.waitForFunction(() => window.pendulab.store.status.model === 'damped' && window.pendulab.store.status.model_params.damping === 0.4, null, { timeout: WAIT });
  await simulated(page, 3);
  await page.waitForTimeout(300);
  const e = await page.evaluate(() => {
    const s = window.pendulab.store.status;
    return { bars: window.pendulab.energy(), e0: window.pendulab.store.reference.energy, mgl: s.params.mass * Math.abs(s.params.g) * s.params.length };
  });
  const want = e.e0 + e.mgl;
  check(e.bars.lost > 0.5 && Math.abs(e.bars.total - want) < 0.01 * want, `energy bars add up: K ${e.bars.kinetic.toFixed(3)} + U ${e.bars.potential.toFixed(3)} + lost ${e.bars.lost.toFixed(3)} = ${e.bars.total.toFixed(4)} J, E₀ + m|g|l = ${want.toFixed(4)} J`);
  await page.screenshot({ path: 'test-results/energy-bars.png' });
  // the ideal pendulum: U = m g (z + l) from the frame, K + U = E + m g l
  await page.evaluate(() => window.pendulab.send({ type: 'load_scenario', name: 'rosette' }));
  await page.waitForFunction(() => window.pendulab.store.status?.model === 'ideal', null, { timeout: WAIT });
  await simulated(page, 1);
  const ideal = await page.evaluate(() => {
    const f = window.pendulab.store.latest();
    const s = window.pendulab.store.status;
    const K = 0.5 * s.params.mass * (f.v[0] ** 2 + f.v[1] ** 2 + f.v[2] ** 2);
    return { K, U: s.params.mass * s.params.g * (f.x[2] + s.params.length), E: f.energy, mgl: s.params.mass * s.params.g * s.params.length };
  });
  check(Math.abs(ideal.K + ideal.U - (ideal.E + ideal.mgl)) < 1e-9 * ideal.mgl, `ideal: kinetic + m g (z + l) = E + m g l (${(ideal.K + ideal.U).toFixed(6)} J)`);

  // two pendulums: the start differs by ε = 0.5°; both drawn, the separation starts at 2 l sin(ε/2)
  await page.locator('[data-input="twin-mode"]').selectOption('epsilon');
  await page.locator('[data-input="twin-epsilon"]').fill('0.5');
  await page.locator('[data-action="twin-start"]').click();
  await page.waitForFunction(() => window.pendulab.twin.trajectory.length > 60 && window.pendulab.separation().t.length > 30, null, { timeout: WAIT, polling: 100 });
  // the second session starts after the first's restart and runs a constant time behind it (0.17 s from
  // file://, its engine starting); the first's playhead waits for it (LabStore.advancePlayhead's holdAt),
  // so the two bobs are drawn at one time. Wait (every animation frame) until the two bobs drawn are
  // states at most 0.04 s apart, then read both as drawn in that frame; checked below
  await page.waitForFunction(() => {
    const a = window.pendulab.store.displayed();
    const b = window.pendulab.twin.displayed();
    return window.pendulab.twinOnScreen() !== null && a !== null && b !== null && Math.abs(a.t - b.t) <= 0.04;
  }, null, { timeout: WAIT, polling: 'raf' }).catch(() => {});
  const two = await page.evaluate(() => {
    const sep = window.pendulab.separation();
    const a = window.pendulab.store.status;
    const b = window.pendulab.twin.status;
    const theta = (x) => Math.atan2(Math.hypot(x[0], x[1]), -x[2]);
    const drawnT = [window.pendulab.store.displayed()?.t, window.pendulab.twin.displayed()?.t];
    return { d0: sep.d[0], t0: sep.t[0], tA: a.t0, n: sep.t.length, dTheta: theta(b.start.x) - theta(a.start.x), twin: window.pendulab.twinOnScreen(), bob: window.pendulab.bobOnScreen(), l: a.params.length, drawnT };
  });
  const expected = 2 * two.l * Math.sin(((0.5 * Math.PI) / 180) / 2);
  check(Math.abs(two.dTheta - (0.5 * Math.PI) / 180) < 1e-9 && two.t0 === two.tA && Math.abs(two.d0 - expected) < 1e-6, `two pendulums: starts ${(two.dTheta * 180 / Math.PI).toFixed(4)}° apart, separation at t0 ${two.d0.toExponential(4)} m (2 l sin(ε/2) = ${expected.toExponential(4)} m), ${two.n} points`);
  check(two.twin !== null && Math.hypot(two.twin.x - two.bob.x, two.twin.y - two.bob.y) < 200, `two pendulums: the second bob is drawn in the same scene (${JSON.stringify(two.twin)} beside ${JSON.stringify(two.bob)}, drawn at t = ${JSON.stringify(two.drawnT)} s)`);
  check(Math.abs(two.drawnT[0] - two.drawnT[1]) <= 0.04, `two pendulums: both drawn at one time (t = ${JSON.stringify(two.drawnT)} s, at most 0.04 s apart)`);
  await page.locator('[data-action="twin-start"]').scrollIntoViewIfNeeded();
  await page.screenshot({ path: 'test-results/two-pendulums.png' });
  // another integrator: the same start, and the two stay within the methods' error of each other
  await page.locator('[data-input="twin-mode"]').selectOption('method');
  await page.locator('[data-input="twin-method"]').selectOption('rk4');
  await page.locator('[data-action="twin-start"]').click();
  await page.waitForFunction(() => window.pendulab.twin.status?.method === 'rk4', null, { timeout: WAIT });
  await page.waitForFunction(() => {
    const s = window.pendulab.separation();
    return s.t.length > 0 && s.t[s.t.length - 1] - s.t[0] > 1;
  }, null, { timeout: WAIT, polling: 200 });
  const methods = await page.evaluate(() => ({ d: window.pendulab.separation().d, a: window.pendulab.store.status.method }));
  check(methods.d[0] < 1e-12 && Math.max(...methods.d) < 1e-3, `another integrator (${methods.a} beside rk4): the same start, at most ${Math.max(...methods.d).toExponential(1)} m apart over 1 s`);
  // ideal beside damped: they drift apart
  await page.locator('[data-input="twin-mode"]').selectOption('damped');
  await page.locator('[data-action="twin-start"]').click();
  await page.waitForFunction(() => window.pendulab.twin.status?.model === 'damped', null, { timeout: WAIT });
  await page.waitForFunction(() => {
    const s = window.pendulab.separation();
    return s.t.length > 0 && s.t[s.t.length - 1] - s.t[0] > 2;
  }, null, { timeout: WAIT, polling: 200 });
  const drift = await page.evaluate(() => {
    const s = window.pendulab.separation();
    return { first: s.d[0], last: s.d[s.d.length - 1] };
  });
  check(drift.first < 1e-9 && drift.last > 0.05, `ideal beside damped: the same start (${drift.first.toExponential(1)} m apart), ${drift.last.toFixed(3)} m apart after 2 s`);
  await checkOwnTwin(page, { check, WAIT });
  await page.locator('[data-input="twin-mode"]').selectOption('off');
  await page.waitForFunction(() => window.pendulab.twinOnScreen() === null, null, { timeout: WAIT });
}

/** PhET's experiment (issue 28): a second pendulum of its own length, mass and start beside the first, each
 *  timed by its own period timer. l₁ = 1 m, m₁ = 1 kg against l₂ = 0.25 m, m₂ = 2 kg, both from 10° at rest:
 *  the same amplitude, so T₁/T₂ = √(l₁/l₂) = 2 whatever the masses (T-6.2: the period is 4K/ω₀). */
async function checkOwnTwin(page, { check, WAIT }) {
  await page.evaluate(() => {
    const s = window.pendulab.send;
    s({ type: 'pause' });
    s({ type: 'set_params', length: 1, mass: 1, g: 9.81 });
    s({ type: 'set_state', theta: (10 * Math.PI) / 180, phi: 0, theta_dot: 0, phi_dot: 0 });
    s({ type: 'set_time_scale', time_scale: 4 });
  });
  await page.waitForFunction(() => window.pendulab.store.status?.params.length === 1 && window.pendulab.store.status.time_scale === 4 && window.pendulab.store.status.paused, null, { timeout: WAIT });
  await page.locator('[data-input="twin-mode"]').selectOption('own');
  await page.locator('[data-input="twin-length"]').fill('0.25');
  await page.locator('[data-input="twin-mass"]').fill('2');
  await page.locator('[data-input="twin-theta"]').fill('10');
  await page.locator('[data-action="twin-start"]').click();
  await page.waitForFunction(() => window.pendulab.twin.status?.params.length === 0.25 && window.pendulab.twin.status.params.mass === 2, null, { timeout: WAIT });
  await page.evaluate(() => window.pendulab.send({ type: 'resume' }));
  await page.waitForFunction(() => window.pendulab.store.periodTimer.reading().intervals >= 2 && window.pendulab.twin.periodTimer.reading().intervals >= 2, null, { timeout: WAIT, polling: 100 });
  await page.waitForTimeout(300);
  await page.waitForFunction(() => window.pendulab.twinOnScreen() !== null && window.pendulab.bobOnScreen() !== null, null, { timeout: WAIT, polling: 100 }).catch(() => {});
  const r = await page.evaluate(() => {
    const c = document.getElementById('scene-canvas').getBoundingClientRect();
    return {
      t1: window.pendulab.store.periodTimer.reading().period,
      t2: window.pendulab.twin.periodTimer.reading().period,
      bob: window.pendulab.bobOnScreen(),
      twin: window.pendulab.twinOnScreen(),
      canvas: { left: c.left, right: c.right, top: c.top, bottom: c.bottom },
      table: document.querySelector('[data-readout="twin-periods"]').textContent,
    };
  });
  const ratio = r.t1 / r.t2;
  check(Math.abs(ratio - 2) < 1e-5 && /0\.250/.test(r.table), `own pendulum beside the first: T₁ = ${r.t1.toFixed(4)} s (1 m, 1 kg), T₂ = ${r.t2.toFixed(4)} s (0.25 m, 2 kg), T₁/T₂ = ${ratio.toFixed(6)} (√(l₁/l₂) = 2)`);
  // each timer against the exact period at time scale 4 (frames 1/15 s apart or more on a loaded machine):
  // to 1e-5, the engine's own accuracy (rattle, dt = 1 ms: (ω₀ dt)²/24 ≈ 2e-6 for 0.25 m)
  const [e1, e2] = [swingPeriod(1, 9.81, (10 * Math.PI) / 180), swingPeriod(0.25, 9.81, (10 * Math.PI) / 180)];
  const [d1, d2] = [Math.abs(r.t1 - e1) / e1, Math.abs(r.t2 - e2) / e2];
  check(d1 < 1e-5 && d2 < 1e-5, `both period timers at time scale 4 against the exact 4K(k²)/ω₀: T₁ ${r.t1.toFixed(6)} s vs ${e1.toFixed(6)} s (${d1.toExponential(1)}), T₂ ${r.t2.toFixed(6)} s vs ${e2.toFixed(6)} s (${d2.toExponential(1)})`);
  const inCanvas = (p) => p !== null && p.x > r.canvas.left && p.x < r.canvas.right && p.y > r.canvas.top && p.y < r.canvas.bottom;
  check(inCanvas(r.bob) && inCanvas(r.twin) && Math.hypot(r.twin.x - r.bob.x, r.twin.y - r.bob.y) > 60, `both bobs in view, side by side (${Math.round(Math.hypot(r.twin.x - r.bob.x, r.twin.y - r.bob.y))} px apart)`);
  await page.screenshot({ path: 'test-results/two-own-pendulums.png' });
  // a longer first pendulum: the camera frames both again (the second stayed where it was before)
  await page.evaluate(() => window.pendulab.send({ type: 'set_params', length: 2.5 }));
  await page.waitForFunction(() => window.pendulab.store.status?.params.length === 2.5, null, { timeout: WAIT });
  // measured once the scene has drawn the longer pendulum (its bob 2.5 m from the pivot in the frame drawn
  // after the change: the camera refits on that frame), not after a fixed wait; no frame yet just after the
  // change (the new epoch's first is on its way): latest() is null then, and a predicate that threw on it
  // ended the wait at once (the check then ran too early, and the throw counted as a page error)
  const drawnBefore = await page.evaluate(() => window.pendulab.drawn());
  await page
    .waitForFunction((n) => Math.abs(Math.hypot(...(window.pendulab.store.latest()?.x ?? [0, 0, 0])) - 2.5) < 1e-6 && window.pendulab.drawn() > n + 2 && window.pendulab.twinOnScreen() !== null, drawnBefore, { timeout: WAIT, polling: 100 })
    .catch(() => {});
  const after = await page.evaluate(() => ({ twin: window.pendulab.twinOnScreen(), bob: window.pendulab.bobOnScreen() }));
  check(inCanvas(after.twin) && inCanvas(after.bob), 'a longer first pendulum keeps both in view');
  await page.evaluate(() => {
    window.pendulab.send({ type: 'set_params', length: 1 });
    window.pendulab.send({ type: 'set_time_scale', time_scale: 1 });
  });
}
