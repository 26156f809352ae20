// The page's French (Français) words: the same keys as ../en (each topic module's type enforces every one,
// and `Words` the whole), one module per topic as in English; and the registry's parameters and models
// in French (models.ts). docs/web.md, "Languages".
import type { Words } from '../en';
import { FR_PANEL } from './panel';
import { FR_TOOLS } from './tools';
import { FR_MESSAGES } from './messages';
import { FR_REFUSALS } from './refusals';
import { FR_SCENARIOS } from './scenarios';
export { FR_PARAMS, FR_MODELS } from './models';

export const FR: Words = {
  ...FR_PANEL,
  ...FR_TOOLS,
  ...FR_MESSAGES,
  ...FR_REFUSALS,
  ...FR_SCENARIOS,
};
