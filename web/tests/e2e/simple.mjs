// End-to-end check of the simple view (issue 28: "a simple view with PhET-level tools first"), run by
// smoke.mjs: the toolbar's *Simple* folds the physicist's panels away (data, plots, portraits, reduced
// view, fitting, the integrator, view, vectors and export folders, the model picker) and keeps what PhET's
// Pendulum Lab has — length and mass (lil-gui's Pendulum folder), gravity and friction, the start angle,
// stopwatch, period timer, ruler and protractor, energy bars, two pendulums, slow motion —; the link
// carries it; with presentation mode on top the type is large; pressing again brings everything back; a link
// that does not say which view opens as the device chose last (localStorage), else in the simple view. A
// "Skip to controls" link, the first Tab stop, takes the keyboard to the length's control.
const shown = (sel) => [...document.querySelectorAll(sel)].some((e) => e.getClientRects().length > 0 && e.getBoundingClientRect().height > 0);

async function state(page) {
  return page.evaluate((shownSrc) => {
    const isShown = new Function(`return (${shownSrc})`)();
    const targets = [...document.querySelectorAll('#panel button, #panel select, #panel input, #panel .lil-controller')].filter((e) => e.getClientRects().length > 0).length;
    const gone = ['#data', '#plots', '#portraits', '#reduced', '.tools[data-tool="fit"]', '[data-control="model"]'].filter((s) => isShown(s));
    const kept = ['[data-tool="start"]', '[data-tool="world"]', '[data-tool="stopwatch"]', '[data-tool="period"]', '[data-tool="overlays"]', '[data-tool="twin"]', '#energy', '#gui [data-folder="pendulum"] .lil-controller.lil-number', '#gui [data-folder="run"]'].filter((s) => !isShown(s));
    const folders = [...document.querySelectorAll('#gui .lil-root > .lil-children > .lil-gui')].filter((f) => f.getClientRects().length > 0).length;
    return { targets, gone, kept, folders, simple: document.body.classList.contains('simple') };
  }, shown.toString());
}

export async function checkSimpleView(page, { check, WAIT, shot }) {
  const full = await state(page);
  await page.locator('[data-action="simple"]').click();
  await page.waitForFunction(() => (new URLSearchParams(location.search).get('view') ?? '').split(',').includes('simple'), null, { timeout: WAIT });
  const simple = await state(page);
  await page.screenshot({ path: shot('simple-view') });
  check(simple.simple && simple.gone.length === 0 && simple.folders === 2, `simple view: the data panel, plots, portraits, reduced view, fitting, model picker and ${full.folders - 2} settings folders are folded away${simple.gone.length ? ' (still shown: ' + simple.gone.join(', ') + ')' : ''}`);
  check(simple.kept.length === 0 && simple.targets < full.targets, `simple view: PhET's tools kept (length and mass, gravity and friction, start, stopwatch, period, ruler, energy, two pendulums, slow motion); ${simple.targets} controls instead of ${full.targets}${simple.kept.length ? '; missing: ' + simple.kept.join(', ') : ''}`);
  await checkSkipLink(page, { check, WAIT });
  // the link hands the simple view out; presentation mode on top of it
  const p2 = await page.context().newPage();
  await p2.goto(page.url(), { timeout: WAIT });
  await p2.waitForFunction(() => window.pendulab?.store.status != null, null, { timeout: WAIT }); // the link may be paused: no frames
  await p2.locator('[data-action="present"]').click();
  const both = await p2.evaluate(() => ({ simple: document.body.classList.contains('simple'), size: parseFloat(getComputedStyle(document.querySelector('.tools label')).fontSize), data: document.getElementById('data').getClientRects().length }));
  await p2.screenshot({ path: shot('simple-presentation') });
  await p2.close();
  check(both.simple && both.data === 0 && both.size >= 18, `the link opens the simple view; with presentation mode on top ${both.size} px type`);
  await page.locator('[data-action="simple"]').click();
  await page.waitForFunction(() => (new URLSearchParams(location.search).get('view') ?? '').split(',').includes('-simple'), null, { timeout: WAIT });
  const back = await state(page);
  check(!back.simple && back.folders === full.folders && back.targets === full.targets, `pressing Simple again brings everything back (${back.targets} controls)`);
  // a link that does not say which view (the documentation's links, a bare address) opens as this device
  // chose last (the advanced view, just pressed), and on a device that never chose, the simple view
  const p3 = await page.context().newPage();
  const bare = page.url().split('?')[0];
  await p3.goto(bare, { timeout: WAIT });
  await p3.waitForFunction(() => window.pendulab?.store.status != null, null, { timeout: WAIT });
  const chosen = await p3.evaluate(() => document.body.classList.contains('simple'));
  await p3.evaluate(() => localStorage.removeItem('pendulab.simple'));
  await p3.close(); // a new page, not reload(): the address bar of this one now says -simple
  const p4 = await page.context().newPage();
  await p4.goto(bare, { timeout: WAIT });
  await p4.waitForFunction(() => window.pendulab?.store.status != null, null, { timeout: WAIT });
  const never = await p4.evaluate(() => document.body.classList.contains('simple'));
  await p4.evaluate(() => localStorage.setItem('pendulab.simple', '0')); // the checks after this one use the whole panel
  await p4.close();
  check(!chosen && never, `a link without a view opens as the device chose (advanced: ${!chosen}); a device that never chose gets the simple view (${never})`);
}

/** "Skip to controls" (index.html #skip) on a fresh page of the simple view: out of sight until the first
 *  Tab gives it the focus, then shown; Enter moves the focus to the rod length's control, which Tab alone
 *  reaches only after many presses (about 28 when the audit counted; counted and printed here). */
async function checkSkipLink(page, { check, WAIT }) {
  const p = await page.context().newPage();
  const fresh = async () => {
    await p.goto(page.url(), { timeout: WAIT });
    await p.waitForFunction(() => window.pendulab?.store.status != null && document.body.classList.contains('simple'), null, { timeout: WAIT });
  };
  const inLength = () => p.evaluate(() => document.activeElement?.closest('[data-param="length"]') != null);
  await fresh();
  let presses = 0;
  while (presses < 100 && !(await inLength())) {
    await p.keyboard.press('Tab');
    presses += 1;
  }
  await fresh();
  const onScreen = () =>
    p.evaluate(() => {
      const r = document.getElementById('skip').getBoundingClientRect();
      return r.width > 0 && r.bottom > 0 && r.top >= 0 && r.right <= innerWidth;
    });
  const before = await onScreen();
  await p.keyboard.press('Tab');
  const first = await p.evaluate(() => ({ id: document.activeElement?.id, text: document.activeElement?.textContent }));
  const shown = await onScreen();
  await p.keyboard.press('Enter');
  const landed = await inLength();
  const url = p.url();
  await p.close();
  check(
    !before && first.id === 'skip' && shown && landed && !url.includes('#'),
    `"${first.text}": the first Tab reaches it (hidden before: ${!before}, shown while focused: ${shown}); Enter moves the focus to the length's control (${presses - 1} Tab presses after the link without it), the address unchanged`,
  );
}
