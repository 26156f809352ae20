// Classroom checks (classroom.mjs; run by smoke.mjs), the layout: at a projector's and a phone's size the
// controls never cover the canvas and the whole sphere of reach is in view; on a phone or tablet (issue 28)
// a message never covers the view, every control is at least 44 px tall, the classroom tools come first,
// and a server that goes away shows a banner. Sizes in CSS px. Waits are generous (a loaded
// 2-core machine), but every check compares against a bound and can fail.

const overlaps = (a, b) => a.left < b.right - 0.5 && b.left < a.right - 0.5 && a.top < b.bottom - 0.5 && b.top < a.bottom - 0.5;
const boxes = (page) =>
  page.evaluate(() => {
    const r = (el) => el.getBoundingClientRect().toJSON();
    return { canvas: r(document.getElementById('scene-canvas')), panel: r(document.getElementById('panel')), sphere: window.pendulab.sphereOnScreen() };
  });

const inside = (s, c) => s.left >= c.left - 1 && s.right <= c.right + 1 && s.top >= c.top - 1 && s.bottom <= c.bottom + 1;


export async function checkLayout(page, { check, WAIT }) {
  for (const [w, h, name] of [
    [1280, 800, 'projector 1280×800'],
    [390, 844, 'phone 390×844'],
  ]) {
    await page.setViewportSize({ width: w, height: h });
    await page.waitForTimeout(600);
    const b = await boxes(page);
    check(!overlaps(b.canvas, b.panel) && b.canvas.width > 0.3 * w && b.canvas.height > 0.3 * h, `${name}: the panel never covers the canvas (canvas ${Math.round(b.canvas.width)}×${Math.round(b.canvas.height)} px)`);
    check(inside(b.sphere, b.canvas), `${name}: the whole sphere of reach is in view with the panel open`);
    await page.screenshot({ path: `test-results/layout-${w}x${h}.png` });
    await page.locator('[data-action="panel"]').click();
    await page.waitForTimeout(600);
    const c = await boxes(page);
    check(!overlaps(c.canvas, c.panel) && c.canvas.width * c.canvas.height > 1.2 * b.canvas.width * b.canvas.height, `${name}: collapsing the panel gives the canvas the room (${Math.round(c.canvas.width)}×${Math.round(c.canvas.height)} px)`);
    await page.screenshot({ path: `test-results/layout-${w}x${h}-collapsed.png` });
    await page.locator('[data-action="panel"]').click();
  }
  await page.setViewportSize({ width: 1280, height: 800 });
  // side-by-side stereo: both eyes in the canvas, none under the panel
  await page.locator('[data-control="stereo"] select').selectOption('side by side');
  await page.waitForTimeout(500);
  const s = await boxes(page);
  await page.screenshot({ path: 'test-results/layout-side-by-side.png' });
  check(!overlaps(s.canvas, s.panel), 'side-by-side stereo: both eyes use the full view beside the panel');
  await page.locator('[data-control="stereo"] select').selectOption('off');
}

/** Phone and tablet (issue 28): a message never covers the view, every control of the panel is at least
 *  44 px tall, the classroom tools come first, and a server that goes away shows a banner above the view. */
