// End-to-end checks of the model picker, the vectors, the portraits and the scenario download, run by
// smoke.mjs on its page (after its own checks). Everything goes through the page's controls as a user
// would (lil-gui's select, number boxes and buttons), and the effects are read from the server's status.
import { readFileSync } from 'node:fs';

/** Chooses `name` in the model picker (a lil-gui select whose options read `label (name)`). */
async function pickModel(page, name) {
  await page.evaluate((name) => {
    const select = document.querySelector('[data-control="model"] select');
    const i = [...select.options].findIndex((o) => o.textContent === name || o.textContent.endsWith(`(${name})`));
    if (i < 0) throw new Error(`no model ${name} in the picker`);
    select.selectedIndex = i;
    select.dispatchEvent(new Event('change'));
  }, name);
}

/** Types `value` into the number box of the parameter control `name` and confirms it (Enter). */
async function typeParam(page, name, value) {
  const input = page.locator(`[data-param="${name}"] input`).first();
  await input.fill(String(value));
  await input.press('Enter');
}

/** Pixels of the scene close to an RGB colour. */
const colourPixels = (page, rgb) =>
  page.evaluate(async (rgb) => {
    const img = new Image();
    img.src = window.pendulab.screenshot();
    await img.decode();
    const c = document.createElement('canvas');
    [c.width, c.height] = [img.width, img.height];
    const ctx = c.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const px = ctx.getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < px.length; i += 4) {
      if (Math.abs(px[i] - rgb[0]) + Math.abs(px[i + 1] - rgb[1]) + Math.abs(px[i + 2] - rgb[2]) < 40) n++;
    }
    return n;
  }, rgb);

/** How far [px] the velocity arrow's tip may land from the pointer that pulled it (see the pull below). */
const TIP_PX = 5;

