// The page's words in one table per language (en.ts, de.ts; docs/web.md, "Languages"). `t(key, vars)` looks a
// string up in the current language and fills its {placeholders}; the language is chosen once at start
// (`chooseLanguage`): the URL's `lang`, else the one picked before (localStorage), else the first of the
// browser's languages the lab speaks, else English. Switching reloads the page (the URL keeps the run).
// The model registry's words (parameter labels and help) are the core's, in English; a table may give its
// own (`params`, `models` of LANGUAGES), else the registry's are shown. No DOM; unit-tested.
import { EN } from './en';
import type { Words } from './en';
import { DE, DE_MODELS, DE_PARAMS } from './de';
import { FR, FR_MODELS, FR_PARAMS } from './fr';

export type Key = keyof Words;

export const LANGUAGES = {
  en: { name: 'English', words: EN, params: {} as Record<string, [string, string]>, models: { crane: 'Gantry crane (crane mode)' } as Record<string, string> },
  de: { name: 'Deutsch', words: DE, params: DE_PARAMS, models: DE_MODELS },
  fr: { name: 'Français', words: FR, params: FR_PARAMS, models: FR_MODELS },
} as const;
export type Lang = keyof typeof LANGUAGES;

let current: Lang = 'en';

export function isLang(v: unknown): v is Lang {
  return typeof v === 'string' && Object.hasOwn(LANGUAGES, v);
}

/** The language to show: `fromUrl` (the `lang` query key), else `stored`, else the first of the browser's
 *  `preferred` languages (their primary subtag: de-AT → de) the lab has, else English. */
export function chooseLanguage(fromUrl: string | null, stored: string | null, preferred: readonly string[]): Lang {
  if (isLang(fromUrl)) return fromUrl;
  if (isLang(stored)) return stored;
  for (const p of preferred) {
    const primary = p.toLowerCase().split('-')[0];
    if (isLang(primary)) return primary;
  }
  return 'en';
}

export function setLanguage(lang: Lang): void {
  current = lang;
}

export function language(): Lang {
  return current;
}

/** The string `key` in the current language with each {name} replaced by vars[name]. */
export function t(key: Key, vars: Record<string, string | number> = {}): string {
  const table: Words = LANGUAGES[current].words;
  return fill(table[key] ?? EN[key], vars);
}

/** `text` with each {name} replaced by vars[name] (a name vars lacks stays as it is). */
export function fill(text: string, vars: Record<string, string | number> = {}): string {
  return text.replace(/\{(\w+)\}/g, (m, name: string) => (name in vars ? String(vars[name]) : m));
}

/** A registry parameter's label and help in the current language: the table's own, else the registry's. */
export function paramWords(name: string, label: string, help: string): [label: string, help: string] {
  const own = (LANGUAGES[current].params as Record<string, [string, string] | undefined>)[name];
  return own ?? [label, help];
}

/** A registry model's label in the current language: the table's own, else the registry's. */
export function modelWords(name: string, label: string): string {
  return (LANGUAGES[current].models as Record<string, string | undefined>)[name] ?? label;
}

/** A method's name for a student (`method.<name>` of the table: "Symplectic (RATTLE, 2nd order)"), else
 *  its code name with its order. */
export function methodWords(name: string, order: number): string {
  const key = `method.${name}`;
  return Object.hasOwn(EN, key) ? t(key as Key) : t('method.other', { name, n: order });
}

/** An exact orbit kind (`kind.<kind>` of the table: "swings to and fro in a plane"), else the code word. */
export function kindWords(kind: string): string {
  const key = `kind.${kind}`;
  return Object.hasOwn(EN, key) ? t(key as Key) : kind;
}

/** A shipped scenario's title (`scenario.<name>` of the table), else the file's own `title`, else its name. */
export function scenarioWords(name: string, title: string | null | undefined): string {
  const key = `scenario.${name}`;
  return Object.hasOwn(EN, key) ? t(key as Key) : (title ?? name);
}

/** A model's one-line description for a student (`modelHelp.<name>`), else the registry's summary. */
export function modelHelp(name: string, summary: string): string {
  const key = `modelHelp.${name}`;
  return Object.hasOwn(EN, key) ? t(key as Key) : summary;
}

/** The words of an HTTP error answer of the server (its JSON body) in the page's language: keyed answers
 *  (`key`, `values`: python/pendulab/server/messages.json) through the table, else the English `detail`,
 *  else `fallback` (e.g. "HTTP 503"). */
export function httpProblem(body: unknown, fallback: string): string {
  const b = (typeof body === 'object' && body !== null ? body : {}) as { detail?: unknown; key?: unknown; values?: unknown };
  const detail = typeof b.detail === 'string' ? b.detail : fallback;
  if (typeof b.key !== 'string') return detail;
  const values = (typeof b.values === 'object' && b.values !== null ? b.values : {}) as Record<string, string | number>;
  return serverWords({ message: detail, key: b.key, values });
}

/** An error notice of the server in the page's language: `server.<key>` of the table filled with the
 *  notice's values when the server keyed it (python/pendulab/server/messages.json), else its English text.
 *  A `model` value (a model's code name; `owner` and `others` too) and a `name` that is a parameter's are shown in the page's words for
 *  them (a German page: "Länge l = -1: mindestens 0.001 erlaubt"). */
export function serverWords(n: { message: string; key?: string; values?: Record<string, string | number> }): string {
  const key = `server.${n.key ?? ''}`;
  if (n.key === undefined || !Object.hasOwn(EN, key)) return n.message;
  const values = { ...(n.values ?? {}) };
  if (typeof values.model === 'string') values.model = modelWords(values.model, values.model);
  // the models that have a parameter (parameter_of_other_model[s]): each in the page's words too
  if (typeof values.owner === 'string') values.owner = modelWords(values.owner, values.owner);
  if (typeof values.others === 'string') values.others = values.others.split(', ').map((m) => modelWords(m, m)).join(', ');
  if (typeof values.name === 'string') values.name = paramWords(values.name, values.name, '')[0];
  // a stopped integration whose cause the engine keyed (`why`: diverged, step_too_small, …): the cause in words too
  const why = `server.${String(values.why)}`;
  if (n.key === 'integration_stopped' && typeof values.why === 'string' && Object.hasOwn(EN, why)) values.detail = t(why as Key, values);
  return t(key as Key, values);
}
