// End-to-end check of the documentation site's "open in the lab" links (issue 26 item 4; tools/lab_links.py
// lists them, python/tests/test_lab_links.py checks every one against the server's session), run by
// smoke.mjs in both transports: a sample — the first link of each kind (a start given as x, v with a plot;
// a second pendulum; a scenario with its plot) — opened in a new page of the lab under test, whose status
// must then be what the link asked for, and whose URL (rewritten by the page from its state) must still
// carry the plot and the second pendulum.
import { execFileSync } from 'node:child_process';

const PY = process.env.PY ?? '../.venv/bin/python';

/** The site's links as [{ where, query }] (tools/lab_links.py, run by the project's Python). */
function siteLinks() {
  return JSON.parse(execFileSync(PY, ['../tools/lab_links.py'], { encoding: 'utf-8' }));
}

export async function checkDocLinks(page, { check, WAIT }) {
  const links = siteLinks();
  const pick = (test) => links.find((l) => test(new URLSearchParams(l.query)));
  const sample = [
    pick((q) => q.has('x') && q.has('plot')),
    pick((q) => q.has('twin')),
    pick((q) => q.has('s') && q.has('plot') && q.get('s') !== 'rosette'),
  ].filter(Boolean);
  check(sample.length === 3, `a sample of ${sample.length} of the ${links.length} site links (${sample.map((l) => l.where).join(', ')})`);
  const base = page.url().split('?')[0];
  for (const { where, query } of sample) {
    const q = new URLSearchParams(query);
    const page2 = await page.context().newPage();
    try {
      await page2.goto(`${base}?${query}`, { timeout: WAIT });
      await page2.waitForFunction(
        (want) => {
          const s = window.pendulab?.store.status;
          if (!s || (want.s && s.scenario !== want.s) || (want.model && s.model !== want.model)) return false;
          return window.pendulab.store.frames.length > 2;
        },
        { s: q.get('s'), model: q.get('model') },
        { timeout: WAIT },
      );
      if (q.has('twin')) await page2.waitForFunction(() => (window.pendulab.twin?.trajectory.length ?? 0) > 2, null, { timeout: WAIT });
      await page2.waitForTimeout(500); // the page rewrites its URL from its state
      const got = await page2.evaluate(() => ({ s: window.pendulab.store.status, search: window.location.search }));
      const now = new URLSearchParams(got.search);
      const problems = [];
      if (q.has('s') && got.s.scenario !== q.get('s')) problems.push(`scenario ${got.s.scenario}`);
      if (q.has('model') && got.s.model !== q.get('model')) problems.push(`model ${got.s.model}`);
      if (q.has('method') && got.s.method !== q.get('method')) problems.push(`method ${got.s.method}`);
      if (q.has('l') && got.s.params.length !== Number(q.get('l'))) problems.push(`l ${got.s.params.length}`);
      if (q.has('x')) {
        const want = q.get('x').split(',').map(Number);
        if (want.some((c, i) => Math.abs(c - got.s.start.x[i]) > 1e-12)) problems.push(`start x ${got.s.start.x}`);
      }
      if (q.has('plot') && now.get('plot') !== q.get('plot')) problems.push(`plot ${now.get('plot')}`);
      if (q.has('twin') && now.get('twin') !== q.get('twin')) problems.push(`twin ${now.get('twin')}`);
      check(problems.length === 0, `the site's link of ${where} (?${query}) opens the lab in its set-up${problems.length ? ': ' + problems.join(', ') : ''}`);
    } finally {
      await page2.close();
    }
  }
}
