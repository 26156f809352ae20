// Classroom checks (classroom.mjs; run by smoke.mjs), the keyboard: the shortcuts and a focused slider,
// and issue 28's inclusion tools (the 3-D view by keyboard, the motion in words, the mystery planet's
// hidden g). Waits are generous (a loaded 2-core machine), but every check compares against a bound and
// can fail.

export async function checkKeyboard(page, { check, WAIT }) {
  await page.evaluate(() => window.pendulab.send({ type: 'load_scenario', name: 'rosette' }));
  await page.waitForFunction(() => window.pendulab.store.status?.scenario === 'rosette', null, { timeout: WAIT });
  await page.evaluate(() => document.activeElement?.blur());
  const paused = () => page.evaluate(() => window.pendulab.store.status.paused);
  const p0 = await paused();
  await page.keyboard.press('Space');
  await page.waitForFunction((p) => window.pendulab.store.status.paused !== p, p0, { timeout: WAIT });
  await page.keyboard.press('Space');
  await page.waitForFunction((p) => window.pendulab.store.status.paused === p, p0, { timeout: WAIT });
  check(true, 'Space pauses and resumes');
  await page.keyboard.press('Space');
  await page.waitForFunction(() => window.pendulab.store.status.paused, null, { timeout: WAIT });
  const tBefore = await page.evaluate(() => window.pendulab.store.status.t);
  await page.keyboard.press('s');
  await page.waitForFunction((t) => window.pendulab.store.status.t > t, tBefore, { timeout: WAIT });
  check(true, 'S takes a step');
  const e0 = await page.evaluate(() => window.pendulab.store.status.epoch);
  await page.keyboard.press('r');
  await page.waitForFunction((e) => window.pendulab.store.status.epoch > e && window.pendulab.store.status.t === window.pendulab.store.status.t0, e0, { timeout: WAIT });
  check(true, 'R resets to the start');
  await page.keyboard.press('?');
  const shown = await page.evaluate(() => !document.getElementById('help').hidden && /Space/.test(document.getElementById('help').textContent) && document.querySelectorAll('#help .swatch').length >= 9);
  await page.screenshot({ path: 'test-results/help-overlay.png' });
  // the focus stays in the dialog: Tab and Shift+Tab from its only control land on it again
  await page.keyboard.press('Tab');
  await page.keyboard.press('Tab');
  await page.keyboard.press('Shift+Tab');
  const kept = await page.evaluate(() => document.getElementById('help').contains(document.activeElement));
  await page.keyboard.press('Escape');
  const closed = await page.evaluate(() => document.getElementById('help').hidden);
  check(shown && closed && kept, '? shows the shortcuts and the colour key, keeps the focus while open; Esc closes it');
  await checkInclusion(page, { check, WAIT });
  // a focused slider: Tab reaches it, arrows and Page keys move it
  const slider = page.locator('[data-param="length"] .lil-slider');
  await slider.focus();
  const ring = await slider.evaluate((el) => getComputedStyle(el).outlineWidth);
  const l0 = await page.evaluate(() => window.pendulab.store.status.params.length);
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction((l) => window.pendulab.store.status.params.length !== l, l0, { timeout: WAIT });
  const l1 = await page.evaluate(() => window.pendulab.store.status.params.length);
  await page.keyboard.press('PageDown');
  await page.waitForFunction((l) => window.pendulab.store.status.params.length !== l, l1, { timeout: WAIT });
  const l2 = await page.evaluate(() => window.pendulab.store.status.params.length);
  const role = await slider.getAttribute('role');
  const label = await slider.getAttribute('aria-label');
  check(l1 > l0 && l2 < l1 && Math.abs((l1 - l2) - 10 * (l1 - l0)) < 1e-9 && role === 'slider' && /length/.test(label) && parseFloat(ring) >= 2, `a focused slider moves with the arrows and Page keys (l ${l0} → ${l1} → ${l2} m), has a label and a ${ring} focus ring`);
  await page.evaluate(() => window.pendulab.send({ type: 'set_params', length: 1 }));
}

/** Issue 28's inclusion tools: the 3-D view by keyboard (arrows turn the camera, Shift + → moves the bob's
 *  start by 1°), the motion in words (D), and the mystery planet's hidden g. */
