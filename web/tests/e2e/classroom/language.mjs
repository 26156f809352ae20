// Classroom checks (classroom.mjs; run by smoke.mjs): the second language (the page in German: its data
// rows, units SI) and axe-core's accessibility rules on the lab as a projector and a phone show it, in
// every language. Waits are generous (a loaded 2-core machine), but every check compares against a bound
// and can fail.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';

/** The data panel's rows as [label, value, unit]. */
export const dataRows = (page) =>
  page.evaluate(() => [...document.querySelectorAll('#data table tr')].map((tr) => [...tr.cells].map((c) => c.textContent ?? '')));

export async function checkLanguage(page, { check, WAIT }) {
  // The switch right after a command (here a resume, as the measured-data check before leaves it): the page
  // waits until the server's status has counted the command, so the reload keeps the run going. (It used
  // to reload from a URL still saying paused=1: the page came back paused and no frames came.) The resume
  // and the switch go in one task, so the resume's status cannot have arrived before the switch.
  await page.evaluate(() => window.pendulab.send({ type: 'pause' }));
  await page.waitForFunction(() => window.pendulab.store.status?.paused === true, null, { timeout: WAIT });
  await page.evaluate(() => {
    window.pendulab.send({ type: 'resume' });
    const select = document.querySelector('[data-input="language"]');
    select.value = 'de';
    select.dispatchEvent(new Event('change'));
  });
  await page.waitForURL(/lang=de/, { timeout: WAIT });
  const running = await page
    .waitForFunction(() => (window.pendulab?.store.frames.length ?? 0) > 2 && window.pendulab.store.status?.paused === false, null, { timeout: WAIT })
    .then(() => true, (e) => String(e).split('\n')[0]);
  const paused = /paused=1/.test(page.url());
  check(running === true && !paused, `the language switch right after a resume keeps the lab running${running === true ? '' : ` (${running})`}${paused ? ' (reloaded paused)' : ''}`);
  const de = await page.evaluate(() => ({ lang: document.documentElement.lang, reset: document.querySelector('[data-action="reset"]').textContent, title: document.querySelector('[data-tool="stopwatch"] h3').textContent }));
  // the row comes with the panel, its value and unit with the first frame that carries an estimate
  await page
    .waitForFunction(
      () => [...document.querySelectorAll('#data tr')].some((tr) => tr.cells[0]?.textContent === 'Lagefehler |Δx|' && tr.cells[2]?.textContent === 'm'),
      null,
      { timeout: WAIT },
    )
    .catch(() => undefined);
  const rowDe = (await dataRows(page)).find((r) => r[0] === 'Lagefehler |Δx|');
  await page.screenshot({ path: 'test-results/lab-de.png' });
  await page.locator('[data-input="language"]').selectOption('en');
  await page.waitForURL(/lang=en/, { timeout: WAIT });
  await page.waitForFunction(() => (window.pendulab?.store.frames.length ?? 0) > 2, null, { timeout: WAIT });
  const en = await page.evaluate(() => document.querySelector('[data-action="reset"]').textContent);
  check(de.lang === 'de' && de.reset === 'Zurück' && /Stoppuhr/.test(de.title) && en === 'Reset', `a second language (German) switches and back (${de.reset}, ${de.title})`);
  check(rowDe !== undefined && rowDe[2] === 'm', `the error estimate in German: ${rowDe?.join(' ')}`);
}

/** axe-core (issue 28): zero violations of its default rules on the lab as a projector and a phone show it,
 *  with "Skip to controls" shown, with the help dialog open, with the second pendulum's panel in use, and in German and French on a phone
 *  (where a button's visible words differ from its tooltip: WCAG's label in name). */
export async function checkAxe(page, { check, WAIT }) {
  const source = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
  await page.evaluate(source); // evaluated by the test driver, as the page's CSP forbids inline scripts
  const run = () =>
    page.evaluate(async () =>
      (await window.axe.run(document)).violations.map((v) => `${v.id} (${v.impact}): ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(', ')}`),
    );
  const found = [];
  for (const [w, h] of [
    [1280, 800],
    [390, 844],
  ]) {
    await page.setViewportSize({ width: w, height: h });
    await page.waitForTimeout(400);
    found.push(...(await run()).map((v) => `${w}×${h} ${v}`));
  }
  await page.setViewportSize({ width: 1280, height: 800 });
  await page.locator('#skip').focus(); // "Skip to controls" shown (it has the focus)
  found.push(...(await run()).map((v) => `skip link shown ${v}`));
  await page.evaluate(() => document.activeElement?.blur());
  await page.keyboard.press('?');
  await page.waitForFunction(() => !document.getElementById('help').hidden, null, { timeout: WAIT });
  found.push(...(await run()).map((v) => `help open ${v}`));
  await page.keyboard.press('Escape');
  await page.evaluate(() => window.pendulab.send({ type: 'resume' }));
  await page.locator('[data-plot="chosen"]').scrollIntoViewIfNeeded();
  await page.waitForFunction(() => /\d at \d/.test(document.querySelector('[data-plot="chosen"]').getAttribute('aria-label')), null, { timeout: WAIT });
  const alt = await page.evaluate(() => [...document.querySelectorAll('.plot.curve canvas, .uplot')].map((c) => [c.getAttribute('role'), c.getAttribute('aria-label')]));
  check(alt.length >= 4 && alt.every(([r, a]) => r === 'img' && a), `every chart (${alt.length}) carries a text alternative, e.g. "${alt.find(([, a]) => /\d at \d/.test(a))?.[1]}"`);
  for (const lang of ['de', 'fr']) {
    const p = await page.context().newPage();
    await p.setViewportSize({ width: 390, height: 844 });
    await p.goto(`${page.url().split('?')[0]}?lang=${lang}`, { timeout: WAIT });
    await p.waitForFunction(() => (window.pendulab?.store.frames.length ?? 0) > 5, null, { timeout: WAIT });
    await p.evaluate(source);
    const v = await p.evaluate(async () => (await window.axe.run(document)).violations.map((x) => `${x.id} (${x.impact}): ${x.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(', ')}`));
    found.push(...v.map((x) => `${lang} 390×844 ${x}`));
    await p.close();
  }
  check(found.length === 0, `axe-core ${await page.evaluate(() => window.axe.version)}: no violations (English at 1280×800 and 390×844, skip link shown, help open; German and French at 390×844)${found.length ? ': ' + found.join('; ') : ''}`);
}
