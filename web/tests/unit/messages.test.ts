// The server's keyed messages (python/pendulab/server/messages.json) and the shipped scenarios in every
// language (issue 28): the English table's `server.<key>` is the JSON's words, every language has every key
// with the same placeholders, a keyed notice is parsed and shown in the page's language, and each scenario
// file of python/pendulab/examples/scenarios has a title in every table.
import { describe, expect, it } from 'vitest';
import messages from '../../../python/pendulab/server/messages.json';
import { LANGUAGES, httpProblem, paramWords, scenarioWords, serverWords, setLanguage } from '../../src/i18n';
import { CRANE_WORDS } from '../../src/i18n/cranewords';
import { EN } from '../../src/i18n/en';
import { parseNotice } from '../../src/protocol';

const holes = (s: string) => [...s.matchAll(/\{(\w+)\}/g)].map((m) => m[1]).sort();
const keys = Object.keys(messages).filter((k) => !k.startsWith('_'));

describe('server messages', () => {
  it('the English table says what messages.json says; every language has every key and placeholder', () => {
    expect(keys.length).toBeGreaterThan(8);
    for (const k of keys) {
      const words = (messages as Record<string, string>)[k] as string;
      expect(EN[`server.${k}` as keyof typeof EN]).toBe(words);
      for (const { words: table } of Object.values(LANGUAGES)) expect(holes(table[`server.${k}` as keyof typeof EN])).toEqual(holes(words));
    }
  });

  it('a keyed notice is shown in the page language; an unkeyed or unknown one as the server wrote it', () => {
    const n = parseNotice(JSON.stringify({ type: 'error', message: 'length = -1: input should be ≥ 0.001', command: 'set_params', key: 'too_small', values: { name: 'length', value: '-1', limit: 0.001 } }));
    expect(n.type === 'error' && n.key).toBe('too_small');
    if (n.type !== 'error') return;
    setLanguage('de');
    expect(serverWords(n)).toBe('Länge l = -1: mindestens 0.001 erlaubt');
    setLanguage('fr');
    expect(serverWords(n)).toBe('longueur l = -1 : au moins 0.001');
    expect(serverWords({ message: 'something new', key: 'no_such_key', values: {} })).toBe('something new');
    expect(serverWords({ message: 'plain' })).toBe('plain');
    // values that are not strings or numbers: the key is dropped, the English message kept
    const odd = parseNotice(JSON.stringify({ type: 'error', message: 'm', command: null, key: 'missing', values: { name: { x: 1 } } }));
    expect(odd.type === 'error' && odd.key).toBe(undefined);
    setLanguage('en');
  });
});

describe("the core's refusals in a lab session", () => {
  it('a command the core refuses (a state off the sphere, a parameter out of range) in en, de and fr', () => {
    // as the server and the in-page engine send them (LiveSession::error_out): the core's English words, its key
    const sphere = parseNotice(JSON.stringify({ type: 'error', message: 'state is not on TS² (|x| = l, x·v = 0): (|x| - l)/l = -0.2929 exceeds the tolerance 1e-9; pass project=True to move it onto TS²', command: 'set_state', key: 'off_sphere', values: { what: '(|x| - l)/l', value: '-0.2929', tolerance: '1e-9' } }));
    const damping = parseNotice(JSON.stringify({ type: 'error', message: 'invalid damping = -1: a number in [0, 100] 1/s', command: 'set_model', key: 'invalid_parameter', values: { name: 'damping', value: '-1', allowed: 'a number in [0, 100] 1/s' } }));
    if (sphere.type !== 'error' || damping.type !== 'error') throw new Error('not error notices');
    const words = (lang: 'en' | 'de' | 'fr') => {
      setLanguage(lang);
      return [serverWords(sphere), serverWords(damping)];
    };
    expect(words('en')).toEqual(['the start is not on the sphere: (|x| - l)/l = -0.2929 exceeds the tolerance 1e-9', 'damping = -1 is not allowed: a number in [0, 100] 1/s']);
    const [de, deDamping] = words('de');
    expect(de).toBe('der Start liegt nicht auf der Kugel: (|x| - l)/l = -0.2929 überschreitet die Toleranz 1e-9');
    expect(deDamping).toBe('Reibung (lineare Dämpfung) c = -1 ist nicht erlaubt: a number in [0, 100] 1/s'); // the allowed range stays English
    const [fr, frDamping] = words('fr');
    expect(fr).toBe('le départ n’est pas sur la sphère : (|x| - l)/l = -0.2929 dépasse la tolérance 1e-9');
    expect(frDamping).toMatch(/ = -1 n’est pas permis : a number in \[0, 100\] 1\/s$/);
    setLanguage('en');
  });
});