async function checkInclusion(page, { check, WAIT }) {
  const canvas = page.locator('#scene-canvas');
  await canvas.focus();
  const cam0 = await page.evaluate(() => window.pendulab.bobOnScreen());
  await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('ArrowLeft');
  await page.waitForTimeout(200);
  const cam1 = await page.evaluate(() => window.pendulab.bobOnScreen());
  const th = () => page.evaluate(() => Math.atan2(Math.hypot(...window.pendulab.store.status.start.x.slice(0, 2)), -window.pendulab.store.status.start.x[2]) * 180 / Math.PI);
  const th0 = await th();
  await page.keyboard.press('Shift+ArrowRight');
  await page.waitForFunction((a) => Math.abs(Math.atan2(Math.hypot(...window.pendulab.store.status.start.x.slice(0, 2)), -window.pendulab.store.status.start.x[2]) * 180 / Math.PI - a - 1) < 1e-6, th0, { timeout: WAIT });
  const th1 = await th();
  check(Math.hypot(cam1.x - cam0.x, cam1.y - cam0.y) > 3 && Math.abs(th1 - th0 - 1) < 1e-6, `the 3-D view by keyboard: the arrows turn the camera (the bob moved ${Math.hypot(cam1.x - cam0.x, cam1.y - cam0.y).toFixed(0)} px on the page), Shift+→ the start θ ${th0.toFixed(2)}° → ${th1.toFixed(2)}°`);
  await page.evaluate(() => window.pendulab.send({ type: 'resume' }));
  await page.waitForTimeout(300);
  await page.keyboard.press('d');
  await page.waitForFunction(() => /from the vertical/.test(document.querySelector('[data-readout="describe"]').textContent), null, { timeout: WAIT });
  const words = await page.evaluate(() => ({ text: document.querySelector('[data-readout="describe"]').textContent, live: document.querySelector('[data-readout="describe"]').getAttribute('aria-live') }));
  check(words.live === 'polite' && /speed \d+\.\d\d m\/s; energy \d+ % kinetic, \d+ % potential/.test(words.text), `D describes the motion in a live region: "${words.text}"`);
  await page.locator('[data-input="sound"]').check();
  await page.waitForFunction(() => window.pendulab.tones() >= 2, null, { timeout: WAIT });
  await page.locator('[data-input="sound"]').uncheck();
  check(true, 'sound: a tone at each lowest point (2 heard)');
  await page.locator('[data-input="gravity-preset"]').selectOption('mystery');
  await page.waitForFunction(() => window.pendulab.store.status.params.g !== 9.81 && document.body.classList.contains('mystery'), null, { timeout: WAIT });
  const hidden = await page.evaluate(() => getComputedStyle(document.querySelector('#gui [data-param="g"] .lil-widget')).visibility);
  const g = await page.evaluate(() => window.pendulab.store.status.params.g);
  await page.locator('[data-action="reveal-g"]').click();
  const revealed = await page.evaluate(() => ({ text: document.getElementById('message').textContent, shown: !document.body.classList.contains('mystery') }));
  check(hidden === 'hidden' && g >= 2 && g <= 21 && revealed.shown && revealed.text.includes(String(g)), `mystery planet: g hidden (${hidden}) until revealed as ${g} m/s²`);
  await page.evaluate(() => window.pendulab.send({ type: 'set_params', g: 9.81 }));
  // the glossary opens by a click (a tap) with its text on the page; formula numbers only in the advanced layer
  const refs = () => page.evaluate(() => [...document.querySelectorAll('[title]')].filter((e) => /T-\d+\.\d+|§\s?\d/.test(e.title)).length);
  const plain = await refs();
  await page.locator('[data-tool="glossary"] summary').first().click();
  const gloss = await page.evaluate(() => {
    const d = document.querySelector('[data-tool="glossary"] details');
    return { open: d.open, h: d.querySelector('p').getBoundingClientRect().height, text: d.querySelector('p').textContent };
  });
  await page.locator('[data-input="advanced"]').check();
  const full = await refs();
  await page.locator('[data-input="advanced"]').uncheck();
  const again = await refs();
  check(gloss.open && gloss.h > 10 && plain === 0 && full > 0 && again === 0, `glossary: "${gloss.text.slice(0, 60)}…" shown on the page; tooltips with formula numbers: ${plain} plain, ${full} advanced`);
}