/** The reduced view, stereo, dragging the bob and pulling the velocity arrow (on the ideal pendulum). */
export async function checkViews(page, { check, WAIT, simulated }) {
  await page.evaluate(() => {
    window.pendulab.send({ type: 'load_scenario', name: 'rosette' });
    window.pendulab.send({ type: 'set_model', model: 'ideal' });
    window.pendulab.send({ type: 'resume' });
  });
  await page.waitForFunction(() => window.pendulab.store.status?.model === 'ideal' && !window.pendulab.store.status.paused, null, { timeout: WAIT });
  await simulated(page, 1);
  await page.locator('#reduced canvas').scrollIntoViewIfNeeded();
  await page.waitForTimeout(1000);
  const reducedInk = await page.evaluate(async () => {
    const img = new Image();
    img.src = document.querySelector('#reduced canvas').toDataURL();
    await img.decode();
    const c = document.createElement('canvas');
    [c.width, c.height] = [img.width, img.height];
    const ctx = c.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const px = ctx.getImageData(0, 0, c.width, c.height).data;
    let orbit = 0;
    for (let i = 0; i < px.length; i += 4) if (Math.abs(px[i] - 0x59) + Math.abs(px[i + 1] - 0xc3) + Math.abs(px[i + 2] - 0xff) < 60) orbit++;
    return orbit;
  });
  check(reducedInk > 30, `reduced view draws the orbit in σ-space (${reducedInk} pixels)`);
  await page.screenshot({ path: 'test-results/lab-reduced.png' });

  // stereo: the anaglyph draws in red and cyan
  await page.locator('.lil-title', { hasText: /^View$/ }).click();
  await page.locator('[data-control="stereo"] select').selectOption('anaglyph');
  await page.waitForTimeout(500);
  await page.screenshot({ path: 'test-results/lab-anaglyph.png' });
  const fringe = await page.evaluate(() => document.getElementById('scene-canvas') !== null);
  await page.locator('[data-control="stereo"] select').selectOption('off');
  check(fringe, 'stereo (anaglyph) renders and switches back');

  // dragging the bob sets a new start at rest and pauses
  await page.evaluate(() => window.pendulab.send({ type: 'pause' }));
  await page.waitForFunction(() => window.pendulab.store.status?.paused === true, null, { timeout: WAIT });
  await page.waitForTimeout(300);
  const before = await page.evaluate(() => window.pendulab.store.status.start.x);
  const bob = await page.evaluate(() => window.pendulab.bobOnScreen());
  await page.mouse.move(bob.x, bob.y);
  await page.mouse.down();
  for (let k = 1; k <= 10; k++) await page.mouse.move(bob.x - 12 * k, bob.y - 6 * k);
  await page.mouse.up();
  await page.waitForFunction(
    (b) => {
      const s = window.pendulab.store.status;
      return s.start.v.every((c) => c === 0) && s.start.x.some((c, i) => Math.abs(c - b[i]) > 0.05);
    },
    before,
    { timeout: WAIT },
  );
  const after = await page.evaluate(() => window.pendulab.store.status);
  const r = Math.hypot(...after.start.x);
  check(after.paused && Math.abs(r - after.params.length) < 1e-12, `dragging the bob sets a start at rest on the sphere (x = ${after.start.x.map((c) => c.toFixed(3)).join(', ')} m)`);

  // pulling the velocity arrow by its handle sets the start velocity at that x: the arrow's tip follows
  // the pointer, the message line shows the speed, and the run starts off in the pulled direction
  await page.waitForFunction(() => window.pendulab.handleOnScreen() !== null, null, { timeout: WAIT });
  await page.waitForTimeout(300); // let the drag's last throttled set_state land
  // the pull starts from the drawn state: wait until that is the server's answer to the bob drag (on a
  // loaded machine a throttled set_state of the drag may still be in flight)
  await page.waitForFunction(
    () => {
      const store = window.pendulab.store;
      const f = store.latest();
      const x = store.status.start.x;
      return store.status.paused && f !== null && f.x.every((c, i) => Math.abs(c - x[i]) < 1e-12);
    },
    null,
    { timeout: WAIT },
  );
  // the x the pull must keep: the start as it stands now (the drag's last throttled set_state may have
  // landed after `after` was read)
  const xBefore = await page.evaluate(() => window.pendulab.store.status.start.x);
  const handle = await page.evaluate(() => window.pendulab.handleOnScreen());
  const target = { x: handle.x + 70, y: handle.y + 35 };
  await page.mouse.move(handle.x, handle.y);
  await page.mouse.down();
  for (let k = 1; k <= 10; k++) await page.mouse.move(handle.x + 7 * k, handle.y + 3.5 * k);
  const message = await page.evaluate(() => document.getElementById('message').textContent);
  await page.mouse.up();
  // Measured from the engine's state and the pull's own geometry, not from a picture taken after a wait
  // (2.08, 3.89 and 5.9 px were seen on loaded machines when the drawn handle was compared with the pointer
  // later, with whatever camera and throttled sends came in between): (1) at the release, with the camera of
  // that instant, the tip of the velocity the page computed from the pointer lies under the pointer; (2) the
  // server's start velocity becomes that velocity (its projection onto the tangent changes it by round-off
  // only); (3) the handle drawn from the server's state sits at that arrow's tip, x + v · scale [m].
  const release = await page.evaluate(() => window.pendulab.lastPull());
  const landed = await page
    .waitForFunction((want) => window.pendulab.store.status.start.v.every((c, i) => Math.abs(c - want[i]) <= 1e-9 * Math.hypot(...want)), release?.v ?? [0, 0, 0], { timeout: WAIT, polling: 100 })
    .then(() => true, () => false);
  const handleMiss = await page
    .waitForFunction(
      () => {
        const s = window.pendulab.store.status;
        const f = window.pendulab.store.latest();
        const h = window.pendulab.handleAt();
        if (h === null || f === null || !f.x.every((c, i) => c === s.start.x[i])) return null;
        const tip = s.start.v.map((c) => c * h.scale);
        const len = Math.hypot(...tip);
        const clear = 0.085 * s.params.length; // scene/body.ts HANDLE_CLEAR: a short arrow's handle sits at this distance
        const off = len >= clear ? tip : tip.map((c) => (c * clear) / len);
        const d = Math.hypot(...h.at.map((c, i) => c - (f.pivot[i] + f.x[i] + off[i])));
        return d <= 1e-9 * s.params.length ? { d } : null;
      },
      null,
      { timeout: WAIT, polling: 100 },
    )
    .then((h) => h.jsonValue().then((o) => o.d), () => null);
  await page.screenshot({ path: 'test-results/lab-velocity.png' });
  const pulled = await page.evaluate(() => ({ s: window.pendulab.store.status }));
  const v = pulled.s.start.v;
  const speed = Math.hypot(...v);
  const x0 = pulled.s.start.x;
  const tangent = Math.abs(v[0] * x0[0] + v[1] * x0[1] + v[2] * x0[2]) < 1e-9 * speed * Math.hypot(...x0);
  const sameX = x0.every((c, i) => Math.abs(c - xBefore[i]) < 1e-12);
  const miss = release === null ? Infinity : Math.hypot(release.tip.x - release.pointer.x, release.tip.y - release.pointer.y);
  const atPointer = release !== null && Math.hypot(release.pointer.x - target.x, release.pointer.y - target.y) < 0.5;
  check(
    pulled.s.paused && sameX && tangent && speed > 0.1 && miss < TIP_PX && atPointer && landed && handleMiss !== null,
    `pulling the velocity arrow sets the start velocity at the same x, tangent (v = ${v.map((c) => c.toFixed(3)).join(', ')} m/s; at the release the tip ${miss.toFixed(2)} px from the pointer; the server's v ${landed ? 'is' : 'is NOT'} the pulled one; the handle drawn ${handleMiss === null ? 'NOT ' : ''}at its tip (${handleMiss?.toExponential(1)} m); paused ${pulled.s.paused}, x moved by ${x0.map((c, i) => (c - xBefore[i]).toExponential(1)).join(', ')} m, x·v ${(v[0] * x0[0] + v[1] * x0[1] + v[2] * x0[2]).toExponential(2)} m²/s)`,
  );
  check(/\|v\| = \d+\.\d\d m\/s/.test(message), `the message line shows the speed while pulling (“${message}”)`);
  // start: the first frames move along v
  await page.evaluate(() => window.pendulab.send({ type: 'resume' }));
  await simulated(page, 0.05);
  const moved = await page.evaluate(() => {
    const tr = window.pendulab.store.trajectory;
    const a = tr[0];
    const b = tr.find((f) => f.t - a.t >= 0.02) ?? tr[tr.length - 1];
    return { dx: b.x.map((c, i) => c - a.x[i]), dt: b.t - a.t, x0: a.x };
  });
  await page.evaluate(() => window.pendulab.send({ type: 'pause' }));
  const along = (moved.dx[0] * v[0] + moved.dx[1] * v[1] + moved.dx[2] * v[2]) / (Math.hypot(...moved.dx) * speed);
  check(along > 0.9 && moved.x0.every((c, i) => Math.abs(c - x0[i]) < 1e-12), `start runs from the pulled velocity: the first frames move along it (cos = ${along.toFixed(4)} over ${moved.dt.toFixed(3)} s)`);
  await page.waitForFunction(() => window.pendulab.store.status?.paused === true, null, { timeout: WAIT });
}