describe('HTTP error answers', () => {
  it('a keyed answer (busy, time limit, device busy) in the page language; an unkeyed one as the server wrote it', () => {
    const busy = { detail: 'busy: 8 computations are waiting; try again in a moment', key: 'busy', values: { waiting: 8 } };
    const timeout = { detail: 'the computation took longer than 60 s …', key: 'work_timeout', values: { seconds: '60' } };
    setLanguage('de');
    expect(httpProblem(busy, 'HTTP 503')).toBe('beschäftigt: 8 Berechnungen warten schon; gleich noch einmal versuchen');
    expect(httpProblem(timeout, 'HTTP 503')).toContain('länger als 60 s');
    setLanguage('fr');
    expect(httpProblem({ detail: 'x', key: 'device_busy', values: { most: 2 } }, 'HTTP 429')).toContain('au plus 2');
    expect(httpProblem({ detail: 'row 3: not a number' }, 'HTTP 422')).toBe('row 3: not a number');
    // a data file's bad cell and a fit setting, keyed by the server (pendulab.fitting.keyed)
    const cell = { detail: "bad.csv: row 2 (line 3), column 'x': 'oops' is not a number", key: 'data_not_number', values: { file: 'bad.csv', row: 2, line: 3, column: "'x'", cell: "'oops'" } };
    expect(httpProblem(cell, 'HTTP 422')).toBe("bad.csv : ligne 2 (ligne 3 du fichier), colonne 'x' : 'oops' n’est pas un nombre");
    setLanguage('de');
    expect(httpProblem(cell, 'HTTP 422')).toBe("bad.csv: Zeile 2 (Zeile 3 der Datei), Spalte 'x': 'oops' ist keine Zahl");
    expect(httpProblem({ detail: 'x', key: 'fit_cannot_fit', values: { param: 'colour', model: 'damped', allowed: 'length, g' } }, 'HTTP 422')).toBe(
      'colour lässt sich mit dem Modell Gedämpft und angetrieben nicht anpassen; wählbar sind length, g',
    );
    expect(httpProblem({ detail: 'x', key: 'worker_died', values: { code: '-9' } }, 'HTTP 500')).toContain('Exit-Code -9');
    setLanguage('fr');
    expect(httpProblem({}, 'HTTP 500')).toBe('HTTP 500');
    expect(httpProblem(null, 'HTTP 502')).toBe('HTTP 502');
    setLanguage('en');
    expect(httpProblem(busy, 'HTTP 503')).toBe(busy.detail);
  });

  it("the core's common refusals (diverged, pole, off the sphere, a bad parameter) in the page language", () => {
    const diverged = { detail: 'the integration diverged …', key: 'diverged', values: { t: '20', method: 'rk4', dt: '10' } };
    const pole = { detail: 'x', key: 'near_pole', values: { t: '0.5' } };
    const length = { detail: 'x', key: 'invalid_parameter', values: { name: 'length', value: '-1', allowed: 'a number in [1e-6, 1e4] m' } };
    setLanguage('de');
    expect(httpProblem(diverged, 'HTTP 422')).toBe('die Integration ist nach t = 20 s mit dem Verfahren rk4 divergiert (dt = 10 s): dt verkleinern oder ein adaptives (dop853) oder strukturerhaltendes (rattle) Verfahren wählen');
    expect(httpProblem(pole, 'HTTP 422')).toContain('bei t = 0.5 s einen Pol');
    expect(httpProblem(length, 'HTTP 422')).toMatch(/^Länge.* = -1 ist nicht erlaubt/);
    setLanguage('fr');
    expect(httpProblem(diverged, 'HTTP 422')).toContain('après t = 20 s avec la méthode rk4');
    expect(httpProblem({ detail: 'x', key: 'off_sphere', values: { what: '(|x| - l)/l', value: '-0.2929', tolerance: '1e-9' } }, 'HTTP 422')).toContain('pas sur la sphère');
    expect(httpProblem({ detail: 'x', key: 'step_too_small', values: { t: '3', h: '1e-15' } }, 'HTTP 422')).toContain('trop petit à t = 3 s');
    const fault = { detail: 'x', key: 'internal_error', values: { detail: "KeyError: 'q'" } };
    expect(httpProblem(fault, 'HTTP 500')).toBe("erreur interne du serveur (un défaut du logiciel : merci de le signaler) ; détails (en anglais) : KeyError: 'q'");
    setLanguage('de');
    expect(httpProblem(fault, 'HTTP 500')).toMatch(/^interner Fehler des Servers .*bitte melden\); Details \(englisch\): KeyError: 'q'$/);
    const stopped = { type: 'error' as const, message: 'x', key: 'integration_stopped', values: { detail: 'the integration diverged…', why: 'diverged', t: '2.5', method: 'rk4', dt: '0.05' } };
    expect(serverWords(stopped)).toBe('die Rechnung ist stehen geblieben (die Integration ist nach t = 2.5 s mit dem Verfahren rk4 divergiert (dt = 0.05 s): dt verkleinern oder ein adaptives (dop853) oder strukturerhaltendes (rattle) Verfahren wählen); angehalten');
    setLanguage('fr');
    expect(serverWords({ ...stopped, values: { detail: 'step size underflow…', why: 'step_too_small', t: '3', h: '1e-15' } })).toContain('(le pas est devenu trop petit à t = 3 s');
    expect(serverWords({ ...stopped, values: { detail: 'English words', why: 'unknown_kind' } })).toBe('le calcul s’est arrêté (English words) ; en pause');
    setLanguage('en');
    expect(httpProblem(diverged, 'HTTP 422')).toBe('the integration diverged after t = 20 s with method rk4 (dt = 10 s): reduce dt, or choose an adaptive (dop853) or structure-preserving (rattle) method');
  });
});

