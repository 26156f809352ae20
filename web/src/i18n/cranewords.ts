// The crane mode's words in the page's languages (docs/web.md, "Crane mode"; the language is the page's,
// index.ts), beside the page's and the fit report's tables. Every table has the English table's keys and
// every language of LANGUAGES has a table (the types say so). Units: SI (m, m/s, degrees shown for angles,
// which travel in rad).
import { fill, language } from './index';
import type { Lang } from './index';

const EN = {
  title: 'Crane',
  on: 'Crane mode',
  onHelp: 'a load on a hoisted rope below a trolley you drive (the core steps it; keys J L: trolley, I K: across)',
  off: 'Back to the pendulum',
  left: 'drive the trolley in −x (hold; key J)',
  right: 'drive the trolley in +x (hold; key L)',
  back: 'drive the crane in +y (hold; key I)',
  fwd: 'drive the crane in −y (hold; key K)',
  moveBy: 'move {d} m',
  moveHelp: 'move the trolley by {d} m along x and stop',
  stop: 'Stop',
  shaping: 'Command shaping',
  shapingHelp: 'the trolley’s command convolved with a shaper designed for the current rope (ZV: 2 impulses, ZVD: 3)',
  shapingOff: 'off',
  rope: 'Rope length (m)',
  ropeHelp: 'the hoist winds the rope to this length, live',
  wind: 'Wind speed (m/s)',
  windDir: 'Wind direction (°)',
  windHelp: 'steady wind on the load: drag ½ρ c_W A |w − v|(w − v)',
  sway: 'Sway angle',
  residual: 'Residual sway (largest in the last 10 s)',
  readout: 'Trolley at x = {x} m, y = {y} m · rope {l} m',
  predicted: 'Last move: residual sway {u}° without shaping, {s}° with {shaper} (linear theory)',
} as const;

export type CraneWord = keyof typeof EN;
type Table = Record<CraneWord, string>;

const DE: Table = {
  title: 'Kran',
  on: 'Kranmodus',
  onHelp: 'eine Last am Hubseil unter einer Laufkatze, die Sie fahren (der Kern rechnet; Tasten J L: Katze, I K: quer)',
  off: 'Zurück zum Pendel',
  left: 'Laufkatze in −x fahren (halten; Taste J)',
  right: 'Laufkatze in +x fahren (halten; Taste L)',
  back: 'Kran in +y fahren (halten; Taste I)',
  fwd: 'Kran in −y fahren (halten; Taste K)',
  moveBy: '{d} m fahren',
  moveHelp: 'die Laufkatze um {d} m in x fahren und anhalten',
  stop: 'Halt',
  shaping: 'Eingangsformung',
  shapingHelp: 'der Fahrbefehl gefaltet mit einem Shaper für die aktuelle Seillänge (ZV: 2 Impulse, ZVD: 3)',
  shapingOff: 'aus',
  rope: 'Seillänge (m)',
  ropeHelp: 'das Hubwerk wickelt das Seil live auf diese Länge',
  wind: 'Windgeschwindigkeit (m/s)',
  windDir: 'Windrichtung (°)',
  windHelp: 'stetiger Wind auf die Last: Widerstand ½ρ c_W A |w − v|(w − v)',
  sway: 'Pendelwinkel',
  residual: 'Restpendeln (größter Winkel der letzten 10 s)',
  readout: 'Laufkatze bei x = {x} m, y = {y} m · Seil {l} m',
  predicted: 'Letzte Fahrt: Restpendeln {u}° ohne Formung, {s}° mit {shaper} (lineare Theorie)',
};

const FR: Table = {
  title: 'Grue',
  on: 'Mode grue',
  onHelp: 'une charge au câble de levage sous un chariot que vous pilotez (le cœur calcule ; touches J L : chariot, I K : travers)',
  off: 'Retour au pendule',
  left: 'déplacer le chariot vers −x (maintenir ; touche J)',
  right: 'déplacer le chariot vers +x (maintenir ; touche L)',
  back: 'déplacer la grue vers +y (maintenir ; touche I)',
  fwd: 'déplacer la grue vers −y (maintenir ; touche K)',
  moveBy: 'avancer de {d} m',
  moveHelp: 'déplacer le chariot de {d} m selon x puis s’arrêter',
  stop: 'Arrêt',
  shaping: 'Mise en forme de la commande',
  shapingHelp: 'la commande du chariot convoluée avec un filtre conçu pour la longueur de câble actuelle (ZV : 2 impulsions, ZVD : 3)',
  shapingOff: 'sans',
  rope: 'Longueur du câble (m)',
  ropeHelp: 'le treuil enroule le câble jusqu’à cette longueur, en direct',
  wind: 'Vitesse du vent (m/s)',
  windDir: 'Direction du vent (°)',
  windHelp: 'vent constant sur la charge : traînée ½ρ c_W A |w − v|(w − v)',
  sway: 'Angle de balancement',
  residual: 'Balancement résiduel (le plus grand des 10 dernières s)',
  readout: 'Chariot en x = {x} m, y = {y} m · câble {l} m',
  predicted: 'Dernier déplacement : balancement résiduel {u}° sans mise en forme, {s}° avec {shaper} (théorie linéaire)',
};

export const CRANE_WORDS: Record<Lang, Table> = { en: EN, de: DE, fr: FR };

/** The crane word `key` in the page's language with each {name} replaced by vars[name]. */
export function cw(key: CraneWord, vars: Record<string, string | number> = {}): string {
  return fill(CRANE_WORDS[language()][key], vars);
}
