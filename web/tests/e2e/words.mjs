// End-to-end check of the page's languages (issue 28: "German and French complete"), run by smoke.mjs: the
// lab opened in English, German and French with every lil-gui folder open; every text of the page — text
// nodes (the help dialog and folded parts too), tooltips, aria-labels, placeholders, picker options — is
// collected, and no text of the German or French page may be one of the English page's, except the
// words that are the same in that language (SAME: names, symbols, cognates). So a scenario title, a model
// description, a region's label or a server message left in English fails here. Then a value the server
// refuses (a length of −1 m) is explained in German from the server's message key (messages.json), one
// the core refuses (a state off the sphere) in German and French from the core's key, and a rarer refusal
// (an unknown model) in German and French from its key.
const SAME = {
  de: ['Deutsch', 'English', 'Français', 'Jupiter (24.79 m/s²)', 'Mars (3.71 m/s²)', 'API', 'Esc', 'Tab', 'Integrator', 'Pause', 'rad', 'ZVD'],
  fr: ['Deutsch', 'English', 'Français', 'Jupiter (24.79 m/s²)', 'Mars (3.71 m/s²)', 'API', 'Esc', 'Tab', 'Pause', 'rad', 'Simple', 'angle θ [°]', 'distance |x| [m]', 'tension T [N]', 'amplitude', 'axes', 'exact', 'tension', 'tension max', 'tension min', 'ZVD'],
};

/** Every text of the page in language `lang` (a new page; closed after), with scenario `scenario` when given. */
async function pageTexts(page, lang, WAIT, scenario = null) {
  const p = await page.context().newPage();
  await p.goto(`${page.url().split("?")[0]}?lang=${lang}${scenario ? `&s=${scenario}` : ''}`, { timeout: WAIT }); // the server's root or the one-file lab's file:// URL
  await p.waitForFunction(() => (window.pendulab?.store.frames.length ?? 0) > 5, null, { timeout: WAIT });
  await p.evaluate(() => {
    for (const t of document.querySelectorAll('#gui .lil-gui.lil-closed > .lil-title')) t.click();
  });
  await p.waitForTimeout(1000);
  const texts = await p.evaluate(() => {
    const out = new Set();
    const w = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
    while (w.nextNode()) out.add(w.currentNode.textContent.trim());
    for (const el of document.querySelectorAll('[title], [aria-label], [placeholder]')) for (const a of ['title', 'aria-label', 'placeholder']) out.add((el.getAttribute(a) ?? '').trim());
    return [...out].filter((s) => /[A-Za-z]{3}/.test(s));
  });
  return { p, texts };
}

export async function checkWords(page, { check, WAIT }) {
  const en = await pageTexts(page, 'en', WAIT);
  await en.p.close();
  const english = new Set(en.texts);
  for (const lang of ['de', 'fr']) {
    const { p, texts } = await pageTexts(page, lang, WAIT);
    const left = texts.filter((s) => english.has(s) && !SAME[lang].includes(s));
    check(left.length === 0 && texts.length > 200, `${lang}: none of the page's ${texts.length} texts is left in English${left.length ? ': ' + left.slice(0, 8).map((s) => JSON.stringify(s.slice(0, 60))).join(', ') : ''}`);
    if (lang === 'de') {
      // both engines key the refusal (the in-page one as the server: crates/pendulab-wasm/src/refusal.rs)
      await p.evaluate(() => window.pendulab.send({ type: 'set_params', length: -1 }));
      await p.waitForFunction(() => /mindestens/.test(document.getElementById('message').textContent), null, { timeout: WAIT });
      const said = await p.evaluate(() => document.getElementById('message').textContent);
      // the parameter named in German, no command code name (set_params) before it
      check(/^Länge l = -1: mindestens 0.001 erlaubt$/.test(said.trim()), `a refused value in German, from the server's message key: "${said}"`);
      // a link with a value the page cannot read: said in German (the value itself as the link has it)
      const odd = await page.context().newPage();
      await odd.goto(`${page.url().split('?')[0]}?lang=de&at=gestern`, { timeout: WAIT });
      const link = await odd
        .waitForFunction(() => /aus dem Link weggelassen/.test(document.getElementById('message').textContent) && document.getElementById('message').textContent, null, { timeout: WAIT })
        .then((h) => h.jsonValue(), () => odd.evaluate(() => document.getElementById('message').textContent));
      check(/^aus dem Link weggelassen: at = "gestern" ist keine endliche Zahl$/.test(link.trim()), `a link's unreadable value is reported in German: "${link}"`);
      await odd.close();
    }
    // a command the core refuses (a state off the sphere): worded from the core's message key, as the server's
    const sphere = { de: 'der Start liegt nicht auf der Kugel: (|x| - l)/l = -0.2928932188134524 überschreitet die Toleranz 1e-9', fr: 'le départ n’est pas sur la sphère : (|x| - l)/l = -0.2928932188134524 dépasse la tolérance 1e-9' }[lang];
    await p.evaluate(() => window.pendulab.send({ type: 'set_state', x: [0.5, 0, -0.5], v: [0, 0, 0], project: false }));
    const core = await p
      .waitForFunction((w) => document.getElementById('message').textContent.trim() === w && w, sphere, { timeout: WAIT })
      .then((h) => h.jsonValue(), () => p.evaluate(() => document.getElementById('message').textContent));
    check(core.trim() === sphere, `${lang}: a refusal of the core in the page's language, from its message key: "${core.trim()}"`);
    // a rarer refusal (an unknown model): keyed too, so worded in the page's language
    const unknown = { de: 'unbekanntes Modell sprung; verfügbar: ', fr: 'modèle inconnu sprung ; disponibles : ' }[lang];
    await p.evaluate(() => window.pendulab.send({ type: 'set_model', model: 'sprung' }));
    const rare = await p
      .waitForFunction((w) => document.getElementById('message').textContent.trim().startsWith(w) && document.getElementById('message').textContent, unknown, { timeout: WAIT })
      .then((h) => h.jsonValue(), () => p.evaluate(() => document.getElementById('message').textContent));
    check(rare.trim().startsWith(unknown), `${lang}: an unknown model in the page's language, from its message key: "${rare.trim()}"`);
    await p.close();
  }
  // the scenarios whose notes and rows differ from the rosette's (issue 28): a damped model (its own parameters,
  // the exact solution's and the reduced view's notes naming the model), a planar swing (no phases: the
  // server's note is English, the page words it from the orbit's kind) and the crane mode (its error row)
  for (const scenario of ['damped', 'planar_large', 'crane_hoist']) {
    const en = await pageTexts(page, 'en', WAIT, scenario);
    await en.p.close();
    const english = new Set(en.texts);
    for (const lang of ['de', 'fr']) {
      const { p, texts } = await pageTexts(page, lang, WAIT, scenario);
      await p.close();
      const left = texts.filter((s) => english.has(s) && !SAME[lang].includes(s));
      const server = texts.filter((s) => /phases are defined|phases need gravity|no estimate: the crane|this is the model/.test(s));
      check(left.length === 0 && server.length === 0, `${lang}, scenario ${scenario}: none of the page's ${texts.length} texts is left in English${[...left, ...server].length ? ': ' + [...left, ...server].slice(0, 6).map((s) => JSON.stringify(s.slice(0, 60))).join(', ') : ''}`);
    }
  }
}