export async function checkTouch(page, { check, skip, transport, WAIT }) {
  for (const [w, h, name] of [
    [390, 844, 'phone 390×844'],
    [820, 1180, 'portrait tablet 820×1180'],
  ]) {
    await page.setViewportSize({ width: w, height: h });
    await page.evaluate(() => window.pendulab.send({ type: 'set_params', length: -1 })); // refused: a message
    await page.waitForFunction(() => document.getElementById('message').classList.contains('shown'), null, { timeout: WAIT });
    const b = await page.evaluate(() => {
      const r = (el) => el.getBoundingClientRect().toJSON();
      const small = [];
      // everything a finger can touch in the panel, with every lil-gui folder and <details> opened for the
      // count (and closed again): buttons, pickers (lil-gui's invisible <select> over its value too), inputs,
      // check box labels, folder titles, lil-gui rows, glossary entries, links
      const closed = [...document.querySelectorAll('#gui .lil-gui.lil-closed > .lil-title, #panel details:not([open]) > summary')];
      for (const c of closed) c.click();
      const TOUCHABLE = '#panel button, #panel select, #panel input:not([type=checkbox]):not([type=hidden]), #panel label:has(> input[type=checkbox]), #panel summary, #panel .lil-gui .lil-controller, #panel .lil-gui .lil-title, #panel a[href], footer a[href]';
      let n = 0;
      for (const el of document.querySelectorAll(TOUCHABLE)) {
        const q = el.getBoundingClientRect();
        if (q.width > 0 && q.height > 0) n++;
        if (q.width > 0 && q.height > 0 && q.height < 44 - 0.5) small.push(`${el.dataset.action ?? el.dataset.input ?? el.tagName + ' ' + el.textContent.slice(0, 24)} ${q.height.toFixed(0)} px`);
      }
      for (const c of closed.reverse()) c.click();
      return { canvas: r(document.getElementById('scene-canvas')), message: r(document.getElementById('message')), small, n, toolsFirst: document.getElementById('tools').getBoundingClientRect().top < document.getElementById('gui').getBoundingClientRect().top };
    });
    check(b.message.height > 0 && !overlaps(b.canvas, b.message), `${name}: a message (${Math.round(b.message.width)}×${Math.round(b.message.height)} px) does not cover the view`);
    check(b.small.length === 0 && b.n > 60, `${name}: every one of the panel's ${b.n} touch targets (toolbar, tools, lil-gui rows and pickers, glossary) is at least 44 px tall${b.small.length ? ': ' + b.small.slice(0, 6).join(', ') : ''}`);
    check(b.toolsFirst, `${name}: the classroom tools come before the other controls`);
    await page.screenshot({ path: `test-results/touch-${w}x${h}.png` });
  }
  await page.setViewportSize({ width: 1280, height: 800 });
  // presentation mode: large type, the view still free and the whole sphere in it; the link carries it
  await page.locator('[data-action="present"]').click();
  await page.waitForFunction(() => /present/.test(location.search), null, { timeout: WAIT });
  await page.waitForTimeout(500);
  const big = await page.evaluate(() => ({ watch: parseFloat(getComputedStyle(document.querySelector('[data-readout="stopwatch"]')).fontSize), body: parseFloat(getComputedStyle(document.querySelector('.tools label')).fontSize) }));
  const pb = await boxes(page);
  await page.screenshot({ path: 'test-results/presentation.png' });
  check(big.watch >= 30 && big.body >= 18 && !overlaps(pb.canvas, pb.panel) && inside(pb.sphere, pb.canvas), `presentation mode: ${big.body} px type, ${big.watch} px readouts, the view free with the whole sphere in it`);
  await page.locator('[data-action="present"]').click();
  // a teacher's presentation link opened on a student's phone, in German and French (long words, large type):
  // every picker, table and row of the panel stays inside it (the gravity picker and the period table
  // reached 110 px past its edge)
  for (const lang of ['de', 'fr']) {
    const phone = await page.context().newPage();
    await phone.setViewportSize({ width: 390, height: 844 });
    await phone.goto(`${page.url().split('?')[0]}?lang=${lang}&view=present`, { timeout: WAIT });
    await phone.waitForFunction(() => (window.pendulab?.store.frames.length ?? 0) > 5, null, { timeout: WAIT });
    const beyond = await phone.evaluate(() => {
      for (const c of document.querySelectorAll('#gui .lil-gui.lil-closed > .lil-title, #panel details:not([open]) > summary')) c.click();
      const edge = document.getElementById('panel').getBoundingClientRect().right;
      return [...document.querySelectorAll('#panel *')]
        .filter((el) => el.getBoundingClientRect().width > 0 && el.getBoundingClientRect().right > edge + 1)
        .map((el) => `${el.tagName} "${el.textContent.trim().slice(0, 24)}" ${Math.round(el.getBoundingClientRect().right - edge)} px`);
    });
    check(beyond.length === 0, `presentation mode on a phone in ${lang}: nothing reaches past the panel's edge${beyond.length ? ': ' + beyond.slice(0, 5).join(', ') : ''}`);
    await phone.close();
  }
  if (transport === 'file') {
    skip('the server gone', 'there is no server: the physics runs in the page (its banner is for a lost WebSocket)');
    return;
  }
  // the server goes away: the page's socket is closed and every reconnection refused, then let through
  const page2 = await page.context().newPage();
  let refuse = false;
  let open = null;
  await page2.routeWebSocket(/\/ws$/, (ws) => {
    if (refuse) return void ws.close();
    open = ws;
    ws.connectToServer();
  });
  await page2.goto(new URL(page.url()).origin + '/', { timeout: WAIT });
  await page2.waitForFunction(() => (window.pendulab?.store.frames.length ?? 0) > 2, null, { timeout: WAIT });
  const before = await page2.evaluate(() => document.getElementById('offline').hidden);
  refuse = true;
  await open.close();
  await page2.waitForFunction(() => !document.getElementById('offline').hidden, null, { timeout: WAIT });
  const banner = await page2.evaluate(() => {
    const b = document.getElementById('offline');
    const c = document.getElementById('scene-canvas').getBoundingClientRect();
    return { text: b.textContent, h: b.getBoundingClientRect().height, below: c.top >= b.getBoundingClientRect().bottom - 0.5, size: parseFloat(getComputedStyle(b).fontSize) };
  });
  await page2.screenshot({ path: 'test-results/server-gone.png' });
  check(before && banner.h > 20 && banner.below && banner.size >= 16 && /not answering/.test(banner.text), `the server gone: a ${banner.size} px banner above the view, "${banner.text.slice(0, 60)}…"`);
  refuse = false;
  await page2.waitForFunction(() => document.getElementById('offline').hidden, null, { timeout: WAIT });
  check(true, 'the banner goes when the server answers again');
  await page2.close();
}
