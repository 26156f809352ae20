// The page's German (Deutsch) words: the same keys as ../en (each topic module's type enforces every one,
// and `Words` the whole), one module per topic as in English; and the registry's parameters and models
// in German (models.ts). docs/web.md, "Languages".
import type { Words } from '../en';
import { DE_PANEL } from './panel';
import { DE_TOOLS } from './tools';
import { DE_MESSAGES } from './messages';
import { DE_REFUSALS } from './refusals';
import { DE_SCENARIOS } from './scenarios';
export { DE_PARAMS, DE_MODELS } from './models';

export const DE: Words = {
  ...DE_PANEL,
  ...DE_TOOLS,
  ...DE_MESSAGES,
  ...DE_REFUSALS,
  ...DE_SCENARIOS,
};
