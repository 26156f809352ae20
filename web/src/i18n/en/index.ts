// The page's English words (the reference table: every other language has the same keys, which the type
// `Words` enforces), one module per topic: panel, tools, messages, refusals, scenarios (their order is
// the keys' order). {name} marks a value filled in by t(). docs/web.md, "Languages".
import { EN_PANEL } from './panel';
import { EN_TOOLS } from './tools';
import { EN_MESSAGES } from './messages';
import { EN_REFUSALS } from './refusals';
import { EN_SCENARIOS } from './scenarios';

export const EN = {
  ...EN_PANEL,
  ...EN_TOOLS,
  ...EN_MESSAGES,
  ...EN_REFUSALS,
  ...EN_SCENARIOS,
};

export type Words = { readonly [K in keyof typeof EN]: string };
