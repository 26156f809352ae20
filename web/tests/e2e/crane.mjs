// End-to-end checks of the crane mode (docs/web.md, "Crane mode"), run by smoke.mjs in both transports
// (the server's live session and the page's WebAssembly engine share the core's crane): the mode opens
// from its button and draws the crane, a trolley move leaves the residual sway the core predicts without
// shaping and far less with ZVD (numbers from the engine's frames against the status's linear prediction,
// T-11.1), the rope slider hoists, and the panel speaks German and French. SI units; angles in rad.

/** Sends commands through the page's session. */
const send = (page, ...cmds) => page.evaluate((cmds) => cmds.forEach((c) => window.pendulab.send(c)), cmds);

/** Waits until the status's crane has the rope target [m] and shaping (null: any) and, with `moved`, a last move. */
const craneIs = (page, { rope, shaping = null, moved = false }, WAIT) =>
  page.waitForFunction(
    ([rope, shaping, moved]) => {
      const c = window.pendulab.store.status?.crane;
      return c != null && c.rope_target === rope && (shaping === null || (c.shaping === shaping && c.drag_area === 0)) && (!moved || c.last_move !== null);
    },
    [rope, shaping, moved],
    { timeout: WAIT, polling: 100 },
  );

/** The largest sway angle [rad] of the frames received with t in [t0, t1] [s]. */
const maxSway = (page, t0, t1) =>
  page.evaluate(([t0, t1]) => {
    let best = 0;
    for (const f of window.pendulab.store.trajectory) {
      if (f.t >= t0 && f.t <= t1) best = Math.max(best, Math.atan2(Math.hypot(f.x[0], f.x[1]), -f.x[2]));
    }
    return best;
  }, [t0, t1]);

/** One 5 m move with `shaping` (0 off, 2 ZVD) from rest on a 10 m rope, the time scale 4: the status's
 *  prediction and the largest sway over 1.5 periods after the move ends. */
async function move(page, shaping, WAIT) {
  await send(
    page,
    { type: 'set_params', length: 10, mass: 1000, g: 9.81 },
    { type: 'set_state', theta: 0, phi: 0, theta_dot: 0, phi_dot: 0 },
    { type: 'crane', on: true },
    { type: 'set_params', params: { shaping, drag_area: 0, wind_x: 0, wind_y: 0, v_max: 0.5, a_max: 0.25 } },
    { type: 'set_time_scale', time_scale: 4 },
    { type: 'resume' },
  );
  const name = ['off', 'zv', 'zvd'][shaping];
  await craneIs(page, { rope: 10, shaping: name }, WAIT);
  await send(page, { type: 'crane', move: [5, 0] });
  await craneIs(page, { rope: 10, shaping: name, moved: true }, WAIT);
  const last = await page.evaluate(() => window.pendulab.store.status.crane.last_move);
  const period = 2 * Math.PI * Math.sqrt(10 / 9.81);
  const until = last.end + 1.5 * period;
  await page.waitForFunction((t) => (window.pendulab.store.latest()?.t ?? 0) >= t, until, { timeout: WAIT * 2, polling: 200 });
  const trolley = await page.evaluate(() => window.pendulab.store.latest().pivot[0]);
  return { last, residual: await maxSway(page, last.end, until), trolley };
}

export async function checkCrane(page, { check, WAIT, shot }) {
  // the mode opens from its button: the status has a crane, the panel its controls, the scene the crane
  await page.locator('[data-crane="toggle"]').scrollIntoViewIfNeeded();
  await page.locator('[data-crane="toggle"]').click();
  await craneIs(page, { rope: 10 }, WAIT);
  // the panel follows the status at 10 Hz
  await page.waitForFunction(() => !document.querySelector('.crane-controls').hidden, null, { timeout: 5000 }).catch(() => {});
  const opened = await page.evaluate(() => ({
    model: window.pendulab.store.status.model,
    method: window.pendulab.store.status.method,
    controls: !document.querySelector('.crane-controls').hidden,
  }));
  check(opened.model === 'crane' && opened.method === 'dop853' && opened.controls, `the crane mode opens (model ${opened.model}, method ${opened.method}, controls shown ${opened.controls})`);
  if (shot) await page.screenshot({ path: shot('crane') });

  // a 5 m trolley move: unshaped as predicted, ZVD-shaped a small fraction of it
  const off = await move(page, 0, WAIT);
  const zvd = await move(page, 2, WAIT);
  const rel = Math.abs(off.residual / off.last.residual_unshaped - 1);
  check(
    rel < 0.03 && Math.abs(off.trolley - 5) < 1e-6,
    `an unshaped 5 m move leaves ${off.residual.toFixed(4)} rad of sway, the core predicts ${off.last.residual_unshaped.toFixed(4)} (${(100 * rel).toFixed(2)} % apart; trolley at ${off.trolley.toFixed(6)} m)`,
  );
  check(
    zvd.last.residual_shaped < 1e-9 && zvd.residual < 0.05 * off.residual && Math.abs(zvd.trolley - 5) < 1e-6,
    `the ZVD-shaped move leaves ${zvd.residual.toExponential(2)} rad (unshaped ${off.residual.toFixed(4)}; predicted shaped ${zvd.last.residual_shaped.toExponential(1)})`,
  );

  // the rope slider hoists: the rope's length in the frames goes to the slider's value
  await page.evaluate(() => {
    const r = document.querySelector('[data-crane="rope"]');
    r.value = '6';
    r.dispatchEvent(new Event('input'));
    r.dispatchEvent(new Event('change'));
  });
  await page.waitForFunction(() => {
    const f = window.pendulab.store.latest();
    return f !== null && Math.abs(Math.hypot(...f.x) - 6) < 1e-6;
  }, null, { timeout: WAIT * 2, polling: 200 });
  const rope = await page.evaluate(() => window.pendulab.store.status.crane.rope_target);
  check(rope === 6, `the rope slider hoists the load to a 6 m rope (target ${rope} m, the frames' |x| reached it)`);

  // German and French labels of the panel
  for (const [lang, word] of [['de', 'Seillänge (m)'], ['fr', 'Longueur du câble (m)']]) {
    const url = new URL(page.url());
    url.searchParams.set('lang', lang);
    const p2 = await page.context().newPage();
    await p2.goto(url.toString(), { timeout: WAIT });
    await p2.waitForSelector('[data-crane="toggle"]', { timeout: WAIT });
    const text = await p2.evaluate(() => document.querySelector('[data-tool="crane"]').textContent);
    check(text.includes(word), `the crane panel in ${lang} says "${word}"`);
    await p2.close();
  }
  await send(page, { type: 'set_model', model: 'ideal' }, { type: 'set_time_scale', time_scale: 1 }, { type: 'load_scenario', name: 'rosette' });
  await page.waitForFunction(() => window.pendulab.store.status?.crane == null, null, { timeout: WAIT });
}