describe('advice and rarer refusals in every language', () => {
  it('a divergence gives the advice for the method that diverged: a diverged rattle is not told to use rattle', () => {
    const stopped = (why: string, method: string) => ({ type: 'error' as const, message: 'x', key: 'integration_stopped', values: { detail: 'English', why, t: '1', method, dt: '0.1' } });
    const words = (lang: 'en' | 'de' | 'fr') => {
      setLanguage(lang);
      return [serverWords(stopped('diverged_rattle', 'rattle')), serverWords(stopped('diverged_dop853', 'dop853')), serverWords(stopped('diverged_dt', 'string'))];
    };
    const [enRattle, enDop, enString] = words('en');
    expect(enRattle).toBe('the computation stopped (the integration diverged after t = 1 s with method rattle (dt = 0.1 s): reduce dt (the step must resolve the fastest motion, dt·ω ≪ 1)); paused');
    expect(enDop).toContain(': lower rtol and atol, or choose the structure-preserving rattle)');
    expect(enString).toContain('(dt = 0.1 s): reduce dt)');
    const [deRattle, deDop, deString] = words('de');
    expect(deRattle).toBe('die Rechnung ist stehen geblieben (die Integration ist nach t = 1 s mit dem Verfahren rattle divergiert (dt = 0.1 s): dt verkleinern (der Schritt muss die schnellste Bewegung auflösen, dt·ω ≪ 1)); angehalten');
    expect(deDop).toContain('rtol und atol verkleinern');
    expect(deString).toContain('(dt = 0.1 s): dt verkleinern)');
    const [frRattle, frDop] = words('fr');
    expect(frRattle).toContain('réduire dt (le pas doit résoudre le mouvement le plus rapide, dt·ω ≪ 1)');
    expect(frDop).toContain('réduire rtol et atol');
    for (const w of [deRattle, frRattle]) expect(w).not.toMatch(/\(rattle\)/);
    setLanguage('en');
  });

  it('an unknown model or parameter, an offline model and too many waiting steps in de and fr', () => {
    const n = (key: string, values: Record<string, string>) => ({ message: 'English', key, values });
    setLanguage('de');
    expect(serverWords(n('unknown_model', { model: 'sprung', available: 'ideal, damped' }))).toBe('unbekanntes Modell sprung; verfügbar: ideal, damped');
    expect(serverWords(n('still_stepping', { waiting: '1000000', most: '1000000' }))).toBe('es wird noch gerechnet: 1000000 Schritte warten (höchstens 1000000); auf das Bild warten oder pausieren');
    expect(serverWords(n('no_parameters', { model: 'ideal', name: 'damping' }))).toMatch(/hat keinen Parameter .*; es hat keine außer Länge, Masse, g$/);
    setLanguage('fr');
    expect(serverWords(n('unknown_parameter', { model: 'damped', name: 'latitude', available: 'damping, amplitude' }))).toMatch(/n’a pas de paramètre .* ; ses paramètres : damping, amplitude$/);
    expect(serverWords(n('not_lab_model', { model: 'sampled_pivot', available: 'ideal' }))).toMatch(/ne tourne pas dans le labo \(utiliser pendulab run\) ; les modèles du labo : ideal$/);
    setLanguage('en');
  });

  it('another model\'s parameter names the models that have it, each in the page\'s words', () => {
    // as pl.Pendulum words it (python/pendulab/model/registry.py Elsewhere); the models as the menu names them
    const n = (key: string, values: Record<string, string>) => ({ message: 'English', key, values });
    const one = n('parameter_of_other_model', { model: 'damped', name: 'latitude', owner: 'rotating', available: 'length, mass, g, damping' });
    const many = n('parameter_of_other_models', { model: 'ideal', name: 'damping', owner: 'damped', others: 'rotating, slewing', available: 'length, mass, g' });
    expect(serverWords(one)).toBe("latitude is a parameter of model rotating, not of damped; its parameters: length, mass, g, damping");
    setLanguage('de');
    expect(serverWords(many)).toBe(`${paramWords('damping', 'damping', '')[0]} ist ein Parameter des Modells Gedämpft und angetrieben (und Auf der drehenden Erde (Foucault), Drehkran), nicht von Ideales Pendel; seine Parameter: length, mass, g`);
    setLanguage('fr');
    expect(serverWords(one)).toMatch(/ est un paramètre du modèle Sur la Terre qui tourne \(Foucault\), pas de Amorti et forcé ; ses paramètres : length, mass, g, damping$/);
    expect(serverWords(one)).not.toMatch(/\{/);
    setLanguage('en');
  });

  it('an unknown method, with the nearest name when there is one, in de and fr', () => {
    // as the server's command check and the in-page engine key it (live::wire::unknown_method): English alone before
    const n = (key: string, values: Record<string, string>) => ({ message: 'English', key, values });
    const available = 'rattle, rattle4, dop853';
    const hint = n('unknown_method_hint', { method: 'RATTLE', nearest: 'rattle', available });
    const none = n('unknown_method', { method: 'euler', available });
    expect(serverWords(hint)).toBe('unknown method RATTLE (did you mean rattle?); available: rattle, rattle4, dop853');
    setLanguage('de');
    expect(serverWords(hint)).toBe('unbekanntes Verfahren RATTLE (vielleicht rattle?); verfügbar: rattle, rattle4, dop853');
    expect(serverWords(none)).toBe('unbekanntes Verfahren euler; verfügbar: rattle, rattle4, dop853');
    setLanguage('fr');
    expect(serverWords(hint)).toBe('méthode inconnue RATTLE (rattle peut-être ?) ; disponibles : rattle, rattle4, dop853');
    expect(serverWords(none)).toBe('méthode inconnue euler ; disponibles : rattle, rattle4, dop853');
    setLanguage('en');
  });

  it('a method the model does not run (its reason for that model) and a crane command outside the crane mode', () => {
    // as the core sends them (crates/pendulab-core/src/live: method_refused, LiveSession::crane); plain English before
    const n = (key: string, values: Record<string, string>) => ({ message: 'English', key, values });
    const spring = n('method_not_for_spring', { method: 'dop853', model: 'spring', available: 'rattle, rattle4' });
    const string = n('method_not_for_string', { method: 'rk4', model: 'string', available: 'rattle, rkmk4' });
    const crane = n('method_not_for_crane', { method: 'rattle', model: 'crane', available: 'dop853' });
    const notCrane = n('not_crane', { model: 'ideal' });
    const words = (lang: 'en' | 'de' | 'fr') => {
      setLanguage(lang);
      return [serverWords(spring), serverWords(string), serverWords(crane), serverWords(notCrane)];
    };
    const en = words('en');
    expect(en[0]).toBe('method dop853 cannot run the spring model (it leaves the sphere: rattle runs Störmer–Verlet (order 2), rattle4 its triple jump (order 4)); use one of rattle, rattle4');
    expect(en[3]).toBe('not in the crane mode (the lab runs the ideal model): switch it on first with the button “Crane mode”');
    const de = words('de');
    expect(de[0]).toBe('das Verfahren dop853 kann das Modell Schwingfeder nicht rechnen (es verlässt die Kugel: rattle rechnet Störmer–Verlet (Ordnung 2), rattle4 dessen Triple-Jump-Komposition (Ordnung 4)); eines von rattle, rattle4 wählen');
    expect(de[1]).toMatch(/^das Verfahren rk4 kann das Modell .* nicht rechnen \(seine straffen Phasen brauchen ein Verfahren mit festem Schritt, das TS² einhält\); eines von rattle, rkmk4 wählen$/);
    expect(de[2]).toMatch(/\(der Kranmodus rechnet seine Last mit dem Kran-Integrator, .*\); dop853 wählen$/);
    const fr = words('fr');
    expect(fr[1]).toMatch(/^la méthode rk4 ne peut pas calculer le modèle .* \(ses phases tendues demandent une méthode à pas fixe qui préserve TS²\) ; choisir parmi rattle, rkmk4$/);
    expect(fr[2]).toContain('(le mode grue calcule sa charge avec l’intégrateur de grue');
    // the crane's refusal names the button that switches the crane mode on, as the crane panel labels it
    for (const [lang, said] of [['en', en[3]], ['de', de[3]], ['fr', fr[3]]] as const) expect(said).toContain(CRANE_WORDS[lang].on);
    expect(de[3]).toMatch(/^nicht im Kranmodus \(das Labor rechnet das Modell .+\): ihn zuerst mit der Schaltfläche „Kranmodus“ einschalten$/);
    expect(fr[3]).toMatch(/^pas en mode grue \(le labo calcule le modèle .+\) : l’activer d’abord avec le bouton « Mode grue »$/);
    for (const said of [...de, ...fr]) expect(said).not.toMatch(/cannot run|not in the crane|\{/);
    setLanguage('en');
  });
});

describe('scenario titles', () => {
  it('every shipped scenario has its title in every language', () => {
    const files = import.meta.glob('../../../python/pendulab/examples/scenarios/*.toml', {
      query: '?raw',
      import: 'default',
      eager: true,
    }) as Record<string, string>;
    // crane files ([crane]) too: the lab opens them in its crane mode
    const names = Object.keys(files).map((f) => f.replace(/^.*\//, '').slice(0, -5));
    expect(names.length).toBeGreaterThan(10);
    for (const lang of Object.keys(LANGUAGES) as (keyof typeof LANGUAGES)[]) {
      setLanguage(lang);
      for (const n of names) {
        expect(Object.hasOwn(LANGUAGES[lang].words, `scenario.${n}`), `${lang}: scenario.${n}`).toBe(true);
        expect(scenarioWords(n, null)).not.toBe(n);
      }
    }
    setLanguage('en');
  });
});
