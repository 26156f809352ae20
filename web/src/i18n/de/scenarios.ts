// The page's German (Deutsch) words, scenarios: the shipped scenarios' titles, the models' one-line help, the
// names of keys in the help overlay, the simple view's button and pendulums 3 and 4. The same keys as
// ../en/scenarios.ts (the type `ScenariosWords` enforces every one). docs/web.md, "Languages".
import type { ScenariosWords } from '../en/scenarios';

export const DE_SCENARIOS: ScenariosWords = {
  'scenario.conical': 'Kegelpendel bei 45°',
  'scenario.damped': 'Gedämpfte Rosette (c = 0.05 1/s)',
  'scenario.foucault': 'Foucault-Pendel bei 49° N, Erddrehung übertrieben (Ω = 0.02 rad/s)',
  'scenario.inverted_g': 'Umgekehrte Schwerkraft: die Rosette gespiegelt',
  'scenario.near_top': 'Knapp unter dem höchsten Punkt losgelassen',
  'scenario.over_the_top': 'Über Kopf: ebene Überschläge',
  'scenario.planar_large': 'Ebene Schwingung mit 150° Amplitude',
  'scenario.rosette': 'Rosette: bei 60° mit seitlichem Schwung losgelassen',
  'scenario.crane_hoist': 'Portalkran: ZV-geformte 8-m-Fahrt beim Heben von 12 m auf 6 m, bei Seitenwind',
  'scenario.slewing_crane': 'Drehkran: R = 5 m, ω = 0.3 rad/s, l = 10 m',
  'scenario.small_ellipse': 'Kleine Ellipse mit Airy-Präzession',
  'scenario.string_slack': 'Pendel an einer Schnur: schlaff bei z = l/2, unelastischer Ruck',
  'scenario.swinging_spring': 'Schwingfeder in der 1:1:2-Resonanz',
  'scenario.zero_g': 'Schwerelos: ein Großkreis',
  'modelHelp.ideal': 'eine Stange ohne Reibung: das Pendel aus dem Lehrbuch',
  'modelHelp.damped': 'mit Reibung, Luftwiderstand oder periodischem Antrieb',
  'modelHelp.rotating': 'von der sich drehenden Erde aus gesehen: die Schwingebene dreht sich (Foucault)',
  'modelHelp.slewing': 'am Ausleger eines sich drehenden Krans',
  'modelHelp.vibrating': 'der Aufhängepunkt wird auf und ab gerüttelt: es kann kopfüber stehen (Kapitza)',
  'modelHelp.sampled_pivot': 'der Aufhängepunkt bewegt sich auf einer vorgegebenen Bahn',
  'modelHelp.spring': 'eine Feder statt einer Stange: es schwingt und federt',
  'modelHelp.string': 'eine Schnur statt einer Stange: sie kann schlaff werden und sich ruckartig spannen',
  'key.space': 'Leertaste',
  'key.page': 'Bild ↑ / Bild ↓',
  'key.shift': 'Umschalt',
  'toolbar.simpleShort': 'Einfach',
  'toolbar.simple': 'einfache Ansicht: nur die Werkzeuge für den Unterricht (Länge, Masse, Schwerkraft, Reibung, Stoppuhr, Periode, Lineal, Energie); noch einmal drücken für alles',
  'extras.add': '+ noch ein Pendel (eigene Länge, Masse, Start)',
  'extras.pendulum': 'Pendel {n}',
  'extras.remove': 'Pendel {n} entfernen',
  'extras.title': 'Bis zu vier Pendel',
  'extras.hint': 'Mit dem zweiten Pendel auf „eigene Länge, Masse und Start“: Pendel 3 und 4 hinzufügen, dann startet „beide starten“ alle, jedes mit seiner eigenen Periodenmessung.',
};