export async function checkModels(page, { check, skip, transport, WAIT, simulated }) {
  const status = () => page.evaluate(() => window.pendulab.store.status);
  const waitStatus = (fn, arg) => page.waitForFunction(fn, arg, { timeout: WAIT, polling: 100 });

  await page.evaluate(() => {
    window.pendulab.send({ type: 'load_scenario', name: 'rosette' });
    window.pendulab.send({ type: 'resume' });
  });
  await waitStatus(() => window.pendulab.store.status?.params.g === 9.81 && !window.pendulab.store.status.paused);

  // the picker: damped, then its damping through the generated control
  await pickModel(page, 'damped');
  await waitStatus(() => window.pendulab.store.status?.model === 'damped');
  const picked = await status();
  const option = await page.evaluate(() => document.querySelector('[data-control="model"] select').selectedOptions[0].textContent);
  check(picked.model_params.damping === 0.3 && option === 'Damped and driven (damped)', `picking “${option}” starts with visible friction (damping ${picked.model_params.damping} 1/s)`);
  await page.locator('[data-param="damping"] input').first().waitFor({ timeout: WAIT });
  await typeParam(page, 'damping', 0.8);
  await waitStatus(() => window.pendulab.store.status?.model_params.damping === 0.8);
  // a length change keeps the model and its damping (the bug: the pendulum was rebuilt without them)
  await typeParam(page, 'length', 1.2);
  await waitStatus(() => window.pendulab.store.status?.params.length === 1.2);
  let s = await status();
  check(s.model === 'damped' && s.model_params.damping === 0.8, `length change keeps the model (${s.model}, damping ${s.model_params.damping} 1/s)`);
  await simulated(page, 3);
  // the energy above the bottom, E + m g l, decays like e^(−c t) for a small swing (c = 0.8 1/s: to 9 % in 3 s)
  const decay = await page.evaluate(() => {
    const tr = window.pendulab.store.trajectory;
    const p = window.pendulab.store.status.params;
    const bottom = -p.mass * p.g * p.length;
    const last = tr[tr.length - 1];
    return { e0: tr[0].energy, e1: last.energy, ratio: (last.energy - bottom) / (tr[0].energy - bottom), dt: last.t - tr[0].t, p: Math.max(...tr.map((f) => f.power)) };
  });
  check(decay.ratio < 0.5 && decay.p <= 1e-9, `damped: energy ${decay.e0.toFixed(3)} → ${decay.e1.toFixed(3)} J (above the bottom: ×${decay.ratio.toFixed(3)} in ${decay.dt.toFixed(2)} s), power ≤ 0`);

  // a value outside the limits is explained by the page and not sent; the server names bad values too
  await typeParam(page, 'damping', -1);
  await page.waitForFunction(() => document.getElementById('message').textContent.includes('damping = -1'), null, { timeout: WAIT });
  await page.evaluate(() => window.pendulab.send({ type: 'set_params', params: { damping: -2 } }));
  await page.waitForFunction(() => document.getElementById('message').textContent.includes('damping = -2'), null, { timeout: WAIT });
  s = await status();
  check(s.model_params.damping === 0.8, 'bad damping explained (page and server) and not applied');

  // vectors: the angular momentum arrow (teal) appears when toggled
  await page.evaluate(() => window.pendulab.send({ type: 'pause' }));
  await waitStatus(() => window.pendulab.store.status?.paused === true);
  await page.evaluate(() => window.pendulab.send({ type: 'reset' }));
  await page.waitForTimeout(500);
  const before = await colourPixels(page, [0x4d, 0xd9, 0xc0]);
  await page.locator('.lil-title', { hasText: 'Vectors' }).click();
  await page.locator('[data-vector="angularMomentum"] input').check();
  await page.locator('[data-vector="net"] input').check();
  await page.waitForTimeout(300);
  const after = await colourPixels(page, [0x4d, 0xd9, 0xc0]);
  check(after > before + 20, `angular momentum arrow drawn (${before} → ${after} teal pixels)`);

  // the portraits: phase portrait and V_eff drawn
  await page.evaluate(() => window.pendulab.send({ type: 'resume' }));
  await simulated(page, 1);
  await page.waitForTimeout(500);
  const inked = await page.evaluate(() =>
    [...document.querySelectorAll('#portraits canvas')].map((c) => {
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let i = 3; i < d.length; i += 4) if (d[i] > 0) n++;
      return n;
    }),
  );
  check(inked.length === 3 && inked.every((n) => n > 500), `phase portrait, V_eff and the energy–momentum map drawn (${inked.join(', ')} pixels)`);

  // the scenario as TOML, through the button (the server renders it: in the one-file lab the page says so)
  if (transport === 'file') {
    await page.locator('.lil-title', { hasText: 'Share and export' }).click();
    await page.locator('[data-control="toml"] button').click();
    const said = await page.waitForFunction(() => {
      const m = /the scenario as a TOML file needs the Python server[^.]*/.exec(document.body.textContent ?? '');
      return m ? m[0] : null;
    }, null, { timeout: WAIT });
    check(true, `the scenario download says it needs the server: "${(await said.jsonValue()).slice(0, 80)}…"`);
    skip('the scenario download (TOML)', 'the TOML file is written by Python (pendulab serve)');
  } else {
    const [download] = await Promise.all([
      page.waitForEvent('download', { timeout: WAIT }),
      page.locator('.lil-title', { hasText: 'Share and export' }).click().then(() =>
        page.locator('[data-control="toml"] button').click(),
      ),
    ]);
    const text = readFileSync(await download.path(), 'utf-8');
    check(/model = "damped"/.test(text) && /damping = 0\.8/.test(text) && /length = 1\.2/.test(text), `scenario download (${download.suggestedFilename()}) has the model and damping`);
  }

  // the URL carries the model and its parameters
  const url = page.url();
  const page2 = await page.context().newPage();
  await page2.goto(url, { timeout: WAIT });
  await page2.waitForFunction(() => window.pendulab?.store.status?.model === 'damped', null, { timeout: WAIT });
  const s2 = await page2.evaluate(() => window.pendulab.store.status);
  check(s2.model_params.damping === 0.8 && s2.params.length === 1.2, `the shared URL carries the model (${new URL(url).searchParams.get('mp')})`);
  await page2.close();

  // a moving pivot: slewing puts the pivot on the boom tip
  await pickModel(page, 'slewing');
  await waitStatus(() => window.pendulab.store.status?.model === 'slewing');
  await simulated(page, 1);
  const pivot = await page.evaluate(() => window.pendulab.store.latest().pivot);
  check(Math.abs(Math.hypot(pivot[0], pivot[1]) - 5) < 1e-9, `slewing: the pivot moves on the boom tip circle (|p| = ${Math.hypot(pivot[0], pivot[1]).toFixed(6)} m)`);
  await page.screenshot({ path: 'test-results/lab-slewing.png' });
}

