// The string pendulum's events as the page shows them (no DOM): the server's core finds each leave (the
// tension reached 0) and snap (the string taut again, with the energy it loses) and sends an `event`
// notice; the page only words them for the message line and keeps the last few of the current trajectory
// for the data panel and the plots' marks.
import type { EventNotice } from './protocol';
import { fmt } from './format';
import { t } from './i18n';

/** How many events the data panel lists (the latest). */
export const EVENTS_SHOWN = 5;

/** The message line's sentence for one event, e.g. "t = 1.234 s: the string went slack". */
export function eventMessage(e: EventNotice): string {
  const what = e.kind === 'slack' ? t('event.slack') : t('event.taut', { lost: fmt(e.energy_lost, 3) });
  const skipped = e.skipped > 0 ? t(e.skipped > 1 ? 'event.skippedMany' : 'event.skippedOne', { n: e.skipped }) : '';
  return `t = ${e.t.toFixed(3)} s: ${what}${skipped}`;
}

/** The data panel's row of one event: [label, value, unit]. */
export function eventRow(e: EventNotice): [string, string, string] {
  return e.kind === 'slack'
    ? [t('event.slackRow'), `t = ${fmt(e.t, 6)} s`, '']
    : [t('event.tautRow'), t('event.tautValue', { t: fmt(e.t, 6), lost: fmt(e.energy_lost, 4) }), 'J'];
}

/** `events` with `e` appended when it belongs to `epoch` (the trajectory shown), keeping the last `max`,
 *  oldest first; unchanged (the same array) when it belongs to another epoch. */
export function recordEvent(
  events: readonly EventNotice[],
  e: EventNotice,
  epoch: number | null,
  max = EVENTS_SHOWN,
): readonly EventNotice[] {
  if (epoch === null || e.epoch !== epoch) return events;
  const out = [...events, e];
  return out.length > max ? out.slice(out.length - max) : out;
}
