// The fit report in every language (issue 28; python/pendulab/server/fit_words.py): the English table says what
// fit_words.json says, every language words every key with the same placeholders, a keyed line is shown in
// the page's language with its code names worded (no `theta_dot0`), and a line without a known key as the
// server's English text.
import { describe, expect, it } from 'vitest';
import words from '../../../python/pendulab/server/fit_words.json';
import { setLanguage } from '../../src/i18n';
import { FIT_WORDS, fitLine, fitParamLine, fitReportLines } from '../../src/i18n/fitwords';

const holes = (s: string) => [...s.matchAll(/\{(\w+)\}/g)].map((m) => m[1]).sort();
const keys = Object.keys(words).filter((k) => !k.startsWith('_'));

describe('fit words', () => {
  it('the English table says what fit_words.json says; every language has every key and placeholder', () => {
    expect(keys.length).toBeGreaterThan(25);
    for (const k of keys) {
      const en = (words as Record<string, string>)[k] as string;
      expect(FIT_WORDS.en[k]).toBe(en);
      for (const table of Object.values(FIT_WORDS)) expect(holes(table[k] ?? '')).toEqual(holes(en));
    }
    const own = Object.keys(FIT_WORDS.en).sort();
    for (const table of Object.values(FIT_WORDS)) expect(Object.keys(table).sort()).toEqual(own);
  });

  it('a misfit warning is German on a German page, with the data kind worded', () => {
    const note = { key: 'systematicDrift', values: { kind: 'positions', rms: '0.00342', ratio: '2.25', floor: '0.00152' }, text: 'positions: the fit misses…' };
    setLanguage('de');
    expect(fitLine(note)).toMatch(/^Positionen: die Anpassung verfehlt die Daten systematisch, mit einer langsamen Drift: die Abweichungen \(rms 0\.00342\) sind 2\.25-mal/);
    setLanguage('fr');
    expect(fitLine(note)).toMatch(/^positions : l’ajustement manque les données systématiquement/);
    setLanguage('en');
    expect(fitLine(note)).toMatch(/^positions: the fit misses the data systematically, with a slow drift/);
    // unknown or missing key: the server's English words
    expect(fitLine({ key: 'somethingNew', values: {}, text: 'a new warning' })).toBe('a new warning');
    expect(fitLine({ key: null, values: {}, text: 'unkeyed' })).toBe('unkeyed');
  });

  it('the clauses of a warning (the band scan, the damping law) follow its words in the language of the page', () => {
    const band = { key: 'bandPower', values: { hz: '0.55', ratio: '5', p: '6.5e-08' } };
    const note = { key: 'systematic', values: { kind: 'angles', rms: '0.004', ratio: '1.6', floor: '0.0025' }, clauses: [band] };
    setLanguage('de');
    expect(fitLine(note)).toMatch(/korreliert; bei 0\.55 Hz haben die Abweichungen das 5-Fache der Leistung ihres übrigen Spektrums \(p = 6\.5e-08\)/);
    const law = { key: 'blocksDisagree', values: { n: '4', param: 'damping', values: '0.01, 0.012 1/s', scale: '9' }, clauses: [{ key: 'dampingDry', values: { param: 'friction' } }] };
    setLanguage('fr');
    expect(fitLine(law)).toMatch(/ ; l’amortissement ajusté à chaque partie croît .* frottement sec : ajuster aussi \S/);
    expect(fitLine(law)).not.toMatch(/\{param\}/);
    setLanguage('en');
    expect(fitLine(law)).toMatch(/widened for it; the damping fitted to each part grows .*as dry friction makes: fit \S/);
    // a clause the table does not know is left out (the English text has it)
    expect(fitLine({ ...note, clauses: [{ key: 'somethingNew', values: {} }] })).not.toMatch(/somethingNew/);
  });

  it('names the parameters in student words and says why one is not determined', () => {
    setLanguage('de');
    const lines = fitReportLines(
      [
        { key: 'header', values: { model: 'ideal', samples: '600', kinds: 'positions', t0: '0' } },
        { key: 'combinationValue', values: { label: 'g/length', value: '15.8', err: '0.1' } },
        { key: 'chi2Estimated', values: { chi2: '1192', dof: '1192', reduced: '1' } },
      ],
      {
        theta_dot0: { value: 0.0789, stderr: 1.24, unit: 'rad/s', determined: true },
        phi0: { value: 0, stderr: null, unit: 'rad', determined: false, reason: { key: 'combination', values: { others: 'phi_dot0, g' } } },
      },
    );
    expect(lines[0]).toBe('Anpassung des Modells „ideales Pendel“ an 600 Messwerte (Positionen), Beginn bei t = 0 s');
    expect(lines[1]).toBe('  Startgeschwindigkeit der Schwingung (Winkel pro Sekunde) = 0.0789000 ± 1.2 rad/s');
    expect(lines[2]).toMatch(/Startrichtung um die Senkrechte = 0\.00000 rad \(nicht bestimmt: die Daten bestimmen nur eine Kombination mit Startgeschwindigkeit um die Senkrechte .*, Schwerebeschleunigung g\)/);
    expect(lines[3]).toBe('  stattdessen bestimmt: Schwerebeschleunigung g/Länge l = 15.8 ± 0.1');
    expect(lines[4]).toMatch(/per Konstruktion 1/);
    expect(lines.join('\n')).not.toMatch(/theta_dot0|phi0|phi_dot0/);
    setLanguage('en');
    expect(fitParamLine('mass', { value: 1, stderr: null, unit: 'kg', determined: false })).toBe('mass m = 1.00000 kg (not determined)');
  });

  it("a short record's reason says, in the language of the page, how to fit it past the lab's time limit", () => {
    const clause = { key: 'stopTimeLimit', values: { seconds: '20' } };
    const length = { value: 0.4, stderr: null, unit: 'm', determined: false, reason: { key: 'shortRecord', values: { periods: '0.33' }, clauses: [clause] } };
    setLanguage('de');
    expect(fitParamLine('length', length)).toMatch(/enden nach 20 s, .*pendulab fit DATEI --time-limit none/);
    setLanguage('fr');
    expect(fitParamLine('length', length)).toMatch(/s’arrêtent après 20 s, .*pendulab fit FICHIER --time-limit none/);
    setLanguage('en');
    expect(fitParamLine('length', length)).toMatch(/does not determine it; the lab's fits stop after 20 s, .*pendulab fit FILE --time-limit none/);
  });
});