/** The swinging spring and the string, chosen in the picker: they move, the spring's length varies and its
 *  coil is drawn, the string goes slack (dashed, tension 0), and the sphere-only panels say why they are
 *  empty. */
export async function checkOffSphere(page, { check, WAIT, simulated }) {
  const waitStatus = (fn, arg) => page.waitForFunction(fn, arg, { timeout: WAIT, polling: 100 });
  await page.evaluate(() => {
    window.pendulab.send({ type: 'load_scenario', name: 'rosette' });
    window.pendulab.send({ type: 'resume' });
  });
  await waitStatus(() => window.pendulab.store.status?.model === 'ideal' && !window.pendulab.store.status.paused);

  // the spring: picked, it bounces and swings (its length |x| varies), energy kept, the coil drawn
  await pickModel(page, 'spring');
  await waitStatus(() => window.pendulab.store.status?.model === 'spring');
  await page.locator('[data-param="stiffness"] input').first().waitFor({ timeout: WAIT });
  await typeParam(page, 'stiffness', 60);
  await waitStatus(() => window.pendulab.store.status?.model_params.stiffness === 60);
  await simulated(page, 2);
  const spring = await page.evaluate(() => {
    const tr = window.pendulab.store.trajectory;
    const r = tr.map((f) => Math.hypot(...f.x));
    const e = tr.map((f) => f.energy);
    const moved = Math.hypot(...tr[0].x.map((c, i) => c - tr[tr.length - 1].x[i]));
    return { dr: Math.max(...r) - Math.min(...r), de: Math.max(...e) - Math.min(...e), moved, n: tr.length };
  });
  check(spring.dr > 0.05 && spring.moved > 0.01 && spring.de < 1e-3, `spring: moves, its length varies by ${spring.dr.toFixed(3)} m, E kept to ${spring.de.toExponential(1)} J (${spring.n} frames)`);
  const springRows = await page.evaluate(() => document.getElementById('data').textContent);
  check(/spring length \|r\|/.test(springRows) && /swinging spring leaves the sphere/.test(springRows), 'spring: the data panel shows its length and says why the exact solution is not shown');
  await page.screenshot({ path: 'test-results/lab-spring.png' });

  // the string: picked, launched hard enough to go slack; frames report it, the panel says slack
  await pickModel(page, 'string');
  await waitStatus(() => window.pendulab.store.status?.model === 'string');
  await page.evaluate(() => window.pendulab.send({ type: 'set_state', theta: 0, theta_dot: 5.8596 }));
  await simulated(page, 2.5);
  const string = await page.evaluate(() => {
    const tr = window.pendulab.store.trajectory;
    const slack = tr.filter((f) => !f.taut);
    return {
      slack: slack.length,
      taut: tr.length - slack.length,
      inside: slack.every((f) => Math.hypot(...f.x) < window.pendulab.store.status.params.length),
      zeroT: slack.every((f) => f.tension === 0),
      moved: Math.hypot(...tr[0].x.map((c, i) => c - tr[tr.length - 1].x[i])),
    };
  });
  check(string.slack > 0 && string.taut > 0 && string.inside && string.zeroT && string.moved > 0.01, `string: moves and goes slack (${string.slack} slack frames inside the sphere with T = 0, ${string.taut} taut)`);
  // the server's event notices: the leave, then the snap (restitution 0: it loses energy), listed in the
  // data panel; the first slack frame comes at or after the leave's time
  const events = await page.evaluate(() => {
    const ev = window.pendulab.store.events;
    const firstSlack = window.pendulab.store.trajectory.find((f) => !f.taut);
    return {
      kinds: ev.map((e) => e.kind).join(','),
      lost: ev.map((e) => e.energy_lost),
      slackT: ev[0]?.t ?? NaN,
      firstSlackT: firstSlack?.t ?? NaN,
      panel: document.getElementById('data').textContent,
    };
  });
  check(
    events.kinds.startsWith('slack,taut') && events.lost[0] === 0 && events.lost[1] > 0 && events.firstSlackT >= events.slackT && /went slack/.test(events.panel) && /snapped taut/.test(events.panel),
    `string: event notices ${events.kinds} (lost ${events.lost.map((v) => v.toFixed(3)).join(', ')} J), listed in the data panel`,
  );
  // catch a slack moment on the page: the data panel says slack, the message line the event
  await page.evaluate(() => window.pendulab.send({ type: 'set_state', theta: 0, theta_dot: 5.8596 }));
  await page.waitForFunction(() => /slack: free flight/.test(document.getElementById('data').textContent), null, { timeout: WAIT, polling: 20 });
  await page.waitForFunction(() => /^t = \d+\.\d{3} s: the string (went slack|snapped taut)/.test(document.getElementById('message').textContent), null, { timeout: WAIT, polling: 20 });
  const said = await page.evaluate(() => document.getElementById('message').textContent);
  check(/the string (went slack|snapped taut, lost \d)/.test(said), `string: the message line shows the event (“${said}”)`);
  await page.evaluate(() => window.pendulab.send({ type: 'pause' }));
  await page.screenshot({ path: 'test-results/lab-string-slack.png' });
  const note = await page.evaluate(() => document.querySelector('[data-note="portraits"]').textContent);
  check(/string goes slack/.test(note), 'string: the data panel reports slack, the portraits say why V_eff is not shown');
  await page.evaluate(() => window.pendulab.send({ type: 'resume' }));
}
